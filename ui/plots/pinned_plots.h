#pragma once
#include "document/plot_series.h"
#include "plots/plot_figures.h"

#include <QList>

class QCustomPlot;

namespace chaplygin::ui {

class PinSet;

/// Adds the pinned runs' series to a time plot drawn by drawPlot: faint lines in each pin's
/// colour, named by what differs ("b = 0.5 m") in the plot's legend; being controlled runs,
/// they set the value range with the controlled body (fitTimeAxes). exact: the runs' series
/// sampled evenly in t, one per pin, for an exported figure (else the path table's nodes that
/// the live plots draw).
void addPinnedSeries(QCustomPlot& plot, PlotKind kind, PinSet& pins,
                     const QList<PlotSeries>* exact = nullptr);

} // namespace chaplygin::ui
