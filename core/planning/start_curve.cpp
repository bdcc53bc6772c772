#include "planning/start_curve.h"

#include "planning/unit_geodesic.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

// the passage of b that continues the first of a, nearest in time within half a period: the n-th
// passage of a continues as the (n + shift)-th of b, the count following the first passage (next
// to the separatrix the periods of neighbouring points differ by much, and the passages nearest in
// time are not the same passage); nullopt where the first passage has no continuation
std::optional<int> passageShift(const StartPoint& a, const StartPoint& b) {
    const double half = 0.5 * std::min(a.period, b.period);
    for (const int n : {0, 1})
        for (const int m : {n - 1, n, n + 1})
            if (m >= 0 && std::fabs(b.t + m * b.period - a.t - n * a.period) < half)
                return m - n;
    return std::nullopt;
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
    const auto shift = passageShift(a, b);
    if (!shift)
        return 2;
    const int m = std::max(0, *shift);
    const double gap = std::fabs(b.t + m * b.period - a.t - (m - *shift) * a.period);
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
        const auto shift = passageShift(a, mid);
        if (!shift || n + *shift < 0)
            break;
        const int j = n + *shift;
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

// Links neighbouring points of the curve G = 0 into seeds: a piece whose ends disagree (the first
// passage jumps, the pendulum changes from libration to rotation, or an end has no passage) is
// halved, its middle put back on the curve, down to 2^-48 of its length at a change of orbit and
// 2^-5 where the passage only moves a lot or the piece is longer than `steep` in asinh Lambda0.
struct CurveTracer {
    const UnitTarget& tg;
    double tMax;
    double steep;
    std::vector<SeedPiece>& seeds;
    int& budget;

    void link(const StartPoint& a, const StartPoint& b) const {
        const auto shift = passageShift(a, b);
        if (!shift)
            return;
        const double jump = 0.5 * std::min(a.period, b.period);
        for (int n = std::max(0, -*shift);; ++n) {
            const double ta = a.t + n * a.period, tb = b.t + (n + *shift) * b.period;
            if (std::min(ta, tb) > tMax + jump)
                break;
            const int best = n + *shift;
            const double ga = a.along + n * a.drift, gb = b.along + best * b.drift;
            if ((ga > 0) == (gb > 0) && ga != 0)
                continue;
            const double f = ga == gb ? 0.5 : ga / (ga - gb);
            seeds.push_back({a, n, b, best, ta + f * (tb - ta)});
        }
    }

    void follow(const StartPoint& a, const StartPoint& b, int depth = 0) {
        const int rough = roughness(a, b, tg);
        const bool tooLong = std::fabs(std::asinh(a.lambda0) - std::asinh(b.lambda0)) > steep;
        if (((rough == 2 && depth < 48) || ((rough == 1 || tooLong) && depth < 5)) &&
            --budget > 0) {
            const double psiM = a.psi0 + 0.5 * wrapAngle(b.psi0 - a.psi0);
            const double lamM = 0.5 * (a.lambda0 + b.lambda0);
            const auto onCurve = projectOnCurve(psiM, lamM, tg);
            if (onCurve) {
                const StartPoint m = startPoint(wrapAngle(onCurve->first), onCurve->second, tg);
                follow(a, m, depth + 1);
                follow(m, b, depth + 1);
                return;
            }
        }
        if (a.valid && b.valid)
            link(a, b);
    }
};

// The curve G = 0 traced cell by cell on the grid of nodes psi x lam (psi periodic over 2 pi, or
// a patch), its seeds appended to the tracer's.
void traceGrid(CurveTracer& tracer, const std::vector<double>& psi, bool periodic,
               const std::vector<double>& lam) {
    const UnitTarget& tg = tracer.tg;
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
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < lastColumn; ++i) {
            const int i1 = (i + 1) % columns;
            int ids[4], count = 0;
            for (int id : {horizontal[j * columns + i], vertical[j * columns + i1],
                           horizontal[(j + 1) * columns + i], vertical[j * columns + i]})
                if (id >= 0)
                    ids[count++] = id;
            if (count == 2) {
                tracer.follow(points[ids[0]], points[ids[1]]);
            } else if (count == 4) { // a saddle of G: either pairing
                for (int a = 0; a < 4; ++a)
                    tracer.follow(points[ids[a]], points[ids[(a + 1) % 4]]);
            }
        }
}

