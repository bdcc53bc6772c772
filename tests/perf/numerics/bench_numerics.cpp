// chaplygin-bench-numerics: cost per right-hand-side call and per solve of every method in the
// registry (docs/numerics.md §3, §5). Compare counters ns_per_rhs against BM_Rk4ClassicalFloor, the
// hand-written classical RK4 on the same problem: the floor.
#include "common/memory_reuse.h"
#include "lab/method_registry.h"
#include "lab/sleigh_problems.h"
#include "lab/work_precision.h"
#include "numerics/fixed_step.h"
#include "numerics/gsl_ode.h"
#include "paths/path.h"
#include "scene/presets.h"
#include "scene/solution.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace chaplygin {
namespace {

// the catenary scene with t_end = 10, built once
const MethodCase& catenary() {
    static const std::unique_ptr<MethodCase> c = [] {
        Scene s = presetScene("catenary");
        s.tEnd = 10;
        return std::make_unique<MethodCase>(s);
    }();
    return *c;
}

std::vector<double> evenTimes(double end, int count = 100) {
    std::vector<double> t(count);
    for (int i = 0; i < count; ++i)
        t[i] = i + 1 == count ? end : end * i / (count - 1);
    return t;
}

void BM_RhsControlled(benchmark::State& state) {
    ControlledProblem p(*catenary().curve, catenary().params);
    double u = 1.3, f = 0;
    for (auto _ : state) {
        p.rhs(0, &u, &f);
        benchmark::DoNotOptimize(f);
        u += 1e-9;
    }
}
BENCHMARK(BM_RhsControlled);

void BM_RhsFree(benchmark::State& state) {
    FreeProblem p(catenary().params.system);
    double y[5] = {1, 0.5, 0.3, 0.7, -0.4}, f[5];
    for (auto _ : state) {
        p.rhs(0, y, f);
        benchmark::DoNotOptimize(f);
        y[2] += 1e-9;
    }
}
BENCHMARK(BM_RhsFree);

void BM_RhsOpenLoop(benchmark::State& state) {
    OpenLoopProblem p(*catenary().plan);
    double y[3] = {1.2, 0.6, 0.3}, f[3];
    double t = 1.0;
    for (auto _ : state) {
        p.rhs(t, y, f);
        benchmark::DoNotOptimize(f);
        t += 1e-9;
    }
}
BENCHMARK(BM_RhsOpenLoop);

// the controlled state at one t (position, heading, curvature, Psi, chidot) from the
// interpolants: locate (Newton on the interpolated t(u)) + geometry + control law
void BM_StateAt(benchmark::State& state) {
    const MethodCase& c = catenary();
    const double end = c.controlledEnd;
    double t = 0.1234;
    for (auto _ : state) {
        PlannedMotion::State s = c.plan->at(t);
        benchmark::DoNotOptimize(s);
        t += 0.0137;
        if (t > end)
            t -= end;
    }
}
BENCHMARK(BM_StateAt);

// the same with exact curve evaluation (the reference): Newton on the Gauss quadrature of t(u)
void BM_StateAtExact(benchmark::State& state) {
    const MethodCase& c = catenary();
    const double end = c.controlledEnd;
    const PathTable& table = *c.path->pieces().front().table;
    double t = 0.1234;
    for (auto _ : state) {
        PathLocation loc = c.plan->timeLaw().locateExact(t);
        PathNode n = table.at(loc.u);
        ControlState s = controlOnCurve(c.params, n.kappa, n.dkappa, n.phi);
        benchmark::DoNotOptimize(s);
        t += 0.0137;
        if (t > end)
            t -= end;
    }
}
BENCHMARK(BM_StateAtExact)->Unit(benchmark::kMicrosecond);

// both bodies at one t, as the GUI and the CSV read them (Solution::at)
void BM_SolutionAt(benchmark::State& state) {
    static const Solution sol = [] {
        Scene s = presetScene("catenary");
        s.tEnd = 5;
        return Solution::compute(s);
    }();
    double t = 0.1234;
    for (auto _ : state) {
        MotionSample m = sol.at(t);
        benchmark::DoNotOptimize(m);
        t += 0.0137;
        if (t > 5)
            t -= 5;
    }
}
BENCHMARK(BM_SolutionAt);

// the controlled right-hand side du/dt = 1/(dt/du) from the interpolated time law
void BM_RhsControlledTable(benchmark::State& state) {
    const TimeLaw& law = catenary().plan->timeLaw();
    double u = 1.3, f = 0;
    for (auto _ : state) {
        f = 1 / law.rateAt(0, u);
        benchmark::DoNotOptimize(f);
        u += 1e-7;
        if (u > 5)
            u = 0;
    }
}
BENCHMARK(BM_RhsControlledTable);

// what a parameter change (a, b, m, v_T) rebuilds on an already tabulated path: the time law
void BM_RebuildTimeLaw(benchmark::State& state, std::string preset) {
    Scene s = presetScene(preset);
    auto path = buildPath(s.path);
    ControlParams params = controlParamsOf(s);
    double b = params.system.b;
    for (auto _ : state) {
        params.system.b = b + 1e-9 * (state.iterations() % 2);
        TimeLaw law(path, params);
        benchmark::DoNotOptimize(law.duration());
    }
    state.counters["panels"] = static_cast<double>(path->pieces().front().table->panels().size());
}
BENCHMARK_CAPTURE(BM_RebuildTimeLaw, catenary, std::string("catenary"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_RebuildTimeLaw, sinusoid, std::string("sinusoid"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_RebuildTimeLaw, line, std::string("line"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_RebuildTimeLaw, circle, std::string("circle"))->Unit(benchmark::kMicrosecond);

// a parameter change with the perturbed bodies on (docs/physics.md §9): Solution::compute on the
// tabulated path, both bodies integrated by rk8pd; arg 0 is the same scene without a perturbation
Scene perturbedScene(const std::string& name) {
    Scene s = presetScene(name == "long_circle" ? "circle" : name);
    if (name == "long_circle")
        s.path.to = 30;
    s.perturbation = Perturbation{};
    s.perturbation->dy = 0.3;
    return s;
}
void BM_RecomputePerturbed(benchmark::State& state, std::string name) {
    Scene s = perturbedScene(name);
    if (state.range(0) == 0)
        s.perturbation.reset();
    auto path = buildPath(s.path);
    long rhs = 0;
    for (auto _ : state) {
        s.system.params["b"] = 1 + 1e-9 * static_cast<double>(state.iterations() % 2);
        const Solution sol = Solution::compute(s, path);
        if (sol.perturbed())
            rhs = sol.openLoop()->work().rhsEvals + sol.feedback()->work().rhsEvals;
        benchmark::DoNotOptimize(sol.duration());
    }
    state.counters["rhs_evals"] = static_cast<double>(rhs);
}
BENCHMARK_CAPTURE(BM_RecomputePerturbed, line, std::string("line"))
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RecomputePerturbed, circle, std::string("circle"))
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RecomputePerturbed, long_circle, std::string("long_circle"))
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RecomputePerturbed, sinusoid, std::string("sinusoid"))
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond);

