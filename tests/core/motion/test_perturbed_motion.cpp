// The perturbed bodies (docs/physics.md §9) against truths derived there: the open loop's
// linearised error on the line and the circle, its exact invariant chi - chi_nominal, the closed
// loop's triple pole in path length (exact in the chained form's domain), energy, and the scenes
// the perturbation refuses.
#include "common/input_error.h"
#include "scene/presets.h"
#include "scene/solution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

using namespace chaplygin;
using std::numbers::pi;

namespace {

// the circle: R = 2 driven for u in [0, 30] (kappa = 0.5, 60 m), m = 1, a = 0.5, b = 1
Scene longCircle(SystemKind kind = SystemKind::Sleigh) {
    Scene s = presetScene("circle");
    s.preset.clear();
    s.path.to = 30;
    s.system.kind = kind;
    if (kind != SystemKind::Sleigh)
        s.system.params = defaultSystemParams(kind);
    return s;
}

// a straight line y = 0 for 60 m
Scene longLine() {
    Scene s = presetScene("line");
    s.preset.clear();
    s.path.y = "0*x";
    s.path.to = 60;
    return s;
}

Scene perturbed(Scene s, double dy, double dphi = 0, double dpsi = 0, double rate = 1) {
    Perturbation p;
    p.dy = dy;
    p.dphi = dphi;
    p.dpsi = dpsi;
    p.feedbackRate = rate;
    s.perturbation = p;
    return s;
}

// lateral error (left > 0) and path coordinate of a point: the circle x^2 + y^2 = 4 turning left
// (the closest point is radial; sNear picks the turn), and the line y = 0
struct PathError {
    double e, s;
};
PathError onCircle(double x, double y, double sNear) {
    double angle = std::atan2(y, x);
    angle += 2 * pi * std::round((sNear / 2 - angle) / (2 * pi));
    return {2 - std::hypot(x, y), 2 * angle};
}
PathError onLine(double x, double y) {
    return {y, x};
}

// the largest |e - eLinear(s)| over the run, relative to the largest |eLinear|
template <class Body, class Linear, class Error>
double linearisationError(const Solution& sol, Body body, Linear eLinear, Error error) {
    double worst = 0, scale = 0;
    for (const MotionSample& m : sol.sample(301)) {
        const PerturbedState& b = body(m);
        const PathError pe = error(b, m.s);
        worst = std::max(worst, std::fabs(pe.e - eLinear(pe.s)));
        scale = std::max(scale, std::fabs(eLinear(pe.s)));
    }
    return worst / scale;
}

const PerturbedState& openLoop(const MotionSample& m) {
    return m.pert;
}

// A 3 cm zig-zag drawn far out (at 350 km) with the push scene's 1 m offset: the feedback body
// circles the stroke's bends, and the integrator would take 3.8 million steps (24 s) before GSL's
// own limit. The step budget refuses it by name within a second of CPU.
Scene drawnStroke(std::vector<std::pair<double, double>> points) {
    Scene s = presetScene("sinusoid");
    s.preset.clear();
    s.path.kind = PathKind::Polyline;
    s.path.points = std::move(points);
    s.path.corners = CornerMode::Smooth;
    s.path.smoothing = 3;
    s.speed = 2.6140999999999996;
    s.system.params = {{"a", -2.0}, {"b", 5.0}, {"m", 10.0}};
    Perturbation p;
    p.dy = -1;
    p.tPush = 3;
    p.pushDy = 0.15;
    p.pushPsi = 0.4;
    s.perturbation = p;
    return s;
}

std::string refusal(const Scene& s) {
    try {
        Solution::compute(s);
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

double cpuSeconds() {
    return double(std::clock()) / CLOCKS_PER_SEC;
}

} // namespace

TEST(PerturbedMotion, AStrokeTooTightForItsOffsetIsRefusedWithinTheStepBudget) {
    const Scene s = drawnStroke({{350064.0838613769, -135204.6437590552},
                                 {350064.08578219154, -135204.66571122236},
                                 {350064.1313329383, -135204.69616985426},
                                 {350064.10169751267, -135204.66132078893},
                                 {350064.1036183273, -135204.6544607367},
                                 {350064.13380255713, -135204.69836507097},
                                 {350064.0926422438, -135204.67147366624},
                                 {350064.1132224004, -135204.69370023545},
                                 {350064.1247472882, -135204.68930980202},
                                 {350064.1011487085, -135204.67394328504},
                                 {350064.1236496798, -135204.68574257486},
                                 {350064.10745995655, -135204.65775356177}});
    const double start = cpuSeconds();
    const std::string why = refusal(s);
    const double cpu = cpuSeconds() - start;
    EXPECT_NE(why.find("perturbation: the feedback body needs more than 100000 steps of the "
                       "integrator by t = "),
              std::string::npos)
        << why;
    // 100,000 rk8pd steps with a projection each: about 0.6 s here, 24 s without the budget
    EXPECT_LT(cpu, 3.0);
}

TEST(PerturbedMotion, ABodyWithoutAClosestPointIsRefusedByName) {
    const Scene s = drawnStroke({{274574.0344446973, -116459.56772572332},
                                 {274574.03636551194, -116459.58967789046},
                                 {274574.0819162587, -116459.62013652235},
                                 {274574.0522808331, -116459.58528745703},
                                 {274574.0542016477, -116459.57842740479},
                                 {274574.08438587753, -116459.62233173907},
                                 {274574.0432255642, -116459.59544033432},
                                 {274574.0638057208, -116459.61766690355},
                                 {274574.0753306086, -116459.61327647013},
                                 {274574.0517320289, -116459.59790995313},
                                 {274574.0742330002, -116459.60970924297},
                                 {274574.05804327695, -116459.58172022986}});
    const std::string why = refusal(s);
    EXPECT_NE(why.find("perturbation: the feedback body has no closest point on the path after "
                       "t = "),
              std::string::npos)
        << why;
    EXPECT_EQ(why.find("internal error"), std::string::npos) << why;
}

TEST(PerturbedMotion, WithoutAPerturbationNoBodyIsComputed) {
    const Solution s = Solution::compute(presetScene("circle"));
    EXPECT_FALSE(s.perturbed());
    EXPECT_EQ(s.openLoop(), nullptr);
    EXPECT_FALSE(s.at(1).perturbed);
    EXPECT_TRUE(s.models().perturbed.empty() && s.models().feedback.empty());
}

TEST(PerturbedMotion, StartsFromTheControlledStateMovedByTheOffsets) {
    const Solution s = Solution::compute(perturbed(presetScene("line"), 0.3, 0.1, 0.05));
    const MotionSample m = s.at(0);
    ASSERT_TRUE(m.perturbed);
    const double phi = std::atan2(1, 2); // y = 0.5 x + 1
    for (const PerturbedState& b : {m.pert, m.fb}) {
        EXPECT_NEAR(b.x, m.x - 0.3 * std::sin(phi), 1e-15);
        EXPECT_NEAR(b.y, m.y + 0.3 * std::cos(phi), 1e-15);
        EXPECT_NEAR(b.phi, m.phi + 0.1, 1e-15);
        EXPECT_NEAR(b.psi, m.control.psi + 0.05, 1e-15);
    }
    EXPECT_NEAR(m.fb.error, 0.3, 1e-14);
}

// docs/physics.md §9, open loop on the line (kappa = 0, lambda = 0): w = Psi - pi/2 decays like
// exp(-a s/b^2), e'' = -w/b; an offset persists, a heading error grows e linearly
TEST(PerturbedMotion, OpenLoopOnTheLineFollowsItsLinearisation) {
    const double d = 1e-5, a = 0.5, b = 1, alpha = a / (b * b);
    const auto line = [](const PerturbedState& p, double) { return onLine(p.x, p.y); };
    const Solution dy = Solution::compute(perturbed(longLine(), d));
    // exact: the body runs a translated copy of the path (to the integrator's 1e-12 over 60 m)
    EXPECT_LT(linearisationError(
                  dy, openLoop, [&](double) { return d; }, line),
              1e-7);
    const Solution dphi = Solution::compute(perturbed(longLine(), 0, d));
    EXPECT_LT(linearisationError(
                  dphi, openLoop, [&](double s) { return d * s; }, line),
              1e-4);
    const Solution dpsi = Solution::compute(perturbed(longLine(), 0, 0, d));
    const auto eDpsi = [&](double s) {
        return -d / b * (s / alpha - (1 - std::exp(-alpha * s)) / (alpha * alpha));
    };
    EXPECT_LT(linearisationError(dpsi, openLoop, eDpsi, line), 1e-4);
    // the disk (a = 0): the heading error grows linearly, e quadratically, e = -dpsi s^2/(2b)
    Scene disk = longLine();
    disk.system.kind = SystemKind::Disk;
    disk.system.params = defaultSystemParams(SystemKind::Disk);
    const Solution diskDpsi = Solution::compute(perturbed(disk, 0, 0, d));
    const double bd = diskDpsi.system().b;
    EXPECT_LT(linearisationError(
                  diskDpsi, openLoop, [&](double s) { return -d * s * s / (2 * bd); }, line),
              1e-4);
}

// docs/physics.md §9, open loop on the circle: e'' + kappa^2 e = -(1 + b^2 kappa^2) w/b with
// w = dpsi exp(-a s/b^2): the lateral error oscillates at the path's own wavenumber and stays
// bounded (nothing grows)
TEST(PerturbedMotion, OpenLoopOnTheCircleFollowsItsLinearisation) {
    const double d = 1e-5, k = 0.5, b = 1, alpha = 0.5;
    const auto circle = [](const PerturbedState& p, double s) { return onCircle(p.x, p.y, s); };
    const Solution dy = Solution::compute(perturbed(longCircle(), d));
    EXPECT_LT(linearisationError(
                  dy, openLoop, [&](double s) { return d * std::cos(k * s); }, circle),
              1e-4);
    const Solution dphi = Solution::compute(perturbed(longCircle(), 0, d));
    EXPECT_LT(linearisationError(
                  dphi, openLoop, [&](double s) { return d / k * std::sin(k * s); }, circle),
              1e-4);
    const Solution dpsi = Solution::compute(perturbed(longCircle(), 0, 0, d));
    const double c = d * (1 + b * b * k * k) / b;
    const auto eDpsi = [&](double s) {
        return c / (alpha * alpha + k * k) *
               (std::cos(k * s) - alpha / k * std::sin(k * s) - std::exp(-alpha * s));
    };
    EXPECT_LT(linearisationError(dpsi, openLoop, eDpsi, circle), 1e-4);
    // the disk (a = 0): the radius changes for good, e = (c/kappa^2)(cos(kappa s) - 1)
    const Solution disk = Solution::compute(perturbed(longCircle(SystemKind::Disk), 0, 0, d));
    const double bd = disk.system().b, cd = d * (1 + bd * bd * k * k) / bd;
    EXPECT_LT(
        linearisationError(
            disk, openLoop, [&](double s) { return cd / (k * k) * (std::cos(k * s) - 1); }, circle),
        1e-4);
}

// docs/physics.md §9: the open loop's chi = Psi - (a/b) phi obeys chidot = lambda(t)/(m b), the
// nominal's own equation, so chi - chi_nominal is the constant dpsi - (a/b) dphi, plus push_psi
// after the push: exact on any path
TEST(PerturbedMotion, OpenLoopKeepsChiMinusTheNominalChiConstant) {
    Scene s = perturbed(presetScene("sinusoid"), 0.2, 0.1, -0.15);
    s.perturbation->tPush = 5;
    s.perturbation->pushPsi = 0.25;
    s.perturbation->pushDy = 0.1;
    const Solution sol = Solution::compute(s);
    const double ab = sol.system().a / sol.system().b;
    double worst = 0;
    for (const MotionSample& m : sol.sample(201)) {
        const double want = -0.15 - ab * 0.1 + (m.t >= 5 ? 0.25 : 0);
        worst = std::max(worst, std::fabs(m.pert.psi - ab * m.pert.phi - m.control.chi - want));
    }
    EXPECT_LT(worst, 1e-10);
}

// docs/physics.md §9: in the chained form's domain the closed loop is exactly
// e''' + 3P e'' + 3P^2 e' + P^3 e = 0 in s_p; a lateral offset starts with e' = 0 and
// e'' = z4 = -kappa^2 e0 (1 - kappa e0), so e/e0 = exp(-Ps)(1 + Ps + (P^2 - kappa^2 (1 - kappa e0))
// s^2/2): the formula with kappa e0 -> 0
double triplePole(double s, double rate, double kappa, double e0) {
    const double p = rate;
    return std::exp(-p * s) * (1 + p * s + (p * p - kappa * kappa * (1 - kappa * e0)) * s * s / 2);
}

TEST(PerturbedMotion, FeedbackErrorIsTheTriplePoleInTheLinearRegime) {
    const double e0 = 1e-5;
    for (double rate : {1.0, 2.0}) {
        for (bool circle : {true, false}) {
            const double k = circle ? 0.5 : 0;
            const Solution sol =
                Solution::compute(perturbed(circle ? longCircle() : longLine(), e0, 0, 0, rate));
            double worstRelative = 0, worstAbsolute = 0;
            for (const MotionSample& m : sol.sample(601)) {
                const PathError pe =
                    circle ? onCircle(m.fb.x, m.fb.y, m.s) : onLine(m.fb.x, m.fb.y);
                EXPECT_NEAR(pe.e, m.fb.error, 1e-14) << m.t;
                EXPECT_NEAR(pe.s, m.fb.pathS, 1e-12) << m.t;
                // the linear formula
                const double f = std::exp(-rate * pe.s) *
                                 (1 + rate * pe.s + (rate * rate - k * k) * pe.s * pe.s / 2);
                const double got = m.fb.error / e0;
                worstAbsolute = std::max(worstAbsolute, std::fabs(got - f));
                if (std::fabs(f) > 1e-3)
                    worstRelative = std::max(worstRelative, std::fabs(got - f) / std::fabs(f));
            }
            EXPECT_LT(worstRelative, 0.01) << "P = " << rate << (circle ? ", circle" : ", line");
            EXPECT_LT(worstAbsolute, 1e-4) << "P = " << rate << (circle ? ", circle" : ", line");
        }
    }
}

TEST(PerturbedMotion, FeedbackIsExactlyLinearInPathLengthForALargeOffset) {
    const double e0 = 0.3, k = 0.5;
    const Solution sol = Solution::compute(perturbed(longCircle(), e0));
    double worst = 0;
    for (const MotionSample& m : sol.sample(601))
        worst = std::max(worst, std::fabs(m.fb.error - e0 * triplePole(m.fb.pathS, 1, k, e0)));
    EXPECT_LT(worst, 1e-10);
}

// the done-when: dy = 0.3 on the circle, |e| < 1e-3 at t = 60 and the energy constant
TEST(PerturbedMotion, LargeOffsetIsCorrectedWithTheEnergyConstant) {
    for (SystemKind kind : {SystemKind::Sleigh, SystemKind::Disk, SystemKind::Carriage}) {
        const Solution sol = Solution::compute(perturbed(longCircle(kind), 0.3));
        ASSERT_GE(sol.tEnd(), 60);
        EXPECT_LT(std::fabs(sol.at(60).fb.error), 1e-3) << systemKindName(kind);
        const double energy0 = sol.at(0).control.energy;
        double drift = 0;
        for (const MotionSample& m : sol.sample(301)) {
            const double b = sol.system().b, mass = sol.system().mass;
            for (const PerturbedState& p : {m.pert, m.fb}) {
                const double t = 0.5 * mass * (p.sdot * p.sdot + b * b * p.phidot * p.phidot);
                drift = std::max(drift, std::fabs(t - energy0));
            }
        }
        EXPECT_LE(drift, 1e-10) << systemKindName(kind);
    }
}

TEST(PerturbedMotion, FeedbackLambdaIsTheControlOfItsPsidot) {
    const Solution sol = Solution::compute(perturbed(presetScene("sinusoid"), 0.2, 0.05));
    const DerivedSystem& sys = sol.system();
    for (const MotionSample& m : sol.sample(21)) {
        EXPECT_NEAR(m.fb.lambda, sys.mass * (sys.b * m.fb.psidot - sys.a * m.fb.phidot), 1e-14);
        // open loop: the nominal lambda(t) itself
        EXPECT_EQ(m.pert.lambda, m.control.lambda);
    }
}

TEST(PerturbedMotion, PsidotBoundIsHeld) {
    Scene s = perturbed(longLine(), 0.5, 0, 0, 2.5);
    s.perturbation->feedbackLimit = 0.4;
    const Solution sol = Solution::compute(s);
    double most = 0, lowest = 0;
    for (const MotionSample& m : sol.sample(601)) {
        most = std::max(most, std::fabs(m.fb.psidot));
        lowest = std::min(lowest, m.fb.error);
    }
    EXPECT_LE(most, 0.4);
    EXPECT_GT(most, 0.4 - 1e-12); // it saturates
    EXPECT_LT(lowest, -0.1);      // and overshoots, where the unbounded law does not
    s.perturbation->feedbackLimit.reset();
    const Solution free = Solution::compute(s);
    for (const MotionSample& m : free.sample(601))
        EXPECT_GT(m.fb.error, -1e-3);
}

TEST(PerturbedMotion, TheScenesItCannotRunAreRefusedByName) {
    const auto message = [](const Scene& s) {
        try {
            Solution::compute(s);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    Scene speed = perturbed(presetScene("line"), 0.1);
    speed.mode = SpeedMode::Speed;
    EXPECT_EQ(message(speed), "perturbation: perturbations need constant-energy mode");
    Scene corners = perturbed(presetScene("line"), 0.1);
    corners.path.kind = PathKind::Polyline;
    corners.path.points = {{0, 0}, {1, 0}, {1, 1}};
    EXPECT_NE(message(corners).find("without corners or cusps"), std::string::npos);
    Scene late = perturbed(presetScene("line"), 0.1);
    late.perturbation->tPush = 100;
    late.perturbation->pushPsi = 0.1;
    EXPECT_NE(message(late).find("perturbation t_push: 100 s is not before the horizon"),
              std::string::npos)
        << message(late);
    Scene backwards = perturbed(presetScene("circle"), 0, 0, -1.2); // Psi(0) = 1.107 - 1.2 < 0
    EXPECT_NE(message(backwards).find("perturbation dpsi"), std::string::npos);
    // a controller whose b is below a third of the plant's: the loop gain (b_c/b)^2 < 1/9 makes
    // the line's triple pole unstable (docs/physics.md §9), and the body leaves the chained form
    Scene wrongB = perturbed(longLine(), 0.3);
    wrongB.perturbation->controllerB = 0.25;
    EXPECT_NE(message(wrongB).find("leaves the chained form's domain"), std::string::npos)
        << message(wrongB);
}
