#include "desktop_entry.h"

#include "canvas/scene_canvas.h"
#include "common/atomic_file.h"
#include "common/input_error.h"
#include "document/scene_document.h"
#include "headless_options.h"
#include "option_table.h"
#include "panels/accuracy_readout.h"
#include "panels/methods_panel.h"
#include "panels/sweep_panel.h"
#include "plots/plots_panel.h"
#include "runtime_directory.h"
#include "scene/lecture.h"
#include "scene/scene_link.h"
#include "shell/language_menu.h"
#include "shell/lecture_panel.h"
#include "shell/main_window.h"
#include "shell/playback.h"
#include "shell/presentation_mode.h"
#include "translations.h"
#include "version.h"
#include "widgets/number_field.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QIcon>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPixmap>
#include <QTimer>
#include <QUrl>

#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <unistd.h>

namespace chaplygin::ui {

namespace {

void describeApplication() {
    QCoreApplication::setOrganizationName(QStringLiteral("ChaplyginLab"));
    QCoreApplication::setApplicationName(QStringLiteral("Chaplygin Lab"));
    QCoreApplication::setApplicationVersion(QStringLiteral(CHAPLYGIN_LAB_VERSION));
    // resources/chaplygin-lab.qrc, compiled into the executable
    QGuiApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/chaplygin-lab.svg")));
    QGuiApplication::setDesktopFileName(QStringLiteral("io.github.chaplyginlab.ChaplyginLab"));
}

// the offscreen platform warns about window hints it cannot honour; that is not news to the user
void quietOffscreenNoise(QtMsgType type, const QMessageLogContext& context,
                         const QString& message) {
    if (message.contains(QLatin1String("propagateSizeHints")))
        return;
    std::fprintf(stderr, "%s\n", qPrintable(qFormatLogMessage(type, context, message)));
}

struct ScreenshotOptions {
    std::string file;
    double at = 0;
    int width = 1280, height = 800;
    bool showParameters =
        false;                ///< --panel parameters: raise the parameters dock over the path dock
    bool showMethods = false; ///< --panel methods: compute and show the work-precision diagram
    bool showSweep = false;   ///< --panel sweep: show the Sweep dock, run --sweep if given
    std::optional<SweepSpec> sweep;
    std::string dock;          ///< --panel notes|equations: raise that dock
    bool presentation = false; ///< --presentation: presentation mode at the given size
    std::string language;      ///< --language en|pt_BR: that catalogue instead of the system's
    std::string viewReport;    ///< --view-report FILE.json: the canvas's place and map
    std::optional<BodyDisplay> body; ///< --body scale|outline|marker
    bool wheelView = false;          ///< --wheel-view: the side view of the wheels
    std::vector<QPointF> measure;    ///< --measure: the ruler's (and protractor's) points [m]
    std::optional<QPointF> probe;    ///< --probe: where the probe hovers [m]
    std::string lecture;             ///< --lecture FILE.json: a lecture instead of a scene
    int lectureEntry = 1;            ///< --lecture-entry N: its scene shown, from 1
    int plotsZoom = 0;               ///< --plots-zoom N: the time plots zoomed in N notches
    Scene scene;
};

// the scene options' errors name the options, not the scene's fields
Scene sceneOf(const app::OptionValues& given) {
    try {
        return sceneFromOptions(given);
    } catch (const InputError& e) {
        throw withOptionNames(e, SpeedMode::Energy);
    }
}

void readPanel(const std::string& panel, ScreenshotOptions& o) {
    if (panel != "path" && panel != "parameters" && panel != "methods" && panel != "sweep" &&
        panel != "notes" && panel != "equations" && panel != "values")
        throw InputError("--panel", "expected path, parameters, methods, sweep, notes, "
                                    "equations or values, got '" +
                                        panel + "'");
    o.showSweep = panel == "sweep";
    if (panel == "notes" || panel == "equations" || panel == "values")
        o.dock = panel + "Dock";
    o.showParameters = panel == "parameters";
    o.showMethods = panel == "methods";
}

// "X,Y" [m], finite
QPointF readWorldPoint(const std::string& text, const std::string& where) {
    const auto comma = text.find(',');
    if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
        throw InputError(where, "expects X,Y, got '" + text + "'");
    return {parseNumber(text.substr(0, comma), where), parseNumber(text.substr(comma + 1), where)};
}

// "X0,Y0 X1,Y1 [X2,Y2]": two or three points [m]
std::vector<QPointF> readMeasure(const std::string& text) {
    std::vector<QPointF> points;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t end = std::min(text.find(' ', at), text.size());
        if (end > at)
            points.push_back(
                readWorldPoint(text.substr(at, end - at),
                               "--measure, point " + std::to_string(points.size() + 1)));
        at = end + 1;
    }
    if (points.size() < 2 || points.size() > 3)
        throw InputError("--measure", "expects two or three points X,Y, got '" + text + "'");
    return points;
}

std::pair<int, int> readWindowSize(const std::string& size) {
    auto x = size.find('x');
    if (x == std::string::npos)
        throw InputError("--size", "expected WxH, e.g. 1280x800");
    double w = parseNumber(size.substr(0, x), "--size");
    double h = parseNumber(size.substr(x + 1), "--size");
    if (w < 320 || h < 240 || w > 8000 || h > 8000 || w != int(w) || h != int(h))
        throw InputError("--size",
                         "width and height must be whole numbers in 320x240 ... 8000x8000");
    return {int(w), int(h)};
}

ScreenshotOptions parseScreenshotOptions(int argc, char** argv) {
    const app::OptionValues given =
        app::readOptions(std::vector<std::string>(argv + 1, argv + argc), app::Screenshot);
    ScreenshotOptions o;
    o.file = given.value("--screenshot").value_or("");
    if (o.file.empty())
        throw InputError("--screenshot", "needs the output file name");
    o.presentation = given.has("--presentation");
    if (auto at = given.value("--at")) {
        o.at = parseNumber(*at, "--at");
        if (o.at < 0)
            throw InputError("--at", "the time must be >= 0");
    }
    if (auto panel = given.value("--panel"))
        readPanel(*panel, o);
    if (auto language = given.value("--language")) {
        o.language = *language;
        if (o.language != "en" && o.language != "pt_BR")
            throw InputError("--language", "expected en or pt_BR, got '" + o.language + "'");
    }
    if (auto size = given.value("--size"))
        std::tie(o.width, o.height) = readWindowSize(*size);
    o.viewReport = given.value("--view-report").value_or("");
    if (auto body = given.value("--body")) {
        checkBodyOption(*body);
        o.body = bodyDisplayNamed(*body);
    }
    o.wheelView = given.has("--wheel-view");
    if (auto measure = given.value("--measure"))
        o.measure = readMeasure(*measure);
    if (auto probe = given.value("--probe"))
        o.probe = readWorldPoint(*probe, "--probe");
    if (auto lecture = given.value("--lecture")) {
        if (given.hasAnyOf(app::OptionSection::Scene) ||
            given.hasAnyOf(app::OptionSection::System) || given.has("--sweep"))
            throw InputError("--lecture", "give a lecture or scene options, not both");
        o.lecture = *lecture;
    }
    if (auto entry = given.value("--lecture-entry")) {
        if (o.lecture.empty())
            throw InputError("--lecture-entry", "needs --lecture FILE.json");
        const double n = parseNumber(*entry, "--lecture-entry");
        if (!(n >= 1 && n <= double(kMaxLectureScenes) && n == int(n)))
            throw InputError("--lecture-entry", "must be a whole number from 1 to " +
                                                    std::to_string(kMaxLectureScenes));
        o.lectureEntry = int(n);
    }
    if (auto zoom = given.value("--plots-zoom")) {
        const double n = parseNumber(*zoom, "--plots-zoom");
        if (!(n >= 0 && n <= 60 && n == int(n)))
            throw InputError("--plots-zoom", "must be a whole number from 0 to 60");
        o.plotsZoom = int(n);
    }
    if (!o.lecture.empty())
        return o;
    o.scene = sceneOf(given);
    if (auto sweep = given.value("--sweep")) {
        o.sweep = parseSweepSpec(*sweep);
        validateSweep(o.scene, *o.sweep);
    }
    return o;
}

// the contract of tests that look at pixels (docs/architecture.md, ui/: the desktop
// application, Screenshot mode): where the canvas is in the image and its metres-to-pixels map
void writeViewReport(const std::string& file, MainWindow& window, const QImage& image) {
    const SceneCanvas* canvas = window.canvas();
    // the image's pixels per widget pixel (the device pixel ratio of the grab)
    const double k = image.width() / double(std::max(window.width(), 1));
    const QPoint corner = canvas->mapTo(&window, QPoint(0, 0));
    const QPointF origin = canvas->worldToPixel().map(QPointF(0, 0)) + QPointF(corner);
    const QJsonObject rect{{"x", k * corner.x()},
                           {"y", k * corner.y()},
                           {"width", k * canvas->width()},
                           {"height", k * canvas->height()}};
    const QJsonObject report{{"canvas", rect},
                             {"scale", k * canvas->scale()},
                             {"origin", QJsonArray{k * origin.x(), k * origin.y()}}};
    writeFileAtomically(file, QJsonDocument(report).toJson().toStdString());
}

// the Measure tool as the mouse drives it: the ruler dragged between the first two points [m],
// the protractor's second arm from the second to the third, then the probe hovering
void showMeasuring(SceneCanvas& canvas, const std::vector<QPointF>& measure,
                   const std::optional<QPointF>& probe) {
    canvas.setMeasureMode(true);
    auto send = [&canvas](QEvent::Type type, QPointF world, Qt::MouseButton button,
                          Qt::MouseButtons buttons) {
        const QPointF pixel = canvas.toPixel(world);
        QMouseEvent e(type, pixel, canvas.mapToGlobal(pixel), button, buttons, {});
        QCoreApplication::sendEvent(&canvas, &e);
    };
    for (std::size_t i = 0; i + 1 < measure.size(); ++i) {
        send(QEvent::MouseButtonPress, measure[i], Qt::LeftButton, Qt::LeftButton);
        send(QEvent::MouseMove, measure[i + 1], Qt::NoButton, Qt::LeftButton);
        send(QEvent::MouseButtonRelease, measure[i + 1], Qt::LeftButton, Qt::NoButton);
    }
    if (probe)
        send(QEvent::MouseMove, *probe, Qt::NoButton, Qt::NoButton);
    QCoreApplication::processEvents();
}

int renderScreenshot(const ScreenshotOptions& o) {
    MainWindow window(false);
    if (o.lecture.empty()) {
        window.loadScene(o.scene);
    } else {
        // its first scene shown, or the one asked for; a refusal names the file or the scene
        if (!window.openLecture(QString::fromStdString(o.lecture)))
            throw InputError("--lecture", window.lastFileError().toStdString());
        const std::size_t n = window.lecturePanel()->lecture().entries.size();
        if (std::size_t(o.lectureEntry) > n)
            throw InputError("--lecture-entry", std::to_string(o.lectureEntry) +
                                                    " is past the lecture's last scene, " +
                                                    std::to_string(n));
        if (!window.showLectureEntry(o.lectureEntry - 1))
            throw InputError("--lecture", window.lastFileError().toStdString());
    }
    if (!window.document()->error().isEmpty())
        throw InputError("scene", window.document()->error().toStdString());
    double tEnd = window.document()->solution()->tEnd();
    if (o.at > tEnd)
        throw InputError("--at", formatNumber(o.at) + " is after the end of the motion, t_end = " +
                                     formatNumber(tEnd));
    window.resize(o.width, o.height);
    window.show();
    QCoreApplication::processEvents();
    window.balanceDocks();
    if (o.presentation) {
        window.presentation()->setFullScreen(false); // the screenshot's size stands
        window.presentation()->setActive(true);
        QCoreApplication::processEvents();
    }
    if (o.showParameters)
        window.showParametersDock();
    if (o.showMethods) {
        window.showMethodsDock();
        window.methodsPanel()->start();
        window.methodsPanel()->waitForFinished();
    }
    if (o.showSweep) {
        window.showSweepDock();
        if (o.sweep) {
            SweepPanel* sweep = window.sweepPanel();
            sweep->parameterBox()->setCurrentText(QString::fromStdString(o.sweep->parameter));
            sweep->fromBox()->setValue(o.sweep->from);
            sweep->toBox()->setValue(o.sweep->to);
            sweep->countBox()->setValue(o.sweep->count);
            sweep->start();
            sweep->waitForFinished();
        }
    }
    const std::string raised = o.dock.empty() && !o.lecture.empty() ? "lectureDock" : o.dock;
    if (auto* dock = window.findChild<QDockWidget*>(QString::fromStdString(raised));
        dock && !raised.empty()) {
        dock->show();
        dock->raise();
    }
    if (o.body || o.wheelView) {
        // this picture only: the saved choice stays
        CanvasStyle style = window.canvas()->canvasStyle();
        style.body = o.body.value_or(style.body);
        style.wheelInset = style.wheelInset || o.wheelView;
        window.canvas()->setCanvasStyle(style);
    }
    QCoreApplication::processEvents();
    window.canvas()->fitScene();
    window.playback()->seek(o.at);
    // the time plots zoomed about the time shown, as View > Plots' time > Zoom in does
    for (int notch = 0; notch < o.plotsZoom; ++notch)
        window.plotsPanel()->zoomInTimeAction()->trigger();
    window.accuracyReadout()->refresh();
    window.plotsPanel()->replotNow();
    QCoreApplication::processEvents();
    if (!o.measure.empty() || o.probe)
        showMeasuring(*window.canvas(), o.measure, o.probe);
    QImage image = window.grab().toImage();
    if (image.isNull() || !image.save(QString::fromStdString(o.file), "PNG")) {
        std::fprintf(stderr, "chaplygin-lab: cannot write the screenshot '%s'\n", o.file.c_str());
        return 1;
    }
    if (!o.viewReport.empty())
        writeViewReport(o.viewReport, window, image);
    return 0;
}

// Qt's own options (QGuiApplication and QApplication take them out of the arguments), with "-" or
// "--" in front: those that take a value, and those that do not
bool isQtOption(const std::string& arg, bool& takesValue) {
    static const std::set<std::string> withValue = {
        "platform",     "platformpluginpath", "platformtheme", "plugin",     "qwindowgeometry",
        "qwindowicon",  "qwindowtitle",       "style",         "stylesheet", "session",
        "display",      "geometry",           "title",         "name",       "visual",
        "qmljsdebugger"};
    static const std::set<std::string> flags = {"reverse", "widgetcount", "sync", "nograb",
                                                "dograb"};
    std::string name = arg.substr(arg.rfind("--", 0) == 0 ? 2 : 1);
    const auto equals = name.find('=');
    if (equals != std::string::npos)
        name.resize(equals);
    takesValue = equals == std::string::npos && withValue.count(name) > 0;
    return withValue.count(name) > 0 || flags.count(name) > 0;
}

// the desktop entry's %u passes a local file as a path or as a file: URL
QString localFile(const QString& argument) {
    const QUrl url(argument);
    return url.isLocalFile() ? url.toLocalFile() : argument;
}

struct DesktopOptions {
    std::optional<std::string> file; ///< a scene file to open
    std::optional<Scene> scene;      ///< or a scene given by options
    bool presentation = false;
};

DesktopOptions parseDesktopOptions(int argc, char** argv) {
    DesktopOptions o;
    std::vector<std::string> rest;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        bool takesValue = false;
        if (arg.size() > 1 && arg[0] == '-' && isQtOption(arg, takesValue))
            i += takesValue ? 1 : 0;
        else
            rest.push_back(arg);
    }
    if (!rest.empty() && rest[0].rfind('-', 0) != 0) {
        o.file = rest[0];
        rest.erase(rest.begin());
    }
    const app::OptionValues given = app::readOptions(rest, app::Window);
    o.presentation = given.has("--presentation");
    const bool sceneOptions =
        given.hasAnyOf(app::OptionSection::Scene) || given.hasAnyOf(app::OptionSection::System);
    if (o.file && sceneOptions)
        throw InputError(*o.file, "give a scene file or scene options, not both");
    if (sceneOptions)
        o.scene = sceneOf(given);
    return o;
}

} // namespace

