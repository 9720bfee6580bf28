// Receivers close to the shooter (solver/shooting/near_field.h): Lambert's
// contour formula against the closed form, and the near factors with the
// far share that keeps every shooter element at the hemicube's total.
#include "solver/shooting/near_field.h"

#include "solver/shooting/edge_angle.h"

#include "support/adaptive_scenes.h"
#include "support/closed_forms.h"
#include "support/prepared_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <numbers>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

using test::cornerFormFactor;

namespace {

// The vertices of an element.
std::vector<Vec3> triangleOf(const PreparedScene& s, const Element& e)
{
    return {s.vertices[size_t(e.vertices[0])], s.vertices[size_t(e.vertices[1])], s.vertices[size_t(e.vertices[2])]};
}

// F(from -> to) without occlusion: the point-to-polygon factor averaged over
// `from` by the midpoint rule on a 24 x 24 grid of sub-triangles.
double meanFormFactor(const PreparedScene& s, const Element& from, const Element& to)
{
    const std::vector<Vec3> a = triangleOf(s, from), b = triangleOf(s, to);
    constexpr int n = 24;
    double sum = 0.0;
    int count = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j)
            for (int up = 0; up < (i + j + 1 < n ? 2 : 1); ++up) {
                const double u = (i + (up ? 2.0 : 1.0) / 3.0) / n, v = (j + (up ? 2.0 : 1.0) / 3.0) / n;
                sum += pointToPolygonFormFactor(a[0] + u * (a[1] - a[0]) + v * (a[2] - a[0]), from.normal, b);
                ++count;
            }
    return sum / count;
}

// A room 5 x 2.5 x 4 with a lamp panel 1 m square and 4 cm thick whose
// emitting top is 2 cm under the ceiling.
model::Scene lampUnderCeiling(double patchSize)
{
    model::Scene scene;
    test::addMaterial(scene, "wall", Rgb{0.7});
    test::addMaterial(scene, "lamp", Rgb{0.8}, Rgb{12.0});
    test::addBox(scene, "room", {0, 0, 0}, {5, 2.5, 4}, "wall", true);
    test::addBox(scene, "panel", {1.0, 2.44, 1.5}, {2.0, 2.48, 2.5}, "lamp");
    scene.solver.patchSize = patchSize;
    return scene;
}

// Every element of `s`, as a row's receivers.
std::vector<std::uint32_t> everyElement(const PreparedScene& s)
{
    std::vector<std::uint32_t> all;
    for (size_t e = 0; e < s.elements.size(); ++e)
        all.push_back(std::uint32_t(e));
    return all;
}

} // namespace

TEST(NearField, ThePointToPolygonFactorIsTheClosedFormOfARectangleOverACorner)
{
    for (const auto& [a, b, c] : {std::array{1.0, 1.0, 1.0}, std::array{2.0, 0.5, 0.3}, std::array{0.1, 3.0, 2.0}}) {
        const std::vector<Vec3> rectangle{{0, 0, c}, {0, b, c}, {a, b, c}, {a, 0, c}};
        EXPECT_NEAR(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, rectangle), cornerFormFactor(a, b, c), 1e-12);
    }
}

TEST(NearField, TheEdgeAngleIsTheArctangentToTheLastBitsOverTheWholeHalfTurn)
{
    // Angles from 1e-12 rad to pi, both sides of the branch points (0.66,
    // tan 3pi/8, a right angle), from unit vectors' sines and cosines.
    double worst = 0.0;
    for (int i = 0; i <= 200000; ++i) {
        const double t = std::numbers::pi * i / 200000.0;
        for (const double angle : {t, t + 1e-12, std::ldexp(1.0, -i % 60) * t}) {
            const double sine = std::sin(angle), cosine = std::cos(angle);
            if (sine < 0.0)
                continue;
            const double exact = std::atan2(sine, cosine);
            const double error = std::abs(edgeAngle(sine, cosine) - exact);
            worst = std::max(worst, error / std::max(exact, 1e-300));
            ASSERT_LE(error, 4e-16 * std::max(exact, 1e-300) + 1e-300) << angle;
        }
    }
    std::printf("edge angle against std::atan2: worst relative error %.2g\n", worst);
    EXPECT_EQ(edgeAngle(0.0, 1.0), 0.0);
    EXPECT_EQ(edgeAngle(1.0, 0.0), std::numbers::pi / 2.0);
    EXPECT_EQ(edgeAngle(0.0, -1.0), std::numbers::pi);
}

