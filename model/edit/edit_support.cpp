#include "model/edit/edit_support.h"

#include <cmath>

namespace regio::model::edit {

PartLocation locatePart(const Scene& scene, const std::string& partId)
{
    for (int o = 0; o < int(scene.objects.size()); ++o) {
        const auto& parts = scene.objects[size_t(o)].parts;
        for (int p = 0; p < int(parts.size()); ++p)
            if (parts[size_t(p)].id == partId)
                return {o, p};
    }
    return {};
}

int objectIndex(const Scene& scene, const std::string& objectId)
{
    for (int o = 0; o < int(scene.objects.size()); ++o)
        if (scene.objects[size_t(o)].id == objectId)
            return o;
    return -1;
}

Diagnostic unknown(const std::string& what, const std::string& id)
{
    return makeError("no " + what + " with id \"" + id + "\"");
}

Check checkNewId(const Scene& scene, const std::string& id, const std::string& what,
                 const std::unordered_set<std::string>& alsoTaken, const std::unordered_set<std::string>& released)
{
    if (id.empty())
        return makeError("the " + what + " id must not be empty");
    if (alsoTaken.count(id) || (scene.idInUse(id) && !released.count(id)))
        return makeError("the id \"" + id +
                         "\" is already in use; ids must be unique across "
                         "objects, parts, faces, materials and regions");
    return success();
}

Check checkMaterialReference(const Scene& scene, const std::string& material, const std::string& pointer)
{
    if (material.empty() || scene.findMaterial(material))
        return success();
    return makeError("unknown material \"" + material + "\"", pointer);
}

bool isFinite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

Check checkPartGeometry(const Scene& scene, const std::vector<Vec3>& vertices, const std::vector<Face>& faces,
                        const std::string& pointer)
{
    for (size_t v = 0; v < vertices.size(); ++v)
        if (!isFinite(vertices[v]))
            return makeError("vertex is not a finite number", pointer + "/vertices/" + std::to_string(v));
    for (size_t f = 0; f < faces.size(); ++f) {
        const Face& face = faces[f];
        std::string fp = pointer + "/faces/" + std::to_string(f);
        if (face.loop.size() < 3)
            return makeError("face \"" + face.id + "\" has fewer than 3 vertices", fp + "/loop");
        for (int index : face.loop)
            if (index < 0 || index >= int(vertices.size()))
                return makeError("face \"" + face.id + "\" names vertex " + std::to_string(index) + " of a part with " +
                                     std::to_string(vertices.size()),
                                 fp + "/loop");
        if (Check check = checkMaterialReference(scene, face.material, fp + "/material"); !check)
            return check;
    }
    return success();
}

Check checkNewPart(const Scene& scene, const Part& part, const std::string& pointer,
                   std::unordered_set<std::string>& taken, const std::unordered_set<std::string>& released)
{
    if (Check check = checkNewId(scene, part.id, "part", taken, released); !check)
        return withPointer(check.error(), pointer + "/id");
    taken.insert(part.id);
    for (size_t f = 0; f < part.faces.size(); ++f) {
        if (Check check = checkNewId(scene, part.faces[f].id, "face", taken, released); !check)
            return withPointer(check.error(), pointer + "/faces/" + std::to_string(f) + "/id");
        taken.insert(part.faces[f].id);
    }
    if (Check check = checkMaterialReference(scene, part.material, pointer + "/material"); !check)
        return check;
    return checkPartGeometry(scene, part.vertices, part.faces, pointer);
}

std::string IdAllocator::fresh(const std::string& base)
{
    std::string id = base;
    for (int n = 2; m_scene.idInUse(id) || m_taken.count(id); ++n)
        id = base + "-" + std::to_string(n);
    m_taken.insert(id);
    return id;
}

std::string IdAllocator::freshRenamed(const std::string& id, const std::string& oldPrefix, const std::string& newPrefix)
{
    return fresh(replacePrefix(id, oldPrefix, newPrefix));
}

std::string replacePrefix(const std::string& id, const std::string& oldPrefix, const std::string& newPrefix)
{
    if (id.size() > oldPrefix.size() && id.compare(0, oldPrefix.size(), oldPrefix) == 0 && id[oldPrefix.size()] == '.')
        return newPrefix + id.substr(oldPrefix.size());
    return id;
}

} // namespace regio::model::edit
