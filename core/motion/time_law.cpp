#include "motion/time_law.h"

#include "common/input_error.h"
#include "numerics/safeguarded_newton.h"
#include "paths/panel_geometry.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace chaplygin {
namespace {

constexpr double kTimeTolerance = 1e-13; // bound on t over a panel, relative to its duration

// Newton on a certified panel's t(xi), polynomial and smooth: a step below 1e-9 leaves an error of
// its square (quadratic convergence), below rounding; a bracket of 1e-15 in xi is at rounding; 60
// iterations would bisect [-1, 1] far below that
constexpr NewtonCaps kPanelTimeCaps{
    .maxIterations = 60, .newtonStep = {.value = 1e-9}, .bracket = {.value = 1e-15}};

// t(xi) = tau on a certified panel of duration D: Newton from the quintic Hermite interpolant of
// the inverse xi(tau/D) (its value, slope D/r and curvature -D^2 r'/r^3 at both ends, r = dt/dxi),
// safeguarded by bisection on [-1, 1].
double solveXi(const TimeLaw::TimePanel& p, double tau, double D) {
    const double th = std::clamp(tau / D, 0.0, 1.0), th2 = th * th, th3 = th2 * th, th4 = th3 * th,
                 th5 = th4 * th;
    const double m0 = D / p.rateStart, m1 = D / p.rateEnd;
    const double q0 = -m0 * m0 * m0 * p.rateSlopeStart / D, q1 = -m1 * m1 * m1 * p.rateSlopeEnd / D;
    const double end = 10 * th3 - 15 * th4 + 6 * th5; // the value basis at 1 (and 1 - it at 0)
    double xi = -(1 - end) + end + (th - 6 * th3 + 8 * th4 - 3 * th5) * m0 +
                (-4 * th3 + 7 * th4 - 3 * th5) * m1 + 0.5 * (th2 - 3 * th3 + 3 * th4 - th5) * q0 +
                0.5 * (th3 - 2 * th4 + th5) * q1;
    auto timeAt = [&](double x) {
        double fr[2];
        cheb::evaluateMany(p.c, x, fr, p.rows);
        return NewtonValue{fr[0] - tau, fr[1]};
    };
    // a converged Newton step may end a little outside [-1, 1]
    return std::clamp(
        safeguardedNewton(timeAt, std::clamp(xi, -1.0, 1.0), {-1, 1}, kPanelTimeCaps).x, -1.0, 1.0);
}

} // namespace

struct TimeLaw::Lazy {
    explicit Lazy(std::size_t n) : panels(n), ready(new std::atomic<bool>[n]) {
        for (std::size_t k = 0; k < n; ++k)
            ready[k].store(false, std::memory_order_relaxed);
    }
    std::vector<TimePanel> panels;
    std::unique_ptr<std::atomic<bool>[]> ready; // panels[k] is built and will not change
    std::mutex mutex;
};

TimeLaw::TimeLaw(std::shared_ptr<const Path> path, const ControlParams& params)
    : m_path(std::move(path)), m_params(params) {
    if (!std::isfinite(params.speed) || !(params.speed > 0))
        throw InputError("speed", "must be a finite number > 0, got " + formatNumber(params.speed));
    const auto& pieces = m_path->pieces();
    m_pieceStart.assign(1, 0.0);
    m_nodeTimes.resize(pieces.size());
    m_lazy.resize(pieces.size());
    const double b2 = params.system.b * params.system.b, invSpeed = 1 / params.speed;
    const bool energy = params.mode == SpeedMode::Energy;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const PathPiece& piece = pieces[k];
        double t0 = m_pieceStart.back();
        if (piece.kind == PathPiece::Kind::Pivot) {
            if (params.mode == SpeedMode::Speed)
                throw InputError(
                    "corner at (" + formatNumber(piece.x) + ", " + formatNumber(piece.y) + ")",
                    "constant-speed mode cannot turn a corner (the kinetic energy would be "
                    "infinite); use the constant-energy mode or smooth corners");
            // pivot about P: |phidot| = v_T/b, so it takes b |dphi|/v_T (docs/physics.md §3)
            m_pieceStart.push_back(t0 + params.system.b * std::fabs(piece.phiTo - piece.phiFrom) /
                                            params.speed);
            continue;
        }
        const PathTable& table = *piece.table;
        if (!energy && table.cuspEnds().end) {
            throw InputError(pathPlace(table.curve(), table.cuspEnds().end->u),
                             "constant-speed mode cannot pass this cusp (sdot would have to jump "
                             "from +v_s to -v_s); use the constant-energy mode");
        }
        std::vector<double>& times = m_nodeTimes[k];
        times.resize(table.nodes().size());
        times[0] = t0;
        if (energy)
            m_closedForm = m_closedForm && table.uniform();
        if (!table.chebPanels().empty())
            m_lazy[k] = std::make_shared<Lazy>(table.panels().size());
        if (!energy) {
            for (std::size_t i = 0; i < times.size(); ++i)
                times[i] = t0 + table.nodes()[i].s * invSpeed;
        } else {
            for (std::size_t i = 0; i < table.panels().size(); ++i) {
                const PathTable::GaussPanel& g = table.panels()[i];
                double dt = 0;
                for (int j = 0; j < gauss::kPoints; ++j)
                    dt += g.weight[j] * std::sqrt(1 + b2 * g.kappa[j] * g.kappa[j]);
                times[i + 1] = times[i] + dt * invSpeed;
            }
        }
        m_pieceStart.push_back(times.back());
    }
}

