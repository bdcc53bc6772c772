#include "plots/plot_crosshair.h"

#include <QEvent>
#include <QLabel>
#include <QMouseEvent>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace chaplygin::ui {

namespace {

// the graph's value at key t, linear between its samples; nothing outside them or across a gap
std::optional<double> valueAt(const QCPGraph& graph, double t) {
    const auto& data = *graph.data();
    if (data.isEmpty())
        return {};
    auto after = data.findBegin(t, false);
    if (after == data.constEnd() || after->key < t)
        return {};
    if (after->key == t)
        return std::isfinite(after->value) ? std::optional(after->value) : std::nullopt;
    if (after == data.constBegin())
        return {};
    const auto before = after - 1;
    const double u = (t - before->key) / (after->key - before->key);
    const double v = before->value + u * (after->value - before->value);
    return std::isfinite(v) ? std::optional(v) : std::nullopt;
}

} // namespace

PlotCrosshair::PlotCrosshair(QCustomPlot* plot)
    : QObject(plot), m_plot(plot), m_line(new QWidget(plot)), m_readout(new QLabel(plot)) {
    m_line->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_line->setAutoFillBackground(true);
    QPalette palette = m_line->palette();
    palette.setColor(QPalette::Window, QColor(60, 60, 60));
    m_line->setPalette(palette);
    m_line->hide();
    m_readout->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_readout->setObjectName(QStringLiteral("plotCrosshairReadout"));
    m_readout->setTextFormat(Qt::RichText);
    m_readout->setStyleSheet(QStringLiteral(
        "QLabel { background: rgba(255, 255, 255, 225); color: black; padding: 3px; }"));
    m_readout->hide();
    plot->setMouseTracking(true);
    plot->installEventFilter(this);
}

bool PlotCrosshair::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_plot) {
        if (event->type() == QEvent::MouseMove)
            hoverAt(static_cast<QMouseEvent*>(event)->position());
        else if (event->type() == QEvent::Leave)
            hide();
    }
    return QObject::eventFilter(watched, event);
}

void PlotCrosshair::hide() {
    m_time.reset();
    m_values.clear();
    m_line->hide();
    m_readout->hide();
}

void PlotCrosshair::hoverAt(QPointF pixel) {
    QCPAxisRect* rect = m_plot->axisRectAt(pixel);
    if (!rect || !rect->rect().contains(pixel.toPoint())) {
        hide();
        return;
    }
    QCPAxis* axis = rect->axis(QCPAxis::atBottom);
    const double t = axis->pixelToCoord(pixel.x());
    m_time = t;
    m_values.clear();
    QStringList lines{tr("t = %1 s").arg(QString::number(t, 'g', 4))};
    for (int i = 0; i < m_plot->graphCount(); ++i) {
        const QCPGraph& graph = *m_plot->graph(i);
        if (!graph.visible() || graph.name().isEmpty() || graph.keyAxis() != axis)
            continue;
        const std::optional<double> v = valueAt(graph, t);
        if (!v)
            continue;
        m_values.push_back({graph.name(), *v});
        lines << QStringLiteral("<span style=\"color:%1\">\u25a0</span> %2 = %3")
                     .arg(graph.pen().color().name(), graph.name().toHtmlEscaped(),
                          QString::number(*v, 'g', 5));
    }
    // in the axes' type, which presentation mode enlarges
    m_readout->setFont(axis->tickLabelFont());
    m_readout->setText(lines.join(QStringLiteral("<br>")));
    m_readout->adjustSize();
    const int x = int(std::lround(pixel.x()));
    m_line->setGeometry(x, rect->top(), 1, rect->height());
    m_line->show();
    m_line->raise();
    // beside the line, on the side with room, inside the axes
    const QSize size = m_readout->size();
    int left = x + 8;
    if (left + size.width() > rect->right())
        left = x - 8 - size.width();
    left = std::max(left, 0);
    const int top = std::clamp(int(std::lround(pixel.y())) - size.height() / 2, rect->top(),
                               std::max(rect->bottom() - size.height(), rect->top()));
    m_readout->move(left, top);
    m_readout->show();
    m_readout->raise();
}

} // namespace chaplygin::ui
