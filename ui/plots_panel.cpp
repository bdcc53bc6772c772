#include "plots_panel.h"

#include "scene_document.h"

#include <QGridLayout>
#include <qcustomplot.h>

namespace chaplygin::ui {

namespace {
const QString kCursorLayer = QStringLiteral("cursor");
}

PlotsPanel::PlotsPanel(SceneDocument* document, QWidget* parent) : QWidget(parent), m_document(document) {
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(2, 2, 2, 2);
    grid->setSpacing(2);
    for (int i = 0; i < 4; ++i) {
        auto* plot = new QCustomPlot;
        plot->setObjectName(plotFileStem(kKinds[i]));
        plot->setMinimumSize(220, 150);
        plot->setToolTip(plotTitle(kKinds[i]) + tr(" \u2014 click to seek the animation to that time"));
        plot->setNotAntialiasedElements(QCP::aeAll);
        plot->addLayer(kCursorLayer, plot->layer(QStringLiteral("main")), QCustomPlot::limAbove);
        plot->layer(kCursorLayer)->setMode(QCPLayer::lmBuffered);
        connect(plot, &QCustomPlot::mousePress, this, [this, plot](QMouseEvent* e) {
            QCPAxisRect* rect = plot->axisRectCount() > 0 ? plot->axisRect() : nullptr;
            if (rect && e->button() == Qt::LeftButton)
                emit seekRequested(rect->axis(QCPAxis::atBottom)->pixelToCoord(e->position().x()));
        });
        grid->addWidget(plot, i / 2, i % 2);
        m_plots[i] = plot;
    }
    connect(document, &SceneDocument::solutionChanged, this, &PlotsPanel::refresh);
}

void PlotsPanel::refresh() {
    for (int i = 0; i < 4; ++i) {
        drawPlot(*m_plots[i], kKinds[i], m_document->series());
        m_cursors[i] = nullptr;
        placeCursor(i);
        m_plots[i]->replot(QCustomPlot::rpQueuedReplot);
    }
}

void PlotsPanel::placeCursor(int index) {
    QCustomPlot* plot = m_plots[index];
    if (plot->axisRectCount() == 0)
        return;
    QCPAxisRect* rect = plot->axisRect();
    if (!m_cursors[index]) {
        auto* line = new QCPItemStraightLine(plot);
        line->setLayer(kCursorLayer);
        line->setPen(QPen(QColor(40, 160, 40), 1));
        line->setClipAxisRect(rect);
        for (QCPItemPosition* p : {line->point1, line->point2}) {
            p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
            p->setAxisRect(rect);
        }
        m_cursors[index] = line;
    }
    m_cursors[index]->point1->setCoords(m_time, 0);
    m_cursors[index]->point2->setCoords(m_time, 1);
}

void PlotsPanel::setTime(double t) {
    m_time = t;
    for (int i = 0; i < 4; ++i) {
        placeCursor(i);
        m_plots[i]->layer(kCursorLayer)->replot();
    }
}

void PlotsPanel::replotNow() {
    for (QCustomPlot* plot : m_plots)
        plot->replot(QCustomPlot::rpImmediateRefresh);
}

} // namespace chaplygin::ui
