#include "lab/parameter_sweep.h"

#include "control/piece_control.h"
#include "planning/scene_path.h"

#include "common/input_error.h"
#include "paths/path.h"
#include "scene/solution.h"
#include "scene/speed_choice.h"
#include "systems/system_parameters.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace chaplygin {
namespace {

constexpr int kScanPerPanel = 4;      // scan points per path-table panel
constexpr int kRefinedCandidates = 8; // candidate maxima refined per quantity and piece
constexpr double kGolden = 0.6180339887498949;

// the four control quantities whose maxima a row holds, from one control state
std::array<double, 4> magnitudes(const ControlState& c) {
    // power of the control: F_cs sdot + tau phidot = dT/dt (docs/physics.md §2)
    double power = c.forceAxial * c.sdot + c.controlCouple * c.phidot;
    return {std::fabs(c.lambda), std::fabs(c.controlCouple), std::fabs(c.forceLateral),
            std::fabs(power)};
}

// golden-section search for the maximum of f on [lo, hi] (f unimodal there)
template <class F> double goldenMax(F f, double lo, double hi) {
    double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
    double f1 = f(x1), f2 = f(x2);
    double best = std::max({f(lo), f(hi), f1, f2});
    const double tol = 1e-13 * std::max({std::fabs(lo), std::fabs(hi), 1.0});
    for (int it = 0; it < 200 && hi - lo > tol; ++it) {
        if (f1 >= f2) {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - kGolden * (hi - lo);
            f1 = f(x1);
            best = std::max(best, f1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + kGolden * (hi - lo);
            f2 = f(x2);
            best = std::max(best, f2);
        }
    }
    return best;
}

// maxima of the four magnitudes over one smooth piece: a scan on the table's panels, then
// golden-section refinement of the largest local maxima of the scan
void curveMaxima(const ControlParams& params, const PathPiece& piece, std::array<double, 4>& max) {
    const PathTable& table = *piece.table;
    const auto& nodes = table.nodes();
    std::vector<double> us;
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
        for (int j = 0; j < kScanPerPanel; ++j)
            us.push_back(nodes[i].u + (nodes[i + 1].u - nodes[i].u) * j / kScanPerPanel);
    us.push_back(nodes.back().u);
    auto stateAt = [&](double u) {
        PathNode n = table.at(u);
        return controlOnPiece(params, piece, n);
    };
    std::vector<std::array<double, 4>> values(us.size());
    for (std::size_t i = 0; i < us.size(); ++i)
        values[i] = magnitudes(stateAt(us[i]));
    for (int q = 0; q < 4; ++q) {
        std::vector<std::pair<double, std::size_t>> candidates;
        for (std::size_t i = 0; i < us.size(); ++i) {
            double v = values[i][q];
            max[q] = std::max(max[q], v);
            double left = i > 0 ? values[i - 1][q] : -1,
                   right = i + 1 < us.size() ? values[i + 1][q] : -1;
            // a strict local maximum on at least one side (a flat stretch is exact already)
            if (v >= left && v >= right && (v > left || v > right))
                candidates.emplace_back(v, i);
        }
        std::sort(candidates.begin(), candidates.end(), std::greater<>());
        if (candidates.size() > kRefinedCandidates)
            candidates.resize(kRefinedCandidates);
        for (const auto& [v, i] : candidates) {
            double lo = us[i > 0 ? i - 1 : i], hi = us[std::min(i + 1, us.size() - 1)];
            auto f = [&](double u) { return magnitudes(stateAt(u))[q]; };
            max[q] = std::max(max[q], goldenMax(f, lo, hi));
        }
    }
}

std::string numberText(double v) {
    char buf[32];
    auto res = std::to_chars(buf, buf + sizeof buf, v + 0.0); // -0 is written 0
    return std::string(buf, res.ptr);
}

} // namespace

std::string sweepQuantityColumn(SweepQuantity q) {
    switch (q) {
    case SweepQuantity::Duration:
        return "duration";
    case SweepQuantity::MaxAbsLambda:
        return "max_abs_lambda";
    case SweepQuantity::MaxAbsControlCouple:
        return "max_abs_control_couple";
    case SweepQuantity::MaxAbsForceLateral:
        return "max_abs_force_lateral";
    case SweepQuantity::MaxAbsControlPower:
        return "max_abs_control_power";
    case SweepQuantity::FinalSeparation:
        return "final_separation";
    }
    return {};
}

std::string sweepQuantityLabel(SweepQuantity q) {
    switch (q) {
    case SweepQuantity::Duration:
        return TRANSLATABLE_TEXT("SweepQuantity", "duration [s]");
    case SweepQuantity::MaxAbsLambda:
        return TRANSLATABLE_TEXT("SweepQuantity", "max |λ| [kg m/s]");
    case SweepQuantity::MaxAbsControlCouple:
        return TRANSLATABLE_TEXT("SweepQuantity", "max |τ| [N m]");
    case SweepQuantity::MaxAbsForceLateral:
        return TRANSLATABLE_TEXT("SweepQuantity", "max |N| [N]");
    case SweepQuantity::MaxAbsControlPower:
        return TRANSLATABLE_TEXT("SweepQuantity", "max |power| [W]");
    case SweepQuantity::FinalSeparation:
        return TRANSLATABLE_TEXT("SweepQuantity", "final separation from the free body [m]");
    }
    return {};
}

double sweepQuantityValue(const SweepRow& row, SweepQuantity q) {
    switch (q) {
    case SweepQuantity::Duration:
        return row.duration;
    case SweepQuantity::MaxAbsLambda:
        return row.maxAbsLambda;
    case SweepQuantity::MaxAbsControlCouple:
        return row.maxAbsControlCouple;
    case SweepQuantity::MaxAbsForceLateral:
        return row.maxAbsForceLateral;
    case SweepQuantity::MaxAbsControlPower:
        return row.maxAbsControlPower;
    case SweepQuantity::FinalSeparation:
        return row.finalSeparation;
    }
    return 0;
}

std::vector<std::string> sweepParameterNames(SystemKind kind, SpeedMode mode) {
    std::vector<std::string> out;
    for (const SystemParameter& p : systemParameters(kind))
        out.push_back(p.name);
    out.push_back(speedParameter(mode).name);
    return out;
}

std::vector<double> sweepValues(const SweepSpec& spec) {
    if (!std::isfinite(spec.from) || !std::isfinite(spec.to))
        throw InputError("sweep " + spec.parameter, "FROM and TO must be finite numbers");
    if (spec.count < 1 || spec.count > 100000)
        throw InputError("sweep " + spec.parameter,
                         "COUNT must be a whole number from 1 to 100000, got " +
                             std::to_string(spec.count));
    if (spec.count == 1 && spec.from != spec.to)
        throw InputError("sweep " + spec.parameter, "COUNT 1 needs FROM = TO");
    if (spec.count > 1 && spec.from == spec.to)
        throw InputError("sweep " + spec.parameter, "FROM and TO must differ when COUNT > 1");
    std::vector<double> v(spec.count);
    for (int i = 0; i < spec.count; ++i)
        v[i] = i + 1 == spec.count ? spec.to
                                   : spec.from + (spec.to - spec.from) * i / (spec.count - 1);
    return v;
}

Scene sceneWithParameter(const Scene& scene, const std::string& name, double value) {
    Scene s = scene;
    if (name == "vT" || name == "vs") {
        bool energy = scene.mode == SpeedMode::Energy;
        if (energy != (name == "vT"))
            throw InputError("sweep " + name, energy ? "in energy mode sweep vT, not vs"
                                                     : "in speed mode sweep vs, not vT");
        s.speed = value;
        return s;
    }
    if (!findSystemParameter(scene.system.kind, name)) {
        std::string list;
        for (const std::string& p : sweepParameterNames(scene.system.kind, scene.mode)) {
            if (!list.empty())
                list += ", ";
            list += p;
        }
        throw InputError("sweep " + name, "unknown parameter for the " +
                                              systemKindName(scene.system.kind) + " (use " + list +
                                              ")");
    }
    setSystemParameter(s.system, name, value);
    return s;
}

double sceneParameter(const Scene& scene, const std::string& name) {
    if (name == "vT" || name == "vs")
        return scene.speed;
    const SystemParameter* p = findSystemParameter(scene.system.kind, name);
    if (!p || (!p->alternative && !scene.system.params.count(name)))
        throw InputError("sweep " + name, "the scene has no parameter " + name);
    return systemParameterValue(scene.system, name);
}

void validateSweep(const Scene& scene, const SweepSpec& spec) {
    std::vector<double> values = sweepValues(spec);
    for (std::size_t i = 0; i < values.size(); ++i) {
        Scene s = sceneWithParameter(scene, spec.parameter, values[i]);
        std::string where = "sweep " + spec.parameter;
        std::string which = spec.parameter + " = " + formatNumber(values[i]) + " (value " +
                            std::to_string(i + 1) + " of " + std::to_string(values.size()) + ")";
        try {
            controlParamsOf(s);
        } catch (const InputError& e) {
            throw InputError(where, which + " is invalid: " + e.what());
        }
        if (!(s.speed > 0))
            throw InputError(where, which + " is invalid: the speed must be > 0");
    }
}

SweepReport runParameterSweep(const Scene& scene, const SweepSpec& spec,
                              const SweepOptions& options) {
    validateSweep(scene, spec);
    std::vector<double> values = sweepValues(spec);
    SweepReport report;
    report.spec = spec;
    Scene base = scene;
    base.tEnd.reset();
    std::shared_ptr<const Path> path = buildScenePath(base.path);
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (options.cancel && options.cancel->load()) {
            report.cancelled = true;
            break;
        }
        Scene s = sceneWithParameter(base, spec.parameter, values[i]);
        Solution solution = Solution::compute(s, path);
        SweepRow row;
        row.value = values[i];
        row.duration = solution.duration();
        std::array<double, 4> max{};
        for (const PathPiece& piece : path->pieces()) {
            if (piece.kind == PathPiece::Kind::Curve) {
                curveMaxima(solution.params(), piece, max);
            } else {
                // the pivot's state is constant during the turn (docs/physics.md §3)
                auto m = magnitudes(
                    controlAtPivot(solution.params(), piece.phiFrom, piece.phiTo - piece.phiFrom));
                for (int q = 0; q < 4; ++q)
                    max[q] = std::max(max[q], m[q]);
            }
        }
        row.maxAbsLambda = max[0];
        row.maxAbsControlCouple = max[1];
        row.maxAbsForceLateral = max[2];
        row.maxAbsControlPower = max[3];
        MotionSample end = solution.at(solution.duration());
        row.finalSeparation = std::hypot(end.x - end.free.x, end.y - end.free.y);
        report.rows.push_back(row);
        if (options.progress)
            options.progress(static_cast<int>(i + 1), static_cast<int>(values.size()));
    }
    return report;
}

std::string formatSweepCsv(const SweepReport& report) {
    std::string out = report.spec.parameter;
    for (int q = 0; q < kSweepQuantityCount; ++q) {
        out += ',';
        out += sweepQuantityColumn(static_cast<SweepQuantity>(q));
    }
    out += '\n';
    for (const SweepRow& row : report.rows) {
        out += numberText(row.value);
        for (int q = 0; q < kSweepQuantityCount; ++q) {
            out += ',';
            out += numberText(sweepQuantityValue(row, static_cast<SweepQuantity>(q)));
        }
        out += '\n';
    }
    return out;
}

} // namespace chaplygin
