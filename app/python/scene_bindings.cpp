// Scenes from Python: the systems, the perturbation and the Scene itself, from a preset, the
// gallery, a JSON text or file, or built from the same path strings the command line takes.
#include "bindings.h"

#include "common/input_error.h"
#include "control/control_law.h"
#include "lab/gallery.h"
#include "scene/perturbation.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "scene/speed_choice.h"
#include "systems/system_parameters.h"

#include <pybind11/stl.h>

#include <cctype>
#include <cmath>
#include <optional>
#include <utility>

namespace py = pybind11;

namespace chaplygin::python {
namespace {

// Sleigh(m=1, a=0.5, b=1): the system's defaults with the given parameters on top, set as --param
// sets them (the sleigh's I and b are alternatives). Checked at once.
SystemSpec makeSystem(SystemKind kind, const py::kwargs& params) {
    SystemSpec spec{kind, defaultSystemParams(kind)};
    for (const auto& [key, value] : params) {
        const std::string name = py::str(key);
        const double v = numberArgument(value, "parameter " + name);
        setSystemParameter(spec, name, v);
    }
    deriveSystem(spec);
    return spec;
}

std::string systemRepr(const SystemSpec& spec) {
    std::string kind = systemKindName(spec.kind);
    kind[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(kind[0])));
    std::string out = kind + "(";
    bool first = true;
    for (const SystemParameter& p : systemParameters(spec.kind)) {
        if (auto it = spec.params.find(p.name); it != spec.params.end()) {
            out += (first ? "" : ", ") + it->first + "=" + formatNumber(it->second);
            first = false;
        }
    }
    return out + ")";
}

Perturbation makePerturbation(const py::dict& fields) {
    Perturbation p;
    for (const auto& [key, value] : fields) {
        const std::string name = py::str(key);
        setPerturbationField(p, name, numberArgument(value, "perturbation " + name));
    }
    checkPerturbation(p);
    return p;
}

Perturbation perturbationArgument(const py::object& value) {
    if (py::isinstance<Perturbation>(value))
        return value.cast<Perturbation>();
    if (py::isinstance<py::dict>(value))
        return makePerturbation(value.cast<py::dict>());
    throw InputError("perturbation", "expects a Perturbation or a dict of its fields, got " +
                                         std::string(py::repr(value)));
}

std::string perturbationRepr(const Perturbation& p) {
    std::string out = "Perturbation(";
    bool first = true;
    for (const auto& [name, value] : perturbationFields(p)) {
        out += (first ? "" : ", ") + name + "=" + formatNumber(value);
        first = false;
    }
    return out + ")";
}

// (FROM, TO): two different numbers; TO < FROM runs the path backwards
std::pair<double, double> rangeArgument(const py::handle& value, const std::string& where) {
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) ||
        py::len(value) != 2)
        throw InputError(where,
                         "expects two numbers (FROM, TO), got " + std::string(py::repr(value)));
    const auto range = value.cast<py::sequence>();
    const double from = numberArgument(range[0], where), to = numberArgument(range[1], where);
    if (from == to)
        throw InputError(where, "FROM and TO must differ (TO < FROM runs backwards), got " +
                                    std::string(py::repr(value)));
    return {from, to};
}

// [(x0, y0), (x1, y1), ...] or an (N, 2) array; a bad point is named by its place, from 1
std::vector<std::pair<double, double>> pointsArgument(const py::handle& value) {
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value))
        throw InputError("points",
                         "expects a sequence of (x, y) pairs, got " + std::string(py::repr(value)));
    std::vector<std::pair<double, double>> points;
    int index = 0;
    for (const py::handle item : value) {
        const std::string where = "points, point " + std::to_string(++index);
        if (!py::isinstance<py::sequence>(item) || py::isinstance<py::str>(item) ||
            py::len(item) != 2)
            throw InputError(where, "expects (x, y), got " + std::string(py::repr(item)));
        const auto xy = py::reinterpret_borrow<py::sequence>(item);
        points.emplace_back(numberArgument(xy[0], where), numberArgument(xy[1], where));
    }
    return points;
}

std::optional<double> optionalNumber(const py::object& value, const std::string& where) {
    if (value.is_none())
        return std::nullopt;
    return numberArgument(value, where);
}