void TimeLaw::buildPanel(int piece, int k, TimePanel& tp) const {
    const PathTable& table = *m_path->pieces()[piece].table;
    const PathTable::ChebPanel& cp = table.chebPanels()[k];
    if (!cp.certified)
        return;
    const bool energy = m_params.mode == SpeedMode::Energy;
    const double b2 = m_params.system.b * m_params.system.b, invSpeed = 1 / m_params.speed;
    // dt/dxi at the Chebyshev points of the panel's degree, its interpolant, and the
    // interpolant's integral
    const int n = cp.degree;
    std::array<std::array<double, 1>, cheb::kPoints> r, a;
    for (int j = 0; j <= n; ++j) {
        const PathTable::Sample& v = table.samples(k)[j];
        r[j][0] = v.dsdxi * invSpeed * (energy ? std::sqrt(1 + b2 * v.kappa * v.kappa) : 1.0);
    }
    cheb::coefficientsMany(r.data(), n, a.data());
    std::array<double, cheb::kPoints> coef{};
    for (int j = 0; j <= n; ++j)
        coef[j] = a[j][0];
    std::array<double, cheb::kPoints + 1> F{};
    cheb::integrate(coef.data(), n + 1, F.data());
    double duration = 0;
    for (int j = 0; j <= n + 1; ++j) {
        tp.c[j][0] = F[j];
        tp.c[j][1] = j <= n ? coef[j] : 0.0;
        duration += F[j]; // T_k(1) = 1
    }
    tp.rows = n + 2;
    tp.rateStart = r[n][0];
    tp.rateEnd = r[0][0];
    // dr/dxi at the ends: T_k'(1) = k^2, T_k'(-1) = (-1)^(k+1) k^2
    tp.rateSlopeStart = tp.rateSlopeEnd = 0;
    for (int k = 1; k <= n; ++k) {
        tp.rateSlopeEnd += coef[k] * k * k;
        tp.rateSlopeStart += (k % 2 ? 1.0 : -1.0) * coef[k] * k * k;
    }
    // \int |r - p| dxi <= 2 max |r - p|, estimated as twice the tail; and the integral over the
    // panel against the Gauss rule on the exact values (the node times)
    const double gaussDuration = m_nodeTimes[piece][k + 1] - m_nodeTimes[piece][k];
    const double bound =
        std::max(4 * cheb::tailEstimate(a.data(), n + 1, 0), std::fabs(duration - gaussDuration));
    tp.bound = bound;
    // the node times themselves are rounded to a few ulps of t
    const double floor =
        8 * std::numeric_limits<double>::epsilon() * std::fabs(m_nodeTimes[piece][k + 1]);
    tp.certified = bound <= std::max(kTimeTolerance * duration, floor) || cp.noiseLimited;
}

