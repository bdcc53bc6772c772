#include "control/printed_branch.h"

#include <cmath>
#include <numbers>

namespace chaplygin {

double printedBranchPsi(double b, double kappa) {
    // atan(rho/b) with rho = 1/kappa; at kappa = 0 the printed formula has no value, and its
    // limits from the two sides are +pi/2 and -pi/2
    if (kappa == 0)
        return std::numbers::pi / 2;
    return std::atan(1.0 / (b * kappa));
}

} // namespace chaplygin
