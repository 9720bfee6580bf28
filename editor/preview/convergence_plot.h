#pragma once
// The convergence plot: per iteration, the unshot power,
// what was absorbed and what escaped, and the error of the energy books
// (emitted - absorbed - unshot - escaped), all as fractions of the emitted
// power on a logarithmic axis (QtCharts).
#include "editor/preview/preview_session.h"

#include <QDockWidget>

#include <vector>

class QChart;
class QChartView;
class QLineSeries;
class QLogValueAxis;
class QValueAxis;

namespace regio::editor {

class ConvergenceDock : public QDockWidget {
    Q_OBJECT
public:
    explicit ConvergenceDock(QWidget* parent = nullptr);
    void setHistory(const std::vector<ConvergencePoint>& history);
    int pointCount() const { return m_points; }

private:
    QChart* m_chart = nullptr;
    QLineSeries* m_unshot = nullptr;
    QLineSeries* m_absorbed = nullptr;
    QLineSeries* m_escaped = nullptr;
    QLineSeries* m_balance = nullptr;
    QValueAxis* m_x = nullptr;
    QLogValueAxis* m_y = nullptr;
    int m_points = 0;
};

} // namespace regio::editor
