#pragma once
// Parameter sweeps: one parameter over a range on one tabulated path, with the duration and the
// maxima of the control quantities per value (docs/numerics.md §6).
#include "scene/scene.h"

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace chaplygin {

/// One parameter swept over FROM:TO in COUNT evenly spaced values (both ends included).
/// The name is one of the system's parameters (sleigh: m, a, I, b; disk: m, R, I1, I2;
/// carriage: R, a, m, I1, I2, M, I) or the speed: vT (energy mode) or vs (speed mode).
struct SweepSpec {
    std::string parameter;
    double from = 0, to = 0;
    int count = 2;
};

/// What one value of the parameter gives, over the whole traversal of the path.
struct SweepRow {
    double value = 0;
    double duration = 0;            ///< time to traverse the path [s]
    double maxAbsLambda = 0;        ///< max |lambda| [kg m/s]
    double maxAbsControlCouple = 0; ///< max |tau| [N m]
    double maxAbsForceLateral = 0;  ///< max |N| = |F_cphi| [N]
    double maxAbsControlPower = 0;  ///< max |F_cs sdot + tau phidot| [W] (0 in energy mode)
    double finalSeparation = 0;     ///< |P - P_free| at the end of the path [m]
};

/// The quantities of a row, in CSV order after the parameter column.
enum class SweepQuantity {
    Duration,
    MaxAbsLambda,
    MaxAbsControlCouple,
    MaxAbsForceLateral,
    MaxAbsControlPower,
    FinalSeparation
};
constexpr int kSweepQuantityCount = 6;
/// The CSV column name of a quantity (duration, max_abs_lambda, ...).
std::string sweepQuantityColumn(SweepQuantity q);
/// A label with units for plots and menus ("max |λ| [kg m/s]").
std::string sweepQuantityLabel(SweepQuantity q);
double sweepQuantityValue(const SweepRow& row, SweepQuantity q);

struct SweepOptions {
    /// Called after every value with (done, total), from the calling thread.
    std::function<void(int, int)> progress;
    /// When set and true, the sweep stops after the value under way.
    const std::atomic<bool>* cancel = nullptr;
};

struct SweepReport {
    SweepSpec spec;
    std::vector<SweepRow> rows;
    bool cancelled = false; ///< stopped by options.cancel: rows holds what was done
};

/// The names that can be swept for a system and mode, in display order.
std::vector<std::string> sweepParameterNames(SystemKind kind, SpeedMode mode);

/// The values FROM, ..., TO of a spec. Throws InputError("sweep") for a bad count or range.
std::vector<double> sweepValues(const SweepSpec& spec);

/// The scene with one parameter set (for the sleigh, setting I drops b and setting b drops I).
/// Throws InputError naming the parameter when the system or mode has no such parameter.
Scene sceneWithParameter(const Scene& scene, const std::string& name, double value);

/// The value of a parameter in a scene (for the sleigh, b or I derived when not given).
double sceneParameter(const Scene& scene, const std::string& name);

/// Checks every value before any work; throws InputError("sweep NAME") naming the first bad
/// value and why it is bad (e.g. b < |a| for the sleigh).
void validateSweep(const Scene& scene, const SweepSpec& spec);

/// Solves the scene once per value on one tabulated path. Each value runs over the whole path
/// (a horizon in the scene is ignored). The maxima are found on the path table's panels (four
/// points per panel), then each candidate maximum is refined by golden-section search in the
/// curve parameter, to about 1e-12 relative. Throws InputError before any work for bad values.
SweepReport runParameterSweep(const Scene& scene, const SweepSpec& spec,
                              const SweepOptions& options = {});

/// CSV with the header NAME,duration,max_abs_lambda,max_abs_control_couple,
/// max_abs_force_lateral,max_abs_control_power,final_separation.
std::string formatSweepCsv(const SweepReport& report);

} // namespace chaplygin
