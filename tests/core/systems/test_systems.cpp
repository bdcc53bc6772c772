#include "common/input_error.h"
#include "systems/system.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace chaplygin;

namespace {
SystemSpec spec(SystemKind k, std::map<std::string, double> p) {
    return {k, std::move(p)};
}

void expectRejected(const SystemSpec& s, const std::string& name) {
    try {
        deriveSystem(s);
        FAIL() << "accepted bad parameters";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
}
} // namespace

TEST(Systems, SleighFromInertia) {
    DerivedSystem d = deriveSystem(spec(SystemKind::Sleigh, {{"m", 2.0}, {"a", 0.3}, {"I", 0.5}}));
    EXPECT_DOUBLE_EQ(d.mass, 2.0);
    EXPECT_NEAR(d.b, std::sqrt(0.09 + 0.25), 1e-15);
    EXPECT_NEAR(d.inertia(), 0.5, 1e-15);
}

TEST(Systems, SleighFromGyrationRadius) {
    DerivedSystem d = deriveSystem(spec(SystemKind::Sleigh, {{"m", 1.0}, {"a", 0.5}, {"b", 1.0}}));
    EXPECT_NEAR(d.inertia(), 0.75, 1e-15);
}

TEST(Systems, DiskGyrationRadiusA14) {
    // uniform disk: I1 = m R^2/2, I2 = m R^2/4 -> b = R sqrt((1/4)/(3/2)) = R/sqrt(6)
    double m = 2, r = 0.4;
    DerivedSystem d = deriveSystem(
        spec(SystemKind::Disk, {{"m", m}, {"R", r}, {"I1", m * r * r / 2}, {"I2", m * r * r / 4}}));
    EXPECT_NEAR(d.b, r / std::sqrt(6.0), 1e-15);
    EXPECT_NEAR(d.mass, m * 1.5, 1e-15);
    EXPECT_EQ(d.a, 0.0);
}

TEST(Systems, CarriageB18) {
    double r = 0.3, a = 0.2, m = 0.5, i1 = 0.0225, i2 = 0.01125, bigM = 2, inertia = 0.2;
    DerivedSystem d = deriveSystem(
        spec(SystemKind::Carriage,
             {{"R", r}, {"a", a}, {"m", m}, {"I1", i1}, {"I2", i2}, {"M", bigM}, {"I", inertia}}));
    double wheel = m + i1 / (r * r); // 0.75
    double meff = bigM + 2 * wheel;  // 3.5
    double j = inertia + 2 * i2 + 2 * a * a * wheel;
    EXPECT_NEAR(d.mass, 3.5, 1e-15);
    EXPECT_NEAR(d.b, std::sqrt(j / meff), 1e-15);
    EXPECT_NEAR(d.b, std::sqrt((0.2 + 0.0225 + 0.06) / 3.5), 1e-15);
    // the centre of mass is at the axle's centre: the half-axle a is not an offset
    EXPECT_EQ(d.a, 0.0);
    EXPECT_NEAR(d.inertia(), 0.2825, 1e-15); // J
    EXPECT_EQ(d.translatingMass, bigM + 2 * m);
}

TEST(Systems, CarriageWithGyrationRadiusBelowHalfAxle) {
    // J = 0.2 + 0.02 + 2 (0.16)(0.5 + 0.02/0.09), M_eff = 3 + 2 (0.5 + 0.02/0.09): b = 0.3186 < a
    DerivedSystem d = deriveSystem(spec(
        SystemKind::Carriage,
        {{"R", 0.3}, {"a", 0.4}, {"m", 0.5}, {"I1", 0.02}, {"I2", 0.01}, {"M", 3.0}, {"I", 0.2}}));
    double wheel = 0.5 + 0.02 / 0.09, j = 0.22 + 0.32 * wheel, meff = 3 + 2 * wheel;
    EXPECT_NEAR(d.b, std::sqrt(j / meff), 1e-15);
    EXPECT_NEAR(d.b, 0.31859064644147983668, 1e-15);
    EXPECT_LT(d.b, 0.4);
    EXPECT_EQ(d.a, 0.0);
    EXPECT_NEAR(d.inertia(), j, 1e-15);
    EXPECT_NEAR(d.translatingMass, 4.0, 1e-15);
}

TEST(Systems, DiskInertiaAboutTheCentreIsI2) {
    DerivedSystem d =
        deriveSystem(spec(SystemKind::Disk, {{"m", 2.0}, {"R", 0.6}, {"I1", 0.36}, {"I2", 0.18}}));
    EXPECT_NEAR(d.inertia(), 0.18, 1e-15);
    EXPECT_EQ(d.translatingMass, 2.0);
    DerivedSystem s = deriveSystem(spec(SystemKind::Sleigh, {{"m", 2.0}, {"a", 0.3}, {"I", 0.5}}));
    EXPECT_EQ(s.translatingMass, 2.0);
}

TEST(Systems, RejectsImpossibleParameters) {
    expectRejected(spec(SystemKind::Sleigh, {{"m", 0.0}, {"a", 0.5}, {"b", 1.0}}), "parameter m");
    expectRejected(spec(SystemKind::Sleigh, {{"m", 1.0}, {"a", 0.5}, {"I", -1.0}}), "parameter I");
    expectRejected(spec(SystemKind::Sleigh, {{"m", 1.0}, {"a", 2.0}, {"b", 1.0}}), "parameter b");
    expectRejected(spec(SystemKind::Sleigh, {{"m", NAN}, {"a", 0.5}, {"b", 1.0}}), "parameter m");
    expectRejected(spec(SystemKind::Sleigh, {{"m", 1.0}, {"a", 0.5}}), "I or b");
    expectRejected(spec(SystemKind::Sleigh, {{"m", 1.0}, {"a", 0.5}, {"b", 1.0}, {"q", 1.0}}),
                   "parameter q");
    expectRejected(spec(SystemKind::Disk, {{"m", 1.0}, {"R", -1.0}, {"I1", 0.1}, {"I2", 0.1}}),
                   "parameter R");
    expectRejected(spec(SystemKind::Disk, {{"m", 1.0}, {"R", 1.0}, {"I1", 0.1}}), "parameter I2");
    expectRejected(spec(SystemKind::Carriage, {{"R", 0.3},
                                               {"a", 0.2},
                                               {"m", 0.5},
                                               {"I1", 0.0},
                                               {"I2", 0.0},
                                               {"M", 2.0},
                                               {"I", INFINITY}}),
                   "parameter I");
    expectRejected(spec(SystemKind::Carriage, {{"R", 0.3},
                                               {"a", -0.2},
                                               {"m", 0.5},
                                               {"I1", 0.0},
                                               {"I2", 0.0},
                                               {"M", 2.0},
                                               {"I", 0.2}}),
                   "parameter a");
}
