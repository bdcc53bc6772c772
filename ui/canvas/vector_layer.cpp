#include "canvas/vector_layer.h"

#include "canvas/body_painter.h"

#include <QPainter>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace chaplygin::ui {

namespace {
constexpr int kFreeSamples = 200;
constexpr double kLongest = 1.2;                        // the largest arrow, in body extents
constexpr double kCoupleRadius = 0.45;                  // the couple's arc, in body extents
constexpr double kLargestTurn = 1.5 * std::numbers::pi; // the largest couple's arc [rad]

constexpr double kLabelPx = 48; // room for an arrowhead's label and its pen around a shape

// the box's size around rows of scale bars: a row of 18 px each (times lineScale); left of the
// texts' column a bar 6 px off, at most 1.6 times its round length long (roundValue's value is
// within a factor sqrt(2.5) of the aim), or the couple's arc out to 55 px; 12 px of margin each
// side (paintScaleBars)
QSizeF scaleBarsSize(int rows, int textWidth, double lineScale, double barPx) {
    const double s = lineScale;
    const double bars = std::max(6 * s + 1.6 * barPx + 6, 55 * s);
    return {textWidth + bars + 24 * s, 18.0 * s * rows + 24 * s};
}

// the bottom right of the rows (paintScaleBars draws them up and left from it) in a corner of
// the drawing area: clear of the legend under it, and at the top clear of the time read-out's
// band and the canvas's own scale bar
QPointF scaleBarsCorner(const QRectF& area, Qt::Corner corner, int rows, int textWidth,
                        double lineScale, double barPx) {
    const double s = lineScale;
    const QSizeF size = scaleBarsSize(rows, textWidth, s, barPx);
    const double right = corner == Qt::TopLeftCorner || corner == Qt::BottomLeftCorner
                             ? area.left() + 2 * s + size.width() - 12 * s
                             : area.right() - 14 * s;
    const double bottom = corner == Qt::TopLeftCorner || corner == Qt::TopRightCorner
                              ? area.top() + 44 * s + size.height() - 12 * s
                              : area.bottom() - 14 * s;
    return {right, bottom};
}

// the box around the scale bars whose rows end at corner
QRect scaleBarsBox(QPointF corner, int rows, int textWidth, double lineScale, double barPx) {
    const double s = lineScale;
    const QSizeF size = scaleBarsSize(rows, textWidth, s, barPx);
    return QRectF(corner + QPointF(12 * s, 12 * s) - QPointF(size.width(), size.height()),
                  corner + QPointF(12 * s, 12 * s))
        .toAlignedRect();
}

// how much smaller the scale bars are drawn on a drawing area narrower or lower than 400 px (a
// small export): down to 0.6 of their size, so that their corner leaves room for the scene
double barsShrink(const QRectF& area) {
    return std::clamp(std::min(area.width(), area.height()) / 400, 0.6, 1.0);
}

int shownRows(const VectorOverlay& overlay) {
    int rows = 0;
    for (int i = 0; i < kVectorKinds; ++i)
        rows += (overlay.*vectorToggle(VectorKind(i))).shown ? 1 : 0;
    return rows;
}

double extentOf(const Solution& s) {
    return std::max(bodyExtent(s.scene().system, s.system()), 1e-3);
}
} // namespace

VectorScales VectorLayer::scales(const std::shared_ptr<const Solution>& solution,
                                 const VectorOverlay& overlay) const {
    if (solution != m_solution) {
        m_solution = solution;
        // the largest of each quantity over the controlled run and the free run
        double speed = 0, force = 0, couple = 0;
        const DerivedSystem& sys = solution->system();
        auto take = [&](const BodyState& b) {
            BodyVectors v = bodyVectors(sys, b);
            speed = std::max({speed, std::hypot(v.knifeVelocity.vx, v.knifeVelocity.vy),
                              std::hypot(v.cmVelocity.vx, v.cmVelocity.vy)});
            force = std::max({force, std::fabs(b.forceAxial), std::fabs(b.knifeReaction)});
            couple = std::max(couple, std::fabs(b.controlCouple));
        };
        for (const MotionSample& m : solution->controlledAtNodes())
            take(controlledBodyState(m));
        for (int i = 0; i < kFreeSamples; ++i)
            take(freeBodyState(sys, solution->freeAt(solution->tEnd() * i / (kFreeSamples - 1))));
        double longest = kLongest * extentOf(*solution);
        auto per = [](double length, double largest) {
            return largest > 1e-12 && std::isfinite(largest) ? length / largest : length;
        };
        m_auto[std::size_t(VectorKind::KnifeVelocity)] = per(longest, speed);
        m_auto[std::size_t(VectorKind::CmVelocity)] = per(longest, speed);
        m_auto[std::size_t(VectorKind::AxialForce)] = per(longest, force);
        m_auto[std::size_t(VectorKind::LateralReaction)] = per(longest, force);
        m_auto[std::size_t(VectorKind::ControlCouple)] = per(kLargestTurn, couple);
    }
    VectorScales out = m_auto;
    for (int i = 0; i < kVectorKinds; ++i) {
        double own = (overlay.*vectorToggle(VectorKind(i))).scale;
        if (own > 0)
            out[std::size_t(i)] = own;
    }
    return out;
}

