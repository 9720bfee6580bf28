#include "model/validation/validation.h"

#include "model/validation/validation_detail.h"

#include "model/io/printable.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace regio::model {

namespace detail {

std::vector<std::string> partPath(const ValidationContext& context, size_t o, size_t p)
{
    const Object& object = context.scene.objects[o];
    return {object.id, object.parts[p].id};
}

std::vector<std::string> facePath(const ValidationContext& context, size_t o, size_t p, size_t f)
{
    const Object& object = context.scene.objects[o];
    return {object.id, object.parts[p].id, object.parts[p].faces[f].id};
}

std::string formatValue(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g", value);
    return buffer;
}

std::string formatLength(double metres)
{
    const double magnitude = std::abs(metres);
    if (magnitude >= 1.0 || magnitude == 0.0)
        return formatValue(metres) + " m";
    if (magnitude >= 1e-4)
        return formatValue(metres * 1e3) + " mm";
    return formatValue(metres * 1e6) + " \u00b5m";
}

std::string quoted(std::string_view id) { return "\"" + std::string(id) + "\""; }

} // namespace detail

namespace {

using detail::ValidationContext;

const char* kChannel[3] = {"red", "green", "blue"};

// Ids are one namespace: a BSP order or an editor selection names an element
// by id alone, so an id must not be shared across kinds either.
void validateIds(ValidationContext& context)
{
    // Where an id was used; pointers and id paths are only spelled out for
    // the rare duplicate, so a clean 100 000-face scene allocates nothing here.
    struct Use {
        const char* kind;
        size_t a = 0, b = 0, c = 0; // material / region / object, part, face positions
    };
    auto pointerOf = [](const Use& use) {
        const std::string kind = use.kind;
        if (kind == "material")
            return materialPointer(use.a);
        if (kind == "region")
            return regionPointer(use.a);
        if (kind == "object")
            return objectPointer(use.a);
        if (kind == "part")
            return partPointer(use.a, use.b);
        return facePointer(use.a, use.b, use.c);
    };
    const Scene& scene = context.scene;
    auto idPathOf = [&](const Use& use) -> std::vector<std::string> {
        const std::string kind = use.kind;
        if (kind == "material")
            return {scene.materials[use.a].id};
        if (kind == "region")
            return {scene.regions[use.a].id};
        if (kind == "object")
            return {scene.objects[use.a].id};
        if (kind == "part")
            return detail::partPath(context, use.a, use.b);
        return detail::facePath(context, use.a, use.b, use.c);
    };
    std::unordered_map<std::string_view, Use> seen;
    seen.reserve(context.faceIndex.size() + scene.materials.size() + scene.regions.size());
    auto claim = [&](const std::string& id, const Use& use) {
        if (id.empty()) {
            context.error(std::string("the ") + use.kind + " has an empty id", pointerOf(use) + "/id", idPathOf(use));
            return;
        }
        // Ids are names people read, type and search for; a control character
        // in one (a pasted escape sequence, a newline) hides or garbles it.
        const auto control = std::find_if(id.begin(), id.end(), [](char c) {
            const auto u = static_cast<unsigned char>(c);
            return u < 0x20 || u == 0x7f;
        });
        if (control != id.end()) {
            char code[16];
            std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(static_cast<unsigned char>(*control)));
            context.error(std::string("the ") + use.kind + " id " + detail::quoted(printable(id)) +
                              " holds a control character (" + code + "); use printable characters",
                          pointerOf(use) + "/id", idPathOf(use));
            return;
        }
        auto [it, fresh] = seen.try_emplace(id, use);
        if (!fresh)
            context.error("duplicate id " + detail::quoted(id) + ": already used by the " + it->second.kind + " at " +
                              pointerOf(it->second),
                          pointerOf(use) + "/id", idPathOf(use));
    };
    for (size_t m = 0; m < scene.materials.size(); ++m)
        claim(scene.materials[m].id, {"material", m});
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& object = scene.objects[o];
        claim(object.id, {"object", o});
        for (size_t p = 0; p < object.parts.size(); ++p) {
            claim(object.parts[p].id, {"part", o, p});
            for (size_t f = 0; f < object.parts[p].faces.size(); ++f)
                claim(object.parts[p].faces[f].id, {"face", o, p, f});
        }
    }
    for (size_t r = 0; r < scene.regions.size(); ++r)
        claim(scene.regions[r].id, {"region", r});
}

