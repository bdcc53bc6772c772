#include "headless_options.h"

#include "common/input_error.h"
#include "scene/presets.h"
#include "scene/scene_json.h"

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

void parsePathExpression(const std::string& text, PathSource& path) {
    // "y=EXPR" (graph) or "x=EXPR;y=EXPR" (parametric)
    auto parts = split(text, ';');
    auto rhs = [&](const std::string& part, const char* name) {
        std::string t = trim(part);
        if (t.size() < 2 || t[0] != name[0] || trim(t.substr(1)).rfind('=', 0) != 0)
            throw InputError("--path", std::string("expected ") + name + "=EXPR, got '" + t + "'");
        return trim(trim(t.substr(1)).substr(1));
    };
    if (parts.size() == 1) {
        path.kind = PathKind::Graph;
        path.y = rhs(parts[0], "y");
    } else if (parts.size() == 2) {
        path.kind = PathKind::Parametric;
        path.xOfU = rhs(parts[0], "x");
        path.yOfU = rhs(parts[1], "y");
    } else {
        throw InputError("--path", "use \"y=EXPR\" or \"x=EXPR;y=EXPR\"");
    }
}

} // namespace

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

HeadlessOptions parseOptions(const std::vector<std::string>& args) {
    HeadlessOptions o;
    std::optional<std::string> preset, pathExpr, points, corners, scenePath, vT, vS;
    std::optional<std::pair<double, double>> xRange, uRange;
    std::optional<std::string> system, mode;
    std::vector<std::pair<std::string, double>> params;
    std::optional<double> tEnd;
    std::set<std::string> seen;

    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& opt = args[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= args.size())
                throw InputError(opt, "needs a value");
            if (args[i + 1].rfind("--", 0) == 0)
                throw InputError(opt,
                                 "needs a value (the next word is the option " + args[i + 1] + ")");
            return args[++i];
        };
        auto once = [&]() {
            if (!seen.insert(opt).second && opt != "--param")
                throw InputError(opt, "given more than once");
        };
        if (opt == "--headless") {
            continue;
        } else if (opt == "--work-precision") {
            once();
            o.workPrecision = true;
        } else if (opt == "--help" || opt == "-h") {
            o.help = true;
        } else if (opt == "--preset") {
            once();
            preset = value();
        } else if (opt == "--scene") {
            once();
            scenePath = value();
        } else if (opt == "--path") {
            once();
            pathExpr = value();
        } else if (opt == "--x-range") {
            once();
            xRange = parseRange(value(), opt);
        } else if (opt == "--u-range") {
            once();
            uRange = parseRange(value(), opt);
        } else if (opt == "--points") {
            once();
            points = value();
        } else if (opt == "--corners") {
            once();
            corners = value();
        } else if (opt == "--system") {
            once();
            system = value();
        } else if (opt == "--param") {
            std::string v = value();
            auto eq = v.find('=');
            if (eq == std::string::npos || eq == 0)
                throw InputError("--param", "expects NAME=VALUE, got '" + v + "'");
            std::string name = trim(v.substr(0, eq));
            params.emplace_back(name, parseNumber(trim(v.substr(eq + 1)), "--param " + name));
        } else if (opt == "--mode") {
            once();
            mode = value();
        } else if (opt == "--vT") {
            once();
            vT = value();
        } else if (opt == "--vs") {
            once();
            vS = value();
        } else if (opt == "--t-end") {
            once();
            tEnd = parseNumber(value(), opt);
        } else if (opt == "--times") {
            once();
            std::vector<double> ts;
            for (const std::string& t : split(value(), ',')) {
                ts.push_back(parseNumber(trim(t), "--times"));
                if (ts.back() < 0)
                    throw InputError("--times", "times must be >= 0, got " + trim(t));
            }
            if (ts.empty())
                throw InputError("--times", "needs at least one time");
            o.times = ts;
        } else if (opt == "--samples") {
            once();
            double n = parseNumber(value(), opt);
            if (n != std::floor(n) || n < 2 || n > 1e7)
                throw InputError(opt, "must be a whole number between 2 and 10000000");
            o.samples = static_cast<int>(n);
        } else if (opt == "--csv") {
            once();
            o.csvPath = value();
        } else if (opt == "--summary") {
            once();
            o.summaryPath = value();
        } else if (opt == "--plots") {
            once();
            o.plotsDir = value();
        } else if (opt == "--sweep") {
            once();
            o.sweep = parseSweepSpec(value());
        } else if (opt == "--animation") {
            once();
            o.animationPath = value();
        } else if (opt == "--with-plots") {
            once();
            o.withPlots = true;
        } else if (opt == "--fps") {
            once();
            double fps = parseNumber(value(), opt);
            if (fps != std::floor(fps) || fps < 1 || fps > 120)
                throw InputError(opt, "must be a whole number from 1 to 120");
            o.fps = static_cast<int>(fps);
        } else if (opt == "--size") {
            once();
            std::string size = value();
            auto x = size.find('x');
            if (x == std::string::npos)
                throw InputError(opt, "expected WxH, e.g. 1280x720, got '" + size + "'");
            double w = parseNumber(size.substr(0, x), opt),
                   h = parseNumber(size.substr(x + 1), opt);
            if (w < 64 || h < 64 || w > 7680 || h > 4320 || w != std::floor(w) ||
                h != std::floor(h))
                throw InputError(opt,
                                 "width and height must be whole numbers in 64x64 ... 7680x4320");
            o.width = static_cast<int>(w);
            o.height = static_cast<int>(h);
        } else if (opt == "--format") {
            once();
            o.formats.clear();
            for (const std::string& f : split(value(), ',')) {
                std::string t = trim(f);
                if (t != "png" && t != "pdf" && t != "svg")
                    throw InputError("--format", "unknown format '" + t + "' (use png, pdf, svg)");
                o.formats.push_back(t);
            }
            if (o.formats.empty())
                throw InputError("--format", "needs at least one of png, pdf, svg");
        } else {
            throw InputError(opt, "unknown option (see --help)");
        }
    }
    if (o.help)
        return o;

    // the scene: a preset, a file, or a path given here; then overrides
    int sources = (preset ? 1 : 0) + (scenePath ? 1 : 0) + (pathExpr ? 1 : 0) + (points ? 1 : 0);
    if (sources > 1)
        throw InputError("path", "give only one of --preset, --scene, --path and --points");
    Scene& s = o.scene;
    if (preset) {
        s = presetScene(*preset);
    } else if (scenePath) {
        s = loadSceneFile(*scenePath);
    } else if (pathExpr) {
        s = Scene{};
        parsePathExpression(*pathExpr, s.path);
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
        s = Scene{};
        s.path.kind = PathKind::Polyline;
        s.path.points = parsePoints(*points);
    } else {
        throw InputError("path",
                         "no path: give --preset, --scene, --path or --points (see --help)");
    }
    if (corners) {
        if (s.path.kind != PathKind::Polyline)
            throw InputError("--corners", "applies only to --points paths");
        s.path.corners = cornerModeFromName(*corners);
    }
    if ((xRange || uRange) && !pathExpr)
        throw InputError(xRange ? "--x-range" : "--u-range", "applies only to --path");
    if (system) {
        SystemKind kind = systemKindFromName(*system);
        if (kind != s.system.kind || !preset)
            s.system.params = defaultSystemParams(kind);
        s.system.kind = kind;
    }
    for (const auto& [name, v] : params) {
        if (s.system.kind == SystemKind::Sleigh && (name == "I" || name == "b"))
            s.system.params.erase(name == "I" ? "b" : "I");
        s.system.params[name] = v;
    }
    if (mode)
        s.mode = speedModeFromName(*mode);
    if (vT && vS)
        throw InputError("--vT", "give --vT (constant energy) or --vs (constant speed), not both");
    if (vS && !mode)
        s.mode = SpeedMode::Speed;
    if (vT && s.mode == SpeedMode::Speed)
        throw InputError("--vT", "is the constant-energy speed; in --mode speed give --vs");
    if (vS && s.mode == SpeedMode::Energy)
        throw InputError("--vs", "is the constant speed; in --mode energy give --vT");
    if (vT)
        s.speed = parseNumber(*vT, "--vT");
    if (vS)
        s.speed = parseNumber(*vS, "--vs");
    if (tEnd)
        s.tEnd = *tEnd;
    if (o.times && o.scene.tEnd)
        throw InputError("--times", "give --times or --t-end, not both");
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
    if (o.animationPath.empty() && (seen.count("--fps") || seen.count("--size") || o.withPlots))
        throw InputError(seen.count("--fps")    ? "--fps"
                         : seen.count("--size") ? "--size"
                                                : "--with-plots",
                         "applies only to --animation");
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
    else if (field == "scene_file")
        option = "--scene";
    else
        return error;
    std::string message = error.what();
    return InputError(option, message.substr(std::min(message.size(), field.size() + 2)));
}

