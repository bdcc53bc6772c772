#include "systems/system.h"

#include "common/input_error.h"

#include <cmath>
#include <set>

namespace chaplygin {
namespace {

const char* const kSleighNames[] = {"m", "a", "I", "b"};
const char* const kDiskNames[] = {"m", "R", "I1", "I2"};
const char* const kCarriageNames[] = {"R", "a", "m", "I1", "I2", "M", "I"};

std::string where(const std::string& name) {
    return "parameter " + name;
}

double get(const SystemSpec& spec, const std::string& name) {
    auto it = spec.params.find(name);
    if (it == spec.params.end())
        throw InputError(where(name), "missing (the " + systemKindName(spec.kind) + " needs it)");
    if (!std::isfinite(it->second))
        throw InputError(where(name), "must be a finite number, got " + formatNumber(it->second));
    return it->second;
}

double positive(const SystemSpec& spec, const std::string& name) {
    double v = get(spec, name);
    if (!(v > 0))
        throw InputError(where(name), "must be > 0, got " + formatNumber(v));
    return v;
}

double nonNegative(const SystemSpec& spec, const std::string& name) {
    double v = get(spec, name);
    if (!(v >= 0))
        throw InputError(where(name), "must be >= 0, got " + formatNumber(v));
    return v;
}

void rejectUnknown(const SystemSpec& spec) {
    int n = 0;
    const char* const* names = systemParameterNames(spec.kind, &n);
    std::set<std::string> allowed(names, names + n);
    for (const auto& [name, value] : spec.params) {
        if (!allowed.count(name)) {
            std::string list;
            for (int i = 0; i < n; ++i)
                list += (i ? ", " : "") + std::string(names[i]);
            throw InputError(where(name), "unknown for the " + systemKindName(spec.kind) +
                                              " (allowed: " + list + ")");
        }
    }
}

DerivedSystem sleigh(const SystemSpec& spec) {
    DerivedSystem d;
    d.mass = positive(spec, "m");
    d.a = get(spec, "a");
    bool hasI = spec.params.count("I") != 0, hasB = spec.params.count("b") != 0;
    if (hasI == hasB)
        throw InputError("parameter I or b", "give exactly one of I and b (b^2 = a^2 + I/m)");
    if (hasI) {
        double inertia = nonNegative(spec, "I");
        d.b = std::sqrt(d.a * d.a + inertia / d.mass);
    } else {
        d.b = positive(spec, "b");
        if (d.b < std::fabs(d.a))
            throw InputError(where("b"), "must be >= |a| = " + formatNumber(std::fabs(d.a)) +
                                             " (b^2 = a^2 + I/m with I >= 0), got " +
                                             formatNumber(d.b));
    }
    if (!(d.b > 0))
        throw InputError(where("b"), "the radius of gyration must be > 0 (a = 0 needs I > 0)");
    d.translatingMass = d.mass;
    return d;
}

// vertical rolling disk, paper (A14): b = R sqrt(I2/(I1 + m R^2)), M_eff = m + I1/R^2, a = 0
DerivedSystem disk(const SystemSpec& spec) {
    double m = positive(spec, "m"), r = positive(spec, "R");
    double i1 = nonNegative(spec, "I1"), i2 = positive(spec, "I2");
    DerivedSystem d;
    d.mass = m + i1 / (r * r);
    d.a = 0.0;
    d.b = r * std::sqrt(i2 / (i1 + m * r * r)); // = sqrt(I2/m_eff): I about the CM is I2
    d.translatingMass = m;
    return d;
}

// two-wheeled carriage, paper (B18): b = sqrt(J/M_eff), M_eff = M + 2(m + I1/R^2),
// J = I + 2 I2 + 2 a^2 (m + I1/R^2). Here a is half the axle: the centre of mass sits at the
// axle's centre (App. B), so the CM offset is 0 and b may be smaller than the half-axle.
DerivedSystem carriage(const SystemSpec& spec) {
    double r = positive(spec, "R"), a = nonNegative(spec, "a"), m = nonNegative(spec, "m");
    double i1 = nonNegative(spec, "I1"), i2 = nonNegative(spec, "I2");
    double bigM = nonNegative(spec, "M"), inertia = nonNegative(spec, "I");
    double wheel = m + i1 / (r * r);
    DerivedSystem d;
    d.mass = bigM + 2 * wheel;
    if (!(d.mass > 0))
        throw InputError("parameter M", "the total effective mass M + 2(m + I1/R^2) must be > 0");
    d.a = 0.0;
    double j = inertia + 2 * i2 + 2 * a * a * wheel;
    d.b = std::sqrt(j / d.mass);
    if (!(d.b > 0))
        throw InputError("parameter I",
                         "the moment of inertia J = I + 2 I2 + 2 a^2 (m + I1/R^2) must be > 0");
    d.translatingMass = bigM + 2 * m;
    return d;
}

} // namespace

const char* const* systemParameterNames(SystemKind kind, int* count) {
    switch (kind) {
    case SystemKind::Sleigh:
        *count = 4;
        return kSleighNames;
    case SystemKind::Disk:
        *count = 4;
        return kDiskNames;
    case SystemKind::Carriage:
        *count = 7;
        return kCarriageNames;
    }
    *count = 0;
    return nullptr;
}

DerivedSystem deriveSystem(const SystemSpec& spec) {
    rejectUnknown(spec);
    switch (spec.kind) {
    case SystemKind::Sleigh:
        return sleigh(spec);
    case SystemKind::Disk:
        return disk(spec);
    case SystemKind::Carriage:
        return carriage(spec);
    }
    throw InputError("system", "unknown system");
}

SystemKind systemKindFromName(const std::string& name) {
    if (name == "sleigh")
        return SystemKind::Sleigh;
    if (name == "disk")
        return SystemKind::Disk;
    if (name == "carriage")
        return SystemKind::Carriage;
    throw InputError("system", "unknown system '" + name + "' (use sleigh, disk or carriage)");
}

std::string systemKindName(SystemKind kind) {
    switch (kind) {
    case SystemKind::Sleigh:
        return "sleigh";
    case SystemKind::Disk:
        return "disk";
    case SystemKind::Carriage:
        return "carriage";
    }
    return "?";
}

std::map<std::string, double> defaultSystemParams(SystemKind kind) {
    switch (kind) {
    case SystemKind::Sleigh:
        return {{"m", 1.0}, {"a", 0.5}, {"b", 1.0}};
    case SystemKind::Disk: // uniform disk: I1 = m R^2/2 about the axle, I2 = m R^2/4 about a
                           // diameter
        return {{"m", 1.0}, {"R", 0.5}, {"I1", 0.125}, {"I2", 0.0625}};
    case SystemKind::Carriage:
        return {{"R", 0.3},      {"a", 0.2}, {"m", 0.5}, {"I1", 0.0225},
                {"I2", 0.01125}, {"M", 2.0}, {"I", 0.2}};
    }
    return {};
}

} // namespace chaplygin
