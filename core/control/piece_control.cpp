#include "control/piece_control.h"

#include <cmath>

namespace chaplygin {

ControlState controlOnPiece(const ControlParams& p, const PathPiece& piece, const PathNode& node,
                            double* phi) {
    const double heading = node.phi + piece.phiOffset;
    if (phi)
        *phi = heading;
    const PathTable::CuspEnds& ends = piece.table->cuspEnds();
    if (!std::isfinite(node.kappa) && (ends.start || ends.end)) {
        // at a cusp end, or so close to it that |r'|^3 underflows: the limit at the nearer one
        const bool start = ends.start && (!ends.end || std::fabs(node.u - ends.start->u) <=
                                                           std::fabs(node.u - ends.end->u));
        const Cusp& cusp = start ? *ends.start : *ends.end;
        const double psi = psiAtCusp(cusp, piece.direction) + piece.psiOffset;
        // sigma falls through 0 into a backing stretch and out of one, rises otherwise
        const int slope = start ? piece.direction : -piece.direction;
        return controlAtCusp(p, heading, psi, cusp.turnRate, cusp.accel, slope);
    }
    // the body's curvature dphi/ds with s along its heading: the table's, reversed when backing
    return controlOnCurve(p, piece.direction * node.kappa, node.dkappa, heading, piece.direction,
                          piece.psiOffset);
}

} // namespace chaplygin