const TimeLaw::TimePanel& TimeLaw::timePanel(int piece, int k) const {
    Lazy& lazy = *m_lazy[piece];
    if (!lazy.ready[k].load(std::memory_order_acquire)) {
        std::lock_guard<std::mutex> lock(lazy.mutex);
        if (!lazy.ready[k].load(std::memory_order_relaxed)) {
            buildPanel(piece, k, lazy.panels[k]);
            lazy.ready[k].store(true, std::memory_order_release);
        }
    }
    return lazy.panels[k];
}

double TimeLaw::timeBound() const {
    double bound = 0;
    for (std::size_t p = 0; p < m_lazy.size(); ++p)
        if (m_lazy[p])
            for (std::size_t k = 0; k < m_lazy[p]->panels.size(); ++k) {
                const TimePanel& tp = timePanel(static_cast<int>(p), static_cast<int>(k));
                if (tp.certified)
                    bound = std::max(bound, tp.bound);
            }
    return bound;
}

int TimeLaw::exactPanels() const {
    int n = 0;
    for (std::size_t p = 0; p < m_lazy.size(); ++p)
        if (m_lazy[p])
            for (std::size_t k = 0; k < m_lazy[p]->panels.size(); ++k)
                n += timePanel(static_cast<int>(p), static_cast<int>(k)).certified ? 0 : 1;
    return n;
}

double TimeLaw::rate(double speed, double kappa) const {
    if (m_params.mode == SpeedMode::Speed)
        return speed / m_params.speed;
    double bk = m_params.system.b * kappa;
    return speed * std::sqrt(1 + bk * bk) / m_params.speed;
}

double TimeLaw::timeAtExact(int piece, double u) const {
    const PathTable& table = *m_path->pieces()[piece].table;
    int k = table.panelOf(u);
    const PathNode& start = table.nodes()[k];
    if (table.uniform())
        return m_nodeTimes[piece][k] + (u - start.u) * rate(start.speed, start.kappa);
    if (m_params.mode == SpeedMode::Speed)
        return m_pieceStart[piece] + table.at(u).s / m_params.speed;
    PathTable::Partial part = table.partial(k, u);
    double t = m_nodeTimes[piece][k];
    for (int i = 0; i < gauss::kPoints; ++i)
        t += part.weight[i] * rate(part.geometry[i].speed, part.geometry[i].kappa);
    return t;
}

TimeLaw::CertifiedPanel TimeLaw::certifiedPanelOf(int piece, double u) const {
    const PathTable& table = *m_path->pieces()[piece].table;
    CertifiedPanel out;
    out.index = table.panelOf(u);
    if (!interpolated(piece))
        return out;
    const TimePanel& tp = timePanel(piece, out.index);
    if (!tp.certified)
        return out;
    const double a = table.nodes()[out.index].u, b = table.nodes()[out.index + 1].u;
    out.panel = &tp;
    out.xi = (2 * u - (a + b)) / (b - a);
    out.halfWidth = 0.5 * (b - a);
    return out;
}

double TimeLaw::timeAt(int piece, double u) const {
    CertifiedPanel p = certifiedPanelOf(piece, u);
    if (!p.panel)
        return timeAtExact(piece, u);
    double f[2];
    cheb::evaluateMany(p.panel->c, p.xi, f, p.panel->rows);
    return m_nodeTimes[piece][p.index] + f[0];
}

double TimeLaw::rateAt(int piece, double u) const {
    CertifiedPanel p = certifiedPanelOf(piece, u);
    if (p.panel)
        return cheb::evaluateOne(p.panel->c, 1, p.xi, p.panel->rows) / p.halfWidth;
    const PathTable& table = *m_path->pieces()[piece].table;
    const int k = p.index;
    if (table.uniform()) {
        const PathNode& n = table.nodes()[k];
        return rate(n.speed, n.kappa);
    }
    return exactRate(table, u);
}

double TimeLaw::exactRate(const PathTable& table, double u) const {
    const PathTable::CuspEnds& ends = table.cuspEnds();
    const std::optional<Cusp>& cusp = u <= table.nodes().front().u ? ends.start : ends.end;
    if (cusp && (u <= table.nodes().front().u || u >= table.nodes().back().u))
        return m_params.system.b * std::fabs(cusp->turnRate) / m_params.speed; // ds = 0 there
    CurveGeometry g = geometryOf(table.curve().eval(u));
    return rate(g.speed, g.kappa);
}

