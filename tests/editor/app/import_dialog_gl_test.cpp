// File ▸ Import…: the dialog imports in the background with its options,
// previews the result (report, warnings, the scene drawn), and the window
// adds it as a new scene or into the open one as one undo step.
#include "editor/app/import_dialog.h"
#include "editor/app/main_window.h"
#include "editor/document/scene_document.h"
#include "editor/viewport/viewport.h"
#include "model/validation/validation.h"
#include "support/editor_documents.h"
#include "support/editor_windows.h"
#include "support/qt_test_registry.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace regio;
using namespace regio::editor;

namespace {

// A 4 x 3 x 2.5 m room of triangles, inward, with a light in the ceiling.
const char* kRoomObj = R"(mtllib room.mtl
o room
v 0 0 0
v 4 0 0
v 4 0 3
v 0 0 3
v 0 2.5 0
v 4 2.5 0
v 4 2.5 3
v 0 2.5 3
usemtl white
f 1 4 3
f 1 3 2
f 5 6 7
f 5 7 8
f 1 2 6
f 1 6 5
f 4 8 7
f 4 7 3
f 1 5 8
f 1 8 4
f 2 3 7
f 2 7 6
o lamp
v 1.5 2.49 1
v 2.5 2.49 1
v 2.5 2.49 2
v 1.5 2.49 2
usemtl light
f 9 10 11
f 9 11 12
)";
const char* kRoomMtl = "newmtl white\nKd 0.7 0.7 0.7\nnewmtl light\nKd 0 0 0\nKe 10 10 10\n";

QString writeModel(const QTemporaryDir& dir)
{
    QFile mtl(dir.filePath(QStringLiteral("room.mtl")));
    mtl.open(QIODevice::WriteOnly);
    mtl.write(kRoomMtl);
    QFile obj(dir.filePath(QStringLiteral("room.obj")));
    obj.open(QIODevice::WriteOnly);
    obj.write(kRoomObj);
    return obj.fileName();
}

bool waitForImport(ImportDialog& dialog)
{
    return QTest::qWaitFor([&] { return !dialog.busy() && dialog.imported().has_value(); }, 60000);
}

// The room as the dialog imports it, for the window to add.
std::optional<importer::Imported> importedRoom(const QString& path)
{
    ImportDialog dialog(path, true);
    if (!waitForImport(dialog))
        return std::nullopt;
    return dialog.imported();
}

QPushButton* okButton(ImportDialog& dialog)
{
    return dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
}

} // namespace

class ImportDialogGlTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void aModelIsImportedAndPreviewedBeforeItIsAccepted()
    {
        QTemporaryDir dir;
        ImportDialog dialog(writeModel(dir), true);
        dialog.resize(900, 600);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QVERIFY(waitForImport(dialog));
        QVERIFY(okButton(dialog)->isEnabled());
        QVERIFY2(dialog.summary().contains(QStringLiteral("14 triangles into 7 faces")), qPrintable(dialog.summary()));
        const model::Scene& scene = dialog.imported()->scene;
        QCOMPARE(scene.objects.size(), size_t(2));
        QVERIFY(!model::hasErrors(model::validateScene(scene)));
        auto* preview = dialog.findChild<Viewport*>();
        QVERIFY(preview);
        QVERIFY(QTest::qWaitFor([&] { return preview->hasRenderedFrame(); }, 20000));
    }

    void changingAnOptionImportsAgain()
    {
        QTemporaryDir dir;
        ImportDialog dialog(writeModel(dir), false);
        QVERIFY(waitForImport(dialog));
        QVERIFY(dialog.target() == ImportDialog::Target::NewScene);
        for (QRadioButton* radio : dialog.findChildren<QRadioButton*>())
            if (radio->text().contains(QStringLiteral("open scene")))
                QVERIFY2(!radio->isEnabled(), "no open scene to import into");
        QSignalSpy finished(&dialog, &ImportDialog::importFinished);
        auto* scale = dialog.findChildren<QDoubleSpinBox*>().front();
        scale->setValue(0.5);
        QVERIFY(finished.wait(60000));
        QCOMPARE(dialog.options().read.scale, 0.5);
        double top = 0.0;
        for (const model::Part& part : dialog.imported()->scene.objects.front().parts)
            for (const model::Vec3& v : part.vertices)
                top = std::max(top, v.y);
        QVERIFY(std::abs(top - 1.25) < 1e-6);
    }

    void aFileThatCannotBeImportedSaysWhyAndCannotBeAccepted()
    {
        QTemporaryDir dir;
        QFile bad(dir.filePath(QStringLiteral("lines.obj")));
        bad.open(QIODevice::WriteOnly);
        bad.write("v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2\nl 2 3\n");
        bad.close();
        ImportDialog dialog(bad.fileName(), true);
        QSignalSpy finished(&dialog, &ImportDialog::importFinished);
        QVERIFY(finished.wait(60000));
        QVERIFY(!dialog.imported());
        QVERIFY(!okButton(dialog)->isEnabled());
        QVERIFY(dialog.summary().contains(QStringLiteral("cannot be imported")));
    }

    void intoTheOpenSceneItIsOneUndoStep()
    {
        QTemporaryDir dir;
        const QString path = writeModel(dir);
        const std::optional<importer::Imported> imported = importedRoom(path);
        QVERIFY(imported);
        auto window = test::quietWindow();
        const model::Scene before = test::smallScene();
        window->document()->reset(before);
        QUndoStack* stack = window->document()->undoStack();
        QVERIFY(window->addImported(*imported, true, path));
        QCOMPARE(stack->count(), 1);
        const model::Scene& after = window->document()->scene();
        QCOMPARE(after.objects.size(), before.objects.size() + 2);
        QVERIFY(!model::hasErrors(model::validateScene(after)));
        stack->undo();
        QVERIFY(window->document()->scene() == before);
        stack->redo();
        QCOMPARE(window->document()->scene().objects.size(), before.objects.size() + 2);
    }

    void asANewSceneItReplacesTheDocumentUnsaved()
    {
        QTemporaryDir dir;
        const QString path = writeModel(dir);
        const std::optional<importer::Imported> imported = importedRoom(path);
        QVERIFY(imported);
        auto window = test::quietWindow();
        window->document()->reset(test::smallScene());
        QVERIFY(window->addImported(*imported, false, path));
        QVERIFY(window->document()->scene() == imported->scene);
        QVERIFY(window->document()->filePath().isEmpty());
        QVERIFY(window->document()->isModified());
    }
};

REGIO_QTEST_MAIN(ImportDialogGlTest)
#include "import_dialog_gl_test.moc"
