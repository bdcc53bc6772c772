#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>

namespace chaplygin::cheb {

/// Degree of the per-panel interpolants: N = 16, N + 1 points.
constexpr int kDegree = 16;
constexpr int kPoints = kDegree + 1;
/// The lower degree a panel tries first (docs/numerics.md §7). Its points are every second point
/// of degree kDegree, so a panel that needs the full degree keeps the values it has.
constexpr int kLowDegree = 8;

/// Chebyshev points of the second kind on [-1, 1], x_j = cos(pi j/N), j = 0..N (from 1 to -1).
const std::array<double, kPoints>& points();

/// The transform of degree n (kLowDegree or kDegree) as a row-major (n + 1) x (n + 1) matrix:
/// c_k = sum_j m[k (n + 1) + j] f_j for f_j at x_j = cos(pi j/n) (discrete cosine transform;
/// Trefethen, Approximation Theory and Approximation Practice, ch. 3). It is symmetric.
const double* transform(int degree);

namespace detail {
/// Two doubles in one vector register (a GCC and Clang extension): the transform below sums
/// across the interleaved series two at a time, which the compilers do not find on their own.
using Pair = double __attribute__((vector_size(16)));
} // namespace detail

/// Coefficients of Q interpolants of degree n (kLowDegree or kDegree) at once, values and
/// coefficients interleaved ([j][q] and [k][q]) so the work vectorises across the Q series.
/// The transform's columns j and n - j differ by (-1)^k, so the values are folded first,
/// f_j + f_{n-j} for even k and f_j - f_{n-j} for odd k: half the products of the full matrix.
template <std::size_t Q>
inline void coefficientsMany(const std::array<double, Q>* values, int degree,
                             std::array<double, Q>* coeffs) {
    const double* m = transform(degree);
    const int n = degree, half = degree / 2, stride = degree + 1;
    std::array<std::array<double, Q>, kDegree / 2 + 1> even, odd;
    for (int j = 0; j < half; ++j)
        for (std::size_t q = 0; q < Q; ++q) {
            even[j][q] = values[j][q] + values[n - j][q];
            odd[j][q] = values[j][q] - values[n - j][q];
        }
    even[half] = values[half]; // the middle column, once (its odd-k entries are cos(k pi/2) = 0)
    constexpr std::size_t kPairs = Q / 2;
    for (int k = 0; k <= n; ++k) {
        const std::array<double, Q>* folded = k % 2 ? odd.data() : even.data();
        const int count = k % 2 ? half : half + 1;
        detail::Pair s[kPairs + 1] = {}; // one more than needed: Q = 1 has no pair
        double last = 0;                 // the odd series out, when Q is odd
        for (int j = 0; j < count; ++j) {
            const double w = m[k * stride + j];
            const detail::Pair ww = {w, w};
            for (std::size_t p = 0; p < kPairs; ++p) {
                detail::Pair f;
                std::memcpy(&f, &folded[j][2 * p], sizeof f);
                s[p] += ww * f;
            }
            if constexpr (Q % 2 == 1)
                last += w * folded[j][Q - 1];
        }
        std::memcpy(coeffs[k].data(), s, kPairs * sizeof(detail::Pair));
        if constexpr (Q % 2 == 1)
            coeffs[k][Q - 1] = last;
    }
}

/// The coefficients (n + 1 of them) of \int_{-1}^x of the series with n coefficients.
void integrate(const double* c, int n, double* out);

/// A posteriori error estimate of series q of an interpolant with n coefficients (interleaved,
/// c[k][q]) from its last three coefficients: for a function resolved by the panel the
/// coefficients decay geometrically and the error of the interpolant is at most a few times the
/// last ones (ATAP ch. 8).
template <std::size_t Q>
inline double tailEstimate(const std::array<double, Q>* c, int n, std::size_t q) {
    return std::max({std::fabs(c[n - 1][q]), std::fabs(c[n - 2][q]), std::fabs(c[n - 3][q])});
}

/// \int_{-1}^{1} of series q of n interleaved coefficients: sum over even k of 2 c_k/(1 - k^2).
template <std::size_t Q>
inline double integral(const std::array<double, Q>* c, int n, std::size_t q) {
    double sum = 0;
    for (int k = 0; k < n; k += 2)
        sum += 2 * c[k][q] / (1.0 - k * k);
    return sum;
}

/// sum c_k T_k(x) by Clenshaw's recurrence, b_k = (c_k - b_{k+2}) + 2x b_{k+1}: b_{k+2} is known
/// a step early, so each step puts one multiply and one add on the dependency chain (here and in
/// the interleaved forms below).
inline double evaluate(const double* c, int n, double x) {
    double b1 = 0, b2 = 0;
    const double x2 = 2 * x;
    for (int k = n - 1; k >= 1; --k) {
        double b = (c[k] - b2) + x2 * b1;
        b2 = b1;
        b1 = b;
    }
    return (c[0] - b2) + x * b1;
}

/// Series q of Q interleaved series (coefficients c[k][q]); the first `rows` coefficients (the
/// rest are zero: a panel of lower degree).
template <std::size_t Q, std::size_t N>
inline double evaluateOne(const std::array<std::array<double, Q>, N>& c, std::size_t q, double x,
                          std::size_t rows = N) {
    double b1 = 0, b2 = 0;
    const double x2 = 2 * x;
    for (std::size_t k = rows - 1; k >= 1; --k) {
        double b = (c[k][q] - b2) + x2 * b1;
        b2 = b1;
        b1 = b;
    }
    return (c[0][q] - b2) + x * b1;
}

/// Q series at once, coefficients interleaved c[k][q] (so the inner loop vectorises); `rows`
/// coefficients from c.
template <std::size_t Q>
inline void evaluateMany(const std::array<double, Q>* c, std::size_t rows, double x, double* out) {
    std::array<double, Q> b1{}, b2{};
    const double x2 = 2 * x;
    for (std::size_t k = rows - 1; k >= 1; --k)
        for (std::size_t q = 0; q < Q; ++q) {
            double b = (c[k][q] - b2[q]) + x2 * b1[q];
            b2[q] = b1[q];
            b1[q] = b;
        }
    for (std::size_t q = 0; q < Q; ++q)
        out[q] = (c[0][q] - b2[q]) + x * b1[q];
}

/// The same over an array, of which only the first `rows` coefficients are summed (the rest are
/// zero: a panel of lower degree).
template <std::size_t Q, std::size_t N>
inline void evaluateMany(const std::array<std::array<double, Q>, N>& c, double x, double* out,
                         std::size_t rows = N) {
    evaluateMany(c.data(), rows, x, out);
}

/// d/dx of series q (the first `rows` coefficients of c[k][q]): sum k c_k U_{k-1}(x), by
/// Clenshaw's recurrence for the Chebyshev polynomials of the second kind.
template <std::size_t Q>
inline double derivativeOne(const std::array<double, Q>* c, std::size_t q, double x,
                            std::size_t rows) {
    double b1 = 0, b2 = 0;
    const double x2 = 2 * x;
    for (std::size_t j = rows - 1; j >= 1; --j) {
        double b = (static_cast<double>(j) * c[j][q] - b2) + x2 * b1;
        b2 = b1;
        b1 = b;
    }
    return b1;
}

} // namespace chaplygin::cheb
