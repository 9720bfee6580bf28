#pragma once
// Checks and lookups shared by the model edit functions (edit_*.h). Every
// edit validates everything first and only then changes the scene, so a
// refused edit leaves the scene exactly as it was; these helpers are the
// "validate" half. Diagnostics carry the JSON pointer of the element concerned,
// the same one validation and the file format use.
#include "model/diagnostic.h"
#include "model/io/json_pointer.h"
#include "model/result.h"
#include "model/scene.h"

#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

namespace regio::model::edit {

struct PartLocation {
    int object = -1;
    int part = -1;
    bool valid() const { return part >= 0; }
};
PartLocation locatePart(const Scene& scene, const std::string& partId);
int objectIndex(const Scene& scene, const std::string& objectId);

Diagnostic unknown(const std::string& what, const std::string& id);

// A new id must be non-empty and unused by any object, part, face, material or
// region of the scene, and not in `alsoTaken` (ids claimed by the same edit).
// Ids in `released` count as free: they belong to what the edit removes.
Check checkNewId(const Scene& scene, const std::string& id, const std::string& what,
                 const std::unordered_set<std::string>& alsoTaken = {},
                 const std::unordered_set<std::string>& released = {});

// A material reference is empty (inherit / none) or names an existing material.
Check checkMaterialReference(const Scene& scene, const std::string& material, const std::string& pointer);

// Structural checks of a part about to enter the scene: ids (part and faces)
// fresh and distinct, loops of at least 3 in-range vertices, finite vertices,
// known materials. Ids claimed are added to `taken`. Geometric quality
// (planarity, convexity) is left to validation, which reports it live.
Check checkNewPart(const Scene& scene, const Part& part, const std::string& pointer,
                   std::unordered_set<std::string>& taken, const std::unordered_set<std::string>& released = {});

// The same without the id check: the geometry (vertices, loops, face
// materials) of a part.
Check checkPartGeometry(const Scene& scene, const std::vector<Vec3>& vertices, const std::vector<Face>& faces,
                        const std::string& pointer);

bool isFinite(const Vec3& v);

// Hands out fresh, human-readable ids for copies: the scene's uniqueId rule
// ("base", "base-2", ...) also avoiding the ids handed out so far.
class IdAllocator {
public:
    explicit IdAllocator(const Scene& scene)
        : m_scene(scene)
    {
    }
    std::string fresh(const std::string& base);
    // Keeps `prefix` + rest, replacing an old prefix: "box1.body" with
    // oldPrefix "box1" and newPrefix "box1-2" gives "box1-2.body" (then made
    // fresh). Ids without the old prefix are only made fresh.
    std::string freshRenamed(const std::string& id, const std::string& oldPrefix, const std::string& newPrefix);
    const std::unordered_set<std::string>& taken() const { return m_taken; }

private:
    const Scene& m_scene;
    std::unordered_set<std::string> m_taken;
};

// "a.b" -> newPrefix + ".b" when id starts with oldPrefix + "."; else id.
std::string replacePrefix(const std::string& id, const std::string& oldPrefix, const std::string& newPrefix);

} // namespace regio::model::edit
