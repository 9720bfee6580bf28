#include "model/geometry/winged_edge.h"

#include "model/geometry/edge_key.h"

#include <algorithm>
#include <unordered_set>

namespace regio::model {

namespace {

bool touches(const WingedEdgeMesh::Edge& edge, int v) { return edge.v0 == v || edge.v1 == v; }

// Appends the loop problems of one face; true when the loop is usable.
bool checkLoop(int face, const std::vector<int>& loop, int vertexCount, std::vector<TopologyProblem>& problems)
{
    bool usable = true;
    if (loop.size() < 3) {
        problems.push_back({TopologyProblem::Kind::LoopTooShort, face, -1, -1, {}});
        usable = false;
    }
    for (size_t i = 0; i < loop.size(); ++i) {
        if (loop[i] < 0 || loop[i] >= vertexCount) {
            problems.push_back({TopologyProblem::Kind::VertexOutOfRange, face, int(i), -1, {}});
            usable = false;
        }
    }
    // Sorting (value, position) pairs finds every later occurrence of a
    // vertex in O(n log n), whatever the loop length.
    std::vector<std::pair<int, int>> sorted;
    sorted.reserve(loop.size());
    for (size_t i = 0; i < loop.size(); ++i)
        sorted.emplace_back(loop[i], int(i));
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> repeats;
    for (size_t i = 1; i < sorted.size(); ++i)
        if (sorted[i].first == sorted[i - 1].first)
            repeats.push_back(sorted[i].second);
    std::sort(repeats.begin(), repeats.end());
    for (int position : repeats)
        problems.push_back({TopologyProblem::Kind::RepeatedVertex, face, position, -1, {}});
    return usable && repeats.empty();
}

} // namespace

WingedEdgeMesh WingedEdgeMesh::build(const Part& part)
{
    std::vector<std::vector<int>> loops;
    loops.reserve(part.faces.size());
    for (const Face& face : part.faces)
        loops.push_back(face.loop);
    return build(int(part.vertices.size()), loops);
}

WingedEdgeMesh WingedEdgeMesh::build(int vertexCount, std::span<const std::vector<int>> loops)
{
    WingedEdgeMesh mesh;
    mesh.m_vertexCount = std::max(vertexCount, 0);
    mesh.buildEdges(loops);
    mesh.buildVertexFans();
    return mesh;
}

void WingedEdgeMesh::buildEdges(std::span<const std::vector<int>> loops)
{
    const int faceCount = int(loops.size());
    m_faceEdge.assign(size_t(faceCount), -1);
    m_vertexEdge.assign(size_t(m_vertexCount), -1);
    m_faceEdgeStart.assign(size_t(faceCount) + 1, 0);

    // Pass 1: one edge per vertex pair, the faces' edge rows, and every use of
    // an edge (face, direction) in face order.
    struct PendingUse {
        int edge;
        int face;
        bool forward;
    };
    std::vector<PendingUse> uses;
    size_t totalCorners = 0;
    for (const auto& loop : loops)
        totalCorners += loop.size();
    uses.reserve(totalCorners);
    m_faceEdgeList.reserve(totalCorners);
    m_edges.reserve(totalCorners / 2 + 1);
    m_edgeIndex.reserve(totalCorners / 2 + 1);

    for (int f = 0; f < faceCount; ++f) {
        m_faceEdgeStart[size_t(f)] = int(m_faceEdgeList.size());
        const std::vector<int>& loop = loops[size_t(f)];
        if (!checkLoop(f, loop, m_vertexCount, m_problems))
            continue;
        const size_t n = loop.size();
        for (size_t i = 0; i < n; ++i) {
            int a = loop[i];
            int b = loop[(i + 1) % n];
            auto [it, fresh] = m_edgeIndex.try_emplace(undirectedEdgeKey(a, b), int(m_edges.size()));
            if (fresh) {
                Edge edge;
                edge.v0 = a;
                edge.v1 = b;
                m_edges.push_back(edge);
            }
            int e = it->second;
            m_faceEdgeList.push_back(e);
            uses.push_back({e, f, m_edges[size_t(e)].v0 == a});
        }
        m_faceEdge[size_t(f)] = m_faceEdgeList[size_t(m_faceEdgeStart[size_t(f)])];
    }
    m_faceEdgeStart[size_t(faceCount)] = int(m_faceEdgeList.size());

    // Pass 2: group the uses by edge (counting sort keeps face order).
    const size_t edgeCount = m_edges.size();
    m_edgeUseStart.assign(edgeCount + 1, 0);
    for (const PendingUse& use : uses)
        ++m_edgeUseStart[size_t(use.edge) + 1];
    for (size_t e = 0; e < edgeCount; ++e)
        m_edgeUseStart[e + 1] += m_edgeUseStart[e];
    m_edgeUseFace.assign(uses.size(), -1);
    m_edgeUseForward.assign(uses.size(), 0);
    {
        std::vector<int> cursor(m_edgeUseStart.begin(), m_edgeUseStart.end() - 1);
        for (const PendingUse& use : uses) {
            int slot = cursor[size_t(use.edge)]++;
            m_edgeUseFace[size_t(slot)] = use.face;
            m_edgeUseForward[size_t(slot)] = use.forward ? 1 : 0;
        }
    }

    // Pass 3: the faces on each side of every edge, and its defects.
    for (size_t e = 0; e < edgeCount; ++e) {
        Edge& edge = m_edges[e];
        const int begin = m_edgeUseStart[e];
        const int count = m_edgeUseStart[e + 1] - begin;
        edge.leftFace = m_edgeUseFace[size_t(begin)]; // the first use defines v0 -> v1
        if (count == 2) {
            edge.rightFace = m_edgeUseFace[size_t(begin) + 1];
            if (m_edgeUseForward[size_t(begin) + 1]) {
                ++m_windingProblems;
                m_problems.push_back({TopologyProblem::Kind::InconsistentWinding,
                                      edge.rightFace,
                                      -1,
                                      int(e),
                                      {edge.leftFace, edge.rightFace}});
            }
        } else if (count > 2) {
            ++m_nonManifoldEdges;
            edge.rightFace = m_edgeUseFace[size_t(begin) + 1];
            for (int u = begin + 1; u < begin + count; ++u) {
                if (!m_edgeUseForward[size_t(u)]) {
                    edge.rightFace = m_edgeUseFace[size_t(u)];
                    break;
                }
            }
            // The faces of edge e as facesOfEdge gives them: its row of uses.
            const auto faces = std::span<const int>(m_edgeUseFace).subspan(size_t(begin), size_t(count));
            m_problems.push_back({TopologyProblem::Kind::NonManifoldEdge, faces[2], -1, int(e),
                                  std::vector<int>(faces.begin(), faces.end())});
        }
        if (m_vertexEdge[size_t(edge.v0)] < 0)
            m_vertexEdge[size_t(edge.v0)] = int(e);
        if (m_vertexEdge[size_t(edge.v1)] < 0)
            m_vertexEdge[size_t(edge.v1)] = int(e);
    }

    // Pass 4: the wings, from each face's row of edges.
    for (int f = 0; f < faceCount; ++f) {
        const int begin = m_faceEdgeStart[size_t(f)];
        const int n = m_faceEdgeStart[size_t(f) + 1] - begin;
        for (int i = 0; i < n; ++i) {
            int e = m_faceEdgeList[size_t(begin + i)];
            int prev = m_faceEdgeList[size_t(begin + (i + n - 1) % n)];
            int next = m_faceEdgeList[size_t(begin + (i + 1) % n)];
            Edge& edge = m_edges[size_t(e)];
            if (edge.leftFace == f) {
                edge.leftPrev = prev;
                edge.leftNext = next;
            } else if (edge.rightFace == f) {
                edge.rightPrev = prev;
                edge.rightNext = next;
            }
        }
    }
}

void WingedEdgeMesh::buildVertexFans()
{
    const size_t vertexCount = size_t(m_vertexCount);
    m_vertexEdgeStart.assign(vertexCount + 1, 0);
    for (const Edge& edge : m_edges) {
        ++m_vertexEdgeStart[size_t(edge.v0) + 1];
        ++m_vertexEdgeStart[size_t(edge.v1) + 1];
    }
    for (size_t v = 0; v < vertexCount; ++v)
        m_vertexEdgeStart[v + 1] += m_vertexEdgeStart[v];
    m_vertexEdgeList.assign(size_t(m_vertexEdgeStart[vertexCount]), -1);
    std::vector<int> cursor(m_vertexEdgeStart.begin(), m_vertexEdgeStart.end() - 1);
    for (size_t e = 0; e < m_edges.size(); ++e) {
        m_vertexEdgeList[size_t(cursor[size_t(m_edges[e].v0)]++)] = int(e);
        m_vertexEdgeList[size_t(cursor[size_t(m_edges[e].v1)]++)] = int(e);
    }

    m_vertexManifold.assign(vertexCount, 1);
    for (size_t v = 0; v < vertexCount; ++v) {
        const int begin = m_vertexEdgeStart[v];
        const int degree = m_vertexEdgeStart[v + 1] - begin;
        if (degree == 0)
            continue;
        bool manifold = true;
        for (int i = 0; i < degree && manifold; ++i)
            if (facesOfEdge(m_vertexEdgeList[size_t(begin + i)]).size() > 2)
                manifold = false;
        if (manifold) {
            std::vector<int> fan = walkFan(int(v), nullptr);
            std::sort(fan.begin(), fan.end());
            manifold = int(fan.size()) == degree && std::adjacent_find(fan.begin(), fan.end()) == fan.end();
        }
        m_vertexManifold[v] = manifold ? 1 : 0;
    }
}

std::span<const int> WingedEdgeMesh::edgesOfFace(int f) const
{
    if (f < 0 || f >= faceCount())
        return {};
    const int begin = m_faceEdgeStart[size_t(f)];
    const int end = m_faceEdgeStart[size_t(f) + 1];
    return std::span<const int>(m_faceEdgeList).subspan(size_t(begin), size_t(end - begin));
}

int WingedEdgeMesh::nextEdgeInFace(int f, int e) const
{
    if (e < 0 || e >= edgeCount())
        return -1;
    const Edge& edge = m_edges[size_t(e)];
    if (edge.leftFace == f)
        return edge.leftNext;
    if (edge.rightFace == f)
        return edge.rightNext;
    // A third face of a non-manifold edge has no wing slot: use its row.
    auto row = edgesOfFace(f);
    for (size_t i = 0; i < row.size(); ++i)
        if (row[i] == e)
            return row[(i + 1) % row.size()];
    return -1;
}

int WingedEdgeMesh::prevEdgeInFace(int f, int e) const
{
    if (e < 0 || e >= edgeCount())
        return -1;
    const Edge& edge = m_edges[size_t(e)];
    if (edge.leftFace == f)
        return edge.leftPrev;
    if (edge.rightFace == f)
        return edge.rightPrev;
    auto row = edgesOfFace(f);
    for (size_t i = 0; i < row.size(); ++i)
        if (row[i] == e)
            return row[(i + row.size() - 1) % row.size()];
    return -1;
}

std::span<const int> WingedEdgeMesh::facesOfEdge(int e) const
{
    if (e < 0 || e >= edgeCount())
        return {};
    const int begin = m_edgeUseStart[size_t(e)];
    const int end = m_edgeUseStart[size_t(e) + 1];
    return std::span<const int>(m_edgeUseFace).subspan(size_t(begin), size_t(end - begin));
}

int WingedEdgeMesh::faceAcross(int f, int e) const
{
    for (int g : facesOfEdge(e))
        if (g != f)
            return g;
    return -1;
}

std::vector<int> WingedEdgeMesh::facesAdjacentTo(int f) const
{
    std::vector<int> result;
    for (int e : edgesOfFace(f))
        for (int g : facesOfEdge(e))
            if (g != f && std::find(result.begin(), result.end(), g) == result.end())
                result.push_back(g);
    return result;
}

int WingedEdgeMesh::otherEdgeAt(int f, int e, int v) const
{
    // In a loop without repeated vertices the edge before e shares e's first
    // vertex and the edge after it shares the second, so exactly one of the
    // two wings in f meets v.
    int prev = prevEdgeInFace(f, e);
    if (prev >= 0 && prev != e && touches(m_edges[size_t(prev)], v))
        return prev;
    int next = nextEdgeInFace(f, e);
    if (next >= 0 && next != e && touches(m_edges[size_t(next)], v))
        return next;
    return -1;
}

std::vector<int> WingedEdgeMesh::walkFan(int v, std::vector<int>* faces) const
{
    const int start = m_vertexEdge[size_t(v)];
    if (start < 0)
        return {};
    const int degree = m_vertexEdgeStart[size_t(v) + 1] - m_vertexEdgeStart[size_t(v)];
    const Edge& first = m_edges[size_t(start)];
    // Leaving v along `start`, the face that traverses it away from v lies
    // counter-clockwise of it (seen from the normal side): walk that way first.
    const int ccwFace = first.v0 == v ? first.leftFace : first.rightFace;
    const int cwFace = first.v0 == v ? first.rightFace : first.leftFace;

    auto walk = [&](int face, std::vector<int>& edges, std::vector<int>& walked) {
        int current = start;
        for (int step = 0; step < degree && face >= 0; ++step) {
            walked.push_back(face);
            int next = otherEdgeAt(face, current, v);
            if (next < 0 || next == start)
                return next == start;
            edges.push_back(next);
            face = faceAcross(face, next);
            current = next;
        }
        return false;
    };

    std::vector<int> forward, forwardFaces;
    const bool closed = walk(ccwFace, forward, forwardFaces);
    std::vector<int> result;
    std::vector<int> resultFaces;
    if (closed) {
        result.push_back(start);
        result.insert(result.end(), forward.begin(), forward.end());
        resultFaces = std::move(forwardFaces);
    } else {
        std::vector<int> backward, backwardFaces;
        walk(cwFace, backward, backwardFaces);
        result.assign(backward.rbegin(), backward.rend());
        result.push_back(start);
        result.insert(result.end(), forward.begin(), forward.end());
        resultFaces.assign(backwardFaces.rbegin(), backwardFaces.rend());
        resultFaces.insert(resultFaces.end(), forwardFaces.begin(), forwardFaces.end());
    }
    if (faces)
        *faces = std::move(resultFaces);
    return result;
}

std::vector<int> WingedEdgeMesh::edgesAroundVertex(int v) const
{
    if (v < 0 || v >= m_vertexCount)
        return {};
    std::vector<int> fan = walkFan(v, nullptr);
    if (m_vertexManifold[size_t(v)])
        return fan;
    std::vector<int> result;
    std::unordered_set<int> seen;
    for (int e : fan)
        if (seen.insert(e).second)
            result.push_back(e);
    for (int i = m_vertexEdgeStart[size_t(v)]; i < m_vertexEdgeStart[size_t(v) + 1]; ++i)
        if (seen.insert(m_vertexEdgeList[size_t(i)]).second)
            result.push_back(m_vertexEdgeList[size_t(i)]);
    return result;
}

std::vector<int> WingedEdgeMesh::facesAroundVertex(int v) const
{
    if (v < 0 || v >= m_vertexCount)
        return {};
    std::vector<int> faces;
    walkFan(v, &faces);
    if (m_vertexManifold[size_t(v)])
        return faces;
    std::vector<int> result;
    std::unordered_set<int> seen;
    for (int f : faces)
        if (seen.insert(f).second)
            result.push_back(f);
    for (int i = m_vertexEdgeStart[size_t(v)]; i < m_vertexEdgeStart[size_t(v) + 1]; ++i)
        for (int f : facesOfEdge(m_vertexEdgeList[size_t(i)]))
            if (seen.insert(f).second)
                result.push_back(f);
    return result;
}

int WingedEdgeMesh::findEdge(int a, int b) const
{
    if (a < 0 || b < 0 || a >= m_vertexCount || b >= m_vertexCount)
        return -1;
    auto it = m_edgeIndex.find(undirectedEdgeKey(a, b));
    return it == m_edgeIndex.end() ? -1 : it->second;
}

std::vector<int> WingedEdgeMesh::boundaryEdges() const
{
    std::vector<int> result;
    for (int e = 0; e < edgeCount(); ++e)
        if (facesOfEdge(e).size() == 1)
            result.push_back(e);
    return result;
}

std::vector<int> WingedEdgeMesh::nonManifoldEdges() const
{
    std::vector<int> result;
    for (int e = 0; e < edgeCount(); ++e)
        if (facesOfEdge(e).size() > 2)
            result.push_back(e);
    return result;
}

bool WingedEdgeMesh::isClosed() const
{
    if (m_edges.empty())
        return false;
    for (int e = 0; e < edgeCount(); ++e)
        if (facesOfEdge(e).size() != 2)
            return false;
    return true;
}

bool WingedEdgeMesh::isManifold() const
{
    if (m_nonManifoldEdges > 0)
        return false;
    return std::all_of(m_vertexManifold.begin(), m_vertexManifold.end(), [](char manifold) { return manifold != 0; });
}

WingedEdgeMesh::WindingRepair WingedEdgeMesh::windingRepair() const
{
    WindingRepair repair;
    // Orientation of each face relative to its piece's first face: +1 agrees,
    // -1 must be reversed to agree, 0 not reached yet.
    std::vector<signed char> sign(m_faceEdge.size(), 0);
    std::vector<int> piece;
    std::vector<int> queue;
    for (int seed = 0; seed < faceCount(); ++seed) {
        if (!faceInTopology(seed) || sign[size_t(seed)] != 0)
            continue;
        piece.clear();
        queue.assign(1, seed);
        sign[size_t(seed)] = 1;
        bool orientable = true;
        while (!queue.empty()) {
            int f = queue.back();
            queue.pop_back();
            piece.push_back(f);
            for (int e : edgesOfFace(f)) {
                const int begin = m_edgeUseStart[size_t(e)];
                if (m_edgeUseStart[size_t(e) + 1] - begin != 2)
                    continue; // boundary or non-manifold: no orientation passes
                const int mine = m_edgeUseFace[size_t(begin)] == f ? begin : begin + 1;
                const int theirs = mine == begin ? begin + 1 : begin;
                const int g = m_edgeUseFace[size_t(theirs)];
                // Agreeing neighbours traverse their shared edge in opposite directions.
                const bool opposite = m_edgeUseForward[size_t(mine)] != m_edgeUseForward[size_t(theirs)];
                const signed char wanted = opposite ? sign[size_t(f)] : static_cast<signed char>(-sign[size_t(f)]);
                if (sign[size_t(g)] == 0) {
                    sign[size_t(g)] = wanted;
                    queue.push_back(g);
                } else if (sign[size_t(g)] != wanted) {
                    orientable = false;
                }
            }
        }
        if (!orientable) {
            repair.orientable = false;
            continue;
        }
        size_t against = 0;
        for (int f : piece)
            against += sign[size_t(f)] < 0 ? 1u : 0u;
        // Flip the minority; on a tie keep the side of the piece's first face.
        const signed char flip = against * 2 <= piece.size() ? -1 : 1;
        for (int f : piece)
            if (sign[size_t(f)] == flip)
                repair.facesToFlip.push_back(f);
    }
    std::sort(repair.facesToFlip.begin(), repair.facesToFlip.end());
    return repair;
}

} // namespace regio::model
