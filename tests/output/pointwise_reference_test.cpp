// The pointwise radiosity reference of tests/support/pointwise_reference.h,
// checked against answers known in closed form before anything is measured
// against it: form factors, visibility, the furnace, reciprocity.
#include "support/closed_forms.h"
#include "support/pointwise_reference.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

using namespace regio;
using namespace regio::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The form factor from a differential area at x (unit normal n) to the
// parallelogram p0 + s e1 + t e2, s, t in [0, 1], straight from its
// definition: cos(theta_x) cos(theta_y) / (pi r^2) integrated by Simpson's
// rule on cells x cells intervals (cells even). Nothing of the contour formula.
double integratedFormFactor(const Vec3& x, const Vec3& n, const Vec3& p0, const Vec3& e1, const Vec3& e2, int cells)
{
    const Vec3 m = glm::cross(e1, e2);
    const double area = glm::length(m);
    const Vec3 ny = m / area;
    const auto weight = [&](int i) { return i == 0 || i == cells ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0); };
    double sum = 0.0;
    for (int i = 0; i <= cells; ++i) {
        for (int j = 0; j <= cells; ++j) {
            const Vec3 d = p0 + e1 * (double(i) / cells) + e2 * (double(j) / cells) - x;
            const double r2 = glm::dot(d, d);
            const double cx = glm::dot(n, d) / std::sqrt(r2);
            const double cy = std::abs(glm::dot(ny, d)) / std::sqrt(r2);
            if (cx > 0.0)
                sum += weight(i) * weight(j) * cx * cy / (kPi * r2);
        }
    }
    return sum * area / (9.0 * cells * cells);
}

// A rectangle in the plane at height y; facing down when x0 < x1 and z0 < z1.
std::vector<Vec3> square(double x0, double x1, double z0, double z1, double y)
{
    return {{x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}};
}

// A closed unit cube seen from inside, every face glowing with `emission` and
// reflecting `reflectance`.
Scene furnace(const Rgb& reflectance, const Rgb& emission)
{
    Scene scene;
    addMaterial(scene, "glow", reflectance, emission);
    addBox(scene, "room", {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, "glow", true);
    return scene;
}

PointwiseReferenceOptions coarse()
{
    PointwiseReferenceOptions options;
    options.patchSize = 0.1;
    return options;
}

} // namespace

TEST(PointwiseReference, FormFactorToAParallelCoaxialSquareIsFourCornerRectangles)
{
    const Vec3 up(0.0, 0.0, 1.0);
    for (const auto& [half, height] : {std::pair{0.5, 1.0}, std::pair{0.1, 2.0}, std::pair{3.0, 0.2}}) {
        const std::vector<Vec3> polygon{
            {-half, -half, height}, {half, -half, height}, {half, half, height}, {-half, half, height}};
        EXPECT_NEAR(pointToPolygonFormFactor(Vec3(0.0), up, polygon), 4.0 * cornerFormFactor(half, half, height), 1e-6)
            << "half side " << half << ", height " << height;
    }
    // Under a corner of a rectangle: the closed form itself.
    const std::vector<Vec3> rectangle{{0.0, 0.0, 0.7}, {1.2, 0.0, 0.7}, {1.2, 0.4, 0.7}, {0.0, 0.4, 0.7}};
    EXPECT_NEAR(pointToPolygonFormFactor(Vec3(0.0), up, rectangle), cornerFormFactor(1.2, 0.4, 0.7), 1e-6);
    // Either winding gives the same.
    const std::vector<Vec3> reversed(rectangle.rbegin(), rectangle.rend());
    EXPECT_NEAR(pointToPolygonFormFactor(Vec3(0.0), up, reversed), cornerFormFactor(1.2, 0.4, 0.7), 1e-12);
}

