// What one step of a region drag costs the UI thread on a room of 100
// objects in the regions the solver proposes (CTest label "timing"): the
// command, the dock's lists and every layer take under 250 ms; the BSP
// figures are left to the worker thread (regions_dock_test.cpp).
#include "editor/document/commands/region_commands.h"
#include "editor/regions/region_figures.h"
#include "region_fixture.h"
#include "solver/authoring/region_proposal.h"
#include "support/editor_documents.h"
#include "support/furnished_room.h"
#include "support/qt_test_registry.h"

#include <QElapsedTimer>
#include <QString>
#include <QTest>

using namespace regio;
using namespace regio::editor;

namespace {

using test::RegionFixture;

} // namespace

class RegionsDockTimingTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void oneRegionEditOnAHundredObjectRoomTakesUnder250MsOnTheUiThread()
    {
        model::Scene room = test::furnishedRoom(1);
        room.regions = solver::proposeRegions(room)->regions;
        RegionFixture f(room);
        QVERIFY(f.regions->figures()->waitUntilCurrent());
        // What the UI thread does for one step of a drag: the command, the
        // dock's lists and every layer. The BSP builds are not part of it.
        const model::Region& r = f.document.scene().regions.front();
        QElapsedTimer clock;
        clock.start();
        // Shrunk, so it cannot come to overlap a neighbour.
        QVERIFY(f.document.push(new SetRegionBox(&f.document, r.id, r.min, r.max - model::Vec3(0.0, 0.1, 0.0))));
        const qint64 ms = clock.elapsed();
        qInfo("one region edit on the furnished room (%zu regions): %lld ms on the UI thread", room.regions.size(),
              static_cast<long long>(ms));
        QVERIFY2(ms < 250, qPrintable(QStringLiteral("%1 ms").arg(ms)));
    }
};

REGIO_QTEST_MAIN(RegionsDockTimingTest)
#include "regions_dock_timing_test.moc"