TEST(NearField, OnlyThePartInFrontOfThePointCounts)
{
    // A wall standing on the floor beside the point: the part below the
    // floor is cut away, and a polygon wholly behind gives nothing.
    const std::vector<Vec3> wall{{1, -1, -1}, {1, -1, 1}, {1, 1, 1}, {1, 1, -1}};
    const std::vector<Vec3> upper{{1, -1, 0}, {1, -1, 1}, {1, 1, 1}, {1, 1, 0}};
    const Vec3 up{0, 0, 1};
    EXPECT_NEAR(pointToPolygonFormFactor({0, 0, 0}, up, wall), pointToPolygonFormFactor({0, 0, 0}, up, upper), 1e-9);
    EXPECT_GT(pointToPolygonFormFactor({0, 0, 0}, up, upper), 0.01);
    const std::vector<Vec3> below{{1, -1, -2}, {1, -1, -1}, {1, 1, -1}, {1, 1, -2}};
    EXPECT_EQ(pointToPolygonFormFactor({0, 0, 0}, up, below), 0.0);
}

TEST(NearField, NearReceiversTakeTheContourFactorsAndTheFarOnesTheRestOfTheHemicubesTotal)
{
    // A floor patch beside the box: the box's side elements next to it are
    // near receivers. They keep their contour factors; every element of the
    // shooter still sends the hemicube's total, its far share scaled for it.
    const PreparedScene s = test::prepared(test::boxUnderLamp());
    int shooter = -1;
    for (size_t p = 0; p < s.patches.size() && shooter < 0; ++p)
        if (s.faces[size_t(s.patches[p].properties)].id == "floor.face" &&
            std::abs(s.patches[p].centroid.x - 0.55) < 0.3 && std::abs(s.patches[p].centroid.z) < 0.3)
            shooter = int(p);
    ASSERT_GE(shooter, 0) << "the premise: a floor patch just beside the box";
    const Patch& patch = s.patches[size_t(shooter)];
    std::vector<std::uint32_t> elements;
    std::vector<double> factors;
    for (size_t e = 0; e < s.elements.size(); ++e) {
        elements.push_back(std::uint32_t(e));
        factors.push_back(0.001 * double(e % 7 + 1)); // a hemicube's row, for the books
    }
    const std::vector<double> hemicube = factors;
    std::vector<NearTerm> near;
    std::vector<double> farScale;
    correctNearField(s, shooter, elements, factors, near, farScale);
    ASSERT_FALSE(near.empty());
    ASSERT_EQ(farScale.size(), size_t(patch.elementCount));

    std::map<std::uint32_t, bool> nearEntries;
    for (const NearTerm& t : near)
        nearEntries[t.entry] = true;
    for (const auto& [entry, _] : nearEntries) {
        EXPECT_EQ(factors[entry], 0.0);
        EXPECT_EQ(s.faces[size_t(s.elements[elements[entry]].properties)].id.rfind("box.", 0), 0u)
            << "only the box's elements face the floor patch from nearby";
    }
    // The near factors are the contour formula's mean over the shooter
    // element's points (taken on the smaller of the two elements).
    for (const NearTerm& t : near) {
        const Element& receiver = s.elements[elements[t.entry]];
        const Element& from = s.elements[size_t(patch.firstElement + t.shooterElement)];
        const double truth = meanFormFactor(s, from, receiver);
        EXPECT_NEAR(t.factor, truth, 0.005 + 0.1 * truth);
    }
    // Each shooter element: its near factors plus its far share of the rest
    // is the hemicube's total.
    double total = 0.0, far = 0.0;
    for (size_t k = 0; k < factors.size(); ++k) {
        total += hemicube[k];
        far += factors[k];
    }
    std::vector<double> sent(size_t(patch.elementCount), 0.0);
    for (const NearTerm& t : near)
        sent[size_t(t.shooterElement)] += t.factor;
    for (size_t e = 0; e < sent.size(); ++e)
        EXPECT_NEAR(sent[e] + farScale[e] * far, total, 1e-12);
}

