// The cut time per family (docs/physics.md §10): the closed forms against mpmath, and the
// Maxwell time as the end of optimality, checked by an independent multi-start search: a little
// before it nothing arrives sooner, a little after it something does.
#include "planning/cut_time.h"

#include "motion/vakonomic_motion.h"
#include "planning_reference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace chaplygin {
namespace {

using std::numbers::pi;

// mpmath at 30 digits: findroot of cn p (E(am p) - p) - dn p sn p on (K, 2K), m = q^2
TEST(CutTime, RotationRootMatchesMpmath) {
    EXPECT_NEAR(firstRotationMaxwellRoot(0.1), 3.13372517739605620661, 1e-13);
    EXPECT_NEAR(firstRotationMaxwellRoot(0.5), 2.95426185407020883944, 1e-13);
    EXPECT_NEAR(firstRotationMaxwellRoot(0.9), 2.94152991585736091417, 1e-13);
    EXPECT_NEAR(firstRotationMaxwellRoot(0.99), 3.74348844218633466640, 1e-12);
}

TEST(CutTime, PerFamily) {
    EXPECT_EQ(unitCutTime(0), pi);                                // pivoting
    EXPECT_NEAR(unitCutTime(0.5), 3.37150070962519208574, 1e-13); // 2 K(m = 1/4)
    EXPECT_NEAR(unitCutTime(0.9), 4.56109827684554040923, 1e-13); // 2 K(m = 0.81)
    EXPECT_NEAR(unitCutTime(2.0), 2.95426185407020883944, 1e-13); // 2 p1(1/2)/2
    EXPECT_TRUE(std::isinf(unitCutTime(1)));                      // separatrix
    EXPECT_NEAR(unitCutTime(1e-9), pi, 1e-12);                    // libration -> pivoting
    EXPECT_GT(unitCutTime(1 - 1e-9), 20);                         // grows towards k = 1
    EXPECT_GT(unitCutTime(1 + 1e-9), 20);
    EXPECT_THROW(unitCutTime(-1), std::invalid_argument);
}

// the sideways shift (0, 1, 0) is a Maxwell point reached at the cut time of its two geodesics
TEST(CutTime, SidewaysShiftArrivesAtItsCutTime) {
    const double k = std::hypot(std::sin(-1.107148717794), 1.492853942033);
    EXPECT_NEAR(unitCutTime(k), 3.340383019231, 1e-11);
}

TEST(CutTime, OptimalUpToItAndNotBeyondByAnIndependentSearch) {
    struct Case {
        double psi0, lambda0;
    };
    // libration (k = 0.63, 0.86), rotation (k = 1.3, 2.2)
    for (const Case c : {Case{0.5, 0.4}, Case{2.3, -0.6}, Case{-0.9, 1.0}, Case{2.8, -2.15}}) {
        const double k = std::hypot(std::sin(c.psi0), c.lambda0);
        const double cut = unitCutTime(k);
        const Pose before = test::unitEnd(c.psi0, c.lambda0, 0.9 * cut);
        const Pose after = test::unitEnd(c.psi0, c.lambda0, 1.1 * cut);
        const auto sBefore = test::leastTimeByShooting(before.x, before.y, before.phi, 400, 11);
        const auto sAfter = test::leastTimeByShooting(after.x, after.y, after.phi, 400, 12);
        EXPECT_NEAR(sBefore.t, 0.9 * cut, 1e-9) << "k = " << k;
        EXPECT_LT(sAfter.t, 1.1 * cut - 1e-4) << "k = " << k;
    }
}

} // namespace
} // namespace chaplygin
