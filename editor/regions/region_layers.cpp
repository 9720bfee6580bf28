#include "editor/regions/region_layers.h"

#include "model/geometry/region_clip.h"
#include "model/validation/validation.h"

#include <QColor>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace regio::editor {

namespace {

// Corner i of a box: bit 0 = x max, bit 1 = y max, bit 2 = z max.
model::Vec3 corner(const model::Box3& box, int i)
{
    return {i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z};
}

// The quad of a box face (handle numbering), counter-clockwise from outside.
std::array<model::Vec3, 4> boxFace(const model::Box3& box, int face)
{
    const int axis = face / 2;
    const bool maxSide = face % 2 == 1;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    auto at = [&](bool uMax, bool vMax) {
        model::Vec3 p;
        p[axis] = maxSide ? box.max[axis] : box.min[axis];
        p[u] = uMax ? box.max[u] : box.min[u];
        p[v] = vMax ? box.max[v] : box.min[v];
        return p;
    };
    if (maxSide)
        return {at(false, false), at(true, false), at(true, true), at(false, true)};
    return {at(false, false), at(false, true), at(true, true), at(true, false)};
}

void addQuad(LineList& triangles, const std::array<model::Vec3, 4>& q, const glm::vec4& colour)
{
    // One winding: layers are drawn without face culling, so a quad seen from
    // behind shows as well (a second winding would double its opacity).
    triangles.addTriangle(q[0], q[1], q[2], colour);
    triangles.addTriangle(q[0], q[2], q[3], colour);
}

std::vector<model::Vec3> loopOf(const model::Part& part, const model::Face& face)
{
    std::vector<model::Vec3> loop;
    loop.reserve(face.loop.size());
    for (int v : face.loop)
        if (v >= 0 && size_t(v) < part.vertices.size())
            loop.push_back(part.vertices[size_t(v)]);
    return loop;
}

} // namespace

glm::vec4 regionColour(int index, float alpha)
{
    // Golden-ratio steps around the hue circle keep neighbours apart.
    const double hue = std::fmod(0.08 + 0.618033988749895 * std::max(index, 0), 1.0);
    const QColor c = QColor::fromHsvF(float(hue), 0.6f, 0.95f);
    return {float(c.redF()), float(c.greenF()), float(c.blueF()), alpha};
}

glm::vec4 outsideRegionsColour() { return {0.55f, 0.55f, 0.57f, 1.0f}; }

model::Box3 boxOf(const model::Region& region)
{
    model::Box3 box;
    box.extend(glm::min(region.min, region.max));
    box.extend(glm::max(region.min, region.max));
    return box;
}

model::Box3 sceneExtent(const model::Scene& scene)
{
    model::Box3 box;
    for (const model::Object& object : scene.objects)
        for (const model::Part& part : object.parts)
            for (const model::Vec3& v : part.vertices)
                if (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))
                    box.extend(v);
    for (const model::Region& region : scene.regions)
        box.extend(boxOf(region));
    return box;
}

int regionHoldingPolygon(const model::Scene& scene, std::span<const model::Vec3> loop)
{
    int best = -1;
    double bestArea = model::kMinFaceArea;
    for (size_t r = 0; r < scene.regions.size(); ++r) {
        const double area = model::polygonAreaInBox(loop, boxOf(scene.regions[r]));
        if (area >= bestArea) {
            bestArea = area;
            best = int(r);
        }
    }
    return best;
}

ViewportLayer buildRegionBoxesLayer(const model::Scene& scene, const std::vector<std::string>& selected)
{
    ViewportLayer layer;
    // Over the scene, without writing depth: a box drawn into the depth
    // buffer would hide the selection of the parts inside it.
    layer.depthTest = false;
    layer.offsetTriangles = false;
    layer.order = 10;
    for (size_t r = 0; r < scene.regions.size(); ++r) {
        const model::Region& region = scene.regions[r];
        const bool isSelected = std::find(selected.begin(), selected.end(), region.id) != selected.end();
        const model::Box3 box = boxOf(region);
        for (int face = 0; face < 6; ++face)
            addQuad(layer.triangles, boxFace(box, face), regionColour(int(r), isSelected ? 0.14f : 0.07f));
        layer.lines.addBox(box.min, box.max, regionColour(int(r), isSelected ? 1.0f : 0.7f));
    }
    return layer;
}

