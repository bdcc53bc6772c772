// The parameter table against docs/physics.md §1: the documented defaults, the bounds the
// derivation enforces, slider ranges that hold the defaults, and the sleigh's "b or I" rule.
#include "common/input_error.h"
#include "systems/system_parameters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace chaplygin;

namespace {

const SystemKind kKinds[] = {SystemKind::Sleigh, SystemKind::Disk, SystemKind::Carriage};

double defaultOf(SystemKind kind, const std::string& name) {
    const SystemParameter* p = findSystemParameter(kind, name);
    EXPECT_NE(p, nullptr) << name;
    return p ? p->defaultValue : NAN;
}

bool accepted(SystemSpec spec) {
    try {
        deriveSystem(spec);
        return true;
    } catch (const InputError&) {
        return false;
    }
}

} // namespace

// docs/physics.md §1, "Defaults": the sleigh m = 1, a = 0.5, b = 1; a uniform disk m = 1, R = 0.5;
// the carriage's uniform wheels R = 0.3, m = 0.5 at half-axle 0.2, its body M = 2, I = 0.2
TEST(SystemParameters, DefaultsAreTheDocumentedOnes) {
    EXPECT_EQ(defaultSystemParams(SystemKind::Sleigh),
              (std::map<std::string, double>{{"m", 1.0}, {"a", 0.5}, {"b", 1.0}}));
    const double md = 1.0, rd = 0.5; // a uniform disk: I1 = m R²/2, I2 = m R²/4
    EXPECT_EQ(defaultSystemParams(SystemKind::Disk),
              (std::map<std::string, double>{
                  {"m", md}, {"R", rd}, {"I1", md * rd * rd / 2}, {"I2", md * rd * rd / 4}}));
    const double mw = 0.5, rw = 0.3;
    auto carriage = defaultSystemParams(SystemKind::Carriage);
    EXPECT_EQ(carriage.size(), 7u);
    EXPECT_EQ(carriage.at("R"), rw);
    EXPECT_EQ(carriage.at("m"), mw);
    EXPECT_NEAR(carriage.at("I1"), mw * rw * rw / 2, 1e-17);
    EXPECT_NEAR(carriage.at("I2"), mw * rw * rw / 4, 1e-17);
    EXPECT_EQ(carriage.at("a"), 0.2);
    EXPECT_EQ(carriage.at("M"), 2.0);
    EXPECT_EQ(carriage.at("I"), 0.2);
}

TEST(SystemParameters, TheSleighsInertiaDefaultMatchesItsGyrationDefault) {
    // b² = a² + I/m with the defaults m = 1, a = 0.5, b = 1: I = 0.75
    const double m = defaultOf(SystemKind::Sleigh, "m"), a = defaultOf(SystemKind::Sleigh, "a");
    const double b = defaultOf(SystemKind::Sleigh, "b");
    EXPECT_DOUBLE_EQ(defaultOf(SystemKind::Sleigh, "I"), m * (b * b - a * a));
    EXPECT_DOUBLE_EQ(defaultOf(SystemKind::Sleigh, "I"), 0.75);
}

TEST(SystemParameters, NamesAreTheOnesTheDocumentsGive) {
    // docs/physics.md §1 and --param's help: sleigh m, a, I or b; disk m, R, I1, I2; carriage
    // R, a, m, I1, I2, M, I
    EXPECT_EQ(systemParameterList(SystemKind::Sleigh), "m, a, I, b");
    EXPECT_EQ(systemParameterList(SystemKind::Disk), "m, R, I1, I2");
    EXPECT_EQ(systemParameterList(SystemKind::Carriage), "R, a, m, I1, I2, M, I");
    EXPECT_EQ(systemParameterSummary(SystemKind::Sleigh), "m, a, and I or b");
    EXPECT_EQ(systemParameterSummary(SystemKind::Disk), "m, R, I1, I2");
    EXPECT_EQ(systemParameterSummary(SystemKind::Carriage), "R, a, m, I1, I2, M, I");
}

