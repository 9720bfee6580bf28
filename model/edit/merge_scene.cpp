#include "model/edit/merge_scene.h"

#include "model/edit/edit_materials.h"
#include "model/edit/edit_objects.h"

#include <map>

namespace regio::model {

MergeItems itemsToMerge(const Scene& scene, const Scene& incoming)
{
    MergeItems out;
    // The scene as it will be: every fresh id is fresh against what is
    // added before it too.
    Scene work = scene;
    std::map<std::string, std::string> materialId; // incoming id -> id in the scene
    for (const Material& m : incoming.materials) {
        if (const Material* same = work.findMaterial(m.id);
            same && same->reflectance == m.reflectance && same->emission == m.emission) {
            materialId[m.id] = m.id;
            continue;
        }
        Material added = m;
        added.id = work.uniqueId(m.id);
        materialId[m.id] = added.id;
        work.materials.push_back(added);
        out.materials.push_back(std::move(added));
    }
    const auto renamed = [&](const std::string& id) {
        const auto it = materialId.find(id);
        return it == materialId.end() ? id : it->second;
    };
    for (const Object& o : incoming.objects) {
        Object object = o;
        for (Part& part : object.parts) {
            part.material = renamed(part.material);
            for (Face& face : part.faces)
                if (!face.material.empty())
                    face.material = renamed(face.material);
        }
        object = withFreshIds(work, object);
        work.objects.push_back(object);
        out.objects.push_back(std::move(object));
    }
    return out;
}

} // namespace regio::model
