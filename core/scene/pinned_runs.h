#pragma once
// Pinned runs: a run from a scene, back to a scene of its own, and its label.
#include "scene/scene.h"

#include <string>

namespace chaplygin {

/// The run a scene defines now, to pin for comparison.
PinnedRun pinOf(const Scene& scene);

/// A pinned run as a scene of its own (no note, vectors or pins), to be solved.
Scene sceneOf(const PinnedRun& pin);

/// What differs between a pinned run and the current scene, for its label, e.g.
/// "b = 0.5 m" or "v_T = 2 m/s, another path"; "same parameters" when nothing does.
std::string pinLabel(const PinnedRun& pin, const Scene& current);

} // namespace chaplygin
