#pragma once
// A model file into a well-sorted Regio scene in one step: read (Assimp),
// triangles merged back into planar convex faces, objects, parts and
// materials built, the scene validated, and (on request) automatic regions
// with a suggested BSP root order in each, kept only where they cost fewer
// fragments than one BSP tree with a suggested order (paper §3, §5.3).
// Nothing is lost silently: the report counts what came in, what was merged
// and what was dropped and why.
#include "importer/assimp_reader.h"
#include "importer/face_merging.h"
#include "importer/scene_building.h"
#include "model/result.h"
#include "model/scene.h"

#include <string>

namespace regio::importer {

struct ImportOptions {
    ReadOptions read;
    MergeOptions merge;
    bool autoRegions = true;
};

struct ImportReport {
    std::string file;
    ReadCounts read;
    MergeCounts merge;
    BuildCounts build;
    // BSP fragments (paper §5.2): the scene as imported (its regions, each
    // with its suggested order) and one tree over everything with a
    // suggested order. Equal when the one tree was kept.
    int regions = 0;
    int fragments = 0;
    int singleTreeFragments = 0;
};

struct Imported {
    model::Scene scene;
    ImportReport report;
};

// Refused with the reason when the file cannot be read, holds no triangle,
// or gives a scene with errors (the validator's diagnostics). Warnings (a
// reflectance scaled down, no face that emits, an open part) come beside
// the scene.
model::Result<Imported> importModel(const std::string& path, const ImportOptions& options = {});

// The report as a JSON document (what `regio-solve import --report` writes).
std::string reportJson(const ImportReport& report);

} // namespace regio::importer