TEST(NearField, ALampElementJustUnderALargeCeilingElementSendsItWhatItSeesOfIt)
{
    // A lamp panel 2 cm under the ceiling, its elements a few times smaller
    // than the ceiling's. From a ceiling element's centroid a lamp element
    // may fill the view or not be seen at all, wherever the two lie, so a
    // factor taken there is off by many times. The factors are the mean of
    // what the lamp element's points see of the ceiling element, within 0.05
    // of it (the contour formula at four points of the lamp element).
    const PreparedScene s = test::prepared(lampUnderCeiling(0.5));
    const std::vector<std::uint32_t> everything = everyElement(s);
    int checked = 0;
    double worst = 0.0;
    for (size_t p = 0; p < s.patches.size(); ++p) {
        const Patch& patch = s.patches[p];
        if (s.faces[size_t(patch.properties)].id != "panel.body.py")
            continue;
        std::vector<double> factors(everything.size(), 1.0 / double(everything.size())); // a total of 1
        std::vector<NearTerm> near;
        std::vector<double> farScale;
        correctNearField(s, int(p), everything, factors, near, farScale);
        double reach = 0.0; // farther out, the facing ceiling's factors follow the hemicube's
        for (int i = 0; i < 3; ++i)
            reach = std::max(reach, glm::length(s.vertices[size_t(patch.vertices[size_t((i + 1) % 3)])] -
                                                s.vertices[size_t(patch.vertices[size_t(i)])]));
        for (const NearTerm& t : near) {
            const Element& to = s.elements[everything[t.entry]];
            if (s.faces[size_t(to.properties)].id != "room.body.py" ||
                glm::length(to.centroid - patch.centroid) >= reach)
                continue;
            const Element& from = s.elements[size_t(patch.firstElement + t.shooterElement)];
            const double truth = meanFormFactor(s, from, to);
            worst = std::max(worst, std::abs(t.factor - truth));
            ++checked;
        }
    }
    EXPECT_GE(checked, 16) << "the premise: ceiling elements near the lamp's patches";
    EXPECT_LT(worst, 0.05) << "taken at a ceiling element's centroid, up to 0.75";
}

