#pragma once
// What a solve will need, known before it starts, so that a scene too big
// for the machine is refused with a message instead of being killed by the
// kernel half way through its preparation.
//
// The element count comes from the faces' areas: meshing (§5.4, §5.5) lays
// strips `patchSize` wide over every face, at least one patch a face, and
// splits each patch into `elementsPerPatch` elements; adaptive subdivision
// (§5.7) grows the mesh at most `growthLimit` times, and the splits in the
// solids' penumbrae before the first shot by a share of that growth at most
// (RefinementPolicy, adaptive_refinement.h).
// The bytes per element are measured (docs/reliability.md), the hemicube's
// item buffers are exact, the kept form-factor rows are the cache's budget.
#include "model/result.h"
#include "model/scene.h"

#include <cstdint>

namespace regio::solver {

struct ResourceEstimate {
    double patches = 0.0;     // of the initial mesh
    double elements = 0.0;    // of the initial mesh
    double maxElements = 0.0; // once adaptive subdivision has grown it to its limit
    double meshBytes = 0.0;   // the prepared scene and the shooting state at maxElements
    double hemicubeBytes = 0.0;
    double cacheBytes = 0.0;
    double totalBytes() const { return meshBytes + hemicubeBytes + cacheBytes; }
};

// Memory per element of the prepared scene and the shooting state, with
// its share of patches, BSP fragments and pieces: measured on the samples
// at fine meshes (the peak resident size over the element count), rounded up.
inline constexpr double kBytesPerElement = 2048.0;
// No solve meshes more elements than this, whatever the memory: a mesh
// beyond it would take hours to shoot, and is nearly always a patch size
// typed in the wrong unit.
inline constexpr double kMaxElements = 20e6;

// `settings` are the resolved ones (resolveSettings); `threads` the hemicube
// threads that will run (at least 1), `cacheBytes` the form-factor cache.
ResourceEstimate estimateResources(const model::Scene& scene, const model::SolverSettings& settings, int threads,
                                   std::uint64_t cacheBytes);

// Memory this process may still take: the kernel's MemAvailable (RAM not in
// use, including caches it can drop), no more than the address-space limit
// (ulimit -v) leaves. 0 when neither can be read.
std::uint64_t availableMemoryBytes();

// An error on /solver/patchSize when the mesh would pass kMaxElements or the
// estimate would pass `availableBytes` (0 = unknown: not checked), saying
// what the scene would need and which setting brings it down.
model::Check checkResources(const ResourceEstimate& estimate, std::uint64_t availableBytes);

} // namespace regio::solver
