#include "headless_run.h"

#include "common/atomic_file.h"
#include "common/input_error.h"
#include "numerics/work_precision.h"
#include "plot_export.h"
#include "scene/csv_writer.h"
#include "scene/headless_options.h"
#include "scene/solution.h"
#include "scene/summary_json.h"

#include <QApplication>
#include <QDir>
#include <QFile>

#include <unistd.h>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace chaplygin::app {
namespace {

int writePlots(const Solution& solution, const HeadlessOptions& o, int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
        // Qt wants a private runtime directory even offscreen
        QString runtime = QDir::tempPath() + QStringLiteral("/chaplygin-lab-runtime-") +
                          QString::number(::getuid());
        QDir().mkpath(runtime);
        QFile::setPermissions(runtime, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        qputenv("XDG_RUNTIME_DIR", runtime.toUtf8());
    }
    QApplication app(argc, argv);
    QStringList formats;
    for (const std::string& f : o.formats)
        formats << QString::fromStdString(f);
    ui::exportPlots(solution, QString::fromStdString(o.plotsDir), formats);
    return 0;
}

} // namespace

int runHeadless(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    try {
        HeadlessOptions o = parseHeadlessOptions(args);
        if (o.help) {
            std::fputs(headlessUsage().c_str(), stdout);
            return 0;
        }
        if (o.workPrecision) {
            writeFileAtomically(o.csvPath.empty() ? "-" : o.csvPath, workPrecisionCsv(o.scene));
            return 0;
        }
        Solution solution = Solution::compute(o.scene);
        if (!o.csvPath.empty()) {
            std::vector<MotionSample> rows;
            if (o.times) {
                for (double t : *o.times)
                    if (t < 0 || t > solution.duration())
                        throw InputError("--times",
                                         formatNumber(t) + " is outside [0, " +
                                             formatNumber(solution.duration()) +
                                             "], the time the body takes along the path");
                rows = solution.sampleAt(*o.times);
            } else {
                rows = solution.sample(o.samples);
            }
            writeFileAtomically(o.csvPath, formatCsv(rows));
        }
        if (!o.summaryPath.empty())
            writeFileAtomically(o.summaryPath, formatSummary(solution));
        if (!o.plotsDir.empty())
            return writePlots(solution, o, argc, argv);
        return 0;
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
