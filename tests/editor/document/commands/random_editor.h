#pragma once
// Random edits through every command family of the editor, for the tests
// that check undo and redo against them (random_edits_test.cpp, in a bare
// document; random_edits_window_gl_test.cpp, in the window with its panels
// and the live preview).
#include "editor/document/commands/bsp_order_commands.h"
#include "editor/document/commands/material_commands.h"
#include "editor/document/commands/object_commands.h"
#include "editor/document/commands/part_commands.h"
#include "editor/document/commands/region_commands.h"
#include "editor/document/commands/solver_settings_commands.h"
#include "model/edit/edit_objects.h"
#include "model/geometry/primitives.h"
#include "model/io/scene_json.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QString>

#include <array>
#include <functional>
#include <random>

namespace regio::test {

using namespace regio::editor;

class RandomEditor {
public:
    RandomEditor(SceneDocument& document, unsigned seed)
        : m_document(document)
        , m_random(seed)
    {
    }

    static constexpr int kKinds = 22;

    // Tries one random edit; true if the document accepted it.
    bool step()
    {
        const int kind = pick(kKinds);
        const bool accepted = attempt(kind);
        if (accepted)
            ++m_acceptedByKind[size_t(kind)];
        return accepted;
    }

    const std::array<int, kKinds>& acceptedByKind() const { return m_acceptedByKind; }

