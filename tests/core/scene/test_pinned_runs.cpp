// Pinned runs: a pin from a scene, back to a scene, and its label.
#include "scene/pinned_runs.h"
#include "scene/presets.h"

#include <gtest/gtest.h>

using namespace chaplygin;

TEST(PinnedRuns, LabelNamesWhatDiffers) {
    Scene current = presetScene("sinusoid");
    PinnedRun pin = pinOf(current);
    EXPECT_EQ(pinLabel(pin, current), "same parameters");
    pin.system.params["b"] = 0.5;
    EXPECT_EQ(pinLabel(pin, current), "b = 0.5 m");
    pin.speed = 2;
    EXPECT_EQ(pinLabel(pin, current), "b = 0.5 m, v_T = 2 m/s");
    pin = pinOf(current);
    pin.mode = SpeedMode::Speed;
    EXPECT_EQ(pinLabel(pin, current), "constant speed, v_s = 1 m/s");
    pin = pinOf(current);
    pin.path.y = "-2*sin(x)";
    EXPECT_EQ(pinLabel(pin, current), "another path");
    Scene back = sceneOf(pinOf(current));
    EXPECT_EQ(back.path, current.path);
    EXPECT_EQ(back.system, current.system);
    EXPECT_TRUE(back.pins.empty());
}
