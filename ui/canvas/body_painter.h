#pragma once
#include "canvas/canvas_style.h"
#include "systems/system.h"

#include <QColor>
#include <QPainterPath>
#include <QRectF>

class QPainter;

namespace chaplygin::ui {

/// A body's pose: the knife (or contact) point P and the heading phi [m, m, rad].
struct BodyPose {
    double x = 0, y = 0, phi = 0;
};

/// Draws the body to scale in world coordinates (the painter maps metres to pixels, y up):
/// the sleigh as an elliptical board with its knife edge at P and its centre of mass at
/// P + a s-hat; the disk seen from above; the carriage with its two wheels at +-a (its half-axle)
/// across the heading on an axle through P, its centre of mass.
/// ghost draws it translucent, for the free motion.
/// look: to scale, outline only, or a marker of a fixed pixel size; fill opacity; pen scale.
struct BodyLook {
    BodyDisplay display = BodyDisplay::ToScale;
    double opacity = 0.8; ///< of the fill (a ghost gets a third of it)
    double lineScale = 1; ///< multiplies the pen widths and the marker size
};
void paintBody(QPainter& painter, const SystemSpec& spec, const DerivedSystem& derived,
               const BodyPose& pose, const QColor& color, bool ghost, const BodyLook& look = {});

/// The radius of the marker [px] before lineScale.
constexpr double kMarkerRadiusPx = 9;

/// The radius [m] of a circle around P that holds the whole body (for fitting the view).
double bodyExtent(const SystemSpec& spec, const DerivedSystem& derived);

/// The box [m] of the body drawn to scale or as an outline at pose: its area, the sleigh's knife
/// and the disk's heading arrow (without the pens' widths, which are pixels).
QRectF bodyBounds(const SystemSpec& spec, const DerivedSystem& derived, const BodyPose& pose);

/// The area the body to scale covers, in its own frame [m] (P at the origin, s-hat along x):
/// where it would hide the path under its fill.
QPainterPath bodyShape(const SystemSpec& spec, const DerivedSystem& derived);

/// The display drawn for the chosen one: the chosen one itself, or for Automatic the body to
/// scale while it is small beside the path (the circle around P that holds it at most
/// kAutoToScale of the path's larger side, pathBounds [m]), an outline up to kAutoOutline, a
/// marker beyond, where even an outline would cross most of the path.
BodyDisplay shownBodyDisplay(BodyDisplay chosen, const SystemSpec& spec,
                             const DerivedSystem& derived, const QRectF& pathBounds);
constexpr double kAutoToScale = 0.4, kAutoOutline = 1.5;

} // namespace chaplygin::ui
