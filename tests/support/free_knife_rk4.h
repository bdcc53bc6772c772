#pragma once
// An independent reference for the free (Lagrange-d'Alembert) sleigh the planner's ghost follows,
// shared by the core's and the window's tests: classical RK4, none of the program's code.
#include "classical_rk4.h"

#include <array>
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
    return classicalRk4(k,
                        std::array{&FreeKnife::x, &FreeKnife::y, &FreeKnife::phi, &FreeKnife::sdot,
                                   &FreeKnife::phidot},
                        rate, t, n);
}

} // namespace chaplygin::reference