int runDesktop(int argc, char** argv) {
    // the arguments are checked before any window system is touched: a wrong option is reported
    // on a machine without a display too
    DesktopOptions options;
    try {
        options = parseDesktopOptions(argc, argv);
    } catch (const InputError& e) {
        const std::string message = e.what();
        const bool pointsToHelp = message.find("--help") != std::string::npos;
        std::fprintf(stderr, "chaplygin-lab: %s%s\n", message.c_str(),
                     pointsToHelp ? "" : " (see chaplygin-lab --help)");
        return 2;
    }
    app::ensureRuntimeDirectory();
    QGuiApplication::setHighDpiScaleFactorRoundingPolicy(
        Qt::HighDpiScaleFactorRoundingPolicy::PassThrough);
    QApplication app(argc, argv);
    describeApplication();
    // View > Language, saved by the last session; the system locale unless one was chosen
    app::installTranslations(app, languageLocale(savedLanguage()));
    MainWindow window;
    if (options.scene)
        window.loadScene(*options.scene);
    QString fileError;
    if (options.file) {
        const QString name = localFile(QString::fromStdString(*options.file));
        if (readsAsLink(name.toStdString())) {
            // the message names what is wrong with the link; the link itself may be long
            if (!window.openLink(name))
                fileError = window.lastFileError();
        } else if (!window.openFile(name)) {
            fileError = window.lastFileError();
            if (!fileError.contains(name))
                fileError = QStringLiteral("%1: %2").arg(name, fileError);
        }
    }
    if (!fileError.isEmpty()) {
        std::fprintf(stderr, "chaplygin-lab: %s\n", qPrintable(fileError));
        // from a terminal the message has been read; from a file manager or a menu there is no
        // one to read stderr, so the window starts with its default scene and says why
        if (isatty(STDERR_FILENO))
            return 2;
        QTimer::singleShot(0, &window, [&window, fileError] {
            QMessageBox::warning(
                &window, QCoreApplication::translate("DesktopEntry", "Cannot open the scene"),
                fileError);
        });
    }
    window.show();
    if (options.presentation)
        window.presentation()->setActive(true);
    // an earlier run that ended abnormally left an unsaved scene: offer it back
    QTimer::singleShot(0, &window, [&window] {
        window.offerRestore();
        window.offerIntroduction(); // the first start explains what the window shows
    });
    return app.exec();
}

