// The elements along contact lines (solver/shooting/contact_lines.h), which
// the refinement splits before the first shot
// (solver/shooting/adaptive_refinement.h): where a solid at least a quarter
// patch wide stands on a face, the elements of the face and of the solid's
// sides that touch its foot, and nothing else.
#include "solver/shooting/contact_lines.h"

#include "solver/shooting/adaptive_refinement.h"

#include "support/adaptive_scenes.h"
#include "support/prepared_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

AdaptiveMesh meshOf(PreparedScene& scene)
{
    const std::vector<Rgb> zero(scene.elements.size(), Rgb{0.0});
    return AdaptiveMesh(scene, zero, zero);
}

// The elements with a corner on the foot of the block [lo, hi]^2 standing at
// height y, each with how many of its corners lie there (at that height on
// one side of the foot's square). Computed from the coordinates alone, apart
// from the mesh's topology.
std::map<int, int> cornersOnFoot(const PreparedScene& s, double y, double lo, double hi)
{
    const double eps = 1e-9;
    const auto within = [&](double c) { return c >= lo - eps && c <= hi + eps; };
    // On the side x = side (axis 0) or z = side (axis 2), within the square.
    const auto onFoot = [&](const Vec3& p) {
        if (std::abs(p.y - y) >= eps || !within(p.x) || !within(p.z))
            return false;
        return std::abs(p.x - lo) < eps || std::abs(p.x - hi) < eps || std::abs(p.z - lo) < eps ||
               std::abs(p.z - hi) < eps;
    };
    std::map<int, int> out;
    for (const InputFace& face : s.faces)
        for (int e : face.elements)
            for (int corner : s.elements[size_t(e)].vertices)
                if (onFoot(s.vertices[size_t(corner)]))
                    ++out[e];
    return out;
}

std::set<int> elementsAlongFoot(const PreparedScene& s, double y, double lo, double hi)
{
    std::set<int> out;
    for (const auto& [e, corners] : cornersOnFoot(s, y, lo, hi))
        out.insert(e);
    return out;
}

std::set<std::string> facesOf(const PreparedScene& s, const std::vector<int>& elements)
{
    std::set<std::string> ids;
    for (int e : elements)
        ids.insert(s.faces[size_t(s.properties[size_t(s.elements[size_t(e)].properties)].face)].id);
    return ids;
}

} // namespace

TEST(ContactLines, AFloorAndTheSidesOfABlockStandingOnItMeetAlongTheBlocksFoot)
{
    PreparedScene s = test::prepared(test::closedRoom()); // block [1, 2] x [0, 1] x [1, 2]
    const std::vector<std::vector<int>> contacts = contactFaces(s);
    const size_t floor = test::faceNamed(s, "room.body.ny");
    std::set<std::string> ofFloor;
    for (int f : contacts[floor])
        ofFloor.insert(s.faces[size_t(f)].id);
    // The block's faces but its bottom, which lies on the floor.
    EXPECT_EQ(ofFloor, (std::set<std::string>{"block.body.nx", "block.body.px", "block.body.py", "block.body.nz",
                                              "block.body.pz"}));
    for (const char* side : {"block.body.nx", "block.body.px", "block.body.nz", "block.body.pz"})
        EXPECT_EQ(contacts[test::faceNamed(s, side)], std::vector<int>{int(floor)}) << side;
    // A room's walls meet its floor, but the room stands on nothing.
    for (const char* wall : {"room.body.nx", "room.body.px", "room.body.nz", "room.body.pz", "room.body.py"})
        EXPECT_TRUE(contacts[test::faceNamed(s, wall)].empty()) << wall;
}

TEST(ContactLines, TheElementsOfTheFloorAndOfTheBlocksSidesAlongItsFootAreFoundAndNoOthers)
{
    PreparedScene s = test::prepared(test::closedRoom());
    const AdaptiveMesh mesh = meshOf(s);
    const std::vector<int> found = elementsOnContactLines(mesh, contactFaces(s));
    const std::set<int> expected = elementsAlongFoot(s, 0.0, 1.0, 2.0);
    ASSERT_FALSE(expected.empty());
    EXPECT_EQ(std::set<int>(found.begin(), found.end()), expected);
    EXPECT_EQ(facesOf(s, found), (std::set<std::string>{"room.body.ny", "block.body.nx", "block.body.px",
                                                        "block.body.nz", "block.body.pz"}));
    // Those that only touch the foot at a corner are found too: of a quad's
    // two triangles along the foot one has an edge on it, the other a corner,
    // and left whole it would carry its far corners' light to the foot.
    const auto onlyACorner =
        std::count_if(found.begin(), found.end(),
                      [&, corners = cornersOnFoot(s, 0.0, 1.0, 2.0)](int e) { return corners.at(e) == 1; });
    EXPECT_GT(onlyACorner, 0);
}