TEST(NearField, AWallPatchSendsAFacingBlockWhatTheWholePatchGivesItWithTheHemicubesVisibility)
{
    // A block 0.2 m in front of a wall of 0.25 m patches (their faces face
    // each other: InputFace::facing). Receivers on the block's side beyond
    // the patch's reach but within three times it take the whole patch's
    // factor, not the one from the patch's centre that a hemicube sees;
    // what the hemicube does not see of them stays unseen.
    const PreparedScene s = test::prepared(test::blockBesideWall());
    int shooter = -1;
    for (size_t p = 0; p < s.patches.size() && shooter < 0; ++p)
        if (s.faces[size_t(s.patches[p].properties)].id == "room.body.nx" &&
            glm::length(s.patches[p].centroid - Vec3{0, 0.3, 1.3}) < 0.15)
            shooter = int(p);
    ASSERT_GE(shooter, 0) << "the premise: a wall patch in front of the block";
    const Patch& patch = s.patches[size_t(shooter)];
    Element whole;
    whole.vertices = patch.vertices;
    whole.normal = s.properties[size_t(patch.properties)].plane.normal;
    double reach = 0.0;
    for (int i = 0; i < 3; ++i)
        reach = std::max(reach, glm::length(s.vertices[size_t(patch.vertices[size_t((i + 1) % 3)])] -
                                            s.vertices[size_t(patch.vertices[size_t(i)])]));

    // An ideal hemicube: the factor from the patch's centre, every receiver
    // seen whole but one, of which it sees half.
    std::vector<std::uint32_t> elements;
    std::vector<double> factors;
    size_t halfSeen = 0;
    for (size_t e = 0; e < s.elements.size(); ++e) {
        const double f = pointToPolygonFormFactor(patch.centroid, whole.normal, triangleOf(s, s.elements[e]));
        if (f <= 0.0)
            continue;
        const double distance = glm::length(s.elements[e].centroid - patch.centroid);
        if (!halfSeen && s.faces[size_t(s.elements[e].properties)].id == "block.body.nx" && distance > reach &&
            distance < 2.0 * reach)
            halfSeen = elements.size();
        elements.push_back(std::uint32_t(e));
        factors.push_back(f);
    }
    ASSERT_GT(halfSeen, 0u);
    factors[halfSeen] *= 0.5;
    const std::vector<double> hemicube = factors;
    std::vector<NearTerm> near;
    std::vector<double> farScale;
    correctNearField(s, shooter, elements, factors, near, farScale);

    std::map<std::uint32_t, double> received; // F(patch -> receiver) from the near terms
    for (const NearTerm& t : near)
        received[t.entry] += t.factor * s.elements[size_t(patch.firstElement + t.shooterElement)].area / patch.area;
    int checked = 0;
    double worstCentre = 0.0, worst = 0.0;
    for (const auto& [entry, factor] : received) {
        const Element& e = s.elements[elements[entry]];
        const double distance = glm::length(e.centroid - patch.centroid);
        if (distance < reach)
            continue;
        EXPECT_EQ(s.faces[size_t(e.properties)].id, "block.body.nx") << "only the facing face, farther out";
        EXPECT_LT(distance, kFacingReach * reach);
        EXPECT_EQ(factors[entry], 0.0) << "its hemicube factor is taken over by the near terms";
        const double seen = entry == halfSeen ? 0.5 : 1.0;
        const double truth = seen * meanFormFactor(s, whole, e);
        worst = std::max(worst, std::abs(factor / truth - 1.0));
        worstCentre = std::max(worstCentre, std::abs(hemicube[entry] / truth - 1.0));
        ++checked;
    }
    EXPECT_GE(checked, 12) << "the premise: the block's side beyond the patch's reach";
    EXPECT_GT(worstCentre, 0.05) << "the premise: the patch's centre is off for some";
    EXPECT_LT(worst, 0.01) << "the centre: " << worstCentre;
    EXPECT_LT(worst, worstCentre / 5.0);
    std::printf("facing receivers: %d, worst %.4f, from the centre %.4f\n", checked, worst, worstCentre);
}

TEST(NearField, GivesTheSameRowBitForBitWhenItsContourFormulaRunsOnSeveralThreads)
{
    // A room of a lamp 2 cm under its ceiling: hundreds of near receivers
    // per lamp patch, in many chunks. The chunks run in reverse order on
    // purpose; the terms must come out in the receivers' order all the same.
    model::Scene scene = lampUnderCeiling(0.25);
    test::addBox(scene, "block", {0.2, 0, 1}, {0.8, 0.6, 1.6}, "wall"); // and a block with facing faces
    const PreparedScene s = test::prepared(scene);
    const std::vector<std::uint32_t> everything = everyElement(s);
    const ParallelFor backwards = [](size_t count, const std::function<void(size_t, size_t)>& body) {
        for (size_t c = count; c-- > 0;)
            body(c, c + 1);
    };
    int rowsWithManyChunks = 0;
    for (size_t p = 0; p < s.patches.size(); p += 7) {
        std::vector<double> one(everything.size(), 1.0 / double(everything.size()));
        std::vector<double> many = one;
        std::vector<NearTerm> nearOne, nearMany;
        std::vector<double> farOne, farMany;
        correctNearField(s, int(p), everything, one, nearOne, farOne);
        correctNearField(s, int(p), everything, many, nearMany, farMany, backwards);
        rowsWithManyChunks += nearOne.size() > 3 * 64;
        ASSERT_EQ(nearMany.size(), nearOne.size());
        for (size_t t = 0; t < nearOne.size(); ++t) {
            EXPECT_EQ(nearMany[t].entry, nearOne[t].entry);
            EXPECT_EQ(nearMany[t].shooterElement, nearOne[t].shooterElement);
            EXPECT_EQ(nearMany[t].factor, nearOne[t].factor);
        }
        EXPECT_EQ(many, one);
        EXPECT_EQ(farMany, farOne);
    }
    EXPECT_GT(rowsWithManyChunks, 4) << "the premise: rows whose near receivers fill several chunks";
}
