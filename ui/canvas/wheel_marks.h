#pragma once
// The wheels' rolling angles drawn (docs/physics.md §1, Rolling angles): stripes across a
// wheel's tread in the top view, and a side view of the wheels with their spokes in a corner of
// the canvas. The angles are the core's (scene/wheel_angles); this file only draws them.
#include "scene/wheel_angles.h"
#include "systems/system.h"

#include <QColor>
#include <QFont>
#include <QPointF>
#include <QRectF>
#include <QString>

#include <vector>

class QPainter;

namespace chaplygin::ui {

/// Stripes around a wheel's tread, evenly spaced; the first (at the bottom at t = 0) marked.
constexpr int kTreadStripes = 8;

/// A stripe seen from above: a rim point at angle theta + 2 pi k/kTreadStripes from the bottom,
/// rolling forwards, is at x = -R sin(alpha) along the heading from the wheel's centre and at the
/// height -R cos(alpha): from above only the upper half (cos(alpha) < 0) shows, its stripes
/// moving forwards at R thetadot relative to the axle and bunching at the wheel's ends.
struct TreadStripe {
    double along = 0;    ///< from the wheel's centre along the heading [m]
    bool marked = false; ///< the stripe k = 0
};
std::vector<TreadStripe> treadStripes(double theta, double radius);

/// The colour of the marked stripe and the marked spoke.
QColor rollMarkColour();

/// Draws the stripes on the controlled body's wheels in its own frame (P at the origin, s-hat
/// along x, metres; as paintBody): the disk's one wheel, the carriage's wheel 1 at -a and wheel 2
/// at +a across the heading. Nothing for the sleigh, nor where a wheel is under 8 px long.
void paintTreadStripes(QPainter& painter, const SystemSpec& spec, const WheelAngles& angles,
                       const QColor& ink, double lineScale);

/// The side view: the wheels' centres and sizes in a box of its own [px, from its top left],
/// the disk's one wheel or the carriage's two side by side (wheel 1 on the left), each with its
/// label under it.
struct WheelInsetLayout {
    QSizeF size;
    double radius = 0;            ///< of each wheel [px]
    std::vector<QPointF> centres; ///< one per wheel
    std::vector<QRectF> labels;   ///< one per wheel, under it
};
WheelInsetLayout wheelInsetLayout(int wheels, double lineScale, const QFont& font);

/// The tip of spoke k of a wheel drawn at centre with radius [px, y down], the wheel rolling to
/// the right (forwards) by theta: clockwise on the screen, spoke 0 pointing down at theta = 0.
QPointF spokeTip(QPointF centre, double radius, double theta, int k = 0);
constexpr int kSpokes = 6;

/// The wheels' labels: "θ = 1.23 rad" for the disk, "1 right: θ1 = …" and "2 left: θ2 = …"
/// for the carriage.
QString wheelLabel(const WheelAngles& angles, int wheel);

/// Draws the side view in box (its size from wheelInsetLayout): a light card, each wheel with
/// its spokes (spoke 0 marked), the ground under it, its label, and the direction ahead.
void paintWheelInset(QPainter& painter, const QRectF& box, const WheelAngles& angles,
                     const QColor& ink, double lineScale, const QFont& font);

} // namespace chaplygin::ui
