#include "motion/time_law.h"

#include "common/input_error.h"

#include <algorithm>
#include <cmath>

namespace chaplygin {

TimeLaw::TimeLaw(std::shared_ptr<const Path> path, const ControlParams& params)
    : m_path(std::move(path)), m_params(params) {
    if (!std::isfinite(params.speed) || !(params.speed > 0))
        throw InputError("speed", "must be a finite number > 0, got " + formatNumber(params.speed));
    const auto& pieces = m_path->pieces();
    m_pieceStart.assign(1, 0.0);
    m_nodeTimes.resize(pieces.size());
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const PathPiece& piece = pieces[k];
        double t0 = m_pieceStart.back();
        if (piece.kind == PathPiece::Kind::Pivot) {
            if (params.mode == SpeedMode::Speed)
                throw InputError(
                    "corner at (" + formatNumber(piece.x) + ", " + formatNumber(piece.y) + ")",
                    "constant-speed mode cannot turn a corner (the kinetic energy would be "
                    "infinite); use the constant-energy mode or smooth corners");
            // pivot about P: |phidot| = v_T/b, so it takes b |dphi|/v_T (sec. 2.8)
            m_pieceStart.push_back(t0 + params.system.b * std::fabs(piece.phiTo - piece.phiFrom) /
                                            params.speed);
            continue;
        }
        const PathTable& table = *piece.table;
        std::vector<double>& times = m_nodeTimes[k];
        times.resize(table.nodes().size());
        times[0] = t0;
        if (params.mode == SpeedMode::Speed) {
            for (std::size_t i = 0; i < times.size(); ++i)
                times[i] = t0 + table.nodes()[i].s / params.speed;
        } else {
            m_closedForm = m_closedForm && table.uniform();
            const double b2 = params.system.b * params.system.b;
            for (std::size_t i = 0; i < table.panels().size(); ++i) {
                const PathTable::GaussPanel& g = table.panels()[i];
                double dt = 0;
                for (int j = 0; j < gauss::kPoints; ++j)
                    dt += g.weight[j] * std::sqrt(1 + b2 * g.kappa[j] * g.kappa[j]);
                times[i + 1] = times[i] + dt / params.speed;
            }
        }
        m_pieceStart.push_back(times.back());
    }
}

double TimeLaw::rate(double speed, double kappa) const {
    if (m_params.mode == SpeedMode::Speed)
        return speed / m_params.speed;
    double bk = m_params.system.b * kappa;
    return speed * std::sqrt(1 + bk * bk) / m_params.speed;
}

double TimeLaw::timeAt(int piece, double u) const {
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

PathLocation TimeLaw::locate(double t) const {
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
    if (t == times[k] || t == times[k + 1]) {
        loc.u = t == times[k] ? lo.u : hi.u;
        return loc;
    }
    if (table.uniform()) {
        loc.u = std::clamp(lo.u + (t - times[k]) / rate(lo.speed, lo.kappa), lo.u, hi.u);
        return loc;
    }
    if (m_params.mode == SpeedMode::Speed) {
        loc.u = table.uAtArcLength((t - m_pieceStart[piece]) * m_params.speed);
        return loc;
    }
    // Newton on t(u) = t with dt/du = |r'| sqrt(1 + b^2 kappa^2)/v_T, safeguarded by bisection
    double a = lo.u, b = hi.u;
    double u = a + (b - a) * (t - times[k]) / (times[k + 1] - times[k]);
    for (int iter = 0; iter < 40; ++iter) {
        double f = timeAt(piece, u) - t;
        (f > 0 ? b : a) = u;
        CurveGeometry g = geometryOf(table.curve().eval(u));
        double step = f / rate(g.speed, g.kappa);
        if (std::fabs(step) <= 1e-15 * (std::fabs(u) + (hi.u - lo.u))) {
            u -= step;
            break;
        }
        u = (u - step > a && u - step < b) ? u - step : 0.5 * (a + b);
    }
    loc.u = u;
    return loc;
}

} // namespace chaplygin
