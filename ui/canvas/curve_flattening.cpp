#include "canvas/curve_flattening.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace chaplygin::ui {

namespace {
// a chord halved at most this often: 2^10 points per panel or seed interval, enough for 0.25 px
// at every zoom a lecture uses, and bounded when the view is zoomed far into one spot
constexpr int kMaxHalvings = 10;
// how often a curve over its budget is flattened again: 16 times coarser, then through its seeds
constexpr int kCoarserTries = 2;
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

// a point closer than this many tolerances to the one before adds nothing that can be seen
constexpr double kDropFraction = 0.25;

// push, but a point within a quarter of the tolerance of the last one is left out (a path of
// thousands of panels seen from afar is a few points per pixel, not two per panel)
void pushVisible(FlatCurve& out, const Sample& s, bool withKappa, const FlattenLimits& limits) {
    if (!out.points.empty()) {
        const QPointF d = s.point - out.points.back();
        if (std::hypot(d.x(), d.y()) < kDropFraction * limits.tolerance)
            return;
    }
    push(out, s, withKappa);
}

// whether the curve near a, m and b (m off the chord by `off`) may be within the seen region
bool maySee(const FlattenLimits& limits, QPointF a, QPointF m, QPointF b, double off) {
    if (limits.seen.isNull())
        return true;
    const double pad = 2 * off + limits.tolerance;
    const double left = std::min({a.x(), m.x(), b.x()}) - pad;
    const double right = std::max({a.x(), m.x(), b.x()}) + pad;
    const double bottom = std::min({a.y(), m.y(), b.y()}) - pad;
    const double top = std::max({a.y(), m.y(), b.y()}) + pad;
    return left <= limits.seen.right() && limits.seen.left() <= right &&
           bottom <= limits.seen.bottom() && limits.seen.top() <= top;
}

// below this the points' own rounding is what a halving would follow: the coordinates of a body
// 1e308 m out are 2e292 m apart, and halving there never ends within the tolerance
double resolution(QPointF a, QPointF b) {
    const double size =
        std::max({std::fabs(a.x()), std::fabs(a.y()), std::fabs(b.x()), std::fabs(b.y())});
    return 64 * std::numeric_limits<double>::epsilon() * size;
}

// sa is already in out; appends the samples of (a, b]
template <class Eval>
void subdivide(FlatCurve& out, const Eval& f, bool withKappa, double a, double b, const Sample& sa,
               const Sample& sb, FlattenLimits& limits, int depth) {
    if (limits.stopped)
        return;
    const double m = 0.5 * (a + b);
    const Sample sm = f(m);
    const QPointF chord = 0.5 * (sa.point + sb.point);
    const double off = std::hypot(sm.point.x() - chord.x(), sm.point.y() - chord.y());
    if (depth > 0 && finite(sm.point) && finite(sa.point) && finite(sb.point) &&
        off > limits.tolerance && off > resolution(sa.point, sb.point) &&
        maySee(limits, sa.point, sm.point, sb.point, off)) {
        if (out.points.size() < limits.budget) {
            subdivide(out, f, withKappa, a, m, sa, sm, limits, depth - 1);
            subdivide(out, f, withKappa, m, b, sm, sb, limits, depth - 1);
            return;
        }
        limits.exceeded = true;
        if (limits.truncate) {
            limits.stopped = true; // the curve ends at sa
            return;
        }
    }
    if (limits.truncate && out.points.size() >= limits.budget) {
        limits.exceeded = limits.stopped = true; // the curve ends at sa
        return;
    }
    // the midpoint is kept too: it is computed already and halves the chord's error again
    pushVisible(out, sm, withKappa, limits);
    pushVisible(out, sb, withKappa, limits);
}

} // namespace

void flattenInto(FlatCurve& out, const std::function<QPointF(double)>& f, double a, double b,
                 QPointF fa, QPointF fb, FlattenLimits& limits, int maxDepth) {
    auto eval = [&](double t) { return Sample{f(t), t, 0}; };
    subdivide(out, eval, false, a, b, Sample{fa, a, 0}, Sample{fb, b, 0}, limits, maxDepth);
}

FlatCurve flattenPath(const Path& path, FlattenLimits& limits) {
    FlatCurve out;
    for (const PathPiece& piece : path.pieces()) {
        if (limits.stopped)
            break;
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
        for (std::size_t k = 0; k + 1 < nodes.size() && !limits.stopped; ++k) {
            // within panel k by xi in [-1, 1]: the body's pose is read the same way
            auto eval = [&](double xi) { return sample(table.interpolatedAt(int(k), xi)); };
            subdivide(out, eval, true, -1, 1, sample(nodes[k]), sample(nodes[k + 1]), limits,
                      kMaxHalvings);
        }
        // a piece's last point is kept: the next piece (a pivot, a cusp) starts there
        if (!limits.stopped && !(out.points.back() == QPointF(nodes.back().x, nodes.back().y)))
            push(out, sample(nodes.back()), true);
    }
    // arc length through a piece's interpolants: kept non-decreasing for countUpTo
    for (std::size_t i = 1; i < out.param.size(); ++i)
        out.param[i] = std::max(out.param[i], out.param[i - 1]);
    return out;
}

