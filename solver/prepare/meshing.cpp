#include "solver/prepare/meshing.h"

#include "model/geometry/edge_key.h"
#include "model/geometry/geometry.h"
#include "solver/prepare/conforming_strips.h"
#include "solver/prepare/covered_parts.h"
#include "solver/prepare/facing_faces.h"
#include "solver/prepare/near_outlines.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <unordered_map>

namespace regio::solver {

namespace {

// Shares the division points of patch edges between the two patches of a
// face that meet along them.
class EdgePoints {
public:
    EdgePoints(std::vector<Vec3>& vertices, int divisions)
        : m_vertices(vertices)
        , m_k(divisions)
    {
    }

    void clear() { m_edges.clear(); }

    // The t-th of the k-1 inner division points of edge p -> q (t in 1..k-1).
    int at(int p, int q, int t)
    {
        const int lo = std::min(p, q), hi = std::max(p, q);
        auto [it, inserted] = m_edges.try_emplace(model::undirectedEdgeKey(p, q), int(m_vertices.size()));
        if (inserted) {
            // Computed once from the lower index, so both users see the same points.
            const Vec3 a = m_vertices[size_t(lo)], b = m_vertices[size_t(hi)];
            for (int s = 1; s < m_k; ++s)
                m_vertices.push_back(a + (b - a) * (double(s) / double(m_k)));
        }
        return it->second + (p < q ? t - 1 : m_k - t - 1);
    }

private:
    std::vector<Vec3>& m_vertices;
    int m_k;
    std::unordered_map<std::uint64_t, int> m_edges;
};

// Lights are cut into smaller patches than everything else (§5.6). The
// hemicube sees the scene from a shooter's centre, so a patch shares its
// light as if all of it sat there; the first shots, which carry all the
// direct light, come from the emitters, and a face whose plane passes close
// to a lamp (a block's side under a ceiling lamp) takes its light from the
// part of the lamp in front of it, which a large patch's centre does not
// tell. A quarter of the patch size puts the centres that close. The face
// gets at most kMaxEmitterPatches patches this way (a luminous ceiling would
// otherwise shoot thousands of times): the divisor halves until it fits.
constexpr int kEmitterPatchDivisor = 4;
constexpr double kMaxEmitterPatches = 256.0;

double patchSizeOf(const PreparedScene& scene, size_t face, const std::vector<std::vector<Vec3>>& pieces)
{
    if (!scene.properties[face].emits())
        return scene.patchSize;
    double area = 0.0;
    for (const std::vector<Vec3>& piece : pieces)
        area += model::polygonArea(piece);
    for (int divisor = kEmitterPatchDivisor; divisor > 1; divisor /= 2) {
        const double size = scene.patchSize / divisor;
        if (2.0 * area / (size * size) <= kMaxEmitterPatches)
            return size;
    }
    return scene.patchSize;
}

double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * glm::length(glm::cross(b - a, c - a)); }

void addElement(PreparedScene& scene, const Patch& patch, int patchIndex, std::array<int, 3> v)
{
    const Vec3 &a = scene.vertices[size_t(v[0])], &b = scene.vertices[size_t(v[1])], &c = scene.vertices[size_t(v[2])];
    Element e;
    e.vertices = v;
    e.patch = patchIndex;
    e.properties = patch.properties;
    e.node = -1; // set by buildPieces
    e.area = triangleArea(a, b, c);
    e.centroid = (a + b + c) / 3.0;
    e.normal = scene.properties[size_t(patch.properties)].plane.normal;
    scene.faces[size_t(patch.properties)].elements.push_back(int(scene.elements.size()));
    scene.elements.push_back(e);
}

// The k x k barycentric grid of a patch: point (i, j) = A + i/k (B - A) + j/k (C - A).
void splitPatch(PreparedScene& scene, int patchIndex, int k, EdgePoints& edges)
{
    const Patch patch = scene.patches[size_t(patchIndex)];
    const int A = patch.vertices[0], B = patch.vertices[1], C = patch.vertices[2];
    if (k == 1) {
        addElement(scene, patch, patchIndex, patch.vertices);
        return;
    }
    std::vector<int> grid(size_t((k + 1) * (k + 1)), -1);
    auto slot = [&](int i, int j) -> int& { return grid[size_t(j * (k + 1) + i)]; };
    slot(0, 0) = A;
    slot(k, 0) = B;
    slot(0, k) = C;
    for (int t = 1; t < k; ++t) {
        slot(t, 0) = edges.at(A, B, t);
        slot(0, t) = edges.at(A, C, t);
        slot(k - t, t) = edges.at(B, C, t);
    }
    const Vec3 pa = scene.vertices[size_t(A)], pb = scene.vertices[size_t(B)], pc = scene.vertices[size_t(C)];
    for (int j = 1; j < k; ++j)
        for (int i = 1; i + j < k; ++i) {
            slot(i, j) = int(scene.vertices.size());
            scene.vertices.push_back(pa + (pb - pa) * (double(i) / k) + (pc - pa) * (double(j) / k));
        }
    for (int j = 0; j < k; ++j)
        for (int i = 0; i + j < k; ++i) {
            addElement(scene, patch, patchIndex, {slot(i, j), slot(i + 1, j), slot(i, j + 1)});
            if (i + j <= k - 2)
                addElement(scene, patch, patchIndex, {slot(i + 1, j), slot(i + 1, j + 1), slot(i, j + 1)});
        }
}

} // namespace