TEST(PointwiseReference, FormFactorToAParallelCoaxialDiskIsRSquaredOverHSquaredPlusRSquared)
{
    // The disk as a regular polygon of 8192 corners, whose area falls short
    // of the disk's by a relative 1e-7.
    const double radius = 0.7, height = 1.3;
    std::vector<Vec3> disk;
    for (int k = 0; k < 8192; ++k) {
        const double angle = 2.0 * kPi * k / 8192.0;
        disk.push_back({radius * std::cos(angle), radius * std::sin(angle), height});
    }
    EXPECT_NEAR(pointToPolygonFormFactor(Vec3(0.0), Vec3(0.0, 0.0, 1.0), disk),
                radius * radius / (height * height + radius * radius), 1e-6);
}

TEST(PointwiseReference, FormFactorToATiltedPolygonMatchesTheIntegratedDefinition)
{
    const Vec3 x(0.1, -0.2, 0.0);
    const Vec3 n = glm::normalize(Vec3(0.2, 0.1, 1.0));
    const Vec3 p0(0.2, -0.3, 1.0), e1(0.8, 0.1, 0.3), e2(-0.1, 0.6, 0.4);
    const std::vector<Vec3> parallelogram{p0, p0 + e1, p0 + e1 + e2, p0 + e2};
    EXPECT_NEAR(pointToPolygonFormFactor(x, n, parallelogram), integratedFormFactor(x, n, p0, e1, e2, 400), 1e-6);
}

TEST(PointwiseReference, FormFactorCountsOnlyWhatLiesInFrontOfTheTangentPlane)
{
    // A wall x = 0.5 reaching from z = -0.4 to z = 0.6 through the tangent
    // plane z = 0 of the point: only its upper part is seen.
    const Vec3 x(0.0), up(0.0, 0.0, 1.0);
    const std::vector<Vec3> wall{{0.5, -0.5, -0.4}, {0.5, 0.5, -0.4}, {0.5, 0.5, 0.6}, {0.5, -0.5, 0.6}};
    const std::vector<Vec3> upper{{0.5, -0.5, 0.0}, {0.5, 0.5, 0.0}, {0.5, 0.5, 0.6}, {0.5, -0.5, 0.6}};
    const double seen = pointToPolygonFormFactor(x, up, wall);
    EXPECT_NEAR(seen, pointToPolygonFormFactor(x, up, upper), 1e-12);
    EXPECT_NEAR(seen, integratedFormFactor(x, up, {0.5, -0.5, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 0.6}, 400), 1e-6);
    // Wholly behind: nothing.
    const std::vector<Vec3> below{{0.5, -0.5, -0.4}, {0.5, 0.5, -0.4}, {0.5, 0.5, -0.1}, {0.5, -0.5, -0.1}};
    EXPECT_EQ(pointToPolygonFormFactor(x, up, below), 0.0);
}

