#include "planning/pose_planner.h"

#include "common/input_error.h"
#include "planning/cut_time.h"
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

// (-pi, pi]
double wrapAngle(double a) {
    double r = std::remainder(a, 2 * pi);
    return r <= -pi ? r + 2 * pi : r;
}

// the target in the start's frame, lengths in b: the normalised problem (docs/physics.md §10)
struct Target {
    double X = 0, Y = 0, Phi = 0;
};

// a geodesic of the normalised problem: Psi0, Lambda0 = b Psidot0 / v_T and t v_T / b
struct UnitSolution {
    double psi0 = 0, lambda0 = 0, t = 0;
};

// the end pose's error (x, y, phi mod 2 pi)
Eigen::Vector3d endResidual(const UnitGeodesicPoint& p, const Target& tg) {
    return {p.x - tg.X, p.y - tg.Y, wrapAngle(p.phi - tg.Phi)};
}

double endError(const UnitSolution& s, const Target& tg) {
    return endResidual(UnitGeodesic(s.psi0, s.lambda0).at(s.t), tg).lpNorm<1>();
}

// Newton's method on (Psi0, Lambda0, t) -> end pose, the Jacobian's t column exact (the velocity)
// and the others central differences; steps halved while the residual does not decrease.
std::optional<UnitSolution> polish(UnitSolution s, const Target& tg) {
    constexpr double converged = 1e-14, accepted = 1e-11;
    double norm = endError(s, tg);
    for (int iter = 0; iter < 40 && norm > converged * (1 + s.t); ++iter) {
        const UnitGeodesic g(s.psi0, s.lambda0);
        const UnitGeodesicPoint p = g.at(s.t);
        const Eigen::Vector3d r = endResidual(p, tg);
        Eigen::Matrix3d J;
        // steps that stay on one side of the separatrix, where the end moves like log |1 - k|
        const double nearSeparatrix = std::clamp(100 * std::fabs(1 - g.modulus()), 1e-4, 1.0);
        const double h0 = 2e-7 * nearSeparatrix, h1 = h0 * (1 + std::fabs(s.lambda0));
        const Eigen::Vector3d dPsi = endResidual(UnitGeodesic(s.psi0 + h0, s.lambda0).at(s.t), tg) -
                                     endResidual(UnitGeodesic(s.psi0 - h0, s.lambda0).at(s.t), tg);
        const Eigen::Vector3d dLambda =
            endResidual(UnitGeodesic(s.psi0, s.lambda0 + h1).at(s.t), tg) -
            endResidual(UnitGeodesic(s.psi0, s.lambda0 - h1).at(s.t), tg);
        J.col(0) = dPsi / (2 * h0);
        J.col(1) = dLambda / (2 * h1);
        J(2, 0) = wrapAngle(dPsi(2)) / (2 * h0);
        J(2, 1) = wrapAngle(dLambda(2)) / (2 * h1);
        J.col(2) << p.sinPsi * std::cos(p.phi), p.sinPsi * std::sin(p.phi), p.cosPsi;
        const Eigen::FullPivLU<Eigen::Matrix3d> lu(J);
        if (!lu.isInvertible())
            break;
        const Eigen::Vector3d step = lu.solve(-r);
        if (!step.allFinite())
            break;
        bool improved = false;
        for (double damping = 1; damping > 1e-3; damping *= 0.5) {
            UnitSolution trial{wrapAngle(s.psi0 + damping * step(0)), s.lambda0 + damping * step(1),
                               s.t + damping * step(2)};
            if (trial.t < 0)
                continue;
            const double trialNorm = endError(trial, tg);
            if (trialNorm < norm) {
                s = trial;
                norm = trialNorm;
                improved = true;
                break;
            }
        }
        if (!improved)
            break;
    }
    // the closed form carries the rounding of k^2 (1e-16) into the phase as 1e-16/|1 - k^2|
    // (docs/physics.md §8): next to the separatrix no end can be closer than that (up to 1e-5)
    const double c0 = std::cos(s.psi0);
    const double gap = std::fabs((c0 - s.lambda0) * (c0 + s.lambda0));
    if (!(norm <= std::min(accepted + 4e-16 / gap, 1e-5)))
        return std::nullopt;
    return s;
}

