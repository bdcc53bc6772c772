#pragma once
// The Chaplygin systems (sleigh, disk, carriage) and their reduction to a sleigh's m_eff, a and b
// (docs/physics.md §1).
#include <map>
#include <string>

namespace chaplygin {

enum class SystemKind { Sleigh, Disk, Carriage };

/// The user's choice of system and its named parameters, as typed (SI units: kg, m, kg m^2).
/// sleigh: m, a, and I or b; disk (App. A): m, R, I1, I2; carriage (App. B): R, a, m, I1, I2, M, I.
struct SystemSpec {
    SystemKind kind = SystemKind::Sleigh;
    std::map<std::string, double> params{{"m", 1.0}, {"a", 0.5}, {"b", 1.0}};

    bool operator==(const SystemSpec&) const = default;
};

/// Every Chaplygin system here reduces to a sleigh: effective mass, CM offset a, gyration radius b
/// (docs/physics.md §1). The disk's and the carriage's centre of mass is above P, so their
/// a is 0; the carriage's half-axle is a system parameter that enters only b.
struct DerivedSystem {
    double mass = 1.0; ///< effective mass m_eff [kg]
    double a = 0.5;    ///< offset of the centre of mass ahead of the contact point [m]
    double b = 1.0;    ///< radius of gyration about the contact point [m], b^2 = a^2 + I/m_eff
    /// The mass that translates with P and so carries the ground's lateral reaction [kg]: m for the
    /// sleigh and the disk, M + 2m for the carriage (wheel spin does not resist sideways motion).
    /// Set it whenever mass is set.
    double translatingMass = mass;
    /// I about the CM [kg m^2]: I for the sleigh, I2 for the disk, J for the carriage.
    double inertia() const { return mass * (b * b - a * a); }
};

/// Maps the spec to (m_eff, a, b). Throws InputError naming the parameter when it is missing,
/// unknown, non-finite or outside its physical range.
DerivedSystem deriveSystem(const SystemSpec& spec);
/// How many times deriveSystem ran in this process: a cost the tests of one edit count.
long derivationCount();

/// "sleigh" | "disk" | "carriage" <-> SystemKind. Throws InputError for other names.
SystemKind systemKindFromName(const std::string& name);
std::string systemKindName(SystemKind kind);

/// Default parameters of each system (SI units), used when a scene does not give them: the
/// defaults of the parameter table (systems/system_parameters.h).
std::map<std::string, double> defaultSystemParams(SystemKind kind);

} // namespace chaplygin
