#include "model/validation.h"

#include <string>
#include <unordered_map>

namespace regio::model {

namespace {

std::string facePointer(size_t o, size_t p, size_t f)
{
    return "/objects/" + std::to_string(o) + "/parts/" + std::to_string(p) + "/faces/" +
           std::to_string(f);
}

} // namespace

Diagnostics validateScene(const Scene& scene)
{
    Diagnostics out;
    std::unordered_map<std::string, std::string> ids; // id -> pointer of first use
    auto claim = [&](const std::string& id, const std::string& pointer,
                     std::vector<std::string> idPath) {
        if (id.empty()) {
            out.push_back(makeError("empty id", pointer + "/id", std::move(idPath)));
            return;
        }
        auto [it, fresh] = ids.emplace(id, pointer);
        if (!fresh)
            out.push_back(makeError("duplicate id \"" + id + "\" (first used at " + it->second + ")",
                                    pointer + "/id", std::move(idPath)));
    };
    for (size_t m = 0; m < scene.materials.size(); ++m)
        claim(scene.materials[m].id, "/materials/" + std::to_string(m), {scene.materials[m].id});
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& object = scene.objects[o];
        claim(object.id, "/objects/" + std::to_string(o), {object.id});
        for (size_t p = 0; p < object.parts.size(); ++p) {
            const Part& part = object.parts[p];
            std::string pp = "/objects/" + std::to_string(o) + "/parts/" + std::to_string(p);
            claim(part.id, pp, {object.id, part.id});
            if (!part.material.empty() && !scene.findMaterial(part.material))
                out.push_back(makeError("unknown material \"" + part.material + "\"",
                                        pp + "/material", {object.id, part.id}));
            for (size_t f = 0; f < part.faces.size(); ++f) {
                const Face& face = part.faces[f];
                claim(face.id, facePointer(o, p, f), {object.id, part.id, face.id});
                if (!face.material.empty() && !scene.findMaterial(face.material))
                    out.push_back(makeError("unknown material \"" + face.material + "\"",
                                            facePointer(o, p, f) + "/material",
                                            {object.id, part.id, face.id}));
            }
        }
    }
    for (size_t r = 0; r < scene.regions.size(); ++r)
        claim(scene.regions[r].id, "/regions/" + std::to_string(r), {scene.regions[r].id});
    return out;
}

} // namespace regio::model
