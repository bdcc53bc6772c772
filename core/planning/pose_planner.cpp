#include "planning/pose_planner.h"

#include "common/input_error.h"
#include "planning/complementary_elliptic.h"
#include "planning/cut_time.h"
#include "planning/start_curve.h"
#include "planning/unit_geodesic.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace chaplygin {
namespace {

using std::numbers::pi;

// the end pose's error (x, y, phi mod 2 pi)
Eigen::Vector3d endResidual(const UnitGeodesicPoint& p, const UnitTarget& tg) {
    return {p.x - tg.X, p.y - tg.Y, wrapAngle(p.phi - tg.Phi)};
}

// the geodesic of a solution, with its 1 - k^2 when that is carried exactly
UnitGeodesic geodesicOf(const UnitSolution& s) {
    return std::isnan(s.gap) ? UnitGeodesic(s.psi0, s.lambda0)
                             : UnitGeodesic(s.psi0, s.lambda0, s.gap);
}

double endError(const UnitSolution& s, const UnitTarget& tg) {
    return endResidual(geodesicOf(s).at(s.t), tg).lpNorm<1>();
}

// Newton's step from the Jacobian J and residual r, halved while the residual does not decrease;
// `move` makes the trial solution from a fraction of the step. False when nothing improves.
template <class Move>
bool dampedStep(UnitSolution& s, double& norm, const Eigen::Matrix3d& J, const Eigen::Vector3d& r,
                const UnitTarget& tg, Move&& move) {
    const Eigen::FullPivLU<Eigen::Matrix3d> lu(J);
    if (!lu.isInvertible())
        return false;
    const Eigen::Vector3d step = lu.solve(-r);
    if (!step.allFinite())
        return false;
    for (double damping = 1; damping > 1e-3; damping *= 0.5) {
        const std::optional<UnitSolution> trial = move(damping * step);
        if (!trial || trial->t < 0)
            continue;
        const double trialNorm = endError(*trial, tg);
        if (trialNorm < norm) {
            s = *trial;
            norm = trialNorm;
            return true;
        }
    }
    return false;
}

// the t column of the Jacobian: the end's velocity
Eigen::Vector3d endVelocity(const UnitGeodesicPoint& p) {
    return {p.sinPsi * std::cos(p.phi), p.sinPsi * std::sin(p.phi), p.cosPsi};
}

// Newton's method on (Psi0, Lambda0, t) -> end pose, the Jacobian's t column exact (the velocity)
// and the others central differences; steps halved while the residual does not decrease.
void newtonOnLambda(UnitSolution& s, double& norm, const UnitTarget& tg, double converged) {
    for (int iter = 0; iter < 40 && norm > converged * (1 + s.t); ++iter) {
        const UnitGeodesic g(s.psi0, s.lambda0);
        const UnitGeodesicPoint p = g.at(s.t);
        const Eigen::Vector3d r = endResidual(p, tg);
        Eigen::Matrix3d J;
        // steps that stay on one side of the separatrix, where the end moves like log |1 - k|
        const double nearSeparatrix = std::clamp(100 * std::fabs(1 - g.modulus()), 1e-4, 1.0);
        // and smaller than the start's distance from a pivot point, next to one
        const double nearPivot = std::clamp(10 * g.modulus(), 1e-6, 1.0);
        const double h0 = 2e-7 * std::min(nearSeparatrix, nearPivot);
        const double h1 = h0 * (1 + std::fabs(s.lambda0));
        const Eigen::Vector3d dPsi = endResidual(UnitGeodesic(s.psi0 + h0, s.lambda0).at(s.t), tg) -
                                     endResidual(UnitGeodesic(s.psi0 - h0, s.lambda0).at(s.t), tg);
        const Eigen::Vector3d dLambda =
            endResidual(UnitGeodesic(s.psi0, s.lambda0 + h1).at(s.t), tg) -
            endResidual(UnitGeodesic(s.psi0, s.lambda0 - h1).at(s.t), tg);
        J.col(0) = dPsi / (2 * h0);
        J.col(1) = dLambda / (2 * h1);
        J(2, 0) = wrapAngle(dPsi(2)) / (2 * h0);
        J(2, 1) = wrapAngle(dLambda(2)) / (2 * h1);
        J.col(2) = endVelocity(p);
        const auto move = [&](const Eigen::Vector3d& d) -> std::optional<UnitSolution> {
            return UnitSolution{wrapAngle(s.psi0 + d(0)), s.lambda0 + d(1), s.t + d(2)};
        };
        if (!dampedStep(s, norm, J, r, tg, move))
            break;
    }
}

// Next to the separatrix a double Lambda0 fixes 1 - k^2 only to 1e-16, and the end moves by
// 1e-16/|1 - k^2| (docs/physics.md §10): Newton on (Psi0, log |1 - k^2|, t) instead, the sign of
// 1 - k^2 and of Lambda0 kept, Lambda0 = +-sqrt(cos^2 Psi0 - (1 - k^2)) following the start.
void newtonOnGap(UnitSolution& s, double& norm, const UnitTarget& tg, double converged) {
    const double c0 = std::cos(s.psi0);
    const double gap0 = std::isnan(s.gap) ? (c0 - s.lambda0) * (c0 + s.lambda0) : s.gap;
    if (gap0 == 0 || s.lambda0 == 0)
        return;
    const double side = gap0 > 0 ? 1.0 : -1.0, sigma = s.lambda0 > 0 ? 1.0 : -1.0;
    const auto solution = [&](double psi0, double logGap, double t) -> std::optional<UnitSolution> {
        const double gap = side * std::exp(logGap), c = std::cos(psi0);
        const double lambda2 = c * c - gap;
        // a step that takes 1 - k^2 out of the doubles (exp underflowing to the separatrix
        // itself, or overflowing) has no closed form to evaluate: rejected, the step halved
        if (!(lambda2 > 0) || gap == 0 || !std::isfinite(gap))
            return std::nullopt;
        return UnitSolution{wrapAngle(psi0), sigma * std::sqrt(lambda2), t, gap};
    };
    const auto start = solution(s.psi0, std::log(std::fabs(gap0)), s.t);
    if (!start)
        return;
    UnitSolution g = *start;
    double gNorm = endError(g, tg);
    for (int iter = 0; iter < 20 && gNorm > converged * (1 + g.t); ++iter) {
        const double logGap = std::log(std::fabs(g.gap));
        const UnitGeodesicPoint p = geodesicOf(g).at(g.t);
        const Eigen::Vector3d r = endResidual(p, tg);
        // Psi0's step below the distance to the turning point Lambda0 = 0, where the start's
        // Lambda0 folds
        const double h0 = 1e-7 * std::min(1.0, std::fabs(g.lambda0)), h1 = 1e-6;
        Eigen::Matrix3d J;
        const auto endAt = [&](double psi0, double lg) -> std::optional<Eigen::Vector3d> {
            const auto u = solution(psi0, lg, g.t);
            if (!u)
                return std::nullopt;
            return endResidual(geodesicOf(*u).at(g.t), tg);
        };
        const auto pp = endAt(g.psi0 + h0, logGap), pm = endAt(g.psi0 - h0, logGap);
        const auto lp = endAt(g.psi0, logGap + h1), lm = endAt(g.psi0, logGap - h1);
        if (!pp || !pm || !lp || !lm)
            break;
        const Eigen::Vector3d dPsi = *pp - *pm, dLog = *lp - *lm;
        J.col(0) = dPsi / (2 * h0);
        J.col(1) = dLog / (2 * h1);
        J(2, 0) = wrapAngle(dPsi(2)) / (2 * h0);
        J(2, 1) = wrapAngle(dLog(2)) / (2 * h1);
        J.col(2) = endVelocity(p);
        const auto move = [&](const Eigen::Vector3d& d) {
            return solution(g.psi0 + d(0), logGap + d(1), g.t + d(2));
        };
        if (!dampedStep(g, gNorm, J, r, tg, move))
            break;
    }
    if (gNorm < norm) {
        s = g;
        norm = gNorm;
    }
}

// Newton on (Psi0, Lambda0, t), then next to the separatrix on (Psi0, log |1 - k^2|, t)
std::optional<UnitSolution> polish(UnitSolution s, const UnitTarget& tg) {
    constexpr double converged = 1e-14, accepted = 1e-11;
    double norm = endError(s, tg);
    newtonOnLambda(s, norm, tg, converged);
    const double c0 = std::cos(s.psi0);
    if (norm > converged * (1 + s.t) && std::fabs((c0 - s.lambda0) * (c0 + s.lambda0)) < 1e-2)
        newtonOnGap(s, norm, tg, converged);
    if (!(norm <= accepted))
        return std::nullopt;
    return s;
}

// the same arrival time and nearly the same start: next to the separatrix Newton ends anywhere
// within the closed form's rounding of the one geodesic
bool sameGeodesic(const UnitSolution& a, const UnitSolution& b) {
    return std::fabs(a.t - b.t) <= 1e-9 * (1 + a.t) &&
           std::fabs(wrapAngle(a.psi0 - b.psi0)) + std::fabs(a.lambda0 - b.lambda0) <= 1e-5;
}

struct Found {
    UnitSolution s;
    GeodesicFamily family;
    double cut = 0; // unit cut time
};

GeodesicFamily familyOf(const UnitGeodesic& g) {
    switch (g.kind()) {
    case VakonomicMotion::Case::Line:
        return GeodesicFamily::Line;
    case VakonomicMotion::Case::Rotation:
        return GeodesicFamily::Rotation;
    case VakonomicMotion::Case::Separatrix:
        return GeodesicFamily::Separatrix;
    case VakonomicMotion::Case::Libration:
        return g.modulus() == 0 ? GeodesicFamily::Pivot : GeodesicFamily::Libration;
    case VakonomicMotion::Case::Rest:
        break;
    }
    return GeodesicFamily::Rest;
}

Found classify(const UnitSolution& s) {
    const UnitGeodesic g = geodesicOf(s);
    Found f{s, familyOf(g), 0};
    switch (f.family) {
    case GeodesicFamily::Line:
    case GeodesicFamily::Separatrix:
        f.cut = std::numeric_limits<double>::infinity();
        break;
    case GeodesicFamily::Libration:
        // 2 K, in the complementary parameter next to the separatrix
        f.cut = g.gap() < 0.5 ? 2 * completeKComplementary(g.gap()) : unitCutTime(g.modulus());
        break;
    default:
        f.cut = unitCutTime(g.modulus());
    }
    return f;
}

bool withinCut(const Found& f) {
    return f.s.t <= f.cut * (1 + 1e-9) + 1e-12;
}

void addUnique(std::vector<Found>& all, const Found& f) {
    for (const Found& g : all)
        if (sameGeodesic(g.s, f.s))
            return;
    all.push_back(f);
}

void checkFinite(double v, const char* where) {
    if (!std::isfinite(v))
        throw InputError(where, "must be a finite number, not " + formatNumber(v));
}

} // namespace