int elementGridDivisions(int elementsPerPatch)
{
    return std::max(1, int(std::lround(std::sqrt(double(std::max(elementsPerPatch, 1))))));
}

void meshFaces(PreparedScene& scene)
{
    scene.vertices.clear();
    scene.patches.clear();
    scene.elements.clear();
    for (InputFace& face : scene.faces)
        face.elements.clear();
    const int k = elementGridDivisions(scene.elementsPerPatch);
    EdgePoints edges(scene.vertices, k);

    // The strip method applied to the whole input face (§5.4): patches and
    // elements do not depend on the regions or on the BSP splits, which only
    // decide how the elements are painted (solver/prepare/pieces.h). The division
    // points of patch edges are shared across the whole face, so its element
    // mesh is conforming. Only what no solid covers is meshed
    // (solver/prepare/covered_parts.h), as one conforming mesh of its pieces.
    scene.shadowCorners.clear();
    std::vector<std::vector<std::vector<Vec3>>> uncovered = uncoveredPieces(scene, &scene.shadowCorners);
    // A face hanging just in front of another (a lamp under the ceiling) cuts
    // it along its outline (solver/prepare/near_outlines.h).
    cutAlongNearOutlines(scene, uncovered);
    // Faces that stand in front of each other across a gap of a few patches
    // take their light from each other by the contour formula farther out
    // (solver/shooting/near_field.h).
    std::vector<std::vector<int>> facing = closeFacingFaces(scene, kFacingGapPatches * scene.patchSize);
    for (size_t f = 0; f < scene.faces.size(); ++f)
        scene.faces[f].facing = std::move(facing[f]);
    for (size_t f = 0; f < scene.faces.size(); ++f) {
        InputFace& face = scene.faces[f];
        face.firstPatch = int(scene.patches.size());
        face.patchCount = 0;
        if (uncovered[f].empty())
            continue;
        const Properties& props = scene.properties[f];
        StripMesh mesh = stripTriangulatePieces(uncovered[f], props.plane.normal, patchSizeOf(scene, f, uncovered[f]));

        const int base = int(scene.vertices.size());
        scene.vertices.insert(scene.vertices.end(), mesh.points.begin(), mesh.points.end());
        face.patchCount = int(mesh.triangles.size());
        edges.clear();
        for (const Triangle& t : mesh.triangles) {
            Patch patch;
            patch.vertices = {base + t[0], base + t[1], base + t[2]};
            patch.properties = int(f);
            const Vec3 &a = scene.vertices[size_t(patch.vertices[0])], &b = scene.vertices[size_t(patch.vertices[1])],
                       &c = scene.vertices[size_t(patch.vertices[2])];
            patch.area = triangleArea(a, b, c);
            patch.centroid = (a + b + c) / 3.0;
            patch.firstElement = int(scene.elements.size());
            const int patchIndex = int(scene.patches.size());
            scene.patches.push_back(patch);
            splitPatch(scene, patchIndex, k, edges);
            scene.patches.back().elementCount = int(scene.elements.size()) - patch.firstElement;
        }
    }
}

} // namespace regio::solver
