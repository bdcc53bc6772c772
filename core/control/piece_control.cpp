#include "control/piece_control.h"

#include <cmath>

namespace chaplygin {

ControlState controlOnPiece(const ControlParams& p, const PathPiece& piece, const PathNode& node,
                            double* phi) {
    const double heading = node.phi + piece.phiOffset;
    if (phi)
        *phi = heading;
    if (!std::isfinite(node.kappa)) {
        const PathTable::CuspEnds& ends = piece.table->cuspEnds();
        const Cusp& cusp = (ends.start && node.u == ends.start->u) ? *ends.start : *ends.end;
        // Psi there: atan2(direction * 0, dphi/du) + the piece's 2 pi n
        const double psi = std::atan2(piece.direction * 0.0, cusp.turnRate) + piece.psiOffset;
        return controlAtCusp(p, heading, psi, cusp.turnRate, cusp.accel);
    }
    // the body's curvature dphi/ds with s along its heading: the table's, reversed when backing
    return controlOnCurve(p, piece.direction * node.kappa, node.dkappa, heading, piece.direction,
                          piece.psiOffset);
}

} // namespace chaplygin
