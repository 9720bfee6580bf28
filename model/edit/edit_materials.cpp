#include "model/edit/edit_materials.h"

#include "model/edit/edit_support.h"

#include <cmath>

namespace regio::model {

namespace {

int materialIndex(const Scene& scene, const std::string& materialId)
{
    for (int m = 0; m < int(scene.materials.size()); ++m)
        if (scene.materials[size_t(m)].id == materialId)
            return m;
    return -1;
}

} // namespace

Check checkReflectance(const Rgb& reflectance)
{
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(reflectance[c]) || reflectance[c] < 0.0 || reflectance[c] >= 1.0)
            return makeError("reflectance must lie in [0, 1) on every channel, not " + std::to_string(reflectance[c]));
    return success();
}

Check checkEmission(const Rgb& emission)
{
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(emission[c]) || emission[c] < 0.0)
            return makeError("emission must be a finite, non-negative number on every channel, not " +
                             std::to_string(emission[c]));
    return success();
}

Result<int> addMaterial(Scene& scene, Material material, int index)
{
    int count = int(scene.materials.size());
    if (index < -1 || index > count)
        return makeError("material position " + std::to_string(index) + " is out of range");
    if (index == -1)
        index = count;
    std::string pointer = materialPointer(index);
    if (Check check = edit::checkNewId(scene, material.id, "material"); !check)
        return withPointer(check.error(), pointer + "/id");
    if (Check check = checkReflectance(material.reflectance); !check)
        return withPointer(check.error(), pointer + "/reflectance");
    if (Check check = checkEmission(material.emission); !check)
        return withPointer(check.error(), pointer + "/emission");
    scene.materials.insert(scene.materials.begin() + index, std::move(material));
    return index;
}

Result<RemovedMaterial> removeMaterial(Scene& scene, const std::string& materialId)
{
    int m = materialIndex(scene, materialId);
    if (m < 0)
        return edit::unknown("material", materialId);
    for (int o = 0; o < int(scene.objects.size()); ++o) {
        const Object& object = scene.objects[size_t(o)];
        for (int p = 0; p < int(object.parts.size()); ++p) {
            const Part& part = object.parts[size_t(p)];
            if (part.material == materialId)
                return makeError("material \"" + materialId + "\" is used by part \"" + part.id + "\"",
                                 partPointer(o, p) + "/material", {object.id, part.id});
            for (int f = 0; f < int(part.faces.size()); ++f)
                if (part.faces[size_t(f)].material == materialId)
                    return makeError(
                        "material \"" + materialId + "\" is used by face \"" + part.faces[size_t(f)].id + "\"",
                        facePointer(o, p, f) + "/material", {object.id, part.id, part.faces[size_t(f)].id});
        }
    }
    RemovedMaterial removed{std::move(scene.materials[size_t(m)]), m};
    scene.materials.erase(scene.materials.begin() + m);
    return removed;
}

Result<Unit> renameMaterial(Scene& scene, const std::string& materialId, const std::string& newId)
{
    Material* material = scene.findMaterial(materialId);
    if (!material)
        return edit::unknown("material", materialId);
    if (newId == materialId)
        return Unit{};
    if (Check check = edit::checkNewId(scene, newId, "material"); !check)
        return check.error();
    material->id = newId;
    for (Object& object : scene.objects)
        for (Part& part : object.parts) {
            if (part.material == materialId)
                part.material = newId;
            for (Face& face : part.faces)
                if (face.material == materialId)
                    face.material = newId;
        }
    return Unit{};
}

Result<Rgb> setMaterialReflectance(Scene& scene, const std::string& materialId, const Rgb& reflectance)
{
    int m = materialIndex(scene, materialId);
    if (m < 0)
        return edit::unknown("material", materialId);
    if (Check check = checkReflectance(reflectance); !check)
        return withPointer(check.error(), materialPointer(m) + "/reflectance");
    Rgb previous = scene.materials[size_t(m)].reflectance;
    scene.materials[size_t(m)].reflectance = reflectance;
    return previous;
}

Result<Rgb> setMaterialEmission(Scene& scene, const std::string& materialId, const Rgb& emission)
{
    int m = materialIndex(scene, materialId);
    if (m < 0)
        return edit::unknown("material", materialId);
    if (Check check = checkEmission(emission); !check)
        return withPointer(check.error(), materialPointer(m) + "/emission");
    Rgb previous = scene.materials[size_t(m)].emission;
    scene.materials[size_t(m)].emission = emission;
    return previous;
}

Result<std::string> setMaterialName(Scene& scene, const std::string& materialId, std::string name)
{
    Material* material = scene.findMaterial(materialId);
    if (!material)
        return edit::unknown("material", materialId);
    std::swap(material->name, name);
    return name;
}

} // namespace regio::model