// G = A Lambda0^2 + B Lambda0 + C at a fixed Psi0 (docs/physics.md §10), its coefficients
// without cancellation next to the pivot points
struct CurveColumn {
    double A = 0, B = 0, C = 0;
    double discriminant() const { return B * B - 4 * A * C; }
};
CurveColumn curveColumn(const StartAngle& a, const UnitTarget& tg) {
    const double cP = std::cos(tg.Phi), sP = std::sin(tg.Phi);
    const double u = tg.Y * a.s - a.oneMinusC, w = tg.Y * a.s + a.onePlusC;
    return {sP * sP + tg.X * tg.X, 2 * (a.s * cP * sP - tg.X * (tg.Y * a.s + a.c)),
            a.s * a.s * cP * cP + u * w};
}

// the curve's points over one Psi0, lowest Lambda0 first: G's real roots in Lambda0
std::vector<double> columnRoots(const CurveColumn& q) {
    if (q.A == 0)
        return q.B == 0 ? std::vector<double>{} : std::vector<double>{-q.C / q.B};
    const double disc = q.discriminant();
    if (disc < 0)
        return {};
    const double h = -0.5 * (q.B + std::copysign(std::sqrt(disc), q.B));
    if (h == 0)
        return {0.0, 0.0};
    const double r0 = h / q.A, r1 = q.C / h;
    return {std::min(r0, r1), std::max(r0, r1)};
}

// The curve G = 0 traced column by column over Psi0 in (-pi, pi]: G is quadratic in Lambda0, so
// each column holds the curve's points exactly, two branches that a grid in Lambda0 misses where
// they run closer than its rows (about the crossings of the curve, where the pendulum's end state
// mirrors its start). Neighbouring columns' points are linked lowest to lowest and highest to
// highest; where the branches meet between two columns (G's discriminant in Lambda0 changes
// sign), through the fold.
void traceColumns(CurveTracer& tracer, int columns, double lambdaMax) {
    const UnitTarget& tg = tracer.tg;
    const double dpsi = 2 * pi / columns;
    std::vector<double> psi(columns);
    std::vector<CurveColumn> column(columns);
    std::vector<std::vector<StartPoint>> points(columns);
    std::vector<std::vector<bool>> evaluated(columns);
    for (int i = 0; i < columns; ++i) {
        psi[i] = -pi + (i + 0.3719) * dpsi; // off the axes, where lines and pivots sit
        column[i] = curveColumn(startAngle(psi[i]), tg);
        for (const double l : columnRoots(column[i])) {
            StartPoint p; // its passages only once a piece within the k bound needs them
            p.psi0 = psi[i];
            p.lambda0 = l;
            points[i].push_back(p);
            evaluated[i].push_back(false);
        }
    }
    const auto point = [&](int i, std::size_t r) -> const StartPoint& {
        if (!evaluated[i][r]) {
            points[i][r] = startPoint(psi[i], points[i][r].lambda0, tg);
            evaluated[i][r] = true;
        }
        return points[i][r];
    };
    // a piece with both ends beyond the k bound is left out
    const auto follow = [&](int i, std::size_t r, const StartPoint* fold, int i1, std::size_t r1) {
        const double la = points[i][r].lambda0;
        const double lb = fold ? fold->lambda0 : points[i1][r1].lambda0;
        if (std::fabs(la) > lambdaMax && std::fabs(lb) > lambdaMax)
            return;
        const StartPoint& a = point(i, r);
        tracer.follow(a, fold ? *fold : point(i1, r1));
    };
    for (int i = 0; i < columns; ++i) {
        const int i1 = (i + 1) % columns;
        const std::size_t n0 = points[i].size(), n1 = points[i1].size();
        if (n0 == n1) {
            for (std::size_t r = 0; r < n0; ++r)
                follow(i, r, nullptr, i1, r);
        } else if ((n0 == 2 && n1 == 0) || (n0 == 0 && n1 == 2)) {
            // the fold, where the discriminant vanishes between the columns
            const double a = psi[i], b = a + dpsi;
            auto disc = [&](double p) { return curveColumn(startAngle(p), tg).discriminant(); };
            const double f =
                edgeRoot(disc, a, column[i].discriminant(), b, column[i1].discriminant());
            const CurveColumn q = curveColumn(startAngle(f), tg);
            const StartPoint fold = startPoint(wrapAngle(f), -q.B / (2 * q.A), tg);
            const int side = n0 == 0 ? i1 : i;
            follow(side, 0, &fold, 0, 0);
            follow(side, 1, &fold, 0, 0);
        } else {
            for (std::size_t r = 0; r < n0; ++r)
                for (std::size_t r1 = 0; r1 < n1; ++r1)
                    follow(i, r, nullptr, i1, r1);
        }
    }
}

} // namespace

