#include "systems/system.h"

#include "common/input_error.h"
#include "systems/system_parameters.h"

#include <atomic>
#include <cmath>

namespace chaplygin {
namespace {

std::string where(const std::string& name) {
    return "parameter " + name;
}

// the value, checked against the bound the parameter table gives it
double value(const SystemSpec& spec, const std::string& name) {
    auto it = spec.params.find(name);
    if (it == spec.params.end())
        throw InputError(where(name), "missing (the " + systemKindName(spec.kind) + " needs it)");
    const double v = it->second;
    if (!std::isfinite(v))
        throw InputError(where(name), "must be a finite number, got " + formatNumber(v));
    const SystemParameter* p = findSystemParameter(spec.kind, name);
    if (p && p->bound == ParameterBound::Positive && !(v > 0))
        throw InputError(where(name), "must be > 0, got " + formatNumber(v));
    if (p && p->bound == ParameterBound::NonNegative && !(v >= 0))
        throw InputError(where(name), "must be >= 0, got " + formatNumber(v));
    return v;
}

void rejectUnknown(const SystemSpec& spec) {
    for (const auto& [name, v] : spec.params)
        if (!findSystemParameter(spec.kind, name))
            throw InputError(where(name), "unknown for the " + systemKindName(spec.kind) +
                                              " (allowed: " + systemParameterList(spec.kind) + ")");
}

DerivedSystem sleigh(const SystemSpec& spec) {
    DerivedSystem d;
    d.mass = value(spec, "m");
    d.a = value(spec, "a");
    bool hasI = spec.params.count("I") != 0, hasB = spec.params.count("b") != 0;
    if (hasI == hasB)
        throw InputError("parameter I or b", "give exactly one of I and b (b^2 = a^2 + I/m)");
    if (hasI) {
        double inertia = value(spec, "I");
        d.b = std::sqrt(d.a * d.a + inertia / d.mass);
    } else {
        d.b = value(spec, "b");
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
    double m = value(spec, "m"), r = value(spec, "R");
    double i1 = value(spec, "I1"), i2 = value(spec, "I2");
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
    double r = value(spec, "R"), a = value(spec, "a"), m = value(spec, "m");
    double i1 = value(spec, "I1"), i2 = value(spec, "I2");
    double bigM = value(spec, "M"), inertia = value(spec, "I");
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

namespace {
std::atomic<long> g_derivations{0};
} // namespace

long derivationCount() {
    return g_derivations.load(std::memory_order_relaxed);
}

DerivedSystem deriveSystem(const SystemSpec& spec) {
    g_derivations.fetch_add(1, std::memory_order_relaxed);
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

} // namespace chaplygin
