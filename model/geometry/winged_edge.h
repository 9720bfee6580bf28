#pragma once
// The winged-edge structure of one part (paper §4): derived topology built
// from the face loops, never stored in the scene file. Every edge knows its two
// vertices, the face on each side and the four "wing" edges that precede and
// follow it in those faces' loops. It answers neighbour queries for the editor
// and the solver and tells validation whether a part is closed, manifold and
// consistently wound.
//
// Conventions. Face loops run counter-clockwise seen from the side the normal
// points to. An edge is stored once per unordered vertex pair; its direction
// v0 -> v1 is the direction in which its first face (in face order) traverses
// it, and that face is its left face. In a consistently wound part the right
// face traverses it v1 -> v0. Faces and vertices are positions in the part.
//
// Building never throws and accepts any input: faces whose loop is unusable
// (fewer than 3 vertices, an index out of range, a repeated vertex) are left
// out of the topology, and every defect is listed in problems().
#include "model/scene.h"

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace regio::model {

struct TopologyProblem {
    enum class Kind {
        LoopTooShort,        // fewer than 3 loop entries
        VertexOutOfRange,    // loop entry < 0 or >= vertex count
        RepeatedVertex,      // a vertex appears twice in one loop
        NonManifoldEdge,     // an edge used by more than two faces
        InconsistentWinding, // two faces traverse an edge in the same direction
    };
    Kind kind = Kind::LoopTooShort;
    // The face the problem is reported on: the offending face for loop
    // problems, the face that made the edge bad (the later one) for edge problems.
    int face = -1;
    int loopPosition = -1;  // loop problems: the offending position in the loop
    int edge = -1;          // edge problems: the edge index
    std::vector<int> faces; // edge problems: every face using the edge, ascending
};

class WingedEdgeMesh {
public:
    struct Edge {
        int v0 = -1;
        int v1 = -1;
        int leftFace = -1;  // traverses v0 -> v1
        int rightFace = -1; // the other face; -1 on a boundary edge
        // The four wings: the edges before and after this one in each face's loop.
        int leftPrev = -1;
        int leftNext = -1;
        int rightPrev = -1;
        int rightNext = -1;

        bool isBoundary() const { return rightFace < 0; }
        int otherVertex(int v) const { return v == v0 ? v1 : v0; }
    };

    WingedEdgeMesh() = default;
    static WingedEdgeMesh build(const Part& part);
    // Same, from bare loops over `vertexCount` vertices (e.g. solver fragments).
    static WingedEdgeMesh build(int vertexCount, std::span<const std::vector<int>> loops);

    int vertexCount() const { return m_vertexCount; }
    int faceCount() const { return int(m_faceEdge.size()); }
    int edgeCount() const { return int(m_edges.size()); }
    const std::vector<Edge>& edges() const { return m_edges; }
    const Edge& edge(int e) const { return m_edges[size_t(e)]; }

    // False for faces left out because of a loop problem.
    bool faceInTopology(int f) const { return m_faceEdge[size_t(f)] >= 0; }
    // One incident edge per face / per vertex; -1 if none.
    int faceEdge(int f) const { return m_faceEdge[size_t(f)]; }
    int vertexEdge(int v) const { return m_vertexEdge[size_t(v)]; }

    // Edges of a face in loop order: entry i joins loop[i] and loop[i + 1].
    std::span<const int> edgesOfFace(int f) const;
    // The wings seen from face f: the edge after / before e in f's loop; -1 if
    // e is not an edge of f.
    int nextEdgeInFace(int f, int e) const;
    int prevEdgeInFace(int f, int e) const;
    // Every face using edge e (two for an interior manifold edge), ascending.
    std::span<const int> facesOfEdge(int e) const;
    // The face across edge e from f; -1 on a boundary (for a non-manifold
    // edge: the first other face).
    int faceAcross(int f, int e) const;
    // Distinct faces sharing an edge with f, in f's loop order.
    std::vector<int> facesAdjacentTo(int f) const;

    // Edges around a vertex. Where the vertex is manifold they come in
    // rotational order: counter-clockwise seen from the side the normals point
    // to when the winding is consistent, and starting at a boundary edge when
    // the fan is open. Elsewhere the ordered fan through vertexEdge(v) comes
    // first, then the remaining edges in index order.
    std::vector<int> edgesAroundVertex(int v) const;
    // Faces around a vertex, in the same rotational order.
    std::vector<int> facesAroundVertex(int v) const;
    // The fan of faces around v is a single disc or half-disc.
    bool isVertexManifold(int v) const { return m_vertexManifold[size_t(v)] != 0; }

    // The edge joining a and b in either direction; -1 if none.
    int findEdge(int a, int b) const;
    std::vector<int> boundaryEdges() const;
    std::vector<int> nonManifoldEdges() const;

    // Every edge has exactly two faces (and there is at least one face).
    bool isClosed() const;
    // No edge has more than two faces and every vertex fan is a single disc.
    bool isManifold() const;
    // No two faces traverse an edge in the same direction.
    bool hasConsistentWinding() const { return m_windingProblems == 0; }

    // The smallest set of faces whose loops must be reversed to make the
    // winding consistent: in each connected piece (joined through manifold
    // edges) the faces oriented against the majority. `orientable` is false
    // when some piece cannot be wound consistently at all (a Moebius band).
    struct WindingRepair {
        std::vector<int> facesToFlip;
        bool orientable = true;
    };
    WindingRepair windingRepair() const;

    const std::vector<TopologyProblem>& problems() const { return m_problems; }

private:
    void buildEdges(std::span<const std::vector<int>> loops);
    void buildVertexFans();
    // The other edge of face f at vertex v (v an endpoint of e), or -1.
    int otherEdgeAt(int f, int e, int v) const;
    std::vector<int> walkFan(int v, std::vector<int>* faces) const;

    int m_vertexCount = 0;
    std::vector<Edge> m_edges;
    std::vector<int> m_faceEdge;   // per face, one edge (-1: not in the topology)
    std::vector<int> m_vertexEdge; // per vertex, one edge (-1: isolated)
    // Compressed rows: edges of each face in loop order, uses of each edge,
    // edges incident to each vertex.
    std::vector<int> m_faceEdgeStart, m_faceEdgeList;
    std::vector<int> m_edgeUseStart, m_edgeUseFace;
    std::vector<char> m_edgeUseForward; // the use traverses its edge v0 -> v1
    std::vector<int> m_vertexEdgeStart, m_vertexEdgeList;
    std::vector<char> m_vertexManifold;
    std::unordered_map<std::uint64_t, int> m_edgeIndex; // (min, max) vertex pair -> edge
    std::vector<TopologyProblem> m_problems;
    int m_windingProblems = 0;
    int m_nonManifoldEdges = 0;
};

} // namespace regio::model
