#pragma once
#include "control/control_law.h"
#include "motion/time_law.h"
#include "numerics/gsl_ode.h"
#include "paths/path.h"
#include "paths/path_projection.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace chaplygin {

/// The controlled motion's control as a signal of time: lambda(t) and the state at t, from the
/// time law and the path table (the values Solution::at gives).
class NominalControl {
  public:
    NominalControl(std::shared_ptr<const Path> path, TimeLaw timeLaw, ControlParams params);
    /// The control at t and, in *phi, *x, *y, the heading and P there.
    ControlState at(double t, double* phi = nullptr, double* x = nullptr,
                    double* y = nullptr) const;
    const ControlParams& params() const { return m_params; }

  private:
    std::shared_ptr<const Path> m_path;
    TimeLaw m_timeLaw;
    ControlParams m_params;
};

/// What is done to the perturbed bodies (docs/physics.md §9): the initial offsets, the push and
/// the feedback's settings (scene.h's Perturbation, with the controller's b resolved).
struct PerturbationSpec {
    double dy = 0, dphi = 0, dpsi = 0;
    std::optional<double> tPush;
    double pushPsi = 0, pushDy = 0;
    double rate = 1;                ///< P [1/m]
    std::optional<double> psiLimit; ///< |Psidot| bound [rad/s]
    double controllerB = 1;         ///< the b the feedback assumes [m]
};

/// The feedback law at one state of the closed-loop body (docs/physics.md §9), each step of
/// u = -P^3 z2 - 3 P^2 z3 - 3 P z4 to the Psidot applied.
struct FeedbackLawValues {
    PathProjection closest;        ///< s_p, the lateral error e and the path's geometry there
    double theta = 0;              ///< heading error phi - phi_path(s_p) [rad]
    double kappaBody = 0;          ///< the body's path curvature phidot/sdot [1/m]
    double sdotPath = 0;           ///< the closest point's speed ds_p/dt [m/s]
    double z2 = 0, z3 = 0, z4 = 0; ///< the chained form: e [m], (1 - kappa e) tan theta, z3'
    double drift = 0, gain = 0;    ///< F and G of z4' = G kappa_b' + F
    double u = 0;                  ///< the triple pole's input [1/m^2]
    double curvatureRate = 0;      ///< kappa_b' = (u - F)/G [1/m^2]
    double psidotAsked = 0;        ///< Psidot before the |Psidot| bound [rad/s]
    bool saturated = false;        ///< the bound holds Psidot
};

/// One perturbed body at time t.
struct PerturbedState {
    double x = 0, y = 0, phi = 0, psi = 0;
    double sdot = 0, phidot = 0, psidot = 0;
    double lambda = 0;     ///< the control input m (b Psidot - a phidot) [kg m/s]
    double energy = 0;     ///< (m/2)(sdot^2 + b^2 phidot^2) [J]
    double error = 0;      ///< feedback body: lateral error e at the closest path point [m]
    double pathS = 0;      ///< feedback body: that point's arc length s_p [m]
    FeedbackLawValues law; ///< feedback body: the law's values (default for the open loop)
};

/// The perturbed body's knife point and its velocity at one accepted step of the integration.
struct TrailKnot {
    double t = 0;          ///< [s]
    double x = 0, y = 0;   ///< [m]
    double vx = 0, vy = 0; ///< [m/s]
};

/// A body of the control-input system x, y, phi, Psi in constant-energy mode
/// (docs/physics.md §9): sdot = v_T sin Psi, b phidot = v_T cos Psi,
/// Psidot = lambda/(m b) + (a/b) phidot, started from the controlled state moved by the
/// perturbation. OpenLoop applies the nominal lambda(t); Feedback the chained-form law
/// (control/path_feedback.h) on top of the nominal feedforward. Integrated once by GSL's rk8pd
/// (from the push on, a second run); a value between the accepted steps is one rk8pd step
/// from the last step before it, so any t has the method's accuracy.
class PerturbedMotion {
  public:
    enum class Kind { OpenLoop, Feedback };
    /// Throws InputError("perturbation") when the feedback body leaves the domain of the chained
    /// form (|theta_e| -> pi/2, 1 - kappa e -> 0 or Psi leaving (0, pi)) or the path, or when a
    /// body needs more than kPerturbedStepBudget steps.
    PerturbedMotion(Kind kind, std::shared_ptr<const NominalControl> nominal, PathFrame frame,
                    const PerturbationSpec& spec, double tEnd);
    PerturbedState at(double t) const;
    Kind kind() const { return m_kind; }
    /// The model used, for the Solution's report.
    std::string model() const;
    /// Accepted steps and right-hand-side calls of the integration.
    const OdeWork& work() const { return m_work; }
    /// The position and velocity at every accepted step, in time order (a push's instant twice,
    /// before and after it): knots for a cubic Hermite drawing of the body's path.
    std::vector<TrailKnot> trailKnots() const;

    class Problem;

  private:
    struct Segment {
        double t0 = 0;
        GslSteps steps;
    };
    Kind m_kind;
    std::shared_ptr<const Problem> m_problem;
    std::vector<Segment> m_segments;
    OdeWork m_work;
};

/// The integrator's tolerance (abs = rel, GSL's standard control).
constexpr double kPerturbedTolerance = 1e-12;
/// The accepted steps one perturbed body may take (both runs, before and after a push): about
/// 0.6 s of one core. A push on 2 km of y = -sin x takes 32,066.
constexpr long kPerturbedStepBudget = 100'000;

} // namespace chaplygin
