// Element pieces (solver/prepare/pieces.h): elements cut by the separating and BSP
// planes exactly where their faces were cut, without loss and without cracks.
#include "solver/prepare/pieces.h"
#include "solver/prepare/prepare.h"
#include "support/covered_faces.h"
#include "support/prepared_scenes.h"
#include "support/sample_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

PreparedScene prepare(const model::Scene& scene, RegionsMode mode)
{
    PrepareOptions options;
    options.regions = mode;
    options.autoRegionPatchThreshold = 100;
    return test::prepared(scene, options);
}

struct NamedScene {
    std::string name;
    model::Scene scene;
};

std::vector<NamedScene> scenes()
{
    return {{"two-lights-room", test::loadSample("two-lights-room")},
            {"cornell-box", test::loadSample("cornell-box")},
            {"random 3", test::randomRegionScene(3, 2, 2)},
            {"random 11", test::randomRegionScene(11, 3, 2)}};
}

double pieceArea(const PreparedScene& s, const Piece& p)
{
    const Vec3 a = s.pieceVertices[size_t(p.vertices[0])], b = s.pieceVertices[size_t(p.vertices[1])],
               c = s.pieceVertices[size_t(p.vertices[2])];
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

constexpr RegionsMode kModes[] = {RegionsMode::Authored, RegionsMode::None, RegionsMode::Auto};

} // namespace

TEST(Pieces, ThePiecesOfEveryElementCoverExactlyItsAreaAndNoneIsLost)
{
    for (const NamedScene& named : scenes())
        for (RegionsMode mode : kModes) {
            const PreparedScene s = prepare(named.scene, mode);
            ASSERT_FALSE(s.elements.empty()) << named.name;
            EXPECT_EQ(s.stats.lostPieces, 0) << named.name;
            EXPECT_EQ(s.stats.lostPieceArea, 0.0) << named.name;
            std::vector<double> covered(s.elements.size(), 0.0);
            for (const Piece& p : s.pieces)
                covered[size_t(p.element)] += pieceArea(s, p);
            for (size_t e = 0; e < s.elements.size(); ++e)
                ASSERT_NEAR(covered[e], s.elements[e].area, 1e-9 * s.elements[e].area)
                    << named.name << " element " << e;
        }
}

TEST(Pieces, ElementsAreCutWhereTheirFacesWereCutAndStayWhole)
{
    // Automatic regions cut the sample's room surfaces; the cut elements have
    // pieces in several nodes, every piece in a node holding its face.
    const PreparedScene s = prepare(test::loadSample("two-lights-room"), RegionsMode::Auto);
    std::vector<std::vector<int>> nodesOf(s.elements.size());
    for (size_t n = 0; n < s.nodes.size(); ++n) {
        const BspNode& node = s.nodes[n];
        for (int i = node.firstPiece; i < node.firstPiece + node.pieceCount; ++i) {
            const int element = s.pieces[size_t(i)].element;
            if (nodesOf[size_t(element)].empty() || nodesOf[size_t(element)].back() != int(n))
                nodesOf[size_t(element)].push_back(int(n));
            bool holds = false;
            for (int f = node.firstFragment; f < node.firstFragment + node.fragmentCount; ++f)
                holds = holds || s.fragments[size_t(f)].properties == s.elements[size_t(element)].properties;
            EXPECT_TRUE(holds) << "piece " << i << " of element " << element << " in node " << n;
        }
    }
    int cut = 0;
    for (const auto& nodes : nodesOf) {
        EXPECT_FALSE(nodes.empty()) << "every element is painted";
        cut += nodes.size() > 1;
    }
    EXPECT_GT(cut, 10) << "the premise: region planes cut elements";
    EXPECT_GT(s.pieces.size(), s.elements.size());
}

