#include "option_table.h"

#include "common/input_error.h"
#include "systems/system_parameters.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace chaplygin::app {

namespace {

constexpr unsigned kAllModes = Window | Screenshot | Headless;
using S = OptionSection;

// --param's help: each system's parameters, from the parameter table
std::string_view parameterHelp() {
    static const std::string help =
        "repeatable. sleigh: " + systemParameterSummary(SystemKind::Sleigh) +
        ";\ndisk: " + systemParameterSummary(SystemKind::Disk) +
        "; carriage: " + systemParameterSummary(SystemKind::Carriage);
    return help;
}

// clang-format off
const std::array kOptions = {
    OptionSpec{.name = "--presentation", .argument = "",
               .help = "start in presentation mode (full screen, large type); with\n"
                       "--screenshot, presentation mode at that size",
               .modes = Window | Screenshot, .section = S::Window},
    OptionSpec{.name = "--screenshot", .argument = "FILE.png",
               .help = "write the window, rendered offscreen, to FILE.png and exit",
               .modes = Screenshot, .section = S::Screenshot},
    OptionSpec{.name = "--size", .argument = "WxH",
               .help = "the window's size (default 1280x800)",
               .modes = Screenshot, .section = S::Screenshot},
    OptionSpec{.name = "--at", .argument = "T",
               .help = "the moment shown [s] (default 0)",
               .modes = Screenshot, .section = S::Screenshot},
    OptionSpec{.name = "--panel",
               .argument = "path|parameters|methods|sweep|notes|equations|values",
               .help = "the dock raised (methods computes the work-precision diagram;\n"
                       "sweep runs --sweep)",
               .modes = Screenshot, .section = S::Screenshot},
    OptionSpec{.name = "--measure", .argument = "\"X0,Y0 X1,Y1 [X2,Y2]\"",
               .help = "the Measure tool's ruler dragged from X0,Y0 to X1,Y1 [m]; a\n"
                       "third point drags the protractor's second arm from X1,Y1",
               .modes = Screenshot, .section = S::Screenshot},
    OptionSpec{.name = "--probe", .argument = "X,Y",
               .help = "the Measure tool's probe hovering X,Y [m] (the path or a trail\n"
                       "near it)",
               .modes = Screenshot, .section = S::Screenshot},
    OptionSpec{.name = "--view-report", .argument = "FILE.json",
               .help = "also write the canvas's rectangle in the screenshot's pixels and\n"
                       "its map: pixel = origin + scale (x, -y), scale in px/m",
               .modes = Screenshot, .section = S::Screenshot},
    OptionSpec{.name = "--body", .argument = "auto|scale|outline|marker",
               .help = "the bodies to scale, as outlines or as markers, in the\n"
                       "screenshot or --animation; auto (the default) picks one\n"
                       "from the body's size beside the path's",
               .modes = Screenshot | Headless, .section = S::Screenshot},
    OptionSpec{.name = "--wheel-view", .argument = "",
               .help = "the side view of the disk's or the carriage's wheels turning\n"
                       "(View > Bodies > Side view of the wheels) in the screenshot",
               .modes = Screenshot, .section = S::Screenshot},
    OptionSpec{.name = "--plots-zoom", .argument = "N",
               .help = "the time plots zoomed in N notches (0 ... 60) about the time\n"
                       "shown, as View > Plots' time > Zoom in on the time",
               .modes = Screenshot, .section = S::Screenshot},
    OptionSpec{.name = "--language", .argument = "en|pt_BR",
               .help = "that catalogue instead of the system's (exit 2 when it is not\n"
                       "installed)",
               .modes = Screenshot, .section = S::Screenshot},
    OptionSpec{.name = "--lecture", .argument = "FILE.json",
               .help = "a lecture file instead of a scene: its scene --lecture-entry\n"
                       "with the Lecture dock in front",
               .modes = Screenshot, .section = S::Screenshot},
    OptionSpec{.name = "--lecture-entry", .argument = "N",
               .help = "the lecture's scene shown, 1 (the default) ... its number of\n"
                       "scenes",
               .modes = Screenshot, .section = S::Screenshot},
    OptionSpec{.name = "--preset", .argument = "line|circle|catenary|sinusoid",
               .help = "the paper's examples with the paper's parameters",
               .modes = kAllModes, .section = S::Scene},
    OptionSpec{.name = "--path", .argument = "\"y=EXPR\" | \"x=EXPR;y=EXPR\"",
               .help = "a graph path in x (with --x-range) or a parametric path in u\n"
                       "(with --u-range)",
               .modes = kAllModes, .section = S::Scene},
    OptionSpec{.name = "--x-range", .argument = "X0,X1",
               .help = "a graph path traversed from X0 to X1 (X1 < X0: from right to left)",
               .modes = kAllModes, .section = S::Scene},
    OptionSpec{.name = "--u-range", .argument = "U0,U1",
               .help = "a parametric path traversed from U0 to U1",
               .modes = kAllModes, .section = S::Scene},
    OptionSpec{.name = "--points", .argument = "\"x0,y0 x1,y1 ...\"",
               .help = "a polyline (drawn) path",
               .modes = kAllModes, .section = S::Scene},
    OptionSpec{.name = "--corners", .argument = "pivot|smooth",
               .help = "how a --points path turns at its corners",
               .modes = kAllModes, .section = S::Scene},
    OptionSpec{.name = "--corner-angle", .argument = "DEG",
               .help = "pivot corners of a --points path: where it turns by more than\n"
                       "DEG degrees over 3 points either side (default 35); smaller\n"
                       "turns are smoothed",
               .modes = kAllModes, .section = S::Scene},
    OptionSpec{.name = "--scene", .argument = "FILE|LINK",
               .help = "a scene saved by the app (JSON), or a scene link\n"
                       "chaplygin-lab:... (File > Copy link, --link)",
               .modes = kAllModes, .section = S::Scene},
    OptionSpec{.name = "--system", .argument = "sleigh|disk|carriage",
               .help = "default sleigh",
               .modes = kAllModes, .section = S::System},
    OptionSpec{.name = "--param", .argument = "NAME=VALUE",
               .help = parameterHelp(),
               .modes = kAllModes, .section = S::System, .repeatable = true},
    OptionSpec{.name = "--mode", .argument = "energy|speed",
               .help = "constant kinetic energy (default) or constant speed",
               .modes = kAllModes, .section = S::System},
    OptionSpec{.name = "--vT", .argument = "V",
               .help = "v_T = sqrt(2T/m_eff) [m/s] in constant-energy mode",
               .modes = kAllModes, .section = S::System},
    OptionSpec{.name = "--vs", .argument = "V",
               .help = "the constant speed [m/s] in constant-speed mode",
               .modes = kAllModes, .section = S::System},
    OptionSpec{.name = "--t-end", .argument = "T",
               .help = "horizon [s]; default: time to traverse the path",
               .modes = kAllModes, .section = S::System},
    OptionSpec{.name = "--perturb", .argument = "NAME=VALUE",
               .help = "repeatable; a perturbed body beside the controlled one, open loop\n"
                       "and with feedback: dy [m, left], dphi, dpsi [rad] at t = 0; a push\n"
                       "t_push [s] with push_psi [rad] or push_dy [m]; controller_b [m]\n"
                       "(constant-energy mode; CSV columns pert_* and fb_*)",
               .modes = kAllModes, .section = S::System, .repeatable = true},
    OptionSpec{.name = "--feedback-rate", .argument = "P",
               .help = "the feedback's triple pole at -P in path length [1/m] (default 1)",
               .modes = kAllModes, .section = S::System},
    OptionSpec{.name = "--feedback-limit", .argument = "PSIDOT_MAX",
               .help = "the feedback's bound on |Psidot| [rad/s] (default none)",
               .modes = kAllModes, .section = S::System},
    OptionSpec{.name = "--headless", .argument = "",
               .help = "run without a window and write what the options below ask for\n"
                       "(it may stand anywhere)",
               .modes = Headless, .section = S::Output, .repeatable = true},
    OptionSpec{.name = "--times", .argument = "T1,T2,...",
               .help = "rows exactly at these times",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--samples", .argument = "N",
               .help = "rows evenly spaced on [0, t_end] (default 501)",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--csv", .argument = "FILE|-",
               .help = "time series (CSV with a header row)",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--summary", .argument = "FILE|-",
               .help = "JSON: b, m_eff, path length, duration, models used\n"
                       "(printed on standard output when no output is given)",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--link", .argument = "",
               .help = "print the scene's link, chaplygin-lab: and the scene compressed\n"
                       "(what File > Copy link copies), alone",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--plan-to", .argument = "X,Y,PHI",
               .help = "plan the genuine vakonomic motions to this pose [m, m, rad]\n"
                       "(docs/physics.md §10; no path needed): --summary gains \"plan\",\n"
                       "--csv writes the optimal motion's vak_* columns",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--plan-from", .argument = "X,Y,PHI",
               .help = "the plan's start pose (default: the path's start, else 0,0,0)",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--plan-horizon", .argument = "T",
               .help = "list motions arriving within T [s] (default: three times the\n"
                       "least time, at least 2 pi b/v_T)",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--plan-choice", .argument = "N",
               .help = "--csv writes the N-th listed motion (default: the first optimal one)",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--track-plan", .argument = "",
               .help = "the chosen motion's knife track becomes the path and the usual run\n"
                       "follows: the controlled body tracking it is the genuine vakonomic\n"
                       "body (docs/physics.md §10)",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--plots", .argument = "DIR",
               .help = "the plots, as the app draws them",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--format", .argument = "png,pdf,svg",
               .help = "the plots' file formats (default png)",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--work-precision", .argument = "",
               .help = "the speed-against-accuracy sweep of every method:\n"
                       "CSV columns problem, method, tolerance, error, seconds, rhs_evals, chosen;\n"
                       "--summary names the references, --plots draws the diagram",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--sweep", .argument = "NAME=FROM:TO:COUNT",
               .help = "one CSV row per value of a parameter (m, a, b, I, vT,\n"
                       "vs, or the disk's or carriage's): NAME, duration,\n"
                       "max_abs_lambda, max_abs_control_couple,\n"
                       "max_abs_force_lateral, max_abs_control_power,\n"
                       "final_separation; --plots draws each column",
               .modes = Headless | Screenshot, .section = S::Output},
    OptionSpec{.name = "--animation", .argument = "FILE",
               .help = "the canvas from 0 to t_end in real time: FILE.gif or\n"
                       "FILE.mp4 (needs the ffmpeg program), or a folder of\n"
                       "PNG frames (FILE ending in / or without extension)",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--fps", .argument = "N",
               .help = "the animation's frames per second (default 30)",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--size", .argument = "WxH",
               .help = "the animation's size (default 1280x720)",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--with-plots", .argument = "",
               .help = "the plots beside the canvas in the animation",
               .modes = Headless, .section = S::Output},
    OptionSpec{.name = "--help", .argument = "",
               .help = "print this text and exit (also -h)",
               .modes = kAllModes, .section = S::General, .repeatable = true},
    OptionSpec{.name = "--version", .argument = "",
               .help = "print the version and exit",
               .modes = kAllModes, .section = S::General},
};
// clang-format on

std::string_view canonicalName(std::string_view name) {
    return name == "-h" ? std::string_view("--help") : name;
}

// "the window and --screenshot": the run modes in which `name` is an option, or empty
std::string modesAccepting(std::string_view name) {
    std::string out;
    for (auto [mode, title] :
         {std::pair{Window, "the window"}, std::pair{Screenshot, "--screenshot"},
          std::pair{Headless, "--headless"}}) {
        const bool accepted = std::any_of(kOptions.begin(), kOptions.end(), [&](const auto& spec) {
            return spec.name == canonicalName(name) && (spec.modes & mode) != 0;
        });
        if (accepted)
            out += (out.empty() ? "" : " and ") + std::string(title);
    }
    return out;
}

} // namespace

