// The hemicube view of one patch (solver/visibility/hemicube_view.h): the item buffer a
// shot of that patch would paint, for the editor's hemicube window.
#include "solver/solver.h"
#include "solver/visibility/hemicube_view.h"
#include "support/sample_scenes.h"
#include "support/solver_test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace regio;
using namespace regio::solver;

namespace {

std::unique_ptr<Solver> cornellSolver(model::Visibility mode)
{
    SolverOptions options;
    options.hemicube = 64;
    options.patchSize = 0.2;
    options.elementsPerPatch = 4;
    options.visibility = mode;
    auto built = Solver::create(test::loadSample("cornell-box"), options);
    return std::move(*built);
}

} // namespace

TEST(HemicubeView, FormFactorsEqualThoseOfTheShotOfThatPatch)
{
    for (model::Visibility mode : {model::Visibility::Painter, model::Visibility::ZBuffer}) {
        auto solver = cornellSolver(mode);
        ASSERT_TRUE(solver);
        const int shooter = solver->shooting().selectShooter();
        ASSERT_GE(shooter, 0);
        // A light's shot renders twice as fine as the scene's 64 (solver/shooting/shooting.h).
        EXPECT_EQ(solver->shooting().shotResolution(shooter), 128);
        const auto view =
            renderHemicubeView(solver->prepared(), shooter, solver->shooting().shotResolution(shooter), mode);
        ASSERT_TRUE(view);
        solver->step(1);
        ASSERT_EQ(solver->shooting().lastShooter(), shooter);
        const std::vector<double>& shot = solver->shooting().lastFormFactors();
        ASSERT_EQ(view->formFactors.size(), shot.size());
        // The shot's row keeps its far factors in single precision
        // (solver/shooting/shooting.h): the same to float's rounding.
        for (size_t j = 0; j < shot.size(); ++j)
            ASSERT_NEAR(view->formFactors[j], shot[j], std::abs(shot[j]) * 1e-7) << "element " << j;
        EXPECT_DOUBLE_EQ(view->escaped, solver->shooting().lastEscapedFraction());
    }
}

TEST(HemicubeView, ThePixelsOfTheFiveFacesNameTheElementsWithAFormFactor)
{
    auto solver = cornellSolver(model::Visibility::Painter);
    ASSERT_TRUE(solver);
    const auto view = renderHemicubeView(solver->prepared(), 0, 32, model::Visibility::Painter);
    ASSERT_TRUE(view);
    std::set<ItemId> seen(view->buffer.all().begin(), view->buffer.all().end());
    double total = view->escaped + view->blocked;
    for (size_t j = 0; j < view->formFactors.size(); ++j) {
        total += view->formFactors[j];
        EXPECT_EQ(view->formFactors[j] > 0.0, seen.count(itemOfElement(static_cast<std::uint32_t>(j))) == 1)
            << "element " << j;
    }
    EXPECT_NEAR(total, 1.0, 1e-5);
    EXPECT_EQ(view->buffer.all().size(), size_t(3 * 32 * 32));
}

TEST(HemicubeView, AnUnknownPatchGivesNoView)
{
    auto solver = cornellSolver(model::Visibility::Painter);
    ASSERT_TRUE(solver);
    EXPECT_FALSE(renderHemicubeView(solver->prepared(), -1, 32, model::Visibility::Painter));
    EXPECT_FALSE(
        renderHemicubeView(solver->prepared(), int(solver->prepared().patches.size()), 32, model::Visibility::Painter));
}
