// The speed's settings (docs/physics.md §2): v_T belongs to constant energy, v_s to constant speed,
// never both, and v_s alone chooses constant speed; the speed's row of the parameter table.
#include "common/input_error.h"
#include "scene/speed_choice.h"

#include <gtest/gtest.h>

using namespace chaplygin;

namespace {
std::string refusal(SpeedMode current, std::optional<SpeedMode> asked, bool vT, bool vS) {
    const SpeedSettingWords words{"--vT", "--vs", "--mode energy", "--mode speed"};
    try {
        chooseSpeedMode(current, asked, vT, vS, words);
        return "";
    } catch (const InputError& e) {
        return e.what();
    }
}
} // namespace

TEST(SpeedChoice, VsAloneChoosesConstantSpeedAndTheWrongSpeedIsNamed) {
    const SpeedSettingWords words{"--vT", "--vs", "--mode energy", "--mode speed"};
    EXPECT_EQ(chooseSpeedMode(SpeedMode::Energy, std::nullopt, false, true, words),
              SpeedMode::Speed);
    EXPECT_EQ(chooseSpeedMode(SpeedMode::Speed, SpeedMode::Energy, true, false, words),
              SpeedMode::Energy);
    EXPECT_EQ(chooseSpeedMode(SpeedMode::Energy, std::nullopt, false, false, words),
              SpeedMode::Energy);
    EXPECT_EQ(refusal(SpeedMode::Energy, std::nullopt, true, true),
              "--vT: give --vT (constant energy) or --vs (constant speed), not both");
    EXPECT_EQ(refusal(SpeedMode::Speed, std::nullopt, true, false),
              "--vT: is the constant-energy speed; in --mode speed give --vs");
    EXPECT_EQ(refusal(SpeedMode::Speed, SpeedMode::Energy, false, true),
              "--vs: is the constant speed; in --mode energy give --vT");
}

TEST(SpeedChoice, TheSpeedRowsNameTheModesSpeed) {
    EXPECT_STREQ(speedParameter(SpeedMode::Energy).name, "vT");
    EXPECT_STREQ(speedParameter(SpeedMode::Speed).name, "vs");
    for (SpeedMode mode : {SpeedMode::Energy, SpeedMode::Speed}) {
        const SystemParameter& p = speedParameter(mode);
        EXPECT_STREQ(p.unit, "m/s");
        EXPECT_EQ(p.bound, ParameterBound::Positive);
        EXPECT_GT(p.sliderMin, 0);
        EXPECT_LE(p.sliderMin, p.defaultValue);
        EXPECT_GE(p.sliderMax, p.defaultValue);
    }
}
