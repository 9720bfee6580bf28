// The viewport's camera and CPU picking: pure geometry, no GL.
#include "editor/viewport/camera.h"
#include "editor/viewport/clip_tool.h"
#include "editor/viewport/picking.h"
#include "editor/viewport/transform_gizmo.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <glm/geometric.hpp>

using namespace regio;
using namespace regio::editor;

namespace {

bool near(const model::Vec3& a, const model::Vec3& b, double eps = 1e-9) { return glm::length(a - b) < eps; }

model::Box3 unitBox()
{
    model::Box3 box;
    box.extend({-1, -1, -1});
    box.extend({1, 1, 1});
    return box;
}

} // namespace

class CameraTest : public QObject {
    Q_OBJECT
private slots:
    void theFrontViewLooksDownMinusZWithYUp()
    {
        Camera camera;
        camera.setStandardView(StandardView::Front);
        QVERIFY(near(camera.forward(), {0, 0, -1}));
        QVERIFY(near(camera.up(), {0, 1, 0}));
        QVERIFY(near(camera.right(), {1, 0, 0}));
    }

    void theTopViewLooksStraightDownWithAWellDefinedUp()
    {
        Camera camera;
        camera.setStandardView(StandardView::Top);
        QVERIFY(near(camera.forward(), {0, -1, 0}));
        QVERIFY(near(camera.up(), {0, 0, -1}));
    }

