#include "plots/plots_panel.h"

#include "document/pin_set.h"
#include "document/scene_document.h"
#include "plots/flat_plot.h"
#include "plots/pinned_plots.h"
#include "plots/plot_context_menu.h"
#include "plots/plot_crosshair.h"
#include "plots/time_axes.h"

#include <QAction>
#include <QApplication>
#include <QGridLayout>
#include <QMenu>
#include <QPalette>
#include <QTimer>

#include <cmath>
#include <qcustomplot.h>

namespace chaplygin::ui {

PlotsPanel::PlotsPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    m_grid = new QGridLayout(this);
    m_grid->setContentsMargins(2, 2, 2, 2);
    m_grid->setSpacing(2);
    makeTimeActions();
    for (int i = 0; i < 4; ++i) {
        auto* plot = new FlatPlot;
        plot->setObjectName(plotFileStem(kKinds[i]));
        plot->setMinimumSize(120, 110);
        plot->setToolTip(plotTitle(kKinds[i]) + tr(" \u2014 click or drag to move the animation "
                                                   "to that time; wheel: zoom the time, Shift+drag "
                                                   "or middle drag: pan it, double click: the "
                                                   "whole run"));
        plot->setNotAntialiasedElements(QCP::aeAll);
        m_cursors[i] = makeCursor(plot);
        makeSeekable(plot);
        makeTimeZoomable(plot);
        m_grid->addWidget(plot, i / 2, i % 2);
        m_plots[i] = plot;
        plot->installEventFilter(this); // the legend follows the plot's width
        m_menus[i] = installPlotExportMenu(
            plot, [i] { return plotFileStem(kKinds[i]); },
            [this](const QString& error) { emit exportFailed(error); });
        m_fitAll[i] = installFitAllAction(plot, *m_menus[i]);
        addTimeActions(*m_menus[i]);
        new PlotCrosshair(plot); // hovering reads every curve at that time
    }
    m_errorPlot = new FlatPlot;
    m_errorPlot->setObjectName(plotFileStem(PlotKind::TrackingError));
    m_errorPlot->setMinimumSize(200, 130);
    m_errorPlot->setToolTip(plotTitle(PlotKind::TrackingError) +
                            tr(" \u2014 click or drag to move the animation to that time; wheel: "
                               "zoom the time, Shift+drag or middle drag: pan it, double click: "
                               "the whole run"));
    m_errorPlot->setNotAntialiasedElements(QCP::aeAll);
    m_errorPlot->hide();
    for (QWidget*& cursor : m_errorCursors)
        cursor = makeCursor(m_errorPlot);
    makeSeekable(m_errorPlot);
    makeTimeZoomable(m_errorPlot);
    new PlotCrosshair(m_errorPlot);
    arrange();
    addTimeActions(*installPlotExportMenu(
        m_errorPlot, [] { return plotFileStem(PlotKind::TrackingError); },
        [this](const QString& error) { emit exportFailed(error); }));
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
    if (!m_clickSeek) {
        m_clickSeek = new QTimer(this);
        m_clickSeek->setSingleShot(true);
        connect(m_clickSeek, &QTimer::timeout, this,
                [this] { emitSeek(m_pendingSeek.t, m_pendingSeek.plan); });
    }
    // a press seeks once no second press made it a double click; dragging with the button
    // down scrubs at once; the time of the panel under the mouse
    auto seek = [this, plot](QMouseEvent* e) {
        if (!(e->buttons() & Qt::LeftButton) || (e->modifiers() & Qt::ShiftModifier) ||
            m_timePan.active)
            return;
        const bool press = e->type() == QEvent::MouseButtonPress;
        if (press) {
            m_pendingSeek.pressedAt = e->position();
            m_pendingSeek.dragging = false;
        } else if (!m_pendingSeek.dragging) {
            const QPointF moved = e->position() - m_pendingSeek.pressedAt;
            if (moved.manhattanLength() < QApplication::startDragDistance())
                return;
            m_pendingSeek.dragging = true;
        }
        for (QCPAxisRect* rect : plot->axisRects())
            if (e->position().x() >= rect->left() - 1 && e->position().x() <= rect->right() + 1)
                if (double t = rect->axis(QCPAxis::atBottom)->pixelToCoord(e->position().x());
                    std::isfinite(t)) {
                    if (press) {
                        m_pendingSeek.t = t;
                        m_pendingSeek.plan = m_plan.has_value();
                        m_clickSeek->start(QApplication::doubleClickInterval());
                    } else {
                        m_clickSeek->stop();
                        emitSeek(t, m_plan.has_value());
                    }
                    return;
                }
    };
    connect(plot, &QCustomPlot::mousePress, this, seek);
    connect(plot, &QCustomPlot::mouseMove, this, seek);
    // the double click's presses do not seek
    connect(plot, &QCustomPlot::mouseDoubleClick, m_clickSeek, &QTimer::stop);
}

