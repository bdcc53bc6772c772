#include "canvas/vector_layer.h"

#include "canvas/body_painter.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace chaplygin::ui {

namespace {
constexpr int kFreeSamples = 200;
constexpr double kLongest = 1.2;                        // the largest arrow, in body extents
constexpr double kCoupleRadius = 0.45;                  // the couple's arc, in body extents
constexpr double kLargestTurn = 1.5 * std::numbers::pi; // the largest couple's arc [rad]

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

void VectorLayer::paint(QPainter& p, const std::shared_ptr<const Solution>& solution,
                        const VectorOverlay& overlay, const MotionSample& now,
                        const QTransform& world, double pixelsPerMetre, const QRectF& area) {
    m_controlled = {};
    m_free = {};
    if (!solution || overlay == VectorOverlay{})
        return;
    bool any = false;
    for (int i = 0; i < kVectorKinds; ++i)
        any = any || (overlay.*vectorToggle(VectorKind(i))).shown;
    if (!any)
        return;
    VectorScales k = scales(solution, overlay);
    const DerivedSystem& sys = solution->system();
    double radius = kCoupleRadius * extentOf(*solution);
    // the free body has no control: its arrows are the velocities and the knife's reaction
    m_free = vectorShapes(sys, freeBodyState(sys, now.free), overlay, k, world, radius, true);
    m_controlled = vectorShapes(sys, controlledBodyState(now), overlay, k, world, radius, false);
    paintVectorShapes(p, m_free, false);
    paintVectorShapes(p, m_controlled, true);
    paintScaleBars(p, overlay, k, pixelsPerMetre, area.bottomRight() - QPointF(10, 70));
}

} // namespace chaplygin::ui