TEST(Pieces, CutPointsAreSharedSoThePiecesOfAFaceMeetEdgeToEdge)
{
    // Per input face, every piece edge is either shared in opposite directions
    // by exactly two piece triangles or lies on the face's outline or on the
    // outline of a solid standing on it (covered_faces.h): no crack and no
    // overlap for the hemicube rasteriser's pixel-centre rule.
    for (const NamedScene& named : scenes())
        for (RegionsMode mode : kModes) {
            const PreparedScene s = prepare(named.scene, mode);
            std::vector<std::map<std::pair<int, int>, int>> directed(s.faces.size());
            for (const Piece& p : s.pieces) {
                auto& edges = directed[size_t(s.elements[size_t(p.element)].properties)];
                for (int i = 0; i < 3; ++i)
                    ++edges[{p.vertices[size_t(i)], p.vertices[size_t((i + 1) % 3)]}];
            }
            for (size_t f = 0; f < s.faces.size(); ++f) {
                const InputFace& face = s.faces[f];
                double boundary = 0.0;
                for (const auto& [edge, count] : directed[f]) {
                    ASSERT_EQ(count, 1) << named.name << " face " << face.id;
                    if (directed[f].count({edge.second, edge.first}))
                        continue;
                    const Vec3 a = s.pieceVertices[size_t(edge.first)], b = s.pieceVertices[size_t(edge.second)];
                    boundary += glm::length(b - a);
                    ASSERT_TRUE(test::onOutlineOrCover(s, f, a) && test::onOutlineOrCover(s, f, (a + b) * 0.5) &&
                                test::onOutlineOrCover(s, f, b))
                        << named.name << " face " << face.id << ": an open edge inside the face";
                }
                if (!test::coversOf(s, f).empty())
                    continue;
                double perimeter = 0.0;
                for (size_t i = 0; i < face.polygon.size(); ++i)
                    perimeter += glm::length(face.polygon[(i + 1) % face.polygon.size()] - face.polygon[i]);
                EXPECT_NEAR(boundary, perimeter, 1e-9) << named.name << " face " << face.id;
            }
        }
}

TEST(Pieces, FacesThatMeetAlongALineMeetThereVertexToVertex)
{
    // The blocks stand on the floor and the walls meet the floor: along those
    // lines no corner of one face's pieces lies inside an open edge of
    // another's, so the rasteriser lets no pixel through between them.
    const PreparedScene s = prepare(test::loadSample("cornell-box"), RegionsMode::None);
    std::vector<std::map<std::pair<int, int>, int>> directed(s.faces.size());
    std::vector<std::vector<int>> cornersOf(s.faces.size());
    for (const Piece& p : s.pieces) {
        const size_t f = size_t(s.elements[size_t(p.element)].properties);
        for (int i = 0; i < 3; ++i) {
            ++directed[f][{p.vertices[size_t(i)], p.vertices[size_t((i + 1) % 3)]}];
            cornersOf[f].push_back(p.vertices[size_t(i)]);
        }
    }
    int contacts = 0;
    for (size_t f = 0; f < s.faces.size(); ++f)
        for (const auto& [edge, count] : directed[f]) {
            if (directed[f].count({edge.second, edge.first}))
                continue;
            const Vec3 a = s.pieceVertices[size_t(edge.first)], ab = s.pieceVertices[size_t(edge.second)] - a;
            ASSERT_GT(glm::length(ab), 1e-7) << s.faces[f].id << " edge " << edge.first << "-" << edge.second;
            for (size_t g = 0; g < s.faces.size(); ++g) {
                if (g == f)
                    continue;
                for (int v : cornersOf[g]) {
                    const Vec3 p = s.pieceVertices[size_t(v)];
                    const double t = glm::dot(p - a, ab) / glm::dot(ab, ab);
                    const double along = t * glm::length(ab);
                    if (along < 1e-7 || along > glm::length(ab) - 1e-7)
                        continue;
                    EXPECT_GT(glm::length(a + ab * t - p), 1e-7)
                        << s.faces[f].id << " has a T-vertex of " << s.faces[g].id << " at (" << p.x << ", " << p.y
                        << ", " << p.z << ")";
                }
            }
            ++contacts;
        }
    EXPECT_GT(contacts, 100) << "the premise: open edges along the walls and around the blocks";
}

TEST(Pieces, RebuildingGivesTheSamePieces)
{
    PreparedScene s = prepare(test::randomRegionScene(5, 2, 2), RegionsMode::Auto);
    const std::vector<Piece> before = s.pieces;
    const std::vector<Vec3> vertices = s.pieceVertices;
    buildPieces(s);
    ASSERT_EQ(s.pieces.size(), before.size());
    for (size_t i = 0; i < before.size(); ++i) {
        EXPECT_EQ(s.pieces[i].vertices, before[i].vertices);
        EXPECT_EQ(s.pieces[i].element, before[i].element);
    }
    EXPECT_EQ(s.pieceVertices, vertices);
}

TEST(Pieces, VerticesAreNumberedInTheOrderThePiecesFirstUseThem)
{
    // A render walks the pieces in order and reads each corner it meets:
    // numbered by first use, those reads run nearly in sequence. Every
    // vertex is some piece's corner, and the first piece to use a vertex
    // meets it right after the vertices numbered before it.
    PreparedScene s = prepare(test::randomRegionScene(5, 2, 2), RegionsMode::Auto);
    ASSERT_FALSE(s.pieces.empty());
    int next = 0;
    for (const Piece& p : s.pieces)
        for (int v : p.vertices) {
            ASSERT_LE(v, next) << "a vertex used before every lower number was";
            if (v == next)
                ++next;
        }
    EXPECT_EQ(size_t(next), s.pieceVertices.size()) << "vertices no piece uses";
}
