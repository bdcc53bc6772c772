#pragma once
// The app's controlled motion at any time, as the method registry and the open loop read it.
#include "control/control_law.h"
#include "motion/time_law.h"
#include "paths/path.h"

#include <memory>

namespace chaplygin {

/// The app's controlled motion (the time law by Gauss-panel quadrature and Newton inversion,
/// or its closed form on lines and circles) at any time, as the method registry needs it:
/// position, heading, the control angle Psi and the control input's rate chidot.
/// Everything goes through TimeLaw, so the registry times exactly what the app does.
class PlannedMotion {
  public:
    PlannedMotion(std::shared_ptr<const Path> path, const ControlParams& params);

    struct State {
        double x = 0, y = 0, phi = 0; ///< knife point P and unwrapped heading
        double psi = 0;               ///< Psi = atan2(1, b kappa), paper (45), docs/physics.md §2
        double chidot = 0;            ///< chidot = Psidot - (a/b) phidot, from paper (33)
    };
    State at(double t) const;
    /// The knife point P alone (no heading or control: one curve evaluation after locate).
    void position(double t, double* x, double* y) const;
    /// Where the body is at time t (clamped to [0, duration]): TimeLaw::locate.
    PathLocation locate(double t) const;
    const TimeLaw& timeLaw() const { return m_timeLaw; }
    const ControlParams& params() const { return m_params; }

  private:
    std::shared_ptr<const Path> m_path;
    ControlParams m_params;
    TimeLaw m_timeLaw;
};

} // namespace chaplygin