const SpeedSettingWords kPythonSpeedWords{"v_T", "v_s", "mode \"energy\"", "mode \"speed\""};

// mode, v_T and v_s as the command line takes --mode, --vT and --vs
void setMotion(Scene& s, const std::optional<std::string>& mode, const py::object& vTArg,
               const py::object& vSArg) {
    const auto vT = optionalNumber(vTArg, "v_T"), vS = optionalNumber(vSArg, "v_s");
    s.mode = chooseSpeedMode(s.mode, mode ? std::optional(speedModeFromName(*mode)) : std::nullopt,
                             vT.has_value(), vS.has_value(), kPythonSpeedWords);
    if (vT)
        s.speed = *vT;
    if (vS)
        s.speed = *vS;
}

void setNote(Scene& s, const std::string& note) {
    if (note.size() > kMaxNoteBytes)
        throw InputError("note", "is " + std::to_string(note.size()) +
                                     " bytes; a note is at most " + std::to_string(kMaxNoteBytes) +
                                     " bytes");
    s.note = note;
}

// the path: "y=EXPR" with x_range, "x=EXPR;y=EXPR" with u_range, or points
PathSource makePath(const std::optional<std::string>& path, const py::object& xRange,
                    const py::object& uRange, const py::object& points, const py::object& corners,
                    const py::object& smoothing, const py::object& cornerAngle) {
    PathSource source;
    if (path && !points.is_none())
        throw InputError("path", "give path or points, not both");
    if (path) {
        setPathExpressions(source, *path, "path");
        const bool graph = source.kind == PathKind::Graph;
        const py::object& range = graph ? xRange : uRange;
        const py::object& other = graph ? uRange : xRange;
        if (range.is_none())
            throw InputError(graph ? "x_range" : "u_range",
                             graph ? "a graph path y=EXPR needs x_range=(X0, X1)"
                                   : "a parametric path x=...;y=... needs u_range=(U0, U1)");
        if (!other.is_none())
            throw InputError(graph ? "u_range" : "x_range",
                             graph ? "belongs to a parametric path x=...;y=...; use x_range"
                                   : "belongs to a graph path y=...; use u_range");
        std::tie(source.from, source.to) = rangeArgument(range, graph ? "x_range" : "u_range");
    } else if (!points.is_none()) {
        source.kind = PathKind::Polyline;
        source.points = pointsArgument(points);
    } else {
        throw InputError("path", "no path: give path=\"y=EXPR\" with x_range, "
                                 "path=\"x=EXPR;y=EXPR\" with u_range, or points=[(x, y), ...]");
    }
    if (!path && !(xRange.is_none() && uRange.is_none()))
        throw InputError(xRange.is_none() ? "u_range" : "x_range", "applies only to path=");
    if (source.kind != PathKind::Polyline &&
        !(corners.is_none() && smoothing.is_none() && cornerAngle.is_none()))
        throw InputError(!corners.is_none()     ? "corners"
                         : !smoothing.is_none() ? "smoothing"
                                                : "corner_angle",
                         "applies only to points=");
    if (!corners.is_none())
        source.corners = cornerModeFromName(py::str(corners));
    if (!smoothing.is_none()) {
        source.smoothing = numberArgument(smoothing, "smoothing");
        if (!(source.smoothing >= 0) || !std::isfinite(source.smoothing))
            throw InputError("smoothing",
                             "must be a finite number >= 0, got " + formatNumber(source.smoothing));
    }
    if (!cornerAngle.is_none()) {
        source.cornerAngle = numberArgument(cornerAngle, "corner_angle");
        if (!(source.cornerAngle >= 0 && source.cornerAngle <= 180))
            throw InputError("corner_angle", "must be between 0 and 180 degrees, got " +
                                                 formatNumber(source.cornerAngle));
    }
    return source;
}

Scene makeScene(const std::optional<std::string>& path, const py::object& xRange,
                const py::object& uRange, const py::object& points, const py::object& corners,
                const py::object& smoothing, const py::object& cornerAngle,
                const std::optional<SystemSpec>& system, const std::optional<std::string>& mode,
                const py::object& vT, const py::object& vS, const py::object& tEnd,
                const py::object& perturbation, const std::string& note) {
    Scene s;
    s.path = makePath(path, xRange, uRange, points, corners, smoothing, cornerAngle);
    if (system)
        s.system = *system;
    setMotion(s, mode, vT, vS);
    s.tEnd = optionalNumber(tEnd, "t_end");
    if (!perturbation.is_none())
        s.perturbation = perturbationArgument(perturbation);
    setNote(s, note);
    return s;
}

