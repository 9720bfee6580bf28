#include "editor/bsp/bsp_layers.h"

#include "model/geometry/geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace regio::editor {

namespace {

constexpr glm::vec4 kBoundaryColour{0.75f, 0.75f, 0.78f, 1.0f};
constexpr glm::vec4 kRegionCutColour{0.2f, 0.85f, 0.95f, 1.0f};
constexpr glm::vec4 kSplitColour{1.0f, 0.55f, 0.05f, 1.0f};
constexpr glm::vec4 kPlaneColour{1.0f, 0.85f, 0.2f, 0.28f};
constexpr glm::vec4 kPlaneOutline{1.0f, 0.85f, 0.2f, 1.0f};
constexpr glm::vec4 kNodeFragmentColour{1.0f, 1.0f, 0.3f, 1.0f};
constexpr glm::vec4 kCurrentColour{1.0f, 1.0f, 1.0f, 1.0f};

double distanceToSegment(const model::Vec3& p, const model::Vec3& a, const model::Vec3& b)
{
    const model::Vec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

// Tolerance for "lies on": the solver's splits are exact to double rounding,
// the separating planes and face outlines are where the author put them.
constexpr double kOnEpsilon = 1e-6 * 100.0;

bool onPolygonOutline(const std::vector<model::Vec3>& loop, const model::Vec3& p)
{
    for (size_t i = 0; i < loop.size(); ++i)
        if (distanceToSegment(p, loop[i], loop[(i + 1) % loop.size()]) < kOnEpsilon)
            return true;
    return false;
}

std::vector<model::Vec3> inputFaceLoop(const model::Scene& scene, const solver::PreparedScene& prepared, int face)
{
    if (face < 0 || size_t(face) >= prepared.faces.size())
        return {};
    const solver::InputFace& input = prepared.faces[size_t(face)];
    if (input.object < 0 || size_t(input.object) >= scene.objects.size())
        return {};
    const model::Object& object = scene.objects[size_t(input.object)];
    if (input.part < 0 || size_t(input.part) >= object.parts.size())
        return {};
    const model::Part& part = object.parts[size_t(input.part)];
    if (input.faceInPart < 0 || size_t(input.faceInPart) >= part.faces.size())
        return {};
    return model::loopPositions(part.vertices, part.faces[size_t(input.faceInPart)].loop);
}

std::span<const model::Vec3> fragmentPolygon(const solver::PreparedScene& prepared, const solver::Fragment& f)
{
    return {prepared.fragmentPoints.data() + f.firstPoint, size_t(f.pointCount)};
}

glm::vec4 edgeColour(FragmentEdgeKind kind)
{
    switch (kind) {
    case FragmentEdgeKind::Boundary: return kBoundaryColour;
    case FragmentEdgeKind::RegionCut: return kRegionCutColour;
    case FragmentEdgeKind::BspSplit: return kSplitColour;
    }
    return kBoundaryColour;
}

void addPolygon(LineList& triangles, std::span<const model::Vec3> loop, const glm::vec4& colour)
{
    for (size_t i = 1; i + 1 < loop.size(); ++i)
        triangles.addTriangle(loop[0], loop[i], loop[i + 1], colour);
}

void addOutline(LineList& lines, std::span<const model::Vec3> loop, const glm::vec4& colour)
{
    for (size_t i = 0; i < loop.size(); ++i)
        lines.add(loop[i], loop[(i + 1) % loop.size()], colour);
}

} // namespace

FragmentEdgeKind classifyFragmentEdge(const model::Scene& scene, const solver::PreparedScene& prepared, int fragment,
                                      const model::Vec3& a, const model::Vec3& b)
{
    const solver::Fragment& f = prepared.fragments[size_t(fragment)];
    const int face = prepared.properties[size_t(f.properties)].face;
    const std::vector<model::Vec3> loop = inputFaceLoop(scene, prepared, face);
    const model::Vec3 mid = (a + b) * 0.5;
    if (!loop.empty() && onPolygonOutline(loop, a) && onPolygonOutline(loop, b) && onPolygonOutline(loop, mid))
        return FragmentEdgeKind::Boundary;
    for (const solver::RegionalNode& node : prepared.regionalNodes) {
        if (node.isLeaf())
            continue;
        const int axis = node.axis;
        if (std::abs(a[axis] - node.position) < kOnEpsilon && std::abs(b[axis] - node.position) < kOnEpsilon)
            return FragmentEdgeKind::RegionCut;
    }
    return FragmentEdgeKind::BspSplit;
}

ViewportLayer buildFragmentLayer(const model::Scene& scene, const solver::PreparedScene& prepared, int region,
                                 FragmentEdgeCounts* counts)
{
    ViewportLayer layer;
    layer.depthTest = true;
    // Before the translucent region boxes (order 10), whose faces write depth
    // and would hide lines drawn after them.
    layer.order = 7;
    FragmentEdgeCounts tally;
    for (size_t i = 0; i < prepared.fragments.size(); ++i) {
        const solver::Fragment& f = prepared.fragments[i];
        if (region >= 0 && f.region != region)
            continue;
        const auto polygon = fragmentPolygon(prepared, f);
        // The outline from the input face is computed once per fragment.
        const int face = prepared.properties[size_t(f.properties)].face;
        const std::vector<model::Vec3> loop = inputFaceLoop(scene, prepared, face);
        for (size_t k = 0; k < polygon.size(); ++k) {
            const model::Vec3& a = polygon[k];
            const model::Vec3& b = polygon[(k + 1) % polygon.size()];
            FragmentEdgeKind kind;
            if (!loop.empty() && onPolygonOutline(loop, a) && onPolygonOutline(loop, b) &&
                onPolygonOutline(loop, (a + b) * 0.5))
                kind = FragmentEdgeKind::Boundary;
            else
                kind = classifyFragmentEdge(scene, prepared, int(i), a, b);
            (kind == FragmentEdgeKind::Boundary    ? tally.boundary
             : kind == FragmentEdgeKind::RegionCut ? tally.regionCuts
                                                   : tally.bspSplits)++;
            layer.lines.add(a, b, edgeColour(kind));
        }
    }
    if (counts)
        *counts = tally;
    return layer;
}

std::vector<model::Vec3> planeInBox(const model::Plane& plane, const model::Box3& box)
{
    if (box.empty)
        return {};
    const model::Vec3 n = glm::normalize(plane.normal);
    const model::Vec3 centre = box.center() - plane.signedDistance(box.center()) * n;
    // Two directions in the plane; the square spans the whole box.
    const model::Vec3 helper = std::abs(n.x) < 0.9 ? model::Vec3(1, 0, 0) : model::Vec3(0, 1, 0);
    const model::Vec3 u = glm::normalize(glm::cross(n, helper));
    const model::Vec3 v = glm::cross(n, u);
    const double r = glm::length(box.size()) + 1.0;
    std::vector<model::Vec3> polygon = {centre - r * u - r * v, centre + r * u - r * v, centre + r * u + r * v,
                                        centre - r * u + r * v};
    for (int axis = 0; axis < 3 && !polygon.empty(); ++axis) {
        for (int side = 0; side < 2 && !polygon.empty(); ++side) {
            // Keep the inside: the back of a plane whose normal points out of the box.
            model::Vec3 outward(0.0);
            outward[axis] = side == 0 ? -1.0 : 1.0;
            const model::Vec3 point = side == 0 ? box.min : box.max;
            std::vector<model::Vec3> front, back;
            model::splitPolygon(polygon, model::Plane::fromPointNormal(point, outward), front, back);
            polygon = std::move(back);
        }
    }
    if (polygon.size() < 3)
        return {};
    return polygon;
}

ViewportLayer buildNodePlaneLayer(const solver::PreparedScene& prepared, int nodeIndex)
{
    ViewportLayer layer;
    layer.depthTest = true;
    layer.offsetTriangles = true;
    layer.order = 8;
    if (nodeIndex < 0 || size_t(nodeIndex) >= prepared.nodes.size())
        return layer;
    const solver::BspNode& node = prepared.nodes[size_t(nodeIndex)];
    const solver::Region& region = prepared.regions[size_t(node.region)];
    const std::vector<model::Vec3> polygon = planeInBox(node.plane, region.box.empty ? region.bounds : region.box);
    addPolygon(layer.triangles, polygon, kPlaneColour);
    // Both sides of the translucent quad are seen.
    std::vector<model::Vec3> reversed(polygon.rbegin(), polygon.rend());
    addPolygon(layer.triangles, reversed, kPlaneColour);
    addOutline(layer.lines, polygon, kPlaneOutline);
    for (int i = node.firstFragment; i < node.firstFragment + node.fragmentCount; ++i)
        addOutline(layer.lines, fragmentPolygon(prepared, prepared.fragments[size_t(i)]), kNodeFragmentColour);
    return layer;
}

glm::vec4 paintStepColour(int index, int count, bool receives)
{
    const float t = count > 1 ? float(index) / float(count - 1) : 0.0f;
    if (!receives) {
        const float g = 0.22f + 0.4f * t;
        return {g, g, g, 1.0f};
    }
    // Blue (first painted, farthest) through green to red (last, nearest).
    if (t < 0.5f) {
        const float s = t * 2.0f;
        return {0.1f, 0.2f + 0.6f * s, 0.9f - 0.6f * s, 1.0f};
    }
    const float s = (t - 0.5f) * 2.0f;
    return {0.1f + 0.85f * s, 0.8f - 0.6f * s, 0.3f - 0.2f * s, 1.0f};
}

ViewportLayer buildPainterLayer(const solver::PreparedScene& prepared, const solver::PainterOrder& order, int steps)
{
    ViewportLayer layer;
    layer.depthTest = true;
    layer.replacesSurfaces = true;
    // Opaque, so before every translucent layer (the region boxes are 10).
    layer.order = -5;
    const int count = int(order.steps.size());
    steps = std::clamp(steps, 0, count);
    for (int i = 0; i < steps; ++i) {
        const solver::PaintStep& step = order.steps[size_t(i)];
        const glm::vec4 colour = paintStepColour(i, count, step.receives);
        auto add = [&](const std::vector<model::Vec3>& v, const std::array<int, 3>& t) {
            layer.triangles.addTriangle(v[size_t(t[0])], v[size_t(t[1])], v[size_t(t[2])], colour);
            // The back is coloured too: a blocker is seen from behind by definition.
            layer.triangles.addTriangle(v[size_t(t[0])], v[size_t(t[2])], v[size_t(t[1])], colour);
        };
        // The pieces this step paints: an element cut by a region or BSP
        // plane is painted in parts, at different steps.
        if (step.pieceCount > 0 && step.firstPiece >= 0) {
            for (int p = step.firstPiece; p < step.firstPiece + step.pieceCount; ++p)
                add(prepared.pieceVertices, prepared.pieces[size_t(p)].vertices);
        } else {
            add(prepared.vertices, prepared.elements[size_t(step.element)].vertices);
        }
    }
    return layer;
}

ViewportLayer buildPainterMarkerLayer(const solver::PreparedScene& prepared, const solver::PainterOrder& order,
                                      int steps, const model::Vec3& eye)
{
    ViewportLayer layer;
    layer.depthTest = false;
    layer.order = 31;
    const double size = std::max(0.05, glm::length(prepared.bounds.size()) * 0.01);
    for (int axis = 0; axis < 3; ++axis) {
        model::Vec3 d(0.0);
        d[axis] = size;
        layer.lines.add(eye - d, eye + d, kCurrentColour);
    }
    if (steps > 0 && steps <= int(order.steps.size())) {
        const solver::Element& e = prepared.elements[size_t(order.steps[size_t(steps - 1)].element)];
        const auto& v = prepared.vertices;
        const model::Vec3 corners[3] = {v[size_t(e.vertices[0])], v[size_t(e.vertices[1])], v[size_t(e.vertices[2])]};
        addOutline(layer.lines, corners, kCurrentColour);
    }
    return layer;
}

} // namespace regio::editor
