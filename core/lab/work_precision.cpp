#include "lab/work_precision.h"

#include "lab/quadrature_time_law.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace chaplygin {
namespace {

using Clock = std::chrono::steady_clock;

std::vector<double> evenTimes(double end, int count) {
    std::vector<double> t(count);
    for (int i = 0; i < count; ++i)
        t[i] = i + 1 == count ? end : end * i / (count - 1);
    return t;
}

double maxDistance(const MethodOutput& a, const MethodOutput& ref) {
    double err = 0;
    for (std::size_t i = 0; i < a.x.size(); ++i) {
        double d = std::hypot(a.x[i] - ref.x[i], a.y[i] - ref.y[i]);
        if (!std::isfinite(d))
            return INFINITY;
        err = std::max(err, d);
    }
    return err;
}

struct Timed {
    MethodOutput output;
    double seconds = 0;
};

// median wall time of repeated solves
Timed timeSolve(const Method& m, const MethodCase& c, double setting,
                const std::vector<double>& times, double minSeconds) {
    std::vector<double> samples;
    Timed out;
    double spent = 0;
    while (samples.size() < 9 && (samples.size() < 1 || spent < minSeconds)) {
        auto start = Clock::now();
        MethodOutput o = m.solve(c, setting, times);
        double s = std::chrono::duration<double>(Clock::now() - start).count();
        samples.push_back(s);
        spent += s;
        if (samples.size() == 1)
            out.output = std::move(o);
    }
    std::sort(samples.begin(), samples.end());
    out.seconds = samples[samples.size() / 2];
    return out;
}

std::vector<double> defaultTolerances() {
    std::vector<double> t;
    for (int e = 3; e <= 13; ++e)
        t.push_back(std::pow(10.0, -e));
    return t;
}

std::vector<long> defaultStepCounts() {
    std::vector<long> n;
    for (long k = 16; k <= 16384; k *= 2)
        n.push_back(k);
    return n;
}

} // namespace

WorkPrecisionReport runWorkPrecision(const Scene& scene, const WorkPrecisionOptions& options) {
    MethodCase c(scene);
    std::vector<Method> methods = methodRegistry(c);
    const std::vector<double> tolerances =
        options.tolerances.empty() ? defaultTolerances() : options.tolerances;
    const std::vector<long> stepCounts =
        options.stepCounts.empty() ? defaultStepCounts() : options.stepCounts;
    WorkPrecisionReport report;
    report.controlledEnd = c.controlledEnd;
    report.freeEnd = c.freeEnd;

    // references: the closed form where there is one, else the tightest method
    const std::vector<double> tc = evenTimes(c.controlledEnd, options.outputs);
    const std::vector<double> tf = evenTimes(c.freeEnd, options.outputs);
    MethodOutput refControlled, refFree;
    for (const Method& m : methods) {
        if (m.problem == MotionProblem::Free && m.appDefault) {
            refFree = m.solve(c, 0, tf);
            report.freeReference = "free " + m.name + " (" + m.description + ")";
            report.freeReferenceMethod = m.name;
        }
        if (m.problem == MotionProblem::Controlled && m.appDefault &&
            c.plan->timeLaw().closedForm()) {
            refControlled = m.solve(c, 0, tc);
            report.controlledReference = "controlled " + m.name + " (" + m.description + ")";
            report.controlledReferenceMethod = m.name;
        }
    }
    if (report.controlledReference.empty()) {
        auto qag = std::find_if(methods.begin(), methods.end(),
                                [](const Method& m) { return m.name == "gsl_qag_newton"; });
        auto app = std::find_if(methods.begin(), methods.end(), [](const Method& m) {
            return m.problem == MotionProblem::Controlled && m.appDefault;
        });
        if (qag != methods.end()) {
            // the tightest method, with a different rule (Gauss-Kronrod 61) from the swept one (21)
            QuadratureTimeLaw law(*c.curve, c.params, 1e-14, 61);
            OdeWork work;
            refControlled = pointsOnCurve(*c.curve, law.invert(tc, work));
            report.controlledReference = "controlled GSL QAG (Gauss-Kronrod 61) + Newton at "
                                         "tolerance 1e-14 (the tightest method)";
            report.controlledReferenceMethod = qag->name;
            report.controlledReferenceTightest = true;
        } else {
            refControlled = app->solve(c, 0, tc);
            report.controlledReference =
                "controlled " + app->name + " (no independent method for this path)";
            report.controlledReferenceMethod = app->name;
            report.controlledReferenceIndependent = false;
        }
    }

    // every method's settings first, so progress knows the total
    std::vector<std::vector<double>> settingsOf;
    int total = 0;
    for (const Method& m : methods) {
        const bool controlled = m.problem == MotionProblem::Controlled;
        std::vector<double> settings;
        if (m.setting == SettingKind::None)
            settings = {0.0};
        else if (m.setting == SettingKind::Tolerance)
            settings = tolerances;
        else
            for (long n : stepCounts)
                settings.push_back((controlled ? c.controlledEnd : c.freeEnd) /
                                   static_cast<double>(n));
        total += static_cast<int>(settings.size());
        settingsOf.push_back(std::move(settings));
    }
    int done = 0;
    for (std::size_t k = 0; k < methods.size() && !report.cancelled; ++k) {
        const Method& m = methods[k];
        const bool controlled = m.problem == MotionProblem::Controlled;
        const std::vector<double>& times = controlled ? tc : tf;
        const MethodOutput& ref = controlled ? refControlled : refFree;
        const std::vector<double>& settings = settingsOf[k];
        int skipped = static_cast<int>(settings.size());
        for (double setting : settings) {
            if (options.cancel && options.cancel->load()) {
                report.cancelled = true;
                break;
            }
            --skipped;
            Timed run;
            bool solved = true;
            try {
                run = timeSolve(m, c, setting, times, options.minTimingSeconds);
            } catch (const std::runtime_error&) {
                solved = false; // a stepper that fails at this setting (too many steps) has no row
            }
            ++done;
            if (options.progress)
                options.progress(done, total);
            if (!solved)
                continue;
            WorkPrecisionRow row;
            row.problem = m.problem;
            row.method = m.name;
            row.setting = setting;
            row.error = maxDistance(run.output, ref);
            row.seconds = run.seconds;
            row.rhsEvals = run.output.work.rhsEvals;
            row.energyDrift = run.output.energyDrift;
            row.chosen = m.appDefault;
            report.rows.push_back(row);
            if (run.seconds > options.maxSolveSeconds)
                break;
        }
        // settings left out after a slow solve count as done
        if (!report.cancelled && skipped > 0) {
            done += skipped;
            if (options.progress)
                options.progress(done, total);
        }
    }
    return report;
}

