// The JSON report of a solve (`regio-solve solve --report`, solveReport()):
// its element count and refinement rounds are the solver's, and its BSP block
// holds the figures the solver's own preparation gives.
#include "output/report.h"

#include "solver/authoring/bsp_figures.h"
#include "solver/solver.h"
#include "support/adaptive_scenes.h"
#include "support/furnished_room.h"
#include "support/sample_scenes.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

using namespace regio;
using namespace regio::output;
using namespace regio::solver;

namespace {

SceneBspFigures figuresOk(const model::Scene& scene, RegionsMode mode)
{
    model::Result<SceneBspFigures> result = computeBspFigures(scene, {mode});
    EXPECT_TRUE(result.ok());
    return result.ok() ? *result : SceneBspFigures{};
}

} // namespace

TEST(AdaptiveSolver, TheReportGivesTheFinalElementCountAndTheRounds)
{
    auto built = Solver::create(test::boxUnderLamp());
    ASSERT_TRUE(built.ok());
    const int initial = (*built)->stats().elements;
    (*built)->step(20);
    const nlohmann::json report = solveReport("box under lamp", **built);
    EXPECT_EQ(report["elements"].get<int>(), (*built)->stats().elements);
    EXPECT_GT(report["elements"].get<int>(), initial);
    EXPECT_TRUE(report["adaptive"]["enabled"].get<bool>());
    EXPECT_EQ(report["adaptive"]["rounds"].get<int>(), (*built)->stats().adaptiveRounds);
    EXPECT_GT(report["adaptive"]["rounds"].get<int>(), 0);
    // The box stands on the floor: its foot's elements, and those of its
    // penumbra from the lamp, were split before the first shot.
    EXPECT_EQ(report["adaptive"]["contactElements"].get<int>(), (*built)->stats().contactElements);
    EXPECT_GT(report["adaptive"]["contactElements"].get<int>(), 0);
    EXPECT_EQ(report["adaptive"]["penumbraElements"].get<int>(), (*built)->stats().penumbraElements);
    EXPECT_GT(report["adaptive"]["penumbraElements"].get<int>(), 0);
}

TEST(BspFigures, EqualTheBspFiguresOfTheSolveReport)
{
    // `regio-solve solve --report` writes solveReport() of the solver it ran.
    for (const model::Scene& scene : {test::loadSample("two-lights-room"), test::furnishedRoom(4, 30)})
        for (RegionsMode mode : {RegionsMode::Authored, RegionsMode::None, RegionsMode::Auto}) {
            SCOPED_TRACE(regionsModeName(mode));
            SolverOptions options;
            options.regions = mode;
            model::Result<std::unique_ptr<Solver>> built = Solver::create(scene, options);
            ASSERT_TRUE(built.ok());
            const nlohmann::json bsp = solveReport("scene", **built)["bsp"];
            const SceneBspFigures figures = figuresOk(scene, mode);
            EXPECT_EQ(bsp["regions"].get<size_t>(), figures.regions.size());
            EXPECT_EQ(bsp["inputFaces"].get<int>(), figures.inputFaces);
            EXPECT_EQ(bsp["regionPieces"].get<int>(), figures.regionPieces);
            EXPECT_EQ(bsp["fragments"].get<int>(), figures.fragments);
            EXPECT_EQ(bsp["splits"].get<int>(), figures.splits);
            EXPECT_EQ(bsp["maxDepth"].get<int>(), figures.maxDepth);
            ASSERT_EQ(bsp["perRegion"].size(), figures.regions.size());
            for (size_t r = 0; r < figures.regions.size(); ++r) {
                const nlohmann::json& region = bsp["perRegion"][r];
                const BspFigures& f = figures.regions[r].figures;
                EXPECT_EQ(region["id"].get<std::string>(), figures.regions[r].id);
                EXPECT_EQ(
                    (BspFigures{region["inputFaces"].get<int>(), region["fragments"].get<int>(),
                                region["splits"].get<int>(), region["depth"].get<int>(), region["nodes"].get<int>()}),
                    f);
            }
        }
}
