#pragma once
// The axes of a time plot: the value axis follows the controlled curves (the body and the pinned
// runs); the free and vakonomic curves are clipped at the frame with a mark where they leave.
#include <QString>

class QCPAxisRect;
class QCPGraph;
class QCPRange;
class QCustomPlot;

namespace chaplygin::ui {

/// A curve that sets its plot's value range (the controlled body, a pinned run), or one that is
/// drawn within it and clipped with a mark naming it (clipName: "free", "vakonomic").
void setControlled(QCPGraph& graph);
void setClipped(QCPGraph& graph, const QString& clipName);

/// How far beyond the controlled curves' range (padded by 5 %) the clipped curves may widen the
/// value axis, on each side, as a fraction of that padded range. When the controlled curves are
/// flat (paddedRange's rule), the others set the range as long as it stays within
/// kFlatFactor times the controlled value's size (at least its band).
constexpr double kWidenFraction = 0.25;
constexpr double kFlatFactor = 10;

/// The key axis holds every finite point; the value axis holds the controlled curves, widened by
/// the others within kWidenFraction (or kFlatFactor), and every point of the others beyond it is
/// clipped at the frame, with a mark "↑ free" at the edge where the curve first leaves (one per
/// curve and edge). With fitAllCurves(plot) every finite value is in view and no mark is drawn.
/// NaN and infinite values are left out of every range.
void fitTimeAxes(QCPAxisRect& rect);
/// The same for the times of `time` alone (a zoomed time axis): the key axis shows `time`, the
/// value axis what the curves reach within it (their points inside and the lines at its edges),
/// and a clip mark stands where a curve first leaves within it (at its left edge when it comes
/// in from outside).
void fitTimeAxes(QCPAxisRect& rect, const QCPRange& time);

/// Turns each clip mark of rect so that its text stays inside the frame: "↑ free" to the right
/// of the exit, "free ↑" to its left, or against the left edge; in a frame narrower than the text
/// the arrow alone, in the curve's colour (after each layout).
void placeClipMarks(QCPAxisRect& rect);

/// The plot's "Fit all curves" choice (off for a new plot and for exported figures).
bool fitAllCurves(const QCustomPlot& plot);
void setFitAllCurves(QCustomPlot& plot, bool on);

/// The clip marks fitTimeAxes put in rect: their texts, as "↑ free" (for tests).
QStringList clipMarks(QCPAxisRect& rect);

} // namespace chaplygin::ui
