#include "model/scene.h"

namespace regio::model {

namespace {

template <typename Vector>
auto* findById(Vector& items, const std::string& id)
{
    for (auto& item : items)
        if (item.id == id)
            return &item;
    return static_cast<decltype(&items.front())>(nullptr);
}

} // namespace

const char* visibilityName(Visibility v) { return v == Visibility::Painter ? "painter" : "zbuffer"; }

const char* regionsModeName(RegionsMode mode)
{
    switch (mode) {
    case RegionsMode::Authored: return "authored";
    case RegionsMode::None: return "none";
    case RegionsMode::Auto: return "auto";
    }
    return "authored";
}

std::optional<Visibility> parseVisibility(std::string_view text)
{
    if (text == "painter")
        return Visibility::Painter;
    if (text == "zbuffer")
        return Visibility::ZBuffer;
    return std::nullopt;
}

std::optional<RegionsMode> parseRegionsMode(std::string_view text)
{
    for (RegionsMode mode : {RegionsMode::Authored, RegionsMode::None, RegionsMode::Auto})
        if (text == regionsModeName(mode))
            return mode;
    return std::nullopt;
}

const Material* Scene::findMaterial(const std::string& id) const { return findById(materials, id); }
Material* Scene::findMaterial(const std::string& id) { return findById(materials, id); }
const Object* Scene::findObject(const std::string& id) const { return findById(objects, id); }
Object* Scene::findObject(const std::string& id) { return findById(objects, id); }
const Region* Scene::findRegion(const std::string& id) const { return findById(regions, id); }
Region* Scene::findRegion(const std::string& id) { return findById(regions, id); }

const Part* Scene::findPart(const std::string& id) const
{
    for (const Object& object : objects)
        if (const Part* part = findById(object.parts, id))
            return part;
    return nullptr;
}

Part* Scene::findPart(const std::string& id)
{
    return const_cast<Part*>(static_cast<const Scene*>(this)->findPart(id));
}

Scene::FaceLocation Scene::locateFace(const std::string& faceId) const
{
    for (int o = 0; o < int(objects.size()); ++o) {
        const auto& parts = objects[size_t(o)].parts;
        for (int p = 0; p < int(parts.size()); ++p) {
            const auto& faces = parts[size_t(p)].faces;
            for (int f = 0; f < int(faces.size()); ++f)
                if (faces[size_t(f)].id == faceId)
                    return {o, p, f};
        }
    }
    return {};
}

const Object* Scene::ownerOfPart(const std::string& partId) const
{
    for (const Object& object : objects)
        if (findById(object.parts, partId))
            return &object;
    return nullptr;
}

const Material* Scene::materialOf(const Part& part, const Face& face) const
{
    return findMaterial(face.material.empty() ? part.material : face.material);
}

bool Scene::idInUse(const std::string& id) const
{
    if (findMaterial(id) || findRegion(id))
        return true;
    for (const Object& object : objects) {
        if (object.id == id)
            return true;
        for (const Part& part : object.parts) {
            if (part.id == id)
                return true;
            for (const Face& face : part.faces)
                if (face.id == id)
                    return true;
        }
    }
    return false;
}

std::string Scene::uniqueId(const std::string& base) const
{
    if (!idInUse(base))
        return base;
    for (int n = 2;; ++n) {
        std::string candidate = base + "-" + std::to_string(n);
        if (!idInUse(candidate))
            return candidate;
    }
}

} // namespace regio::model
