#pragma once
// Clipping a part to the region boxes: the one-click fix for a part that
// straddles region boundaries (validation's warning). The solver would clip
// its faces at the separating planes anyway (the Warnock variant, paper §3);
// doing it in the model instead makes the cut visible and lets each piece be
// ordered in its own region's BSP order (§5.3), as the paper's whole-part
// modelling intends ("we can split each object into several logical parts and
// even cut it into small pieces", §3).
//
// The part is cut with the plane cut (splitPartInScene) down the tree of
// planes that separate the region boxes (found on limit lists, as the
// solver's regional tree finds its planes, §5.2): at each level what sticks
// out of the bounds of the level's boxes is cut away first (it lies outside
// every region), then the piece is cut by the separating plane if it crosses
// it. So a part inside the union of the boxes falls into exactly one piece
// per region it reaches, whatever the layout of the boxes.
// Solids (closed, normals out) get caps (CutCaps::Close); open parts (walls)
// and closed shells facing inwards (a room, makeRoom) stay open: capping a
// room would build walls across it at the region boundaries. The
// final pieces are named after their region: "table" clipped to regions
// "middle" and "east" becomes parts "table-middle" and "table-east" with faces
// "table-middle.top", ...; a piece outside every box is "table-outside". BSP
// orders that named a cut face name its pieces, except pieces that left the
// region's box (an order may only name faces inside its region).
//
// Undo: unclipPart(scene, clip) restores the exact scene.
#include "model/edit/edit_parts.h"
#include "model/geometry/geometry.h"
#include "model/result.h"
#include "model/scene.h"

#include <span>
#include <string>
#include <utility>
#include <vector>

namespace regio::model {

// Area of a polygon inside a box (the polygon clipped by the box's six planes).
double polygonAreaInBox(std::span<const Vec3> loop, const Box3& box);
// Validation's rule for "the face is in the region": at least kMinFaceArea of
// it lies inside the box. A BSP order may only name such faces.
bool faceTouchesRegionBox(std::span<const Vec3> loop, const Box3& box);

// Validation's straddle rule for one part: it lies inside no region box but
// has faces inside at least one.
bool partStraddlesRegions(const Scene& scene, const Part& part);

struct RegionClip {
    std::string partId;            // the part that was clipped
    std::vector<PartSplit> splits; // in the order applied
    // Final renames (temporary piece ids -> region names), in the order applied.
    std::vector<std::pair<std::string, std::string>> partRenames;
    std::vector<std::pair<std::string, std::string>> faceRenames;
    BspOrderSnapshots bspOrders;       // orders before pieces outside their region left them
    std::vector<std::string> pieces;   // the resulting parts, in object order
    std::vector<std::string> capFaces; // faces of the pieces made by the cuts (closed parts only)

    bool operator==(const RegionClip&) const = default;
};

// Refused (scene unchanged) when the part is unknown, does not straddle region
// boundaries (inside one box, or outside all), or a cut fails.
Result<RegionClip> clipPartToRegions(Scene& scene, const std::string& partId);
// Undoes clipPartToRegions: the pieces go, the part and the orders return.
Result<Unit> unclipPart(Scene& scene, const RegionClip& clip);

} // namespace regio::model
