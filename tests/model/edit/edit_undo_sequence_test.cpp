// The contract the editor's undo stack relies on: every edit returns what its
// inverse needs. A long random sequence of edits (including refused ones),
// each recorded with its inverse, unwound in reverse gives back the scene it
// started from, exactly.
#include "model/edit/edit_materials.h"
#include "model/edit/edit_objects.h"
#include "model/edit/edit_parts.h"
#include "model/edit/edit_regions.h"
#include "model/edit/edit_settings.h"

#include "edit_fixture.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <functional>
#include <random>
#include <set>

using namespace regio::model;
using namespace regio::model::testing;

namespace {

class RandomEdits {
public:
    explicit RandomEdits(std::uint32_t seed)
        : m_random(seed)
    {
    }

    // Applies one random edit; returns its inverse, or nothing when refused.
    std::function<void(Scene&)> step(Scene& scene)
    {
        switch (pick(14)) {
        case 0: {
            std::string part = randomPart(scene);
            glm::dmat4 m = glm::translate(glm::dmat4(1.0), Vec3{real(-1, 1), real(-1, 1), real(-1, 1)});
            m = glm::rotate(m, real(-3, 3), Vec3{real(-1, 1), 1.0, real(-1, 1)});
            if (pick(4) == 0)
                m = glm::scale(m, Vec3{-1, 1, 1});
            return undoWith(transformPart(scene, part, m),
                            [](Scene& s, const PartGeometry& g) { return setPartGeometry(s, g); });
        }
        case 1: {
            std::string part = randomPart(scene);
            const Part* p = scene.findPart(part);
            Vec3 centre{0.0};
            for (const Vec3& v : p->vertices)
                centre += v / double(p->vertices.size());
            Plane plane = Plane::fromPointNormal(centre, {real(-1, 1), real(-1, 1), real(0.1, 1)});
            return undoWith(splitPartInScene(scene, part, plane, scene.uniqueId(part + "a"), scene.uniqueId(part + "b"),
                                             pick(2) ? CutCaps::Close : CutCaps::Open),
                            [](Scene& s, const PartSplit& r) { return unsplitPart(s, r); });
        }
        case 2:
            return undoWith(duplicateObject(scene, randomObject(scene)),
                            [](Scene& s, const std::string& id) { return removeObject(s, id); });
        case 3:
            if (scene.objects.size() < 3)
                return {};
            return undoWith(removeObject(scene, randomObject(scene)),
                            [](Scene& s, const RemovedObject& r) { return restoreObject(s, r); });
        case 4:
            return undoWith(groupParts(scene, {randomPart(scene), randomPart(scene)}, scene.uniqueId("group")),
                            [](Scene& s, const ObjectLayout& l) { return restoreObjectLayout(s, l); });
        case 5:
            return undoWith(ungroupObject(scene, randomObject(scene)),
                            [](Scene& s, const ObjectLayout& l) { return restoreObjectLayout(s, l); });
        case 6: {
            std::string part = randomPart(scene);
            const Object& target = scene.objects[size_t(pick(int(scene.objects.size())))];
            return undoWith(
                movePart(scene, part, target.id, pick(int(target.parts.size()) + 1) - 1),
                [part](Scene& s, const PartPlace& from) { return movePart(s, part, from.objectId, from.index); });
        }
        case 7: {
            std::string face = randomFace(scene);
            std::string newId = pick(8) == 0 ? "crate" : scene.uniqueId(face + "x");
            return undoWith(renameFace(scene, face, newId),
                            [face, newId](Scene& s, const Unit&) { return renameFace(s, newId, face); });
        }
        case 8: {
            std::string face = randomFace(scene);
            const char* materials[] = {"", "white", "red", "lamp", "gold"};
            return undoWith(setFaceMaterial(scene, face, materials[pick(5)]),
                            [face](Scene& s, const std::string& m) { return setFaceMaterial(s, face, m); });
        }
        case 9: {
            std::string region = scene.regions[size_t(pick(int(scene.regions.size())))].id;
            int size = int(scene.findRegion(region)->bspOrder.size());
            switch (pick(3)) {
            case 0:
                return undoWith(insertBspEntry(scene, region, randomFace(scene), pick(size + 1)),
                                [region](Scene& s, int index) { return removeBspEntry(s, region, index); });
            case 1:
                return undoWith(
                    removeBspEntry(scene, region, pick(size + 1) - 1),
                    [region](Scene& s, const BspEntry& e) { return insertBspEntry(s, region, e.faceId, e.index); });
            default: {
                int from = pick(size + 1) - 1, to = pick(size + 1) - 1;
                return undoWith(moveBspEntry(scene, region, from, to), [region, from, to](Scene& s, const Unit&) {
                    return moveBspEntry(s, region, to, from);
                });
            }
            }
        }
        case 10: {
            std::string region = scene.regions[size_t(pick(int(scene.regions.size())))].id;
            Vec3 min{real(-2, 2), real(-2, 2), real(-2, 2)};
            Vec3 max = min + Vec3{real(-0.5, 3), real(-0.5, 3), real(-0.5, 3)};
            return undoWith(setRegionBox(scene, region, min, max),
                            [region](Scene& s, const RegionBox& b) { return setRegionBox(s, region, b.min, b.max); });
        }
        case 11: {
            if (pick(2) == 0)
                return undoWith(addMaterial(scene, {scene.uniqueId("paint"), "", {real(0, 1), 0.5, 0.5}, {}},
                                            pick(int(scene.materials.size()) + 2) - 1),
                                [id = scene.uniqueId("paint")](Scene& s, int) { return removeMaterial(s, id); });
            const Material& m = scene.materials[size_t(pick(int(scene.materials.size())))];
            return undoWith(removeMaterial(scene, m.id),
                            [](Scene& s, const RemovedMaterial& r) { return addMaterial(s, r.material, r.index); });
        }
        case 12: {
            std::string id = scene.materials[size_t(pick(int(scene.materials.size())))].id;
            std::string newId = scene.uniqueId(id + "x");
            return undoWith(renameMaterial(scene, id, newId),
                            [id, newId](Scene& s, const Unit&) { return renameMaterial(s, newId, id); });
        }
        default: {
            if (pick(2) == 0) {
                std::string id = randomObject(scene);
                std::string newId = scene.uniqueId(id + "x");
                return undoWith(renameObject(scene, id, newId),
                                [id, newId](Scene& s, const Unit&) { return renameObject(s, newId, id); });
            }
            return undoWith(removePart(scene, randomPart(scene)),
                            [](Scene& s, const RemovedPart& r) { return restorePart(s, r); });
        }
        }
    }

