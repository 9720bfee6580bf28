#pragma once
// A lit mesh's triangles cut at their edges' midpoints, round after round,
// without T-vertices: an edge is cut on both of its triangles, each
// triangle into two, three or four (by how many of its edges are cut; a
// quad left over is split along its shorter diagonal). The picture with
// the lights' direct part exact (output/exact_direct.h) cuts every edge
// once, then again where the direct part bends.
#include "output/lit_mesh.h"
#include "output/point_grid.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace regio::output {

// Where a picture goes. A model file's reader may weld corners closer than
// a millimetre (the importer does), which would fold the triangles between
// them: for files, a new corner is kept 1.25 mm from every other (a search
// that costs a quarter of a cached build); the screen needs no search.
enum class CutFor { Files, Screen };

class MidpointCut {
public:
    // The mesh to cut; its vertices keep their numbers, new ones follow.
    MidpointCut(LitMesh mesh, CutFor cutFor);
    ~MidpointCut();

    // Cuts the edges that `wanted(a, b)` picks (by their corners), where
    // the pieces stay apart: an edge at least 2.5 mm long, whose midpoint
    // lies 1.25 mm or more from the triangles' opposite corners (and, for
    // files, from every other corner, and after the first cut no piece
    // thinner than 1.05 mm). Returns the corners added.
    size_t cut(const std::function<bool(std::uint32_t, std::uint32_t)>& wanted);

    const LitMesh& mesh() const { return m_mesh; }
    LitMesh takeMesh() { return std::move(m_mesh); }
    size_t originalVertices() const { return m_original; }
    // Per vertex: the input face of its triangles (-1: in none).
    const std::vector<int>& faceOf() const { return m_faceOf; }
    // Per added vertex (the k-th after the original ones): the two
    // vertices whose midpoint it is, at 2 k and 2 k + 1.
    const std::vector<std::uint32_t>& ends() const { return m_ends; }

private:
    struct Apart;
    // The triangles' corners with every vertex numbered as the first vertex
    // of its face at its place.
    std::vector<std::uint32_t> placesOf(const std::vector<std::uint32_t>& corner) const;
    LitMesh m_mesh;
    size_t m_original = 0;
    int m_rounds = 0; // cuts so far
    std::vector<int> m_faceOf;
    std::vector<std::uint32_t> m_ends;
    // Every vertex in doubles: a corner cut from corners cut before is
    // rounded to a float once, not once per round, so that a corner on a
    // face's outline stays on the line to a file's float round-off.
    std::vector<Vec3> m_exact;
    std::unique_ptr<Apart> m_apart; // for files: every corner so far, on a grid
};

} // namespace regio::output