void PlotsPanel::emitSeek(double t, bool plan) {
    if (plan && m_plan)
        emit planSeekRequested(t);
    else if (!plan)
        emit seekRequested(t);
}

bool PlotsPanel::seekPending() const {
    return m_clickSeek && m_clickSeek->isActive();
}

namespace {

// the axis rectangle of plot at (or nearest to) pixel column x
QCPAxisRect* rectAt(QCustomPlot* plot, double x) {
    QCPAxisRect* nearest = nullptr;
    double best = INFINITY;
    for (QCPAxisRect* rect : plot->axisRects()) {
        const double d = x < rect->left()    ? rect->left() - x
                         : x > rect->right() ? x - rect->right()
                                             : 0;
        if (d < best) {
            best = d;
            nearest = rect;
        }
    }
    return nearest && nearest->width() > 0 ? nearest : nullptr;
}

} // namespace

void PlotsPanel::makeTimeZoomable(QCustomPlot* plot) {
    connect(plot, &QCustomPlot::mouseWheel, this, [this, plot](QWheelEvent* e) {
        QCPAxisRect* rect = rectAt(plot, e->position().x());
        if (!rect || e->angleDelta().y() == 0)
            return;
        // about the time under the mouse; following, about the time cursor, which stays put
        const double at = m_timeWindow.mode() == TimeWindow::Mode::Following
                              ? cursorTime()
                              : rect->axis(QCPAxis::atBottom)->pixelToCoord(e->position().x());
        m_timeWindow.wheel(at, e->angleDelta().y());
        m_timeWindow.followCursor(cursorTime());
        showTimeWindow();
        e->accept();
    });
    // a middle or a Shift drag pans the time; the left button alone seeks (makeSeekable)
    connect(plot, &QCustomPlot::mousePress, this, [this, plot](QMouseEvent* e) {
        const bool pan = e->button() == Qt::MiddleButton ||
                         (e->button() == Qt::LeftButton && (e->modifiers() & Qt::ShiftModifier));
        QCPAxisRect* rect = rectAt(plot, e->position().x());
        if (!pan || !rect)
            return;
        const QCPRange shown = rect->axis(QCPAxis::atBottom)->range();
        m_timePan = {true, e->position().x(), shown, shown.size() / rect->width()};
        plot->setCursor(Qt::ClosedHandCursor);
    });
    connect(plot, &QCustomPlot::mouseMove, this, [this](QMouseEvent* e) {
        // the whole run has nowhere to move
        if (!m_timePan.active || m_timeWindow.mode() == TimeWindow::Mode::WholeRun)
            return;
        m_timeWindow.pan(m_timePan.from,
                         -(e->position().x() - m_timePan.startX) * m_timePan.secondsPerPixel);
        showTimeWindow();
    });
    connect(plot, &QCustomPlot::mouseRelease, this, [this, plot](QMouseEvent*) {
        if (m_timePan.active)
            plot->unsetCursor();
        m_timePan.active = false;
    });
    connect(plot, &QCustomPlot::mouseDoubleClick, this, [this](QMouseEvent* e) {
        if (e->button() == Qt::LeftButton && !(e->modifiers() & Qt::ShiftModifier))
            m_wholeRun->trigger();
    });
}