// scene.replace(t_end=10, ...): a copy with the motion, the system or the perturbation changed
Scene replaceInScene(const Scene& scene, const py::kwargs& changes) {
    Scene s = scene;
    std::optional<std::string> mode;
    py::object vT = py::none(), vS = py::none();
    for (const auto& [key, value] : changes) {
        const std::string name = py::str(key);
        const auto object = py::reinterpret_borrow<py::object>(value);
        if (name == "system") {
            if (!py::isinstance<SystemSpec>(value))
                throw InputError("system", "expects a System such as Sleigh(m=1, a=0.5, b=1)");
            s.system = value.cast<SystemSpec>();
        } else if (name == "mode") {
            mode = py::str(value);
        } else if (name == "v_T") {
            vT = object;
        } else if (name == "v_s") {
            vS = object;
        } else if (name == "t_end") {
            s.tEnd = optionalNumber(object, "t_end");
        } else if (name == "perturbation") {
            s.perturbation.reset();
            if (!object.is_none())
                s.perturbation = perturbationArgument(object);
        } else if (name == "note") {
            setNote(s, py::str(value));
        } else {
            throw InputError(name, "cannot be replaced (use system, mode, v_T, v_s, t_end, "
                                   "perturbation or note; a new path is a new Scene)");
        }
    }
    setMotion(s, mode, vT, vS);
    s.preset.clear();
    return s;
}

py::object pathText(const Scene& s) {
    switch (s.path.kind) {
    case PathKind::Graph:
        return py::str("y=" + s.path.y);
    case PathKind::Parametric:
        return py::str("x=" + s.path.xOfU + ";y=" + s.path.yOfU);
    case PathKind::Polyline:
    case PathKind::Geodesic:
        break;
    }
    return py::none();
}

std::string sceneRepr(const Scene& s) {
    std::string out = "Scene(";
    if (!s.preset.empty())
        out += "preset='" + s.preset + "', ";
    if (s.path.kind == PathKind::Polyline)
        out += "points=<" + std::to_string(s.path.points.size()) + " points>";
    else
        out += "path='" + std::string(py::str(pathText(s))) + "', " +
               (s.path.kind == PathKind::Graph ? "x_range=(" : "u_range=(") +
               formatNumber(s.path.from) + ", " + formatNumber(s.path.to) + ")";
    out += ", system=" + systemRepr(s.system) + ", mode='" + speedModeName(s.mode) + "', " +
           (s.mode == SpeedMode::Energy ? "v_T=" : "v_s=") + formatNumber(s.speed);
    if (s.tEnd)
        out += ", t_end=" + formatNumber(*s.tEnd);
    if (s.perturbation)
        out += ", perturbation=" + perturbationRepr(*s.perturbation);
    return out + ")";
}

py::object optionalValue(const std::optional<double>& v) {
    return v ? py::object(py::float_(*v)) : py::object(py::none());
}

