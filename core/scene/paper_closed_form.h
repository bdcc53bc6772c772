#pragma once
// The paper's closed forms for the line and circle presets, independent of the path table and
// the time law: what the accuracy readout compares with.
#include "scene/scene.h"

#include <optional>
#include <string>

namespace chaplygin {

/// The knife point P by the paper's own closed forms, independent of the path table and the
/// time law: what the GUI's accuracy readout compares the Solution with.
struct PaperPoint {
    double x = 0, y = 0;   ///< [m]
    std::string equations; ///< which of the paper's equations, e.g. "eqs. (93)-(94)"
};

/// For the unmodified line and circle presets in constant-energy mode (any system, any v_T):
/// line y = A x + B from x = 0, paper (80)-(81): x = v_T t/sqrt(1 + A^2), y = A x + B;
/// circle of radius R from (R, 0), paper (93)-(94): x = R cos(w t), y = R sin(w t) with
/// w = v_T/sqrt(b^2 + R^2), paper (95). Empty for every other scene and for negative t.
std::optional<PaperPoint> paperClosedForm(const Scene& scene, double t);

} // namespace chaplygin
