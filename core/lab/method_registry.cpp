#include "lab/method_registry.h"

#include "common/input_error.h"
#include "control/piece_control.h"
#include "lab/quadrature_time_law.h"
#include "lab/sleigh_problems.h"
#include "numerics/fixed_step.h"
#include "numerics/gsl_ode.h"
#include "planning/scene_path.h"
#include "scene/solution.h"

#include <algorithm>
#include <cmath>

namespace chaplygin {

std::string motionProblemName(MotionProblem problem) {
    return problem == MotionProblem::Controlled ? "controlled" : "free";
}

namespace {

// the controlled state at t = 0, where the free motion starts (as the Solution does)
FreeInitial initialOf(const Path& path, const ControlParams& params) {
    const PathPiece& first = path.pieces().front();
    PathNode n = path.start();
    ControlState c = first.kind == PathPiece::Kind::Pivot
                         ? controlAtPivot(params, n.phi, first.phiTo - first.phiFrom)
                         : controlOnPiece(params, first, first.table->nodes().front());
    return {n.x, n.y, n.phi, c.sdot, c.phidot};
}

long stepsFor(double span, double h) {
    return std::max(1L, std::lround(std::ceil(span / h - 1e-9)));
}

std::vector<OdeValue> valuesOf(const DenseOutput& dense, const std::vector<double>& times) {
    std::vector<OdeValue> v(times.size());
    for (std::size_t i = 0; i < times.size(); ++i)
        dense.at(times[i], v[i].data());
    return v;
}

// positions on the path from the curve parameter, the state's first component
MethodOutput controlledFrom(const MethodCase& c, const std::vector<OdeValue>& values,
                            const OdeWork& work) {
    std::vector<double> us(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
        us[i] = values[i][0];
    MethodOutput out = pointsOnCurve(*c.curve, us);
    out.work = work;
    return out;
}

// positions from the state (x, y, ...); energy drift for the free motion, against e0
MethodOutput stateFrom(const std::vector<OdeValue>& values, const OdeWork& work,
                       const FreeProblem* free, double e0) {
    MethodOutput out;
    out.work = work;
    for (const OdeValue& v : values) {
        out.x.push_back(v[0]);
        out.y.push_back(v[1]);
        if (free)
            out.energyDrift = std::max(out.energyDrift, std::fabs(free->energy(v.data()) - e0) /
                                                            std::max(e0, 1e-300));
    }
    return out;
}

std::vector<double> freeStart(const MethodCase& c) {
    const FreeInitial& f = c.freeInitial;
    return {f.x, f.y, f.phi, f.sdot, f.phidot};
}

std::vector<double> openLoopStart(const MethodCase& c) {
    PlannedMotion::State s = c.plan->at(0);
    return {s.x, s.y, s.phi};
}

const GslStepper kSteppers[] = {GslStepper::Rk4,   GslStepper::Rkf45,   GslStepper::Rkck,
                                GslStepper::Rk8pd, GslStepper::MsAdams, GslStepper::MsBdf};

void addControlled(const MethodCase& c, std::vector<Method>& out) {
    Method app;
    app.name = c.plan->timeLaw().closedForm() ? "closed_form" : "quadrature_gauss_newton";
    app.problem = MotionProblem::Controlled;
    app.setting = SettingKind::None;
    app.appDefault = true;
    app.description =
        c.plan->timeLaw().closedForm()
            ? "closed-form time law (constant curvature)"
            : "the app's time law: certified per-panel Chebyshev interpolants of the path "
              "table, Newton on the interpolated t(u)";
    app.solve = [](const MethodCase& k, double, const std::vector<double>& times) {
        PlannedMotion plan(k.path, k.params);
        MethodOutput o;
        o.x.resize(times.size());
        o.y.resize(times.size());
        for (std::size_t i = 0; i < times.size(); ++i)
            plan.position(times[i], &o.x[i], &o.y[i]);
        return o;
    };
    out.push_back(app);
    if (!c.curve)
        return;

    Method qag;
    qag.name = "gsl_qag_newton";
    qag.problem = MotionProblem::Controlled;
    qag.description = "GSL QAG (Gauss-Kronrod 21) of dt/du, Newton for u(t)";
    qag.solve = [](const MethodCase& k, double tol, const std::vector<double>& times) {
        QuadratureTimeLaw law(*k.curve, k.params, tol);
        OdeWork work;
        std::vector<double> us = law.invert(times, work);
        MethodOutput o = pointsOnCurve(*k.curve, us);
        o.work = work;
        return o;
    };
    out.push_back(qag);

    for (GslStepper st : kSteppers) {
        Method m;
        m.name = gslStepperName(st);
        m.problem = MotionProblem::Controlled;
        m.description =
            "ODE in t for the path parameter, du/dt = sdot/|r'|, GSL " + m.name.substr(4);
        m.solve = [st](const MethodCase& k, double tol, const std::vector<double>& times) {
            ControlledProblem prob(*k.curve, k.params);
            double u0 = k.curve->u0();
            GslSolve s = integrateGsl(prob, st, 0, &u0, k.controlledEnd, tol);
            std::vector<OdeValue> v = gslValuesAt(prob, st, s, times);
            return controlledFrom(k, v, s.work);
        };
        out.push_back(m);
    }

    Method rk4;
    rk4.name = "rk4_classical";
    rk4.problem = MotionProblem::Controlled;
    rk4.setting = SettingKind::StepSize;
    rk4.order = 4;
    rk4.description = "ODE in t for the path parameter, hand-written classical RK4, fixed step";
    rk4.solve = [](const MethodCase& k, double h, const std::vector<double>& times) {
        ControlledProblem prob(*k.curve, k.params);
        double u0 = k.curve->u0();
        FixedStepSolve s =
            integrateRk4(prob, 0, &u0, k.controlledEnd, stepsFor(k.controlledEnd, h));
        return controlledFrom(k, valuesOf(s.dense, times), s.work);
    };
    out.push_back(rk4);

    if (c.params.mode != SpeedMode::Energy)
        return;
    Method open;
    open.name = "open_loop_gsl_rk8pd";
    open.problem = MotionProblem::Controlled;
    open.description =
        "the paper's open-loop eqs. (35)-(37) in (x, y, phi) with chi(t) given, GSL rk8pd";
    open.solve = [](const MethodCase& k, double tol, const std::vector<double>& times) {
        OpenLoopProblem prob(*k.plan);
        std::vector<double> y0 = openLoopStart(k);
        GslSolve s = integrateGsl(prob, GslStepper::Rk8pd, 0, y0.data(), k.controlledEnd, tol);
        std::vector<OdeValue> v = gslValuesAt(prob, GslStepper::Rk8pd, s, times);
        return stateFrom(v, s.work, nullptr, 0);
    };
    out.push_back(open);
    Method openRk4 = open;
    openRk4.name = "open_loop_rk4_classical";
    openRk4.setting = SettingKind::StepSize;
    openRk4.order = 4;
    openRk4.description = "the paper's open-loop eqs. (35)-(37), classical RK4, fixed step";
    openRk4.solve = [](const MethodCase& k, double h, const std::vector<double>& times) {
        OpenLoopProblem prob(*k.plan);
        std::vector<double> y0 = openLoopStart(k);
        FixedStepSolve s =
            integrateRk4(prob, 0, y0.data(), k.controlledEnd, stepsFor(k.controlledEnd, h));
        return stateFrom(valuesOf(s.dense, times), s.work, nullptr, 0);
    };
    out.push_back(openRk4);
}

void addFree(std::vector<Method>& out) {
    Method app;
    app.name = "closed_form";
    app.problem = MotionProblem::Free;
    app.setting = SettingKind::None;
    app.appDefault = true;
    app.description = "closed-form velocities and heading, Gauss-panel position (FreeMotion)";
    app.solve = [](const MethodCase& k, double, const std::vector<double>& times) {
        FreeMotion free(k.params.system, k.freeInitial, k.freeEnd);
        MethodOutput o;
        const double b2 = k.params.system.b * k.params.system.b;
        const double e0 = k.freeInitial.sdot * k.freeInitial.sdot +
                          b2 * k.freeInitial.phidot * k.freeInitial.phidot;
        for (double t : times) {
            FreeState s = free.at(t);
            o.x.push_back(s.x);
            o.y.push_back(s.y);
            double e = s.sdot * s.sdot + b2 * s.phidot * s.phidot;
            o.energyDrift = std::max(o.energyDrift, std::fabs(e - e0) / std::max(e0, 1e-300));
        }
        return o;
    };
    out.push_back(app);

    for (GslStepper st : kSteppers) {
        Method m;
        m.name = gslStepperName(st);
        m.problem = MotionProblem::Free;
        m.description = "(x, y, phi, sdot, phidot) with eqs. (D12)-(D13), GSL " + m.name.substr(4);
        m.solve = [st](const MethodCase& k, double tol, const std::vector<double>& times) {
            FreeProblem prob(k.params.system);
            std::vector<double> y0 = freeStart(k);
            GslSolve s = integrateGsl(prob, st, 0, y0.data(), k.freeEnd, tol);
            std::vector<OdeValue> v = gslValuesAt(prob, st, s, times);
            return stateFrom(v, s.work, &prob, prob.energy(y0.data()));
        };
        out.push_back(m);
    }

    for (bool project : {false, true}) {
        Method m;
        m.name = project ? "rk4_energy_projection" : "rk4_classical";
        m.problem = MotionProblem::Free;
        m.setting = SettingKind::StepSize;
        m.order = 4;
        m.description =
            project ? "classical RK4, fixed step, (sdot, phidot) projected onto the energy level"
                    : "classical RK4, fixed step";
        m.solve = [project](const MethodCase& k, double h, const std::vector<double>& times) {
            FreeProblem prob(k.params.system);
            std::vector<double> y0 = freeStart(k);
            const double e0 = prob.energy(y0.data());
            StepProjection proj;
            if (project)
                proj = [&prob, e0](double* y) { prob.projectToEnergy(y, e0); };
            FixedStepSolve s =
                integrateRk4(prob, 0, y0.data(), k.freeEnd, stepsFor(k.freeEnd, h), proj);
            return stateFrom(valuesOf(s.dense, times), s.work, &prob, e0);
        };
        out.push_back(m);
    }
}

} // namespace

MethodOutput pointsOnCurve(const Curve& curve, const std::vector<double>& us) {
    MethodOutput out;
    out.x.reserve(us.size());
    out.y.reserve(us.size());
    for (double u : us) {
        const CurvePoint p = curve.eval(u);
        out.x.push_back(p.x);
        out.y.push_back(p.y);
    }
    return out;
}

MethodCase::MethodCase(const Scene& s) : MethodCase(s, buildScenePath(s.path)) {}

MethodCase::MethodCase(const Scene& s, std::shared_ptr<const Path> p)
    : scene(s), path(std::move(p)), params(controlParamsOf(s)) {
    plan = std::make_shared<PlannedMotion>(path, params);
    freeInitial = initialOf(*path, params);
    const double duration = plan->timeLaw().duration();
    double tEnd = duration;
    if (s.tEnd) {
        tEnd = *s.tEnd;
        if (!std::isfinite(tEnd) || !(tEnd > 0))
            throw InputError("t_end", "must be a finite number > 0, got " + formatNumber(tEnd));
    }
    controlledEnd = std::min(tEnd, duration);
    freeEnd = tEnd;
    const auto& pieces = path->pieces();
    if (pieces.size() == 1 && pieces.front().kind == PathPiece::Kind::Curve)
        curve = &pieces.front().table->curve();
}

std::vector<Method> methodRegistry(const MethodCase& c) {
    std::vector<Method> out;
    addControlled(c, out);
    addFree(out);
    return out;
}

} // namespace chaplygin
