// The viewport on a real OpenGL 3.3 context (Xvfb + Mesa): the screenshot
// command, where a known red face lands, picking by mouse, and buffers that
// follow the document's change signals.
#include "editor/app/main_window.h"
#include "editor/document/commands/material_commands.h"
#include "editor/document/scene_document.h"
#include "editor/viewport/scene_mesh.h"
#include "editor/viewport/viewport.h"
#include "support/editor_documents.h"
#include "support/editor_windows.h"
#include "support/qt_test_registry.h"

#include <QApplication>
#include <QImage>
#include <QProcess>
#include <QSet>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QWheelEvent>

#include <memory>

using namespace regio;
using namespace regio::editor;

namespace {

bool reddish(QRgb c) { return qRed(c) > 90 && qRed(c) > 2 * qGreen(c) && qRed(c) > 2 * qBlue(c); }
bool greenish(QRgb c) { return qGreen(c) > 60 && qGreen(c) > 1.5 * qRed(c) && qGreen(c) > 1.5 * qBlue(c); }
bool bluish(QRgb c) { return qBlue(c) > 90 && qBlue(c) > 2 * qRed(c) && qBlue(c) > 1.5 * qGreen(c); }

test::EditorRun runEditor(const QStringList& arguments) { return test::runEditor(arguments, 120000); }

std::unique_ptr<MainWindow> showWindow(const QString& scene)
{
    auto window = test::quietWindow();
    window->resize(1200, 800);
    if (!scene.isEmpty() && !window->openFile(scene))
        qFatal("cannot open %s", qPrintable(scene));
    test::showAndWaitForFrame(*window);
    return window;
}

// The framebuffer pixel where a face's centroid is drawn.
QPoint pixelOfFace(const Viewport* viewport, const model::Scene& scene, const std::string& faceId)
{
    const model::Box3 box = boundsOfFaces(scene, {faceId});
    const auto pixel = viewport->screenView().toPixels(box.center());
    if (!pixel)
        return {-1, -1};
    return {int(pixel->x), int(pixel->y)};
}

} // namespace

class ViewportGlTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void theScreenshotOfTheCornellBoxIsNotBlankAndHasItsRedWallOnTheLeft()
    {
        QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("cornell.png"));
        const test::EditorRun run = runEditor({test::sampleFile("cornell-box"), QStringLiteral("--screenshot"), png,
                                               QStringLiteral("--size"), QStringLiteral("1200x800")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.stderrText));
        QImage image(png);
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), QSize(1200, 800));

        QSet<QRgb> colours;
        qint64 redX = 0, redCount = 0, greenX = 0, greenCount = 0;
        for (int y = 0; y < image.height(); y += 2)
            for (int x = 0; x < image.width(); x += 2) {
                const QRgb c = image.pixel(x, y);
                colours.insert(c & 0xf0f0f0);
                if (reddish(c)) {
                    redX += x;
                    ++redCount;
                }
                if (greenish(c)) {
                    greenX += x;
                    ++greenCount;
                }
            }
        QVERIFY2(colours.size() > 50, "the screenshot is blank");
        // The walls fill a good part of the view: thousands of sampled pixels.
        QVERIFY(redCount > 2000);
        QVERIFY(greenCount > 2000);
        QVERIFY2(redX / redCount < greenX / greenCount, "the red wall is not left of the green one");
    }

    void aSceneThatCannotBeOpenedFailsTheScreenshotWithExitCode2()
    {
        QTemporaryDir dir;
        const test::EditorRun run =
            runEditor({dir.filePath(QStringLiteral("missing.json")), QStringLiteral("--screenshot"),
                       dir.filePath(QStringLiteral("out.png"))});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.stderrText.contains(QStringLiteral("missing.json")));
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("out.png"))));
    }

    void anUnwritableScreenshotPathFailsWithExitCode2()
    {
        const test::EditorRun run = runEditor({test::sampleFile("cornell-box"), QStringLiteral("--screenshot"),
                                               QStringLiteral("/proc/regio-cannot-write-here/out.png")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(!run.stderrText.isEmpty());
    }

    void theViewportRunsOnAnOpenGL33CoreContext()
    {
        auto window = showWindow(test::sampleFile("cornell-box"));
        const QSurfaceFormat format = window->viewport()->format();
        QVERIFY(format.majorVersion() > 3 || (format.majorVersion() == 3 && format.minorVersion() >= 3));
        QCOMPARE(format.profile(), QSurfaceFormat::CoreProfile);
        QVERIFY(window->viewport()->renderingError().isEmpty());
    }

    void theRedWallIsDrawnWhereItsGeometryProjects()
    {
        auto window = showWindow(test::sampleFile("cornell-box"));
        Viewport* viewport = window->viewport();
        const QImage frame = viewport->grabFramebuffer();
        const model::Scene& scene = window->document()->scene();
        const QPoint red = pixelOfFace(viewport, scene, "left-wall.lower");
        const QPoint green = pixelOfFace(viewport, scene, "right-wall.inside");
        QVERIFY(frame.rect().contains(red) && frame.rect().contains(green));
        QVERIFY(red.x() < frame.width() / 2);
        QVERIFY2(reddish(frame.pixel(red)), qPrintable(QColor(frame.pixel(red)).name()));
        QVERIFY2(greenish(frame.pixel(green)), qPrintable(QColor(frame.pixel(green)).name()));
    }

    void aMaterialEditRecoloursTheFacesThatUseIt()
    {
        auto window = showWindow(test::sampleFile("cornell-box"));
        Viewport* viewport = window->viewport();
        SceneDocument* document = window->document();
        const QPoint red = pixelOfFace(viewport, document->scene(), "left-wall.lower");
        QVERIFY(document->push(new SetMaterialReflectance(document, "red", {0.05, 0.1, 0.7})));
        const QImage frame = viewport->grabFramebuffer();
        QVERIFY2(bluish(frame.pixel(red)), qPrintable(QColor(frame.pixel(red)).name()));
        document->undoStack()->undo();
        QVERIFY(reddish(viewport->grabFramebuffer().pixel(red)));
    }

    void clickingAFaceSelectsItsObjectPartOrFace()
    {
        auto window = showWindow(test::sampleFile("cornell-box"));
        Viewport* viewport = window->viewport();
        SceneDocument* document = window->document();
        const QPoint top = pixelOfFace(viewport, document->scene(), "short-block.top");
        QTest::mouseClick(viewport, Qt::LeftButton, {}, top);
        QCOMPARE(document->selection(), Selection::single(SelectionKind::Object, "short"));
        viewport->setPickMode(PickMode::Face);
        QTest::mouseClick(viewport, Qt::LeftButton, {}, top);
        QCOMPARE(document->selection(), Selection::single(SelectionKind::Face, "short-block.top"));
        // Clicking empty space clears the selection.
        QTest::mouseClick(viewport, Qt::LeftButton, {}, QPoint(3, 3));
        QVERIFY(document->selection().empty());
    }

    void aLayerThatReplacesSurfacesIsDrawnInsteadOfTheSceneAndGoesAwayWhenRemoved()
    {
        auto window = showWindow(test::sampleFile("cornell-box"));
        Viewport* viewport = window->viewport();
        const model::Scene& scene = window->document()->scene();
        const QPoint red = pixelOfFace(viewport, scene, "left-wall.lower");
        QVERIFY(reddish(viewport->grabFramebuffer().pixel(red)));

        // The red wall's own polygon, painted blue with per-vertex colours.
        const auto location = scene.locateFace("left-wall.lower");
        const model::Part& part = scene.objects[size_t(location.object)].parts[size_t(location.part)];
        const model::Face& face = part.faces[size_t(location.face)];
        ViewportLayer layer;
        for (size_t i = 1; i + 1 < face.loop.size(); ++i)
            layer.triangles.addTriangle(part.vertices[size_t(face.loop[0])], part.vertices[size_t(face.loop[i])],
                                        part.vertices[size_t(face.loop[i + 1])], {0.1f, 0.2f, 0.9f, 1.0f});
        layer.replacesSurfaces = true;
        viewport->setLayer(QStringLiteral("test"), layer);
        QVERIFY(viewport->hasLayer(QStringLiteral("test")));
        QImage frame = viewport->grabFramebuffer();
        QVERIFY2(bluish(frame.pixel(red)), qPrintable(QColor(frame.pixel(red)).name()));
        // The green wall is not in the layer and the scene's surfaces are replaced.
        const QPoint green = pixelOfFace(viewport, scene, "right-wall.inside");
        QVERIFY2(!greenish(frame.pixel(green)), qPrintable(QColor(frame.pixel(green)).name()));

        viewport->removeLayer(QStringLiteral("test"));
        QVERIFY(!viewport->hasLayer(QStringLiteral("test")));
        QVERIFY(reddish(viewport->grabFramebuffer().pixel(red)));
    }

    void aToolGetsClicksFirstAndEscapeDropsIt()
    {
        struct CountingTool : ViewportTool {
            int presses = 0, releases = 0;
            bool deactivatedCalled = false;
            bool mousePress(Viewport&, QMouseEvent* e) override { return e->button() == Qt::LeftButton && ++presses; }
            bool mouseRelease(Viewport&, QMouseEvent* e) override
            {
                return e->button() == Qt::LeftButton && ++releases;
            }
            void deactivated() override { deactivatedCalled = true; }
        } tool;
        auto window = showWindow(test::sampleFile("cornell-box"));
        Viewport* viewport = window->viewport();
        SceneDocument* document = window->document();
        const QPoint top = pixelOfFace(viewport, document->scene(), "short-block.top");
        viewport->setTool(&tool);
        QTest::mouseClick(viewport, Qt::LeftButton, {}, top);
        QCOMPARE(tool.presses, 1);
        QCOMPARE(tool.releases, 1);
        QVERIFY(document->selection().empty()); // the tool used the click
        QTest::keyClick(viewport, Qt::Key_Escape);
        QVERIFY(tool.deactivatedCalled);
        QCOMPARE(viewport->tool(), nullptr);
        QTest::mouseClick(viewport, Qt::LeftButton, {}, top);
        QCOMPARE(document->selection(), Selection::single(SelectionKind::Object, "short"));
    }

    void theSelectionIsHighlighted()
    {
        auto window = showWindow(test::sampleFile("cornell-box"));
        Viewport* viewport = window->viewport();
        SceneDocument* document = window->document();
        const QPoint wall = pixelOfFace(viewport, document->scene(), "right-wall.inside");
        const QRgb before = viewport->grabFramebuffer().pixel(wall);
        document->setSelection(Selection::single(SelectionKind::Face, "right-wall.inside"));
        const QRgb after = viewport->grabFramebuffer().pixel(wall);
        // The orange highlight warms the green wall.
        QVERIFY2(qRed(after) > qRed(before) + 40, qPrintable(QColor(before).name() + QColor(after).name()));
        document->clearSelection();
        QCOMPARE(viewport->grabFramebuffer().pixel(wall), before);
    }

    void wireframeAndNormalViewsDrawSomethingDifferent()
    {
        auto window = showWindow(test::sampleFile("two-lights-room"));
        Viewport* viewport = window->viewport();
        const QImage solid = viewport->grabFramebuffer();
        viewport->setShading(ShadingMode::Wireframe);
        const QImage wire = viewport->grabFramebuffer();
        viewport->setShading(ShadingMode::Normals);
        const QImage normals = viewport->grabFramebuffer();
        QVERIFY(solid != wire);
        QVERIFY(solid != normals);
        QVERIFY(wire != normals);
    }

    void draggingTheMoveGizmoMovesTheSelectionInOneUndoStep()
    {
        auto window = showWindow(test::sampleFile("cornell-box"));
        Viewport* viewport = window->viewport();
        SceneDocument* document = window->document();
        const model::Scene before = document->scene();
        document->setSelection(Selection::single(SelectionKind::Object, "short"));
        viewport->setGizmoMode(GizmoMode::Move);
        viewport->setSnapEnabled(false);
        // The gizmo sits at the selection's centre; grab its y handle a bit
        // above the centre and drag upwards.
        const model::Box3 box =
            boundsOfFaces(document->scene(), selectedFaceIds(document->scene(), document->selection()));
        const auto centre = viewport->screenView().toPixels(box.center());
        QVERIFY(centre);
        const QPoint grab(int(centre->x), int(centre->y) - 40);
        QTest::mousePress(viewport, Qt::LeftButton, {}, grab);
        for (int dy = 5; dy <= 60; dy += 5)
            QTest::mouseMove(viewport, grab - QPoint(0, dy));
        QTest::mouseRelease(viewport, Qt::LeftButton, {}, grab - QPoint(0, 60));
        QCOMPARE(document->undoStack()->count(), 1);
        const double lift =
            document->scene().findPart("short-block")->vertices[0].y - before.findPart("short-block")->vertices[0].y;
        QVERIFY2(lift > 0.01, qPrintable(QString::number(lift)));
        // Only upwards: x and z stay.
        QCOMPARE(document->scene().findPart("short-block")->vertices[0].x,
                 before.findPart("short-block")->vertices[0].x);
        document->undoStack()->undo();
        QVERIFY(document->scene() == before);
    }

    void middleDragOrbitsAndTheWheelZooms()
    {
        auto window = showWindow(test::sampleFile("cornell-box"));
        Viewport* viewport = window->viewport();
        const double yaw = viewport->camera().yawDegrees();
        const QPoint centre = viewport->rect().center();
        QTest::mousePress(viewport, Qt::MiddleButton, {}, centre);
        QTest::mouseMove(viewport, centre + QPoint(50, 0));
        QTest::mouseRelease(viewport, Qt::MiddleButton, {}, centre + QPoint(50, 0));
        QVERIFY(std::abs(viewport->camera().yawDegrees() - yaw) > 5.0);

        const double distance = viewport->camera().distance();
        QWheelEvent wheel(QPointF(centre), viewport->mapToGlobal(QPointF(centre)), QPoint(), QPoint(0, 120),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(viewport, &wheel);
        QVERIFY(viewport->camera().distance() < distance);
        // Nothing of that is an edit.
        QCOMPARE(window->document()->undoStack()->count(), 0);
    }

    void framingTheSelectionCentresIt()
    {
        auto window = showWindow(test::sampleFile("two-lights-room"));
        Viewport* viewport = window->viewport();
        SceneDocument* document = window->document();
        document->setSelection(Selection::single(SelectionKind::Object, "table"));
        viewport->frameSelection();
        const QPoint centre = pixelOfFace(viewport, document->scene(), "table.desk.py");
        QVERIFY(std::abs(centre.x() - viewport->width() / 2) < viewport->width() / 8);
    }
};

namespace {

// Its own main rather than the set-up of QTEST_MAIN: the default surface format
// has to be set before the application exists.
int runViewportGlTest(int argc, char* argv[])
{
    // As in the application: the 3.3 core format before the application exists.
    QSurfaceFormat::setDefaultFormat(Viewport::requestedFormat());
    QApplication app(argc, argv);
    ViewportGlTest test;
    return QTest::qExec(&test, argc, argv);
}

} // namespace

REGIO_QTEST_OWN_MAIN(ViewportGlTest, runViewportGlTest)

#include "viewport_gl_test.moc"
