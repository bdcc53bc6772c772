#pragma once
#include "paths/path_table.h"

#include <memory>
#include <stdexcept>

namespace chaplygin {

/// The path's geometry at a curve parameter, with the second arc-length derivative of the
/// curvature that the feedback law needs (docs/physics.md §9).
struct PathPoint {
    double u = 0, s = 0, x = 0, y = 0, phi = 0;
    double kappa = 0, dkappa = 0, ddkappa = 0; ///< kappa, d kappa/ds, d^2 kappa/ds^2
    double speed = 0;                          ///< ds/du
};

/// The closest point of a path to a point near it: the body's path coordinate s_p, lateral
/// error e (> 0 to the left of the tangent) and the path's geometry there (docs/physics.md §9).
struct PathProjection {
    PathPoint point;
    double e = 0;
};

/// Newton's projection found no closest point near its guess: the point is farther from the path
/// than the path's bends allow (beyond a centre of curvature, or where the path folds back).
struct PathProjectionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A smooth tabulated curve as a frame for the feedback law: the geometry at any u from the table's
/// interpolants, continued beyond the ends along the osculating circle there (constant kappa), and
/// the projection of a point by Newton's method from a nearby u.
class PathFrame {
  public:
    /// phiOffset: the piece's 2 pi n added to the table's heading.
    PathFrame(std::shared_ptr<const PathTable> table, double phiOffset);

    /// Geometry at u; kappa'' from the derivative of the certified interpolant of kappa_s (0 on
    /// lines and circles, and on a panel left to exact evaluation).
    PathPoint at(double u) const;
    /// The closest point to (x, y) from the guess u: Newton on (P - r(u)) . t(u) = 0, whose
    /// derivative is -|r'| (1 - kappa e). Throws PathProjectionError when it does not converge.
    PathProjection project(double x, double y, double uGuess) const;
    double u0() const { return m_u0; }
    double u1() const { return m_u1; }

  private:
    PathPoint beyond(const PathNode& end, double u) const;
    std::shared_ptr<const PathTable> m_table;
    double m_phiOffset = 0;
    double m_u0 = 0, m_u1 = 0;
    PathNode m_start, m_end;
};

} // namespace chaplygin