    // A burst of edits that merge: a colour dragged and solver settings
    // scrubbed, in turns (reflectance of one material, then the settings).
    bool mergingBurst()
    {
        const std::string material = anyMaterial();
        bool any = false;
        for (int i = 0, n = 2 + pick(5); i < n; ++i) {
            if (pick(2) == 0 && !material.empty()) {
                any = push(new SetMaterialReflectance(&m_document, material,
                                                      {real(0, 0.9), real(0, 0.9), real(0, 0.9)})) ||
                      any;
            } else {
                model::SolverSettings s = scene().solver;
                s.hemicube = 2 * (8 + pick(200));
                s.convergence = real(0.0001, 0.1);
                any = push(new SetSolverSettings(&m_document, s)) || any;
            }
        }
        return any;
    }

private:
    bool attempt(int kind)
    {
        switch (kind) {
        case 0: return push(new SetObjectName(&m_document, anyObject(), "name" + number()));
        case 1: return push(new RenameObject(&m_document, anyObject(), fresh("object")));
        case 2: return objects() < 25 && push(new DuplicateObject(&m_document, anyObject()));
        case 3: return objects() > 3 && push(new RemoveObject(&m_document, anyObject()));
        case 4: {
            const std::string id = fresh("box");
            const model::Vec3 at(real(-2, 2), 0.0, real(-2, 2));
            model::Object box{id, "", {*model::makeBox(id + ".body", at, at + model::Vec3(0.3), anyMaterial())}};
            return push(new AddObject(&m_document, model::withFreshIds(scene(), box)));
        }
        case 5: return push(ChangeObjectLayout::groupParts(&m_document, {anyPart(), anyPart()}, fresh("group")));
        case 6: return push(ChangeObjectLayout::ungroup(&m_document, anyObject()));
        case 7: return push(ChangeObjectLayout::moveParts(&m_document, {anyPart()}, pick(4) == 0 ? "" : anyObject()));
        case 8: return parts() < 60 && push(new DuplicatePart(&m_document, anyPart()));
        case 9: {
            const std::string part = anyPart();
            const model::Object* owner = scene().ownerOfPart(part);
            return owner && owner->parts.size() > 1 && push(new RemovePart(&m_document, part));
        }
        case 10: return push(new RenamePart(&m_document, anyPart(), fresh("part")));
        case 11: return push(new SetPartMaterial(&m_document, anyPart(), anyMaterial()));
        case 12: return push(new RenameFace(&m_document, anyFace(), fresh("face")));
        case 13: return push(new SetFaceMaterial(&m_document, anyFace(), pick(3) == 0 ? "" : anyMaterial()));
        case 14: {
            glm::dmat4 m = glm::translate(glm::dmat4(1.0), {real(-1, 1), real(-1, 1), real(-1, 1)});
            m = glm::rotate(m, real(-3, 3), glm::normalize(model::Vec3(real(-1, 1), 1.0, real(-1, 1))));
            m = glm::scale(m, {real(0.5, 2), real(0.5, 2), real(0.5, 2)});
            return push(new TransformParts(&m_document, {anyPart()}, m));
        }
        case 15: return dragSteps();
        case 16: {
            if (parts() >= 60)
                return false;
            const std::string part = anyPart();
            const model::Part* p = scene().findPart(part);
            model::Box3 box;
            for (const model::Vec3& v : p->vertices)
                box.extend(v);
            model::Vec3 normal(0.0);
            normal[pick(3)] = 1.0;
            return push(new SplitPart(&m_document, part, model::Plane::fromPointNormal(box.center(), normal), part,
                                      fresh(part)));
        }
        case 17: {
            switch (pick(5)) {
            case 0:
                return push(new AddMaterial(
                    &m_document, {fresh("material"), "", {real(0, 0.9), real(0, 0.9), real(0, 0.9)}, {0, 0, 0}}));
            case 1:
                return push(
                    new SetMaterialReflectance(&m_document, anyMaterial(), {real(0, 0.9), real(0, 0.9), real(0, 0.9)}));
            case 2:
                return push(new SetMaterialEmission(&m_document, anyMaterial(), {real(0, 5), real(0, 5), real(0, 5)}));
            case 3: return push(new RenameMaterial(&m_document, anyMaterial(), fresh("material")));
            default: return push(new RemoveMaterial(&m_document, anyMaterial())); // refused while in use
            }
        }
        case 18: {
            switch (pick(4)) {
            case 0: {
                const model::Vec3 lo(real(-20, 20), real(-20, 20), real(-20, 20));
                return push(new AddRegion(&m_document, {fresh("region"), "", lo, lo + model::Vec3(real(0.5, 3)), {}}));
            }
            case 1:
                return regions() > 0 &&
                       push(new SetRegionBox(&m_document, anyRegion(), {-5, -5, -5}, {real(-4, 5), 5, 5}));
            case 2: return regions() > 0 && push(new RenameRegion(&m_document, anyRegion(), fresh("region")));
            default: return regions() > 1 && push(new RemoveRegion(&m_document, anyRegion()));
            }
        }
        case 19: {
            if (regions() == 0)
                return false;
            const std::string region = anyRegion();
            const int size = int(scene().findRegion(region)->bspOrder.size());
            switch (pick(4)) {
            case 0: return push(new InsertBspEntry(&m_document, region, anyFace(), size > 0 ? pick(size + 1) : 0));
            case 1: return size > 0 && push(new RemoveBspEntry(&m_document, region, pick(size)));
            case 2: return size > 1 && push(new MoveBspEntry(&m_document, region, pick(size), pick(size)));
            default: {
                std::vector<std::string> order = scene().findRegion(region)->bspOrder;
                std::shuffle(order.begin(), order.end(), m_random);
                return push(new SetBspOrder(&m_document, region, order));
            }
            }
        }
        case 20: {
            model::SolverSettings s = scene().solver;
            s.hemicube = 2 * (8 + pick(200));
            s.patchSize = real(0.05, 1.0);
            s.adaptive.enabled = pick(2) == 0;
            return push(new SetSolverSettings(&m_document, s));
        }
        default: {
            model::Camera c;
            c.position = {real(-5, 5), real(0.5, 3), real(-5, 5)};
            c.target = {0.0, 1.0, 0.0};
            return push(new SetSceneCamera(&m_document, pick(4) == 0 ? std::nullopt : std::optional(c)));
        }
        }
    }

    const model::Scene& scene() const { return m_document.scene(); }
    bool push(SceneCommand* command) { return m_document.push(command); }
    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(m_random); }
    double real(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(m_random); }
    std::string number() { return std::to_string(pick(1000000)); }
    std::string fresh(const std::string& base) { return scene().uniqueId(base + "-" + number()); }