// The integrals of the motion (docs/physics.md §10): P = (sin Psi0, Lambda0) is constant in the
// plane and cos Psi + x P_y - y P_x = cos Psi0. At the target they fix the pendulum's state,
//   sin Psi1 = P.(cos Phi, sin Phi),  cos Psi1 = cos Psi0 + Y sin Psi0 - X Lambda0,
//   Lambda1 = Lambda0 cos Phi - sin Psi0 sin Phi,
// and sin^2 Psi1 + cos^2 Psi1 = 1 is the curve G(Psi0, Lambda0) = 0 on which every geodesic to the
// target starts. On it the heading and the position across P come out right at every passage of
// the pendulum through (Psi1, Lambda1); what is left is the position along P.
double curveG(double s0, double c0, double lambda, const Target& tg) {
    const double s1 = s0 * std::cos(tg.Phi) + lambda * std::sin(tg.Phi);
    const double c1 = c0 + tg.Y * s0 - tg.X * lambda;
    return s1 * s1 + c1 * c1 - 1;
}

// a point of the curve with the passages' along-P misses: at the n-th passage,
// t = t + n period and the miss is along + n drift
struct CurvePoint {
    double psi0 = 0, lambda0 = 0;
    bool valid = false;
    double t = 0, period = 0, along = 0, drift = 0;
    double k = 0;
};

CurvePoint curvePoint(double psi0, double lambda0, const Target& tg) {
    CurvePoint cp;
    cp.psi0 = psi0;
    cp.lambda0 = lambda0;
    const double s0 = std::sin(psi0), c0 = std::cos(psi0);
    const double k2 = s0 * s0 + lambda0 * lambda0;
    // the separatrix level and pivoting are found by Newton from their neighbours
    if (k2 == 1 || k2 < 1e-18)
        return cp;
    double s1 = s0 * std::cos(tg.Phi) + lambda0 * std::sin(tg.Phi);
    double c1 = c0 + tg.Y * s0 - tg.X * lambda0;
    const double n1 = std::hypot(s1, c1);
    s1 /= n1;
    c1 /= n1;
    const double lambda1 = lambda0 * std::cos(tg.Phi) - s0 * std::sin(tg.Phi);
    const auto pass = pendulumPassage(psi0, lambda0, s1, c1, lambda1);
    if (!pass)
        return cp;
    const double k = std::sqrt(k2);
    cp.valid = true;
    cp.k = k;
    cp.t = pass->t;
    cp.period = pass->period;
    cp.along = ((pass->x - tg.X) * s0 + (pass->y - tg.Y) * lambda0) / k;
    cp.drift = (pass->driftX * s0 + pass->driftY * lambda0) / k;
    return cp;
}

// G's root on the segment from (a, Ga) to (b, Gb), Ga and Gb of opposite signs (Illinois)
template <class F> double edgeRoot(F&& G, double a, double Ga, double b, double Gb) {
    int side = 0;
    for (int i = 0; i < 80; ++i) {
        const double c = (a * Gb - b * Ga) / (Gb - Ga);
        const double Gc = G(c);
        if (Gc == 0 || std::fabs(b - a) < 1e-15 * (1 + std::fabs(c)))
            return c;
        if ((Gc > 0) == (Gb > 0)) {
            b = c;
            Gb = Gc;
            if (side == -1)
                Ga *= 0.5;
            side = -1;
        } else {
            a = c;
            Ga = Gc;
            if (side == 1)
                Gb *= 0.5;
            side = 1;
        }
    }
    return 0.5 * (a + b);
}