std::span<const OptionSpec> optionTable() {
    return kOptions;
}

const OptionSpec* findOption(std::string_view name, RunMode mode) {
    name = canonicalName(name);
    for (const OptionSpec& spec : kOptions)
        if (spec.name == name && (spec.modes & mode) != 0)
            return &spec;
    return nullptr;
}

const OptionSpec& OptionValues::checked(std::string_view name) const {
    for (const OptionSpec& spec : kOptions)
        if (spec.name == name)
            return spec;
    throw std::logic_error("no option " + std::string(name) + " in the option table");
}

std::optional<std::string> OptionValues::value(std::string_view name) const {
    checked(name);
    for (const Given& g : m_given)
        if (g.spec->name == name)
            return g.value;
    return std::nullopt;
}

std::vector<std::string> OptionValues::values(std::string_view name) const {
    checked(name);
    std::vector<std::string> out;
    for (const Given& g : m_given)
        if (g.spec->name == name)
            out.push_back(g.value);
    return out;
}

bool OptionValues::has(std::string_view name) const {
    return value(name).has_value();
}

bool OptionValues::hasAnyOf(OptionSection section) const {
    return std::any_of(m_given.begin(), m_given.end(),
                       [section](const Given& g) { return g.spec->section == section; });
}

OptionValues readOptions(const std::vector<std::string>& args, RunMode mode) {
    OptionValues read;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& word = args[i];
        const OptionSpec* spec = findOption(word, mode);
        if (!spec) {
            const std::string where = modesAccepting(word);
            throw InputError(word, where.empty() ? "unknown option (see --help)"
                                                 : "applies only to " + where);
        }
        std::string value;
        if (!spec->argument.empty()) {
            if (i + 1 >= args.size())
                throw InputError(word, "needs a value");
            if (args[i + 1].rfind("--", 0) == 0)
                throw InputError(word,
                                 "needs a value (the next word is the option " + args[i + 1] + ")");
            value = args[++i];
        }
        const bool again =
            std::any_of(read.m_given.begin(), read.m_given.end(),
                        [spec](const OptionValues::Given& g) { return g.spec == spec; });
        if (again && !spec->repeatable)
            throw InputError(word, "given more than once");
        read.m_given.push_back({spec, std::move(value)});
    }
    return read;
}

} // namespace chaplygin::app
