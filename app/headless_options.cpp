#include "headless_options.h"

#include "canvas/canvas_style.h"
#include "common/input_error.h"
#include "option_table.h"
#include "scene/perturbation.h"
#include "scene/presets.h"
#include "scene/scene_link.h"
#include "scene/speed_choice.h"
#include "systems/system_parameters.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

namespace chaplygin {
namespace {

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> out;
    std::string item;
    std::istringstream in(text);
    while (std::getline(in, item, sep))
        out.push_back(item);
    return out;
}

std::string trim(const std::string& s) {
    auto b = s.find_first_not_of(" \t");
    auto e = s.find_last_not_of(" \t");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::pair<double, double> parseRange(const std::string& text, const std::string& option) {
    auto parts = split(text, ',');
    if (parts.size() != 2)
        throw InputError(option, "expects two numbers FROM,TO, got '" + text + "'");
    double a = parseNumber(trim(parts[0]), option), b = parseNumber(trim(parts[1]), option);
    if (a == b)
        throw InputError(option, "FROM and TO must differ (TO < FROM runs backwards), got " + text);
    return {a, b};
}

std::vector<std::pair<double, double>> parsePoints(const std::string& text) {
    std::vector<std::pair<double, double>> pts;
    std::istringstream in(text);
    std::string item;
    int index = 0;
    while (in >> item) {
        ++index;
        auto xy = split(item, ',');
        std::string where = "--points, point " + std::to_string(index);
        if (xy.size() != 2)
            throw InputError(where, "expects x,y, got '" + item + "'");
        pts.emplace_back(parseNumber(xy[0], where), parseNumber(xy[1], where));
    }
    return pts;
}

} // namespace

void checkBodyOption(const std::string& value) {
    if (!ui::bodyDisplayNamed(value))
        throw InputError("--body", "expected auto, scale, outline or marker, got '" + value + "'");
}

double parseNumber(const std::string& text, const std::string& where) {
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(begin, &end);
    if (text.empty() || end != begin + text.size())
        throw InputError(where, "'" + text + "' is not a number");
    if (errno == ERANGE || !std::isfinite(v))
        throw InputError(where, "'" + text + "' is not a finite number");
    return v;
}

SweepSpec parseSweepSpec(const std::string& text) {
    auto eq = text.find('=');
    auto parts =
        eq == std::string::npos ? std::vector<std::string>{} : split(text.substr(eq + 1), ':');
    if (eq == std::string::npos || eq == 0 || parts.size() != 3)
        throw InputError("--sweep",
                         "expects NAME=FROM:TO:COUNT, e.g. b=0.6:2.4:8, got '" + text + "'");
    SweepSpec spec;
    spec.parameter = trim(text.substr(0, eq));
    spec.from = parseNumber(trim(parts[0]), "--sweep FROM");
    spec.to = parseNumber(trim(parts[1]), "--sweep TO");
    double count = parseNumber(trim(parts[2]), "--sweep COUNT");
    if (count != std::floor(count) || count < 1 || count > 100000)
        throw InputError("--sweep COUNT",
                         "must be a whole number from 1 to 100000, got " + trim(parts[2]));
    spec.count = static_cast<int>(count);
    return spec;
}

namespace {

using app::OptionValues;

std::optional<std::pair<double, double>> rangeOption(const OptionValues& given, const char* name) {
    if (auto text = given.value(name))
        return parseRange(*text, name);
    return std::nullopt;
}

// --preset, --scene, --path or --points: the scene's path, system and mode before the overrides
Scene baseScene(const OptionValues& given) {
    const auto preset = given.value("--preset"), scenePath = given.value("--scene"),
               pathExpr = given.value("--path"), points = given.value("--points");
    const auto xRange = rangeOption(given, "--x-range"), uRange = rangeOption(given, "--u-range");
    int sources = (preset ? 1 : 0) + (scenePath ? 1 : 0) + (pathExpr ? 1 : 0) + (points ? 1 : 0);
    if (sources > 1)
        throw InputError("path", "give only one of --preset, --scene, --path and --points");
    Scene s;
    if (preset) {
        s = presetScene(*preset);
    } else if (scenePath) {
        s = loadSceneFileOrLink(*scenePath);
    } else if (pathExpr) {
        setPathExpressions(s.path, *pathExpr, "--path");
        if (s.path.kind == PathKind::Graph) {
            if (!xRange)
                throw InputError("--x-range", "a graph path y=EXPR needs --x-range X0,X1");
            if (uRange)
                throw InputError("--u-range",
                                 "belongs to a parametric path x=...;y=...; use --x-range");
            std::tie(s.path.from, s.path.to) = *xRange;
        } else {
            if (!uRange)
                throw InputError("--u-range",
                                 "a parametric path x=...;y=... needs --u-range U0,U1");
            if (xRange)
                throw InputError("--x-range", "belongs to a graph path y=...; use --u-range");
            std::tie(s.path.from, s.path.to) = *uRange;
        }
    } else if (points) {
        s.path.kind = PathKind::Polyline;
        s.path.points = parsePoints(*points);
    } else if (given.has("--plan-to")) {
        s = presetScene("line"); // planning needs no path: only the system and the speed
    } else {
        throw InputError("path",
                         "no path: give --preset, --scene, --path or --points (see --help)");
    }
    if ((xRange || uRange) && !pathExpr)
        throw InputError(xRange ? "--x-range" : "--u-range", "applies only to --path");
    return s;
}

// --perturb NAME=VALUE, --feedback-rate and --feedback-limit on top of the scene's perturbation
// (docs/physics.md §9)
void applyPerturbation(const OptionValues& given, Scene& s) {
    const std::vector<std::string> perturb = given.values("--perturb");
    const auto rate = given.value("--feedback-rate"), limit = given.value("--feedback-limit");
    if (perturb.empty() && !s.perturbation) {
        if (rate || limit)
            throw InputError(rate ? "--feedback-rate" : "--feedback-limit",
                             "applies only to a perturbed scene (give --perturb NAME=VALUE)");
        return;
    }
    Perturbation p = s.perturbation.value_or(Perturbation{});
    for (const std::string& v : perturb) {
        auto eq = v.find('=');
        if (eq == std::string::npos || eq == 0)
            throw InputError("--perturb", "expects NAME=VALUE, e.g. dy=0.1, got '" + v + "'");
        const std::string name = trim(v.substr(0, eq));
        setPerturbationField(p, name, parseNumber(trim(v.substr(eq + 1)), "--perturb " + name));
    }
    if (rate)
        setPerturbationField(p, "feedback_rate", parseNumber(*rate, "--feedback-rate"));
    if (limit)
        setPerturbationField(p, "feedback_limit", parseNumber(*limit, "--feedback-limit"));
    checkPerturbation(p);
    s.perturbation = p;
}

const SpeedSettingWords kCommandLineSpeedWords{"--vT", "--vs", "--mode energy", "--mode speed"};

// --corners, --corner-angle, --system, --param, --mode, --vT/--vs and --t-end on top of the base
// scene
void applyOverrides(const OptionValues& given, Scene& s) {
    if (auto corners = given.value("--corners")) {
        if (s.path.kind != PathKind::Polyline)
            throw InputError("--corners", "applies only to --points paths");
        s.path.corners = cornerModeFromName(*corners);
    }
    if (auto angle = given.value("--corner-angle")) {
        if (s.path.kind != PathKind::Polyline)
            throw InputError("--corner-angle", "applies only to --points paths");
        s.path.cornerAngle = parseNumber(*angle, "--corner-angle");
    }
    if (auto system = given.value("--system")) {
        SystemKind kind = systemKindFromName(*system);
        if (kind != s.system.kind || !given.has("--preset"))
            s.system.params = defaultSystemParams(kind);
        s.system.kind = kind;
    }
    for (const std::string& v : given.values("--param")) {
        auto eq = v.find('=');
        if (eq == std::string::npos || eq == 0)
            throw InputError("--param", "expects NAME=VALUE, got '" + v + "'");
        std::string name = trim(v.substr(0, eq));
        double value = parseNumber(trim(v.substr(eq + 1)), "--param " + name);
        setSystemParameter(s.system, name, value);
    }
    const auto mode = given.value("--mode"), vT = given.value("--vT"), vS = given.value("--vs");
    s.mode = chooseSpeedMode(s.mode, mode ? std::optional(speedModeFromName(*mode)) : std::nullopt,
                             vT.has_value(), vS.has_value(), kCommandLineSpeedWords);
    if (vT)
        s.speed = parseNumber(*vT, "--vT");
    if (vS)
        s.speed = parseNumber(*vS, "--vs");
    if (auto tEnd = given.value("--t-end"))
        s.tEnd = parseNumber(*tEnd, "--t-end");
    applyPerturbation(given, s);
}

std::vector<double> parseTimes(const std::string& text) {
    std::vector<double> ts;
    for (const std::string& t : split(text, ',')) {
        ts.push_back(parseNumber(trim(t), "--times"));
        if (ts.back() < 0)
            throw InputError("--times", "times must be >= 0, got " + trim(t));
    }
    if (ts.empty())
        throw InputError("--times", "needs at least one time");
    return ts;
}

int parseWholeNumber(const std::string& text, const char* option, double lo, double hi,
                     const char* range) {
    double n = parseNumber(text, option);
    if (n != std::floor(n) || n < lo || n > hi)
        throw InputError(option, std::string("must be a whole number ") + range);
    return static_cast<int>(n);
}

std::vector<std::string> parseFormats(const std::string& text) {
    std::vector<std::string> formats;
    for (const std::string& f : split(text, ',')) {
        std::string t = trim(f);
        if (t != "png" && t != "pdf" && t != "svg")
            throw InputError("--format", "unknown format '" + t + "' (use png, pdf, svg)");
        formats.push_back(t);
    }
    if (formats.empty())
        throw InputError("--format", "needs at least one of png, pdf, svg");
    return formats;
}

// X,Y,PHI: a pose [m, m, rad]
Pose parsePose(const std::string& text, const std::string& where) {
    const std::vector<std::string> parts = split(text, ',');
    if (parts.size() != 3)
        throw InputError(where, "expects X,Y,PHI (metres and radians), got '" + text + "'");
    return {parseNumber(trim(parts[0]), where + " x"), parseNumber(trim(parts[1]), where + " y"),
            parseNumber(trim(parts[2]), where + " phi")};
}

// the output options of a headless run
void readOutputs(const OptionValues& given, HeadlessOptions& o) {
    o.workPrecision = given.has("--work-precision");
    if (auto times = given.value("--times"))
        o.times = parseTimes(*times);
    if (auto samples = given.value("--samples"))
        o.samples = parseWholeNumber(*samples, "--samples", 2, 1e7, "between 2 and 10000000");
    o.csvPath = given.value("--csv").value_or("");
    o.summaryPath = given.value("--summary").value_or("");
    o.plotsDir = given.value("--plots").value_or("");
    if (auto sweep = given.value("--sweep"))
        o.sweep = parseSweepSpec(*sweep);
    o.animationPath = given.value("--animation").value_or("");
    o.withPlots = given.has("--with-plots");
    if (auto body = given.value("--body")) {
        checkBodyOption(*body);
        o.body = *body;
    }
    if (auto fps = given.value("--fps"))
        o.fps = parseWholeNumber(*fps, "--fps", 1, 120, "from 1 to 120");
    if (auto size = given.value("--size")) {
        auto x = size->find('x');
        if (x == std::string::npos)
            throw InputError("--size", "expected WxH, e.g. 1280x720, got '" + *size + "'");
        double w = parseNumber(size->substr(0, x), "--size"),
               h = parseNumber(size->substr(x + 1), "--size");
        if (w < 64 || h < 64 || w > 7680 || h > 4320 || w != std::floor(w) || h != std::floor(h))
            throw InputError("--size",
                             "width and height must be whole numbers in 64x64 ... 7680x4320");
        o.width = static_cast<int>(w);
        o.height = static_cast<int>(h);
    }
    if (auto formats = given.value("--format"))
        o.formats = parseFormats(*formats);
    if (auto to = given.value("--plan-to"))
        o.planTo = parsePose(*to, "--plan-to");
    if (auto from = given.value("--plan-from"))
        o.planFrom = parsePose(*from, "--plan-from");
    if (auto horizon = given.value("--plan-horizon")) {
        o.planHorizon = parseNumber(*horizon, "--plan-horizon");
        if (!(o.planHorizon > 0))
            throw InputError("--plan-horizon", "must be > 0 [s], not " + *horizon);
    }
    o.trackPlan = given.has("--track-plan");
    o.link = given.has("--link");
    if (auto choice = given.value("--plan-choice"))
        o.planChoice = parseWholeNumber(*choice, "--plan-choice", 1, 1e6, "from 1 on");
    o.pathGiven = given.has("--preset") || given.has("--scene") || given.has("--path") ||
                  given.has("--points");
}

} // namespace

Scene sceneFromOptions(const app::OptionValues& given) {
    Scene s = baseScene(given);
    applyOverrides(given, s);
    return s;
}

namespace {

HeadlessOptions parseOptions(const std::vector<std::string>& args) {
    const OptionValues given = app::readOptions(args, app::Headless);
    HeadlessOptions o;
    o.help = given.has("--help");
    if (o.help)
        return o;
    readOutputs(given, o);
    o.scene = sceneFromOptions(given);
    if (o.times && o.scene.tEnd)
        throw InputError("--times", "give --times or --t-end, not both");
    if (o.link && (o.workPrecision || o.sweep || !o.animationPath.empty() || !o.csvPath.empty() ||
                   !o.summaryPath.empty() || !o.plotsDir.empty() || o.planTo || o.times))
        throw InputError("--link", "prints the scene's link alone; run the other outputs "
                                   "separately");
    if (o.sweep && (o.workPrecision || !o.animationPath.empty()))
        throw InputError("--sweep", "give one of --sweep, --work-precision and --animation");
    if (o.sweep && (o.times || o.scene.tEnd))
        throw InputError("--sweep",
                         "runs each value over the whole path; drop --times and --t-end");
    if (o.sweep && !o.summaryPath.empty())
        throw InputError("--summary", "does not apply to --sweep (its rows go to --csv)");
    if (!o.animationPath.empty() &&
        (o.workPrecision || !o.csvPath.empty() || !o.summaryPath.empty() || !o.plotsDir.empty()))
        throw InputError("--animation", "writes the animation alone; run --csv, --summary and "
                                        "--plots separately");
    if (o.animationPath.empty() &&
        (given.has("--fps") || given.has("--size") || o.withPlots || given.has("--body")))
        throw InputError(given.has("--fps")    ? "--fps"
                         : given.has("--size") ? "--size"
                         : o.withPlots         ? "--with-plots"
                                               : "--body",
                         "applies only to --animation");
    if (!o.planTo && (o.planFrom || given.has("--plan-horizon") || o.planChoice || o.trackPlan))
        throw InputError(o.planFrom                    ? "--plan-from"
                         : given.has("--plan-horizon") ? "--plan-horizon"
                         : o.planChoice                ? "--plan-choice"
                                                       : "--track-plan",
                         "applies only to --plan-to X,Y,PHI");
    if (o.planTo && (o.sweep || o.workPrecision || !o.animationPath.empty() || !o.plotsDir.empty()))
        throw InputError("--plan-to", "plans alone or beside a plain run (--csv, --summary); "
                                      "not with --sweep, --work-precision, --animation or --plots");
    if (o.sweep)
        validateSweep(o.scene, *o.sweep);
    return o;
}

} // namespace

HeadlessOptions parseHeadlessOptions(const std::vector<std::string>& args) {
    try {
        return parseOptions(args);
    } catch (const InputError& e) {
        // the core names the scene's fields (preset, system, ...); here they are options
        throw withOptionNames(e, SpeedMode::Energy);
    }
}

InputError withOptionNames(const InputError& error, SpeedMode mode) {
    const std::string& field = error.where();
    std::string option;
    if (field == "speed")
        option = mode == SpeedMode::Energy ? "--vT" : "--vs";
    else if (field == "t_end")
        option = "--t-end";
    else if (field == "preset" || field == "system" || field == "mode" || field == "corners")
        option = "--" + field;
    else if (field == "corner_angle")
        option = "--corner-angle";
    else if (field == "scene_file")
        option = "--scene";
    else if (field == "perturbation feedback_rate")
        option = "--feedback-rate";
    else if (field == "perturbation feedback_limit")
        option = "--feedback-limit";
    else if (field == "perturbation")
        option = "--perturb";
    else if (field.rfind("perturbation ", 0) == 0)
        option = "--perturb " + field.substr(std::string("perturbation ").size());
    else
        return error;
    std::string message = error.what();
    return InputError(option, message.substr(std::min(message.size(), field.size() + 2)));
}

} // namespace chaplygin
