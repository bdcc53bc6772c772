// The method lab from Python: parameter sweeps and the work-precision table as dicts of NumPy
// arrays (the columns of their CSVs), and the gallery's entries. Both run without the GIL.
#include "bindings.h"

#include "lab/gallery.h"
#include "lab/parameter_sweep.h"
#include "lab/work_precision.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace pybind11::literals;

namespace chaplygin::python {
namespace {

template <typename T, typename Row, typename Get>
py::array_t<T> columnOf(const std::vector<Row>& rows, Get get) {
    py::array_t<T> out(static_cast<py::ssize_t>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i)
        out.mutable_data()[i] = static_cast<T>(get(rows[i]));
    return out;
}

template <typename Row, typename Get>
py::array stringColumnOf(const std::vector<Row>& rows, Get get) {
    py::list out;
    for (const Row& r : rows)
        out.append(get(r));
    return py::module_::import("numpy").attr("array")(out, "dtype"_a = "str");
}

// the columns of formatSweepCsv: the parameter's values, then each quantity
py::dict sweep(const Scene& scene, const std::string& parameter, double from, double to,
               int count) {
    SweepSpec spec{parameter, from, to, count};
    SweepReport report;
    {
        py::gil_scoped_release release;
        report = runParameterSweep(scene, spec);
    }
    py::dict out;
    out[py::str(parameter)] =
        columnOf<double>(report.rows, [](const SweepRow& r) { return r.value; });
    for (int q = 0; q < kSweepQuantityCount; ++q) {
        const auto quantity = static_cast<SweepQuantity>(q);
        out[py::str(sweepQuantityColumn(quantity))] = columnOf<double>(
            report.rows, [quantity](const SweepRow& r) { return sweepQuantityValue(r, quantity); });
    }
    return out;
}

// the columns of formatWorkPrecisionCsv, and the free body's energy drift
py::dict workPrecision(const Scene& scene, int outputs,
                       const std::optional<std::vector<double>>& tolerances,
                       const std::optional<std::vector<long>>& stepCounts, double maxSolveSeconds) {
    WorkPrecisionOptions options;
    options.outputs = outputs;
    if (tolerances)
        options.tolerances = *tolerances;
    if (stepCounts)
        options.stepCounts = *stepCounts;
    options.maxSolveSeconds = maxSolveSeconds;
    WorkPrecisionReport report;
    {
        py::gil_scoped_release release;
        report = runWorkPrecision(scene, options);
    }
    using Row = WorkPrecisionRow;
    const auto& rows = report.rows;
    py::dict out;
    out["problem"] =
        stringColumnOf(rows, [](const Row& r) { return motionProblemName(r.problem); });
    out["method"] = stringColumnOf(rows, [](const Row& r) { return r.method; });
    out["tolerance"] = columnOf<double>(rows, [](const Row& r) { return r.setting; });
    out["error"] = columnOf<double>(rows, [](const Row& r) { return r.error; });
    out["seconds"] = columnOf<double>(rows, [](const Row& r) { return r.seconds; });
    out["rhs_evals"] = columnOf<long>(rows, [](const Row& r) { return r.rhsEvals; });
    out["chosen"] = columnOf<bool>(rows, [](const Row& r) { return r.chosen; });
    out["energy_drift"] = columnOf<double>(rows, [](const Row& r) { return r.energyDrift; });
    return out;
}

} // namespace

void bindLab(py::module_& m) {
    py::class_<Scene>(m.attr("Scene"))
        .def("sweep", &sweep, py::arg("parameter"), py::arg("start"), py::arg("stop"),
             py::arg("count"),
             "sweep(\"b\", 0.6, 2.4, 8): the parameter over COUNT evenly spaced values, each "
             "solved over the whole path (docs/numerics.md §6). A dict of arrays: the "
             "parameter's values, duration [s], max_abs_lambda [kg m/s], "
             "max_abs_control_couple [N m], max_abs_force_lateral [N], max_abs_control_power "
             "[W], final_separation [m].")
        .def_property_readonly(
            "sweep_parameters",
            [](const Scene& s) { return sweepParameterNames(s.system.kind, s.mode); },
            "the names sweep() takes for this system and mode")
        .def("with_parameter", &sceneWithParameter, py::arg("name"), py::arg("value"),
             "A copy with one system parameter, or the speed (vT, vs), set.")
        .def("parameter", &sceneParameter, py::arg("name"),
             "A system parameter's value (the sleigh's b or I derived when not given).")
        .def("work_precision", &workPrecision, py::arg("outputs") = 100,
             py::arg("tolerances") = py::none(), py::arg("step_counts") = py::none(),
             py::arg("max_solve_seconds") = 0.25,
             "Every method of the registry over its tolerances or step counts, timed and "
             "compared with the reference (docs/numerics.md §2): a dict of arrays problem, "
             "method, tolerance (or the step h [s]), error [m], seconds, rhs_evals, chosen "
             "(the CSV's columns) and energy_drift. Takes seconds.");
    m.def(
        "gallery_entries",
        [] {
            py::list out;
            for (const GalleryEntry& e : galleryEntries()) {
                py::dict entry;
                entry["name"] = e.name;
                entry["title"] = e.title;
                entry["rejected"] = e.rejected;
                entry["message"] = e.message;
                entry["note"] = e.scene.note;
                out.append(entry);
            }
            return out;
        },
        "The gallery: name, title, whether the app refuses the scene (rejected) and the words "
        "of its refusal (message), and the lecturer's note; Scene.gallery(name) loads one.");
}

} // namespace chaplygin::python
