#pragma once
// The cusps of a curve, where r' vanishes, found and checked before it is tabulated
// (docs/physics.md §3).
#include "paths/curve.h"

#include <vector>

namespace chaplygin {

/// A cusp inside a curve's range: r'(u) = 0 with r''(u) != 0 and r'' x r''' != 0
/// (docs/physics.md §3). The knife heading, the tangent line, is continuous through it; the
/// direction of travel reverses.
struct Cusp {
    double u = 0;
    double accel = 0;    ///< |r''(u)|: d|r'|/du on either side
    double turnRate = 0; ///< dphi/du = (r'' x r''')/(2 |r''|^2), the heading's rate in u
};

/// Psi = atan2(sdot, b phidot) at the cusp on a stretch driven in `direction` (+1 forwards, -1
/// backing up), before the stretch's 2 pi n: sdot -> 0 with the sign of the direction, phidot
/// with the sign of dphi/du.
double psiAtCusp(const Cusp& cusp, int direction);

/// The interior points where r' vanishes, found from a sampled |r'|^2 and refined by Newton on
/// r'.r'' = 0. Each is a passable cusp, or an InputError naming the place: r' = r'' = 0 (a
/// stationary point of higher order) or r'' x r''' = 0 (the curve retraces itself: the body
/// would have to stop and reverse at once). The ends of the range are left to PathTable.
std::vector<Cusp> findCusps(const Curve& curve);

} // namespace chaplygin
