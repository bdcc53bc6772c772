// The chaplygin_lab Python module: the core of Chaplygin Lab without Qt (docs/python.md). Bad
// input raises chaplygin_lab.InputError, a ValueError whose message is the core's ("where: what")
// and whose `where` attribute names the field or the place on the path.
#include "bindings.h"

#include "common/input_error.h"

#include <cmath>

namespace py = pybind11;

namespace chaplygin::python {

double numberArgument(py::handle value, const std::string& where) {
    if (PyBool_Check(value.ptr()) || !PyNumber_Check(value.ptr()) || PyComplex_Check(value.ptr()))
        throw InputError(where, "expects a number, got " + std::string(py::repr(value)));
    const double v = PyFloat_AsDouble(value.ptr());
    if (v == -1.0 && PyErr_Occurred()) {
        PyErr_Clear();
        throw InputError(where, "expects a number, got " + std::string(py::repr(value)));
    }
    return v;
}

} // namespace chaplygin::python

PYBIND11_MODULE(chaplygin_lab, m) {
    m.doc() = "Chaplygin Lab's engine: scenes, their exact solution sampled into NumPy arrays, "
              "parameter sweeps and the work-precision table (docs/python.md).";
    m.attr("__version__") = CHAPLYGIN_VERSION;

    static py::exception<chaplygin::InputError> inputError(m, "InputError", PyExc_ValueError);
    inputError.doc() = "Bad input: a ValueError with the core's message; `where` names the field, "
                       "the parameter or the place on the path.";
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p)
                std::rethrow_exception(p);
        } catch (const chaplygin::InputError& e) {
            // the class called with the message: an instance that can carry `where`
            py::object error = py::handle(inputError.ptr())(py::str(e.what()));
            error.attr("where") = py::str(e.where());
            PyErr_SetObject(inputError.ptr(), error.ptr());
        }
    });

    chaplygin::python::bindScene(m);
    chaplygin::python::bindSolution(m);
    chaplygin::python::bindLab(m);
    chaplygin::python::bindPlan(m);
}