// the free motion's parameter-dependent part (FreeMotion over the catenary's 10 s)
void BM_RebuildFreeMotion(benchmark::State& state) {
    const MethodCase& c = catenary();
    for (auto _ : state) {
        FreeMotion free(c.params.system, c.freeInitial, c.freeEnd);
        benchmark::DoNotOptimize(free.horizon());
    }
}
BENCHMARK(BM_RebuildFreeMotion)->Unit(benchmark::kMicrosecond);

// tabulation: the presets, 500-point polylines (pivot corners) and drawn strokes (smoothed)
PathSource strokeOf(int points, CornerMode corners) {
    PathSource p;
    p.kind = PathKind::Polyline;
    p.corners = corners;
    p.smoothing = 10; // the app's default bandwidth
    for (int i = 0; i < points; ++i) {
        double th = 3.0 * i / points;
        p.points.push_back({3 * std::cos(th) + 0.01 * std::sin(7.0 * i),
                            3 * std::sin(th) + 0.01 * std::cos(5.0 * i)});
    }
    return p;
}

void BM_Tabulate(benchmark::State& state, PathSource source) {
    std::size_t panels = 0, lowDegree = 0;
    for (auto _ : state) {
        auto path = buildPath(source);
        panels = lowDegree = 0;
        for (const PathPiece& p : path->pieces())
            if (p.kind == PathPiece::Kind::Curve) {
                panels += p.table->panels().size();
                for (const PathTable::ChebPanel& c : p.table->chebPanels())
                    lowDegree += c.degree == cheb::kLowDegree ? 1 : 0;
            }
        benchmark::DoNotOptimize(path.get());
    }
    state.counters["panels"] = static_cast<double>(panels);
    state.counters["low_degree"] = static_cast<double>(lowDegree);
}
BENCHMARK_CAPTURE(BM_Tabulate, catenary, presetScene("catenary").path)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Tabulate, sinusoid, presetScene("sinusoid").path)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Tabulate, polyline500_pivot, strokeOf(500, CornerMode::Pivot))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Tabulate, stroke500_smooth, strokeOf(500, CornerMode::Smooth))
    ->Unit(benchmark::kMicrosecond);

