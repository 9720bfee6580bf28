#include "solver/prepare/prepare.h"

#include "solver/prepare/auto_regions.h"
#include "solver/prepare/bsp_tree.h"
#include "solver/prepare/meshing.h"
#include "solver/prepare/pieces.h"
#include "solver/prepare/regional_tree.h"
#include "model/geometry/winged_edge.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <string>
#include <unordered_map>

namespace regio::solver {

namespace {

std::string facePointer(size_t o, size_t p, size_t f)
{
    return "/objects/" + std::to_string(o) + "/parts/" + std::to_string(p) + "/faces/" + std::to_string(f);
}

// Reads every face of the scene into the face table, its Properties and its
// polygon (projected onto its plane, so everything downstream is exactly planar).
bool collectFaces(const model::Scene& scene, PreparedScene& out, std::vector<FacePolygon>& polygons,
                  model::Diagnostics& diagnostics)
{
    bool ok = true;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const model::Object& object = scene.objects[o];
        for (size_t p = 0; p < object.parts.size(); ++p) {
            const model::Part& part = object.parts[p];
            // A closed part with volume (Properties::solid): a closed surface
            // needs at least four faces; two faces back to back are a thin wall.
            const bool solid = part.faces.size() >= 4 && model::WingedEdgeMesh::build(part).isClosed();
            for (size_t f = 0; f < part.faces.size(); ++f) {
                const model::Face& face = part.faces[f];
                const int index = int(out.faces.size());
                const std::string pointer = facePointer(o, p, f);
                const std::vector<std::string> idPath{object.id, part.id, face.id};

                InputFace info;
                info.id = face.id;
                info.object = int(o);
                info.part = int(p);
                info.faceInPart = int(f);
                Properties props;
                props.face = index;
                props.solid = solid;

                const model::Material* material = scene.materialOf(part, face);
                if (!material) {
                    diagnostics.push_back(model::makeError(
                        "face '" + face.id + "' has no material the solver can use (unknown material id '" +
                            (face.material.empty() ? part.material : face.material) + "')",
                        pointer + "/material", idPath));
                    ok = false;
                } else {
                    props.reflectance = material->reflectance;
                    props.emission = material->emission;
                }

                bool indicesValid = face.loop.size() >= 3;
                for (int v : face.loop)
                    indicesValid = indicesValid && v >= 0 && size_t(v) < part.vertices.size();
                std::vector<Vec3> loop;
                if (indicesValid)
                    loop = model::loopPositions(part.vertices, face.loop);
                const double area = indicesValid ? model::polygonArea(loop) : 0.0;
                if (!indicesValid || area <= model::kAreaEpsilon) {
                    diagnostics.push_back(model::makeWarning("face '" + face.id +
                                                                 "' has no area; it is left out of the solution",
                                                             pointer + "/loop", idPath));
                    out.faces.push_back(std::move(info));
                    out.properties.push_back(props);
                    continue;
                }
                props.plane = model::polygonPlane(loop);
                for (Vec3& v : loop)
                    v -= props.plane.normal * props.plane.signedDistance(v);
                if (!model::isConvex(loop, props.plane.normal)) {
                    diagnostics.push_back(model::makeError(
                        "face '" + face.id + "' is not convex; the solver needs convex faces (split it)",
                        pointer + "/loop", idPath));
                    ok = false;
                }
                info.area = area;
                std::vector<Vec3> clean = cleanConvexLoop(loop);
                if (ok && clean.size() >= 3) {
                    for (const Vec3& v : clean)
                        out.bounds.extend(v);
                    info.polygon = clean;
                    polygons.push_back({std::move(clean), index});
                    ++out.stats.inputFaces;
                }
                out.faces.push_back(std::move(info));
                out.properties.push_back(props);
            }
        }
    }
    return ok;
}

struct RegionSetup {
    std::vector<Box3> boxes;
    std::vector<std::string> ids;
    std::vector<const std::vector<std::string>*> orders; // per region
};

Box3 regionBox(const model::Region& region)
{
    Box3 box;
    box.extend(glm::min(region.min, region.max));
    box.extend(glm::max(region.min, region.max));
    return box;
}

} // namespace