std::string geodesicFamilyName(GeodesicFamily family) {
    switch (family) {
    case GeodesicFamily::Rest:
        return "rest";
    case GeodesicFamily::Pivot:
        return "pivot";
    case GeodesicFamily::Line:
        return "line";
    case GeodesicFamily::Libration:
        return "libration";
    case GeodesicFamily::Rotation:
        return "rotation";
    case GeodesicFamily::Separatrix:
        return "separatrix";
    }
    return "";
}

Plan planVakonomic(const PlanRequest& request) {
    checkFinite(request.from.x, "plan start x");
    checkFinite(request.from.y, "plan start y");
    checkFinite(request.from.phi, "plan start phi");
    checkFinite(request.to.x, "plan target x");
    checkFinite(request.to.y, "plan target y");
    checkFinite(request.to.phi, "plan target phi");
    checkFinite(request.vT, "vT");
    checkFinite(request.horizon, "plan horizon");
    const double b = request.system.b, v = request.vT;
    if (!(b > 0) || !std::isfinite(b))
        throw InputError("b", "must be > 0 and finite, not " + formatNumber(b));
    if (!(v > 0))
        throw InputError("vT", "planning needs a speed v_T > 0, not " + formatNumber(v));
    if (request.horizon < 0)
        throw InputError("plan horizon", "must be > 0, not " + formatNumber(request.horizon));

    // the normalised target: lengths in b, times in b/v_T, in the start's frame
    const double dx = request.to.x - request.from.x, dy = request.to.y - request.from.y;
    const double c = std::cos(request.from.phi), s = std::sin(request.from.phi);
    const UnitTarget tg{(c * dx + s * dy) / b, (-s * dx + c * dy) / b,
                        wrapAngle(request.to.phi - request.from.phi)};
    const double d = std::hypot(tg.X, tg.Y);
    const double userHorizon = request.horizon * v / b;
    // pivot to face the target, drive, pivot to the heading: the least time is at most this
    const double upper = d + 1.5 * pi;

    std::vector<Found> all;
    double scanT = 0;
    if (d <= 1e-12) {
        // only pivoting returns to the start's position (docs/physics.md §10); the least time
        // is at most pi, so the default horizon at most 3 pi
        scanT = userHorizon > 0 ? userHorizon : 3 * pi;
        if (std::fabs(tg.Phi) <= 1e-15)
            all.push_back({{0, 0, 0}, GeodesicFamily::Rest, pi});
        for (const double psi0 : {0.0, pi}) {
            double t0 = std::fmod(psi0 == 0 ? tg.Phi : -tg.Phi, 2 * pi);
            if (t0 <= 1e-15)
                t0 += 2 * pi;
            for (double t = t0; t <= scanT * (1 + 1e-12); t += 2 * pi)
                all.push_back({{psi0, 0, t}, GeodesicFamily::Pivot, pi});
        }
    } else {
        scanT = userHorizon > 0 ? userHorizon : std::max(3 * upper, 2 * pi);
        if (request.optimalOnly)
            scanT = userHorizon > 0 ? std::min(userHorizon, upper) : upper;
        if (std::fabs(tg.Y) <= 1e-12 && std::fabs(tg.Phi) <= 1e-12 && d <= scanT)
            all.push_back({{tg.X > 0 ? pi / 2 : -pi / 2, 0, d},
                           GeodesicFamily::Line,
                           std::numeric_limits<double>::infinity()});
        // |z| <= (2 + t)/k and |phi| <= 2 asin(1/k) on a rotation (docs/physics.md §10)
        double kMax = std::min((2 + scanT) / d, 1e4);
        if (std::fabs(tg.Phi) > 1e-12)
            kMax = std::min(kMax, 1 / std::sin(0.5 * std::fabs(tg.Phi)));
        kMax = std::max(kMax, 1.2);
        // the least time alone: a coarse grid first, enough once its answer is certified (and,
        // on the Maxwell set, its twin found); the fine grid otherwise, and for the whole list
        const GridSize fine{96, 0.05}, coarse{48, 0.1};
        // the straight line never stops being optimal: nothing else ties with it
        const bool lineOnly = request.optimalOnly && !all.empty();
        std::vector<GridSize> grids;
        if (!lineOnly)
            grids = request.optimalOnly ? std::vector{coarse, fine} : std::vector{fine};
        for (const GridSize size : grids) {
            double certifiedT = std::numeric_limits<double>::infinity();
            bool tie = false;
            int optima = 0;
            for (const SeedPiece& piece : curveSeeds(tg, scanT, kMax, size)) {
                if (request.optimalOnly && std::isfinite(certifiedT) &&
                    (!tie || piece.t > 1.3 * certifiedT + 0.1))
                    break;
                const UnitSolution seed = refineSeed(piece, tg);
                bool known = false;
                for (const Found& f : all)
                    known = known || sameGeodesic(f.s, seed);
                if (known)
                    continue;
                const auto sol = polish(seed, tg);
                if (!sol || sol->t > scanT * (1 + 1e-9) + 1e-12)
                    continue;
                const Found f = classify(*sol);
                addUnique(all, f);
                if (request.optimalOnly && withinCut(f)) {
                    if (f.s.t < certifiedT - 1e-9 * (1 + f.s.t)) {
                        certifiedT = f.s.t;
                        tie = f.s.t > f.cut * (1 - 1e-7);
                        optima = 1;
                    } else if (f.s.t <= certifiedT + 1e-9 * (1 + f.s.t)) {
                        ++optima;
                    }
                }
            }
            if (std::isfinite(certifiedT) && (!tie || optima >= 2))
                break;
        }
    }

    std::sort(all.begin(), all.end(), [](const Found& a, const Found& b) { return a.s.t < b.s.t; });
    Plan plan;
    const double tMin = all.empty() ? 0 : all.front().s.t;
    double horizon = userHorizon > 0 ? userHorizon : std::max(3 * tMin, 2 * pi);
    plan.horizon = horizon * b / v;
    const double m = request.system.mass, a = request.system.a;
    for (const Found& f : all) {
        if (f.s.t > horizon * (1 + 1e-12))
            continue;
        const bool leastTime = f.s.t <= tMin + 1e-9 * (1 + tMin);
        if (request.optimalOnly && !leastTime)
            continue;
        PlannedGeodesic g;
        g.t = f.s.t * b / v;
        g.psi0 = f.s.psi0 <= -pi ? f.s.psi0 + 2 * pi : f.s.psi0;
        g.psidot0 = f.s.lambda0 * v / b;
        // lambda = m (b Psidot - a phidot), phidot(0) = v_T cos Psi0 / b (docs/physics.md §8)
        const double phidot0 = f.family == GeodesicFamily::Line ? 0 : v * std::cos(g.psi0) / b;
        g.lambda0 = m * (b * g.psidot0 - a * phidot0);
        if (f.family == GeodesicFamily::Line) {
            g.modulus = 1;
            g.modulusGap = 0;
        } else if (f.family != GeodesicFamily::Pivot && f.family != GeodesicFamily::Rest) {
            const UnitGeodesic unit = geodesicOf(f.s);
            g.modulus = unit.modulus();
            g.modulusGap = unit.gap();
        }
        g.family = f.family;
        g.cutTime = f.cut * b / v;
        g.optimal = leastTime && withinCut(f);
        g.endError = f.family == GeodesicFamily::Rest ? 0 : endError(f.s, tg);
        plan.certified = plan.certified || g.optimal;
        plan.geodesics.push_back(g);
    }
    return plan;
}

VakonomicInitial plannedStart(const PlanRequest& request, const PlannedGeodesic& motion) {
    VakonomicInitial init;
    init.x = request.from.x;
    init.y = request.from.y;
    init.phi = request.from.phi;
    const double v = request.vT, b = request.system.b;
    if (motion.family != GeodesicFamily::Line)
        init.phidot = v * std::cos(motion.psi0) / b;
    if (motion.family != GeodesicFamily::Pivot && motion.family != GeodesicFamily::Rest)
        init.sdot = v * std::sin(motion.psi0);
    init.lambda = motion.lambda0;
    return init;
}

} // namespace chaplygin
