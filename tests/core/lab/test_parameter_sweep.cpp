#include "common/input_error.h"
#include "lab/parameter_sweep.h"
#include "scene/presets.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <numbers>

namespace chaplygin {
namespace {

constexpr double kPi = std::numbers::pi;

double rel(double value, double reference) {
    return std::fabs(value - reference) / std::fabs(reference);
}

// circle R = 2, one loop (paper (82)-(96)): constant curvature, so every quantity is constant:
// duration 2 pi sqrt(b^2 + R^2)/v_T, sdot = v_T R/sqrt(R^2 + b^2), lambda = -m a kappa sdot,
// N = m sdot^2 kappa, tau = a N, and the control is workless
TEST(ParameterSweep, CircleMatchesTheClosedForms) {
    Scene scene = presetScene("circle");
    SweepReport report = runParameterSweep(scene, {"b", 0.6, 2.4, 4});
    ASSERT_EQ(report.rows.size(), 4u);
    const double m = 1, a = 0.5, R = 2, vT = 1;
    for (const SweepRow& row : report.rows) {
        double b = row.value;
        double sdot = vT * R / std::sqrt(R * R + b * b);
        EXPECT_LT(rel(row.duration, 2 * kPi * std::sqrt(b * b + R * R) / vT), 1e-12) << b;
        EXPECT_LT(rel(row.maxAbsLambda, m * a * sdot / R), 1e-12) << b;
        EXPECT_LT(rel(row.maxAbsForceLateral, m * sdot * sdot / R), 1e-12) << b;
        EXPECT_LT(rel(row.maxAbsControlCouple, a * m * sdot * sdot / R), 1e-12) << b;
        EXPECT_LT(row.maxAbsControlPower, 1e-12) << b;
        EXPECT_GT(row.finalSeparation, 0.1) << b;
    }
    EXPECT_DOUBLE_EQ(report.rows.front().value, 0.6);
    EXPECT_DOUBLE_EQ(report.rows.back().value, 2.4);
}

// sinusoid y = -sin x: kappa = sin x / D^(3/2), D = 1 + cos^2 x, dkappa/dx = cos x D^(-3/2) +
// 3 cos x sin^2 x D^(-5/2), ds/dx = sqrt(D)
double kappaOf(double x) {
    double d = 1 + std::cos(x) * std::cos(x);
    return std::sin(x) / std::pow(d, 1.5);
}
double kappaS(double x) {
    double c = std::cos(x), s = std::sin(x), d = 1 + c * c;
    return (c / std::pow(d, 1.5) + 3 * c * s * s / std::pow(d, 2.5)) / std::sqrt(d);
}

// max over [0, 4 pi] of f on a grid of 400001 points, refined by golden section
template <class F> double denseMax(F f) {
    const int n = 400001;
    const double h = 4 * kPi / (n - 1);
    double best = 0;
    for (int i = 1; i + 1 < n; ++i) {
        double v = f(i * h);
        best = std::max(best, v);
        if (v < f((i - 1) * h) || v < f((i + 1) * h))
            continue;
        double lo = (i - 1) * h, hi = (i + 1) * h, g = (std::sqrt(5.0) - 1) / 2;
        for (int it = 0; it < 80; ++it) {
            double c = hi - g * (hi - lo), d = lo + g * (hi - lo);
            (f(c) >= f(d) ? hi : lo) = (f(c) >= f(d) ? d : c);
        }
        best = std::max(best, f(0.5 * (lo + hi)));
    }
    return best;
}

// speed mode (App. C): dT/dt = m b^2 v_s^3 kappa kappa_s, N = m v_s^2 (kappa + a kappa_s),
// tau = I phiddot + a N with phiddot = v_s^2 kappa_s
TEST(ParameterSweep, SinusoidSpeedModeMatchesADenseSearch) {
    Scene scene = presetScene("sinusoid");
    scene.mode = SpeedMode::Speed;
    scene.speed = 1.5;
    SweepReport report = runParameterSweep(scene, {"b", 0.8, 1.6, 2});
    ASSERT_EQ(report.rows.size(), 2u);
    const double m = 1, a = 0.5, vs = 1.5;
    for (const SweepRow& row : report.rows) {
        double b = row.value, inertia = m * (b * b - a * a);
        double power = denseMax(
            [&](double x) { return std::fabs(m * b * b * vs * vs * vs * kappaOf(x) * kappaS(x)); });
        double lateral = denseMax(
            [&](double x) { return std::fabs(m * vs * vs * (kappaOf(x) + a * kappaS(x))); });
        double couple = denseMax([&](double x) {
            return std::fabs(inertia * vs * vs * kappaS(x) +
                             a * m * vs * vs * (kappaOf(x) + a * kappaS(x)));
        });
        EXPECT_LT(rel(row.maxAbsControlPower, power), 1e-8) << b;
        EXPECT_LT(rel(row.maxAbsForceLateral, lateral), 1e-8) << b;
        EXPECT_LT(rel(row.maxAbsControlCouple, couple), 1e-8) << b;
        // t = s/v_s; the sinusoid's length over two periods
        EXPECT_GT(row.duration, 4 * kPi / vs);
    }
}

TEST(ParameterSweep, StraightLineLeavesNoSeparation) {
    SweepReport report = runParameterSweep(presetScene("line"), {"vT", 0.5, 2, 3});
    for (const SweepRow& row : report.rows) {
        EXPECT_LT(row.finalSeparation, 1e-9);
        EXPECT_LT(row.maxAbsLambda, 1e-12);
        EXPECT_LT(rel(row.duration, 4 * std::sqrt(5.0) / row.value), 1e-12);
    }
}

TEST(ParameterSweep, SweepingIDropsB) {
    // b^2 = a^2 + I/m: I = 0.75 gives b = 1, the preset's own circle
    SweepReport report = runParameterSweep(presetScene("circle"), {"I", 0, 0.75, 4});
    ASSERT_EQ(report.rows.size(), 4u);
    for (const SweepRow& row : report.rows) {
        double b = std::sqrt(0.25 + row.value);
        EXPECT_LT(rel(row.duration, 2 * kPi * std::sqrt(b * b + 4)), 1e-12);
    }
}

TEST(ParameterSweep, NamesTheFirstBadValueBeforeAnyWork) {
    int progress = 0;
    SweepOptions options;
    options.progress = [&](int, int) { ++progress; };
    try {
        runParameterSweep(presetScene("circle"), {"a", 0, 2, 5}, options);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), "sweep a");
        EXPECT_NE(std::string(e.what()).find("a = 1.5 (value 4 of 5) is invalid"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_EQ(progress, 0);
    EXPECT_THROW(runParameterSweep(presetScene("circle"), {"b", 0.4, 1, 3}), InputError);
    EXPECT_THROW(runParameterSweep(presetScene("circle"), {"R", 1, 2, 3}), InputError);
    EXPECT_THROW(runParameterSweep(presetScene("circle"), {"vs", 1, 2, 3}), InputError);
    EXPECT_THROW(runParameterSweep(presetScene("circle"), {"vT", -1, 2, 3}), InputError);
    EXPECT_THROW(runParameterSweep(presetScene("circle"), {"b", 1, 2, 0}), InputError);
    EXPECT_THROW(runParameterSweep(presetScene("circle"), {"b", 1, 1, 3}), InputError);
    Scene disk = presetScene("circle");
    disk.system = {SystemKind::Disk, defaultSystemParams(SystemKind::Disk)};
    EXPECT_THROW(runParameterSweep(disk, {"R", -1, 1, 3}), InputError);
    EXPECT_NO_THROW(validateSweep(disk, {"R", 0.1, 1, 3}));
}

TEST(ParameterSweep, ReportsProgressAndStopsWhenCancelled) {
    std::atomic<bool> stop{false};
    std::vector<std::pair<int, int>> calls;
    SweepOptions options;
    options.cancel = &stop;
    options.progress = [&](int done, int total) {
        calls.emplace_back(done, total);
        if (done == 2)
            stop = true;
    };
    SweepReport report = runParameterSweep(presetScene("catenary"), {"b", 0.5, 2, 6}, options);
    EXPECT_TRUE(report.cancelled);
    EXPECT_EQ(report.rows.size(), 2u);
    ASSERT_EQ(calls.size(), 2u);
    EXPECT_EQ(calls[1], std::make_pair(2, 6));
}

TEST(ParameterSweep, CsvHasTheParameterThenTheQuantities) {
    SweepReport report = runParameterSweep(presetScene("circle"), {"m", 1, 2, 2});
    std::string csv = formatSweepCsv(report);
    EXPECT_EQ(csv.substr(0, csv.find('\n')),
              "m,duration,max_abs_lambda,max_abs_control_couple,max_abs_force_lateral,"
              "max_abs_control_power,final_separation");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
    // lambda = m (b Psidot - a phidot) scales with m; the time law does not depend on m
    EXPECT_LT(rel(report.rows[1].maxAbsLambda, 2 * report.rows[0].maxAbsLambda), 1e-12);
    EXPECT_LT(rel(report.rows[1].duration, report.rows[0].duration), 1e-14);
}

} // namespace
} // namespace chaplygin