PrepareResult prepareScene(const model::Scene& scene, const PrepareOptions& options)
{
    PrepareResult result;
    PreparedScene out;
    out.patchSize = options.patchSize.value_or(scene.solver.patchSize);
    out.elementsPerPatch = options.elementsPerPatch.value_or(scene.solver.elementsPerPatch);
    if (!(out.patchSize > 0.0) || !std::isfinite(out.patchSize)) {
        result.diagnostics.push_back(model::makeError("the patch size must be a positive length", "/solver/patchSize"));
        return result;
    }
    if (out.elementsPerPatch < 1) {
        result.diagnostics.push_back(
            model::makeError("the element/patch ratio must be at least 1", "/solver/elementsPerPatch"));
        return result;
    }

    std::vector<FacePolygon> polygons;
    if (!collectFaces(scene, out, polygons, result.diagnostics))
        return result;

    // One priority list for modes that do not use the authored regions: the
    // authored orders one after the other, so the author's sorting still counts.
    std::vector<std::string> combinedOrder;
    for (const model::Region& region : scene.regions)
        combinedOrder.insert(combinedOrder.end(), region.bspOrder.begin(), region.bspOrder.end());

    RegionSetup setup;
    if (options.regions == RegionsMode::Authored && !scene.regions.empty()) {
        for (const model::Region& region : scene.regions) {
            setup.boxes.push_back(regionBox(region));
            setup.ids.push_back(region.id);
            setup.orders.push_back(&region.bspOrder);
        }
    } else if (options.regions == RegionsMode::Auto) {
        setup.boxes = autoRegionBoxes(polygons, out.bounds, options.autoRegionPatchThreshold, out.patchSize);
        for (size_t i = 0; i < setup.boxes.size(); ++i) {
            setup.ids.push_back("auto-" + std::to_string(i + 1));
            setup.orders.push_back(&combinedOrder);
        }
    }
    if (setup.boxes.empty()) {
        setup.boxes.push_back(out.bounds);
        setup.ids.push_back("scene");
        setup.orders.push_back(&combinedOrder);
    }

    // §5.2: the regional tree.
    RegionalTreeBuild tree = buildRegionalTree(setup.boxes);
    if (!tree.ok()) {
        std::string names;
        for (int r : tree.inseparable)
            names += (names.empty() ? "'" : ", '") + setup.ids[size_t(r)] + "'";
        result.diagnostics.push_back(model::makeError(
            "regions " + names +
                " cannot be separated by axis-aligned planes (they overlap or interlock); move or split one of them",
            "/regions/" + std::to_string(tree.inseparable.front()), {setup.ids[size_t(tree.inseparable.front())]}));
        return result;
    }
    out.regionalNodes = std::move(tree.tree.nodes);
    out.regionalRoot = tree.tree.root;
    for (size_t r = 0; r < setup.boxes.size(); ++r) {
        Region region;
        region.id = setup.ids[r];
        region.box = setup.boxes[r];
        out.regions.push_back(region);
    }

    // Face assignment with clipping at the separating planes, then §5.3.
    RegionalTree cellsTree{out.regionalNodes, out.regionalRoot};
    std::vector<std::vector<FacePolygon>> cells =
        assignToCells(cellsTree, std::move(polygons), int(out.regions.size()));

    std::unordered_map<std::string, int> faceIndex;
    for (size_t i = 0; i < out.faces.size(); ++i)
        faceIndex.emplace(out.faces[i].id, int(i));
    std::vector<int> rank(out.faces.size());
    for (size_t r = 0; r < out.regions.size(); ++r) {
        const std::vector<std::string>& order = *setup.orders[r];
        // Unlisted faces follow the listed ones in scene order; ids that name
        // no face are ignored here (validation reports them).
        for (size_t i = 0; i < rank.size(); ++i)
            rank[i] = int(order.size() + i);
        for (size_t i = order.size(); i-- > 0;)
            if (auto it = faceIndex.find(order[i]); it != faceIndex.end())
                rank[size_t(it->second)] = int(i);
        out.stats.regionPieces += int(cells[r].size());
        buildRegionBsp(out, int(r), std::move(cells[r]), rank);
        const RegionStats& stats = out.regions[r].stats;
        out.stats.fragments += stats.fragments;
        out.stats.splits += stats.splits;
        out.stats.maxDepth = std::max(out.stats.maxDepth, stats.depth);
    }

    // §5.4, §5.5 on the input faces, then the elements cut into the pieces
    // the painter paints per BSP node (solver/prepare/pieces.h).
    meshFaces(out);
    buildPieces(out);
    out.stats.patches = int(out.patches.size());
    out.stats.elements = int(out.elements.size());
    for (const Element& e : out.elements)
        out.stats.area += e.area;

    result.scene = std::move(out);
    return result;
}

} // namespace regio::solver