void bindSystem(py::module_& m) {
    py::class_<SystemSpec>(m, "System",
                           "A Chaplygin system and its parameters in SI units (kg, m, kg m^2). "
                           "Made by Sleigh(), Disk() or Carriage().")
        .def_property_readonly(
            "kind", [](const SystemSpec& s) { return systemKindName(s.kind); },
            "\"sleigh\", \"disk\" or \"carriage\"")
        .def_property_readonly(
            "parameters", [](const SystemSpec& s) { return s.params; },
            "the parameters as given, by name (SI units)")
        .def_property_readonly(
            "derived",
            [](const SystemSpec& s) {
                const DerivedSystem d = deriveSystem(s);
                py::dict out;
                out["m_eff"] = d.mass;
                out["a"] = d.a;
                out["b"] = d.b;
                out["I"] = d.inertia();
                out["m_translating"] = d.translatingMass;
                return out;
            },
            "the reduced sleigh (docs/physics.md §1): m_eff [kg], a [m], b [m], I about the "
            "centre of mass [kg m^2], m_translating [kg]")
        .def("__eq__", [](const SystemSpec& a, const SystemSpec& b) { return a == b; })
        .def("__repr__", &systemRepr);
    m.def(
        "Sleigh", [](const py::kwargs& p) { return makeSystem(SystemKind::Sleigh, p); },
        "Sleigh(m=1, a=0.5, b=1): mass m [kg], centre of mass a [m] ahead of the knife, and "
        "either I [kg m^2] about the centre of mass or the gyration radius b [m] about the knife. "
        "Missing parameters take the defaults.");
    m.def(
        "Disk", [](const py::kwargs& p) { return makeSystem(SystemKind::Disk, p); },
        "Disk(m=1, R=0.5, I1=0.125, I2=0.0625): the vertical rolling disk (paper App. A): mass "
        "[kg], radius [m], moments of inertia about the axle and about a diameter [kg m^2].");
    m.def(
        "Carriage", [](const py::kwargs& p) { return makeSystem(SystemKind::Carriage, p); },
        "Carriage(R=0.3, a=0.2, m=0.5, I1=0.0225, I2=0.01125, M=2, I=0.2): the two-wheeled "
        "carriage (paper App. B): wheel radius R [m], half-axle a [m], wheel mass m [kg] and "
        "moments I1, I2 [kg m^2], body mass M [kg] and moment I [kg m^2].");
}

void bindPerturbation(py::module_& m) {
    auto cls = py::class_<Perturbation>(
        m, "Perturbation",
        "The perturbed bodies of a scene (docs/physics.md §9): Perturbation(dy=0.3, "
        "feedback_rate=1, ...). Fields: dy [m], dphi [rad], dpsi [rad], t_push [s], push_psi "
        "[rad], push_dy [m], feedback_rate [1/m], feedback_limit [rad/s], controller_b [m].");
    cls.def(py::init([](const py::kwargs& fields) { return makePerturbation(fields); }))
        .def_property_readonly(
            "fields",
            [](const Perturbation& p) {
                py::dict out;
                for (const auto& [name, value] : perturbationFields(p))
                    out[py::str(name)] = value;
                return out;
            },
            "the fields a scene file writes, by name")
        .def_readonly("dy", &Perturbation::dy)
        .def_readonly("dphi", &Perturbation::dphi)
        .def_readonly("dpsi", &Perturbation::dpsi)
        .def_readonly("push_psi", &Perturbation::pushPsi)
        .def_readonly("push_dy", &Perturbation::pushDy)
        .def_readonly("feedback_rate", &Perturbation::feedbackRate)
        .def_property_readonly("t_push",
                               [](const Perturbation& p) { return optionalValue(p.tPush); })
        .def_property_readonly("feedback_limit",
                               [](const Perturbation& p) { return optionalValue(p.feedbackLimit); })
        .def_property_readonly("controller_b",
                               [](const Perturbation& p) { return optionalValue(p.controllerB); })
        .def("__eq__", [](const Perturbation& a, const Perturbation& b) { return a == b; })
        .def("__repr__", &perturbationRepr);
}

std::string filePath(const py::object& path) {
    return py::str(py::module_::import("os").attr("fspath")(path));
}

} // namespace

