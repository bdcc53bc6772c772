#pragma once
#include "scene/scene.h"

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace chaplygin {

/// The named fields of a Perturbation, as the scene file ("perturbation": {NAME: VALUE}) and the
/// command line (--perturb NAME=VALUE) spell them (docs/physics.md §9).
std::span<const std::string_view> perturbationFieldNames();

/// Sets the field NAME. Throws InputError("perturbation NAME") for a value out of its range, and
/// InputError("perturbation") naming the fields for an unknown NAME.
void setPerturbationField(Perturbation& p, std::string_view name, double value);

/// The fields a scene file writes: the offsets and the feedback rate always, the push and the
/// optional bounds when they are given.
std::vector<std::pair<std::string, double>> perturbationFields(const Perturbation& p);

/// The checks between fields: a push needs its time and its time a push. Throws InputError.
void checkPerturbation(const Perturbation& p);

} // namespace chaplygin
