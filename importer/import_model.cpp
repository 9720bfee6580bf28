#include "importer/import_model.h"

#include "importer/isolated_read.h"

#include "model/geometry/geometry.h"
#include "model/validation/validation.h"
#include "solver/authoring/region_proposal.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace regio::importer {

namespace {

// The box around every vertex of the scene.
model::Box3 boundsOf(const model::Scene& scene)
{
    model::Box3 box;
    for (const model::Object& o : scene.objects)
        for (const model::Part& p : o.parts)
            for (const Vec3& v : p.vertices)
                box.extend(v);
    return box;
}

// Solver settings for a model of this size: patches about a twentieth of
// the bounding box's diagonal, between 5 cm and 1 m.
void fitSolverSettings(model::Scene& scene)
{
    const model::Box3 box = boundsOf(scene);
    if (!box.empty)
        scene.solver.patchSize = std::clamp(glm::length(box.size()) / 20.0, 0.05, 1.0);
}

} // namespace

model::Result<Imported> importModel(const std::string& path, const ImportOptions& options)
{
    auto read =
        options.read.separateProcess ? readModelFileIsolated(path, options.read) : readModelFile(path, options.read);
    if (!read)
        return read.diagnostics();
    model::Diagnostics warnings = read.diagnostics();

    Imported out;
    out.report.file = path;
    out.report.read = read->counts;
    const MergedModel merged = mergeTriangles(read->soup, options.merge);
    out.report.merge = merged.counts;
    if (merged.faces.empty())
        return model::makeError("'" + path + "': no triangle with an area is left (" +
                                std::to_string(merged.counts.degenerate) + " of no area, " +
                                std::to_string(merged.counts.duplicate) +
                                " repeated; is --scale right for the model's units?)");
    BuiltScene built = buildScene(merged, read->soup);
    out.report.build = built.counts;
    warnings.insert(warnings.end(), built.warnings.begin(), built.warnings.end());
    out.scene = std::move(built.scene);
    fitSolverSettings(out.scene);

    const model::Diagnostics problems = model::validateScene(out.scene);
    if (model::hasErrors(problems)) {
        model::Diagnostics errors;
        for (const model::Diagnostic& d : problems)
            if (d.isError())
                errors.push_back(d);
        return errors;
    }
    warnings.insert(warnings.end(), problems.begin(), problems.end());

    if (options.autoRegions) {
        // The proposal never costs more fragments than one region around
        // everything with its suggested order (it falls back to that).
        auto proposal = solver::proposeRegions(out.scene);
        if (!proposal)
            return proposal.diagnostics();
        out.scene = solver::withRegions(out.scene, proposal->regions);
        out.report.regions = int(proposal->regions.size());
        out.report.fragments = proposal->figures.fragments;
        out.report.singleTreeFragments =
            proposal->singleRegionFragments >= 0 ? proposal->singleRegionFragments : proposal->figures.fragments;
    }
    return {std::move(out), std::move(warnings)};
}

std::string reportJson(const ImportReport& r)
{
    nlohmann::ordered_json j;
    j["file"] = r.file;
    j["meshes"] = r.read.meshes;
    j["triangles_in"] = r.merge.trianglesIn;
    j["dropped"] = {
        {"points_and_lines", r.read.pointsAndLines}, {"no_area", r.merge.degenerate}, {"repeated", r.merge.duplicate}};
    j["welded_vertices"] = r.merge.weldedVertices;
    j["t_junctions_split"] = r.merge.tJunctions;
    j["flat_surfaces"] = r.merge.surfaces;
    j["faces_out"] = r.merge.faces;
    j["objects"] = r.build.objects;
    j["parts"] = {{"total", r.build.parts},
                  {"closed", r.build.closedParts},
                  {"closed_facing_in", r.build.closedFacingIn},
                  {"open_shells", r.build.parts - r.build.closedParts}};
    j["materials"] = r.build.materials;
    j["reflectance_scaled_down"] = r.build.clampedMaterials;
    j["textured_materials"] = r.build.texturedMaterials;
    j["emitting_faces"] = r.build.emittingFaces;
    j["faces_turned"] = r.build.turnedFaces;
    j["bsp"] = {{"regions", r.regions}, {"fragments", r.fragments}, {"single_tree_fragments", r.singleTreeFragments}};
    return j.dump(2) + "\n";
}

} // namespace regio::importer
