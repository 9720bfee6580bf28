// Faces that stand close in front of each other (solver/prepare/facing_faces.h).
#include "solver/prepare/facing_faces.h"

#include "support/adaptive_scenes.h"
#include "support/prepared_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace regio;
using namespace regio::solver;
using model::Vec3;

namespace {

std::vector<Vec3> rectangle(double x0, double x1, double y0, double y1, double z)
{
    return {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
}

bool paired(const PreparedScene& s, const std::vector<std::vector<int>>& facing, const std::string& a,
            const std::string& b)
{
    const std::vector<int>& list = facing[test::faceNamed(s, a)];
    return std::find(list.begin(), list.end(), int(test::faceNamed(s, b))) != list.end();
}

} // namespace

TEST(FacingFaces, TheGapBetweenTwoPolygonsIsTheirShortestDistance)
{
    const std::vector<Vec3> floor = rectangle(0, 1, 0, 1, 0);
    // Straight above: the distance of the planes.
    EXPECT_NEAR(polygonGap(floor, rectangle(0.2, 0.8, 0.2, 0.8, 0.3)), 0.3, 1e-12);
    // Above and beside: from edge to edge.
    EXPECT_NEAR(polygonGap(floor, rectangle(2, 3, 0, 1, 0.3)), std::sqrt(1.0 + 0.09), 1e-12);
    // Two boards laid crosswise: no corner of either lies over the other.
    EXPECT_NEAR(polygonGap(rectangle(0, 1, 0.45, 0.55, 0), rectangle(0.45, 0.55, 0, 1, 0.2)), 0.2, 1e-12);
    // Touching along an edge.
    const std::vector<Vec3> wall{{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}};
    EXPECT_NEAR(polygonGap(floor, wall), 0.0, 1e-12);
}

TEST(FacingFaces, ABlockAHandsWidthFromAWallFacesItAndNotTheFloorItStandsOn)
{
    // 0.25 m patches, so faces facing up to 0.75 m apart; the block stands
    // 0.2 m from the west wall and 1.9 m under the ceiling.
    const PreparedScene s = test::prepared(test::blockBesideWall());
    const std::vector<std::vector<int>> facing = closeFacingFaces(s, kFacingGapPatches * s.patchSize);

    EXPECT_TRUE(paired(s, facing, "block.body.nx", "room.body.nx")) << "0.2 m across";
    EXPECT_TRUE(paired(s, facing, "room.body.nx", "block.body.nx")) << "both ways";
    EXPECT_FALSE(paired(s, facing, "block.body.ny", "room.body.ny")) << "standing on it: a contact, not a gap";
    EXPECT_FALSE(paired(s, facing, "block.body.py", "room.body.py")) << "1.9 m: farther than three patches";
    EXPECT_FALSE(paired(s, facing, "block.body.nz", "room.body.nx")) << "at right angles";
    EXPECT_FALSE(paired(s, facing, "block.body.px", "room.body.nx")) << "turning its back";
    EXPECT_FALSE(paired(s, facing, "block.body.nz", "room.body.nz")) << "1 m: farther than three patches";
    for (size_t f = 0; f < s.faces.size(); ++f)
        EXPECT_EQ(s.faces[f].facing, facing[f]) << "the prepared scene keeps them: " << s.faces[f].id;
}