// the passage of b that continues the n-th of a: the nearest in time, within half a period
int pairedPassage(const CurvePoint& a, const CurvePoint& b, int n) {
    const double ta = a.t + n * a.period;
    int best = -1;
    double bestGap = 0.5 * std::min(a.period, b.period);
    for (int m = std::max(0, n - 1); m <= n + 1; ++m) {
        const double gap = std::fabs(b.t + m * b.period - ta);
        if (gap < bestGap) {
            bestGap = gap;
            best = m;
        }
    }
    return best;
}

// the point of G = 0 nearest to (psi0, lambda0), by Newton steps along G's gradient, until G is
// at its rounding (about 1e-16 (1 + |X| + |Y|))
std::optional<std::pair<double, double>> projectOnCurve(double psi0, double lambda0,
                                                        const Target& tg) {
    const double cP = std::cos(tg.Phi), sP = std::sin(tg.Phi);
    const double rounding =
        1e-15 * (1 + std::fabs(tg.X) + std::fabs(tg.Y)) * (1 + std::fabs(lambda0));
    double G = 1;
    for (int i = 0; i < 20; ++i) {
        const double s0 = std::sin(psi0), c0 = std::cos(psi0);
        const double s1 = s0 * cP + lambda0 * sP, c1 = c0 + tg.Y * s0 - tg.X * lambda0;
        G = s1 * s1 + c1 * c1 - 1;
        if (std::fabs(G) <= rounding)
            break;
        const double gPsi = 2 * s1 * c0 * cP + 2 * c1 * (tg.Y * c0 - s0);
        const double gLam = 2 * s1 * sP - 2 * c1 * tg.X;
        const double g2 = gPsi * gPsi + gLam * gLam;
        if (!(g2 > 0))
            return std::nullopt;
        psi0 -= G * gPsi / g2;
        lambda0 -= G * gLam / g2;
    }
    if (!(std::fabs(G) <= 1e3 * rounding))
        return std::nullopt;
    return std::make_pair(psi0, lambda0);
}

// how far a piece of the curve is from smooth: 0 when both ends have the same kind of orbit and
// nearly the same first passage (or neither has one), 1 when the first passage moves a lot, 2 at
// a change of orbit, where the passage ends, or next to the separatrix
int roughness(const CurvePoint& a, const CurvePoint& b, const Target& tg) {
    if (!a.valid && !b.valid)
        return 0;
    if (a.valid != b.valid || (a.k < 1) != (b.k < 1))
        return 2;
    // the first passage grows like log 1/|1 - k| near the separatrix: a piece that comes much
    // closer to it inside than at its ends, or whose ends differ in that logarithm, is halved
    const double ea = std::fabs(1 - a.k), eb = std::fabs(1 - b.k);
    if (std::fabs(std::log(ea / eb)) > 2)
        return 2;
    const auto mid = projectOnCurve(a.psi0 + 0.5 * wrapAngle(b.psi0 - a.psi0),
                                    0.5 * (a.lambda0 + b.lambda0), tg);
    if (mid &&
        std::fabs(1 - std::hypot(std::sin(mid->first), mid->second)) < 0.5 * std::min(ea, eb))
        return 2;
    const int m = pairedPassage(a, b, 0);
    if (m < 0)
        return 2;
    const double gap = std::fabs(b.t + m * b.period - a.t);
    return gap <= 0.05 * (1 + a.t) ? 0 : 1;
}

// Seeds for Newton: where the along-P miss of one passage changes sign between two neighbouring
// points of the curve G = 0, traced cell by cell on a grid in (Psi0, asinh Lambda0).
// A piece of the curve over which the n-th passage of a and the m-th of b miss on opposite
// sides along P, and the time interpolated there.
struct SeedPiece {
    CurvePoint a;
    int n = 0;
    CurvePoint b;
    int m = 0;
    double t = 0;
};

