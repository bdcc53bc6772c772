#include "paths/cusp_finder.h"

#include "common/input_error.h"
#include "numerics/safeguarded_newton.h"
#include "paths/panel_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace chaplygin {
namespace {

constexpr int kSamples = 256; // a cusp is the sample nearest to it, a discrete minimum of |r'|^2
constexpr double kZeroSpeed = 1e-12; // |r'| at the cusp, relative to the largest |r'|
constexpr double kZeroAccel = 1e-8;  // |r''|, relative to the largest |r'| per unit u
constexpr double kZeroCross = 1e-10; // r'' x r''', relative to |r''| |r'''|

double speed2(const CurvePoint& p) {
    return p.dx * p.dx + p.dy * p.dy;
}

// The cusp's u to rounding: no step test, the iteration runs until the bracket is 4 eps |u| wide
// or r'.r'' is exactly 0; 100 iterations are a bound (bisection alone would need about 45)
constexpr NewtonCaps kCuspCaps{
    .maxIterations = 100,
    .bracket = {.value = 4 * std::numeric_limits<double>::epsilon(), .relativeToX = true},
    .stopAtRoot = true};

// r'.r'' = (|r'|^2)'/2 changes sign from - to + at a minimum of |r'|: Newton, kept in [lo, hi]
double refineMinimum(const Curve& c, double lo, double hi, double u) {
    auto slope = [&](double v) {
        CurvePoint p = c.eval(v);
        return NewtonValue{p.dx * p.ddx + p.dy * p.ddy,
                           p.ddx * p.ddx + p.ddy * p.ddy + p.dx * p.dddx + p.dy * p.dddy};
    };
    return safeguardedNewton(slope, u, {lo, hi}, kCuspCaps).x;
}

} // namespace

double psiAtCusp(const Cusp& cusp, int direction) {
    return std::atan2(direction * 0.0, cusp.turnRate);
}

std::vector<Cusp> findCusps(const Curve& c) {
    const double u0 = c.u0(), u1 = c.u1(), width = u1 - u0;
    std::vector<double> us(kSamples + 1), q(kSamples + 1);
    double qMax = 0;
    for (int i = 0; i <= kSamples; ++i) {
        us[i] = i == kSamples ? u1 : u0 + width * i / kSamples;
        q[i] = speed2(c.eval(us[i]));
        if (std::isfinite(q[i]))
            qMax = std::max(qMax, q[i]);
    }
    std::vector<Cusp> cusps;
    if (!(qMax > 0))
        return cusps; // no direction anywhere: PathTable names the place
    const double scale = std::sqrt(qMax);
    for (int i = 1; i < kSamples; ++i) {
        // near a cusp |r'|^2 ~ (u - u*)^2 |r''|^2: the nearest sample is at most a ninth of the
        // larger neighbour; a slow but moving stretch is not a candidate
        if (!(q[i] <= q[i - 1] && q[i] <= q[i + 1] && q[i] <= 0.25 * std::max(q[i - 1], q[i + 1])))
            continue;
        double u = q[i] == 0 ? us[i] : refineMinimum(c, us[i - 1], us[i + 1], us[i]);
        CurvePoint p = c.eval(u);
        if (!(std::sqrt(speed2(p)) <= kZeroSpeed * scale))
            continue; // a slow stretch, not a stop
        if (!cusps.empty() && u <= cusps.back().u)
            continue; // the same point seen from two samples
        const double accel = std::hypot(p.ddx, p.ddy), jerk = std::hypot(p.dddx, p.dddy);
        if (!(accel > kZeroAccel * scale / width))
            throw InputError(pathPlace(c, u),
                             "the path stops here (x' = y' = 0 and x'' = y'' = 0): "
                             "not a cusp the body can be driven through");
        const double cross = p.ddx * p.dddy - p.ddy * p.dddx;
        if (!(std::fabs(cross) > kZeroCross * accel * std::max(jerk, accel / width)))
            throw InputError(pathPlace(c, u),
                             "the path stops and retraces itself here (x' = y' = 0 without a "
                             "turn): the body would have to reverse at once");
        cusps.push_back({u, accel, cross / (2 * accel * accel)});
    }
    return cusps;
}

} // namespace chaplygin
