#include "systems/system_parameters.h"

#include "common/input_error.h"

#include <algorithm>

namespace chaplygin {
namespace {

using B = ParameterBound;

// the sleigh (docs/physics.md §1): I's default is m (b² − a²) of the defaults m, a and b
const SystemParameter kSleigh[] = {
    {"m", "m", "kg", 1.0, 0.05, 10, B::Positive, TRANSLATABLE_TEXT("SystemParameters", "mass m"),
     TRANSLATABLE_TEXT("SystemParameters", "The sleigh's mass")},
    {"a", "a", "m", 0.5, -2, 2, B::Any, TRANSLATABLE_TEXT("SystemParameters", "CM offset a"),
     TRANSLATABLE_TEXT("SystemParameters",
                       "How far the centre of mass lies ahead of the knife's contact point P "
                       "(negative: behind it)")},
    {"I", "I", "kg m\u00b2", 0.75, 0, 10, B::NonNegative,
     TRANSLATABLE_TEXT("SystemParameters", "moment of inertia I about the CM"),
     TRANSLATABLE_TEXT("SystemParameters",
                       "The moment of inertia about the centre of mass; b\u00b2 = a\u00b2 + I/m"),
     "b", false},
    {"b", "b", "m", 1.0, 0.05, 5, B::Positive,
     TRANSLATABLE_TEXT("SystemParameters", "gyration radius b about P"),
     TRANSLATABLE_TEXT("SystemParameters", "The radius of gyration about the contact point P; "
                                           "b\u00b2 = a\u00b2 + I/m, so b \u2265 |a|"),
     "I", true},
};

// the vertical rolling disk (App. A), uniform: I1 = m R²/2, I2 = m R²/4
const SystemParameter kDisk[] = {
    {"m", "m", "kg", 1.0, 0.05, 10, B::Positive, TRANSLATABLE_TEXT("SystemParameters", "mass m"),
     TRANSLATABLE_TEXT("SystemParameters", "The disk's mass")},
    {"R", "R", "m", 0.5, 0.05, 2, B::Positive,
     TRANSLATABLE_TEXT("SystemParameters", "wheel radius R"),
     TRANSLATABLE_TEXT("SystemParameters", "The disk's radius")},
    {"I1", "I1", "kg m\u00b2", 0.125, 0, 2, B::NonNegative,
     TRANSLATABLE_TEXT("SystemParameters", "wheel inertia I1 about its axle"),
     TRANSLATABLE_TEXT("SystemParameters",
                       "The moment of inertia about the axle (a uniform disk: m R\u00b2/2)")},
    // I2 > 0 (a = 0 needs b > 0): the slider starts one step above 0
    {"I2", "I2", "kg m\u00b2", 0.0625, 0.002, 2, B::Positive,
     TRANSLATABLE_TEXT("SystemParameters", "wheel inertia I2 about a diameter"),
     TRANSLATABLE_TEXT("SystemParameters", "The moment of inertia about a vertical diameter "
                                           "(a uniform disk: m R\u00b2/4)")},
};

// the two-wheeled carriage (App. B): a is half the axle, not an offset of the centre of mass
const SystemParameter kCarriage[] = {
    {"R", "R", "m", 0.3, 0.05, 2, B::Positive,
     TRANSLATABLE_TEXT("SystemParameters", "wheel radius R"),
     TRANSLATABLE_TEXT("SystemParameters", "The radius of each wheel")},
    {"a", "a", "m", 0.2, 0, 2, B::NonNegative,
     // "\u00b1" and "a" apart: lupdate would read "\u00b1a" as one longer escape
     TRANSLATABLE_TEXT("SystemParameters", "half-axle a (wheels at \u00b1"
                                           "a across the heading)"),
     TRANSLATABLE_TEXT("SystemParameters", "Half the axle: each wheel is a from the axle's "
                                           "centre, where the centre of mass is")},
    {"m", "m", "kg", 0.5, 0, 10, B::NonNegative,
     TRANSLATABLE_TEXT("SystemParameters", "wheel mass m"),
     TRANSLATABLE_TEXT("SystemParameters", "The mass of each wheel")},
    {"I1", "I1", "kg m\u00b2", 0.0225, 0, 2, B::NonNegative,
     TRANSLATABLE_TEXT("SystemParameters", "wheel inertia I1 about its axle"),
     TRANSLATABLE_TEXT("SystemParameters", "Each wheel's moment of inertia about the axle")},
    {"I2", "I2", "kg m\u00b2", 0.01125, 0, 2, B::NonNegative,
     TRANSLATABLE_TEXT("SystemParameters", "wheel inertia I2 about a diameter"),
     TRANSLATABLE_TEXT("SystemParameters",
                       "Each wheel's moment of inertia about a vertical diameter")},
    {"M", "M", "kg", 2.0, 0, 20, B::NonNegative,
     TRANSLATABLE_TEXT("SystemParameters", "carriage body mass M"),
     TRANSLATABLE_TEXT("SystemParameters", "The mass of the body without its wheels")},
    {"I", "I", "kg m\u00b2", 0.2, 0, 10, B::NonNegative,
     TRANSLATABLE_TEXT("SystemParameters", "body's moment of inertia I about the axle's centre"),
     TRANSLATABLE_TEXT("SystemParameters", "The body's moment of inertia about the vertical "
                                           "axis through the axle's centre")},
};

} // namespace

std::span<const SystemParameter> systemParameters(SystemKind kind) {
    switch (kind) {
    case SystemKind::Sleigh:
        return kSleigh;
    case SystemKind::Disk:
        return kDisk;
    case SystemKind::Carriage:
        return kCarriage;
    }
    return {};
}

const SystemParameter* findSystemParameter(SystemKind kind, const std::string& name) {
    const auto table = systemParameters(kind);
    auto it = std::find_if(table.begin(), table.end(),
                           [&](const SystemParameter& p) { return name == p.name; });
    return it == table.end() ? nullptr : &*it;
}

std::string systemParameterList(SystemKind kind) {
    std::string list;
    for (const SystemParameter& p : systemParameters(kind))
        list += (list.empty() ? "" : ", ") + std::string(p.name);
    return list;
}

std::string systemParameterSummary(SystemKind kind) {
    std::string plain, alternatives;
    for (const SystemParameter& p : systemParameters(kind)) {
        if (!p.alternative)
            plain += (plain.empty() ? "" : ", ") + std::string(p.name);
        else
            alternatives += (alternatives.empty() ? "" : " or ") + std::string(p.name);
    }
    return alternatives.empty() ? plain : plain + ", and " + alternatives;
}

std::map<std::string, double> defaultSystemParams(SystemKind kind) {
    std::map<std::string, double> params;
    for (const SystemParameter& p : systemParameters(kind))
        if (p.byDefault)
            params[p.name] = p.defaultValue;
    return params;
}

void setSystemParameter(SystemSpec& spec, const std::string& name, double value) {
    if (const SystemParameter* p = findSystemParameter(spec.kind, name); p && p->alternative)
        spec.params.erase(p->alternative);
    spec.params[name] = value;
}

double systemParameterValue(const SystemSpec& spec, const std::string& name) {
    if (auto it = spec.params.find(name); it != spec.params.end())
        return it->second;
    const SystemParameter* p = findSystemParameter(spec.kind, name);
    if (!p)
        throw InputError("parameter " + name, "unknown for the " + systemKindName(spec.kind) +
                                                  " (allowed: " + systemParameterList(spec.kind) +
                                                  ")");
    if (!p->alternative)
        throw InputError("parameter " + name,
                         "missing (the " + systemKindName(spec.kind) + " needs it)");
    const DerivedSystem d = deriveSystem(spec);
    return name == "b" ? d.b : d.inertia();
}

} // namespace chaplygin
