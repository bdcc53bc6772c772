#pragma once
#include "control/control_law.h"
#include "paths/path_source.h"
#include "systems/system.h"

#include <optional>
#include <string>

namespace chaplygin {

/// Everything that defines a scene: plain data with defaults, saved and loaded as JSON,
/// shared by the GUI, the CLI and the tests.
struct Scene {
    std::string preset; ///< the preset it came from, or empty
    PathSource path;
    SystemSpec system;
    SpeedMode mode = SpeedMode::Energy;
    double speed = 1.0;         ///< v_T (Energy) or v_s (Speed) [m/s]
    std::optional<double> tEnd; ///< horizon [s]; default: the time to traverse the path

    bool operator==(const Scene&) const = default;
};

} // namespace chaplygin
