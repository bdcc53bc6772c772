#include "canvas/curve_flattening.h"

#include <algorithm>
#include <cmath>

namespace chaplygin::ui {

namespace {
// a chord halved at most this often: 2^10 points per panel or seed interval, enough for 0.25 px
// at every zoom a lecture uses, and bounded when the view is zoomed far into one spot
constexpr int kMaxHalvings = 10;
} // namespace

std::size_t FlatCurve::countUpTo(double limit) const {
    return std::size_t(std::upper_bound(param.begin(), param.end(), limit) - param.begin());
}

namespace {

bool finite(QPointF p) {
    return std::isfinite(p.x()) && std::isfinite(p.y());
}

// one evaluation: the point, the parameter recorded for it and a path's curvature
struct Sample {
    QPointF point;
    double param = 0, kappa = 0;
};

void push(FlatCurve& out, const Sample& s, bool withKappa) {
    out.points.push_back(s.point);
    out.param.push_back(s.param);
    if (withKappa)
        out.kappa.push_back(s.kappa);
}

// sa is already in out; appends the samples of (a, b]
template <class Eval>
void subdivide(FlatCurve& out, const Eval& f, bool withKappa, double a, double b, const Sample& sa,
               const Sample& sb, double tolerance, int depth) {
    const double m = 0.5 * (a + b);
    const Sample sm = f(m);
    const QPointF chord = 0.5 * (sa.point + sb.point);
    if (depth > 0 && finite(sm.point) && finite(sa.point) && finite(sb.point) &&
        std::hypot(sm.point.x() - chord.x(), sm.point.y() - chord.y()) > tolerance) {
        subdivide(out, f, withKappa, a, m, sa, sm, tolerance, depth - 1);
        subdivide(out, f, withKappa, m, b, sm, sb, tolerance, depth - 1);
        return;
    }
    // the midpoint is kept too: it is computed already and halves the chord's error again
    push(out, sm, withKappa);
    push(out, sb, withKappa);
}

} // namespace

void flattenInto(FlatCurve& out, const std::function<QPointF(double)>& f, double a, double b,
                 QPointF fa, QPointF fb, double tolerance, int maxDepth) {
    auto eval = [&](double t) { return Sample{f(t), t, 0}; };
    subdivide(out, eval, false, a, b, Sample{fa, a, 0}, Sample{fb, b, 0}, tolerance, maxDepth);
}

FlatCurve flattenPath(const Path& path, double tolerance) {
    FlatCurve out;
    for (const PathPiece& piece : path.pieces()) {
        if (piece.kind == PathPiece::Kind::Pivot) {
            push(out, Sample{{piece.x, piece.y}, piece.s0, 0}, true);
            continue;
        }
        const PathTable& table = *piece.table;
        const auto& nodes = table.nodes();
        auto sample = [&](const PathNode& n) {
            return Sample{{n.x, n.y}, piece.s0 + n.s, piece.direction * n.kappa};
        };
        push(out, sample(nodes.front()), true);
        for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
            // within panel k by xi in [-1, 1]: the body's pose is read the same way
            auto eval = [&](double xi) { return sample(table.interpolatedAt(int(k), xi)); };
            subdivide(out, eval, true, -1, 1, sample(nodes[k]), sample(nodes[k + 1]), tolerance,
                      kMaxHalvings);
        }
    }
    // arc length through a piece's interpolants: kept non-decreasing for countUpTo
    for (std::size_t i = 1; i < out.param.size(); ++i)
        out.param[i] = std::max(out.param[i], out.param[i - 1]);
    return out;
}

FlatCurve flattenInTime(const std::function<QPointF(double)>& f, double tEnd, double tolerance,
                        int seeds) {
    FlatCurve out;
    seeds = std::max(seeds, 2);
    double a = 0;
    QPointF fa = f(0);
    out.param.push_back(0);
    out.points.push_back(fa);
    for (int i = 1; i < seeds; ++i) {
        const double b = i + 1 == seeds ? tEnd : tEnd * i / (seeds - 1);
        const QPointF fb = f(b);
        flattenInto(out, f, a, b, fa, fb, tolerance);
        a = b;
        fa = fb;
    }
    return out;
}

