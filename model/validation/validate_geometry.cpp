// Validation of the parts: vertices, face loops, face geometry (planar, convex,
// not degenerate) and part topology from the winged-edge structure (paper §4).
#include "model/geometry/winged_edge.h"
#include "model/validation/validation.h"
#include "model/validation/validation_detail.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace regio::model::detail {

namespace {

bool isFinite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string vertexPair(const WingedEdgeMesh::Edge& edge)
{
    return "vertices " + std::to_string(edge.v0) + " and " + std::to_string(edge.v1);
}

void reportLoopProblem(ValidationContext& context, size_t o, size_t p, const TopologyProblem& problem)
{
    const Part& part = context.part(int(o), int(p));
    const size_t f = size_t(problem.face);
    const Face& face = part.faces[f];
    const std::string name = "face " + quoted(face.id);
    const std::string loopPointer = facePointer(o, p, f) + "/loop";
    const std::vector<std::string> path = facePath(context, o, p, f);
    switch (problem.kind) {
    case TopologyProblem::Kind::LoopTooShort:
        context.error(name + " has " + std::to_string(face.loop.size()) + " loop vertices; a face needs at least 3",
                      loopPointer, path);
        break;
    case TopologyProblem::Kind::VertexOutOfRange:
        context.error(name + ": loop entry " + std::to_string(face.loop[size_t(problem.loopPosition)]) +
                          " is not a vertex of part " + quoted(part.id) + " (it has " +
                          std::to_string(part.vertices.size()) + " vertices)",
                      loopPointer + "/" + std::to_string(problem.loopPosition), path);
        break;
    case TopologyProblem::Kind::RepeatedVertex: {
        const int vertex = face.loop[size_t(problem.loopPosition)];
        const auto first = std::find(face.loop.begin(), face.loop.end(), vertex) - face.loop.begin();
        context.error(name + ": vertex " + std::to_string(vertex) + " appears twice in the loop (positions " +
                          std::to_string(first) + " and " + std::to_string(problem.loopPosition) +
                          "); a face is a simple polygon",
                      loopPointer + "/" + std::to_string(problem.loopPosition), path);
        break;
    }
    default: break;
    }
}

void validateFaceGeometry(ValidationContext& context, size_t o, size_t p, size_t f, std::span<const Vec3> positions)
{
    const std::string name = "face " + quoted(context.part(int(o), int(p)).faces[f].id);
    const std::string pointer = facePointer(o, p, f);
    Box3 bounds;
    for (const Vec3& v : positions)
        bounds.extend(v);
    const double size = glm::length(bounds.size());
    const Vec3 newell = newellNormal(positions);
    const double area = 0.5 * glm::length(newell);
    if (!(area >= kMinFaceArea)) {
        context.error(name + " has zero area (" + formatValue(area) +
                          " m\u00b2): its vertices coincide or lie on one line",
                      pointer, facePath(context, o, p, f));
        return;
    }

    const double deviation = planarityDeviation(positions);
    const double warnAt = std::max(kDistanceEpsilon, kPlanarityWarning * size);
    const double errorAt = std::max(kDistanceEpsilon, kPlanarityError * size);
    if (deviation > errorAt) {
        context.error(name + " is not planar: a vertex lies " + formatLength(deviation) +
                          " from its best-fit plane (at most " + formatLength(errorAt) +
                          " for its size); split it into planar faces",
                      pointer, facePath(context, o, p, f));
        return; // convexity is meaningless on a warped loop
    }
    if (deviation > warnAt)
        context.warning(name + " is slightly non-planar: a vertex lies " + formatLength(deviation) +
                            " from its best-fit plane (tolerance " + formatLength(warnAt) +
                            "); the solver flattens it onto that plane",
                        pointer, facePath(context, o, p, f));

    if (!isConvex(positions, newell / (2.0 * area)))
        context.error(name +
                          " is not convex; the solver's BSP trees and patch strips need convex "
                          "faces: split it into convex pieces",
                      pointer, facePath(context, o, p, f));
    else if (area < kSliverRatio * size * size)
        context.warning(name + " is a sliver (" + formatValue(area) + " m\u00b2 over " + formatLength(size) +
                            "): hemicubes and the patch mesh sample it badly",
                        pointer, facePath(context, o, p, f));
}

// All usable faces lie in one plane (within the tolerance of a face: a panel
// may be folded along a diagonal): a panel or a single wall, which can only
// be an open shell by nature, so its open edges are no news.
bool isFlat(const Part& part, const std::vector<char>& usable)
{
    std::vector<Vec3> points;
    for (size_t f = 0; f < part.faces.size(); ++f)
        if (usable[f])
            for (int v : part.faces[f].loop)
                points.push_back(part.vertices[size_t(v)]);
    if (points.empty())
        return false;
    Box3 bounds;
    for (const Vec3& q : points)
        bounds.extend(q);
    const double tolerance = std::max(kDistanceEpsilon, kPlanarityError * glm::length(bounds.size()));
    for (size_t f = 0; f < part.faces.size(); ++f) {
        if (!usable[f])
            continue;
        const Plane plane = polygonPlane(loopPositions(part.vertices, part.faces[f].loop));
        if (plane.normal == Vec3(0.0))
            continue;
        return std::all_of(points.begin(), points.end(),
                           [&](const Vec3& q) { return std::abs(plane.signedDistance(q)) <= tolerance; });
    }
    return false;
}

void validateTopology(ValidationContext& context, size_t o, size_t p, const WingedEdgeMesh& mesh)
{
    const Part& part = context.part(int(o), int(p));
    if (!mesh.hasConsistentWinding()) {
        const WingedEdgeMesh::WindingRepair repair = mesh.windingRepair();
        if (repair.orientable) {
            for (int f : repair.facesToFlip)
                context.error("face " + quoted(part.faces[size_t(f)].id) +
                                  " is wound opposite to its neighbours, so its normal points the "
                                  "wrong way: reverse its loop",
                              facePointer(o, p, size_t(f)), facePath(context, o, p, size_t(f)));
        } else {
            for (const TopologyProblem& problem : mesh.problems()) {
                if (problem.kind != TopologyProblem::Kind::InconsistentWinding)
                    continue;
                const size_t f = size_t(problem.face);
                context.error("faces " + quoted(part.faces[size_t(problem.faces[0])].id) + " and " +
                                  quoted(part.faces[f].id) + " run through their shared edge (" +
                                  vertexPair(mesh.edge(problem.edge)) + ") in the same direction, and part " +
                                  quoted(part.id) + " is one-sided: no choice of windings makes it consistent",
                              facePointer(o, p, f), facePath(context, o, p, f));
            }
        }
    }
    for (const TopologyProblem& problem : mesh.problems()) {
        if (problem.kind != TopologyProblem::Kind::NonManifoldEdge)
            continue;
        std::string names;
        for (int g : problem.faces)
            names += (names.empty() ? "" : ", ") + quoted(part.faces[size_t(g)].id);
        const size_t f = size_t(problem.face);
        context.error("the edge between " + vertexPair(mesh.edge(problem.edge)) + " is shared by " +
                          std::to_string(problem.faces.size()) + " faces (" + names +
                          "); an edge of a part bounds at most two faces: split the part",
                      facePointer(o, p, f), facePath(context, o, p, f));
    }
    // With faces left out for bad loops the gaps say nothing about the part.
    for (int f = 0; f < mesh.faceCount(); ++f)
        if (!mesh.faceInTopology(f))
            return;
    const std::vector<int> boundary = mesh.boundaryEdges();
    if (!boundary.empty() && !isFlat(part, context.faceUsable[o][p]))
        context.warning("part " + quoted(part.id) + " is an open shell: " + std::to_string(boundary.size()) +
                            (boundary.size() == 1 ? " edge has" : " edges have") +
                            " only one face (the first between " + vertexPair(mesh.edge(boundary.front())) +
                            "); fine for walls seen from one side, but a solid must be closed or "
                            "light leaks through the gap",
                        partPointer(o, p), partPath(context, o, p));
}

} // namespace

