#pragma once
// A Newton iteration kept inside a bracket, bisecting when a Newton point would leave it: the one
// root finder of the time law, the path table, the cusp search and the quadrature time law.
// Header-only, so that the hot callers (the time law's inversion, docs/numerics.md §7) inline it.
#include <cmath>

namespace chaplygin {

/// How small a step, or the bracket's width, has to be: at most `value`, or with `relativeToX`
/// at most value * (|x| + scale). A negative value switches the test off.
struct NewtonTolerance {
    double value = -1;
    bool relativeToX = false;
    double scale = 0;

    /// |d| is small at x (false while the test is off).
    bool holds(double d, double x) const {
        return value >= 0 && std::fabs(d) <= (relativeToX ? value * (std::fabs(x) + scale) : value);
    }
};

/// The caps of one caller's iteration. The callers' stopping rules differ, and each keeps its own.
struct NewtonCaps {
    int maxIterations = 0;
    /// Converged when the Newton step f/f' is this small; the result is then x - f/f', even where
    /// that is a little outside the bracket.
    NewtonTolerance newtonStep{};
    /// Converged when the step taken, Newton or bisection, is this small relative to the point
    /// it reached; the result is that point.
    NewtonTolerance takenStep{};
    /// Stop when the bracket has shrunk to this width (relative to the point evaluated last); the
    /// result is the point just reached.
    NewtonTolerance bracket{};
    /// A Newton point on an end of the bracket is taken; otherwise only one strictly inside.
    bool closedBracket = false;
    /// f(x) == 0 ends the iteration at x before anything else.
    bool stopAtRoot = false;
};

/// f and f' at one point, as the function given to safeguardedNewton returns them.
struct NewtonValue {
    double f = 0, df = 0;
};

/// [lo, hi] with f(lo) < 0 < f(hi): f increases through its root.
struct NewtonBracket {
    double lo = 0, hi = 0;
};

/// What ended the iteration: one of the caps' tests, f(x) == 0, a step that left x where it was,
/// or the iteration cap.
enum class NewtonEnd { NewtonStep, TakenStep, Bracket, Root, Stalled, IterationCap };

struct NewtonResult {
    double x = 0;
    int evaluations = 0; ///< calls of f, one per iteration
    NewtonEnd end = NewtonEnd::IterationCap;
};

/// Solves f(x) = 0 from x by Newton steps x - f/f'; after each evaluation the bracket's end on
/// f's side of zero moves to x, and a Newton point outside the bracket is replaced by its
/// midpoint. Ends on the first of the caps' tests that holds, on a step that leaves x where it
/// was (the bracket has shrunk to rounding) or after caps.maxIterations evaluations.
template <class F>
inline NewtonResult safeguardedNewton(F&& f, double x, NewtonBracket bracket,
                                      const NewtonCaps& caps) {
    double lo = bracket.lo, hi = bracket.hi;
    for (int iter = 1; iter <= caps.maxIterations; ++iter) {
        const NewtonValue v = f(x);
        if (caps.stopAtRoot && v.f == 0)
            return {x, iter, NewtonEnd::Root};
        (v.f > 0 ? hi : lo) = x;
        const double step = v.f / v.df;
        if (caps.newtonStep.holds(step, x))
            return {x - step, iter, NewtonEnd::NewtonStep};
        double next = x - step;
        const bool inside = caps.closedBracket ? next >= lo && next <= hi : next > lo && next < hi;
        if (!inside)
            next = 0.5 * (lo + hi);
        const double from = x;
        x = next;
        if (x == from)
            return {x, iter, NewtonEnd::Stalled};
        if (caps.takenStep.holds(x - from, x))
            return {x, iter, NewtonEnd::TakenStep};
        if (caps.bracket.holds(hi - lo, from))
            return {x, iter, NewtonEnd::Bracket};
    }
    return {x, caps.maxIterations, NewtonEnd::IterationCap};
}

} // namespace chaplygin
