#pragma once
// Triangles back to B-rep faces. A model file holds triangles; a Regio scene
// holds planar convex faces, and every face costs the solver a BSP node and
// hemicube items, so the triangles of one flat wall should come back as one
// face, not as the two (or two hundred) a modelling tool wrote.
//
//   1. Corners closer than `distance` are welded into one vertex.
//   2. Triangles of no area (two corners welded, or collinear ones) and
//      repeated triangles (the same three vertices, wound the same way, in
//      one mesh) are dropped.
//      A triangle with another's corner inside one of its edges (a
//      T-junction) is split there, so that the two share an edge.
//   3. Edge-adjacent triangles of one mesh and one material whose normals
//      differ by at most `angleDegrees` and whose corners lie within
//      `distance` of the first one's plane form a group: one flat surface.
//   4. Each group is cut into convex polygons along its outline (one outer
//      loop and its holes, model::convexDecomposition), so that the
//      vertices inside a surface disappear. Where the outline is not that
//      simple (the surface touches itself at a corner), its triangles are
//      merged the way Hertel and Mehlhorn (1983) merge a triangulation:
//      across shared edges, longest first, while the union stays convex.
//      Either gives at most four times the fewest convex pieces, with the
//      model's own vertices.
//   5. Corners on a straight edge are dropped from every face that has them,
//      unless one face has a true corner there.
//
// Pure geometry: nothing of the file format, the scene or the solver.
#include "importer/triangle_soup.h"

#include <cstddef>
#include <vector>

namespace regio::importer {

struct MergeOptions {
    double angleDegrees = 1.0; // normals within this angle are one plane
    double distance = 0.001;   // metres: welding, and the distance from the plane
};

struct MergedFace {
    std::vector<int> loop; // indices into MergedModel::positions, counter-clockwise seen from the front
    int material = 0;      // as in the soup
    int mesh = 0;
};

struct MergeCounts {
    std::size_t trianglesIn = 0;
    std::size_t degenerate = 0;     // dropped: no area after welding
    std::size_t duplicate = 0;      // dropped: the same three vertices as another triangle of its mesh, same winding
    std::size_t tJunctions = 0;     // triangles split where a neighbour's corner lies inside an edge
    std::size_t weldedVertices = 0; // corners that became another corner
    std::size_t surfaces = 0;       // groups of step 3
    std::size_t faces = 0;          // faces out
};

struct MergedModel {
    std::vector<Vec3> positions;
    std::vector<MergedFace> faces;
    MergeCounts counts;
};

MergedModel mergeTriangles(const TriangleSoup& soup, const MergeOptions& options = {});

} // namespace regio::importer