void validateParts(ValidationContext& context)
{
    const Scene& scene = context.scene;
    context.faceUsable.resize(scene.objects.size());
    std::vector<Vec3> positions;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& object = scene.objects[o];
        context.faceUsable[o].resize(object.parts.size());
        for (size_t p = 0; p < object.parts.size(); ++p) {
            const Part& part = object.parts[p];
            std::vector<char> finite(part.vertices.size(), 1);
            for (size_t v = 0; v < part.vertices.size(); ++v) {
                if (isFinite(part.vertices[v]))
                    continue;
                finite[v] = 0;
                context.error("part " + quoted(part.id) + ": vertex " + std::to_string(v) +
                                  " has a coordinate that is not a finite number",
                              partPointer(o, p) + "/vertices/" + std::to_string(v), partPath(context, o, p));
            }

            const WingedEdgeMesh mesh = WingedEdgeMesh::build(part);
            for (const TopologyProblem& problem : mesh.problems())
                reportLoopProblem(context, o, p, problem);

            std::vector<char>& usable = context.faceUsable[o][p];
            usable.assign(part.faces.size(), 0);
            for (size_t f = 0; f < part.faces.size(); ++f) {
                if (!mesh.faceInTopology(int(f)))
                    continue;
                const auto& loop = part.faces[f].loop;
                if (!std::all_of(loop.begin(), loop.end(), [&](int v) { return finite[size_t(v)] != 0; }))
                    continue;
                usable[f] = 1;
                positions = loopPositions(part.vertices, loop);
                validateFaceGeometry(context, o, p, f, positions);
            }
            validateTopology(context, o, p, mesh);
        }
    }
}

} // namespace regio::model::detail
