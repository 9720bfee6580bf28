// Triangles cut at their edges' midpoints (output/midpoint_cut.h): an edge
// is cut on both of its triangles, whichever copy of its corners each uses,
// and each copy takes its own midpoint.
#include "output/midpoint_cut.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

using namespace regio;
using namespace regio::output;

namespace {

// A unit square of one face as two triangles along the diagonal (0,0)-(1,1);
// with `copies`, the second triangle's diagonal corners are copies of the
// first's (vertices 4 and 5 at the places of 0 and 2), as the smooth
// shading makes at a shadow corner.
LitMesh square(bool copies)
{
    LitMesh mesh;
    mesh.faceIds = {"floor.top"};
    const std::vector<glm::vec3> corners = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {0, 0, 0}, {1, 0, 1}};
    for (const glm::vec3& p : corners) {
        mesh.positions.push_back(p);
        mesh.normals.emplace_back(0, 1, 0);
        mesh.radiosity.emplace_back(0.0f);
        mesh.reflectance.emplace_back(0.5f);
    }
    mesh.indices = {0, 2, 1};
    if (copies)
        mesh.indices.insert(mesh.indices.end(), {4, 3, 5});
    else
        mesh.indices.insert(mesh.indices.end(), {0, 3, 2});
    mesh.triangleFace = {0, 0};
    return mesh;
}

// Whether (a, b) is the diagonal, by its corners' places.
bool isDiagonal(const LitMesh& mesh, std::uint32_t a, std::uint32_t b)
{
    const glm::vec3 d = mesh.positions[a] - mesh.positions[b];
    return std::abs(d.x) == 1.0f && std::abs(d.z) == 1.0f;
}

} // namespace

TEST(MidpointCut, AnEdgeIsCutOnBothTrianglesAndEachCopyTakesItsOwnMidpoint)
{
    for (const bool copies : {false, true}) {
        MidpointCut cut(square(copies), CutFor::Files);
        const LitMesh& before = cut.mesh();
        const size_t added = cut.cut([&](std::uint32_t a, std::uint32_t b) { return isDiagonal(before, a, b); });
        const LitMesh& mesh = cut.mesh();
        EXPECT_EQ(mesh.triangleCount(), 4u) << "copies " << copies;
        EXPECT_EQ(added, copies ? 2u : 1u);
        for (size_t v = cut.originalVertices(); v < mesh.vertexCount(); ++v) {
            EXPECT_EQ(glm::length(mesh.positions[v] - glm::vec3(0.5f, 0.0f, 0.5f)), 0.0f);
            EXPECT_EQ(cut.faceOf()[v], 0);
        }
        // Each midpoint between the corners of the triangle that made it.
        ASSERT_EQ(cut.ends().size(), 2 * added);
        if (copies) {
            EXPECT_EQ((std::vector<std::uint32_t>{cut.ends()[0], cut.ends()[1]}), (std::vector<std::uint32_t>{0, 2}));
            EXPECT_EQ((std::vector<std::uint32_t>{cut.ends()[2], cut.ends()[3]}), (std::vector<std::uint32_t>{5, 4}));
        }
    }
}

TEST(MidpointCut, ForFilesNoLaterRoundCutsAPieceThinnerThanAMillimetre)
{
    // A strip 3 mm wide: the first round cuts its long sides (pieces at
    // least half as tall as the triangles), a second round that wants every
    // edge again would make pieces 0.75 mm thin, which a reader welding at
    // a millimetre folds; for the screen it cuts them.
    LitMesh strip = square(false);
    for (glm::vec3& p : strip.positions)
        p.z *= 0.003f;
    const auto every = [](std::uint32_t, std::uint32_t) { return true; };
    MidpointCut files(strip, CutFor::Files), screen(strip, CutFor::Screen);
    files.cut(every);
    screen.cut(every);
    const size_t firstFiles = files.mesh().triangleCount();
    EXPECT_GT(firstFiles, 2u);
    files.cut(every);
    screen.cut(every);
    EXPECT_GT(screen.mesh().triangleCount(), files.mesh().triangleCount());
    const LitMesh& mesh = files.mesh();
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]), b(mesh.positions[mesh.indices[3 * t + 1]]),
            c(mesh.positions[mesh.indices[3 * t + 2]]);
        const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
        EXPECT_GE(glm::length(glm::cross(b - a, c - a)) / longest, 1.0e-3) << "triangle " << t;
    }
}