// Newton's start from a piece: halve it (its middle put back on the curve) while the passage
// continues, then interpolate. Done only for the pieces Newton is run from.
UnitSolution refineSeed(SeedPiece piece, const Target& tg) {
    CurvePoint a = piece.a, b = piece.b;
    int n = piece.n, m = piece.m;
    for (int i = 0; i < 60; ++i) {
        const double ga = a.along + n * a.drift;
        if (ga == 0 ||
            std::fabs(wrapAngle(b.psi0 - a.psi0)) + std::fabs(b.lambda0 - a.lambda0) < 1e-14)
            break;
        const auto onCurve = projectOnCurve(a.psi0 + 0.5 * wrapAngle(b.psi0 - a.psi0),
                                            0.5 * (a.lambda0 + b.lambda0), tg);
        if (!onCurve)
            break;
        const CurvePoint mid = curvePoint(wrapAngle(onCurve->first), onCurve->second, tg);
        if (!mid.valid)
            break;
        const int j = pairedPassage(a, mid, n);
        if (j < 0)
            break;
        const double gm = mid.along + j * mid.drift;
        if ((gm > 0) == (ga > 0)) {
            a = mid;
            n = j;
        } else {
            b = mid;
            m = j;
        }
    }
    const double ga = a.along + n * a.drift, gb = b.along + m * b.drift;
    const double f = ga == gb ? 0.5 : ga / (ga - gb);
    const double ta = a.t + n * a.period, tb = b.t + m * b.period;
    return {wrapAngle(a.psi0 + f * wrapAngle(b.psi0 - a.psi0)),
            a.lambda0 + f * (b.lambda0 - a.lambda0), ta + f * (tb - ta)};
}

// The grid: columns over Psi0 in (-pi, pi], rows du apart in asinh Lambda0.
struct GridSize {
    int columns = 96;
    double du = 0.05;
};

