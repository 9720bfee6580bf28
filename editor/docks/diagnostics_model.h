#pragma once
// Diagnostics as a table: severity, where (JSON pointer or line:column) and
// message. Shared by the diagnostics dock and the "cannot open" dialog.
#include "model/diagnostic.h"

#include <QAbstractTableModel>

namespace regio::editor {

class DiagnosticsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { SeverityColumn, LocationColumn, MessageColumn, ColumnCount };

    using QAbstractTableModel::QAbstractTableModel;

    void setDiagnostics(model::Diagnostics diagnostics);
    const model::Diagnostics& diagnostics() const { return m_diagnostics; }
    const model::Diagnostic* at(const QModelIndex& index) const;
    int errorCount() const;
    int warningCount() const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    static QString locationText(const model::Diagnostic& diagnostic);

private:
    model::Diagnostics m_diagnostics;
};

} // namespace regio::editor
