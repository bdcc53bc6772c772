#pragma once
// Axes fitted to the plot's size after every layout: readable tick steps from the pixel lengths,
// axis labels that fit the frame, equal scales where asked.
#include <QStringList>

class QCPAxis;
class QCustomPlot;

namespace chaplygin::ui {

/// The labels an axis may show, longest first. A value axis shows the first one whose longest
/// line fits its length ("χ = Ψ − (a/b)φ [rad]", then "χ [rad]"); a time axis drops its label on
/// a plot too low for it (its axis rectangle would be under four tick labels high), so that the
/// frame keeps room for ticks.
void setAxisLabels(QCPAxis* axis, const QStringList& labels);

/// Gives every axis of the plot a PixelTicker, and after each layout chooses the axis labels
/// (setAxisLabels), gives an axis rectangle with the property "chaplyginEqualAspect" (a QRectF of
/// data) equal scales on x and y (fitEqualAspect), keeps the clip marks inside the frame
/// (placeClipMarks) and lays the plot out again, so that the ticks
/// are made for the final axis lengths. Call after drawing (drawPlot makes new axis rectangles).
void fitAxesAfterLayout(QCustomPlot& plot);

} // namespace chaplygin::ui