ViewportLayer buildProposalLayer(const std::vector<model::Region>& regions)
{
    ViewportLayer layer;
    layer.depthTest = false;
    layer.order = 20;
    for (size_t r = 0; r < regions.size(); ++r) {
        const model::Box3 box = boxOf(regions[r]);
        const glm::vec4 colour = regionColour(int(r), 0.95f);
        // Dashed edges: a proposal is not part of the scene yet.
        for (int i = 0; i < 8; ++i)
            for (int bit : {1, 2, 4}) {
                if (i & bit)
                    continue;
                const model::Vec3 a = corner(box, i), b = corner(box, i | bit);
                const int dashes = 12;
                for (int d = 0; d < dashes; d += 2)
                    layer.lines.add(a + (b - a) * (double(d) / dashes), a + (b - a) * (double(d + 1) / dashes), colour);
            }
        for (int face = 0; face < 6; ++face)
            addQuad(layer.triangles, boxFace(box, face), regionColour(int(r), 0.06f));
    }
    return layer;
}

std::vector<ColouredFace> colourFacesByRegion(const model::Scene& scene)
{
    std::vector<ColouredFace> faces;
    const model::Vec3 light = glm::normalize(model::Vec3(0.35, 0.85, 0.4));
    for (const model::Object& object : scene.objects)
        for (const model::Part& part : object.parts)
            for (const model::Face& face : part.faces) {
                std::vector<model::Vec3> loop = loopOf(part, face);
                if (loop.size() < 3 || model::polygonArea(loop) < model::kMinFaceArea)
                    continue;
                const int region = regionHoldingPolygon(scene, loop);
                const glm::vec4 base = region >= 0 ? regionColour(region) : outsideRegionsColour();
                const model::Vec3 n = model::polygonNormal(loop);
                // Two-sided lighting: rooms are seen from inside.
                const float shade = float(0.55 + 0.45 * std::abs(glm::dot(n, light)));
                faces.push_back({std::move(loop), n, glm::vec4(base.r * shade, base.g * shade, base.b * shade, 1.0f)});
            }
    return faces;
}

ViewportLayer buildPartsByRegionLayer(const std::vector<ColouredFace>& faces, const Viewer* viewer)
{
    ViewportLayer layer;
    layer.replacesSurfaces = true;
    layer.order = -10;
    for (const ColouredFace& face : faces) {
        if (viewer) {
            const model::Vec3 toEye = viewer->orthographic ? -viewer->forward : viewer->eye - face.loop.front();
            if (glm::dot(face.normal, toEye) <= 0.0)
                continue;
        }
        for (size_t i = 1; i + 1 < face.loop.size(); ++i)
            layer.triangles.addTriangle(face.loop[0], face.loop[i], face.loop[i + 1], face.colour);
    }
    return layer;
}

ViewportLayer buildPartsByRegionLayer(const model::Scene& scene)
{
    return buildPartsByRegionLayer(colourFacesByRegion(scene));
}

