#include "numerics/chebyshev.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace chaplygin {
namespace {

// exp(x) = I_0(1) + 2 sum_k I_k(1) T_k(x); the interpolant in the n + 1 Chebyshev points aliases
// a_j onto c_k for j = 2mn +- k (Trefethen, ATAP Thm 4.2)
double expSeries(int k) {
    return (k == 0 ? 1.0 : 2.0) * std::cyl_bessel_i(static_cast<double>(k), 1.0);
}
double aliasedExp(int k, int n) {
    double c = 0;
    for (int j = 0; j <= 60; ++j)
        if ((j - k) % (2 * n) == 0 || (j + k) % (2 * n) == 0)
            c += expSeries(j);
    return c;
}

TEST(Chebyshev, InterpolantOfExpHasTheAliasedBesselCoefficients) {
    for (int n : {cheb::kLowDegree, cheb::kDegree}) {
        std::array<std::array<double, 2>, cheb::kPoints> f, c;
        for (int j = 0; j <= n; ++j) {
            const double x = std::cos(std::numbers::pi * j / n);
            f[j] = {std::exp(x), -3 * std::exp(x)};
        }
        cheb::coefficientsMany(f.data(), n, c.data());
        for (int k = 0; k <= n; ++k) {
            EXPECT_NEAR(c[k][0], aliasedExp(k, n), 4e-16) << "degree " << n << ", k = " << k;
            EXPECT_NEAR(c[k][1], -3 * aliasedExp(k, n), 12e-16) << "degree " << n << ", k = " << k;
        }
        // the interpolant's integral: \int T_k = 2/(1 - k^2) for even k; at degree 16 that of exp
        double integral = 0;
        for (int k = 0; k <= n; k += 2)
            integral += aliasedExp(k, n) * 2 / (1.0 - k * k);
        EXPECT_NEAR(cheb::integral(c.data(), n + 1, 0), integral, 1e-15);
        if (n == cheb::kDegree) {
            EXPECT_NEAR(integral, std::exp(1.0) - std::exp(-1.0), 1e-15);
        }
    }
}

// the folded transform against the full cosine sum written out here, on random values
TEST(Chebyshev, FoldedTransformEqualsTheFullCosineSum) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> value(-1, 1);
    for (int n : {cheb::kLowDegree, cheb::kDegree}) {
        std::array<std::array<double, 5>, cheb::kPoints> f, c;
        for (int j = 0; j <= n; ++j)
            for (double& v : f[j])
                v = value(rng);
        cheb::coefficientsMany(f.data(), n, c.data());
        for (int k = 0; k <= n; ++k)
            for (std::size_t q = 0; q < 5; ++q) {
                double s = 0, size = 0;
                for (int j = 0; j <= n; ++j) {
                    const double w = (j == 0 || j == n) ? 0.5 : 1.0;
                    s += w * f[j][q] * std::cos(std::numbers::pi * j * k / n);
                    size += std::fabs(w * f[j][q]);
                }
                s *= (k == 0 || k == n ? 1.0 : 2.0) / n;
                size *= 2.0 / n;
                // both sums round at most n + 1 times, each by an ulp of the terms' size
                EXPECT_NEAR(c[k][q], s, 2 * (n + 1) * std::numeric_limits<double>::epsilon() * size)
                    << "degree " << n << ", k = " << k;
            }
    }
}

// the first 4 of 5 series at +-x from a table of T_k(x): the even and odd sums written out here,
// and Clenshaw's sum at both points
TEST(Chebyshev, SeriesAtPlusAndMinusXAreTheirEvenPartPlusOrMinusTheOddPart) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> value(-1, 1);
    for (int n : {cheb::kLowDegree + 1, cheb::kPoints}) {
        std::array<std::array<double, 5>, cheb::kPoints> c{};
        for (int k = 0; k < n; ++k)
            for (double& v : c[k])
                v = value(rng);
        const double x = 0.5255324099163290; // a Gauss node
        std::array<double, cheb::kPoints> t{};
        t[0] = 1;
        t[1] = x;
        for (int k = 2; k < n; ++k)
            t[k] = 2 * x * t[k - 1] - t[k - 2];
        double atPlus[4], atMinus[4];
        int visits = 0;
        cheb::evaluateAtPlusMinus<4>(c.data(), n, t.data(), [&](int sign, const double* f) {
            std::copy(f, f + 4, sign > 0 ? atPlus : atMinus);
            visits += sign > 0 ? 1 : 10;
        });
        EXPECT_EQ(visits, 11);
        for (std::size_t q = 0; q < 4; ++q) {
            double even = 0, odd = 0;
            for (int k = 0; k < n; k += 2)
                even += t[k] * c[k][q];
            for (int k = 1; k < n; k += 2)
                odd += t[k] * c[k][q];
            EXPECT_NEAR(atPlus[q], even + odd, 1e-15) << "n = " << n << ", series " << q;
            EXPECT_NEAR(atMinus[q], even - odd, 1e-15) << "n = " << n << ", series " << q;
            const std::size_t rows = static_cast<std::size_t>(n);
            EXPECT_NEAR(atPlus[q], cheb::evaluateOne(c, q, x, rows), 1e-14);
            EXPECT_NEAR(atMinus[q], cheb::evaluateOne(c, q, -x, rows), 1e-14);
        }
    }
}

TEST(Chebyshev, TailEstimateReadsTheLastThreeCoefficientsOfItsColumn) {
    std::array<std::array<double, 2>, 6> c{};
    c[2] = {5, 0}; // outside the last three rows
    c[3] = {1e-3, 7};
    c[4] = {-2e-3, 8};
    c[5] = {1e-4, -9};
    EXPECT_EQ(cheb::tailEstimate(c.data(), 6, 0), 2e-3);
    EXPECT_EQ(cheb::tailEstimate(c.data(), 6, 1), 9.0);
}

} // namespace
} // namespace chaplygin
