#pragma once
// The method registry: every method that solves a scene's controlled or free motion, prepared
// once per scene (docs/numerics.md §1).
#include "control/control_law.h"
#include "lab/planned_motion.h"
#include "motion/free_motion.h"
#include "numerics/ode_problem.h"
#include "paths/path.h"
#include "scene/scene.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace chaplygin {

/// The two problems each scene poses: the controlled motion along the path and the free motion
/// from the same initial state.
enum class MotionProblem { Controlled, Free };
std::string motionProblemName(MotionProblem problem);

/// What the methods of one scene share, prepared once: the tabulated path, the parameters,
/// the app's planned motion, the free initial state and both horizons.
struct MethodCase {
    /// Builds the path; throws InputError for bad input. The controlled horizon is
    /// min(t_end, the time to traverse the path); the free motion runs to t_end itself.
    explicit MethodCase(const Scene& scene);
    MethodCase(const Scene& scene, std::shared_ptr<const Path> path);

    Scene scene;
    std::shared_ptr<const Path> path;
    ControlParams params;
    std::shared_ptr<const PlannedMotion> plan;
    FreeInitial freeInitial;
    double controlledEnd = 0; ///< [s]
    double freeEnd = 0;       ///< [s]
    /// The path's curve when the path is one smooth piece (the ODE methods need it), else null.
    const Curve* curve = nullptr;
};

/// The knife point P at the requested times, and the work it took.
struct MethodOutput {
    std::vector<double> x, y;
    double energyDrift = 0; ///< free motion: max |T(t) - T(0)|/T(0) over the requested times
    OdeWork work;
};

/// P = (x, y) on the curve at each curve parameter u of us: the controlled motion's positions once
/// a method has found u(t).
MethodOutput pointsOnCurve(const Curve& curve, const std::vector<double>& us);

/// How a method's accuracy is set: not at all, by a tolerance, or by a fixed step [s].
enum class SettingKind { None, Tolerance, StepSize };

/// One entry of the registry.
struct Method {
    std::string name;
    MotionProblem problem = MotionProblem::Controlled;
    SettingKind setting = SettingKind::Tolerance;
    bool appDefault = false; ///< the configuration the app uses (chosen = 1)
    int order = 0;           ///< the convergence order in the step size (fixed-step methods)
    std::string description;
    /// Solves on [0, horizon] and evaluates at the ascending times (within the horizon).
    std::function<MethodOutput(const MethodCase&, double setting, const std::vector<double>& times)>
        solve;
};

/// The methods that apply to the case: closed form or Gauss-panel quadrature (app default),
/// GSL QAG + Newton, the six GSL steppers, classical RK4 and the open-loop paper (35)-(37) for the
/// controlled motion (the ODE methods need a path of one smooth piece; open loop needs Energy
/// mode); closed form (app default), the six GSL steppers, classical RK4 and RK4 with energy
/// projection for the free motion.
std::vector<Method> methodRegistry(const MethodCase& c);

} // namespace chaplygin
