#include "editor/docks/diagnostics_model.h"

#include "model/diagnostic_subject.h"
#include "model/io/printable.h"

#include "editor/document/qt_conversions.h"

#include <QApplication>
#include <QStyle>

#include <algorithm>

namespace regio::editor {

void DiagnosticsModel::setDiagnostics(model::Diagnostics diagnostics)
{
    beginResetModel();
    m_diagnostics = std::move(diagnostics);
    // Errors first, then by position in the file.
    std::stable_sort(
        m_diagnostics.begin(), m_diagnostics.end(),
        [](const model::Diagnostic& a, const model::Diagnostic& b) { return a.isError() && !b.isError(); });
    endResetModel();
}

const model::Diagnostic* DiagnosticsModel::at(const QModelIndex& index) const
{
    if (!index.isValid() || index.row() >= int(m_diagnostics.size()))
        return nullptr;
    return &m_diagnostics[size_t(index.row())];
}

int DiagnosticsModel::errorCount() const
{
    return int(std::count_if(m_diagnostics.begin(), m_diagnostics.end(),
                             [](const model::Diagnostic& d) { return d.isError(); }));
}

int DiagnosticsModel::warningCount() const { return int(m_diagnostics.size()) - errorCount(); }

int DiagnosticsModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_diagnostics.size());
}

int DiagnosticsModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QString DiagnosticsModel::locationText(const model::Diagnostic& d)
{
    if (d.line > 0)
        return tr("line %1, column %2").arg(d.line).arg(d.column);
    if (d.pointer.empty())
        return tr("(whole scene)");
    // The element at fault by its id first, which stays right when the file
    // is edited; the pointer after it.
    if (const std::optional<model::DiagnosticSubject> subject = model::subjectOf(d)) {
        const QString id = toQString(model::printable(subject->id));
        QString what;
        if (subject->kind == "material")
            what = tr("material %1").arg(id);
        else if (subject->kind == "object")
            what = tr("object %1").arg(id);
        else if (subject->kind == "part")
            what = tr("part %1").arg(id);
        else if (subject->kind == "face")
            what = tr("face %1").arg(id);
        else
            what = tr("region %1").arg(id);
        return what + QStringLiteral("  ") + toQString(d.pointer);
    }
    return toQString(d.pointer);
}

QVariant DiagnosticsModel::data(const QModelIndex& index, int role) const
{
    const model::Diagnostic* d = at(index);
    if (!d)
        return {};
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case SeverityColumn: return d->isError() ? tr("Error") : tr("Warning");
        case LocationColumn: return locationText(*d);
        case MessageColumn: return toQString(d->message);
        }
    }
    if (role == Qt::DecorationRole && index.column() == SeverityColumn)
        return QApplication::style()->standardIcon(d->isError() ? QStyle::SP_MessageBoxCritical
                                                                : QStyle::SP_MessageBoxWarning);
    if (role == Qt::ToolTipRole) {
        QString path;
        for (const std::string& id : d->idPath)
            path += (path.isEmpty() ? QString() : QStringLiteral(" › ")) + toQString(id);
        return path.isEmpty() ? toQString(d->message) : path + QLatin1Char('\n') + toQString(d->message);
    }
    return {};
}

QVariant DiagnosticsModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case SeverityColumn: return tr("Severity");
    case LocationColumn: return tr("Where");
    case MessageColumn: return tr("Problem");
    }
    return {};
}

} // namespace regio::editor