FlatCurve flattenThroughKnots(const std::vector<TrailKnot>& knots, double tEnd, double tolerance) {
    FlatCurve out;
    if (knots.empty())
        return out;
    out.param.push_back(knots.front().t);
    out.points.emplace_back(knots.front().x, knots.front().y);
    // no more points than a trail flattened in time at its most (400 seeds, kMaxHalvings each),
    // however many steps the integration took
    const double intervals = double(knots.size());
    const int maxDepth = std::clamp(
        int(std::floor(std::log2(400.0 * (1 << kMaxHalvings) / intervals))), 1, kMaxHalvings);
    for (std::size_t k = 0; k + 1 < knots.size() && knots[k].t < tEnd; ++k) {
        const TrailKnot& a = knots[k];
        const TrailKnot& b = knots[k + 1];
        const double h = b.t - a.t;
        if (!(h > 0)) { // a push: the body jumps at that instant
            out.param.push_back(b.t);
            out.points.emplace_back(b.x, b.y);
            continue;
        }
        // cubic Hermite in tau = (t - a.t)/h on [0, 1]
        auto hermite = [&](double t) {
            const double tau = (t - a.t) / h, t2 = tau * tau, t3 = t2 * tau;
            const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + tau;
            const double h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
            return QPointF(h00 * a.x + h10 * h * a.vx + h01 * b.x + h11 * h * b.vx,
                           h00 * a.y + h10 * h * a.vy + h01 * b.y + h11 * h * b.vy);
        };
        flattenInto(out, hermite, a.t, b.t, {a.x, a.y}, {b.x, b.y}, tolerance, maxDepth);
    }
    return out;
}

void CanvasCurves::update(const std::shared_ptr<const Solution>& solution,
                          double devicePxPerMetre) {
    // flattened for the next power of two of the scale: never coarser than asked for, and made
    // anew only when a zoom passes a power of two, not at every wheel step
    const double scale =
        devicePxPerMetre > 0 ? std::exp2(std::ceil(std::log2(devicePxPerMetre))) : 0;
    if (solution == m_solution && scale == m_scale)
        return;
    m_solution = solution;
    m_scale = scale;
    m_pins.clear();
    m_path = m_free = m_vak = m_openLoop = m_closedLoop = {};
    if (!solution || !(devicePxPerMetre > 0))
        return;
    const double tolerance = kTolerancePx / scale;
    m_path = flattenPath(*solution->path(), tolerance);
    const Solution& s = *solution;
    m_free = flattenInTime(
        [&](double t) {
            const FreeState f = s.freeAt(t);
            return QPointF(f.x, f.y);
        },
        s.tEnd(), tolerance);
    m_vak = flattenInTime(
        [&](double t) {
            const VakonomicState v = s.vakonomicAt(t);
            return QPointF(v.x, v.y);
        },
        s.tEnd(), tolerance);
    // the pushed bodies (docs/physics.md §9), when the scene has a perturbation: a state between
    // the integrator's steps costs an integration step, so they are drawn through their accepted
    // steps, by the cubic Hermite interpolant of the position and velocity there
    auto pushed = [&](const PerturbedMotion* body) {
        return flattenThroughKnots(body->trailKnots(), s.tEnd(), tolerance);
    };
    if (s.perturbed()) {
        m_openLoop = pushed(s.openLoop());
        m_closedLoop = pushed(s.feedback());
    }
}

const FlatCurve& CanvasCurves::pinnedPath(const std::shared_ptr<const Solution>& run) {
    auto it = m_pins.find(run.get());
    if (it == m_pins.end() || it->second.first != run) {
        const double tolerance = m_scale > 0 ? kTolerancePx / m_scale : 1e-3;
        it =
            m_pins.insert_or_assign(run.get(), std::pair{run, flattenPath(*run->path(), tolerance)})
                .first;
    }
    return it->second.second;
}

} // namespace chaplygin::ui
