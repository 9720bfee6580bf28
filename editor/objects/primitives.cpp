#include "editor/objects/primitives.h"

#include "model/geometry/primitives.h"

namespace regio::editor {

std::string primitiveBaseId(PrimitiveKind kind)
{
    switch (kind) {
    case PrimitiveKind::Box: return "box";
    case PrimitiveKind::Room: return "room";
    case PrimitiveKind::Prism: return "prism";
    case PrimitiveKind::Wedge: return "wedge";
    case PrimitiveKind::Stairs: return "stairs";
    }
    return "object";
}

model::Result<model::Object> buildPrimitive(const PrimitiveParams& p)
{
    const model::Vec3 half(p.size.x * 0.5, 0.0, p.size.z * 0.5);
    const model::Vec3 min = p.base - half;
    const model::Vec3 max = p.base + model::Vec3(half.x, p.size.y, half.z);
    const std::string partId = p.id + ".body";
    auto wrap = [&](model::Result<model::Part> part) -> model::Result<model::Object> {
        if (!part)
            return part.error();
        return model::Object{p.id, {}, {std::move(*part)}};
    };
    switch (p.kind) {
    case PrimitiveKind::Box: return wrap(model::makeBox(partId, min, max, p.material));
    case PrimitiveKind::Room: return wrap(model::makeRoom(p.id + ".shell", min, max, p.material));
    case PrimitiveKind::Prism:
        return wrap(
            model::makePrism(partId, p.sides, std::min(p.size.x, p.size.z) * 0.5, p.size.y, p.base, p.material));
    case PrimitiveKind::Wedge: return wrap(model::makeWedge(partId, min, max, p.material));
    case PrimitiveKind::Stairs: return model::makeStairs(p.id, p.steps, p.size.x, p.size.z, p.size.y, min, p.material);
    }
    return model::makeError("unknown primitive");
}

} // namespace regio::editor
