#include "editor/docks/diagnostics_dock.h"

#include "editor/docks/diagnostics_model.h"
#include "editor/document/scene_document.h"
#include "model/validation/validation.h"

#include <QHeaderView>
#include <QLabel>
#include <QTreeView>
#include <QVBoxLayout>

namespace regio::editor {

namespace {
constexpr int kDebounceMs = 250;
}

DiagnosticsDock::DiagnosticsDock(SceneDocument* document, QWidget* parent)
    : QDockWidget(tr("Diagnostics"), parent)
    , m_document(document)
    , m_model(new DiagnosticsModel(this))
{
    setObjectName(QStringLiteral("DiagnosticsDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    m_summary = new QLabel(body);
    layout->addWidget(m_summary);
    m_view = new QTreeView(body);
    m_view->setModel(m_model);
    m_view->setRootIsDecorated(false);
    m_view->setAlternatingRowColors(true);
    m_view->setUniformRowHeights(true);
    m_view->header()->setStretchLastSection(true);
    m_view->header()->resizeSection(DiagnosticsModel::SeverityColumn, 90);
    m_view->header()->resizeSection(DiagnosticsModel::LocationColumn, 260);
    layout->addWidget(m_view);
    setWidget(body);

    m_debounce.setSingleShot(true);
    m_debounce.setInterval(kDebounceMs);
    connect(&m_debounce, &QTimer::timeout, this, &DiagnosticsDock::validateNow);
    auto schedule = [this] { m_debounce.start(); };
    connect(document, &SceneDocument::objectsChanged, this, schedule);
    connect(document, &SceneDocument::geometryChanged, this, schedule);
    connect(document, &SceneDocument::materialsChanged, this, schedule);
    connect(document, &SceneDocument::regionsChanged, this, schedule);
    connect(document, &SceneDocument::settingsChanged, this, schedule);
    connect(document, &SceneDocument::sceneReset, this, &DiagnosticsDock::validateNow);
    connect(m_view, &QTreeView::activated, this, &DiagnosticsDock::activate);
    connect(m_view, &QTreeView::clicked, this, &DiagnosticsDock::activate);
    validateNow();
}

void DiagnosticsDock::validateNow()
{
    m_debounce.stop();
    m_model->setDiagnostics(model::validateScene(m_document->scene()));
    const int errors = m_model->errorCount(), warnings = m_model->warningCount();
    m_summary->setText(errors + warnings == 0 ? tr("The scene is valid.")
                                              : tr("%n error(s)", nullptr, errors) + QStringLiteral(", ") +
                                                    tr("%n warning(s)", nullptr, warnings));
    emit problemCountChanged(errors, warnings);
}

Selection DiagnosticsDock::selectionFor(const model::Scene& scene, const std::vector<std::string>& idPath)
{
    for (auto it = idPath.rbegin(); it != idPath.rend(); ++it) {
        for (SelectionKind kind : {SelectionKind::Face, SelectionKind::Part, SelectionKind::Object,
                                   SelectionKind::Material, SelectionKind::Region})
            if (selectionIdExists(scene, kind, *it))
                return Selection::single(kind, *it);
    }
    return {};
}

void DiagnosticsDock::activate(const QModelIndex& index)
{
    const model::Diagnostic* d = m_model->at(index);
    if (!d)
        return;
    const Selection selection = selectionFor(m_document->scene(), d->idPath);
    if (selection.empty())
        return;
    m_document->setSelection(selection);
    emit elementActivated(selection);
}

} // namespace regio::editor
