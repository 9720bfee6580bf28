#pragma once
// What a solve hands out: statistics, the element mesh and a snapshot of the
// radiosity on it, and the mean radiosity of every input face. Everything
// here is plain data that can be copied to another thread; output/ draws
// every picture and file from it.
#include "model/types.h"
#include "solver/shooting/energy_balance.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace regio::solver {

using model::Vec3;

enum class StopReason { None, Converged, MaxIterations, NothingToShoot, Cancelled };
const char* stopReasonName(StopReason reason);

// Percent of a solve's work done: the larger of the iterations against their
// limit and the unshot power's way down to the convergence target (on a log
// scale, since progressive shooting drops it about geometrically). The
// batch's progress lines and the editor's progress bar show it.
int workPercent(int iteration, int maxIterations, double unshot, double convergence);

struct SolverStats {
    int iterations = 0;
    int renderedShots = 0; // shots that rendered a hemicube; the others reused a kept row
    int patches = 0;
    int elements = 0;       // active elements the shooter works on
    int adaptiveRounds = 0; // §5.7 refinement rounds that split elements
    // Elements that the splits along contact lines added before the first
    // shot (solver/shooting/contact_lines.h); part of `elements`.
    int contactElements = 0;
    // Elements that the splits in the solids' penumbrae added before the
    // first shot (solver/shooting/penumbrae.h); part of `elements`.
    int penumbraElements = 0;
    EnergyBalance energy;
    Rgb ambient{0.0};
    double unshotRatio = 0.0; // largest unshot / emitted over the emitting channels
    StopReason stop = StopReason::None;
    double preprocessSeconds = 0.0;
    double shootSeconds = 0.0;
    double adaptiveSeconds = 0.0; // spent refining the mesh (not part of shootSeconds)
};

// The element mesh, shared between snapshots until the mesh changes.
struct SolutionMesh {
    int revision = 0; // changes whenever the mesh does
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles; // per element, CCW from its normal
    std::vector<Vec3> normals;                 // per element
    std::vector<int> elementFace;              // per element: index into faceIds
    std::vector<Rgb> reflectance;              // per element
    std::vector<std::string> faceIds;          // the input faces of the file, scene order
    // After adaptive subdivision (§5.7) with anchoring: the conforming
    // triangulation of the elements (a coarse element next to finer ones is
    // fanned through their vertices on its edges, the "special edges" of the
    // paper's Figure 5), each triangle with the element whose value it shows.
    // Empty before the first refinement and with anchoring off: then the
    // triangles above are what there is.
    std::vector<std::array<int, 3>> anchoredTriangles;
    std::vector<int> anchoredElement;
};

struct SolutionSnapshot {
    std::shared_ptr<const SolutionMesh> mesh;
    std::vector<Rgb> radiosity; // per element, W/m^2
    SolverStats stats;
    // Radiosity plus the ambient term (Cohen et al. 1988), for early pictures.
    Rgb displayRadiosity(size_t element) const
    {
        return radiosity[element] + mesh->reflectance[element] * stats.ambient;
    }
};

struct FaceResult {
    std::string id; // face id of the file
    double area = 0.0;
    Rgb radiosity{0.0}; // area-weighted mean over the face's elements
};

} // namespace regio::solver
