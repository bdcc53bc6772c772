#pragma once
// The parts of the chaplygin_lab Python module (docs/python.md), each binding one concept of the
// core: scenes and their systems, solutions and the CSV's columns, the method lab.
#include <pybind11/pybind11.h>

#include <string>

namespace chaplygin::python {

/// System, Sleigh, Disk, Carriage, Perturbation and Scene (presets, gallery, JSON, built in
/// Python).
void bindScene(pybind11::module_& m);
/// Column, columns, column() and Solution (sample, summary, models, tracking errors).
void bindSolution(pybind11::module_& m);
/// Scene.sweep, Scene.work_precision and the gallery's entries.
void bindLab(pybind11::module_& m);
/// plan(), Motion and Scene.from_plan (pose to pose).
void bindPlan(pybind11::module_& m);

/// A Python number as a double; throws InputError(where) for anything else.
double numberArgument(pybind11::handle value, const std::string& where);

} // namespace chaplygin::python
