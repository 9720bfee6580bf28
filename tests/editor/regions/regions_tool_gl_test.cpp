// The region tool driven by real mouse events on a shown viewport (Xvfb +
// Mesa): drawing a box on the ground grid, selecting it by a click, resizing
// it by a face handle (one undo step per drag), and Esc.
#include "editor/document/commands/region_commands.h"
#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/regions/region_authoring.h"
#include "editor/regions/region_box_tool.h"
#include "editor/regions/region_layers.h"
#include "editor/viewport/viewport.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QAction>
#include <QMainWindow>
#include <QUndoStack>

#include <cmath>
#include <memory>

using namespace regio;
using namespace regio::editor;

namespace {

// The small scene without its region, seen from the top: the table at
// x 0..1, the crate at x 2..2.5; nothing stands between x 1 and 2.
struct ShownTool {
    SceneDocument document; // outlives the window and everything in it
    QMainWindow window;
    Viewport* viewport;
    RegionAuthoring* regions;

    ShownTool()
    {
        model::Scene scene = test::smallScene();
        scene.regions.clear();
        test::resetDocument(document, scene);
        viewport = new Viewport(&document, &window);
        window.setCentralWidget(viewport);
        regions = new RegionAuthoring(&document, viewport, nullptr, nullptr, &window);
        window.resize(900, 700);
        window.show();
        if (!QTest::qWaitForWindowExposed(&window))
            qFatal("the window was never exposed");
        if (!QTest::qWaitFor([&] { return viewport->hasRenderedFrame(); }, 20000))
            qFatal("the viewport never rendered a frame");
        viewport->setSnapEnabled(true);
        viewport->setGridStep(0.1);
        viewport->setStandardView(StandardView::Top);
        viewport->frameAll();
        regions->drawAction()->setChecked(true);
    }

    QPoint pixelOf(const model::Vec3& world) const
    {
        const auto p = viewport->screenView().toPixels(world);
        if (!p)
            qFatal("the point is behind the eye");
        return {int(std::lround(p->x)), int(std::lround(p->y))};
    }

    // A left drag in steps, as a hand would do it.
    void drag(const QPoint& from, const QPoint& to)
    {
        QTest::mousePress(viewport, Qt::LeftButton, {}, from);
        for (int i = 1; i <= 8; ++i)
            QTest::mouseMove(viewport, from + (to - from) * i / 8);
        QTest::mouseRelease(viewport, Qt::LeftButton, {}, to);
    }
};

bool near(double a, double b) { return std::abs(a - b) < 1e-9; }

} // namespace

class RegionsToolGlTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void draggingOnTheGroundDrawsASnappedBoxAsOneUndoStep()
    {
        ShownTool t;
        QVERIFY(t.regions->tool()->isActive());
        QCOMPARE(t.viewport->cursor().shape(), Qt::CrossCursor);
        t.drag(t.pixelOf({1.2, 0, 0.1}), t.pixelOf({1.8, 0, 0.9}));
        QCOMPARE(t.document.scene().regions.size(), size_t(1));
        QCOMPARE(t.document.undoStack()->count(), 1);
        const model::Region& r = t.document.scene().regions.front();
        QVERIFY2(near(r.min.x, 1.2) && near(r.max.x, 1.8), qPrintable(formatVector(r.min) + " " + formatVector(r.max)));
        QVERIFY(near(r.min.z, 0.1) && near(r.max.z, 0.9));
        // Up from the ground to the top of the scene (the lamp at 2.02).
        QVERIFY(near(r.min.y, 0.0) && near(r.max.y, 2.02));
        QVERIFY(t.document.selection() == Selection::single(SelectionKind::Region, r.id));
        QVERIFY(t.viewport->hasLayer(QString::fromLatin1(kRegionHandlesLayer)));
        QVERIFY(!t.viewport->hasLayer(QString::fromLatin1(kRegionDraftLayer)));
        t.document.undoStack()->undo();
        QVERIFY(t.document.scene().regions.empty());
    }

    void dragsStartedOnATableTopDrawFromItsHeight()
    {
        ShownTool t;
        t.drag(t.pixelOf({0.2, 0.75, 0.2}), t.pixelOf({0.8, 0.75, 0.8}));
        QCOMPARE(t.document.scene().regions.size(), size_t(1));
        QVERIFY(near(t.document.scene().regions.front().min.y, 0.75));
    }

    void aFaceHandleDragResizesTheSelectedRegionOneUndoStepPerDrag()
    {
        ShownTool t;
        t.drag(t.pixelOf({1.2, 0, 0.1}), t.pixelOf({1.8, 0, 0.9}));
        const std::string id = t.document.scene().regions.front().id;
        const model::Scene drawn = t.document.scene();
        // The +x handle sits at the middle of the box's x-max face.
        const model::Box3 box = boxOf(*drawn.findRegion(id));
        const model::Vec3 handle = handlePosition(box, 1);
        const QPoint at = t.pixelOf(handle);
        QCOMPARE(t.regions->tool()->handleAt(at.x(), at.y()), 1);
        QTest::mouseMove(t.viewport, at);
        QCOMPARE(t.viewport->cursor().shape(), Qt::SizeAllCursor);

        t.drag(at, t.pixelOf(handle + model::Vec3(0.4, 0, 0)));
        QVERIFY(near(t.document.scene().findRegion(id)->max.x, 2.2));
        QCOMPARE(t.document.undoStack()->count(), 2);
        const model::Scene widened = t.document.scene();

        const model::Vec3 moved = handlePosition(boxOf(*widened.findRegion(id)), 1);
        t.drag(t.pixelOf(moved), t.pixelOf(moved - model::Vec3(0.3, 0, 0)));
        QVERIFY(near(t.document.scene().findRegion(id)->max.x, 1.9));
        QCOMPARE(t.document.undoStack()->count(), 3);

        t.document.undoStack()->undo();
        QVERIFY(t.document.scene() == widened);
        t.document.undoStack()->undo();
        QVERIFY(t.document.scene() == drawn);
    }

    void aClickSelectsTheRegionUnderTheCursorAndElsewhereClearsIt()
    {
        ShownTool t;
        t.drag(t.pixelOf({1.2, 0, 0.1}), t.pixelOf({1.8, 0, 0.9}));
        t.document.clearSelection();
        QTest::mouseClick(t.viewport, Qt::LeftButton, {}, t.pixelOf({1.5, 0, 0.5}));
        QCOMPARE(t.document.selection().kind, SelectionKind::Region);
        QTest::mouseClick(t.viewport, Qt::LeftButton, {}, t.pixelOf({2.2, 0, 0.8}));
        QVERIFY(t.document.selection().empty());
        QCOMPARE(t.document.undoStack()->count(), 1);
    }

    void colouringPartsByRegionIsWhatTheViewportShows()
    {
        ShownTool t;
        t.regions->drawAction()->setChecked(false);
        t.regions->showBoxesAction()->setChecked(false);
        QVERIFY(t.document.push(new AddRegion(&t.document, {"left", "", {-1, -1, -1}, {1.5, 3, 2}, {}})));
        const QPoint desk = t.pixelOf({0.15, 0.75, 0.15}); // the desk top, beside the lamp
        const auto pixelAt = [&](const QPoint& p) {
            t.viewport->update();
            QTest::qWait(50);
            return t.viewport->grabFramebuffer().pixel(p * t.viewport->devicePixelRatio());
        };
        const QRgb material = pixelAt(desk);
        // The white material: grey.
        QVERIFY2(std::abs(qRed(material) - qBlue(material)) < 30, qPrintable(QString::number(material, 16)));
        t.regions->colourByRegionAction()->setChecked(true);
        const QRgb coloured = pixelAt(desk);
        const glm::vec4 expected = regionColour(0);
        // The region's hue (orange for the first), shaded by the fixed light.
        QVERIFY2(expected.r > expected.b + 0.3f, "the first region colour is warm");
        QVERIFY2(qRed(coloured) > qBlue(coloured) + 60, qPrintable(QString::number(coloured, 16)));
        // The crate (x 2..2.5) lies outside every region: grey.
        const QRgb crate = pixelAt(t.pixelOf({2.25, 0.5, 0.25}));
        QVERIFY2(std::abs(qRed(crate) - qBlue(crate)) < 30, qPrintable(QString::number(crate, 16)));
    }

    void escapeCancelsADrawingThenLeavesTheTool()
    {
        ShownTool t;
        const QPoint from = t.pixelOf({1.2, 0, 0.1}), to = t.pixelOf({1.8, 0, 0.9});
        QTest::mousePress(t.viewport, Qt::LeftButton, {}, from);
        for (int i = 1; i <= 4; ++i)
            QTest::mouseMove(t.viewport, from + (to - from) * i / 4);
        QVERIFY(t.regions->tool()->draft().has_value());
        QTest::keyClick(t.viewport, Qt::Key_Escape);
        QVERIFY(!t.regions->tool()->draft());
        QTest::mouseRelease(t.viewport, Qt::LeftButton, {}, to);
        QVERIFY(t.document.scene().regions.empty());
        QVERIFY(t.regions->tool()->isActive());
        QTest::keyClick(t.viewport, Qt::Key_Escape);
        QVERIFY(!t.regions->tool()->isActive());
        QVERIFY(!t.regions->drawAction()->isChecked());
        QCOMPARE(t.viewport->cursor().shape(), Qt::ArrowCursor);
    }
};

REGIO_QTEST_MAIN(RegionsToolGlTest)
#include "regions_tool_gl_test.moc"
