#include "solver/resource_estimate.h"

#include "model/geometry/geometry.h"
#include "solver/shooting/adaptive_refinement.h"
#include "solver/shooting/shooting.h"
#include "solver/visibility/hemicube_renderer.h"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace regio::solver {

namespace {

// Strip triangulation (§5.4) cuts a face into triangles about patchSize on a
// side: two per patchSize square, plus the strips' ragged ends.
constexpr double kPatchesPerSquare = 2.0;
// What adaptive subdivision may grow the mesh to, as a multiple of the
// initial mesh (RefinementPolicy): the growth budget, and on top of it the
// splits in the solids' penumbrae before the first shot, at most a share of
// that budget. The splits along contact lines before the first shot come on
// top as well, without a limit of their own: a tenth of the initial mesh on
// the samples (2-3 % of the final one), a third on a hall with a hundred
// solids on its floor (8 % of the final one). Left out of an estimate that
// is no closer than that anyway.
double adaptiveGrowth()
{
    const RefinementPolicy policy;
    return policy.growthLimit + policy.penumbraShare * (policy.growthLimit - 1.0);
}

std::string gigabytes(double bytes)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
    return text;
}

std::string millions(double count)
{
    char text[32];
    if (count >= 1e6)
        std::snprintf(text, sizeof text, "%.3g million", count / 1e6);
    else
        std::snprintf(text, sizeof text, "%.0f", count);
    return text;
}

} // namespace

ResourceEstimate estimateResources(const model::Scene& scene, const model::SolverSettings& settings, int threads,
                                   std::uint64_t cacheBytes)
{
    ResourceEstimate e;
    const double patchArea = settings.patchSize * settings.patchSize;
    std::vector<model::Vec3> loop;
    for (const model::Object& object : scene.objects)
        for (const model::Part& part : object.parts)
            for (const model::Face& face : part.faces) {
                loop.clear();
                for (const int v : face.loop)
                    if (v >= 0 && std::size_t(v) < part.vertices.size())
                        loop.push_back(part.vertices[std::size_t(v)]);
                const double area = model::polygonArea(loop);
                e.patches += std::max(1.0, std::ceil(kPatchesPerSquare * area / patchArea));
            }
    e.elements = e.patches * std::max(1, settings.elementsPerPatch);
    e.maxElements = settings.adaptive.enabled ? e.elements * adaptiveGrowth() : e.elements;
    e.meshBytes = e.maxElements * kBytesPerElement;
    // Every painter keeps an item buffer of the whole hemicube (a top face
    // N x N and four sides N x N/2), ids and, for the z-buffer, depths; the
    // helper threads a stretch of the same size; the lights' finer hemicube
    // (solver/shooting/shooting.h) has painters of its own.
    const double n = settings.hemicube;
    const double light = lightHemicubeResolution(settings.hemicube);
    const int painters = std::min(resolveThreadCount(threads), HemicubeRenderer::kMaxThreads);
    e.hemicubeBytes = 2.0 * painters * 3.0 * (n * n + light * light) * 8.0;
    e.cacheBytes = double(cacheBytes);
    return e;
}

std::uint64_t availableMemoryBytes()
{
    std::uint64_t available = 0;
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    std::uint64_t value = 0;
    std::string unit;
    while (meminfo >> key >> value) {
        std::getline(meminfo, unit);
        if (key == "MemAvailable:") {
            available = value * 1024;
            break;
        }
    }
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
        const auto cap = std::uint64_t(limit.rlim_cur);
        available = available == 0 ? cap : std::min(available, cap);
    }
    return available;
}

model::Check checkResources(const ResourceEstimate& e, std::uint64_t availableBytes)
{
    const std::string pointer = "/solver/patchSize";
    if (e.maxElements > kMaxElements)
        return model::makeError("the mesh would have about " + millions(e.maxElements) +
                                    " elements, beyond the limit of " + millions(kMaxElements) +
                                    ": raise the patch size (or lower elementsPerPatch)",
                                pointer);
    if (availableBytes > 0 && e.totalBytes() > double(availableBytes))
        return model::makeError(
            "the solve would need about " + gigabytes(e.totalBytes()) + " of memory (" + millions(e.maxElements) +
                " elements), more than the " + gigabytes(double(availableBytes)) +
                " available (free memory, or the process's ulimit): raise the patch size, lower the hemicube "
                "resolution or the form-factor cache",
            pointer);
    return model::success();
}

} // namespace regio::solver