void buildIndices(ValidationContext& context)
{
    const Scene& scene = context.scene;
    size_t faceCount = 0;
    for (const Object& object : scene.objects)
        for (const Part& part : object.parts)
            faceCount += part.faces.size();
    context.faceIndex.reserve(faceCount);
    for (size_t m = 0; m < scene.materials.size(); ++m)
        context.materialIndex.try_emplace(scene.materials[m].id, int(m));
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const auto& parts = scene.objects[o].parts;
        for (size_t p = 0; p < parts.size(); ++p)
            for (size_t f = 0; f < parts[p].faces.size(); ++f)
                context.faceIndex.try_emplace(parts[p].faces[f].id, detail::FaceLocation{int(o), int(p), int(f)});
    }
}

void validateMaterials(ValidationContext& context)
{
    const Scene& scene = context.scene;
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        const Material& material = scene.materials[m];
        const std::string pointer = materialPointer(m);
        const std::string name = "material " + detail::quoted(material.id);
        for (int c = 0; c < 3; ++c) {
            const double r = material.reflectance[c];
            const std::string at = pointer + "/reflectance/" + std::to_string(c);
            if (!std::isfinite(r))
                context.error(name + ": the " + kChannel[c] + " reflectance is not a finite number", at, {material.id});
            else if (r < 0.0)
                context.error(name + ": the " + kChannel[c] + " reflectance " + detail::formatValue(r) +
                                  " is negative; reflectance lies in [0, 1)",
                              at, {material.id});
            else if (r >= 1.0)
                context.error(name + ": the " + kChannel[c] + " reflectance " + detail::formatValue(r) +
                                  " must be below 1, or the reflected energy never dies out and "
                                  "the solution does not converge",
                              at, {material.id});
        }
        for (int c = 0; c < 3; ++c) {
            const double e = material.emission[c];
            const std::string at = pointer + "/emission/" + std::to_string(c);
            if (!std::isfinite(e))
                context.error(name + ": the " + kChannel[c] + " emission is not a finite number", at, {material.id});
            else if (e < 0.0)
                context.error(name + ": the " + kChannel[c] + " emission " + detail::formatValue(e) +
                                  " is negative; a surface cannot absorb light it was never given",
                              at, {material.id});
        }
    }
}

// Unknown references, faces without any material, and whether anything emits.
void validateMaterialUse(ValidationContext& context)
{
    const Scene& scene = context.scene;
    auto find = [&](const std::string& id) -> const Material* {
        auto it = context.materialIndex.find(id);
        return it == context.materialIndex.end() ? nullptr : &scene.materials[size_t(it->second)];
    };
    auto emits = [](const Material* material) {
        return material && std::isfinite(material->emission.x) && std::isfinite(material->emission.y) &&
               std::isfinite(material->emission.z) &&
               (material->emission.x > 0.0 || material->emission.y > 0.0 || material->emission.z > 0.0);
    };
    bool anyEmitter = false;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& object = scene.objects[o];
        for (size_t p = 0; p < object.parts.size(); ++p) {
            const Part& part = object.parts[p];
            const Material* partMaterial = nullptr;
            if (!part.material.empty()) {
                partMaterial = find(part.material);
                if (!partMaterial)
                    context.error("part " + detail::quoted(part.id) + " uses the unknown material " +
                                      detail::quoted(part.material),
                                  partPointer(o, p) + "/material", detail::partPath(context, o, p));
            }
            for (size_t f = 0; f < part.faces.size(); ++f) {
                const Face& face = part.faces[f];
                const Material* material = partMaterial;
                if (!face.material.empty()) {
                    material = find(face.material);
                    if (!material)
                        context.error("face " + detail::quoted(face.id) + " uses the unknown material " +
                                          detail::quoted(face.material),
                                      facePointer(o, p, f) + "/material", detail::facePath(context, o, p, f));
                } else if (part.material.empty()) {
                    context.error("face " + detail::quoted(face.id) + " has no material, and neither has part " +
                                      detail::quoted(part.id) + ": give one to either",
                                  facePointer(o, p, f), detail::facePath(context, o, p, f));
                }
                anyEmitter = anyEmitter || emits(material);
            }
        }
    }
    if (!anyEmitter)
        context.warning(
            "no face emits light (no face uses a material with emission above 0): "
            "there is nothing to solve",
            "", {});
}

} // namespace

Diagnostics validateScene(const Scene& scene)
{
    Diagnostics out;
    ValidationContext context{scene, out, {}, {}, {}};
    buildIndices(context);
    validateIds(context);
    validateMaterials(context);
    validateMaterialUse(context);
    detail::validateParts(context);
    detail::validateRegions(context);
    return out;
}

} // namespace regio::model
