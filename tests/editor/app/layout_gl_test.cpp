// The window a new user meets, at common screen sizes (a virtual X server,
// real OpenGL): the viewport keeps at least 60 % of the width, the scene tree
// shows every top-level id of the sample whole, the solver's settings are in
// the Solver panel only, and View > Reset Layout brings that back after the
// panels were moved. Screenshots of each size are left in the build folder
// (layout-WxH.png) to look at.
#include "editor/app/main_window.h"
#include "editor/docks/scene_tree_dock.h"
#include "editor/docks/scene_tree_model.h"
#include "editor/preview/preview_controller.h"
#include "editor/preview/solver_dock.h"
#include "editor/viewport/viewport.h"
#include "support/editor_documents.h"
#include "support/qt_test_registry.h"

#include <QDockWidget>
#include <QHeaderView>
#include <QMenuBar>
#include <QSpinBox>
#include <QTreeView>

#include <memory>

using namespace regio;
using namespace regio::editor;

namespace {

std::unique_ptr<MainWindow> windowOfSize(QSize size)
{
    MainWindowOptions options;
    options.persistent = false;
    options.interactive = false;
    options.autosave = false;
    auto window = std::make_unique<MainWindow>(options);
    window->resize(size);
    window->openFile(test::sampleFile("two-lights-room"));
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get()))
        qWarning("the window was not exposed");
    QTest::qWait(100);
    return window;
}

// How the window's layout fares: the viewport's share of the width, and the
// top-level ids the scene tree cuts.
struct LayoutCheck {
    double viewportShare = 0.0;
    QStringList cutIds;
};

LayoutCheck check(MainWindow& window)
{
    LayoutCheck c;
    c.viewportShare = double(window.findChild<Viewport*>()->width()) / window.width();
    QTreeView* tree = window.findChild<SceneTreeDock*>()->view();
    const QFontMetrics metrics(tree->font());
    const int column = SceneTreeModel::IdColumn;
    // The id column must end inside the tree's viewport, and each id fit in it.
    const int columnEnd = tree->header()->sectionViewportPosition(column) + tree->header()->sectionSize(column);
    for (int row = 0; row < tree->model()->rowCount(); ++row) {
        const QModelIndex index = tree->model()->index(row, column);
        const QString id = index.data().toString();
        const QRect cell = tree->visualRect(index);
        const int needed = metrics.horizontalAdvance(id);
        // visualRect spans the column after the indentation and decoration.
        const int room = std::min(cell.right(), tree->viewport()->width()) - cell.left() - 24; // icon + margins
        if (needed > room || columnEnd > tree->viewport()->width())
            c.cutIds << id;
    }
    return c;
}

} // namespace

class LayoutGlTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::initTestEnvironment(); }

    void theFirstLayoutFitsTheScreen_data()
    {
        QTest::addColumn<QSize>("size");
        QTest::newRow("1280x800") << QSize(1280, 800);
        QTest::newRow("1600x1000") << QSize(1600, 1000);
        QTest::newRow("2560x1440") << QSize(2560, 1440);
    }
    void theFirstLayoutFitsTheScreen()
    {
        QFETCH(QSize, size);
        auto window = windowOfSize(size);
        QCOMPARE(window->size(), size);
        window->grab().save(QStringLiteral(REGIO_BINARY_DIR "/layout-%1x%2.png").arg(size.width()).arg(size.height()));
        for (QDockWidget* dock : window->findChildren<QDockWidget*>())
            if (dock->isVisible())
                qInfo("%s: %d px wide (at least %d)", qPrintable(dock->objectName()), dock->width(),
                      dock->minimumSizeHint().width());
        const LayoutCheck c = check(*window);
        QVERIFY2(
            c.viewportShare >= 0.6,
            qPrintable(QStringLiteral("the viewport has %1 % of the width").arg(100.0 * c.viewportShare, 0, 'f', 1)));
        QVERIFY2(c.cutIds.isEmpty(), qPrintable(QStringLiteral("cut: ") + c.cutIds.join(QStringLiteral(", "))));
        // The solver's settings have one place: the Solver panel.
        QVERIFY(window->findChild<SolverDock*>()->findChild<QSpinBox*>(QStringLiteral("hemicube")));
        int hemicubeBoxes = 0;
        for (QSpinBox* box : window->findChildren<QSpinBox*>())
            hemicubeBoxes += box->objectName() == QStringLiteral("hemicube") ? 1 : 0;
        QCOMPARE(hemicubeBoxes, 1);
    }

    void resetLayoutBringsThePanelsBack()
    {
        auto window = windowOfSize(QSize(1600, 1000));
        auto* tree = window->findChild<SceneTreeDock*>();
        tree->setFloating(true);
        window->findChild<SolverDock*>()->hide();
        QTest::qWait(50);
        QVERIFY(check(*window).viewportShare > 0.6 || tree->isFloating());
        QAction* reset = nullptr;
        for (QAction* action : window->findChildren<QAction*>())
            if (action->text() == MainWindow::tr("&Reset Layout"))
                reset = action;
        QVERIFY(reset);
        reset->trigger();
        QTest::qWait(100);
        QVERIFY(!tree->isFloating());
        QVERIFY(tree->isVisible());
        const LayoutCheck c = check(*window);
        QVERIFY2(c.viewportShare >= 0.6, qPrintable(QString::number(c.viewportShare)));
        QVERIFY2(c.cutIds.isEmpty(), qPrintable(c.cutIds.join(QStringLiteral(", "))));
    }
};

REGIO_QTEST_MAIN(LayoutGlTest)
#include "layout_gl_test.moc"