TEST(ContactLines, ABoxStandingOnABoxMeetsItsTopAlongItsFoot)
{
    model::Scene scene = test::closedRoom();
    test::addBox(scene, "upper", {1.25, 1.0, 1.25}, {1.75, 1.5, 1.75}, "wall");
    PreparedScene s = test::prepared(scene);
    const AdaptiveMesh mesh = meshOf(s);
    const std::vector<int> found = elementsOnContactLines(mesh, contactFaces(s));
    std::set<int> onTop;
    for (int e : elementsAlongFoot(s, 1.0, 1.25, 1.75))
        onTop.insert(e);
    ASSERT_FALSE(onTop.empty());
    for (int e : onTop)
        EXPECT_TRUE(std::binary_search(found.begin(), found.end(), e)) << e;
    const std::set<std::string> faces = facesOf(s, found);
    EXPECT_TRUE(faces.count("block.body.py"));
    EXPECT_TRUE(faces.count("upper.body.nx"));
}

TEST(ContactLines, ALegNarrowerThanAQuarterPatchMakesNone)
{
    model::Scene scene = test::closedRoom();
    scene.objects.erase(std::remove_if(scene.objects.begin(), scene.objects.end(),
                                       [](const model::Object& o) { return o.id == "block"; }),
                        scene.objects.end());
    // 5 cm square at 0.5 m patches: narrower than 0.125 m.
    test::addBox(scene, "leg", {1.0, 0.0, 1.0}, {1.05, 0.7, 1.05}, "wall");
    PreparedScene s = test::prepared(scene);
    const std::vector<std::vector<int>> contacts = contactFaces(s);
    EXPECT_TRUE(std::all_of(contacts.begin(), contacts.end(), [](const auto& faces) { return faces.empty(); }));
    EXPECT_TRUE(elementsOnContactLines(meshOf(s), contacts).empty());
}

TEST(ContactLines, TheRefinementSplitsThemBeforeTheFirstShotOnTopOfItsBudget)
{
    const model::Scene scene = test::closedRoomRefined();
    PreparedScene s = test::prepared(scene);
    const int initial = int(s.elements.size());
    RefinementPolicy policy;
    policy.penumbraPasses = 0; // the block's penumbra: tests/solver/shooting/penumbrae_test.cpp
    AdaptiveRefinement r(s, scene.solver.adaptive, policy);
    const int limit = r.elementLimit();
    const int splits = r.splitBeforeFirstShot();
    ASSERT_GT(splits, 0);
    EXPECT_EQ(r.contactElements(), 3 * splits);
    EXPECT_EQ(r.penumbraElements(), 0);
    EXPECT_EQ(r.elementLimit(), limit + 3 * splits);
    EXPECT_EQ(r.roundLimit(), initial + 3 * splits + (limit - initial) / RefinementPolicy{}.maxRounds);
    const ActiveScene active = r.takeActiveScene();
    EXPECT_EQ(int(active.scene.elements.size()), initial + 3 * splits);
    // Two passes: the elements along the foot are a quarter of the size of those
    // of the floor away from it, and every element holds its emission.
    const AdaptiveMesh before = meshOf(s);
    double coarse = 0.0;
    for (int e : elementsOnContactLines(before, contactFaces(s)))
        coarse = std::max(coarse, s.elements[size_t(e)].area);
    PreparedScene split = active.scene;
    for (int e : elementsAlongFoot(split, 0.0, 1.0, 2.0))
        EXPECT_LE(split.elements[size_t(e)].area, coarse / 16.0 + 1e-12) << e;
    for (size_t e = 0; e < active.scene.elements.size(); ++e) {
        const Rgb emission = active.scene.properties[size_t(active.scene.elements[e].properties)].emission;
        EXPECT_EQ(active.radiosity[e], emission);
        EXPECT_EQ(active.unshot[e], emission);
    }
    // Once only: the mesh is the refinement's from now on.
    EXPECT_EQ(r.splitBeforeFirstShot(), 0);
}

TEST(ContactLines, TheRefinementSplitsNothingWhereNoSolidStandsOnAFace)
{
    model::Scene scene = test::closedRoom();
    scene.objects.erase(std::remove_if(scene.objects.begin(), scene.objects.end(),
                                       [](const model::Object& o) { return o.id == "block"; }),
                        scene.objects.end());
    PreparedScene s = test::prepared(scene);
    AdaptiveRefinement r(s, scene.solver.adaptive);
    EXPECT_EQ(r.splitBeforeFirstShot(), 0);
    EXPECT_EQ(r.contactElements(), 0);
}
