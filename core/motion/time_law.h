#pragma once
#include "control/control_law.h"
#include "paths/path.h"

#include <memory>
#include <vector>

namespace chaplygin {

/// Where the body is on the path at a time: a piece, and the curve parameter u in it (Curve)
/// or the time since the pivot began (Pivot).
struct PathLocation {
    int piece = 0;
    double u = 0;
    double sincePivotStart = 0;
};

/// The time law t(s) and its inverse for one path and one set of control parameters.
/// Energy mode: dt/ds = sqrt(1 + b^2 kappa^2)/v_T (docs/physics.md §2), summed over the path
/// table's Gauss nodes; pivots take b |dphi|/v_T. Speed mode: t = s/v_s (App. C).
/// Building it never re-tabulates the path: it costs one pass over the stored nodes.
class TimeLaw {
  public:
    /// Throws InputError when the mode cannot follow the path (a corner in Speed mode) or the
    /// speed is not a finite positive number.
    TimeLaw(std::shared_ptr<const Path> path, const ControlParams& params);

    double duration() const { return m_pieceStart.back(); }
    double pieceStart(int piece) const { return m_pieceStart[piece]; }
    /// Times at the panel ends of a Curve piece.
    const std::vector<double>& nodeTimes(int piece) const { return m_nodeTimes[piece]; }
    /// t at parameter u of a Curve piece (exact: Gauss quadrature over the partial panel).
    double timeAt(int piece, double u) const;
    /// The inverse: where the body is at time t (clamped to [0, duration]).
    PathLocation locate(double t) const;
    /// True when every piece's time law is closed form (lines, circles, pivots, Speed mode).
    bool closedForm() const { return m_closedForm; }

  private:
    double rate(double speed, double kappa) const; // dt/du
    std::shared_ptr<const Path> m_path;
    ControlParams m_params;
    std::vector<double> m_pieceStart; // size pieces + 1
    std::vector<std::vector<double>> m_nodeTimes;
    bool m_closedForm = true;
};

} // namespace chaplygin