TEST(SystemParameters, EveryRowIsComplete) {
    for (SystemKind kind : kKinds) {
        std::set<std::string> names;
        for (const SystemParameter& p : systemParameters(kind)) {
            SCOPED_TRACE(systemKindName(kind) + " " + p.name);
            EXPECT_TRUE(names.insert(p.name).second) << "twice";
            EXPECT_STRNE(p.symbol, "");
            EXPECT_STRNE(p.label, "");
            EXPECT_STRNE(p.tooltip, "");
            const std::string unit = p.unit;
            EXPECT_TRUE(unit == "kg" || unit == "m" || unit == "kg m\u00b2") << unit;
            // the unit follows from the name: masses in kg, lengths in m, inertias in kg m²
            const char first = p.name[0];
            EXPECT_EQ(unit, first == 'm' || first == 'M' ? "kg"
                            : first == 'I'               ? "kg m\u00b2"
                                                         : "m");
            EXPECT_LT(p.sliderMin, p.sliderMax);
            EXPECT_LE(p.sliderMin, p.defaultValue);
            EXPECT_GE(p.sliderMax, p.defaultValue);
            if (p.bound == ParameterBound::Positive) {
                EXPECT_GT(p.sliderMin, 0);
            }
            if (p.bound == ParameterBound::NonNegative) {
                EXPECT_GE(p.sliderMin, 0);
            }
        }
    }
}

// the bound of each row is the one deriveSystem enforces: just outside it is refused, naming
// the parameter; on it (NonNegative: 0) it is accepted with the other defaults
TEST(SystemParameters, BoundsAreTheDerivationsChecks) {
    for (SystemKind kind : kKinds) {
        for (const SystemParameter& p : systemParameters(kind)) {
            if (!p.byDefault)
                continue;
            SCOPED_TRACE(systemKindName(kind) + " " + p.name);
            SystemSpec spec{kind, defaultSystemParams(kind)};
            EXPECT_TRUE(accepted(spec));
            switch (p.bound) {
            case ParameterBound::Positive:
                spec.params[p.name] = 0.0;
                EXPECT_FALSE(accepted(spec));
                break;
            case ParameterBound::NonNegative:
                spec.params[p.name] = -1e-9;
                EXPECT_FALSE(accepted(spec));
                spec.params[p.name] = 0.0;
                EXPECT_TRUE(accepted(spec));
                break;
            case ParameterBound::Any:
                spec.params[p.name] = -p.defaultValue;
                EXPECT_TRUE(accepted(spec));
                break;
            }
            spec.params[p.name] = NAN;
            try {
                deriveSystem(spec);
                ADD_FAILURE() << "NaN accepted";
            } catch (const InputError& e) {
                EXPECT_NE(std::string(e.what()).find(std::string("parameter ") + p.name),
                          std::string::npos)
                    << e.what();
            }
        }
    }
}

TEST(SystemParameters, TheSleighTakesBOrIAndTheLastGivenWins) {
    SystemSpec spec{SystemKind::Sleigh, defaultSystemParams(SystemKind::Sleigh)};
    setSystemParameter(spec, "I", 0.5);
    EXPECT_EQ(spec.params.count("b"), 0u);
    EXPECT_EQ(spec.params.at("I"), 0.5);
    // b² = a² + I/m with m = 1, a = 0.5
    EXPECT_NEAR(systemParameterValue(spec, "b"), std::sqrt(0.25 + 0.5), 1e-15);
    setSystemParameter(spec, "b", 2.0);
    EXPECT_EQ(spec.params.count("I"), 0u);
    EXPECT_NEAR(systemParameterValue(spec, "I"), 4.0 - 0.25, 1e-15);
    // the other systems have no alternatives: I1 and I of the carriage stay side by side
    SystemSpec carriage{SystemKind::Carriage, defaultSystemParams(SystemKind::Carriage)};
    setSystemParameter(carriage, "I1", 0.03);
    setSystemParameter(carriage, "I", 0.3);
    EXPECT_EQ(carriage.params.size(), 7u);
    EXPECT_THROW(systemParameterValue(carriage, "b"), InputError);
}
