#include "editor/app/diagnostics_dialog.h"

#include "editor/docks/diagnostics_model.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QTreeView>
#include <QVBoxLayout>

namespace regio::editor {

DiagnosticsDialog::DiagnosticsDialog(const QString& title, const QString& text, const model::Diagnostics& diagnostics,
                                     QWidget* parent)
    : QDialog(parent)
{
    setWindowTitle(title);
    auto* layout = new QVBoxLayout(this);
    auto* label = new QLabel(text, this);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(label);

    auto* model = new DiagnosticsModel(this);
    model->setDiagnostics(diagnostics);
    auto* view = new QTreeView(this);
    view->setRootIsDecorated(false);
    view->setModel(model);
    view->setAlternatingRowColors(true);
    view->setWordWrap(true);
    view->header()->setStretchLastSection(true);
    view->resizeColumnToContents(DiagnosticsModel::SeverityColumn);
    view->resizeColumnToContents(DiagnosticsModel::LocationColumn);
    layout->addWidget(view);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    layout->addWidget(buttons);
    resize(760, 360);
}

} // namespace regio::editor
