#pragma once
// Internals of scene validation shared by validation.cpp (ids, materials),
// validate_geometry.cpp (faces and part topology) and validate_regions.cpp
// (regions and BSP orders). Not part of the public API: include
// model/validation/validation.h instead.
#include "model/diagnostic.h"
#include "model/geometry/geometry.h"
#include "model/io/json_pointer.h"
#include "model/scene.h"

#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace regio::model::detail {

struct FaceLocation {
    int object = -1;
    int part = -1;
    int face = -1;
};

// What the rules share: the scene, id indices built once (first use of an id
// wins; duplicates are reported by the id rule), and per-part facts that the
// geometry pass learns and the region pass reuses.
struct ValidationContext {
    const Scene& scene;
    Diagnostics& out;
    std::unordered_map<std::string_view, int> materialIndex;
    std::unordered_map<std::string_view, FaceLocation> faceIndex;

    // Per object, per part, per face: the loop is valid and every vertex it
    // names is finite, so the face has positions worth measuring.
    std::vector<std::vector<std::vector<char>>> faceUsable;

    const Part& part(int o, int p) const { return scene.objects[size_t(o)].parts[size_t(p)]; }
    bool usable(const FaceLocation& at) const
    {
        return faceUsable[size_t(at.object)][size_t(at.part)][size_t(at.face)] != 0;
    }
    void error(std::string message, std::string pointer, std::vector<std::string> idPath)
    {
        out.push_back(makeError(std::move(message), std::move(pointer), std::move(idPath)));
    }
    void warning(std::string message, std::string pointer, std::vector<std::string> idPath)
    {
        out.push_back(makeWarning(std::move(message), std::move(pointer), std::move(idPath)));
    }
};

// Id paths (outside in) of a part and a face, for diagnostics.
std::vector<std::string> partPath(const ValidationContext& context, size_t o, size_t p);
std::vector<std::string> facePath(const ValidationContext& context, size_t o, size_t p, size_t f);

// "0.8 mm", "3.2 m", "12 µm": a length for a message.
std::string formatLength(double metres);
// A number for a message, short but exact enough ("0.5", "1e-07").
std::string formatValue(double value);
// `"id"` quoted for messages.
std::string quoted(std::string_view id);

// Faces whose loops and vertices are usable; fills context.faceUsable and
// reports non-finite vertices, loop defects, face geometry and part topology.
void validateParts(ValidationContext& context);
// Region boxes, overlaps, separability, parts against regions, BSP orders.
// Runs after validateParts (it reads faceUsable).
void validateRegions(ValidationContext& context);

// The area of the part of a polygon inside a box (the box's faces count as
// inside, within kDistanceEpsilon).
double areaInsideBox(std::span<const Vec3> loop, const Box3& box);

} // namespace regio::model::detail