    int objects() const { return int(scene().objects.size()); }
    int regions() const { return int(scene().regions.size()); }
    int parts() const
    {
        int n = 0;
        for (const auto& o : scene().objects)
            n += int(o.parts.size());
        return n;
    }
    std::string anyObject() { return scene().objects[size_t(pick(objects()))].id; }
    std::string anyRegion() { return scene().regions[size_t(pick(regions()))].id; }
    std::string anyMaterial()
    {
        const auto& m = scene().materials;
        return m.empty() ? std::string() : m[size_t(pick(int(m.size())))].id;
    }
    std::string anyPart()
    {
        const auto& o = scene().objects[size_t(pick(objects()))];
        return o.parts.empty() ? std::string() : o.parts[size_t(pick(int(o.parts.size())))].id;
    }
    std::string anyFace()
    {
        const model::Part* part = scene().findPart(anyPart());
        return part && !part->faces.empty() ? part->faces[size_t(pick(int(part->faces.size())))].id : std::string();
    }

    // A gizmo drag: several steps with one serial, merging into one edit.
    bool dragSteps()
    {
        const model::Part* part = scene().findPart(anyPart());
        if (!part)
            return false;
        const std::vector<model::PartGeometry> start{model::geometryOf(*part)};
        const int serial = ++m_serial;
        bool any = false;
        for (int i = 0, n = 1 + pick(6); i < n; ++i)
            any = push(TransformParts::dragStep(&m_document, start,
                                                glm::translate(glm::dmat4(1.0), {real(-1, 1), 0.0, real(-1, 1)}),
                                                serial, QStringLiteral("drag"))) ||
                  any;
        return any;
    }

    SceneDocument& m_document;
    std::mt19937 m_random;
    int m_serial = 0;
    std::array<int, kKinds> m_acceptedByKind{};
};

// A short random sequence of edits, merging bursts, undos and redos on
// `document`, `settle` run after each step; then redone to the top, undone
// to the start and redone again. Returns what went wrong, or nothing.
inline QString runShortSequence(SceneDocument& document, unsigned seed, const std::function<void()>& settle)
{
    const std::string loadedBytes = model::serializeScene(document.scene());
    RandomEditor editor(document, seed);
    std::mt19937 order(seed * 7919u);
    for (int action = 0, n = 10 + static_cast<int>(order() % 30); action < n; ++action) {
        const auto roll = order() % 20;
        if (roll < 3) {
            const int index = document.undoStack()->index();
            document.undoStack()->undo();
            settle();
            if (index > 0 && document.undoStack()->index() != index - 1)
                return QStringLiteral("an undo left the stack at %1 instead of %2")
                    .arg(document.undoStack()->index())
                    .arg(index - 1);
        } else if (roll < 5) {
            document.undoStack()->redo();
        } else if (roll < 8) {
            editor.mergingBurst();
        } else {
            editor.step();
        }
        settle();
    }
    while (document.undoStack()->canRedo()) {
        document.undoStack()->redo();
        settle();
    }
    const std::string editedBytes = model::serializeScene(document.scene());
    const int top = document.undoStack()->index();
    while (document.undoStack()->canUndo()) {
        document.undoStack()->undo();
        settle();
    }
    if (model::serializeScene(document.scene()) != loadedBytes)
        return QStringLiteral("undoing everything did not give back the loaded bytes");
    if (document.isModified())
        return QStringLiteral("undone to the start, the document still counts as modified");
    while (document.undoStack()->canRedo()) {
        document.undoStack()->redo();
        settle();
    }
    if (document.undoStack()->index() != top)
        return QStringLiteral("redoing everything stopped at %1 of %2").arg(document.undoStack()->index()).arg(top);
    if (model::serializeScene(document.scene()) != editedBytes)
        return QStringLiteral("redoing everything did not give back the edited bytes");
    return {};
}

} // namespace regio::test
