#pragma once
// Checks shared by the primitive, plane-cut and edit tests: the properties
// every part the model builds must have (closed, manifold, outward, planar
// convex faces, unique ids), stated once.
#include "model/geometry/geometry.h"
#include "model/geometry/winged_edge.h"
#include "model/scene.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <set>
#include <string>

namespace regio::test {

using model::Face;
using model::Part;
using model::Vec3;

// Divergence theorem: the sum over faces of the signed volumes of the
// tetrahedra (origin, fan triangle). Positive when the normals point out.
inline double signedVolume(const Part& part)
{
    double volume = 0.0;
    for (const Face& face : part.faces)
        for (size_t i = 1; i + 1 < face.loop.size(); ++i) {
            const Vec3& a = part.vertices[size_t(face.loop[0])];
            const Vec3& b = part.vertices[size_t(face.loop[i])];
            const Vec3& c = part.vertices[size_t(face.loop[i + 1])];
            volume += glm::dot(a, glm::cross(b, c)) / 6.0;
        }
    return volume;
}

inline double totalArea(const Part& part)
{
    double area = 0.0;
    for (const Face& face : part.faces)
        area += model::polygonArea(model::loopPositions(part.vertices, face.loop));
    return area;
}

inline ::testing::AssertionResult isClosedManifold(const Part& part)
{
    model::WingedEdgeMesh mesh = model::WingedEdgeMesh::build(part);
    if (!mesh.problems().empty())
        return ::testing::AssertionFailure() << part.id << ": " << mesh.problems().size() << " topology problems";
    if (!mesh.isClosed())
        return ::testing::AssertionFailure()
               << part.id << " is open: " << mesh.boundaryEdges().size() << " boundary edges";
    if (!mesh.isManifold())
        return ::testing::AssertionFailure() << part.id << " is not manifold";
    if (!mesh.hasConsistentWinding())
        return ::testing::AssertionFailure() << part.id << " is not consistently wound";
    return ::testing::AssertionSuccess();
}

inline ::testing::AssertionResult facesArePlanarAndConvex(const Part& part)
{
    for (const Face& face : part.faces) {
        std::vector<Vec3> loop = model::loopPositions(part.vertices, face.loop);
        if (model::polygonArea(loop) < 1e-9)
            return ::testing::AssertionFailure() << face.id << " has no area";
        if (model::planarityDeviation(loop) > 1e-9)
            return ::testing::AssertionFailure()
                   << face.id << " is not planar (" << model::planarityDeviation(loop) << " m)";
        if (!model::isConvex(loop, model::polygonNormal(loop)))
            return ::testing::AssertionFailure() << face.id << " is not convex";
    }
    return ::testing::AssertionSuccess();
}

// Part id and face ids distinct (and, across several parts, from each other).
inline ::testing::AssertionResult idsAreUnique(const std::vector<const Part*>& parts)
{
    std::set<std::string> ids;
    for (const Part* part : parts) {
        if (part->id.empty() || !ids.insert(part->id).second)
            return ::testing::AssertionFailure() << "part id \"" << part->id << "\" repeats or is empty";
        for (const Face& face : part->faces)
            if (face.id.empty() || !ids.insert(face.id).second)
                return ::testing::AssertionFailure() << "face id \"" << face.id << "\" repeats or is empty";
    }
    return ::testing::AssertionSuccess();
}

inline const Face* findFace(const Part& part, const std::string& id)
{
    for (const Face& face : part.faces)
        if (face.id == id)
            return &face;
    return nullptr;
}

inline Vec3 faceNormal(const Part& part, const Face& face)
{
    return model::polygonNormal(model::loopPositions(part.vertices, face.loop));
}

} // namespace regio::test
