#pragma once
#include "canvas/canvas_style.h"
#include "document/plot_series.h"

#include <QString>

class QCPAxisRect;
class QCPRange;
class QCustomPlot;
class QRectF;

namespace chaplygin::ui {

/// TrackingError: the perturbed bodies' lateral and heading errors (docs/physics.md §9), drawn
/// only for a scene with a perturbation.
enum class PlotKind { Psi, Chi, Lambda, Energy, Trajectory, PaperFigure, TrackingError };

/// File stem and title of each plot.
QString plotFileStem(PlotKind kind);
QString plotTitle(PlotKind kind);

/// Fills a QCustomPlot with one plot: axes with units, legend, the controlled motion and the
/// free motion where it means something. A time plot's value axis follows the controlled body
/// (fitTimeAxes); every axis gets a PixelTicker (installTickers). PaperFigure is the paper's 2x2
/// layout of Figs. 2 and 3: s(t), x(t), y(t) and y(x) with the prescribed path.
void drawPlot(QCustomPlot& plot, PlotKind kind, const PlotSeries& series);

/// The axis range drawn for data in [lower, upper]: 5 % margins; a series flat to rounding
/// (relative spread <= 1e-6) gets a band of +-10 % around its value instead.
QCPRange paddedRange(double lower, double upper);
/// Sets the axis ranges of rect so that one metre is as long on x as on y and data stays whole.
void fitEqualAspect(QCPAxisRect& rect, const QRectF& data);
/// The font and line scale and the palette drawPlot uses for this plot from now on.
void setPlotLook(QCustomPlot& plot, const CanvasStyle& look);

/// Wraps the legend in the row under a lone plot into as many columns as fit the plot's width
/// (at most the legend's "maxColumns" property when set), so that no entry is cut off; when one
/// column is still too wide, its names are set smaller (down to 6.5 pt) until they fit. Call
/// after drawing and after every resize.
void fitLegendToWidth(QCustomPlot& plot);

/// Adds the caption line above the plot(s).
void addCaption(QCustomPlot& plot, const QString& caption);

} // namespace chaplygin::ui
