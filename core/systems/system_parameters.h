#pragma once
// Every system parameter once (docs/physics.md §1): its name, symbol, unit, default, slider range,
// the bound deriveSystem checks, the words of its label and tooltip, and the sleigh's rule that b
// and I are alternatives. The command line, the Python module, the sweep, the scene file and the
// parameters panel all read this table. The words are plain English; the UI translates them in
// the context kSystemParameterContext (resources/translations).
#include "systems/system.h"

#include <span>
#include <string>

/// Marks words for the catalogues: lupdate reads it as QT_TRANSLATE_NOOP
/// (resources/translations/CMakeLists.txt), so they reach the translations without Qt in the core.
#define TRANSLATABLE_TEXT(context, text) text

namespace chaplygin {

/// What deriveSystem requires of a parameter's value besides being finite.
enum class ParameterBound { Any, NonNegative, Positive };

struct SystemParameter {
    const char* name;   ///< as typed: --param NAME=VALUE, Sleigh(NAME=...), the scene file
    const char* symbol; ///< as printed beside its value
    const char* unit;   ///< SI: "kg", "m", "kg m²"
    double defaultValue;
    double sliderMin, sliderMax; ///< the slider's range; typed values may lie outside it
    ParameterBound bound;
    const char* label;   ///< a few words naming it: "mass m"
    const char* tooltip; ///< one sentence saying what it is
    /// The parameter given instead of this one (the sleigh's b and I, b² = a² + I/m), or null.
    const char* alternative = nullptr;
    /// Whether defaultSystemParams gives it (of two alternatives, one only).
    bool byDefault = true;
};

/// The translation context of the labels and tooltips.
inline constexpr const char* kSystemParameterContext = "SystemParameters";

/// The parameters of a system, in display order.
std::span<const SystemParameter> systemParameters(SystemKind kind);

/// The parameter of that name, or null when the system has none.
const SystemParameter* findSystemParameter(SystemKind kind, const std::string& name);

/// "m, a, I, b": the names a system accepts, for messages.
std::string systemParameterList(SystemKind kind);

/// "m, a, and I or b": what a system takes, its alternatives joined by "or", for help texts.
std::string systemParameterSummary(SystemKind kind);

/// Sets a parameter as typed. Of two alternatives (the sleigh's I and b) giving one drops the
/// other, as --param, Sleigh(...), the sweep and the panel's gyration choice all do.
void setSystemParameter(SystemSpec& spec, const std::string& name, double value);

/// A parameter's value: as given, or for an alternative not given (the sleigh's b or I) as the
/// derivation makes it. Throws InputError when the system has no such parameter.
double systemParameterValue(const SystemSpec& spec, const std::string& name);

} // namespace chaplygin
