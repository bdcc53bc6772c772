#include "paths/panel_geometry.h"

#include "common/input_error.h"

#include <cmath>

namespace chaplygin {
namespace {

// 0 x is 0 for a finite x and NaN for an infinite or NaN one: one test for all six
bool finite(const CurvePoint& p) {
    return std::isfinite(0 * p.dx + 0 * p.dy + 0 * p.ddx + 0 * p.ddy + 0 * p.dddx + 0 * p.dddy);
}

} // namespace

std::string pathPlace(const Curve& c, double u) {
    return "path at " + c.parameterName() + " = " + formatNumber(c.parameterValue(u));
}

CurveGeometry checkedGeometry(const Curve& c, double u, CurvePoint* out) {
    CurvePoint p = c.eval(u);
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw InputError(pathPlace(c, u),
                         "the path is not defined here (division by zero, log of 0 or of a "
                         "negative number, sqrt of a negative number, or overflow)");
    if (!finite(p))
        throw InputError(pathPlace(c, u),
                         "the path has no finite tangent or curvature here (a vertical "
                         "tangent, a kink, or a singular point)");
    if (p.dx == 0 && p.dy == 0)
        throw InputError(pathPlace(c, u),
                         "the path stops here (x' = y' = 0): a cusp or a stationary point "
                         "has no direction to follow");
    CurveGeometry g = geometryOf(p);
    if (!std::isfinite(g.kappa) || !std::isfinite(g.dkappa))
        throw InputError(pathPlace(c, u), "the curvature overflows here");
    if (out)
        *out = p;
    return g;
}

PanelData computePanel(const Curve& c, double a, double b, double lengthScale) {
    PanelData d;
    d.a = a;
    d.b = b;
    gauss::Mapped m = gauss::mapTo(a, b);
    for (int i = 0; i < gauss::kPoints; ++i) {
        CurvePoint p;
        const CurveGeometry& g = d.geometry[i] = checkedGeometry(c, m.x[i], &p);
        d.x[i] = p.x;
        d.y[i] = p.y;
        double ds = m.w[i] * g.speed;
        d.gauss.weight[i] = ds;
        d.gauss.kappa[i] = g.kappa;
        d.length += ds;
        d.turn += ds * g.kappa;
        d.absTurn += ds * std::fabs(g.kappa);
        // proxy for the time-law integrand sqrt(1 + b^2 kappa^2) ds with b of the path's size
        d.weighted += ds * hypotOne(lengthScale * g.kappa);
        d.stiff += ds * hypotOne(kStiffScale * lengthScale * g.kappa);
    }
    return d;
}

} // namespace chaplygin
