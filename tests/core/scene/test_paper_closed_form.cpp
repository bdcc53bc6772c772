// The paper's closed forms that the GUI's accuracy readout compares the Solution with.
#include "scene/paper_closed_form.h"
#include "scene/presets.h"
#include "scene/solution.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace chaplygin;

TEST(PaperClosedForm, AgreesWithTheSolutionOnLineAndCircle) {
    for (const char* name : {"line", "circle"}) {
        Scene scene = presetScene(name);
        scene.system.params = {{"m", 1.3}, {"a", 0.4}, {"b", 0.9}};
        scene.speed = 1.2;
        Solution sol = Solution::compute(scene);
        for (double t : {0.0, 0.9, 3.7, sol.tEnd()}) {
            auto p = paperClosedForm(scene, t);
            ASSERT_TRUE(p) << name;
            MotionSample m = sol.at(t);
            EXPECT_NEAR(p->x, m.x, 1e-12) << name << " t = " << t;
            EXPECT_NEAR(p->y, m.y, 1e-12) << name << " t = " << t;
        }
    }
    EXPECT_EQ(paperClosedForm(presetScene("circle"), 1)->equations, "eqs. (93)-(94)");
}

TEST(PaperClosedForm, OnlyForTheUnmodifiedPresetsInEnergyMode) {
    EXPECT_FALSE(paperClosedForm(presetScene("catenary"), 1));
    Scene edited = presetScene("circle");
    edited.path.xOfU = "3*cos(u)";
    EXPECT_FALSE(paperClosedForm(edited, 1));
    Scene speed = presetScene("line");
    speed.mode = SpeedMode::Speed;
    EXPECT_FALSE(paperClosedForm(speed, 1));
    EXPECT_FALSE(paperClosedForm(presetScene("line"), -1));
}
