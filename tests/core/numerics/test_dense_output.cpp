// The quintic Hermite dense output (docs/numerics.md §1): exact for quintics, O(h^6) otherwise,
// y'' from the Jacobian, clamped outside its nodes.
#include "numerics/dense_output.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace chaplygin;

namespace {

// y' = p'(t), independent of y: the solution is p(t) + const
class Quadrature final : public OdeProblem {
  public:
    Quadrature(std::function<double(double)> dp, std::function<double(double)> ddp)
        : m_dp(std::move(dp)), m_ddp(std::move(ddp)) {}
    int dimension() const override { return 1; }
    void rhs(double t, const double*, double* dydt) const override { dydt[0] = m_dp(t); }
    void jacobian(double t, const double*, double* dfdy, double* dfdt) const override {
        dfdy[0] = 0;
        dfdt[0] = m_ddp(t);
    }

  private:
    std::function<double(double)> m_dp, m_ddp;
};

// y' = (-y1, y0): y = (cos t, sin t), y'' = J y' with no df/dt
class Rotation final : public OdeProblem {
  public:
    int dimension() const override { return 2; }
    void rhs(double, const double* y, double* dydt) const override {
        dydt[0] = -y[1];
        dydt[1] = y[0];
    }
    void jacobian(double, const double*, double* dfdy, double* dfdt) const override {
        dfdy[0] = 0, dfdy[1] = -1, dfdy[2] = 1, dfdy[3] = 0;
        dfdt[0] = dfdt[1] = 0;
    }
};

DenseOutput rotationNodes(double h, double end, OdeWork& work) {
    Rotation r;
    DenseOutput d(2);
    for (double t = 0; t <= end + 1e-12; t += h) {
        const double y[2] = {std::cos(t), std::sin(t)}, f[2] = {-std::sin(t), std::cos(t)};
        d.add(r, t, y, f, work);
    }
    return d;
}

double rotationError(double h) {
    OdeWork work;
    DenseOutput d = rotationNodes(h, 2.0, work);
    double worst = 0;
    for (int i = 0; i <= 997; ++i) {
        const double t = 2.0 * i / 997;
        double y[2];
        d.at(t, y);
        worst = std::max({worst, std::fabs(y[0] - std::cos(t)), std::fabs(y[1] - std::sin(t))});
    }
    return worst;
}

} // namespace

TEST(DenseOutput, ReproducesAQuinticExactly) {
    const auto p = [](double t) { return 1 - 2 * t + 0.5 * t * t * t - 0.25 * std::pow(t, 5); };
    const auto dp = [](double t) { return -2 + 1.5 * t * t - 1.25 * std::pow(t, 4); };
    const auto ddp = [](double t) { return 3 * t - 5 * t * t * t; };
    Quadrature q(dp, ddp);
    DenseOutput d(1);
    OdeWork work;
    for (double t : {0.0, 0.7, 2.0}) { // unequal steps
        const double y = p(t), f = dp(t);
        d.add(q, t, &y, &f, work);
    }
    EXPECT_EQ(work.jacobianEvals, 3);
    for (int i = 0; i <= 200; ++i) {
        const double t = 2.0 * i / 200;
        double y = 0;
        d.at(t, &y);
        EXPECT_NEAR(y, p(t), 1e-13) << t; // roundings of terms up to h|f| ~ 20, h²|f'| ~ 60
    }
}

TEST(DenseOutput, ErrorFallsAsTheSixthPowerOfTheStep) {
    // the Hermite remainder y^(6)(xi) s³(1-s)³ h^6/6!, at most h^6/(64 · 720) for |y^(6)| <= 1
    const double coarse = rotationError(0.4), fine = rotationError(0.2);
    EXPECT_LE(coarse, std::pow(0.4, 6) / (64 * 720) * 1.0001);
    EXPECT_LE(fine, std::pow(0.2, 6) / (64 * 720) * 1.0001);
    EXPECT_NEAR(coarse / fine, 64, 8);
}

TEST(DenseOutput, ClampsOutsideItsNodesAndFindsTheNodeBefore) {
    OdeWork work;
    DenseOutput d = rotationNodes(0.5, 1.0, work);
    ASSERT_EQ(d.size(), 3u);
    EXPECT_EQ(d.tFront(), 0.0);
    EXPECT_EQ(d.tBack(), 1.0);
    double y[2];
    d.at(-1, y);
    EXPECT_EQ(y[0], 1.0);
    EXPECT_EQ(y[1], 0.0);
    d.at(7, y);
    EXPECT_EQ(y[0], std::cos(1.0));
    EXPECT_EQ(y[1], std::sin(1.0));
    EXPECT_EQ(d.nodeBefore(-1), 0u);
    EXPECT_EQ(d.nodeBefore(0.5), 1u);
    EXPECT_EQ(d.nodeBefore(0.75), 1u);
    EXPECT_EQ(d.nodeBefore(9), 2u);
    EXPECT_EQ(d.time(1), 0.5);
    EXPECT_EQ(d.state(1)[1], std::sin(0.5));
    EXPECT_EQ(d.derivative(1)[0], -std::sin(0.5));
    // at a node the interpolant is the node's state
    d.at(0.5, y);
    EXPECT_NEAR(y[0], std::cos(0.5), 1e-16);
}