    int applied = 0;
    int refused = 0;

private:
    template <typename T, typename Inverse>
    std::function<void(Scene&)> undoWith(Result<T> result, Inverse inverse)
    {
        if (!result.ok()) {
            ++refused;
            return {};
        }
        ++applied;
        return [value = std::move(result.value()), inverse](Scene& scene) {
            auto undone = inverse(scene, value);
            ASSERT_TRUE(undone.ok()) << undone.error().message;
        };
    }

    int pick(int n) { return int(m_random() % std::uint32_t(n)); }
    double real(double lo, double hi) { return lo + (hi - lo) * (double(m_random()) / 4294967296.0); }

    std::string randomObject(const Scene& scene) { return scene.objects[size_t(pick(int(scene.objects.size())))].id; }
    std::string randomPart(const Scene& scene)
    {
        std::vector<std::string> ids;
        for (const Object& object : scene.objects)
            for (const Part& part : object.parts)
                ids.push_back(part.id);
        return ids.empty() ? std::string("none") : ids[size_t(pick(int(ids.size())))];
    }
    std::string randomFace(const Scene& scene)
    {
        const Part* part = scene.findPart(randomPart(scene));
        return part && !part->faces.empty() ? part->faces[size_t(pick(int(part->faces.size())))].id
                                            : std::string("none");
    }

    std::mt19937 m_random;
};

// What every edit keeps true, whatever else it allows while editing
// (overlapping regions, faces outside their region's box: validation reports
// those live): ids unique and non-empty, material and BSP references known,
// loops naming existing vertices. Empty string when all hold.
std::string referenceProblem(const Scene& scene)
{
    std::set<std::string> ids;
    auto claim = [&](const std::string& id) { return !id.empty() && ids.insert(id).second; };
    for (const Material& m : scene.materials)
        if (!claim(m.id))
            return "material id " + m.id;
    for (const Region& r : scene.regions)
        if (!claim(r.id))
            return "region id " + r.id;
    auto knownMaterial = [&](const std::string& id) { return id.empty() || scene.findMaterial(id); };
    for (const Object& object : scene.objects) {
        if (!claim(object.id))
            return "object id " + object.id;
        for (const Part& part : object.parts) {
            if (!claim(part.id))
                return "part id " + part.id;
            if (!knownMaterial(part.material))
                return "material of " + part.id;
            for (const Face& face : part.faces) {
                if (!claim(face.id))
                    return "face id " + face.id;
                if (!knownMaterial(face.material))
                    return "material of " + face.id;
                for (int v : face.loop)
                    if (v < 0 || v >= int(part.vertices.size()))
                        return "loop of " + face.id;
            }
        }
    }
    for (const Region& r : scene.regions)
        for (const std::string& face : r.bspOrder)
            if (!scene.locateFace(face).valid())
                return "BSP order of " + r.id + " names " + face;
    return {};
}

} // namespace

TEST(EditUndoSequence, AThousandRandomEditsUndoneInReverseGiveBackTheOriginalScene)
{
    const Scene original = sampleScene();
    Scene scene = original;
    RandomEdits edits(7);
    std::vector<std::function<void(Scene&)>> undo;
    for (int i = 0; i < 1000; ++i) {
        Scene before = scene;
        auto inverse = edits.step(scene);
        if (!inverse) {
            ASSERT_TRUE(scene == before) << "a refused edit changed the scene at step " << i;
            continue;
        }
        undo.push_back(std::move(inverse));
        ASSERT_EQ(referenceProblem(scene), "") << "after step " << i;
    }
    EXPECT_GT(edits.applied, 500);
    EXPECT_GT(edits.refused, 20) << "refusals are part of the sequence";
    for (auto it = undo.rbegin(); it != undo.rend(); ++it)
        (*it)(scene);
    EXPECT_TRUE(scene == original);
}
