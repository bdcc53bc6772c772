#pragma once
#include <QPointF>
#include <QTransform>

class QPainter;

namespace chaplygin::ui {

class PinSet;

/// Draws the pinned runs over the live trails, under the live bodies: each run's trail up to t
/// faint in its colour, its body faint, a dot where it is at time t, and a key of colours and
/// labels ("b = 0.5 m") from topLeft down.
void paintPinnedRuns(QPainter& painter, PinSet& pins, const QTransform& world, double t,
                     QPointF topLeft);

} // namespace chaplygin::ui
