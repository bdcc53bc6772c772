#pragma once
#include <array>
#include <cstddef>

namespace chaplygin::cheb {

/// Degree of the per-panel interpolants: N = 16, N + 1 points.
constexpr int kDegree = 16;
constexpr int kPoints = kDegree + 1;

/// Chebyshev points of the second kind on [-1, 1], x_j = cos(pi j/N), j = 0..N (from 1 to -1).
const std::array<double, kPoints>& points();

/// Coefficients c_0..c_N of the interpolant sum c_k T_k(x) through f_j at points()
/// (discrete cosine transform; Trefethen, Approximation Theory and Approximation Practice, ch. 3).
void coefficients(const double* values, double* coeffs);

/// The coefficients (n + 1 of them) of \int_{-1}^x of the series with n coefficients.
void integrate(const double* c, int n, double* out);

/// A posteriori error estimate of an interpolant from its last three coefficients: for a
/// function resolved by the panel the coefficients decay geometrically and the error of the
/// interpolant is at most a few times the last ones (ATAP ch. 8).
double tailEstimate(const double* c, int n);

/// sum c_k T_k(x) by Clenshaw's recurrence.
inline double evaluate(const double* c, int n, double x) {
    double b1 = 0, b2 = 0;
    const double x2 = 2 * x;
    for (int k = n - 1; k >= 1; --k) {
        double b = x2 * b1 - b2 + c[k];
        b2 = b1;
        b1 = b;
    }
    return x * b1 - b2 + c[0];
}

/// Series q of Q interleaved series (coefficients c[k][q]).
template <std::size_t Q, std::size_t N>
inline double evaluateOne(const std::array<std::array<double, Q>, N>& c, std::size_t q, double x) {
    double b1 = 0, b2 = 0;
    const double x2 = 2 * x;
    for (std::size_t k = N - 1; k >= 1; --k) {
        double b = x2 * b1 - b2 + c[k][q];
        b2 = b1;
        b1 = b;
    }
    return x * b1 - b2 + c[0][q];
}

/// Q series at once, coefficients interleaved c[k][q] (so the inner loop vectorises).
template <std::size_t Q, std::size_t N>
inline void evaluateMany(const std::array<std::array<double, Q>, N>& c, double x, double* out) {
    std::array<double, Q> b1{}, b2{};
    const double x2 = 2 * x;
    for (std::size_t k = N - 1; k >= 1; --k)
        for (std::size_t q = 0; q < Q; ++q) {
            double b = x2 * b1[q] - b2[q] + c[k][q];
            b2[q] = b1[q];
            b1[q] = b;
        }
    for (std::size_t q = 0; q < Q; ++q)
        out[q] = x * b1[q] - b2[q] + c[0][q];
}

} // namespace chaplygin::cheb
