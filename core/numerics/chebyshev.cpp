#include "numerics/chebyshev.h"

#include <cmath>
#include <numbers>

namespace chaplygin::cheb {
namespace {

// c = dct * f for degree n, row-major (n + 1) x (n + 1)
template <int n> std::array<double, (n + 1) * (n + 1)> dctOf() {
    std::array<double, (n + 1) * (n + 1)> m;
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j) {
            double w = (j == 0 || j == n) ? 0.5 : 1.0;
            double v = (k == 0 || k == n) ? 0.5 : 1.0;
            m[k * (n + 1) + j] =
                2.0 / n * w * v * std::cos(std::numbers::pi * ((j * k) % (2 * n)) / n);
        }
    return m;
}

struct Tables {
    std::array<double, kPoints> x;
    std::array<double, kPoints* kPoints> dct = dctOf<kDegree>();
    std::array<double, (kLowDegree + 1) * (kLowDegree + 1)> dctLow = dctOf<kLowDegree>();
    Tables() {
        for (int j = 0; j < kPoints; ++j)
            x[j] = std::cos(std::numbers::pi * j / kDegree);
        x[kDegree / 2] = 0; // exactly
    }
};

const Tables& tables() {
    static const Tables t;
    return t;
}

} // namespace

const std::array<double, kPoints>& points() {
    return tables().x;
}

const double* transform(int degree) {
    return degree == kLowDegree ? tables().dctLow.data() : tables().dct.data();
}

void integrate(const double* c, int n, double* out) {
    // T_k' relations: \int T_k = T_{k+1}/(2(k+1)) - T_{k-1}/(2(k-1)), \int T_0 = T_1, \int T_1 =
    // T_2/4
    auto at = [&](int k) { return k < n ? c[k] : 0.0; };
    for (int k = 1; k <= n; ++k)
        out[k] = k == 1 ? at(0) - 0.5 * at(2) : (at(k - 1) - at(k + 1)) / (2.0 * k);
    double atMinusOne = 0; // the series at x = -1 without out[0]
    for (int k = 1; k <= n; ++k)
        atMinusOne += (k % 2 ? -1.0 : 1.0) * out[k];
    out[0] = -atMinusOne;
}

} // namespace chaplygin::cheb
