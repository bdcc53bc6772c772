#pragma once
#include "scene/body_vectors.h"
#include "scene/scene.h"

#include <QColor>
#include <QFont>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QTransform>

#include <array>
#include <vector>

class QPainter;

namespace chaplygin::ui {

/// The arrows of View > Vectors, in menu order.
enum class VectorKind { KnifeVelocity, AxialForce, LateralReaction, ControlCouple, CmVelocity };
constexpr int kVectorKinds = 5;

/// The toggle of a kind in the scene's overlay.
VectorToggle VectorOverlay::*vectorToggle(VectorKind kind);
QString vectorName(VectorKind kind);   ///< menu text, e.g. "Knife point velocity v_P"
QString vectorSymbol(VectorKind kind); ///< label at the arrow, e.g. "v_P"
QString vectorUnit(VectorKind kind);   ///< "m/s", "N" or "N m"
QColor vectorColor(VectorKind kind);

/// Length per unit of each quantity, by VectorKind: [m per m/s], [m per N], and for the couple
/// [rad of arc per N m].
using VectorScales = std::array<double, kVectorKinds>;

/// One arrow as drawn, in widget pixels (what tests query).
struct ArrowShape {
    VectorKind kind;
    QPointF tail, head;
    double value = 0; ///< the quantity's magnitude in its unit
    bool ghost = false;
};

/// The couple as drawn: an arc about the centre of mass whose span shows tau (counter-clockwise
/// for tau > 0), in widget pixels and degrees (Qt's convention: counter-clockwise on screen).
struct CoupleShape {
    QPointF centre;
    double radius = 0;
    double startDeg = 0, spanDeg = 0;
    double value = 0; ///< tau [N m]
    bool pivot = false;
    bool ghost = false;
};

struct VectorShapes {
    std::vector<ArrowShape> arrows;
    std::vector<CoupleShape> couples;
};

/// The shapes of one body's shown arrows: any body state (controlled, free or another model's),
/// world mapping metres to pixels. A pivoting body shows the couple alone. coupleRadius [m].
VectorShapes vectorShapes(const DerivedSystem& system, const BodyState& body,
                          const VectorOverlay& overlay, const VectorScales& scales,
                          const QTransform& world, double coupleRadius, bool ghost);

/// Draws shapes; labels names the controlled body's arrows. Each label goes at its arrowhead,
/// or, where that box is taken by an earlier label (placed, which it extends), at the nearest
/// free place around the head: on a small body the names do not pile up. lineScale multiplies
/// the pens, heads and type (presentation mode's, CanvasStyle::lineScale).
void paintVectorShapes(QPainter& painter, const VectorShapes& shapes, bool labels,
                       std::vector<QRectF>* placed = nullptr, double lineScale = 1);

/// A scale bar's length [px] for a round value: about this much (a small drawing area shortens
/// it, VectorLayer).
constexpr double kBarPx = 80;

/// The width [px] the scale bars' texts take in font, the widest of them (at least 104 px for
/// bars of kBarPx, in proportion for shorter ones): the bars stand left of it, so no text is cut.
int scaleBarsTextWidth(const QFont& font, const VectorOverlay& overlay, const VectorScales& scales,
                       double pixelsPerMetre, double barPx = kBarPx);

/// A scale bar for each shown quantity (a round value in physical units, its bar about barPx
/// long), stacked upwards from bottomRight; pixelsPerMetre is the canvas's zoom. lineScale
/// multiplies pens and type; the texts' column is scaleBarsTextWidth of the scaled font.
void paintScaleBars(QPainter& painter, const VectorOverlay& overlay, const VectorScales& scales,
                    double pixelsPerMetre, QPointF bottomRight, double lineScale = 1,
                    double barPx = kBarPx);

/// A round value (1, 2 or 5 x 10^k) near target.
double roundValue(double target);

} // namespace chaplygin::ui
