#pragma once
// The rules of the speed's settings, as the command line (--mode, --vT, --vs) and the Python module
// (mode, v_T, v_s) take them (docs/physics.md §2): v_T is the constant-energy speed, v_s the
// constant speed, never both, and v_s alone chooses constant speed.
#include "control/control_law.h"
#include "systems/system_parameters.h"

#include <optional>
#include <string>

namespace chaplygin {

/// How an entry point spells the settings in its messages.
struct SpeedSettingWords {
    std::string vT;         ///< "--vT"
    std::string vS;         ///< "--vs"
    std::string energyMode; ///< "--mode energy"
    std::string speedMode;  ///< "--mode speed"
};

/// The mode a scene in mode current takes when it is given mode asked (if any) and a v_T or a v_s.
/// Throws InputError naming the setting that does not fit.
SpeedMode chooseSpeedMode(SpeedMode current, std::optional<SpeedMode> asked, bool givesVT,
                          bool givesVS, const SpeedSettingWords& words);

/// The speed as a parameter: v_T ("vT") in constant-energy mode, v_s ("vs") in constant-speed mode,
/// with its unit, default, slider range and words, as systems/system_parameters.h has them.
const SystemParameter& speedParameter(SpeedMode mode);

} // namespace chaplygin
