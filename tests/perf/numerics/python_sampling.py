#!/usr/bin/python3
"""The chaplygin_lab module's sample() against scipy's DOP853 on the catenary preset
(docs/numerics.md §8). Not a ctest test: it times, and the machine is shared.

1. States per second: Solution.sample over 10^6 evenly spaced times on [0, t_end], every column
   (the controlled, free and vakonomic bodies, 27 float64 arrays) and the controlled body's 18
   columns alone, on one thread and on every core; wall time (time.perf_counter) and the
   process's CPU time, best of REPEATS.
2. The same scene to the same error: the controlled catenary's time law
   ds/dt = v_T/sqrt(1 + b^2 kappa(s)^2), kappa = -x0/(s^2 + x0^2) (docs/physics.md §7), with P from
   the catenary's closed form x = sqrt(s^2 + x0^2), y = x0 asinh(s/x0). The truth at 1000 times:
   for the s that a solver gives at t, its exact time t(s) = integral of sqrt(1 + b^2 kappa^2)/v_T
   ds by mpmath at 30 digits, so the position error is |P - P(s)| + |sdot| |t(s) - t|. DOP853 runs
   at the loosest tolerance of 1e-10, 1e-11, ... that reaches the module's error (or its tightest,
   1e-13), and is timed solving and evaluating its dense output at the same 10^6 times.

Usage: PYTHONPATH=build/release/app/python /usr/bin/python3 tests/perf/numerics/python_sampling.py"""
import math
import os
import time

import mpmath
import numpy as np
from scipy.integrate import solve_ivp

import chaplygin_lab as cl

A, B, VT, X0 = 0.5, 1.0, 1.0, 1.0
COUNT = 10**6
REPEATS = 3
CONTROLLED = ["t", "s", "x", "y", "phi", "psi", "chi", "lambda", "energy", "sdot", "phidot",
              "psidot", "force_axial", "force_lateral", "control_couple"]


def best(run):
    """(wall, cpu) of the fastest of REPEATS runs."""
    times = []
    for _ in range(REPEATS):
        w, c = time.perf_counter(), time.process_time()
        run()
        times.append((time.perf_counter() - w, time.process_time() - c))
    return min(times)


def rhs(t, y):
    kappa = -X0 / (y[0] * y[0] + X0 * X0)
    return [VT / math.sqrt(1.0 + (B * kappa) ** 2)]


def dop853(tol, t_end):
    return solve_ivp(rhs, (0.0, t_end), [0.0], method="DOP853", rtol=tol, atol=tol,
                     dense_output=True)


def position(s):
    return np.sqrt(s * s + X0 * X0), X0 * np.arcsinh(s / X0)


def exact_time(s):
    mpmath.mp.dps = 30
    return float(mpmath.quad(lambda u: mpmath.sqrt(1 + (B * X0 / (u * u + X0 * X0)) ** 2) / VT,
                             [0, s]))


def error_of(t, s, x, y):
    """max over the times of |P - P(s)| + |sdot| |t(s) - t| [m]."""
    xs, ys = position(s)
    kappa = -X0 / (s * s + X0 * X0)
    sdot = VT / np.sqrt(1.0 + (B * kappa) ** 2)
    lag = np.abs(np.array([exact_time(v) for v in s]) - t)
    return float(np.max(np.hypot(x - xs, y - ys) + sdot * lag))


def main():
    solution = cl.Scene.preset("catenary").solve()
    t_end = solution.t_end
    t = np.linspace(0.0, t_end, COUNT)
    cores = os.cpu_count()
    print(f"load average {os.getloadavg()[0]:.1f} on {cores} cores; {COUNT} times on "
          f"[0, {t_end:.6f}] s")
    for label, columns in (("every column (27)", None), ("controlled body (15)", CONTROLLED)):
        for threads in (1, None):
            wall, cpu = best(lambda: solution.sample(t, columns=columns, threads=threads))
            print(f"sample, {label}, threads={threads or cores}: wall {wall:.3f} s "
                  f"({COUNT / wall:.3g} states/s), CPU {cpu:.3f} s ({COUNT / cpu:.3g} states/s "
                  f"of CPU)")

    check = np.linspace(0.0, t_end, 1000)
    ours = solution.sample(check, columns=["s", "x", "y"])
    error = error_of(check, ours["s"], ours["x"], ours["y"])
    print(f"module error: {error:.2e} m")
    for tol in (1e-10, 1e-11, 1e-12, 1e-13):
        r = dop853(tol, t_end)
        s = r.sol(check)[0]
        dop_error = error_of(check, s, *position(s))
        print(f"DOP853 at {tol:g}: error {dop_error:.2e} m, {r.nfev} RHS calls")
        if dop_error <= error:
            break

    def scipy_states():
        r = dop853(tol, t_end)
        position(r.sol(t)[0])

    wall, cpu = best(scipy_states)
    ours_wall, ours_cpu = best(lambda: solution.sample(t, columns=["x", "y"], threads=1))
    print(f"DOP853 at {tol:g} (error {dop_error:.2e} m, {r.nfev} RHS calls): solve and "
          f"{COUNT} dense outputs, P only: wall {wall:.3f} s, CPU {cpu:.3f} s")
    print(f"module, x and y only, one thread: wall {ours_wall:.3f} s, CPU {ours_cpu:.3f} s; "
          f"DOP853/module {wall / ours_wall:.1f}x wall, {cpu / ours_cpu:.1f}x CPU")


if __name__ == "__main__":
    main()
