#include "planning/start_curve.h"

#include "planning/unit_geodesic.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

namespace chaplygin {
namespace {

using std::numbers::pi;

// The integrals of the motion (docs/physics.md §10): P = (sin Psi0, Lambda0) is constant in the
// plane and cos Psi + x P_y - y P_x = cos Psi0. At the target they fix the pendulum's state,
//   sin Psi1 = P.(cos Phi, sin Phi),  cos Psi1 = cos Psi0 + Y sin Psi0 - X Lambda0,
//   Lambda1 = Lambda0 cos Phi - sin Psi0 sin Phi,
// and sin^2 Psi1 + cos^2 Psi1 = 1 is the curve G(Psi0, Lambda0) = 0 on which every geodesic to the
// target starts. On it the heading and the position across P come out right at every passage of
// the pendulum through (Psi1, Lambda1); what is left is the position along P.
// sin Psi0, cos Psi0 and 1 -+ cos Psi0 = 2 sin^2(Psi0/2), 2 cos^2(Psi0/2): exact next to the pivot
// points Psi0 = 0, pi, where G is a sum of terms as small as the target's distance
struct StartAngle {
    double s = 0, c = 1, oneMinusC = 0, onePlusC = 2;
};
StartAngle startAngle(double psi0) {
    const double h = std::sin(0.5 * psi0), g = std::cos(0.5 * psi0);
    return {2 * h * g, (g - h) * (g + h), 2 * h * h, 2 * g * g};
}

// c1^2 - 1 = (c1 - 1)(c1 + 1), c1 = cos Psi0 + shift: no cancellation where c1 = +-1
double curveG(const StartAngle& a, double lambda, const UnitTarget& tg) {
    const double s1 = a.s * std::cos(tg.Phi) + lambda * std::sin(tg.Phi);
    const double shift = tg.Y * a.s - tg.X * lambda;
    return s1 * s1 + (shift - a.oneMinusC) * (shift + a.onePlusC);
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
int pairedPassage(const StartPoint& a, const StartPoint& b, int n) {
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
// at its rounding (1e-15 times the size of its terms: next to the pivot points they are as small
// as the target's distance)
std::optional<std::pair<double, double>> projectOnCurve(double psi0, double lambda0,
                                                        const UnitTarget& tg) {
    const double cP = std::cos(tg.Phi), sP = std::sin(tg.Phi);
    double G = 1, rounding = 0;
    for (int i = 0; i < 20; ++i) {
        const StartAngle a = startAngle(psi0);
        const double s0 = a.s, c0 = a.c;
        const double s1 = s0 * cP + lambda0 * sP, c1 = c0 + tg.Y * s0 - tg.X * lambda0;
        const double shift = tg.Y * s0 - tg.X * lambda0;
        G = s1 * s1 + (shift - a.oneMinusC) * (shift + a.onePlusC);
        const double size = std::fabs(tg.Y * s0) + std::fabs(tg.X * lambda0);
        rounding = 1e-15 * (s1 * s1 + (size + a.oneMinusC) * (size + a.onePlusC)) *
                   (1 + std::fabs(lambda0));
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
int roughness(const StartPoint& a, const StartPoint& b, const UnitTarget& tg) {
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

} // namespace

// (-pi, pi]
double wrapAngle(double a) {
    double r = std::remainder(a, 2 * pi);
    return r <= -pi ? r + 2 * pi : r;
}

StartPoint startPoint(double psi0, double lambda0, const UnitTarget& tg) {
    StartPoint cp;
    cp.psi0 = psi0;
    cp.lambda0 = lambda0;
    const double s0 = std::sin(psi0), c0 = std::cos(psi0);
    const double k2 = s0 * s0 + lambda0 * lambda0;
    // the separatrix level and pivoting are found by Newton from their neighbours
    if (k2 == 1 || k2 < 1e-40)
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

// Newton's start from a piece: halve it (its middle put back on the curve) while the passage
// continues, then interpolate. Done only for the pieces Newton is run from.
UnitSolution refineSeed(SeedPiece piece, const UnitTarget& tg) {
    StartPoint a = piece.a, b = piece.b;
    int n = piece.n, m = piece.m;
    for (int i = 0; i < 60; ++i) {
        const double ga = a.along + n * a.drift;
        if (ga == 0 ||
            std::fabs(wrapAngle(b.psi0 - a.psi0)) + std::fabs(b.lambda0 - a.lambda0) < 1e-10)
            break;
        const auto onCurve = projectOnCurve(a.psi0 + 0.5 * wrapAngle(b.psi0 - a.psi0),
                                            0.5 * (a.lambda0 + b.lambda0), tg);
        if (!onCurve)
            break;
        const StartPoint mid = startPoint(wrapAngle(onCurve->first), onCurve->second, tg);
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

namespace {

// The curve G = 0 traced cell by cell on the grid of nodes psi x lam (psi periodic over 2 pi, or
// a patch), its seeds appended to `seeds`.
void traceGrid(const UnitTarget& tg, double tMax, const std::vector<double>& psi, bool periodic,
               const std::vector<double>& lam, std::vector<SeedPiece>& seeds, int& budget) {
    const int columns = static_cast<int>(psi.size()), rows = static_cast<int>(lam.size()) - 1;
    const int lastColumn = periodic ? columns : columns - 1; // cells and horizontal edges
    std::vector<StartAngle> angle(columns);
    for (int i = 0; i < columns; ++i)
        angle[i] = startAngle(psi[i]);
    std::vector<double> G((rows + 1) * columns);
    auto node = [&](int i, int j) -> double& { return G[j * columns + i]; };
    for (int j = 0; j <= rows; ++j)
        for (int i = 0; i < columns; ++i)
            node(i, j) = curveG(angle[i], lam[j], tg);

    std::vector<StartPoint> points;
    std::vector<int> horizontal((rows + 1) * columns, -1), vertical(rows * columns, -1);
    for (int j = 0; j <= rows; ++j)
        for (int i = 0; i < lastColumn; ++i) {
            const int i1 = (i + 1) % columns;
            const double g0 = node(i, j), g1 = node(i1, j);
            if ((g0 > 0) == (g1 > 0))
                continue;
            const double l = lam[j];
            auto along = [&](double p) { return curveG(startAngle(p), l, tg); };
            const double p = edgeRoot(along, psi[i], g0, psi[i] + wrapAngle(psi[i1] - psi[i]), g1);
            horizontal[j * columns + i] = static_cast<int>(points.size());
            points.push_back(startPoint(wrapAngle(p), l, tg));
        }
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            const double g0 = node(i, j), g1 = node(i, j + 1);
            if ((g0 > 0) == (g1 > 0))
                continue;
            auto along = [&](double l) { return curveG(angle[i], l, tg); };
            const double l = edgeRoot(along, lam[j], g0, lam[j + 1], g1);
            vertical[j * columns + i] = static_cast<int>(points.size());
            points.push_back(startPoint(psi[i], l, tg));
        }

    auto link = [&](const StartPoint& a, const StartPoint& b) {
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
    // middle put back on the curve, down to 2^-48 of a cell at a change of orbit and 2^-5 where
    // the passage only moves a lot
    auto follow = [&](auto&& self, const StartPoint& a, const StartPoint& b, int depth) -> void {
        const int rough = roughness(a, b, tg);
        if (((rough == 2 && depth < 48) || (rough == 1 && depth < 5)) && --budget > 0) {
            const double psiM = a.psi0 + 0.5 * wrapAngle(b.psi0 - a.psi0);
            const double lamM = 0.5 * (a.lambda0 + b.lambda0);
            const auto onCurve = projectOnCurve(psiM, lamM, tg);
            if (onCurve) {
                const StartPoint m = startPoint(wrapAngle(onCurve->first), onCurve->second, tg);
                self(self, a, m, depth + 1);
                self(self, m, b, depth + 1);
                return;
            }
        }
        if (a.valid && b.valid)
            link(a, b);
    };
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < lastColumn; ++i) {
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
}

} // namespace

std::vector<SeedPiece> curveSeeds(const UnitTarget& tg, double tMax, double kMax, GridSize size) {
    const int columns = size.columns;
    const double uMax = std::asinh(kMax * 1.02);
    const int rows = std::max(8, static_cast<int>(std::ceil(2 * uMax / size.du)));
    const double dpsi = 2 * pi / columns, duRow = 2 * uMax / rows;
    std::vector<double> psi(columns), lam(rows + 1);
    for (int i = 0; i < columns; ++i)
        psi[i] = -pi + (i + 0.3719) * dpsi; // off the axes, where lines and pivots sit
    for (int j = 0; j <= rows; ++j)
        lam[j] = std::sinh(-uMax + (j + 0.2113) * duRow);
    std::vector<SeedPiece> seeds;
    int budget = 20000; // halvings, a bound on the time a pathological target can take
    traceGrid(tg, tMax, psi, true, lam, seeds, budget);
    // next to the start's position the curve has a loop about the size of the distance around
    // each pivot point (0, 0) and (pi, 0), finer than the grid: a patch twenty times as wide
    const double d = std::hypot(tg.X, tg.Y);
    if (d < 0.05) {
        constexpr int patch = 24;
        for (const double h : {20 * d, 3 * d})
            for (const double centre : {0.0, pi}) {
                std::vector<double> p(patch + 1), l(patch + 1);
                for (int i = 0; i <= patch; ++i) {
                    p[i] = wrapAngle(centre - h + (i + 0.3719) * 2 * h / patch);
                    l[i] = -h + (i + 0.2113) * 2 * h / patch;
                }
                traceGrid(tg, tMax, p, false, l, seeds, budget);
            }
    }
    std::sort(seeds.begin(), seeds.end(),
              [](const SeedPiece& a, const SeedPiece& b) { return a.t < b.t; });
    return seeds;
}

} // namespace chaplygin
