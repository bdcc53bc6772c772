#pragma once
#include "plots/plot_series.h"

#include <QString>

class QCustomPlot;

namespace chaplygin::ui {

enum class PlotKind { Psi, Chi, Lambda, Energy, Trajectory, PaperFigure };

/// File stem and title of each plot.
QString plotFileStem(PlotKind kind);
QString plotTitle(PlotKind kind);

/// Fills a QCustomPlot with one plot: axes with units, legend, the controlled motion and the
/// free motion where it means something. PaperFigure is the paper's 2x2 layout of Figs. 2 and 3:
/// s(t), x(t), y(t) and y(x) with the prescribed path.
void drawPlot(QCustomPlot& plot, PlotKind kind, const PlotSeries& series);

/// Adds the caption line above the plot(s).
void addCaption(QCustomPlot& plot, const QString& caption);

} // namespace chaplygin::ui
