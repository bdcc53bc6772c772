#include "scene/paper_closed_form.h"

#include "scene/presets.h"

#include <cmath>

namespace chaplygin {

std::optional<PaperPoint> paperClosedForm(const Scene& scene, double t) {
    if (scene.mode != SpeedMode::Energy || !std::isfinite(t) || t < 0)
        return std::nullopt;
    if (scene.preset != "line" && scene.preset != "circle")
        return std::nullopt;
    // only the preset's own path: an edited expression has no closed form here
    if (scene.path != presetScene(scene.preset).path)
        return std::nullopt;
    const double vT = scene.speed;
    PaperPoint p;
    if (scene.preset == "line") {
        // y = A x + B with A = 0.5, B = 1 from x = 0; sdot = v_T, paper (80)-(81)
        const double A = 0.5, B = 1;
        p.x = vT * t / std::sqrt(1 + A * A);
        p.y = A * p.x + B;
        p.equations = "eqs. (80)-(81)";
        return p;
    }
    // circle R = 2 from (R, 0) counter-clockwise: w = v_T/sqrt(b^2 + R^2), paper (93)-(95)
    const double R = 2, b = deriveSystem(scene.system).b;
    const double w = vT / std::sqrt(b * b + R * R);
    p.x = R * std::cos(w * t);
    p.y = R * std::sin(w * t);
    p.equations = "eqs. (93)-(94)";
    return p;
}

} // namespace chaplygin
