#include "editor/preview/convergence_plot.h"

#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QValueAxis>

#include <algorithm>

namespace regio::editor {

namespace {

// A log axis cannot show 0: exact books (balance error 0) sit at the floor.
constexpr double kFloor = 1e-16;

} // namespace

ConvergenceDock::ConvergenceDock(QWidget* parent)
    : QDockWidget(tr("Convergence"), parent)
{
    setObjectName(QStringLiteral("ConvergenceDock"));
    m_chart = new QChart;
    m_chart->legend()->setAlignment(Qt::AlignBottom);
    m_chart->setMargins(QMargins(2, 2, 2, 2));
    auto series = [this](const QString& name) {
        auto* s = new QLineSeries;
        s->setName(name);
        m_chart->addSeries(s);
        return s;
    };
    m_unshot = series(tr("unshot"));
    m_absorbed = series(tr("absorbed"));
    m_escaped = series(tr("escaped"));
    m_balance = series(tr("balance error"));
    m_x = new QValueAxis;
    m_x->setTitleText(tr("iteration"));
    m_x->setLabelFormat(QStringLiteral("%d"));
    m_x->setRange(0, 1);
    m_y = new QLogValueAxis;
    m_y->setTitleText(tr("fraction of emitted power"));
    m_y->setLabelFormat(QStringLiteral("%.0e"));
    m_y->setRange(1e-6, 1.0);
    m_chart->addAxis(m_x, Qt::AlignBottom);
    m_chart->addAxis(m_y, Qt::AlignLeft);
    for (QLineSeries* s : {m_unshot, m_absorbed, m_escaped, m_balance}) {
        s->attachAxis(m_x);
        s->attachAxis(m_y);
    }
    auto* view = new QChartView(m_chart);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumSize(240, 180);
    setWidget(view);
}

void ConvergenceDock::setHistory(const std::vector<ConvergencePoint>& history)
{
    // Thousands of points are more than a dock's pixels: thin them evenly.
    const size_t stride = std::max<size_t>(1, history.size() / 2000);
    QList<QPointF> unshot, absorbed, escaped, balance;
    double lowest = 1.0;
    for (size_t i = 0; i < history.size(); i += stride) {
        const ConvergencePoint& p = history[i];
        const double x = p.iteration;
        unshot << QPointF(x, std::max(p.unshot, kFloor));
        absorbed << QPointF(x, std::max(p.absorbed, kFloor));
        escaped << QPointF(x, std::max(p.escaped, kFloor));
        balance << QPointF(x, std::max(p.balanceError, kFloor));
        lowest = std::min({lowest, std::max(p.unshot, kFloor), std::max(p.balanceError, kFloor)});
        if (p.escaped > 0.0)
            lowest = std::min(lowest, p.escaped);
    }
    m_unshot->replace(unshot);
    m_absorbed->replace(absorbed);
    m_escaped->replace(escaped);
    m_balance->replace(balance);
    m_points = int(history.size());
    m_x->setRange(0, std::max(1, history.empty() ? 1 : history.back().iteration));
    m_y->setRange(std::max(kFloor, lowest / 2.0), 1.5);
}

} // namespace regio::editor