int runScreenshot(int argc, char** argv) {
    std::optional<ScreenshotOptions> options;
    try {
        options = parseScreenshotOptions(argc, argv);
    } catch (const InputError& e) {
        std::fprintf(stderr, "chaplygin-lab: %s\n", e.what());
        return 2;
    }
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    app::ensureRuntimeDirectory();
    // tests call this inside their own QApplication
    std::unique_ptr<QApplication> app;
    if (!QCoreApplication::instance()) {
        qInstallMessageHandler(quietOffscreenNoise);
        app = std::make_unique<QApplication>(argc, argv);
    }
    // the system's locale (LANG) unless --language names one; a test's own application keeps its
    // translators
    if (!options->language.empty()) {
        const QString catalogue = app::installTranslations(
            *QCoreApplication::instance(), QLocale(QString::fromStdString(options->language)));
        if (catalogue.isEmpty() && options->language != "en") {
            std::fprintf(stderr,
                         "chaplygin-lab: --language: the %s catalogue (chaplygin-lab_%s.qm) is "
                         "not installed, so the window cannot be shown in that language\n",
                         options->language.c_str(), options->language.c_str());
            return 2;
        }
    } else if (app)
        app::installTranslations(*app, QLocale::system());
    try {
        return renderScreenshot(*options);
    } catch (const InputError& e) {
        std::fprintf(stderr, "chaplygin-lab: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "chaplygin-lab: internal error: %s\n", e.what());
        return 1;
    }
}

} // namespace chaplygin::ui