RegionalTreeView regionalTreeOf(const model::Scene& scene)
{
    RegionalTreeView view;
    if (scene.regions.empty())
        return view;
    std::vector<model::Box3> boxes;
    for (const model::Region& region : scene.regions) {
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite(region.min[a]) || !std::isfinite(region.max[a]) || !(region.min[a] < region.max[a]))
                return view;
        boxes.push_back(boxOf(region));
    }
    solver::RegionalTreeBuild build = solver::buildRegionalTree(boxes);
    if (!build.ok())
        return view;
    view.tree = std::move(build.tree);
    view.ok = view.tree.root >= 0;
    // Walk the tree with the cell of each node: the extent cut by the planes above.
    std::vector<std::pair<int, model::Box3>> stack;
    if (view.ok)
        stack.emplace_back(view.tree.root, sceneExtent(scene));
    std::vector<SeparatingPlane> planes;
    while (!stack.empty()) {
        auto [index, cell] = stack.back();
        stack.pop_back();
        const solver::RegionalNode& node = view.tree.nodes[size_t(index)];
        if (node.isLeaf())
            continue;
        planes.push_back({index, node.axis, node.position, cell});
        model::Box3 back = cell, front = cell;
        back.max[node.axis] = std::min(cell.max[node.axis], node.position);
        front.min[node.axis] = std::max(cell.min[node.axis], node.position);
        if (node.front >= 0)
            stack.emplace_back(node.front, front);
        if (node.back >= 0)
            stack.emplace_back(node.back, back);
    }
    std::sort(planes.begin(), planes.end(), [](const auto& a, const auto& b) { return a.node < b.node; });
    view.planes = std::move(planes);
    return view;
}

ViewportLayer buildSeparatingPlanesLayer(const RegionalTreeView& view, int highlightedNode)
{
    ViewportLayer layer;
    layer.depthTest = false; // as the boxes: planes run through the parts
    layer.offsetTriangles = false;
    layer.order = 5;
    static const glm::vec4 kAxisColour[3] = {
        {1.0f, 0.35f, 0.3f, 1.0f}, {0.35f, 0.9f, 0.35f, 1.0f}, {0.35f, 0.5f, 1.0f, 1.0f}};
    for (const SeparatingPlane& plane : view.planes) {
        model::Box3 flat = plane.cell;
        flat.min[plane.axis] = flat.max[plane.axis] = plane.position;
        const std::array<model::Vec3, 4> quad = boxFace(flat, 2 * plane.axis + 1);
        const bool highlighted = plane.node == highlightedNode;
        glm::vec4 fill = kAxisColour[plane.axis];
        fill.a = highlighted ? 0.45f : 0.18f;
        addQuad(layer.triangles, quad, fill);
        const glm::vec4 edge = highlighted ? glm::vec4(1.0f) : kAxisColour[plane.axis];
        for (int i = 0; i < 4; ++i)
            layer.lines.add(quad[size_t(i)], quad[size_t((i + 1) % 4)], edge);
    }
    return layer;
}

model::Vec3 handlePosition(const model::Box3& box, int handle)
{
    model::Vec3 p = box.center();
    const int axis = handle / 2;
    p[axis] = handle % 2 ? box.max[axis] : box.min[axis];
    return p;
}

ViewportLayer buildHandlesLayer(const model::Box3& box, double size, int active)
{
    ViewportLayer layer;
    layer.depthTest = false;
    layer.order = 30;
    for (int handle = 0; handle < 6; ++handle) {
        const int axis = handle / 2;
        const model::Vec3 centre = handlePosition(box, handle);
        model::Box3 square;
        model::Vec3 half(size * 0.5);
        half[axis] = 0.0;
        square.extend(centre - half);
        square.extend(centre + half);
        const glm::vec4 colour =
            handle == active ? glm::vec4(1.0f, 0.85f, 0.2f, 0.95f) : glm::vec4(0.95f, 0.95f, 1.0f, 0.8f);
        addQuad(layer.triangles, boxFace(square, handle), colour);
        const std::array<model::Vec3, 4> q = boxFace(square, handle);
        for (int i = 0; i < 4; ++i)
            layer.lines.add(q[size_t(i)], q[size_t((i + 1) % 4)], glm::vec4(0.1f, 0.1f, 0.1f, 1.0f));
    }
    return layer;
}

} // namespace regio::editor