PathLocation TimeLaw::curveLocation(int piece, int panel, double u) const {
    const PathTable& table = *m_path->pieces()[piece].table;
    const double a = table.nodes()[panel].u, b = table.nodes()[panel + 1].u;
    PathLocation loc;
    loc.piece = piece;
    loc.panel = panel;
    loc.u = u;
    loc.xi = std::clamp((2 * u - (a + b)) / (b - a), -1.0, 1.0);
    return loc;
}

PathLocation TimeLaw::locate(double t) const {
    t = std::clamp(t, 0.0, duration());
    auto it = std::upper_bound(m_pieceStart.begin(), m_pieceStart.end() - 1, t);
    int piece = std::clamp(static_cast<int>(it - m_pieceStart.begin()) - 1, 0,
                           static_cast<int>(m_path->pieces().size()) - 1);
    const PathPiece& pp = m_path->pieces()[piece];
    if (pp.kind == PathPiece::Kind::Curve) {
        if (interpolated(piece)) {
            const std::vector<double>& times = m_nodeTimes[piece];
            auto nt = std::upper_bound(times.begin(), times.end(), t);
            int k = std::clamp(static_cast<int>(nt - times.begin()) - 1, 0,
                               static_cast<int>(times.size()) - 2);
            const TimePanel& tp = timePanel(piece, k);
            if (tp.certified) {
                const PathNode &lo = pp.table->nodes()[k], &hi = pp.table->nodes()[k + 1];
                PathLocation loc;
                loc.piece = piece;
                loc.panel = k;
                loc.xi = solveXi(tp, t - times[k], times[k + 1] - times[k]);
                loc.u = 0.5 * (lo.u + hi.u) + 0.5 * (hi.u - lo.u) * loc.xi;
                return loc;
            }
        }
    }
    return locateExact(t);
}

PathLocation TimeLaw::locateExact(double t) const {
    t = std::clamp(t, 0.0, duration());
    auto it = std::upper_bound(m_pieceStart.begin(), m_pieceStart.end() - 1, t);
    int piece = std::clamp(static_cast<int>(it - m_pieceStart.begin()) - 1, 0,
                           static_cast<int>(m_path->pieces().size()) - 1);
    PathLocation loc;
    loc.piece = piece;
    const PathPiece& pp = m_path->pieces()[piece];
    if (pp.kind == PathPiece::Kind::Pivot) {
        loc.sincePivotStart = t - m_pieceStart[piece];
        return loc;
    }
    const PathTable& table = *pp.table;
    const std::vector<double>& times = m_nodeTimes[piece];
    auto nt = std::upper_bound(times.begin(), times.end(), t);
    int k = std::clamp(static_cast<int>(nt - times.begin()) - 1, 0,
                       static_cast<int>(table.panels().size()) - 1);
    const PathNode &lo = table.nodes()[k], &hi = table.nodes()[k + 1];
    if (t == times[k] || t == times[k + 1])
        return curveLocation(piece, k, t == times[k] ? lo.u : hi.u);
    if (table.uniform())
        return curveLocation(
            piece, k, std::clamp(lo.u + (t - times[k]) / rate(lo.speed, lo.kappa), lo.u, hi.u));
    if (m_params.mode == SpeedMode::Speed) {
        double u = table.uAtArcLength((t - m_pieceStart[piece]) * m_params.speed);
        return curveLocation(piece, table.panelOf(u), u);
    }
    // Newton on t(u) = t with dt/du = |r'| sqrt(1 + b^2 kappa^2)/v_T, safeguarded by bisection on
    // the panel: converged at a step below 1e-15 of |u| plus the panel's width (the rounding of t's
    // Gauss sum); on the smooth t(u) Newton takes a few steps, and 40 only bound a bisection
    const NewtonCaps caps{
        .maxIterations = 40,
        .newtonStep = {.value = 1e-15, .relativeToX = true, .scale = hi.u - lo.u}};
    auto timeAt = [&](double u) {
        return NewtonValue{timeAtExact(piece, u) - t, exactRate(table, u)};
    };
    const double u0 = lo.u + (hi.u - lo.u) * (t - times[k]) / (times[k + 1] - times[k]);
    return curveLocation(piece, k, safeguardedNewton(timeAt, u0, {lo.u, hi.u}, caps).x);
}

} // namespace chaplygin
