#include "plots/plots_panel.h"

#include "document/pin_set.h"
#include "document/scene_document.h"
#include "plots/flat_plot.h"
#include "plots/pinned_plots.h"
#include "plots/plot_context_menu.h"

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
        plot->setMinimumSize(200, 110);
        plot->setToolTip(plotTitle(kKinds[i]) +
                         tr(" \u2014 click or drag to move the animation to that time"));
        plot->setNotAntialiasedElements(QCP::aeAll);
        // the time cursor is a thin child widget: moving it repaints two narrow strips, not the
        // plot
        auto* cursor = new QWidget(plot);
        cursor->setAttribute(Qt::WA_TransparentForMouseEvents);
        cursor->setAutoFillBackground(true);
        QPalette palette = cursor->palette();
        palette.setColor(QPalette::Window, QColor(40, 160, 40));
        cursor->setPalette(palette);
        cursor->hide();
        m_cursors[i] = cursor;
        connect(plot, &QCustomPlot::afterReplot, this, [this, i] { placeCursor(i); });
        // press seeks, dragging with the button down scrubs
        auto seek = [this, plot](QMouseEvent* e) {
            QCPAxisRect* rect = plot->axisRectCount() > 0 ? plot->axisRect() : nullptr;
            if (rect && (e->buttons() & Qt::LeftButton))
                if (double t = rect->axis(QCPAxis::atBottom)->pixelToCoord(e->position().x());
                    std::isfinite(t))
                    emit seekRequested(t);
        };
        connect(plot, &QCustomPlot::mousePress, this, seek);
        connect(plot, &QCustomPlot::mouseMove, this, seek);
        m_grid->addWidget(plot, i / 2, i % 2);
        m_plots[i] = plot;
        plot->installEventFilter(this); // the legend follows the plot's width
        installPlotExportMenu(
            plot, [i] { return plotFileStem(kKinds[i]); },
            [this](const QString& error) { emit exportFailed(error); });
    }
    m_errorPlot = new FlatPlot;
    m_errorPlot->setObjectName(plotFileStem(PlotKind::TrackingError));
    m_errorPlot->setMinimumSize(200, 110);
    m_errorPlot->setToolTip(plotTitle(PlotKind::TrackingError));
    m_errorPlot->setNotAntialiasedElements(QCP::aeAll);
    m_errorPlot->hide();
    connect(m_errorPlot, &QCustomPlot::mousePress, this, [this](QMouseEvent* e) {
        QCPAxisRect* rect = m_errorPlot->axisRectCount() > 0 ? m_errorPlot->axisRect() : nullptr;
        if (rect && (e->buttons() & Qt::LeftButton))
            if (double t = rect->axis(QCPAxis::atBottom)->pixelToCoord(e->position().x());
                std::isfinite(t))
                emit seekRequested(t);
    });
    m_grid->addWidget(m_errorPlot, 4, 0, 1, -1);
    installPlotExportMenu(
        m_errorPlot, [] { return plotFileStem(PlotKind::TrackingError); },
        [this](const QString& error) { emit exportFailed(error); });
    connect(document, &SceneDocument::solutionChanged, this, &PlotsPanel::refresh);
}

void PlotsPanel::resizeEvent(QResizeEvent* e) {
    // a wide, low dock shows the four plots in a row, otherwise two by two
    int columns = width() > 3 * height() ? 4 : 2;
    if (columns != m_columns) {
        m_columns = columns;
        for (int i = 0; i < 4; ++i) {
            m_grid->removeWidget(m_plots[i]);
            m_grid->addWidget(m_plots[i], i / columns, i % columns);
        }
    }
    QWidget::resizeEvent(e);
}

bool PlotsPanel::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Resize)
        for (QCustomPlot* plot : m_plots)
            if (plot == watched) {
                fitLegendToWidth(*plot);
                fitTicksToHeight(*plot);
                plot->replot(QCustomPlot::rpQueuedReplot);
            }
    return QWidget::eventFilter(watched, event);
}

void PlotsPanel::refresh() {
    for (int i = 0; i < 4; ++i) {
        drawPlot(*m_plots[i], kKinds[i], m_document->series());
        addPinnedSeries(*m_plots[i], kKinds[i], *PinSet::of(m_document));
        fitLegendToWidth(*m_plots[i]);
        fitTicksToHeight(*m_plots[i]);
        m_plots[i]->replot(QCustomPlot::rpQueuedReplot);
    }
    const bool perturbed = m_document->series().perturbed;
    m_errorPlot->setVisible(perturbed);
    if (perturbed) {
        drawPlot(*m_errorPlot, PlotKind::TrackingError, m_document->series());
        fitTicksToHeight(*m_errorPlot);
        m_errorPlot->replot(QCustomPlot::rpQueuedReplot);
    }
}

void PlotsPanel::placeCursor(int index) {
    QCustomPlot* plot = m_plots[index];
    QWidget* cursor = m_cursors[index];
    if (plot->axisRectCount() == 0) {
        cursor->hide();
        return;
    }
    QCPAxisRect* rect = plot->axisRect();
    QCPAxis* axis = rect->axis(QCPAxis::atBottom);
    double x = axis->coordToPixel(m_time);
    bool inside = axis->range().contains(m_time) && rect->height() > 0;
    cursor->setGeometry(int(std::lround(x)) - 1, rect->top(), 2, rect->height());
    cursor->setVisible(inside);
}

void PlotsPanel::setTime(double t) {
    m_time = t;
    for (int i = 0; i < 4; ++i)
        placeCursor(i);
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
