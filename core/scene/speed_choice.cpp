#include "scene/speed_choice.h"

#include "common/input_error.h"

namespace chaplygin {
namespace {

const SystemParameter kEnergySpeed{
    "vT",
    "v_T",
    "m/s",
    1.0,
    0.05,
    5,
    ParameterBound::Positive,
    TRANSLATABLE_TEXT("SystemParameters", "speed"),
    TRANSLATABLE_TEXT("SystemParameters",
                      "v_T = \u221a(2T/m_eff), the speed the kinetic energy is worth")};
const SystemParameter kConstantSpeed{
    "vs",
    "v_s",
    "m/s",
    1.0,
    0.05,
    5,
    ParameterBound::Positive,
    TRANSLATABLE_TEXT("SystemParameters", "speed"),
    TRANSLATABLE_TEXT("SystemParameters", "v_s, the constant speed of P along the path")};

} // namespace

const SystemParameter& speedParameter(SpeedMode mode) {
    return mode == SpeedMode::Energy ? kEnergySpeed : kConstantSpeed;
}

SpeedMode chooseSpeedMode(SpeedMode current, std::optional<SpeedMode> asked, bool givesVT,
                          bool givesVS, const SpeedSettingWords& words) {
    SpeedMode mode = asked.value_or(current);
    if (givesVT && givesVS)
        throw InputError(words.vT, "give " + words.vT + " (constant energy) or " + words.vS +
                                       " (constant speed), not both");
    if (givesVS && !asked)
        mode = SpeedMode::Speed;
    if (givesVT && mode == SpeedMode::Speed)
        throw InputError(words.vT, "is the constant-energy speed; in " + words.speedMode +
                                       " give " + words.vS);
    if (givesVS && mode == SpeedMode::Energy)
        throw InputError(words.vS,
                         "is the constant speed; in " + words.energyMode + " give " + words.vT);
    return mode;
}

} // namespace chaplygin
