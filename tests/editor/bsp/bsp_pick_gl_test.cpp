// The BSP pick tools on a real OpenGL view (Xvfb): a click on a face with
// "pick face to insert" adds exactly that face to the region's BSP order (one
// undo step), and a click with "painter order from point / patch" starts the
// playback that equals the solver's traversal from the clicked spot.
#include "editor/app/main_window.h"
#include "editor/bsp/bsp_authoring.h"
#include "editor/bsp/face_pick_tool.h"
#include "editor/bsp/painter_playback.h"
#include "editor/document/scene_document.h"
#include "editor/viewport/scene_mesh.h"
#include "editor/viewport/viewport.h"
#include "model/geometry/region_clip.h"
#include "solver/solver.h"
#include "solver/visibility/painter_order.h"
#include "support/editor_documents.h"
#include "support/editor_windows.h"
#include "support/qt_test_registry.h"

#include <QColor>
#include <QImage>

#include <glm/geometric.hpp>

#include <memory>
#include <optional>

using namespace regio;
using namespace regio::editor;

namespace {

std::unique_ptr<MainWindow> showWindow(const QString& scene)
{
    auto window = test::quietWindow();
    window->resize(1200, 800);
    if (!window->openFile(scene))
        qFatal("cannot open %s", qPrintable(scene));
    // Outside the room, looking in through the front wall (the viewport
    // culls back faces): every region's faces are in view, whatever camera
    // the sample stores.
    model::Camera outside;
    outside.position = {3.0, 1.6, -2.5};
    outside.target = {3.0, 1.2, 2.0};
    outside.up = {0.0, 1.0, 0.0};
    outside.fovY = 60.0;
    window->viewport()->camera().setFromSceneCamera(outside);
    window->viewport()->update();
    test::showAndWaitForFrame(*window);
    return window;
}

struct Target {
    std::string faceId;
    QPoint pixel;
};

// A face of `regionId` not yet in its order whose centre pixel shows that
// very face (not hidden behind another one).
std::optional<Target> visibleUnlistedFace(const Viewport* viewport, const model::Scene& scene,
                                          const std::string& regionId)
{
    const model::Region* region = scene.findRegion(regionId);
    model::Box3 box;
    box.min = region->min;
    box.max = region->max;
    box.empty = false;
    for (const model::Object& object : scene.objects)
        for (const model::Part& part : object.parts)
            for (const model::Face& face : part.faces) {
                if (std::find(region->bspOrder.begin(), region->bspOrder.end(), face.id) != region->bspOrder.end())
                    continue;
                if (!model::faceTouchesRegionBox(model::loopPositions(part.vertices, face.loop), box))
                    continue;
                const auto pixel = viewport->screenView().toPixels(boundsOfFaces(scene, {face.id}).center());
                if (!pixel || pixel->x < 5 || pixel->y < 5 || pixel->x > viewport->width() - 5 ||
                    pixel->y > viewport->height() - 5)
                    continue;
                const QPoint p(int(pixel->x), int(pixel->y));
                const auto hit = FacePickTool::pickAt(*viewport, scene, p);
                if (hit && hit->faceId == face.id)
                    return Target{face.id, p};
            }
    return std::nullopt;
}

} // namespace

class BspPickGlTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void clickingAFaceWithThePickToolInsertsThatFace()
    {
        auto window = showWindow(test::sampleFile("two-lights-room"));
        Viewport* viewport = window->viewport();
        SceneDocument* document = window->document();
        BspAuthoring* bsp = window->bspAuthoring();
        bsp->setCurrentRegion("east");
        const auto target = visibleUnlistedFace(viewport, document->scene(), "east");
        QVERIFY2(target, "no unlisted face of the east region is visible");
        const model::Scene before = document->scene();

        bsp->startInsertPick();
        QVERIFY(bsp->insertPickActive());
        QTest::mouseClick(viewport, Qt::LeftButton, {}, target->pixel);
        QCOMPARE(document->scene().findRegion("east")->bspOrder.back(), target->faceId);
        QCOMPARE(document->scene().findRegion("east")->bspOrder.size(), before.findRegion("east")->bspOrder.size() + 1);
        QCOMPARE(document->undoStack()->count(), 1);
        QVERIFY(document->selection().empty()); // the tool took the click, not the selection
        // The tool stays for more picks; a second click on the same face is refused.
        QVERIFY(bsp->insertPickActive());
        QTest::mouseClick(viewport, Qt::LeftButton, {}, target->pixel);
        QCOMPARE(document->undoStack()->count(), 1);
        VERIFY_UNDO_REDO(*document, before);

        QTest::keyClick(viewport, Qt::Key_Escape);
        QVERIFY(!bsp->insertPickActive());
        QTest::mouseClick(viewport, Qt::LeftButton, {}, target->pixel);
        QCOMPARE(document->undoStack()->count(), 1); // an ordinary click selects again
        QVERIFY(!document->selection().empty());
    }

    void clickingWithThePlaybackToolPaintsFromThatPoint()
    {
        auto window = showWindow(test::sampleFile("two-lights-room"));
        Viewport* viewport = window->viewport();
        SceneDocument* document = window->document();
        BspAuthoring* bsp = window->bspAuthoring();
        const auto target = visibleUnlistedFace(viewport, document->scene(), "east");
        QVERIFY(target);
        const auto hit = FacePickTool::pickAt(*viewport, document->scene(), target->pixel);
        QVERIFY(hit);

        const QRgb surface = viewport->grabFramebuffer().pixel(target->pixel);
        bsp->startPlaybackPick(false);
        QVERIFY(bsp->playbackPickActive());
        QTest::mouseClick(viewport, Qt::LeftButton, {}, target->pixel);
        QVERIFY(!bsp->playbackPickActive()); // one pick
        PainterPlayback* playback = bsp->playback();
        QVERIFY(playback->active());
        solver::SolverOptions unsplit; // the prepared mesh, before adaptive subdivision splits any element
        unsplit.adaptive = false;
        auto created = solver::Solver::create(document->scene(), unsplit);
        QVERIFY(created.ok());
        const solver::PreparedScene& prepared = (*created)->prepared();
        const model::Vec3 eye = eyeAbovePick(*hit, glm::length(prepared.bounds.size()));
        QVERIFY(glm::length(playback->eye() - eye) < 1e-12);
        // The eye is off the surface, on the side the click came from.
        QVERIFY(glm::dot(eye - hit->point, hit->backFacing ? -hit->normal : hit->normal) > 0.0);
        const solver::PainterOrder expected = solver::painterOrder(prepared, eye);
        QCOMPARE(playback->order()->nodes, expected.nodes);
        QCOMPARE(playback->order()->steps.size(), expected.steps.size());
        for (size_t i = 0; i < expected.steps.size(); ++i)
            QCOMPARE(playback->order()->steps[i].element, expected.steps[i].element);

        // The ramp replaces the surfaces: the clicked spot is no longer the material's colour.
        QVERIFY(viewport->hasLayer(PainterPlayback::layerName()));
        const QRgb painted = viewport->grabFramebuffer().pixel(target->pixel);
        QVERIFY2(painted != surface, qPrintable(QColor(painted).name()));

        // From a patch: the patch under the click shoots, as in the solver.
        bsp->startPlaybackPick(true);
        QTest::mouseClick(viewport, Qt::LeftButton, {}, target->pixel);
        QVERIFY(playback->patch() >= 0);
        const solver::PainterOrder fromPatch = solver::painterOrderFromPatch(prepared, playback->patch());
        QCOMPARE(playback->order()->nodes, fromPatch.nodes);
        QCOMPARE(playback->order()->culledRegions, fromPatch.culledRegions);
        QCOMPARE(playback->order()->steps.size(), fromPatch.steps.size());
        QCOMPARE(document->undoStack()->count(), 0);
    }
};

REGIO_QTEST_MAIN(BspPickGlTest)
#include "bsp_pick_gl_test.moc"