    void framingABoxPutsItsCentreInTheMiddleAndAllOfItInView()
    {
        Camera camera;
        camera.frame(unitBox(), 1.5);
        QVERIFY(near(camera.target(), {0, 0, 0}));
        for (int i = 0; i < 8; ++i) {
            const model::Vec3 corner(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
            const glm::dvec3 ndc = camera.project(corner, 1.5);
            QVERIFY(std::abs(ndc.x) <= 1.0 && std::abs(ndc.y) <= 1.0 && ndc.z > -1.0 && ndc.z < 1.0);
        }
    }

    void orbitingKeepsTheDistanceAndNeverFlipsOverThePole()
    {
        Camera camera;
        camera.frame(unitBox(), 1.0);
        const double distance = glm::length(camera.eye() - camera.target());
        camera.orbit(123.0, 500.0);
        QCOMPARE(camera.pitchDegrees(), 89.0);
        QVERIFY(std::abs(glm::length(camera.eye() - camera.target()) - distance) < 1e-9);
    }

    void panningMovesTheTargetInTheViewPlane()
    {
        Camera camera;
        camera.setStandardView(StandardView::Front);
        camera.pan(0.5, 0.0);             // the scene follows the cursor to the right...
        QVERIFY(camera.target().x < 0.0); // ...so the camera moves left
        QCOMPARE(camera.target().y, 0.0);
        QCOMPARE(camera.target().z, 0.0);
    }

    void zoomingNeverReachesZeroDistance()
    {
        Camera camera;
        for (int i = 0; i < 200; ++i)
            camera.zoom(0.5);
        QVERIFY(camera.distance() > 0.0);
    }

    void lookingTurnsAboutTheEye()
    {
        Camera camera;
        const model::Vec3 eye = camera.eye();
        camera.look(40.0, -10.0);
        QVERIFY(near(camera.eye(), eye, 1e-9));
    }

    void aSceneCameraIsAdoptedAndGivenBack()
    {
        model::Camera stored;
        stored.position = {0.278, 0.273, -0.8};
        stored.target = {0.278, 0.273, 0.0};
        stored.fovY = 39.3;
        Camera camera;
        camera.setFromSceneCamera(stored);
        QVERIFY(near(camera.eye(), stored.position, 1e-9));
        const model::Camera back = camera.toSceneCamera();
        QVERIFY(near(back.position, stored.position, 1e-9));
        QVERIFY(near(back.target, stored.target, 1e-9));
        QCOMPARE(back.fovY, 39.3);
    }

    void theRayThroughTheCentreOfTheViewHitsTheTarget()
    {
        Camera camera;
        camera.frame(unitBox(), 1.0);
        for (bool ortho : {false, true}) {
            camera.setOrthographic(ortho);
            const Ray ray = camera.rayThrough({0.0, 0.0}, 1.0);
            const model::Vec3 toTarget = camera.target() - ray.origin;
            QVERIFY(glm::length(glm::cross(toTarget, ray.direction)) < 1e-6 * glm::length(toTarget));
        }
    }

    void pixelsAndRaysAgree()
    {
        ScreenView view{Camera{}, 800, 600};
        view.camera.frame(unitBox(), view.aspect());
        const model::Vec3 p(0.3, -0.2, 0.5);
        const auto pixel = view.toPixels(p);
        QVERIFY(pixel);
        const Ray ray = view.ray(pixel->x, pixel->y);
        const model::Vec3 toP = p - ray.origin;
        QVERIFY(glm::length(glm::cross(toP, ray.direction)) < 1e-6 * glm::length(toP));
    }

    void pickingFindsTheNearestFaceAlongTheRay()
    {
        const model::Scene scene = test::smallScene();
        // Straight down onto the crate's top.
        const Ray ray{{2.25, 5.0, 0.25}, {0.0, -1.0, 0.0}};
        const auto hit = pickFace(scene, ray, true);
        QVERIFY(hit);
        QCOMPARE(hit->objectId, std::string("crate"));
        QCOMPARE(hit->partId, std::string("crate.body"));
        QCOMPARE(hit->faceId, std::string("crate.body.py"));
        QVERIFY(near(hit->point, {2.25, 0.5, 0.25}));
    }

    void pickingSeesThroughBackFacesOnlyWhenTheyAreHidden()
    {
        const model::Scene scene = test::smallScene();
        // From inside the crate looking up: the top is seen from behind.
        const Ray ray{{2.25, 0.25, 0.25}, {0.0, 1.0, 0.0}};
        const auto culled = pickFace(scene, ray, true);
        QVERIFY(!culled);
        const auto hit = pickFace(scene, ray, false);
        QVERIFY(hit);
        QCOMPARE(hit->faceId, std::string("crate.body.py"));
        QVERIFY(hit->backFacing);
    }

    void aRayThatMissesEverythingPicksNothing()
    {
        const Ray ray{{50, 50, 50}, {0.0, 1.0, 0.0}};
        QVERIFY(!pickFace(test::smallScene(), ray, false));
    }

    void theClipToolWantsThreePointsThatAreNotInALine()
    {
        ClipTool tool;
        tool.start();
        QVERIFY(!tool.addPoint({0, 0, 0}));
        QVERIFY(!tool.addPoint({1, 0, 0}));
        QVERIFY(!tool.addPoint({2, 0, 0})); // collinear: ignored
        QCOMPARE(tool.points().size(), size_t(2));
        const auto plane = tool.addPoint({0, 0, -1});
        QVERIFY(plane);
        QVERIFY(near(plane->normal, {0, 1, 0}));
        QVERIFY(!tool.active());
    }

    void draggingTheMoveGizmoAlongXMovesBySnappedSteps()
    {
        ScreenView view{Camera{}, 800, 600};
        view.camera.setStandardView(StandardView::Front);
        view.camera.setTargetAndDistance({0, 0, 0}, 5.0);
        TransformGizmo gizmo;
        gizmo.setPivot({0, 0, 0});
        const auto centre = view.toPixels({0, 0, 0});
        const auto tip = view.toPixels({0.3, 0, 0});
        QVERIFY(centre && tip);
        // Press on the x handle a little right of the centre, drag right.
        const double px = centre->x + 30.0, py = centre->y;
        QCOMPARE(gizmo.hitTest(view, px, py), GizmoHandle::X);
        gizmo.beginDrag(GizmoHandle::X, view, px, py);
        GizmoSnap snap;
        snap.step = 0.25;
        const double worldPerPixel = view.worldPerPixelAt({0, 0, 0});
        const glm::dmat4 m = gizmo.dragTo(view, px + 0.6 / worldPerPixel, py, snap);
        const model::Vec3 moved = glm::dvec3(m * glm::dvec4(0, 0, 0, 1));
        QVERIFY(near(moved, {0.5, 0, 0}, 1e-9));
    }
};

REGIO_QTEST_MAIN(CameraTest)
#include "camera_test.moc"
