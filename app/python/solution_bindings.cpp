// Solutions from Python: Scene.solve(), the CSV's column table, and sample(), which fills NumPy
// arrays in C++ with the GIL released (one Solution::at per time, no Python call per point).
#include "bindings.h"

#include "common/input_error.h"
#include "scene/csv_columns.h"
#include "scene/solution.h"
#include "scene/summary_json.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <sys/mman.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace py = pybind11;

namespace chaplygin::python {
namespace {

/// A solved scene as Python holds it: shared, so that arrays, threads and the Python object
/// may outlive the Scene it was solved from (the Solution keeps its own copy of the scene).
struct SolutionHandle {
    std::shared_ptr<const Solution> solution;
};

using TimesArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string columnNames(std::span<const CsvColumn> columns) {
    std::string out;
    for (const CsvColumn& c : columns)
        out += (out.empty() ? "" : ", ") + std::string(c.name);
    return out;
}

// the columns asked for, in the order asked, or every column the CSV writes for this solution
std::vector<const CsvColumn*>
selectedColumns(const Solution& solution, const std::optional<std::vector<std::string>>& names) {
    const auto written = csvColumnsWritten(solution.perturbed());
    std::vector<const CsvColumn*> out;
    if (!names) {
        for (const CsvColumn& c : written)
            out.push_back(&c);
        return out;
    }
    for (const std::string& name : *names) {
        const auto index = csvColumnIndex(name);
        if (!index)
            throw InputError("columns", "unknown column '" + name + "' (the columns are " +
                                            columnNames(written) + ")");
        if (*index >= written.size())
            throw InputError("columns", "'" + name +
                                            "' is a perturbed body's column; the scene has no "
                                            "perturbation");
        out.push_back(&csvColumns()[*index]);
    }
    return out;
}

// times within the horizon [0, t_end], the span the CSV's rows cover
void checkTimes(const Solution& solution, const double* t, py::ssize_t n) {
    const double horizon = solution.tEnd();
    for (py::ssize_t i = 0; i < n; ++i)
        if (!(t[i] >= 0 && t[i] <= horizon))
            throw InputError("t", formatNumber(t[i]) + " s at index " + std::to_string(i) +
                                      " is outside [0, " + formatNumber(horizon) +
                                      "], the scene's horizon t_end");
}

std::vector<py::ssize_t> shapeOf(const TimesArray& times) {
    return std::vector<py::ssize_t>(times.shape(), times.shape() + times.ndim());
}

// A long output array in memory of its own, mapped in 2 MB pages where the kernel grants them:
// the first touch of 4 kB pages (a fault each, 2048 per 8 MB column) was a fifth of a whole
// row's time (docs/numerics.md §8). Short arrays come from NumPy.
constexpr std::size_t kHugePage = std::size_t(2) << 20;

py::array_t<double> outputArray(const std::vector<py::ssize_t>& shape, py::ssize_t n) {
    const std::size_t bytes = std::size_t(n) * sizeof(double);
    if (bytes < 2 * kHugePage)
        return py::array_t<double>(shape);
    const std::size_t mapped = (bytes + kHugePage - 1) / kHugePage * kHugePage + kHugePage;
    void* base = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (base == MAP_FAILED)
        return py::array_t<double>(shape);
    // the 2 MB-aligned start within the mapping: only aligned 2 MB ranges get a huge page
    const auto start = (reinterpret_cast<std::uintptr_t>(base) + kHugePage - 1) & ~(kHugePage - 1);
    madvise(reinterpret_cast<void*>(start),
            mapped - (start - reinterpret_cast<std::uintptr_t>(base)), MADV_HUGEPAGE);
    struct Mapping {
        void* base;
        std::size_t size;
    };
    auto* owner = new Mapping{base, mapped};
    py::capsule free(owner, [](void* p) {
        auto* m = static_cast<Mapping*>(p);
        munmap(m->base, m->size);
        delete m;
    });
    std::vector<py::ssize_t> strides(shape.size(), py::ssize_t(sizeof(double)));
    for (std::size_t k = shape.size(); k-- > 1;)
        strides[k - 1] = strides[k] * shape[k];
    return py::array_t<double>(shape, strides, reinterpret_cast<double*>(start), free);
}

// the union of the columns' bodies: only these are computed per time
MotionParts partsOf(const std::vector<const CsvColumn*>& columns) {
    MotionParts parts{false, false, false, false};
    for (const CsvColumn* c : columns) {
        const MotionParts p = csvColumnParts(*c);
        parts.controlled |= p.controlled;
        parts.free |= p.free;
        parts.vakonomic |= p.vakonomic;
        parts.perturbed |= p.perturbed;
    }
    return parts;
}

// how many threads share n times: at least kTimesPerThread each, at most the machine's cores
constexpr py::ssize_t kTimesPerThread = 20000;

unsigned threadCount(const py::object& threads, py::ssize_t n) {
    if (!threads.is_none()) {
        const double asked = numberArgument(threads, "threads");
        if (asked != std::floor(asked) || asked < 1 || asked > 256)
            throw InputError("threads",
                             "must be a whole number from 1 to 256, got " + formatNumber(asked));
        return static_cast<unsigned>(asked);
    }
    const auto cores = static_cast<py::ssize_t>(std::max(1u, std::thread::hardware_concurrency()));
    return static_cast<unsigned>(std::clamp<py::ssize_t>(n / kTimesPerThread, 1, cores));
}

// every time is independent of the others (Solution::at is const and its caches per thread), so
// the values do not depend on how the times are shared out
void fillColumns(const Solution& solution, const std::vector<const CsvColumn*>& columns,
                 const double* t, py::ssize_t n, const std::vector<double*>& targets,
                 unsigned threads) {
    const MotionParts parts = partsOf(columns);
    const auto fill = [&](py::ssize_t begin, py::ssize_t end) {
        for (py::ssize_t i = begin; i < end; ++i) {
            const MotionSample m = solution.at(t[i], parts);
            for (std::size_t j = 0; j < columns.size(); ++j) {
                targets[j][i] = columns[j]->value(m);
                // a NaN never reaches an array without an error (docs/robustness.md)
                if (!std::isfinite(targets[j][i]))
                    throw InputError("", "column " + std::string(columns[j]->name) +
                                             " is not finite at t = " + formatNumber(t[i]) +
                                             " s (index " + std::to_string(i) +
                                             "): " + formatNumber(targets[j][i]));
            }
        }
    };
    if (threads <= 1) {
        fill(0, n);
        return;
    }
    std::vector<std::exception_ptr> errors(threads);
    std::vector<std::thread> workers;
    for (unsigned k = 0; k < threads; ++k) {
        const py::ssize_t begin = n * k / threads, end = n * (k + 1) / threads;
        workers.emplace_back([&, k, begin, end] {
            try {
                fill(begin, end);
            } catch (...) {
                errors[k] = std::current_exception();
            }
        });
    }
    for (std::thread& w : workers)
        w.join();
    for (const std::exception_ptr& e : errors)
        if (e)
            std::rethrow_exception(e);
}

py::dict sample(const SolutionHandle& self, const TimesArray& times,
                const std::optional<std::vector<std::string>>& names, const py::object& threads) {
    const Solution& solution = *self.solution;
    const std::vector<const CsvColumn*> columns = selectedColumns(solution, names);
    const py::ssize_t n = times.size();
    const double* t = times.data();
    checkTimes(solution, t, n);
    const unsigned workers = threadCount(threads, n);
    py::dict out;
    std::vector<double*> targets;
    for (const CsvColumn* c : columns) {
        py::array_t<double> values = outputArray(shapeOf(times), n);
        targets.push_back(values.mutable_data());
        out[py::str(std::string(c->name))] = std::move(values);
    }
    {
        py::gil_scoped_release release;
        fillColumns(solution, columns, t, n, targets, workers);
    }
    return out;
}

py::dict trackingErrors(const SolutionHandle& self, const TimesArray& times) {
    const Solution& solution = *self.solution;
    if (!solution.perturbed())
        throw InputError("tracking_errors", "the scene has no perturbation");
    const py::ssize_t n = times.size();
    checkTimes(solution, times.data(), n);
    const std::vector<double> t(times.data(), times.data() + n);
    std::vector<TrackingError> errors;
    {
        py::gil_scoped_release release;
        errors = solution.trackingErrors(t);
    }
    py::array_t<double> openE(n), openTheta(n), fbE(n), fbTheta(n);
    for (py::ssize_t i = 0; i < n; ++i) {
        openE.mutable_data()[i] = errors[i].openE;
        openTheta.mutable_data()[i] = errors[i].openTheta;
        fbE.mutable_data()[i] = errors[i].fbE;
        fbTheta.mutable_data()[i] = errors[i].fbTheta;
    }
    py::dict out;
    out["t"] = py::array_t<double>(n, t.data());
    out["open_e"] = openE;
    out["open_theta"] = openTheta;
    out["fb_e"] = fbE;
    out["fb_theta"] = fbTheta;
    return out;
}

py::object summaryOf(const Solution& solution) {
    return py::module_::import("json").attr("loads")(formatSummary(solution));
}

/// One column of the CSV as Python sees it.
struct ColumnInfo {
    std::string name, unit, meaning;
    bool perturbed = false;
};

ColumnInfo columnInfo(const CsvColumn& c) {
    return {std::string(c.name), std::string(c.unit), std::string(c.meaning), c.perturbed};
}

std::vector<ColumnInfo> columnInfos(std::span<const CsvColumn> columns) {
    std::vector<ColumnInfo> out;
    for (const CsvColumn& c : columns)
        out.push_back(columnInfo(c));
    return out;
}

void bindColumns(py::module_& m) {
    py::class_<ColumnInfo>(m, "Column", "One column of the CSV and of Solution.sample()")
        .def_readonly("name", &ColumnInfo::name, "the key in sample()'s dict and the CSV header")
        .def_readonly("unit", &ColumnInfo::unit, "its SI unit: s, m, rad, m/s, rad/s, J, N, ...")
        .def_readonly("meaning", &ColumnInfo::meaning, "what it is")
        .def_readonly("perturbed", &ColumnInfo::perturbed,
                      "only for a scene with a perturbation (docs/physics.md §9)")
        .def("__repr__", [](const ColumnInfo& c) {
            return "Column('" + c.name + "', unit='" + c.unit + "', meaning='" + c.meaning + "')";
        });
    m.attr("columns") = py::tuple(py::cast(columnInfos(csvColumns())));
    m.def(
        "column",
        [](const std::string& name) {
            const auto index = csvColumnIndex(name);
            if (!index)
                throw InputError("column", "unknown column '" + name + "' (the columns are " +
                                               columnNames(csvColumns()) + ")");
            return columnInfo(csvColumns()[*index]);
        },
        py::arg("name"), "The Column called NAME: its unit and meaning.");
}

} // namespace

void bindSolution(py::module_& m) {
    bindColumns(m);
    py::class_<SolutionHandle, std::shared_ptr<SolutionHandle>>(
        m, "Solution",
        "The exact solution of a scene: the controlled body, the free and the vakonomic body and, "
        "with a perturbation, the perturbed bodies, at any time. Immutable and safe to sample "
        "from several threads.")
        .def_property_readonly(
            "duration", [](const SolutionHandle& h) { return h.solution->duration(); },
            "the time to traverse the path [s]")
        .def_property_readonly(
            "t_end", [](const SolutionHandle& h) { return h.solution->tEnd(); }, "the horizon [s]")
        .def_property_readonly(
            "path_length", [](const SolutionHandle& h) { return h.solution->path()->length(); },
            "the path's length [m]")
        .def_property_readonly(
            "perturbed", [](const SolutionHandle& h) { return h.solution->perturbed(); },
            "whether the scene has a perturbation (and sample() the pert_ and fb_ columns)")
        .def_property_readonly(
            "scene", [](const SolutionHandle& h) { return h.solution->scene(); },
            "a copy of the Scene it was solved from")
        .def_property_readonly(
            "summary", [](const SolutionHandle& h) { return summaryOf(*h.solution); },
            "the --summary JSON as a dict")
        .def_property_readonly(
            "models",
            [](const SolutionHandle& h) {
                const py::object summary = summaryOf(*h.solution);
                return py::object(summary["models"]);
            },
            "which model or method produced each quantity, as in --summary")
        .def_property_readonly(
            "columns",
            [](const SolutionHandle& h) {
                return columnInfos(csvColumnsWritten(h.solution->perturbed()));
            },
            "the Columns sample() returns by default, in CSV order")
        .def("sample", &sample, py::arg("t"), py::arg("columns") = py::none(),
             py::arg("threads") = py::none(),
             "sample(t, columns=None, threads=None): the state at the times t [s] (a number, a "
             "list or an array, each in [0, t_end]), as a dict of float64 arrays of t's shape "
             "keyed by the CSV's "
             "column names (every column the CSV writes, or those named: only their bodies are "
             "computed). Runs in C++ without the GIL, on up to one thread per core for long "
             "arrays (threads=1: this thread only); the values do not depend on the threads.")
        .def("tracking_errors", &trackingErrors, py::arg("t"),
             "The perturbed bodies' lateral error e [m] and heading error theta [rad] against "
             "the path at increasing times t [s] (docs/physics.md §9): a dict of arrays t, "
             "open_e, open_theta, fb_e, fb_theta; NaN where no closest point is found.")
        .def("__repr__", [](const SolutionHandle& h) {
            return "<Solution duration=" + formatNumber(h.solution->duration()) +
                   " s, t_end=" + formatNumber(h.solution->tEnd()) + " s>";
        });
    py::class_<Scene>(m.attr("Scene"))
        .def(
            "solve",
            [](const Scene& scene) {
                std::shared_ptr<const Solution> solution;
                {
                    py::gil_scoped_release release;
                    solution = std::make_shared<const Solution>(Solution::compute(scene));
                }
                return std::make_shared<SolutionHandle>(SolutionHandle{std::move(solution)});
            },
            "Tabulates the path and solves: the Solution. Raises InputError (a ValueError) for "
            "a path, parameter or horizon the core refuses.");
}

} // namespace chaplygin::python
