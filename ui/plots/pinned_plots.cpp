#include "plots/pinned_plots.h"

#include "document/pin_set.h"
#include "plots/plot_figures.h"
#include "plots/time_axes.h"

#include <qcustomplot.h>

namespace chaplygin::ui {

namespace {

const QVector<double>* valuesOf(const PlotSeries& s, PlotKind kind) {
    switch (kind) {
    case PlotKind::Psi:
        return &s.psi;
    case PlotKind::Chi:
        return &s.chi;
    case PlotKind::Lambda:
        return &s.lambda;
    case PlotKind::Energy:
        return &s.energy;
    default:
        return nullptr;
    }
}

QCPLegend* legendOf(QCustomPlot& plot, QCPAxisRect* rect) {
    // drawPlot puts the legend in the row under a lone plot, or inside the axis rect
    for (int i = 0; i < plot.plotLayout()->elementCount(); ++i)
        if (auto* l = qobject_cast<QCPLegend*>(plot.plotLayout()->elementAt(i)))
            return l;
    for (int i = 0; i < rect->insetLayout()->elementCount(); ++i)
        if (auto* l = qobject_cast<QCPLegend*>(rect->insetLayout()->elementAt(i)))
            return l;
    return nullptr;
}

} // namespace

void addPinnedSeries(QCustomPlot& plot, PlotKind kind, PinSet& pins,
                     const QList<PlotSeries>* exact) {
    if (plot.axisRectCount() == 0 || pins.count() == 0)
        return;
    QCPAxisRect* rect = plot.axisRect();
    QCPLegend* legend = legendOf(plot, rect);
    for (int i = 0; i < pins.count(); ++i) {
        const PinSet::Run& run = pins.run(i);
        const PlotSeries& series = exact && i < exact->size() ? (*exact)[i] : run.series;
        const QVector<double>* values = valuesOf(series, kind);
        if (!run.solution || !values)
            continue;
        QCPGraph* g = plot.addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        g->setData(series.t, *values, true);
        g->setName(pins.label(i)); // the canvas's key says "pin N: " before the same label
        QColor c = PinSet::color(i);
        c.setAlpha(170);
        g->setPen(QPen(c, 1.5));
        setControlled(*g); // a controlled run: it sets the value range too
        if (legend)
            g->addToLegend(legend);
    }
    fitTimeAxes(*rect);
    // the legend under a plot wraps into rows of three so that every name stays readable
    if (legend && legend->fillOrder() == QCPLegend::foColumnsFirst) {
        legend->setProperty("maxColumns", 3);
        fitLegendToWidth(plot);
    }
}

} // namespace chaplygin::ui