// the bare floor: classical RK4 steps on the free sleigh with no dense output, no virtual call
void BM_Rk4BareStep(benchmark::State& state) {
    FreeProblem p(catenary().params.system);
    double y[5] = {1, 0, 1.5707963267948966, 0.7071067811865476, -0.7071067811865476};
    double k1[5], k2[5], k3[5], k4[5], tmp[5];
    const double h = 10.0 / 1024;
    double t = 0;
    for (auto _ : state) {
        p.FreeProblem::rhs(t, y, k1);
        for (int j = 0; j < 5; ++j)
            tmp[j] = y[j] + 0.5 * h * k1[j];
        p.FreeProblem::rhs(t + 0.5 * h, tmp, k2);
        for (int j = 0; j < 5; ++j)
            tmp[j] = y[j] + 0.5 * h * k2[j];
        p.FreeProblem::rhs(t + 0.5 * h, tmp, k3);
        for (int j = 0; j < 5; ++j)
            tmp[j] = y[j] + h * k3[j];
        p.FreeProblem::rhs(t + h, tmp, k4);
        for (int j = 0; j < 5; ++j)
            y[j] += h / 6.0 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
        t += h;
        benchmark::DoNotOptimize(y);
    }
    state.counters["ns_per_rhs"] = benchmark::Counter(
        4e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Rk4BareStep);

// hand-written classical RK4, 1024 steps with dense output, per solve and per RHS call: the floor
void BM_Rk4ClassicalFloor(benchmark::State& state) {
    const bool free = state.range(0) == 1;
    const MethodCase& c = catenary();
    FreeProblem fp(c.params.system);
    ControlledProblem cp(*c.curve, c.params);
    const OdeProblem& p = free ? static_cast<const OdeProblem&>(fp) : cp;
    const double end = free ? c.freeEnd : c.controlledEnd;
    double y0[5] = {c.freeInitial.x, c.freeInitial.y, c.freeInitial.phi, c.freeInitial.sdot,
                    c.freeInitial.phidot};
    double u0 = c.curve->u0();
    long evals = 0;
    for (auto _ : state) {
        FixedStepSolve s = integrateRk4(p, 0, free ? y0 : &u0, end, 1024);
        evals = s.work.rhsEvals;
        benchmark::DoNotOptimize(s.dense.size());
    }
    state.counters["rhs_evals"] = static_cast<double>(evals);
    state.counters["ns_per_rhs"] = benchmark::Counter(
        static_cast<double>(evals) * 1e-9,
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.SetLabel(free ? "free" : "controlled");
}
BENCHMARK(BM_Rk4ClassicalFloor)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// every registry method at tolerance 1e-10 (fixed-step methods: h = t_end/1024), 100 outputs
void BM_Solve(benchmark::State& state, std::string problem, std::string method) {
    const MethodCase& c = catenary();
    std::vector<Method> methods = methodRegistry(c);
    const Method* m = nullptr;
    for (const Method& k : methods)
        if (motionProblemName(k.problem) == problem && k.name == method)
            m = &k;
    if (!m) {
        state.SkipWithError("no such method");
        return;
    }
    const bool controlled = m->problem == MotionProblem::Controlled;
    const double end = controlled ? c.controlledEnd : c.freeEnd;
    const std::vector<double> times = evenTimes(end);
    const double setting = m->setting == SettingKind::StepSize ? end / 1024 : 1e-10;
    long evals = 0;
    for (auto _ : state) {
        MethodOutput o = m->solve(c, setting, times);
        evals = o.work.rhsEvals;
        benchmark::DoNotOptimize(o.x.data());
    }
    state.counters["rhs_evals"] = static_cast<double>(evals);
    if (evals > 0)
        state.counters["ns_per_rhs"] = benchmark::Counter(
            static_cast<double>(evals) * 1e-9,
            benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// the app's chosen configuration is on the Pareto front of the catenary's
// work-precision chart (t_end = 10). One iteration is one whole sweep; the counters say whether
// each chosen row is on the front, and the run fails if one is not.
void BM_ChosenOnParetoFront(benchmark::State& state) {
    Scene scene = presetScene("catenary");
    scene.tEnd = 10;
    double controlled = 0, free = 0;
    for (auto _ : state) {
        WorkPrecisionReport r = runWorkPrecision(scene);
        for (std::size_t i = 0; i < r.rows.size(); ++i)
            if (r.rows[i].chosen)
                (r.rows[i].problem == MotionProblem::Controlled ? controlled : free) =
                    onParetoFront(r.rows, i) ? 1 : 0;
    }
    state.counters["controlled_chosen_on_front"] = controlled;
    state.counters["free_chosen_on_front"] = free;
    if (controlled != 1 || free != 1)
        state.SkipWithError("a chosen configuration is off the Pareto front");
}
BENCHMARK(BM_ChosenOnParetoFront)->Unit(benchmark::kMillisecond)->Iterations(3);

void registerSolves() {
    const MethodCase& c = catenary();
    for (const Method& m : methodRegistry(c)) {
        const std::string problem = motionProblemName(m.problem);
        benchmark::RegisterBenchmark(("BM_Solve/" + problem + "/" + m.name).c_str(), BM_Solve,
                                     problem, m.name)
            ->Unit(benchmark::kMicrosecond);
    }
}

} // namespace
} // namespace chaplygin

int main(int argc, char** argv) {
    chaplygin::keepFreedMemoryForReuse(); // as the program does (app/main.cpp)
    chaplygin::registerSolves();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