void PlotsPanel::makeTimeActions() {
    m_followCursor = new QAction(tr("&Follow the cursor"), this);
    m_followCursor->setObjectName(QStringLiteral("followTimeCursor"));
    m_followCursor->setCheckable(true);
    m_followCursor->setToolTip(tr("The time plots show a window of the run that moves on with the "
                                  "time cursor"));
    connect(m_followCursor, &QAction::toggled, this, [this](bool on) {
        m_timeWindow.setFollowing(on, cursorTime());
        showTimeWindow();
    });
    m_wholeRun = new QAction(tr("&Whole run"), this);
    m_wholeRun->setObjectName(QStringLiteral("wholeRunTime"));
    m_wholeRun->setToolTip(tr("The time plots show the whole run (a double click on a plot)"));
    connect(m_wholeRun, &QAction::triggered, this, [this] {
        m_timeWindow.showWholeRun();
        showTimeWindow();
    });
    m_zoomInTime = new QAction(tr("Zoom &in on the time"), this);
    m_zoomInTime->setObjectName(QStringLiteral("zoomInTime"));
    connect(m_zoomInTime, &QAction::triggered, this, [this] { zoomTimeAboutCursor(kWheelZoom); });
    m_zoomOutTime = new QAction(tr("Zoom &out the time"), this);
    m_zoomOutTime->setObjectName(QStringLiteral("zoomOutTime"));
    connect(m_zoomOutTime, &QAction::triggered, this,
            [this] { zoomTimeAboutCursor(1 / kWheelZoom); });
}

void PlotsPanel::addTimeActions(QMenu& menu) {
    menu.addSeparator();
    menu.addAction(m_followCursor);
    menu.addAction(m_wholeRun);
    menu.addAction(m_zoomInTime);
    menu.addAction(m_zoomOutTime);
}

void PlotsPanel::zoomTimeAboutCursor(double factor) {
    // about the time cursor where it is shown, else about the middle of the time shown
    const QCPRange shown = m_timeWindow.range();
    const double t = cursorTime();
    m_timeWindow.zoomAbout(shown.contains(t) ? t : shown.center(), factor);
    showTimeWindow();
}

QList<QCPAxisRect*> PlotsPanel::timeRects() const {
    QList<QCPAxisRect*> rects;
    for (QCustomPlot* plot : m_plots)
        rects << plot->axisRects();
    if (m_errorsShown)
        rects << m_errorPlot->axisRects();
    return rects;
}

void PlotsPanel::measureRun() {
    // the union of the whole-run time axes; the sample interval of the first curve
    double lo = INFINITY, hi = -INFINITY;
    for (QCPAxisRect* rect : timeRects()) {
        const QCPRange r = rect->axis(QCPAxis::atBottom)->range();
        lo = std::min(lo, r.lower);
        hi = std::max(hi, r.upper);
    }
    double interval = NAN;
    if (m_plots[0]->graphCount() > 0 && m_plots[0]->graph(0)->dataCount() > 1) {
        const auto data = m_plots[0]->graph(0)->data();
        interval = (data->constEnd() - 1)->key - data->constBegin()->key;
        interval /= data->size() - 1;
    }
    m_timeWindow.setRun(QCPRange(lo, hi), interval);
}

void PlotsPanel::showTimeWindow() {
    {
        const QSignalBlocker quiet(m_followCursor);
        m_followCursor->setChecked(m_timeWindow.mode() == TimeWindow::Mode::Following);
    }
    if (m_timeWindow.mode() == TimeWindow::Mode::WholeRun) {
        refresh(); // drawn afresh: the whole run exactly as before any zoom
        return;
    }
    const QCPRange shown = m_timeWindow.range();
    for (QCPAxisRect* rect : timeRects())
        fitTimeAxes(*rect, shown);
    for (QCustomPlot* plot : m_plots)
        plot->replot(QCustomPlot::rpQueuedReplot);
    if (m_errorsShown)
        m_errorPlot->replot(QCustomPlot::rpQueuedReplot);
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
    // the time shown is kept, within the new run
    measureRun();
    if (m_timeWindow.mode() != TimeWindow::Mode::WholeRun) {
        m_timeWindow.followCursor(cursorTime());
        showTimeWindow();
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
    if (m_timeWindow.followCursor(cursorTime()))
        showTimeWindow();
    placeCursors();
}

void PlotsPanel::showPlan(const PlotSeries& series) {
    m_plan = series;
    refresh();
}

void PlotsPanel::setPlanTime(double t) {
    m_planTime = t;
    if (m_timeWindow.followCursor(cursorTime()))
        showTimeWindow();
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
