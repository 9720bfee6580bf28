// A long random sequence of edits through every command family, undone to
// the start, must give back exactly the scene that was loaded; redone to the
// end, exactly the scene the edits made.
#include "editor/document/commands/bsp_order_commands.h"
#include "editor/document/commands/material_commands.h"
#include "editor/document/commands/object_commands.h"
#include "editor/document/commands/part_commands.h"
#include "editor/document/commands/region_commands.h"
#include "editor/document/commands/solver_settings_commands.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <random>

using namespace regio;
using namespace regio::editor;

namespace {

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

} // namespace

class RandomEditsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void thousandRandomEditsUndoneGiveBackTheLoadedSceneAndRedoneTheEditedOne_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<unsigned>("seed");
        QTest::newRow("two-lights room, seed 1") << QStringLiteral("two-lights-room") << 1u;
        QTest::newRow("two-lights room, seed 2024") << QStringLiteral("two-lights-room") << 2024u;
        QTest::newRow("Cornell box, seed 7") << QStringLiteral("cornell-box") << 7u;
    }

    void thousandRandomEditsUndoneGiveBackTheLoadedSceneAndRedoneTheEditedOne()
    {
        QFETCH(QString, scene);
        QFETCH(unsigned, seed);
        SceneDocument document;
        model::Diagnostics diagnostics;
        QVERIFY(document.open(test::sampleFile(scene.toStdString()), diagnostics));
        const model::Scene loaded = document.scene();

        RandomEditor editor(document, seed);
        int accepted = 0, attempts = 0;
        while (accepted < 1000 && attempts < 20000) {
            ++attempts;
            if (editor.step())
                ++accepted;
        }
        QCOMPARE(accepted, 1000);
        // Every kind of edit took part.
        for (int kind = 0; kind < RandomEditor::kKinds; ++kind)
            QVERIFY2(editor.acceptedByKind()[size_t(kind)] > 0,
                     qPrintable(QStringLiteral("edit kind %1 never ran").arg(kind)));
        QVERIFY(!(document.scene() == loaded));
        const model::Scene edited = document.scene();

        while (document.undoStack()->canUndo())
            document.undoStack()->undo();
        QVERIFY2(document.scene() == loaded, "undoing everything did not give back the loaded scene");
        QVERIFY(!document.isModified());

        while (document.undoStack()->canRedo())
            document.undoStack()->redo();
        QVERIFY2(document.scene() == edited, "redoing everything did not give back the edited scene");
    }
};

REGIO_QTEST_MAIN(RandomEditsTest)
#include "random_edits_test.moc"