bool VectorLayer::shapes(const std::shared_ptr<const Solution>& solution,
                         const VectorOverlay& overlay, const MotionSample& now,
                         const QTransform& world, VectorShapes& free, VectorShapes& controlled,
                         VectorScales& k) const {
    if (!solution || overlay == VectorOverlay{})
        return false;
    bool any = false;
    for (int i = 0; i < kVectorKinds; ++i)
        any = any || (overlay.*vectorToggle(VectorKind(i))).shown;
    if (!any)
        return false;
    k = scales(solution, overlay);
    const DerivedSystem& sys = solution->system();
    double radius = kCoupleRadius * extentOf(*solution);
    // the free body has no control: its arrows are the velocities and the knife's reaction
    free = vectorShapes(sys, freeBodyState(sys, now.free), overlay, k, world, radius, true);
    controlled = vectorShapes(sys, controlledBodyState(now), overlay, k, world, radius, false);
    return true;
}

void VectorLayer::paintScaleBars(QPainter& p, const std::shared_ptr<const Solution>& solution,
                                 const VectorOverlay& overlay, double pixelsPerMetre,
                                 const QRectF& area, const QRegion& repainted) {
    if (!solution || shownRows(overlay) == 0)
        return;
    const VectorScales k = scales(solution, overlay);
    const double shrink = barsShrink(area), s = m_lineScale * shrink;
    QFont barsFont = p.font();
    barsFont.setPointSizeF(8.5 * s);
    m_barsText = scaleBarsTextWidth(barsFont, overlay, k, pixelsPerMetre, kBarPx * shrink);
    // the scale bars stay put: a frame that repaints what moves need not draw them
    if (repainted.intersects(scaleBarsBounds(overlay, area)))
        chaplygin::ui::paintScaleBars(
            p, overlay, k, pixelsPerMetre,
            scaleBarsCorner(area, m_barsCorner, shownRows(overlay), m_barsText, s, kBarPx * shrink),
            s, kBarPx * shrink);
}

void VectorLayer::paint(QPainter& p, const std::shared_ptr<const Solution>& solution,
                        const VectorOverlay& overlay, const MotionSample& now,
                        const QTransform& world) {
    m_controlled = {};
    m_free = {};
    m_labels.clear();
    VectorScales k{};
    if (!shapes(solution, overlay, now, world, m_free, m_controlled, k))
        return;
    paintVectorShapes(p, m_free, false, nullptr, m_lineScale);
    paintVectorShapes(p, m_controlled, true, &m_labels, m_lineScale);
}

QRect VectorLayer::scaleBarsBounds(const VectorOverlay& overlay, const QRectF& area) const {
    return scaleBarsBounds(overlay, area, m_barsCorner);
}

QRect VectorLayer::scaleBarsBounds(const VectorOverlay& overlay, const QRectF& area,
                                   Qt::Corner corner) const {
    const int rows = shownRows(overlay);
    const double shrink = barsShrink(area), s = m_lineScale * shrink, barPx = kBarPx * shrink;
    return rows > 0 ? scaleBarsBox(scaleBarsCorner(area, corner, rows, m_barsText, s, barPx), rows,
                                   m_barsText, s, barPx)
                    : QRect();
}

std::vector<QRectF> VectorLayer::bounds(const std::shared_ptr<const Solution>& solution,
                                        const VectorOverlay& overlay, const MotionSample& now,
                                        const QTransform& world) const {
    VectorShapes free, controlled;
    VectorScales k{};
    if (!shapes(solution, overlay, now, world, free, controlled, k))
        return {};
    std::vector<QRectF> boxes;
    auto add = [&](QRectF r) { boxes.push_back(r); };
    const double label = kLabelPx * m_lineScale;
    for (const VectorShapes* s : {&free, &controlled}) {
        for (const ArrowShape& a : s->arrows)
            add(QRectF(a.tail, a.head).normalized().adjusted(-label, -label, label, label));
        for (const CoupleShape& c : s->couples) // "tau = 0 while turning" under it
            add(QRectF(c.centre, c.centre)
                    .adjusted(-c.radius - label, -c.radius - label, c.radius + label,
                              c.radius + label + 20 * m_lineScale));
    }
    return boxes;
}

} // namespace chaplygin::ui
