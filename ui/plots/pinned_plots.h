#pragma once
#include "plots/plot_figures.h"

class QCustomPlot;

namespace chaplygin::ui {

class PinSet;

/// Adds the pinned runs' series to a time plot drawn by drawPlot: faint lines in each pin's
/// colour, named by what differs ("b = 0.5 m") in the plot's legend; being controlled runs,
/// they set the value range with the controlled body (fitTimeAxes).
void addPinnedSeries(QCustomPlot& plot, PlotKind kind, PinSet& pins);

} // namespace chaplygin::ui
