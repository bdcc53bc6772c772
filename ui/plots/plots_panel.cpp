#include "plots/plots_panel.h"

#include "document/pin_set.h"
#include "document/scene_document.h"
#include "plots/flat_plot.h"
#include "plots/pinned_plots.h"
#include "plots/plot_context_menu.h"
#include "plots/plot_crosshair.h"

#include <QGridLayout>
#include <QPalette>

#include <cmath>
#include <qcustomplot.h>

namespace chaplygin::ui {

PlotsPanel::PlotsPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    m_grid = new QGridLayout(this);
    m_grid->setContentsMargins(2, 2, 2, 2);
    m_grid->setSpacing(2);
    for (int i = 0; i < 4; ++i) {
        auto* plot = new FlatPlot;
        plot->setObjectName(plotFileStem(kKinds[i]));
        plot->setMinimumSize(120, 110);
        plot->setToolTip(plotTitle(kKinds[i]) +
                         tr(" \u2014 click or drag to move the animation to that time"));
        plot->setNotAntialiasedElements(QCP::aeAll);
        m_cursors[i] = makeCursor(plot);
        makeSeekable(plot);
        m_grid->addWidget(plot, i / 2, i % 2);
        m_plots[i] = plot;
        plot->installEventFilter(this); // the legend follows the plot's width
        m_menus[i] = installPlotExportMenu(
            plot, [i] { return plotFileStem(kKinds[i]); },
            [this](const QString& error) { emit exportFailed(error); });
        m_fitAll[i] = installFitAllAction(plot, *m_menus[i]);
        new PlotCrosshair(plot); // hovering reads every curve at that time
    }
    m_errorPlot = new FlatPlot;
    m_errorPlot->setObjectName(plotFileStem(PlotKind::TrackingError));
    m_errorPlot->setMinimumSize(200, 130);
    m_errorPlot->setToolTip(plotTitle(PlotKind::TrackingError) +
                            tr(" \u2014 click or drag to move the animation to that time"));
    m_errorPlot->setNotAntialiasedElements(QCP::aeAll);
    m_errorPlot->hide();
    for (QWidget*& cursor : m_errorCursors)
        cursor = makeCursor(m_errorPlot);
    makeSeekable(m_errorPlot);
    new PlotCrosshair(m_errorPlot);
    arrange();
    installPlotExportMenu(
        m_errorPlot, [] { return plotFileStem(PlotKind::TrackingError); },
        [this](const QString& error) { emit exportFailed(error); });
    connect(document, &SceneDocument::solutionChanged, this, &PlotsPanel::refresh);
}

QWidget* PlotsPanel::makeCursor(QCustomPlot* plot) {
    // the time cursor is a thin child widget: moving it repaints two narrow strips, not the plot
    auto* cursor = new QWidget(plot);
    cursor->setAttribute(Qt::WA_TransparentForMouseEvents);
    cursor->setAutoFillBackground(true);
    QPalette palette = cursor->palette();
    palette.setColor(QPalette::Window, QColor(40, 160, 40));
    cursor->setPalette(palette);
    cursor->hide();
    connect(plot, &QCustomPlot::afterReplot, this, &PlotsPanel::placeCursors, Qt::UniqueConnection);
    return cursor;
}

void PlotsPanel::makeSeekable(QCustomPlot* plot) {
    // press seeks, dragging with the button down scrubs; the time of the panel under the mouse
    auto seek = [this, plot](QMouseEvent* e) {
        if (!(e->buttons() & Qt::LeftButton))
            return;
        for (QCPAxisRect* rect : plot->axisRects())
            if (e->position().x() >= rect->left() - 1 && e->position().x() <= rect->right() + 1)
                if (double t = rect->axis(QCPAxis::atBottom)->pixelToCoord(e->position().x());
                    std::isfinite(t)) {
                    if (m_plan)
                        emit planSeekRequested(t);
                    else
                        emit seekRequested(t);
                    return;
                }
    };
    connect(plot, &QCustomPlot::mousePress, this, seek);
    connect(plot, &QCustomPlot::mouseMove, this, seek);
}

void PlotsPanel::resizeEvent(QResizeEvent* e) {
    // a wide, low dock shows the four plots in a row, otherwise two by two
    int columns = width() > 3 * height() ? 4 : 2;
    if (columns != m_columns) {
        m_columns = columns;
        arrange();
    }
    QWidget::resizeEvent(e);
}

