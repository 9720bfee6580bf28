#include "solver/prepare/prepare.h"

#include "model/geometry/winged_edge.h"
#include "model/io/json_pointer.h"
#include "solver/prepare/bsp_tree.h"
#include "solver/prepare/meshing.h"
#include "solver/prepare/pieces.h"
#include "solver/settings.h"

#include <glm/common.hpp>

#include <string>
#include <unordered_map>

namespace regio::solver {

namespace {

Box3 regionBox(const model::Region& region)
{
    Box3 box;
    box.extend(glm::min(region.min, region.max));
    box.extend(glm::max(region.min, region.max));
    return box;
}

} // namespace

PrepareOptions prepareOptionsFor(const model::SolverSettings& settings, int autoRegionPatchThreshold)
{
    PrepareOptions options;
    options.regions = settings.regions;
    options.autoRegionPatchThreshold = autoRegionPatchThreshold;
    options.patchSize = settings.patchSize;
    options.elementsPerPatch = settings.elementsPerPatch;
    return options;
}

model::Result<FaceSet> collectFaces(const model::Scene& scene)
{
    FaceSet out;
    model::Diagnostics diagnostics;
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
                const std::string pointer = model::facePointer(o, p, f);
                const std::vector<std::string> idPath{object.id, part.id, face.id};

                InputFace info;
                info.id = face.id;
                info.objectId = object.id;
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
                } else {
                    info.materialId = material->id;
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
                    diagnostics.push_back(
                        model::makeWarning("face '" + face.id + "' has no area; it is left out of the solution",
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
                }
                info.area = area;
                std::vector<Vec3> clean = cleanConvexLoop(loop);
                if (clean.size() >= 3) {
                    for (const Vec3& v : clean)
                        out.bounds.extend(v);
                    info.polygon = clean;
                    out.polygons.push_back({std::move(clean), index});
                }
                out.faces.push_back(std::move(info));
                out.properties.push_back(props);
            }
        }
    }
    if (model::hasErrors(diagnostics))
        return diagnostics;
    return {std::move(out), std::move(diagnostics)};
}

model::Result<RegionLayout> layOutRegions(const model::Scene& scene, const FaceSet& faces, RegionsMode mode,
                                          double patchSize, int autoRegionPatchThreshold)
{
    // One priority list for modes that do not use the authored regions: the
    // authored orders one after the other, so the author's sorting still counts.
    std::vector<std::string> combinedOrder;
    for (const model::Region& region : scene.regions)
        combinedOrder.insert(combinedOrder.end(), region.bspOrder.begin(), region.bspOrder.end());

    RegionLayout out;
    std::vector<Box3> boxes;
    auto add = [&](std::string id, const Box3& box, const std::vector<std::string>& order) {
        Region region;
        region.id = std::move(id);
        region.box = box;
        out.regions.push_back(std::move(region));
        out.orders.push_back(order);
        boxes.push_back(box);
    };
    if (mode == RegionsMode::Authored && !scene.regions.empty()) {
        for (const model::Region& region : scene.regions)
            add(region.id, regionBox(region), region.bspOrder);
    } else if (mode == RegionsMode::Auto) {
        const std::vector<Box3> automatic =
            autoRegionBoxes(faces.polygons, faces.bounds, autoRegionPatchThreshold, patchSize);
        for (size_t i = 0; i < automatic.size(); ++i)
            add("auto-" + std::to_string(i + 1), automatic[i], combinedOrder);
    }
    if (boxes.empty())
        add("scene", faces.bounds, combinedOrder);

    RegionalTreeBuild tree = buildRegionalTree(boxes);
    if (!tree.ok()) {
        std::string names;
        for (int r : tree.inseparable)
            names += (names.empty() ? "'" : ", '") + out.regions[size_t(r)].id + "'";
        const size_t first = size_t(tree.inseparable.front());
        return model::makeError("regions " + names +
                                    " cannot be separated by axis-aligned planes (they overlap or interlock); "
                                    "move or split one of them",
                                model::regionPointer(first), {out.regions[first].id});
    }
    out.tree = std::move(tree.tree);
    return out;
}