TEST(PointwiseReference, ABlockerHidingHalfOfASourceLetsHalfOfTheRaysThrough)
{
    // A 1 m lamp at y = 1 facing down, a black board at y = 0.5 over x >= 0.5
    // and a floor. Seen from (0.5, 0, 0.5) the board's edge falls on the
    // lamp's middle line x = 0.5.
    Scene scene;
    addMaterial(scene, "lamp", Rgb(0.0), Rgb(10.0));
    addMaterial(scene, "black", Rgb(0.0));
    addMaterial(scene, "floor", Rgb(0.5));
    addPolygon(scene, "lamp", square(0.0, 1.0, 0.0, 1.0, 1.0), "lamp");
    addPolygon(scene, "board", square(0.5, 2.0, -1.0, 2.0, 0.5), "black");
    addPolygon(scene, "floor", square(-1.0, 2.0, 2.0, -1.0, 0.0), "floor");
    PointwiseReferenceOptions options = coarse(); // 0.1 m patches: the middle line is a patch border
    const PointwiseReference reference(scene, options);
    ASSERT_GE(reference.faceIndex("floor.face"), 0);
    const Vec3 up(0.0, 1.0, 0.0), down(0.0, -1.0, 0.0);
    const std::vector<Vec3> lamp = square(0.0, 1.0, 0.0, 1.0, 1.0);
    const Vec3 half(0.5, 0.0, 0.5), open(-0.5, 0.0, 0.5), shadow(1.5, 0.0, 0.5);
    for (int rays : {2, 4, 8})
        EXPECT_EQ(reference.visibility(half, up, lamp, down, rays), 0.5) << rays << " rays per side";
    EXPECT_EQ(reference.visibility(open, up, lamp, down, 4), 1.0);
    EXPECT_EQ(reference.visibility(shadow, up, lamp, down, 4), 0.0);

    // The gathered radiosity: 0.5 x 10 W/m^2 times the form factor of what
    // the point sees of the lamp (nothing else is lit: the lamp and the
    // board reflect nothing, and nothing is left for the floor to see of itself).
    const auto direct = [&](const Vec3& p, const std::vector<Vec3>& seen) {
        return 0.5 * 10.0 * pointToPolygonFormFactor(p, up, seen);
    };
    EXPECT_NEAR(reference.radiosityAt("floor.face", open).x, direct(open, lamp), 1e-9);
    EXPECT_NEAR(reference.radiosityAt("floor.face", half).x, direct(half, square(0.0, 0.5, 0.0, 1.0, 1.0)), 1e-9);
    EXPECT_EQ(reference.radiosityAt("floor.face", shadow).x, 0.0);
}

TEST(PointwiseReference, FloorUnderABlockIsCovered)
{
    Scene scene;
    addMaterial(scene, "white", Rgb(0.5));
    addPolygon(scene, "floor", square(0.0, 2.0, 2.0, 0.0, 0.0), "white");
    addBox(scene, "block", {0.5, 0.0, 0.5}, {1.0, 0.4, 1.0}, "white");
    const PointwiseReference reference(scene, coarse());
    const int floor = reference.faceIndex("floor.face");
    const int bottom = reference.faceIndex("block.body.ny");
    ASSERT_GE(floor, 0);
    ASSERT_GE(bottom, 0);
    EXPECT_TRUE(reference.covered(floor, {0.7, 0.0, 0.8}));
    EXPECT_FALSE(reference.covered(floor, {1.1, 0.0, 0.8}));
    EXPECT_TRUE(reference.covered(bottom, {0.7, 0.0, 0.8}));
    EXPECT_FALSE(reference.covered(reference.faceIndex("block.body.py"), {0.7, 0.4, 0.8}));
    // Patches under the block take no part. The 0.1 m grid of the floor
    // follows the block's footprint: its patches are under it or not.
    for (const ReferencePatch& p : reference.patches()) {
        const bool under = p.centroid.x > 0.5 && p.centroid.x < 1.0 && p.centroid.z > 0.5 && p.centroid.z < 1.0;
        if (p.face == bottom || (p.face == floor && under))
            EXPECT_EQ(p.visibleArea, 0.0) << p.centroid.x << " " << p.centroid.z;
        else
            EXPECT_NEAR(p.visibleArea, p.area, 1e-12) << p.centroid.x << " " << p.centroid.z;
    }
}

