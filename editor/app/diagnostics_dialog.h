#pragma once
// "The file could not be opened" with every diagnostic the reader found.
#include "model/diagnostic.h"

#include <QDialog>

namespace regio::editor {

class DiagnosticsDialog : public QDialog {
    Q_OBJECT
public:
    DiagnosticsDialog(const QString& title, const QString& text, const model::Diagnostics& diagnostics,
                      QWidget* parent = nullptr);
};

} // namespace regio::editor
