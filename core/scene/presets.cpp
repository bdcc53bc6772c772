#include "scene/presets.h"

#include "common/input_error.h"

#include <numbers>

namespace chaplygin {

std::vector<std::string> presetNames() {
    return {"line", "circle", "catenary", "sinusoid"};
}

Scene presetScene(const std::string& name) {
    Scene s;
    s.preset = name;
    s.system.kind = SystemKind::Sleigh;
    s.system.params = {{"m", 1.0}, {"a", 0.5}, {"b", 1.0}};
    s.mode = SpeedMode::Energy;
    s.speed = 1.0;
    PathSource& p = s.path;
    if (name == "line") {
        // y = A x + B, eqs. (72)-(81)
        p.kind = PathKind::Graph;
        p.y = "0.5*x + 1";
        p.from = 0;
        p.to = 8;
    } else if (name == "circle") {
        // x = R cos(s/R), y = R sin(s/R), eq. (82): starts at (R, 0), counter-clockwise
        p.kind = PathKind::Parametric;
        p.xOfU = "2*cos(u)";
        p.yOfU = "2*sin(u)";
        p.from = 0;
        p.to = 2 * std::numbers::pi;
    } else if (name == "catenary") {
        // x = sqrt(s^2 + x0^2), y = x0 ln(s + sqrt(s^2 + x0^2)), eqs. (97)-(98), x0 = 1, s in [0,
        // 5]
        p.kind = PathKind::Parametric;
        p.xOfU = "sqrt(u^2 + 1)";
        p.yOfU = "ln(u + sqrt(u^2 + 1))";
        p.from = 0;
        p.to = 5;
    } else if (name == "sinusoid") {
        // y = -R sin(x/R), R = 1, eqs. (108)-(113), two periods
        p.kind = PathKind::Graph;
        p.y = "-sin(x)";
        p.from = 0;
        p.to = 4 * std::numbers::pi;
    } else {
        throw InputError("preset",
                         "unknown preset '" + name + "' (use line, circle, catenary or sinusoid)");
    }
    return s;
}

std::string presetDescription(const std::string& name) {
    if (name == "line")
        return "Straight line y = 0.5 x + 1 (paper eqs. 72-81): Psi = pi/2, chi constant, lambda = "
               "0.";
    if (name == "circle")
        return "Circle of radius 2 from (2, 0), counter-clockwise (eqs. 82-96): period 2 pi "
               "sqrt(b^2 + R^2)/v_T.";
    if (name == "catenary")
        return "Catenary with x0 = 1, arc length 0..5 (eqs. 97-107, Fig. 2): turns clockwise, Psi "
               "in (pi/2, pi).";
    if (name == "sinusoid")
        return "Sinusoid y = -sin x over two periods (eqs. 108-113, Fig. 3): Psi passes pi/2 at "
               "inflections.";
    return {};
}

} // namespace chaplygin
