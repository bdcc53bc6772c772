#pragma once
// The 8-point Gauss-Legendre rule: its nodes and weights, mapped to an interval.
#include <array>

namespace chaplygin::gauss {

/// 8-point Gauss-Legendre rule on [-1, 1]; exact for polynomials up to degree 15.
constexpr int kPoints = 8;
constexpr std::array<double, kPoints> kNodes = {
    -0.9602898564975362316835609, -0.7966664774136267395915539, -0.5255324099163289858177390,
    -0.1834346424956498049394761, 0.1834346424956498049394761,  0.5255324099163289858177390,
    0.7966664774136267395915539,  0.9602898564975362316835609};
constexpr std::array<double, kPoints> kWeights = {
    0.1012285362903762591525314, 0.2223810344533744705443560, 0.3137066458778872873379622,
    0.3626837833783619829651504, 0.3626837833783619829651504, 0.3137066458778872873379622,
    0.2223810344533744705443560, 0.1012285362903762591525314};

/// The nodes of the rule mapped to [a, b]; weights scaled by (b - a)/2.
struct Mapped {
    std::array<double, kPoints> x;
    std::array<double, kPoints> w;
};
inline Mapped mapTo(double a, double b) {
    Mapped m;
    double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    for (int i = 0; i < kPoints; ++i) {
        m.x[i] = mid + half * kNodes[i];
        m.w[i] = half * kWeights[i];
    }
    return m;
}

/// \int_a^b f(x) dx with the 8-point rule.
template <class F> double integrate(double a, double b, F&& f) {
    Mapped m = mapTo(a, b);
    double sum = 0;
    for (int i = 0; i < kPoints; ++i)
        sum += m.w[i] * f(m.x[i]);
    return sum;
}

} // namespace chaplygin::gauss
