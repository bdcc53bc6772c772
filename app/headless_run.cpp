#include "headless_run.h"

#include "common/atomic_file.h"
#include "common/input_error.h"
#include "document/scene_document.h"
#include "headless_options.h"
#include "lab/parameter_sweep.h"
#include "lab/work_precision.h"
#include "planning/plan_track.h"
#include "plots/plot_export.h"
#include "plots/sweep_plot.h"
#include "plots/work_precision_plot.h"
#include "program_usage.h"
#include "runtime_directory.h"
#include "scene/csv_writer.h"
#include "scene/scene_link.h"
#include "scene/solution.h"
#include "scene/summary_json.h"
#include "shell/animation_export.h"
#include "systems/system.h"

#include <QApplication>
#include <QDir>
#include <QFile>

#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

namespace chaplygin::app {
namespace {

// plots need a QApplication; headless it runs on the offscreen platform
void prepareOffscreen() {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    ensureRuntimeDirectory();
}

QStringList formatList(const HeadlessOptions& o) {
    QStringList formats;
    for (const std::string& f : o.formats)
        formats << QString::fromStdString(f);
    return formats;
}

void checkTimes(const Solution& solution, const HeadlessOptions& o) {
    for (double t : o.times.value_or(std::vector<double>{}))
        if (t < 0 || t > solution.duration())
            throw InputError("--times", formatNumber(t) + " is outside [0, " +
                                            formatNumber(solution.duration()) +
                                            "], the time the body takes along the path");
}

std::vector<MotionSample> rowsFor(const Solution& solution, const HeadlessOptions& o) {
    return o.times ? solution.sampleAt(*o.times) : solution.sample(o.samples);
}

int solveScene(const HeadlessOptions& o, int argc, char** argv) {
    Solution solution = Solution::compute(o.scene);
    checkTimes(solution, o); // whether or not a CSV is asked for
    if (!o.csvPath.empty())
        writeFileAtomically(o.csvPath, formatCsv(rowsFor(solution, o)));
    bool noOutput = o.csvPath.empty() && o.summaryPath.empty() && o.plotsDir.empty();
    if (!o.summaryPath.empty() || noOutput)
        writeFileAtomically(noOutput ? "-" : o.summaryPath, formatSummary(solution));
    if (!o.plotsDir.empty()) {
        prepareOffscreen();
        QApplication app(argc, argv);
        ui::exportPlots(solution, QString::fromStdString(o.plotsDir), formatList(o));
    }
    return 0;
}

// --plan-to: the genuine vakonomic motions from the start pose to the target (docs/physics.md
// §10), beside the path's plain run when a path is given
int solvePlan(const HeadlessOptions& o) {
    if (o.scene.mode == SpeedMode::Speed)
        throw InputError("--mode", "planning needs constant energy (--mode energy, --vT): the "
                                   "genuine vakonomic motion keeps T, and at constant speed there "
                                   "is no such family");
    std::optional<Solution> solution;
    if (o.pathGiven)
        solution = Solution::compute(o.scene);
    PlanRequest request;
    request.system = deriveSystem(o.scene.system);
    request.vT = o.scene.speed;
    request.to = *o.planTo;
    request.horizon = o.planHorizon;
    if (o.planFrom) {
        request.from = *o.planFrom;
    } else if (solution) {
        const MotionSample start = solution->sampleAt({0.0}).at(0);
        request.from = {start.x, start.y, start.phi};
    }
    const Plan plan = planVakonomic(request);
    if (plan.geodesics.empty())
        throw InputError("--plan-to", "no genuine vakonomic motion reaches the target within "
                                      "the horizon of " +
                                          formatNumber(plan.horizon) + " s (see --plan-horizon)");
    // the chosen motion: the N-th listed, or the first optimal one
    std::size_t chosen = 0;
    if (o.planChoice > static_cast<int>(plan.geodesics.size()))
        throw InputError("--plan-choice", "there are " + std::to_string(plan.geodesics.size()) +
                                              " motions within the horizon, not " +
                                              std::to_string(o.planChoice));
    if (o.planChoice > 0)
        chosen = static_cast<std::size_t>(o.planChoice - 1);
    else
        while (chosen + 1 < plan.geodesics.size() && !plan.geodesics[chosen].optimal)
            ++chosen;
    const PlannedGeodesic& g = plan.geodesics[chosen];
    if (o.trackPlan) {
        // the usual run on the motion's knife track: the controlled body is the genuine
        // vakonomic one (docs/physics.md §10)
        if (g.family == GeodesicFamily::Rest)
            throw InputError("--track-plan", "the target is the start (t = 0): there is no "
                                             "track to follow");
        HeadlessOptions tracked = o;
        tracked.scene.path = planTrack(request, g);
        tracked.scene.preset.clear();
        tracked.scene.tEnd.reset();
        tracked.scene.perturbation.reset();
        tracked.scene.pins.clear();
        const Solution run = Solution::compute(tracked.scene);
        checkTimes(run, tracked);
        if (!o.csvPath.empty())
            writeFileAtomically(o.csvPath, formatCsv(rowsFor(run, tracked)));
        if (!o.summaryPath.empty() || o.csvPath.empty())
            writeFileAtomically(o.summaryPath.empty() ? "-" : o.summaryPath,
                                formatPlanSummary(request, plan, &run));
        return 0;
    }
    if (!o.csvPath.empty()) {
        std::vector<double> times = o.times.value_or(std::vector<double>{});
        for (double t : times)
            if (t < 0 || t > g.t)
                throw InputError("--times", formatNumber(t) + " is outside [0, " +
                                                formatNumber(g.t) + "], the planned motion");
        if (!o.times)
            for (int i = 0; i < o.samples; ++i)
                times.push_back(i + 1 == o.samples ? g.t : g.t * i / (o.samples - 1));
        writeFileAtomically(o.csvPath, formatPlanCsv(request, g, times));
    }
    if (!o.summaryPath.empty() || o.csvPath.empty())
        writeFileAtomically(o.summaryPath.empty() ? "-" : o.summaryPath,
                            formatPlanSummary(request, plan, solution ? &*solution : nullptr));
    return 0;
}

// --work-precision: the speed-against-accuracy sweep as CSV, its references as JSON, and the
// diagram
int runWorkPrecisionLab(const HeadlessOptions& o, int argc, char** argv) {
    // bad input is reported as for a plain run; the sweep's horizon may pass the path's end
    Scene check = o.scene;
    check.tEnd.reset();
    Solution::compute(check);
    WorkPrecisionReport report = runWorkPrecision(o.scene);
    writeFileAtomically(o.csvPath.empty() ? "-" : o.csvPath, formatWorkPrecisionCsv(report));
    if (!o.summaryPath.empty())
        writeFileAtomically(o.summaryPath, formatWorkPrecisionSummary(report));
    if (!o.plotsDir.empty()) {
        prepareOffscreen();
        QApplication app(argc, argv);
        QString caption = o.scene.preset.empty()
                              ? QStringLiteral("typed scene")
                              : QStringLiteral("preset ") + QString::fromStdString(o.scene.preset);
        ui::exportWorkPrecision(report, caption, QString::fromStdString(o.plotsDir), formatList(o));
    }
    return 0;
}

// one CSV row per value of a parameter; --plots draws each column against it
int runSweep(const HeadlessOptions& o, int argc, char** argv) {
    SweepReport report = runParameterSweep(o.scene, *o.sweep);
    writeFileAtomically(o.csvPath.empty() ? "-" : o.csvPath, formatSweepCsv(report));
    if (!o.plotsDir.empty()) {
        prepareOffscreen();
        QApplication app(argc, argv);
        QString caption = (o.scene.preset.empty() ? QStringLiteral("typed scene")
                                                  : QStringLiteral("preset ") +
                                                        QString::fromStdString(o.scene.preset)) +
                          QStringLiteral(", %1, %2 mode, speed %3 m/s")
                              .arg(QString::fromStdString(systemKindName(o.scene.system.kind)),
                                   QString::fromStdString(speedModeName(o.scene.mode)))
                              .arg(o.scene.speed);
        ui::exportSweep(report, caption, QString::fromStdString(o.plotsDir), formatList(o));
    }
    return 0;
}

// the canvas from 0 to t_end, rendered offscreen frame by frame
int runAnimation(const HeadlessOptions& o, int argc, char** argv) {
    Solution::compute(o.scene); // bad input is reported as for a plain run
    prepareOffscreen();
    QApplication app(argc, argv);
    ui::SceneDocument document;
    document.setSceneNow(o.scene);
    ui::AnimationSettings settings;
    settings.file = QString::fromStdString(o.animationPath);
    settings.fps = o.fps;
    settings.size = QSize(o.width, o.height);
    settings.withPlots = o.withPlots;
    settings.look.style.body = *ui::bodyDisplayNamed(o.body);
    ui::AnimationExporter exporter(&document, settings);
    exporter.run();
    return 0;
}

// --link: the scene's link on standard output, its system checked as a run would check it
int printLink(const HeadlessOptions& o) {
    deriveSystem(o.scene.system);
    writeFileAtomically("-", sceneToLink(o.scene) + "\n");
    return 0;
}

} // namespace

int runHeadless(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    try {
        HeadlessOptions o = parseHeadlessOptions(args);
        if (o.help) {
            std::fputs(programUsage().c_str(), stdout);
            return 0;
        }
        try {
            if (o.link)
                return printLink(o);
            if (o.sweep)
                return runSweep(o, argc, argv);
            if (!o.animationPath.empty())
                return runAnimation(o, argc, argv);
            if (o.planTo)
                return solvePlan(o);
            return o.workPrecision ? runWorkPrecisionLab(o, argc, argv) : solveScene(o, argc, argv);
        } catch (const InputError& e) {
            throw withOptionNames(e, o.scene.mode);
        }
    } catch (const InputError& e) {
        std::fprintf(stderr, "chaplygin-lab: %s\n", e.what());
        return 2;
    } catch (const IoError& e) {
        std::fprintf(stderr, "chaplygin-lab: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "chaplygin-lab: internal error: %s\n", e.what());
        return 1;
    }
}

} // namespace chaplygin::app
