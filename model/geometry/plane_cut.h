#pragma once
// The plane cut: one part becomes two, in front of and behind a plane. It is
// how an author turns a single solid into the paper's whole-part model ("a
// table ... as a whole-part model of a desk and legs", §2), where separating
// planes between regions are easier to find, and how a part straddling a
// region boundary is clipped to the regions.
//
// Every face is clipped by the plane (splitPolygon) and the pieces keep their
// material. Vertices are welded within kDistanceEpsilon, so the pieces of two
// neighbouring faces share their new corner and each side is manifold where
// the input was. A face lying in the plane goes to the side its solid is on
// (the side its normal points away from).
//
// Caps. When the input part is closed, each side is closed again by cap faces
// built from the cut: the boundary left open on that side is chained into
// loops, and each loop (with the holes it encloses, e.g. a tube cut across) is
// split into convex pieces - ear clipping, then Hertel-Mehlhorn merging of
// the triangles back into convex polygons - using only the loop's own
// vertices, so cap edges match the side faces' edges exactly. Collinear loop
// vertices (corners of side faces along a straight cut line) stay on the cap
// edges. A convex part gets one convex cap per side. Open parts (walls) and
// CutCaps::Open get no caps: clipping a room to regions must not build a wall.
//
// Face ids. Pieces take the id of their source face with the source part's id
// prefix replaced by the new part's id: cutting "table.slab" into "table.desk"
// and "table.legs" turns face "table.slab.top" into "table.desk.top" (and,
// were it cut, "table.legs.top"); a face id without the prefix gets the new
// part id prepended ("top" -> "table.desk.top"). Caps are "<new part>.cut",
// or "<new part>.cut1", ".cut2", ... when a side has several. Any clash is
// resolved with "-2", "-3", ... Cap faces have no material of their own: they
// take the part's material.
#include "model/geometry/geometry.h"
#include "model/result.h"
#include "model/scene.h"

#include <string>
#include <vector>

namespace regio::model {

enum class CutCaps { Close, Open };

struct PlaneCut {
    Part front; // on the side the plane's normal points to
    Part back;
    // For each source face, in source order: the ids of its pieces, the front
    // piece first. A face that lies on one side has one piece.
    struct FacePieces {
        std::string sourceId;
        std::vector<std::string> pieceIds;
        bool operator==(const FacePieces&) const = default;
    };
    std::vector<FacePieces> pieces;
    std::vector<std::string> frontCaps;
    std::vector<std::string> backCaps;
};

// Refused (with a diagnostic) when the ids are empty or equal, the plane is
// not finite, the part has a broken loop, or the plane misses the part (no
// vertex strictly on each side; touching a face or an edge counts as missing).
Result<PlaneCut> splitPart(const Part& part, const Plane& plane, const std::string& frontId, const std::string& backId,
                           CutCaps caps = CutCaps::Close);

// The id rule above, for one face: `faceId` of `sourcePartId` moved to `newPartId`.
std::string cutPieceId(const std::string& faceId, const std::string& sourcePartId, const std::string& newPartId);

} // namespace regio::model
