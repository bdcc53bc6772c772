#include "paths/curve.h"

#include <cmath>

namespace chaplygin {

CurveGeometry geometryOf(const CurvePoint& p) {
    CurveGeometry g;
    // kappa = N / D^{3/2}, N = x'y'' - y'x'', D = x'^2 + y'^2 (docs/physics.md §2)
    double d = p.dx * p.dx + p.dy * p.dy;
    double n = p.dx * p.ddy - p.dy * p.ddx;
    g.speed = std::sqrt(d);
    const double invSpeed = 1 / g.speed, invD15 = invSpeed / d;
    g.kappa = n * invD15;
    // dN/du = x'y''' - y'x''' (the x''y'' terms cancel), dD/du = 2(x'x'' + y'y'')
    double dn = p.dx * p.dddy - p.dy * p.dddx;
    double dd = 2 * (p.dx * p.ddx + p.dy * p.ddy);
    double dkappaDu = (dn - 1.5 * n * dd / d) * invD15;
    g.dkappa = dkappaDu * invSpeed;
    g.heading = std::atan2(p.dy, p.dx);
    return g;
}

} // namespace chaplygin
