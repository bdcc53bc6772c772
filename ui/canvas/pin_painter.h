#pragma once
#include <QPointF>
#include <QRectF>
#include <QTransform>

class QFont;
class QPainter;

namespace chaplygin::ui {

class CanvasCurves;
class PinSet;

/// Draws the pinned runs over the live trails, under the live bodies: each run's trail up to t
/// faint in its colour, its body faint, a dot where it is at time t, and a key of colours and
/// labels ("b = 0.5 m") from topLeft down. The trails are the runs' paths flattened by curves.
void paintPinnedRuns(QPainter& painter, PinSet& pins, CanvasCurves& curves, const QTransform& world,
                     double t, QPointF topLeft);

/// The box the key of paintPinnedRuns covers when drawn from topLeft (the first row's baseline)
/// by a painter whose font is font; empty without pins.
QRectF pinKeyBounds(PinSet& pins, QPointF topLeft, const QFont& font);

} // namespace chaplygin::ui