TEST(PointwiseReference, ClosedFurnaceGlowsWithEmissionOverOneMinusReflectanceEverywhere)
{
    // Every face emits E and reflects rho, all of a closed room: B = E + rho B
    // at every point, B = E / (1 - rho).
    const Rgb reflectance(0.5, 0.3, 0.8), emission(1.0, 2.0, 0.5);
    const Rgb expected = emission / (Rgb(1.0) - reflectance);
    const PointwiseReference reference(furnace(reflectance, emission), coarse());
    ASSERT_EQ(reference.patches().size(), 600u);
    for (size_t i = 0; i < reference.patches().size(); ++i) {
        const Rgb& b = reference.patches()[i].radiosity;
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(b[c], expected[c], 1e-3 * expected[c]) << "patch " << i << ", channel " << c;
    }
    // Points in the open, beside edges and in corners of the floor.
    const int floor = reference.faceIndex("room.body.ny");
    ASSERT_GE(floor, 0);
    for (const Vec3& p : {Vec3(0.5, 0.0, 0.5), Vec3(0.01, 0.0, 0.5), Vec3(0.003, 0.0, 0.997), Vec3(0.37, 0.0, 0.02)}) {
        const Rgb b = reference.radiosityAt(floor, p);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(b[c], expected[c], 1e-3 * expected[c]) << p.x << " " << p.z << ", channel " << c;
    }
}

TEST(PointwiseReference, ClosedRoomSeesAllOfItselfAndFormFactorsAreReciprocal)
{
    const PointwiseReference reference(furnace(Rgb(0.5), Rgb(1.0)), coarse());
    const std::vector<ReferencePatch>& patches = reference.patches();
    // Energy: each patch's form factors add up to the whole hemisphere.
    for (size_t i = 0; i < patches.size(); ++i) {
        double row = 0.0;
        for (size_t j = 0; j < patches.size(); ++j)
            row += reference.formFactor(i, j);
        ASSERT_NEAR(row, 1.0, 1e-9) << "patch " << i;
    }
    // Reciprocity, A_i F_ij = A_j F_ji: each direction is estimated from the
    // receiver's own sample points, so they agree as well as the samples
    // resolve the form factor across the patches.
    double difference = 0.0, total = 0.0, worstFar = 0.0;
    for (size_t i = 0; i < patches.size(); ++i) {
        for (size_t j = i + 1; j < patches.size(); ++j) {
            const double ij = patches[i].area * reference.formFactor(i, j);
            const double ji = patches[j].area * reference.formFactor(j, i);
            difference += std::abs(ij - ji);
            total += ij + ji;
            const double gap = glm::length(patches[i].centroid - patches[j].centroid);
            if (gap > 3.0 * patches[i].size && ij + ji > 0.0)
                worstFar = std::max(worstFar, 2.0 * std::abs(ij - ji) / (ij + ji));
        }
    }
    EXPECT_LT(difference / total, 0.005); // 0.1 % when written
    EXPECT_LT(worstFar, 0.01);            // 0.6 % when written
}

TEST(PointwiseReference, FurnaceWithABlockInsideStaysNearEmissionOverOneMinusReflectance)
{
    // A block standing on the floor of the glowing room, glowing alike: the
    // answer is still E / (1 - rho) everywhere, but now the visibility rays
    // decide what each point sees, and they only estimate it.
    Scene scene = furnace(Rgb(0.5), Rgb(1.0));
    addBox(scene, "block", {0.3, 0.0, 0.35}, {0.6, 0.4, 0.65}, "glow");
    const PointwiseReference reference(scene, coarse());
    double worst = 0.0;
    for (const ReferencePatch& p : reference.patches()) {
        if (p.visibleArea > 0.0)
            worst = std::max(worst, std::abs(p.radiosity.x - 2.0) / 2.0);
    }
    EXPECT_LT(worst, 0.005); // 0.25 % when written
    // Points beside the block's foot and on its side just above the floor.
    for (const auto& [face, p] :
         {std::pair{"room.body.ny", Vec3(0.62, 0.0, 0.5)}, std::pair{"room.body.ny", Vec3(0.45, 0.0, 0.33)},
          std::pair{"block.body.px", Vec3(0.6, 0.01, 0.5)}, std::pair{"block.body.py", Vec3(0.45, 0.4, 0.5)}})
        EXPECT_NEAR(reference.radiosityAt(face, p).x, 2.0, 0.005 * 2.0) << face;
}

