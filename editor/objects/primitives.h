#pragma once
// What the Create menu makes: a primitive's kind and parameters, and the
// object the model's primitive functions build from them.
#include "model/result.h"
#include "model/scene.h"

#include <string>

namespace regio::editor {

enum class PrimitiveKind { Box, Room, Prism, Wedge, Stairs };

struct PrimitiveParams {
    PrimitiveKind kind = PrimitiveKind::Box;
    std::string id;        // the object's id; parts and faces derive from it
    std::string material;  // empty = none yet
    model::Vec3 base{0.0}; // centre of the bottom face, metres
    model::Vec3 size{1.0, 1.0, 1.0};
    int sides = 16; // prism / cylinder
    int steps = 5;  // stairs
};

// The object for the parameters (ids not yet made fresh in any scene).
model::Result<model::Object> buildPrimitive(const PrimitiveParams& params);
// A readable default id for a kind ("box", "room", ...), before uniqueness.
std::string primitiveBaseId(PrimitiveKind kind);

} // namespace regio::editor
