#pragma once
// The control law on one piece of a path: its heading offset, direction of travel and the limits
// at a cusp end.
#include "control/control_law.h"
#include "paths/path.h"

namespace chaplygin {

/// The control at a node of a Curve piece (a table node or an interpolated one), in the body's
/// frame: the piece's heading offset and direction of travel applied, and the limit at a cusp end
/// (where the node's kappa is infinite; docs/physics.md §3). Returns the body's heading in *phi.
ControlState controlOnPiece(const ControlParams& p, const PathPiece& piece, const PathNode& node,
                            double* phi = nullptr);

} // namespace chaplygin