std::vector<SeedPiece> curveSeeds(const UnitTarget& tg, double tMax, double kMax, GridSize size) {
    std::vector<SeedPiece> seeds;
    int budget = 20000; // halvings, a bound on the time a pathological target can take
    CurveTracer tracer{tg, tMax, size.du, seeds, budget};
    traceColumns(tracer, size.columns, kMax * 1.02);
    // G's Lambda0^2 and Lambda0 terms vanish for a target straight across from the start with
    // Phi = 0 or pi (X = 0, sin Phi = 0): the curve then runs along Lambda0, and next to such a
    // target it turns steeply; a grid in (Psi0, asinh Lambda0) follows it there as well
    if (std::pow(std::sin(tg.Phi), 2) + tg.X * tg.X < 1e-2) {
        CurveTracer gridTracer{tg, tMax, std::numeric_limits<double>::infinity(), seeds, budget};
        const double uMax = std::asinh(kMax * 1.02);
        const int rows = std::max(8, static_cast<int>(std::ceil(2 * uMax / size.du)));
        const double dpsi = 2 * pi / size.columns, duRow = 2 * uMax / rows;
        std::vector<double> psi(size.columns), lam(rows + 1);
        for (int i = 0; i < size.columns; ++i)
            psi[i] = -pi + (i + 0.3719) * dpsi;
        for (int j = 0; j <= rows; ++j)
            lam[j] = std::sinh(-uMax + (j + 0.2113) * duRow);
        traceGrid(gridTracer, psi, true, lam);
    }
    // next to the start's position the curve has a loop about the size of the distance around
    // each pivot point (0, 0) and (pi, 0), finer than the columns: a patch twenty times as wide
    const double d = std::hypot(tg.X, tg.Y);
    if (d < 0.05) {
        CurveTracer patchTracer{tg, tMax, std::numeric_limits<double>::infinity(), seeds, budget};
        constexpr int patch = 24;
        for (const double h : {20 * d, 3 * d})
            for (const double centre : {0.0, pi}) {
                std::vector<double> p(patch + 1), l(patch + 1);
                for (int i = 0; i <= patch; ++i) {
                    p[i] = wrapAngle(centre - h + (i + 0.3719) * 2 * h / patch);
                    l[i] = -h + (i + 0.2113) * 2 * h / patch;
                }
                traceGrid(patchTracer, p, false, l);
            }
    }
    std::sort(seeds.begin(), seeds.end(),
              [](const SeedPiece& a, const SeedPiece& b) { return a.t < b.t; });
    return seeds;
}

} // namespace chaplygin
