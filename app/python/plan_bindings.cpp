// Pose to pose from Python: plan() lists the genuine vakonomic motions from a start pose to a
// target (docs/physics.md §10), each sampled from its closed form, and Scene.from_plan() makes
// the scene that tracks one.
#include "bindings.h"

#include "common/input_error.h"
#include "planning/plan_track.h"
#include "planning/pose_planner.h"
#include "scene/scene.h"
#include "systems/system.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <string>

namespace py = pybind11;

namespace chaplygin::python {
namespace {

/// One planned motion with the request it answers and the system as given.
struct PlannedMotion {
    PlanRequest request;
    SystemSpec system;
    PlannedGeodesic geodesic;
};

using TimesArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

Pose poseArgument(const py::object& value, const std::string& where) {
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) ||
        py::len(value) != 3)
        throw InputError(where, "expects (x, y, phi), got " + std::string(py::repr(value)));
    const py::sequence s = value;
    return {numberArgument(s[0], where + " x"), numberArgument(s[1], where + " y"),
            numberArgument(s[2], where + " phi")};
}

std::vector<PlannedMotion> plan(const py::object& start, const py::object& target,
                                const py::object& system, const py::object& vT,
                                const py::object& horizon) {
    PlanRequest request;
    request.from = poseArgument(start, "start");
    request.to = poseArgument(target, "target");
    const SystemSpec spec = system.is_none() ? SystemSpec{} : system.cast<SystemSpec>();
    request.system = deriveSystem(spec);
    request.vT = numberArgument(vT, "v_T");
    if (!horizon.is_none()) {
        request.horizon = numberArgument(horizon, "horizon");
        if (!(request.horizon > 0) || !std::isfinite(request.horizon))
            throw InputError("horizon", "must be a finite number > 0 [s], got " +
                                            formatNumber(request.horizon));
    }
    Plan p;
    {
        py::gil_scoped_release release;
        p = planVakonomic(request);
    }
    std::vector<PlannedMotion> out;
    for (const PlannedGeodesic& g : p.geodesics)
        out.push_back({request, spec, g});
    return out;
}

py::dict sample(const PlannedMotion& m, const TimesArray& t) {
    const py::buffer_info in = t.request();
    const double* times = static_cast<const double*>(in.ptr);
    for (py::ssize_t i = 0; i < in.size; ++i)
        if (!(times[i] >= 0 && times[i] <= m.geodesic.t))
            throw InputError("t", formatNumber(times[i]) + " is outside [0, " +
                                      formatNumber(m.geodesic.t) + "], the planned motion");
    const char* names[] = {"vak_x", "vak_y", "vak_phi", "vak_sdot", "vak_phidot", "vak_lambda"};
    std::vector<py::array_t<double>> columns;
    for (int k = 0; k < 6; ++k)
        columns.emplace_back(in.shape);
    std::vector<double*> data;
    for (auto& c : columns)
        data.push_back(c.mutable_data());
    {
        py::gil_scoped_release release;
        const VakonomicMotion motion(m.request.system, plannedStart(m.request, m.geodesic));
        for (py::ssize_t i = 0; i < in.size; ++i) {
            const VakonomicState v = motion.at(times[i]);
            const double row[] = {v.x, v.y, v.phi, v.sdot, v.phidot, v.lambda};
            for (int k = 0; k < 6; ++k)
                data[k][i] = row[k];
        }
    }
    py::dict out;
    out["t"] = py::array_t<double>(in.shape, times);
    for (int k = 0; k < 6; ++k)
        out[names[k]] = columns[k];
    return out;
}

std::string motionRepr(const PlannedMotion& m) {
    const PlannedGeodesic& g = m.geodesic;
    return "<Motion " + geodesicFamilyName(g.family) + " t=" + formatNumber(g.t) +
           " s, psi0=" + formatNumber(g.psi0) + ", lambda0=" + formatNumber(g.lambda0) +
           (g.optimal ? ", optimal>" : ">");
}

} // namespace

