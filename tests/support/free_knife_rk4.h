#pragma once
// An independent reference for the free (Lagrange-d'Alembert) sleigh the planner's ghost follows,
// shared by the core's and the window's tests: classical RK4, none of the program's code.
#include <cmath>
#include <vector>

namespace chaplygin::reference {

/// The knife's state: position [m], heading [rad], sdot [m/s], phidot [rad/s].
struct FreeKnife {
    double x, y, phi, sdot, phidot;
};

/// The free sleigh, sddot = a phidot^2, phiddot = -a sdot phidot / b^2, x' = sdot cos phi,
/// y' = sdot sin phi (paper (D12)-(D15)), by classical RK4 in n steps to t: the n + 1 states.
inline std::vector<FreeKnife> integrateFree(FreeKnife k, double a, double b, double t, int n) {
    auto rate = [&](const FreeKnife& s) {
        return FreeKnife{s.sdot * std::cos(s.phi), s.sdot * std::sin(s.phi), s.phidot,
                         a * s.phidot * s.phidot, -a * s.sdot * s.phidot / (b * b)};
    };
    auto step = [](const FreeKnife& s, const FreeKnife& d, double h) {
        return FreeKnife{s.x + h * d.x, s.y + h * d.y, s.phi + h * d.phi, s.sdot + h * d.sdot,
                         s.phidot + h * d.phidot};
    };
    std::vector<FreeKnife> out{k};
    const double h = t / n;
    for (int i = 0; i < n; ++i) {
        const FreeKnife k1 = rate(k), k2 = rate(step(k, k1, h / 2)), k3 = rate(step(k, k2, h / 2)),
                        k4 = rate(step(k, k3, h));
        auto mix = [&](double FreeKnife::*f) {
            return k.*f + h / 6 * (k1.*f + 2 * k2.*f + 2 * k3.*f + k4.*f);
        };
        k = FreeKnife{mix(&FreeKnife::x), mix(&FreeKnife::y), mix(&FreeKnife::phi),
                      mix(&FreeKnife::sdot), mix(&FreeKnife::phidot)};
        out.push_back(k);
    }
    return out;
}

} // namespace chaplygin::reference