std::string headlessUsage() {
    return R"(Headless (no window; --headless may stand anywhere):
Scene (one of):
  --preset line|circle|catenary|sinusoid      the paper's examples with the paper's parameters
  --path "y=EXPR" --x-range X0,X1             graph path, traversed from X0 to X1 (X1 < X0:
                                              from right to left)
  --path "x=EXPR;y=EXPR" --u-range U0,U1      parametric path in u
  --points "x0,y0 x1,y1 ..." [--corners pivot|smooth]   polyline (drawn) path
  --scene FILE                                a scene saved by the app (JSON)
System and motion:
  --system sleigh|disk|carriage               default sleigh
  --param NAME=VALUE                          repeatable. sleigh: m, a, and I or b;
                                              disk: m, R, I1, I2; carriage: R, a, m, I1, I2, M, I
  --mode energy|speed                         constant kinetic energy (default) or constant speed
  --vT V | --vs V                             v_T = sqrt(2T/m_eff) [m/s], or the constant speed [m/s]
  --t-end T                                   horizon [s]; default: time to traverse the path
Output:
  --times T1,T2,...                           rows exactly at these times
  --samples N                                 rows evenly spaced on [0, t_end] (default 501)
  --csv FILE|-                                time series (CSV with a header row)
  --summary FILE|-                            JSON: b, m_eff, path length, duration, models used
                                              (printed on standard output when no output is given)
  --plots DIR --format png,pdf,svg            the plots, as the app draws them
  --work-precision                            the speed-against-accuracy sweep of every method:
                                              CSV problem,method,tolerance,error,seconds,rhs_evals,chosen;
                                              --summary names the references, --plots draws the diagram
  --sweep NAME=FROM:TO:COUNT                  one CSV row per value of a parameter (m, a, b, I, vT,
                                              vs, or the disk's or carriage's): NAME,duration,
                                              max_abs_lambda,max_abs_control_couple,
                                              max_abs_force_lateral,max_abs_control_power,
                                              final_separation; --plots draws each column
  --animation FILE [--fps N] [--size WxH]     the canvas from 0 to t_end in real time: FILE.gif or
                                              FILE.mp4 (needs the ffmpeg program), or a folder of
                                              PNG frames (FILE ending in / or without extension);
                                              default 30 fps, 1280x720; --with-plots puts
                                              the plots beside the canvas
Expressions: + - * / ^ ( ), sin cos tan asin acos atan sinh cosh tanh exp sqrt abs ln log, pi, e.
Exit status: 0 success, 2 bad input (the message names the option or the place), 1 internal failure.
)";
}

} // namespace chaplygin
