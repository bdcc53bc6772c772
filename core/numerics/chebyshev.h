#pragma once
#include <array>
#include <cstddef>

namespace chaplygin::cheb {

/// Degree of the per-panel interpolants: N = 16, N + 1 points.
constexpr int kDegree = 16;
constexpr int kPoints = kDegree + 1;
/// The lower degree a panel tries first (docs/numerics.md §7). Its points are every second point
/// of degree kDegree, so a panel that needs the full degree keeps the values it has.
constexpr int kLowDegree = 8;

/// Chebyshev points of the second kind on [-1, 1], x_j = cos(pi j/N), j = 0..N (from 1 to -1).
const std::array<double, kPoints>& points();

/// Coefficients c_0..c_N of the interpolant sum c_k T_k(x) through f_j at points()
/// (discrete cosine transform; Trefethen, Approximation Theory and Approximation Practice, ch. 3).
void coefficients(const double* values, double* coeffs);

/// The transform of degree n (kLowDegree or kDegree) as a row-major (n + 1) x (n + 1) matrix:
/// c_k = sum_j m[k (n + 1) + j] f_j for f_j at x_j = cos(pi j/n). It is symmetric.
const double* transform(int degree);

/// Coefficients of Q interpolants of degree n (kLowDegree or kDegree) at once, values and
/// coefficients interleaved ([j][q] and [k][q]) so the work vectorises across the Q series.
template <std::size_t Q>
inline void coefficientsMany(const std::array<double, Q>* values, int degree,
                             std::array<double, Q>* coeffs) {
    const double* m = transform(degree);
    const int n = degree + 1;
    if constexpr (Q >= 4) {
        // enough series to fill the vector registers: one coefficient at a time
        for (int k = 0; k < n; ++k) {
            std::array<double, Q> s{};
            for (int j = 0; j < n; ++j) {
                const double w = m[k * n + j];
                for (std::size_t q = 0; q < Q; ++q)
                    s[q] += w * values[j][q];
            }
            coeffs[k] = s;
        }
    } else {
        // few series: the n + 1 sums side by side (independent, so they vectorise and pipeline),
        // each over j in the same order; the transform is symmetric
        for (int k = 0; k < n; ++k)
            coeffs[k] = {};
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const double w = m[j * n + k];
                for (std::size_t q = 0; q < Q; ++q)
                    coeffs[k][q] += w * values[j][q];
            }
    }
}

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

/// Q series at once, coefficients interleaved c[k][q] (so the inner loop vectorises); `rows`
/// coefficients from c.
template <std::size_t Q>
inline void evaluateMany(const std::array<double, Q>* c, std::size_t rows, double x, double* out) {
    std::array<double, Q> b1{}, b2{};
    const double x2 = 2 * x;
    for (std::size_t k = rows - 1; k >= 1; --k)
        for (std::size_t q = 0; q < Q; ++q) {
            double b = x2 * b1[q] - b2[q] + c[k][q];
            b2[q] = b1[q];
            b1[q] = b;
        }
    for (std::size_t q = 0; q < Q; ++q)
        out[q] = x * b1[q] - b2[q] + c[0][q];
}

/// The same over an array, of which only the first `rows` coefficients are summed (the rest are
/// zero: a panel of lower degree).
template <std::size_t Q, std::size_t N>
inline void evaluateMany(const std::array<std::array<double, Q>, N>& c, double x, double* out,
                         std::size_t rows = N) {
    evaluateMany(c.data(), rows, x, out);
}

} // namespace chaplygin::cheb