model::Result<BspInput> prepareBspInput(const model::Scene& scene, const PrepareOptions& options)
{
    SettingsOverrides overrides;
    overrides.patchSize = options.patchSize;
    overrides.elementsPerPatch = options.elementsPerPatch;
    const model::SolverSettings settings = resolveSettings(scene.solver, overrides);
    if (model::Check meshable = checkMeshSettings(settings); !meshable)
        return meshable.error();

    model::Result<FaceSet> faces = collectFaces(scene);
    if (!faces)
        return model::Result<BspInput>::failureOf(faces);
    model::Diagnostics warnings = faces.takeDiagnostics();
    model::Result<RegionLayout> layout =
        layOutRegions(scene, *faces, options.regions, settings.patchSize, options.autoRegionPatchThreshold);
    if (!layout) {
        warnings.push_back(layout.error());
        return warnings;
    }
    BspInput out;
    out.patchSize = settings.patchSize;
    out.elementsPerPatch = settings.elementsPerPatch;
    out.layout = std::move(*layout);
    out.faces = std::move(*faces);
    out.cells = assignToCells(out.layout.tree, out.faces.polygons, int(out.layout.regions.size()));
    return {std::move(out), std::move(warnings)};
}

PreparedScene buildBsps(BspInput input)
{
    PreparedScene out;
    out.faces = std::move(input.faces.faces);
    out.properties = std::move(input.faces.properties);
    out.bounds = input.faces.bounds;
    out.stats.inputFaces = int(input.faces.polygons.size());
    input.faces.polygons.clear();
    out.patchSize = input.patchSize;
    out.elementsPerPatch = input.elementsPerPatch;
    out.regionalNodes = std::move(input.layout.tree.nodes);
    out.regionalRoot = input.layout.tree.root;
    out.regions = std::move(input.layout.regions);

    std::unordered_map<std::string, int> faceIndex;
    for (size_t i = 0; i < out.faces.size(); ++i)
        faceIndex.emplace(out.faces[i].id, int(i));
    std::vector<int> rank(out.faces.size());
    for (size_t r = 0; r < out.regions.size(); ++r) {
        const std::vector<std::string>& order = input.layout.orders[r];
        // Unlisted faces follow the listed ones in scene order; ids that name
        // no face are ignored here (validation reports them).
        for (size_t i = 0; i < rank.size(); ++i)
            rank[i] = int(order.size() + i);
        for (size_t i = order.size(); i-- > 0;)
            if (auto it = faceIndex.find(order[i]); it != faceIndex.end())
                rank[size_t(it->second)] = int(i);
        out.stats.regionPieces += int(input.cells[r].size());
        buildRegionBsp(out, int(r), std::move(input.cells[r]), rank);
        const RegionStats& stats = out.regions[r].stats;
        out.stats.fragments += stats.fragments;
        out.stats.splits += stats.splits;
        out.stats.maxDepth = std::max(out.stats.maxDepth, stats.depth);
    }
    return out;
}

model::Result<PreparedScene> prepareBsp(const model::Scene& scene, const PrepareOptions& options)
{
    model::Result<BspInput> input = prepareBspInput(scene, options);
    if (!input)
        return model::Result<PreparedScene>::failureOf(input);
    model::Diagnostics warnings = input.takeDiagnostics();
    return {buildBsps(std::move(*input)), std::move(warnings)};
}

model::Result<PreparedScene> prepareScene(const model::Scene& scene, const PrepareOptions& options)
{
    model::Result<PreparedScene> prepared = prepareBsp(scene, options);
    if (!prepared)
        return prepared;
    PreparedScene& out = *prepared;
    // §5.4, §5.5 on the input faces, then the elements cut into the pieces
    // the painter paints per BSP node (solver/prepare/pieces.h).
    meshFaces(out);
    buildPieces(out);
    out.stats.patches = int(out.patches.size());
    out.stats.elements = int(out.elements.size());
    for (const Element& e : out.elements)
        out.stats.area += e.area;
    return prepared;
}

} // namespace regio::solver