void bindScene(py::module_& m) {
    bindSystem(m);
    bindPerturbation(m);
    py::class_<Scene>(m, "Scene",
                      "A scene: the path, the system, the mode and speed, the horizon and an "
                      "optional perturbation. Immutable; solve() gives its Solution.")
        .def(py::init(&makeScene), py::arg("path") = py::none(), py::kw_only(),
             py::arg("x_range") = py::none(), py::arg("u_range") = py::none(),
             py::arg("points") = py::none(), py::arg("corners") = py::none(),
             py::arg("smoothing") = py::none(), py::arg("corner_angle") = py::none(),
             py::arg("system") = py::none(), py::arg("mode") = py::none(),
             py::arg("v_T") = py::none(), py::arg("v_s") = py::none(),
             py::arg("t_end") = py::none(), py::arg("perturbation") = py::none(),
             py::arg("note") = "",
             "Scene(path=\"y=-sin(x)\", x_range=(0, 12.57), system=Sleigh(m=1, a=0.5, b=1), "
             "mode=\"energy\", v_T=1): path as the command line's --path (\"y=EXPR\" with "
             "x_range, \"x=EXPR;y=EXPR\" with u_range) or points=[(x, y), ...] with corners "
             "(\"pivot\" or \"smooth\"), smoothing and corner_angle (degrees; pivot corners "
             "where the stroke turns by more, default 35); mode \"energy\" with v_T [m/s] or "
             "\"speed\" with v_s [m/s]; t_end [s]; perturbation a Perturbation or a dict.")
        .def_static("preset", &presetScene, py::arg("name"),
                    "One of the paper's four examples: \"line\", \"circle\", \"catenary\", "
                    "\"sinusoid\".")
        .def_static("preset_names", &presetNames, "The names Scene.preset() takes.")
        .def_static("preset_description", &presetDescription, py::arg("name"),
                    "One sentence about a preset.")
        .def_static(
            "gallery", [](const std::string& name) { return galleryEntry(name).scene; },
            py::arg("name"), "A scene of the gallery (where methods fail), by its name.")
        .def_static(
            "gallery_names",
            [] {
                std::vector<std::string> names;
                for (const GalleryEntry& e : galleryEntries())
                    names.push_back(e.name);
                return names;
            },
            "The names Scene.gallery() takes, in menu order.")
        .def_static("from_json", &sceneFromJson, py::arg("text"),
                    "A scene from the text of a scene file (File > Save, --scene).")
        .def_static(
            "from_file", [](const py::object& path) { return loadSceneFile(filePath(path)); },
            py::arg("path"), "A scene file (*.chaplygin.json, a preset's or a saved scene).")
        .def("to_json", &sceneToJson, "The scene file's text.")
        .def("replace", &replaceInScene,
             "A copy with some of system, mode, v_T, v_s, t_end, perturbation, note changed.")
        .def_property_readonly(
            "preset_name",
            [](const Scene& s) {
                return s.preset.empty() ? py::object(py::none()) : py::object(py::str(s.preset));
            },
            "the preset the scene came from, or None")
        .def_property_readonly("path", &pathText,
                               "\"y=EXPR\" or \"x=EXPR;y=EXPR\", or None for a polyline")
        .def_property_readonly(
            "path_range",
            [](const Scene& s) {
                return s.path.kind == PathKind::Polyline
                           ? py::object(py::none())
                           : py::object(py::make_tuple(s.path.from, s.path.to));
            },
            "(FROM, TO): the x_range of a graph or the u_range of a parametric path")
        .def_property_readonly(
            "points",
            [](const Scene& s) {
                return s.path.kind == PathKind::Polyline ? py::cast(s.path.points)
                                                         : py::object(py::none());
            },
            "the polyline's vertices [m], or None")
        .def_property_readonly(
            "corners", [](const Scene& s) { return cornerModeName(s.path.corners); },
            "a polyline's corners: \"pivot\" or \"smooth\"")
        .def_property_readonly(
            "corner_angle", [](const Scene& s) { return s.path.cornerAngle; },
            "a polyline's least turn that is a pivot corner [degrees]")
        .def_property_readonly(
            "system", [](const Scene& s) { return s.system; }, "the System")
        .def_property_readonly(
            "mode", [](const Scene& s) { return speedModeName(s.mode); },
            "\"energy\" (constant kinetic energy, v_T) or \"speed\" (constant speed, v_s)")
        .def_readonly("speed", &Scene::speed, "v_T or v_s by the mode [m/s]")
        .def_property_readonly(
            "t_end", [](const Scene& s) { return optionalValue(s.tEnd); },
            "the horizon [s], or None: the time to traverse the path")
        .def_property_readonly(
            "perturbation",
            [](const Scene& s) {
                return s.perturbation ? py::cast(*s.perturbation) : py::object(py::none());
            },
            "the Perturbation, or None")
        .def_readonly("note", &Scene::note, "the lecturer's Markdown note")
        .def("__eq__", [](const Scene& a, const Scene& b) { return a == b; })
        .def("__repr__", &sceneRepr)
        .def(py::pickle([](const Scene& s) { return sceneToJson(s); },
                        [](const std::string& json) { return sceneFromJson(json); }));
}

} // namespace chaplygin::python