std::string formatWorkPrecisionCsv(const WorkPrecisionReport& report) {
    std::string out = "problem,method,tolerance,error,seconds,rhs_evals,chosen\n";
    char buf[256];
    for (const WorkPrecisionRow& r : report.rows) {
        std::snprintf(buf, sizeof buf, "%s,%s,%.6g,%.6e,%.6e,%ld,%d\n",
                      motionProblemName(r.problem).c_str(), r.method.c_str(), r.setting, r.error,
                      r.seconds, r.rhsEvals, r.chosen ? 1 : 0);
        out += buf;
    }
    return out;
}

std::string workPrecisionCsv(const Scene& scene) {
    return formatWorkPrecisionCsv(runWorkPrecision(scene));
}

bool onParetoFront(const std::vector<WorkPrecisionRow>& rows, std::size_t index) {
    const WorkPrecisionRow& r = rows[index];
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const WorkPrecisionRow& o = rows[i];
        if (i == index || o.problem != r.problem)
            continue;
        bool noWorse = o.error <= r.error && o.seconds <= r.seconds;
        bool better = o.error < r.error || o.seconds < r.seconds;
        if (noWorse && better)
            return false;
    }
    return true;
}

std::string formatWorkPrecisionSummary(const WorkPrecisionReport& report) {
    nlohmann::json j;
    j["controlled_reference"] = report.controlledReference;
    j["free_reference"] = report.freeReference;
    j["controlled_end"] = report.controlledEnd;
    j["free_end"] = report.freeEnd;
    j["rows"] = report.rows.size();
    j["chosen"] = nlohmann::json::array();
    for (std::size_t i = 0; i < report.rows.size(); ++i) {
        const WorkPrecisionRow& r = report.rows[i];
        if (!r.chosen)
            continue;
        j["chosen"].push_back({{"problem", motionProblemName(r.problem)},
                               {"method", r.method},
                               {"error", r.error},
                               {"seconds", r.seconds},
                               {"on_pareto_front", onParetoFront(report.rows, i)}});
    }
    return j.dump(2) + "\n";
}

} // namespace chaplygin