FlatCurve flattenInTime(const std::function<QPointF(double)>& f, double tEnd, FlattenLimits& limits,
                        int seeds) {
    FlatCurve out;
    seeds = std::max(seeds, 2);
    double a = 0;
    QPointF fa = f(0);
    out.param.push_back(0);
    out.points.push_back(fa);
    for (int i = 1; i < seeds && !limits.stopped; ++i) {
        const double b = i + 1 == seeds ? tEnd : tEnd * i / (seeds - 1);
        const QPointF fb = f(b);
        flattenInto(out, f, a, b, fa, fb, limits);
        a = b;
        fa = fb;
    }
    // the last point is the trail's end at tEnd
    if (!limits.stopped && !(out.points.back() == fa)) {
        out.param.push_back(tEnd);
        out.points.push_back(fa);
    }
    return out;
}

FlatCurve flattenThroughKnots(const std::vector<TrailKnot>& knots, double tEnd,
                              FlattenLimits& limits) {
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
    for (std::size_t k = 0; k + 1 < knots.size() && knots[k].t < tEnd && !limits.stopped; ++k) {
        const TrailKnot& a = knots[k];
        const TrailKnot& b = knots[k + 1];
        const double h = b.t - a.t;
        if (!(h > 0)) { // a push: the body jumps at that instant, from where it was
            if (!(out.points.back() == QPointF(a.x, a.y))) {
                out.param.push_back(a.t);
                out.points.emplace_back(a.x, a.y);
            }
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
        flattenInto(out, hermite, a.t, b.t, {a.x, a.y}, {b.x, b.y}, limits, maxDepth);
    }
    return out;
}

FlatCurve flattenWithinBudget(const std::function<FlatCurve(FlattenLimits&)>& build,
                              FlattenLimits& limits) {
    limits.budget = kPointBudget;
    const double asked = limits.tolerance;
    for (int attempt = 0;; ++attempt) {
        limits.exceeded = false;
        FlatCurve out = build(limits);
        if (attempt == kCoarserTries) {
            // the last attempt ends the curve where the budget ran out
            out.truncated = limits.stopped;
            return out;
        }
        if (!limits.exceeded && out.points.size() <= kPointBudget)
            return out;
        // 16 times coarser, and then the tolerance asked for, as far as the budget goes
        if (attempt + 1 == kCoarserTries) {
            limits.tolerance = asked;
            limits.truncate = true;
        } else {
            limits.tolerance *= 16;
        }
    }
}

void CanvasCurves::update(const std::shared_ptr<const Solution>& solution, double devicePxPerMetre,
                          const QRectF& view) {
    // flattened for the next power of two of the scale: never coarser than asked for, and made
    // anew only when a zoom passes a power of two, not at every wheel step, or when the view
    // leaves the region flattened exactly
    const double scale =
        devicePxPerMetre > 0 ? std::exp2(std::ceil(std::log2(devicePxPerMetre))) : 0;
    const bool inside = m_seen.isNull() || (!view.isNull() && m_seen.contains(view));
    if (solution == m_solution && scale == m_scale && inside)
        return;
    m_solution = solution;
    m_scale = scale;
    // a view's size around the view: panning by less than that keeps the curves
    m_seen = view.isNull()
                 ? QRectF()
                 : view.adjusted(-view.width(), -view.height(), view.width(), view.height());
    m_pins.clear();
    m_path = m_free = m_vak = m_openLoop = m_closedLoop = {};
    if (!solution || !(devicePxPerMetre > 0))
        return;
    const double tolerance = kTolerancePx / scale;
    auto within = [&](const std::function<FlatCurve(FlattenLimits&)>& build) {
        FlattenLimits limits{tolerance, m_seen};
        return flattenWithinBudget(build, limits);
    };
    const Solution& s = *solution;
    m_path = within([&](FlattenLimits& l) { return flattenPath(*s.path(), l); });
    m_free = within([&](FlattenLimits& l) {
        return flattenInTime(
            [&](double t) {
                const FreeState f = s.freeAt(t);
                return QPointF(f.x, f.y);
            },
            s.tEnd(), l);
    });
    m_vak = within([&](FlattenLimits& l) {
        return flattenInTime(
            [&](double t) {
                const VakonomicState v = s.vakonomicAt(t);
                return QPointF(v.x, v.y);
            },
            s.tEnd(), l);
    });
    // the pushed bodies (docs/physics.md §9), when the scene has a perturbation: a state between
    // the integrator's steps costs an integration step, so they are drawn through their accepted
    // steps, by the cubic Hermite interpolant of the position and velocity there
    auto pushed = [&](const PerturbedMotion* body) {
        return within(
            [&](FlattenLimits& l) { return flattenThroughKnots(body->trailKnots(), s.tEnd(), l); });
    };
    if (s.perturbed()) {
        m_openLoop = pushed(s.openLoop());
        m_closedLoop = pushed(s.feedback());
    }
}

const FlatCurve& CanvasCurves::pinnedPath(const std::shared_ptr<const Solution>& run) {
    auto it = m_pins.find(run.get());
    if (it == m_pins.end() || it->second.first != run) {
        FlattenLimits limits{m_scale > 0 ? kTolerancePx / m_scale : 1e-3, m_seen};
        FlatCurve flat = flattenWithinBudget(
            [&](FlattenLimits& l) { return flattenPath(*run->path(), l); }, limits);
        it = m_pins.insert_or_assign(run.get(), std::pair{run, std::move(flat)}).first;
    }
    return it->second.second;
}

} // namespace chaplygin::ui
