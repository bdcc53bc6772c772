#pragma once
// The work-precision sweep: every method of the registry over its tolerances or steps, timed and
// compared with a reference (docs/numerics.md §2).
#include "lab/method_registry.h"
#include "scene/scene.h"

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace chaplygin {

/// One configuration of one method on one problem.
struct WorkPrecisionRow {
    MotionProblem problem = MotionProblem::Controlled;
    std::string method;
    double setting = 0;     ///< tolerance, or the step size h [s] of fixed-step methods, 0 for none
    double error = 0;       ///< max |P - P_ref| over the evenly spaced output times [m]
    double seconds = 0;     ///< median wall time of one solve [s]
    long rhsEvals = 0;      ///< right-hand side (or integrand) evaluations of one solve
    double energyDrift = 0; ///< free motion: max |T - T0|/T0
    bool chosen = false;    ///< the app's default configuration
};

struct WorkPrecisionOptions {
    int outputs = 100;              ///< evenly spaced times on [0, t_end], both ends included
    std::vector<double> tolerances; ///< default 1e-3, 1e-4, ..., 1e-13
    std::vector<long> stepCounts;   ///< fixed-step methods: h = t_end/n; default 16, 32, ..., 16384
    double maxSolveSeconds = 0.25;  ///< a method's sweep stops after a solve slower than this
    double minTimingSeconds = 0.02; ///< repeat fast solves until this much time is spent (max 9)
    /// Called after every configuration with (done, total), from the calling thread.
    std::function<void(int, int)> progress;
    /// When set and true, the sweep stops after the configuration under way (GUI cancel button).
    const std::atomic<bool>* cancel = nullptr;
};

struct WorkPrecisionReport {
    std::vector<WorkPrecisionRow> rows;
    /// which solution the errors are measured against
    std::string controlledReference, freeReference;
    /// the registry ids of the reference methods, for a plain name on screen
    std::string controlledReferenceMethod, freeReferenceMethod;
    /// the controlled reference is the tightest method (a different quadrature rule at 1e-14),
    /// or, with no closed form and no such method, the app's own method
    bool controlledReferenceTightest = false, controlledReferenceIndependent = true;
    double controlledEnd = 0, freeEnd = 0; ///< horizons [s]
    /// stopped by options.cancel: rows holds what was done
    bool cancelled = false;
};

/// The speed-against-accuracy sweep for one scene (docs/numerics.md §2).
WorkPrecisionReport runWorkPrecision(const Scene& scene, const WorkPrecisionOptions& options = {});

/// CSV with the header problem,method,tolerance,error,seconds,rhs_evals,chosen (the tolerance
/// column holds the step size h [s] for fixed-step methods and 0 for closed forms).
std::string formatWorkPrecisionCsv(const WorkPrecisionReport& report);

/// JSON for --work-precision --summary: the references, horizons and the chosen rows.
std::string formatWorkPrecisionSummary(const WorkPrecisionReport& report);

/// runWorkPrecision + formatWorkPrecisionCsv, for --headless --work-precision.
std::string workPrecisionCsv(const Scene& scene);

/// True when no other row of the same problem is at least as fast and at least as accurate
/// and strictly better in one of the two.
bool onParetoFront(const std::vector<WorkPrecisionRow>& rows, std::size_t index);

} // namespace chaplygin