std::vector<SeedPiece> curveSeeds(const Target& tg, double tMax, double kMax, GridSize size) {
    const int columns = size.columns;
    const double du = size.du;
    const double uMax = std::asinh(kMax * 1.02);
    const int rows = std::max(8, static_cast<int>(std::ceil(2 * uMax / du)));
    const double dpsi = 2 * pi / columns, duRow = 2 * uMax / rows;
    std::vector<double> psi(columns), sinPsi(columns), cosPsi(columns), lam(rows + 1);
    for (int i = 0; i < columns; ++i) {
        psi[i] = -pi + (i + 0.3719) * dpsi; // off the axes, where lines and pivots sit
        sinPsi[i] = std::sin(psi[i]);
        cosPsi[i] = std::cos(psi[i]);
    }
    for (int j = 0; j <= rows; ++j)
        lam[j] = std::sinh(-uMax + (j + 0.2113) * duRow);
    std::vector<double> G((rows + 1) * columns);
    auto node = [&](int i, int j) -> double& { return G[j * columns + i]; };
    for (int j = 0; j <= rows; ++j)
        for (int i = 0; i < columns; ++i)
            node(i, j) = curveG(sinPsi[i], cosPsi[i], lam[j], tg);

    std::vector<CurvePoint> points;
    std::vector<int> horizontal((rows + 1) * columns, -1), vertical(rows * columns, -1);
    for (int j = 0; j <= rows; ++j)
        for (int i = 0; i < columns; ++i) {
            const int i1 = (i + 1) % columns;
            const double g0 = node(i, j), g1 = node(i1, j);
            if ((g0 > 0) == (g1 > 0))
                continue;
            const double l = lam[j];
            auto along = [&](double p) { return curveG(std::sin(p), std::cos(p), l, tg); };
            const double p = edgeRoot(along, psi[i], g0, psi[i] + dpsi, g1);
            horizontal[j * columns + i] = static_cast<int>(points.size());
            points.push_back(curvePoint(wrapAngle(p), l, tg));
        }
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            const double g0 = node(i, j), g1 = node(i, j + 1);
            if ((g0 > 0) == (g1 > 0))
                continue;
            auto along = [&](double l) { return curveG(sinPsi[i], cosPsi[i], l, tg); };
            const double l = edgeRoot(along, lam[j], g0, lam[j + 1], g1);
            vertical[j * columns + i] = static_cast<int>(points.size());
            points.push_back(curvePoint(psi[i], l, tg));
        }

    std::vector<SeedPiece> seeds;
    int budget = 20000; // halvings, a bound on the time a pathological target can take
    auto link = [&](const CurvePoint& a, const CurvePoint& b) {
        const double jump = 0.5 * std::min(a.period, b.period);
        for (int n = 0;; ++n) {
            const double ta = a.t + n * a.period;
            if (ta > tMax + jump)
                break;
            const int best = pairedPassage(a, b, n);
            if (best < 0)
                continue;
            const double ga = a.along + n * a.drift, gb = b.along + best * b.drift;
            if ((ga > 0) == (gb > 0) && ga != 0)
                continue;
            const double tb = b.t + best * b.period;
            const double f = ga == gb ? 0.5 : ga / (ga - gb);
            seeds.push_back({a, n, b, best, ta + f * (tb - ta)});
        }
    };
    // continuation along the curve: a piece whose ends disagree (the first passage jumps, the
    // pendulum changes from libration to rotation, or an end has no passage) is halved, its
    // middle put back on the curve, down to a piece 2^-10 of a cell long
    auto follow = [&](auto&& self, const CurvePoint& a, const CurvePoint& b, int depth) -> void {
        const int rough = roughness(a, b, tg);
        if (((rough == 2 && depth < 48) || (rough == 1 && depth < 5)) && --budget > 0) {
            const double psiM = a.psi0 + 0.5 * wrapAngle(b.psi0 - a.psi0);
            const double lamM = 0.5 * (a.lambda0 + b.lambda0);
            const auto onCurve = projectOnCurve(psiM, lamM, tg);
            if (onCurve) {
                const CurvePoint m = curvePoint(wrapAngle(onCurve->first), onCurve->second, tg);
                self(self, a, m, depth + 1);
                self(self, m, b, depth + 1);
                return;
            }
        }
        if (a.valid && b.valid)
            link(a, b);
    };
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            const int i1 = (i + 1) % columns;
            int ids[4], count = 0;
            for (int id : {horizontal[j * columns + i], vertical[j * columns + i1],
                           horizontal[(j + 1) * columns + i], vertical[j * columns + i]})
                if (id >= 0)
                    ids[count++] = id;
            if (count == 2) {
                follow(follow, points[ids[0]], points[ids[1]], 0);
            } else if (count == 4) { // a saddle of G: either pairing
                for (int a = 0; a < 4; ++a)
                    follow(follow, points[ids[a]], points[ids[(a + 1) % 4]], 0);
            }
        }
    std::sort(seeds.begin(), seeds.end(),
              [](const SeedPiece& a, const SeedPiece& b) { return a.t < b.t; });
    return seeds;
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
    const UnitGeodesic g(s.psi0, s.lambda0);
    Found f{s, familyOf(g), 0};
    switch (f.family) {
    case GeodesicFamily::Line:
    case GeodesicFamily::Separatrix:
        f.cut = std::numeric_limits<double>::infinity();
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
    const Target tg{(c * dx + s * dy) / b, (-s * dx + c * dy) / b,
                    wrapAngle(request.to.phi - request.from.phi)};
    const double d = std::hypot(tg.X, tg.Y);
    const double userHorizon = request.horizon * v / b;
    // pivot to face the target, drive, pivot to the heading: the least time is at most this
    const double upper = d + 1.5 * pi;

    std::vector<Found> all;
    double scanT = 0;
    if (d <= 1e-12) {
        // only pivoting returns to the start's position (docs/physics.md §10)
        scanT = userHorizon > 0 ? userHorizon : std::max(3 * pi, 2 * pi);
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
        g.modulus =
            std::hypot(f.family == GeodesicFamily::Line ? 1.0 : std::sin(f.s.psi0), f.s.lambda0);
        if (f.family == GeodesicFamily::Pivot || f.family == GeodesicFamily::Rest)
            g.modulus = 0;
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