TEST(PointwiseReference, WhatAPointGathersBySourceAddsUpToItsRadiosityAndTakesOtherValuesInstead)
{
    const Rgb reflectance(0.5, 0.3, 0.8), emission(1.0, 2.0, 0.5);
    const PointwiseReference reference(furnace(reflectance, emission), coarse());
    const int floor = reference.faceIndex("room.body.ny");
    const int ceiling = reference.faceIndex("room.body.py");
    ASSERT_GE(floor, 0);
    ASSERT_GE(ceiling, 0);
    const Vec3 centre(0.5, 0.0, 0.5);
    // Its own radiosity, face by face.
    const std::vector<Rgb> bySource = reference.gatheredBySource(floor, centre);
    ASSERT_EQ(bySource.size(), reference.faces().size());
    EXPECT_EQ(bySource[size_t(floor)], Rgb(0.0)) << "a plane gathers nothing from itself";
    Rgb sum(0.0);
    for (const Rgb& b : bySource)
        sum += b;
    const Rgb whole = reference.radiosityAt(floor, centre);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(emission[c] + reflectance[c] * sum[c], whole[c], 1e-12 * whole[c]);
    // One everywhere in place of the patches' values: each face's share is
    // the point's form factor to it, the ceiling's the analytic one, and
    // together the whole hemisphere of a closed room.
    const PointwiseReference::SourceRadiosity one = [](int, const Vec3&) { return Rgb(1.0); };
    const std::vector<Rgb> factors = reference.gatheredBySource(floor, centre, one);
    const std::vector<Vec3>& top = reference.faces()[size_t(ceiling)].polygon;
    EXPECT_NEAR(factors[size_t(ceiling)].x, pointToPolygonFormFactor(centre, {0.0, 1.0, 0.0}, top), 1e-9);
    double total = 0.0;
    for (const Rgb& f : factors)
        total += f.x;
    EXPECT_NEAR(total, 1.0, 1e-9);
}

TEST(PointwiseReference, FacesWithTheirOwnPatchSizeKeepTheFurnaceAndTheHemisphere)
{
    // The floor cut four times finer than the rest, as a narrow gap is cut
    // finer than the room around it: patches of two sizes meet along the
    // floor's edges, and the furnace and the closed room still hold.
    const Rgb reflectance(0.5), emission(1.0);
    PointwiseReferenceOptions options = coarse();
    options.facePatchSizes["room.body.ny"] = 0.025;
    const PointwiseReference reference(furnace(reflectance, emission), options);
    const int floor = reference.faceIndex("room.body.ny");
    ASSERT_GE(floor, 0);
    EXPECT_EQ(reference.faces()[size_t(floor)].patchCount, 1600);
    EXPECT_EQ(reference.patches().size(), 5u * 100u + 1600u);
    const std::vector<ReferencePatch>& patches = reference.patches();
    for (size_t i = 0; i < patches.size(); i += 37) {
        double row = 0.0;
        for (size_t j = 0; j < patches.size(); ++j)
            row += reference.formFactor(i, j);
        ASSERT_NEAR(row, 1.0, 1e-9) << "patch " << i;
    }
    for (const ReferencePatch& p : patches)
        ASSERT_NEAR(p.radiosity.x, 2.0, 2e-3) << "a patch of face " << reference.faces()[size_t(p.face)].id;
    EXPECT_NEAR(reference.radiosityAt(floor, Vec3(0.01, 0.0, 0.5)).x, 2.0, 2e-3);

    PointwiseReferenceOptions unknown = coarse();
    unknown.facePatchSizes["room.body.nowhere"] = 0.05;
    EXPECT_THROW(PointwiseReference(furnace(reflectance, emission), unknown), std::invalid_argument);
    PointwiseReferenceOptions zero = coarse();
    zero.facePatchSizes["room.body.ny"] = 0.0;
    EXPECT_THROW(PointwiseReference(furnace(reflectance, emission), zero), std::invalid_argument);
}
