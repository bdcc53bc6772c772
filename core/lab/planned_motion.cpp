#include "lab/planned_motion.h"

#include "control/piece_control.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace chaplygin {

PlannedMotion::PlannedMotion(std::shared_ptr<const Path> path, const ControlParams& params)
    : m_path(std::move(path)), m_params(params), m_timeLaw(m_path, params) {}

PathLocation PlannedMotion::locate(double t) const {
    return m_timeLaw.locate(t);
}

void PlannedMotion::position(double t, double* x, double* y) const {
    PathLocation loc = locate(t);
    const PathPiece& piece = m_path->pieces()[loc.piece];
    if (piece.kind == PathPiece::Kind::Pivot) {
        *x = piece.x;
        *y = piece.y;
        return;
    }
    PathNode n = piece.table->interpolatedAt(loc.panel, loc.xi);
    *x = n.x;
    *y = n.y;
}

PlannedMotion::State PlannedMotion::at(double t) const {
    PathLocation loc = locate(t);
    const PathPiece& piece = m_path->pieces()[loc.piece];
    const double a = m_params.system.a, b = m_params.system.b;
    State st;
    if (piece.kind == PathPiece::Kind::Pivot) {
        // pivot about P at |phidot| = v_T/b, Psi = 0 or pi (docs/physics.md §3)
        const double turn = piece.phiTo - piece.phiFrom;
        const double rate = m_params.speed / b;
        st.x = piece.x;
        st.y = piece.y;
        st.phi = piece.phiFrom +
                 std::copysign(std::min(rate * loc.sincePivotStart, std::fabs(turn)), turn);
        st.psi = turn > 0 ? 0.0 : std::numbers::pi;
        st.chidot = -(a / b) * std::copysign(rate, turn);
        return st;
    }
    PathNode n = piece.table->interpolatedAt(loc.panel, loc.xi);
    st.x = n.x;
    st.y = n.y;
    ControlState c = controlOnPiece(m_params, piece, n, &st.phi);
    st.psi = c.psi;
    st.chidot = c.psidot - (a / b) * c.phidot;
    return st;
}

} // namespace chaplygin
