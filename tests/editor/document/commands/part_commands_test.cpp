// Undo commands on parts and faces.
#include "editor/document/commands/part_commands.h"
#include "model/validation/validation.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <glm/gtc/matrix_transform.hpp>

using namespace regio;
using namespace regio::editor;

namespace {

model::Vec3 vertexOf(const model::Scene& scene, const std::string& partId, int index)
{
    return scene.findPart(partId)->vertices[size_t(index)];
}

} // namespace

class PartCommandsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void addingAPartPutsItIntoItsObject()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(
            new AddPart(&document, "crate", *model::makeBox("crate.lid", {2, 0.5, 0}, {2.5, 0.55, 0.5}, "red"))));
        QCOMPARE(document.scene().findObject("crate")->parts.size(), size_t(2));
        VERIFY_UNDO_REDO(document, before);
    }

    void removingAPartKeepsItsObjectAndUndoRestoresItInPlace()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(new RemovePart(&document, "table.desk")));
        QVERIFY(!document.scene().findPart("table.desk"));
        QCOMPARE(document.scene().regions.front().bspOrder, std::vector<std::string>{"table.legs.py"});
        VERIFY_UNDO_REDO(document, before);
    }

    void duplicatingAPartAddsACopyWithFreshIds()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        auto* command = new DuplicatePart(&document, "crate.body");
        QVERIFY(document.push(command));
        QCOMPARE(command->copyId(), std::string("crate.body-2"));
        QCOMPARE(document.scene().findObject("crate")->parts.size(), size_t(2));
        VERIFY_UNDO_REDO(document, before);
    }

    void renamingAPartKeepsItsFaces()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(new RenamePart(&document, "table.legs", "table.frame")));
        QVERIFY(document.scene().findPart("table.frame"));
        QVERIFY(document.scene().locateFace("table.legs.py").valid());
        VERIFY_UNDO_REDO(document, before);
    }

    void settingAPartsNameAndMaterialCanBeUndone()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(new SetPartName(&document, "crate.body", "Body")));
        QCOMPARE(document.scene().findPart("crate.body")->name, std::string("Body"));
        VERIFY_UNDO_REDO(document, before);
        const model::Scene named = document.scene();
        QVERIFY(document.push(new SetPartMaterial(&document, "crate.body", "white")));
        QCOMPARE(document.scene().findPart("crate.body")->material, std::string("white"));
        VERIFY_UNDO_REDO(document, named);
        document.undoStack()->undo();
        document.undoStack()->undo();
        QVERIFY(document.scene() == before);
    }

    void assigningAnUnknownMaterialIsRefused()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QVERIFY(!document.push(new SetPartMaterial(&document, "crate.body", "gold")));
        QVERIFY(!document.push(new SetFaceMaterial(&document, "crate.body.px", "gold")));
        QVERIFY(document.scene() == test::smallScene());
    }

    void movingAPartToAnotherObjectCanBeUndone()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(new MovePart(&document, "table.legs", "crate", 0)));
        QCOMPARE(document.scene().findObject("crate")->parts.front().id, std::string("table.legs"));
        VERIFY_UNDO_REDO(document, before);
    }

    void renamingAFaceRenamesItsBspOrderEntries()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(new RenameFace(&document, "table.desk.py", "table.desk.top")));
        QCOMPARE(document.scene().regions.front().bspOrder.front(), std::string("table.desk.top"));
        VERIFY_UNDO_REDO(document, before);
    }

    void aFaceCanHaveItsOwnMaterialAndGoBackToThePartsOne()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(new SetFaceMaterial(&document, "crate.body.py", "white")));
        const auto at = document.scene().locateFace("crate.body.py");
        QCOMPARE(document.scene().objects[size_t(at.object)].parts[size_t(at.part)].faces[size_t(at.face)].material,
                 std::string("white"));
        VERIFY_UNDO_REDO(document, before);
        QVERIFY(document.push(new SetFaceMaterial(&document, "crate.body.py", "")));
        QVERIFY(document.scene() == before);
    }

    void transformingPartsMovesTheirVerticesAndUndoRestoresTheExactNumbers()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        const glm::dmat4 m = glm::rotate(glm::translate(glm::dmat4(1.0), {0.1, 0.2, 0.3}), 0.7, {0.0, 1.0, 0.0});
        QVERIFY(document.push(new TransformParts(&document, {"table.desk", "table.legs"}, m)));
        QVERIFY(vertexOf(document.scene(), "table.desk", 0) != vertexOf(before, "table.desk", 0));
        VERIFY_UNDO_REDO(document, before);
    }

    void aSingularTransformIsRefused()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const glm::dmat4 flatten = glm::scale(glm::dmat4(1.0), {1.0, 0.0, 1.0});
        QVERIFY(!document.push(new TransformParts(&document, {"crate.body"}, flatten)));
        QVERIFY(document.scene() == test::smallScene());
    }

    void theStepsOfOneDragMergeIntoOneUndoStepWithoutDrift()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        const std::vector<model::PartGeometry> start{model::geometryOf(*before.findPart("crate.body"))};
        for (int step = 1; step <= 50; ++step) {
            const glm::dmat4 m = glm::translate(glm::dmat4(1.0), {0.01 * step, 0.0, 0.0});
            QVERIFY(document.push(TransformParts::dragStep(&document, start, m, 7, QStringLiteral("Move"))));
        }
        QCOMPARE(document.undoStack()->count(), 1);
        // The whole drag is one transform of the starting geometry.
        const model::Vec3 expected = vertexOf(before, "crate.body", 0) + model::Vec3(0.5, 0.0, 0.0);
        QCOMPARE(vertexOf(document.scene(), "crate.body", 0).x, expected.x);
        VERIFY_UNDO_REDO(document, before);
    }

    void twoDragsAreTwoUndoSteps()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const std::vector<model::PartGeometry> start{model::geometryOf(*document.scene().findPart("crate.body"))};
        const glm::dmat4 m = glm::translate(glm::dmat4(1.0), {1.0, 0.0, 0.0});
        document.push(TransformParts::dragStep(&document, start, m, 1, QStringLiteral("Move")));
        const std::vector<model::PartGeometry> second{model::geometryOf(*document.scene().findPart("crate.body"))};
        document.push(TransformParts::dragStep(&document, second, m, 2, QStringLiteral("Move")));
        QCOMPARE(document.undoStack()->count(), 2);
    }

    void aDragBackToTheStartLeavesNothingToUndo()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const std::vector<model::PartGeometry> start{model::geometryOf(*document.scene().findPart("crate.body"))};
        document.push(TransformParts::dragStep(&document, start, glm::translate(glm::dmat4(1.0), {1.0, 0, 0}), 3, {}));
        document.push(TransformParts::dragStep(&document, start, glm::dmat4(1.0), 3, {}));
        QCOMPARE(document.undoStack()->count(), 0);
        QVERIFY(document.scene() == test::smallScene());
    }

    void splittingAPartMakesTwoValidClosedPartsInItsObject()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        const model::Plane plane = model::Plane::fromPointNormal({2.25, 0.25, 0.25}, {1.0, 0.0, 0.0});
        QVERIFY(document.push(new SplitPart(&document, "crate.body", plane, "crate.body", "crate.back")));
        const model::Object* crate = document.scene().findObject("crate");
        QCOMPARE(crate->parts.size(), size_t(2));
        QCOMPARE(crate->parts[1].id, std::string("crate.back"));
        QVERIFY(!model::hasErrors(model::validateScene(document.scene())));
        VERIFY_UNDO_REDO(document, before);
    }

    void splittingWithAPlaneThatMissesThePartIsRefused()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Plane plane = model::Plane::fromPointNormal({10, 0, 0}, {1.0, 0.0, 0.0});
        QVERIFY(!document.push(new SplitPart(&document, "crate.body", plane, "crate.body", "crate.back")));
        QVERIFY(document.scene() == test::smallScene());
    }
};

REGIO_QTEST_MAIN(PartCommandsTest)
#include "part_commands_test.moc"
