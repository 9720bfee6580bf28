// Undo commands on regions and their BSP root-patch orders.
#include "editor/document/commands/bsp_order_commands.h"
#include "editor/document/commands/region_commands.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QSignalSpy>

using namespace regio;
using namespace regio::editor;

namespace {

const std::vector<std::string>& orderOf(const SceneDocument& document, const std::string& region)
{
    return document.scene().findRegion(region)->bspOrder;
}

} // namespace

class RegionCommandsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void addingARegionCanBeUndone()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QSignalSpy regions(&document, &SceneDocument::regionsChanged);
        model::Region right{"right", "Right", {3, -1, -1}, {5, 3, 2}, {"crate.body.py"}};
        QVERIFY(document.push(new AddRegion(&document, right)));
        QCOMPARE(document.scene().regions.size(), size_t(2));
        QCOMPARE(regions.count(), 1);
        VERIFY_UNDO_REDO(document, before);
    }

    void anEmptyOrInsideOutBoxIsRefused()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QVERIFY(!document.push(new AddRegion(&document, {"bad", "", {1, 1, 1}, {0, 2, 2}, {}})));
        QVERIFY(!document.push(new SetRegionBox(&document, "left", {0, 0, 0}, {0, 1, 1})));
        QVERIFY(document.scene() == test::smallScene());
    }

    void removingARegionRestoresItInPlace()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(new RemoveRegion(&document, "left")));
        QVERIFY(document.scene().regions.empty());
        VERIFY_UNDO_REDO(document, before);
    }

    void renamingAndNamingARegionCanBeUndone()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(new RenameRegion(&document, "left", "west")));
        QVERIFY(document.scene().findRegion("west"));
        VERIFY_UNDO_REDO(document, before);
        const model::Scene renamed = document.scene();
        QVERIFY(document.push(new SetRegionName(&document, "west", "West wing")));
        VERIFY_UNDO_REDO(document, renamed);
    }

    void resizingARegionMergesWhileDragging()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        for (int i = 1; i <= 10; ++i)
            QVERIFY(document.push(new SetRegionBox(&document, "left", {-1, -1, -1}, {3 + 0.1 * i, 3, 2})));
        QCOMPARE(document.undoStack()->count(), 1);
        QCOMPARE(document.scene().findRegion("left")->max.x, 4.0);
        VERIFY_UNDO_REDO(document, test::smallScene());
    }

    void replacingABspOrderCanBeUndone()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        const model::Scene before = document.scene();
        QVERIFY(document.push(new SetBspOrder(&document, "left", {"table.legs.py", "table.desk.py", "table.desk.ny"})));
        QCOMPARE(orderOf(document, "left").size(), size_t(3));
        VERIFY_UNDO_REDO(document, before);
    }

    void aBspOrderNamingAMissingFaceIsRefused()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QVERIFY(!document.push(new SetBspOrder(&document, "left", {"no-such-face"})));
        QVERIFY(!document.push(new InsertBspEntry(&document, "left", "no-such-face")));
        QVERIFY(document.scene() == test::smallScene());
    }

    void insertingRemovingAndMovingEntriesCanBeUndone()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        model::Scene expected = document.scene();
        QVERIFY(document.push(new InsertBspEntry(&document, "left", "table.desk.ny", 0)));
        QCOMPARE(orderOf(document, "left").front(), std::string("table.desk.ny"));
        VERIFY_UNDO_REDO(document, expected);
        expected = document.scene();
        QVERIFY(document.push(new MoveBspEntry(&document, "left", 0, 2)));
        QCOMPARE(orderOf(document, "left").back(), std::string("table.desk.ny"));
        VERIFY_UNDO_REDO(document, expected);
        expected = document.scene();
        QVERIFY(document.push(new RemoveBspEntry(&document, "left", 1)));
        QCOMPARE(orderOf(document, "left"), (std::vector<std::string>{"table.desk.py", "table.desk.ny"}));
        VERIFY_UNDO_REDO(document, expected);
    }

    void aFaceCannotBeInAnOrderTwice()
    {
        SceneDocument document;
        test::resetDocument(document, test::smallScene());
        QVERIFY(!document.push(new InsertBspEntry(&document, "left", "table.desk.py")));
        QCOMPARE(document.undoStack()->count(), 0);
    }
};

REGIO_QTEST_MAIN(RegionCommandsTest)
#include "region_commands_test.moc"
