#pragma once
// Points on a scene's faces where a picture of radiosity is judged, and the
// value a lit mesh (output/lit_mesh.h) shows there.
//
// Three kinds of points, because smooth shading goes wrong in three places:
//   - a grid over every face (blotches in the open);
//   - a row just inside every face edge (the boundary values of the vertex
//     averages: dark rings, corners);
//   - rows beside contact lines, where an edge of one face lies inside
//     another face (a block's foot on the floor): points of the carrying face
//     just outside the footprint, points of the standing face just above it.
//     Light leaks there when a value is averaged across the line.
#include "model/geometry/geometry.h"
#include "model/scene.h"
#include "output/lit_mesh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace regio::test {

// Rec. 709 luminance of linear RGB.
inline double luminance(const model::Rgb& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

struct FaceGeometry {
    std::string id;
    std::vector<model::Vec3> polygon; // counter-clockwise seen from the normal
    model::Vec3 normal{0.0};          // unit, the front side
};

// Every face of the scene with an area, in scene order.
inline std::vector<FaceGeometry> faceGeometry(const model::Scene& scene)
{
    std::vector<FaceGeometry> faces;
    for (const model::Object& object : scene.objects) {
        for (const model::Part& part : object.parts) {
            for (const model::Face& face : part.faces) {
                FaceGeometry f{face.id, model::loopPositions(part.vertices, face.loop), model::Vec3(0.0)};
                f.normal = model::polygonNormal(f.polygon);
                if (f.polygon.size() >= 3 && glm::dot(f.normal, f.normal) > 0.5)
                    faces.push_back(std::move(f));
            }
        }
    }
    return faces;
}

// The in-plane distance from p to the nearest edge line of the face: positive
// inside, negative outside.
inline double insideDistance(const FaceGeometry& face, const model::Vec3& p)
{
    double nearest = 1e300;
    for (size_t k = 0; k < face.polygon.size(); ++k) {
        const model::Vec3& a = face.polygon[k];
        const model::Vec3& b = face.polygon[(k + 1) % face.polygon.size()];
        const model::Vec3 inward = glm::normalize(glm::cross(face.normal, b - a));
        nearest = std::min(nearest, glm::dot(inward, p - a));
    }
    return nearest;
}

// The face's extent along two in-plane directions, from its first corner:
// {min along u, max along u, min along v, max along v}.
inline std::array<double, 4> extentAlong(const FaceGeometry& face, const model::Vec3& u, const model::Vec3& v)
{
    std::array<double, 4> e{1e300, -1e300, 1e300, -1e300};
    for (const model::Vec3& p : face.polygon) {
        e[0] = std::min(e[0], glm::dot(u, p - face.polygon[0]));
        e[1] = std::max(e[1], glm::dot(u, p - face.polygon[0]));
        e[2] = std::min(e[2], glm::dot(v, p - face.polygon[0]));
        e[3] = std::max(e[3], glm::dot(v, p - face.polygon[0]));
    }
    return e;
}

struct SurfacePoint {
    enum class Kind { Grid, Edge, Contact };
    std::string face; // face id
    model::Vec3 point{0.0};
    Kind kind = Kind::Grid;
};

// A grid of `spacing` over every face, centred on its extent along its longest
// edge, keeping the points at least `margin` inside the face.
inline std::vector<SurfacePoint> gridPoints(const std::vector<FaceGeometry>& faces, double spacing, double margin)
{
    std::vector<SurfacePoint> points;
    for (const FaceGeometry& f : faces) {
        model::Vec3 longest(0.0);
        for (size_t k = 0; k < f.polygon.size(); ++k) {
            const model::Vec3 e = f.polygon[(k + 1) % f.polygon.size()] - f.polygon[k];
            if (glm::dot(e, e) > glm::dot(longest, longest))
                longest = e;
        }
        const model::Vec3 u = glm::normalize(longest);
        const model::Vec3 v = glm::cross(f.normal, u);
        const auto [s0, s1, t0, t1] = extentAlong(f, u, v);
        const int ns = static_cast<int>(std::floor((s1 - s0) / spacing)) + 1;
        const int nt = static_cast<int>(std::floor((t1 - t0) / spacing)) + 1;
        const double sStart = s0 + 0.5 * ((s1 - s0) - (ns - 1) * spacing);
        const double tStart = t0 + 0.5 * ((t1 - t0) - (nt - 1) * spacing);
        for (int i = 0; i < ns; ++i) {
            for (int j = 0; j < nt; ++j) {
                const model::Vec3 p = f.polygon[0] + u * (sStart + i * spacing) + v * (tStart + j * spacing);
                if (insideDistance(f, p) >= margin)
                    points.push_back({f.id, p, SurfacePoint::Kind::Grid});
            }
        }
    }
    return points;
}

// Rows `inset` inside every edge, a point every `spacing`, keeping those at
// least `inset` from every other edge too (the corners of the face).
inline std::vector<SurfacePoint> edgePoints(const std::vector<FaceGeometry>& faces, double spacing, double inset)
{
    std::vector<SurfacePoint> points;
    for (const FaceGeometry& f : faces) {
        for (size_t k = 0; k < f.polygon.size(); ++k) {
            const model::Vec3& a = f.polygon[k];
            const model::Vec3& b = f.polygon[(k + 1) % f.polygon.size()];
            const model::Vec3 inward = glm::normalize(glm::cross(f.normal, b - a));
            const double length = glm::length(b - a);
            for (double t = 0.5 * spacing; t < length; t += spacing) {
                const model::Vec3 p = a + (b - a) * (t / length) + inward * inset;
                if (insideDistance(f, p) >= 0.999 * inset)
                    points.push_back({f.id, p, SurfacePoint::Kind::Edge});
            }
        }
    }
    return points;
}

// Points beside contact lines: an edge of face g that lies in the plane of a
// face f (not parallel to g) and inside it, not on its border (a block's
// foot on the floor; a wall meeting the floor at the floor's edge is a plain
// corner). For every offset, a row on f at that distance from the line on
// the side g's front looks to, and a row on g at that distance from the edge;
// a point every `spacing`, none closer than `endMargin` to the ends of the edge.
inline std::vector<SurfacePoint> contactPoints(const std::vector<FaceGeometry>& faces, double spacing,
                                               const std::vector<double>& offsets, double endMargin)
{
    std::vector<SurfacePoint> points;
    for (const FaceGeometry& g : faces) {
        for (const FaceGeometry& f : faces) {
            if (&f == &g || std::abs(glm::dot(f.normal, g.normal)) > 1.0 - 1e-6)
                continue;
            for (size_t k = 0; k < g.polygon.size(); ++k) {
                const model::Vec3& a = g.polygon[k];
                const model::Vec3& b = g.polygon[(k + 1) % g.polygon.size()];
                const auto height = [&](const model::Vec3& p) { return glm::dot(f.normal, p - f.polygon[0]); };
                if (std::abs(height(a)) > 1e-6 || std::abs(height(b)) > 1e-6 || insideDistance(f, 0.5 * (a + b)) < 1e-4)
                    continue;
                // On f, away from the line on g's front side; on g, into g.
                const model::Vec3 away = glm::normalize(g.normal - f.normal * glm::dot(f.normal, g.normal));
                const model::Vec3 into = glm::normalize(glm::cross(g.normal, b - a));
                const double length = glm::length(b - a);
                for (double t = endMargin; t <= length - endMargin + 1e-9; t += spacing) {
                    const model::Vec3 onLine = a + (b - a) * (t / length);
                    for (double offset : offsets) {
                        const model::Vec3 onF = onLine + away * offset;
                        const model::Vec3 onG = onLine + into * offset;
                        if (insideDistance(f, onF) > 1e-4)
                            points.push_back({f.id, onF, SurfacePoint::Kind::Contact});
                        if (insideDistance(g, onG) >= 0.999 * std::min(offset, endMargin))
                            points.push_back({g.id, onG, SurfacePoint::Kind::Contact});
                    }
                }
            }
        }
    }
    return points;
}

// What a lit mesh shows at a point of a face: the display radiosity of its
// triangles of that face, interpolated barycentrically (Gouraud shading).
class LitMeshProbe {
public:
    explicit LitMeshProbe(const output::LitMesh& mesh)
        : m_mesh(mesh)
    {
        for (size_t t = 0; t < mesh.triangleCount(); ++t)
            m_triangles[mesh.faceIds[static_cast<size_t>(mesh.triangleFace[t])]].push_back(t);
    }

    // The triangle of the face that holds the point (within 1e-6 of its
    // edges, in barycentric terms), or empty. In a flat lit mesh
    // (output::litMeshFromSolution) triangle t is element t.
    std::optional<size_t> triangleAt(const std::string& faceId, const model::Vec3& p) const
    {
        const auto found = m_triangles.find(faceId);
        if (found == m_triangles.end())
            return std::nullopt;
        double best = -1e300;
        size_t holder = 0;
        for (size_t t : found->second) {
            const std::array<double, 3> w = barycentric(t, p);
            const double inside = std::min(w[0], std::min(w[1], w[2]));
            if (inside > best) {
                best = inside;
                holder = t;
            }
        }
        if (best < -1e-6)
            return std::nullopt;
        return holder;
    }

    // The display radiosity of the triangle that holds the point,
    // interpolated barycentrically; empty when no triangle of the face does.
    std::optional<model::Rgb> displayRadiosityAt(const std::string& faceId, const model::Vec3& p,
                                                 const glm::vec3& ambient) const
    {
        const std::optional<size_t> t = triangleAt(faceId, p);
        if (!t)
            return std::nullopt;
        const uint32_t* corner = &m_mesh.indices[3 * *t];
        const std::array<double, 3> w = barycentric(*t, p);
        return w[0] * model::Rgb(m_mesh.displayRadiosity(corner[0], ambient)) +
               w[1] * model::Rgb(m_mesh.displayRadiosity(corner[1], ambient)) +
               w[2] * model::Rgb(m_mesh.displayRadiosity(corner[2], ambient));
    }

    std::array<model::Vec3, 3> corners(size_t t) const
    {
        const uint32_t* corner = &m_mesh.indices[3 * t];
        return {model::Vec3(m_mesh.positions[corner[0]]), model::Vec3(m_mesh.positions[corner[1]]),
                model::Vec3(m_mesh.positions[corner[2]])};
    }

private:
    // Barycentric coordinates of p projected onto triangle t's plane; all
    // -1e300 for a degenerate triangle.
    std::array<double, 3> barycentric(size_t t, const model::Vec3& p) const
    {
        const auto [a, b, c] = corners(t);
        const model::Vec3 e0 = b - a, e1 = c - a, d = p - a;
        const double d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
        const double d20 = glm::dot(d, e0), d21 = glm::dot(d, e1);
        const double denominator = d00 * d11 - d01 * d01;
        if (denominator <= 0.0)
            return {-1e300, -1e300, -1e300};
        const double wb = (d11 * d20 - d01 * d21) / denominator;
        const double wc = (d00 * d21 - d01 * d20) / denominator;
        return {1.0 - wb - wc, wb, wc};
    }

    const output::LitMesh& m_mesh;
    std::map<std::string, std::vector<size_t>> m_triangles; // per face id
};

} // namespace regio::test
