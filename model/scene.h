#pragma once
// The scene: whole-part B-rep objects, materials, regions with their BSP
// root-patch order, solver settings and an optional camera. Plain value types:
// copyable, comparable, no signals. Cross-references use ids, never indices.
#include "model/types.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace regio::model {

struct Material {
    std::string id;
    std::string name;               // optional display name; empty = use the id
    Rgb reflectance{0.5, 0.5, 0.5}; // diffuse coefficient per channel, [0,1)
    Rgb emission{0.0, 0.0, 0.0};    // radiant exitance per unit area (paper §5.1)

    bool operator==(const Material&) const = default;
};

// A planar convex polygon. `loop` indexes the vertices of its part and runs
// counter-clockwise seen from the side the face's normal points to.
struct Face {
    std::string id;
    std::vector<int> loop;
    std::string material; // empty = the part's material

    bool operator==(const Face&) const = default;
};

// One B-rep solid (closed) or open shell (walls): the "part" of a whole-part model.
struct Part {
    std::string id;
    std::string name;
    std::string material; // default material of its faces
    std::vector<Vec3> vertices;
    std::vector<Face> faces;

    bool operator==(const Part&) const = default;
};

// The "whole" of a whole-part model: the paper's table with parts desk and legs.
struct Object {
    std::string id;
    std::string name;
    std::vector<Part> parts;

    bool operator==(const Object&) const = default;
};

// An axis-aligned box of space with its BSP root-patch order (paper §5.2, §5.3).
struct Region {
    std::string id;
    std::string name;
    Vec3 min{0.0};
    Vec3 max{0.0};
    std::vector<std::string> bspOrder; // face ids, first = root of the region's BSP tree

    bool operator==(const Region&) const = default;
};

struct AdaptiveSettings {
    bool enabled = true;
    double threshold = 0.05; // relative luminance difference between neighbours
    double minEdge = 0.02;   // metres
    // Anchoring (Baum et al. 1991, the paper's Figure 5): keep the element mesh
    // conforming and graded 2:1. Off only to show what it is for.
    bool anchoring = true;

    bool operator==(const AdaptiveSettings&) const = default;
};

// How the hemicube decides visibility: the paper's painter (back to front
// through the regional BSP trees, no depth) or a z-buffer for reference.
enum class Visibility { Painter, ZBuffer };
// Which regions the solver uses: the authored boxes, none (one BSP tree for
// the whole scene, the baseline) or automatic boxes by patch count (§3).
enum class RegionsMode { Authored, None, Auto };

const char* visibilityName(Visibility v);      // "painter" | "zbuffer"
const char* regionsModeName(RegionsMode mode); // "authored" | "none" | "auto"
std::optional<Visibility> parseVisibility(std::string_view text);
std::optional<RegionsMode> parseRegionsMode(std::string_view text);

struct SolverSettings {
    int hemicube = 150;       // top face resolution N (sides are N x N/2)
    double patchSize = 0.5;   // strip width of the patch triangulation, metres
    int elementsPerPatch = 4; // element / patch ratio
    AdaptiveSettings adaptive;
    int maxIterations = 500;
    double convergence = 0.001; // stop when unshot / emitted power falls below
    Visibility visibility = Visibility::Painter;
    RegionsMode regions = RegionsMode::Authored;

    bool operator==(const SolverSettings&) const = default;
};

struct Camera {
    Vec3 position{0.0, 0.0, 5.0};
    Vec3 target{0.0, 0.0, 0.0};
    Vec3 up{0.0, 1.0, 0.0};
    double fovY = 45.0; // vertical field of view, degrees

    bool operator==(const Camera&) const = default;
};

struct Scene {
    std::vector<Material> materials;
    std::vector<Object> objects;
    std::vector<Region> regions;
    SolverSettings solver;
    std::optional<Camera> camera;

    bool operator==(const Scene&) const = default;

    // Lookups by id; nullptr when absent. Linear: scenes hold hundreds of
    // parts, and callers that need many lookups build their own index.
    const Material* findMaterial(const std::string& id) const;
    Material* findMaterial(const std::string& id);
    const Object* findObject(const std::string& id) const;
    Object* findObject(const std::string& id);
    const Part* findPart(const std::string& id) const;
    Part* findPart(const std::string& id);
    const Region* findRegion(const std::string& id) const;
    Region* findRegion(const std::string& id);

    // Where a face lives: object, part and face indices.
    struct FaceLocation {
        int object = -1;
        int part = -1;
        int face = -1;
        bool valid() const { return face >= 0; }
    };
    FaceLocation locateFace(const std::string& faceId) const;
    // The object that owns a part, or nullptr.
    const Object* ownerOfPart(const std::string& partId) const;

    // The material a face is drawn with: its own, else its part's; nullptr if
    // neither names an existing material.
    const Material* materialOf(const Part& part, const Face& face) const;

    // Every id used by any object, part, face, material or region.
    bool idInUse(const std::string& id) const;
    // `base` if unused, else base + "-2", "-3", ...: a fresh human-readable id.
    std::string uniqueId(const std::string& base) const;
};

} // namespace regio::model