void bindPlan(py::module_& m) {
    py::class_<PlannedMotion>(m, "Motion",
                              "A genuine vakonomic motion from plan() (docs/physics.md §10).")
        .def_property_readonly(
            "t", [](const PlannedMotion& p) { return p.geodesic.t; }, "arrival time [s]")
        .def_property_readonly(
            "psi0", [](const PlannedMotion& p) { return p.geodesic.psi0; },
            "Psi(0) = atan2(sdot, b phidot) in (-pi, pi] [rad]")
        .def_property_readonly(
            "psidot0", [](const PlannedMotion& p) { return p.geodesic.psidot0; },
            "Psidot(0) [rad/s]")
        .def_property_readonly(
            "lambda0", [](const PlannedMotion& p) { return p.geodesic.lambda0; },
            "lambda(0) [kg m/s]")
        .def_property_readonly(
            "family", [](const PlannedMotion& p) { return geodesicFamilyName(p.geodesic.family); },
            "\"rest\", \"pivot\", \"line\", \"libration\", \"rotation\" or \"separatrix\"")
        .def_property_readonly(
            "cut_time",
            [](const PlannedMotion& p) {
                return std::isfinite(p.geodesic.cutTime)
                           ? py::object(py::float_(p.geodesic.cutTime))
                           : py::object(py::none());
            },
            "the first Maxwell time [s], None where infinite")
        .def_property_readonly(
            "optimal", [](const PlannedMotion& p) { return p.geodesic.optimal; },
            "a least-time motion, certified by its cut time")
        .def_property_readonly(
            "modulus", [](const PlannedMotion& p) { return p.geodesic.modulus; },
            "the pendulum's k")
        .def_property_readonly(
            "modulus_gap", [](const PlannedMotion& p) { return p.geodesic.modulusGap; },
            "1 - k^2 as the planner carries it: exact next to the separatrix, where "
            "1 - modulus**2 in double is not; 0 on the line, 1 pivoting (docs/physics.md §10)")
        .def_property_readonly(
            "start",
            [](const PlannedMotion& p) {
                return py::make_tuple(p.request.from.x, p.request.from.y, p.request.from.phi);
            },
            "the start pose (x, y, phi)")
        .def_property_readonly(
            "target",
            [](const PlannedMotion& p) {
                return py::make_tuple(p.request.to.x, p.request.to.y, p.request.to.phi);
            },
            "the target pose (x, y, phi)")
        .def("sample", &sample, py::arg("t"),
             "sample(t): the genuine vakonomic body at the times t [s] (a number, a list or an "
             "array, each in [0, self.t]) from its closed form, as a dict of float64 arrays of "
             "t's shape: t, vak_x, vak_y, vak_phi, vak_sdot, vak_phidot, vak_lambda")
        .def("__repr__", &motionRepr);
    m.def("plan", &plan, py::arg("start"), py::arg("target"), py::kw_only(),
          py::arg("system") = py::none(), py::arg("v_T") = 1.0, py::arg("horizon") = py::none(),
          "plan(start, target, system=Sleigh(), v_T=1, horizon=None): every genuine vakonomic "
          "motion from the pose start = (x, y, phi) to target within the horizon [s] (None: "
          "three times the least time, at least 2 pi b/v_T), sorted by arrival time, as Motion "
          "objects; the least-time one(s) flagged optimal (docs/physics.md §10).");
    py::class_<Scene>(m.attr("Scene"))
        .def_static(
            "from_plan",
            [](const PlannedMotion& p) {
                Scene s;
                s.path = planTrack(p.request, p.geodesic);
                s.system = p.system;
                s.mode = SpeedMode::Energy;
                s.speed = p.request.vT;
                return s;
            },
            py::arg("motion"),
            "The scene whose path is the motion's knife track (through its cusps), at its v_T: "
            "the controlled body tracking it is the genuine vakonomic body (docs/physics.md §10).");
}

} // namespace chaplygin::python