void PlotsPanel::arrange() {
    // the error plot takes two columns' width beside a row of four, or a row under two by two, so
    // that in a low dock every plot keeps the dock's height
    for (QWidget* w : {static_cast<QWidget*>(m_errorPlot), static_cast<QWidget*>(m_plots[0]),
                       static_cast<QWidget*>(m_plots[1]), static_cast<QWidget*>(m_plots[2]),
                       static_cast<QWidget*>(m_plots[3])})
        m_grid->removeWidget(w);
    for (int i = 0; i < 4; ++i)
        m_grid->addWidget(m_plots[i], i / m_columns, i % m_columns);
    const bool wide = m_columns == 4;
    if (wide)
        m_grid->addWidget(m_errorPlot, 0, 4);
    else
        m_grid->addWidget(m_errorPlot, 2, 0, 1, 2);
    for (int c = 0; c < 5; ++c) // the error plot's two panels as wide as two plots
        m_grid->setColumnStretch(c, c < m_columns ? 1 : c == 4 && wide && m_errorsShown ? 2 : 0);
    for (int r = 0; r < 3; ++r)
        m_grid->setRowStretch(r, r == 0 || (!wide && (r == 1 || m_errorsShown)) ? 1 : 0);
}

bool PlotsPanel::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Resize)
        for (QCustomPlot* plot : m_plots)
            if (plot == watched) {
                fitLegendToWidth(*plot);
                plot->replot(QCustomPlot::rpQueuedReplot);
            }
    return QWidget::eventFilter(watched, event);
}

void PlotsPanel::refresh() {
    for (int i = 0; i < 4; ++i) {
        drawPlot(*m_plots[i], kKinds[i], m_plan ? *m_plan : m_document->series());
        if (!m_plan) // the pinned runs are the scene's
            addPinnedSeries(*m_plots[i], kKinds[i], *m_document->pins());
        fitLegendToWidth(*m_plots[i]);
        m_plots[i]->replot(QCustomPlot::rpQueuedReplot);
    }
    const bool perturbed = !m_plan && m_document->series().perturbed;
    m_errorPlot->setVisible(perturbed);
    if (perturbed != m_errorsShown) {
        m_errorsShown = perturbed;
        arrange();
    }
    if (perturbed) {
        drawPlot(*m_errorPlot, PlotKind::TrackingError, m_document->series());
        m_errorPlot->replot(QCustomPlot::rpQueuedReplot);
    }
}

void PlotsPanel::placeCursor(QCustomPlot* plot, int rectIndex, QWidget* cursor) {
    if (plot->axisRectCount() <= rectIndex) {
        cursor->hide();
        return;
    }
    QCPAxisRect* rect = plot->axisRect(rectIndex);
    QCPAxis* axis = rect->axis(QCPAxis::atBottom);
    const double t = cursorTime();
    double x = axis->coordToPixel(t);
    bool inside = t >= 0 && axis->range().contains(t) && rect->height() > 0;
    cursor->setGeometry(int(std::lround(x)) - 1, rect->top(), 2, rect->height());
    cursor->setVisible(inside);
}

void PlotsPanel::placeCursors() {
    for (int i = 0; i < 4; ++i)
        placeCursor(m_plots[i], 0, m_cursors[i]);
    for (int i = 0; i < 2; ++i)
        placeCursor(m_errorPlot, i, m_errorCursors[i]);
}

void PlotsPanel::setTime(double t) {
    m_time = t;
    placeCursors();
}

void PlotsPanel::showPlan(const PlotSeries& series) {
    m_plan = series;
    refresh();
}

void PlotsPanel::setPlanTime(double t) {
    m_planTime = t;
    placeCursors();
}

void PlotsPanel::showScene() {
    if (!m_plan)
        return;
    m_plan.reset();
    m_planTime = -1;
    refresh();
    placeCursors();
}

void PlotsPanel::setLook(const CanvasStyle& look) {
    for (QCustomPlot* plot : m_plots)
        setPlotLook(*plot, look);
    setPlotLook(*m_errorPlot, look);
    refresh();
}

void PlotsPanel::replotNow() {
    for (QCustomPlot* plot : m_plots)
        plot->replot(QCustomPlot::rpImmediateRefresh);
    if (m_errorPlot->isVisible())
        m_errorPlot->replot(QCustomPlot::rpImmediateRefresh);
}

} // namespace chaplygin::ui
