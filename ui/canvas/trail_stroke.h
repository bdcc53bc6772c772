#pragma once
#include <QPen>
#include <QPolygonF>
#include <QRegion>

class QPainter;

namespace chaplygin::ui {

/// Strokes the polyline with pen as QPainter::drawPolyline would, but only what can reach area
/// (the painter's user coordinates): inside area the pixels are drawPolyline's, outside they
/// may be missing. The segments that cannot reach area are left out, and a dashed pen's dashes
/// are laid out here from the line's start (the pattern runs on across what is left out) and
/// stroked as one path of solid dashes, so that crossings are inked once, as Qt's dasher does.
/// An animation frame repaints a small region; a trail of thousands of vertices then costs its
/// few nearby segments instead of its whole outline.
void strokePolylineWithin(QPainter& painter, const QPolygonF& line, const QPen& pen,
                          const QRegion& area);

/// What the painter can reach, in its user coordinates: its window through the world transform,
/// within its clip. For a whole-picture strokePolylineWithin: a curve far larger than the
/// picture is then handed to Qt clipped to it.
QRegion paintableArea(const QPainter& painter);

} // namespace chaplygin::ui
