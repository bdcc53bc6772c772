#!/usr/bin/python3
"""DOP853 (scipy.integrate.solve_ivp) on the catenary preset, for comparison with the method
registry (docs/numerics.md §5): the controlled time law ds/dt = v_T/sqrt(1 + b^2 kappa(s)^2) with
kappa = -x0/(s^2 + x0^2) (docs/physics.md §7, erratum to paper (99)), s in [0, 5], and the free sleigh,
paper (D12)-(D13), from the catenary's initial state over [0, 10]. Both at rtol = atol = 1e-10,
100 evenly spaced outputs from DOP853's own dense output. Prints the median wall time of one
solve (over at least 21 solves and 1.2 s, half before and half after the app's benchmark), its
RHS count and its error against DOP853 at 1e-13.

With the path of chaplygin-bench-numerics as argument it also runs the app's chosen methods
(BM_Solve/controlled/quadrature_gauss_newton and BM_Solve/free/closed_form, 100 outputs, median
wall time of 5 repetitions) in the same run, interleaved with the DOP853 timings, and prints the
ratios DOP853/app. Usage: dop853_catenary.py [build/release/tests/perf/numerics/chaplygin-bench-numerics]"""
import json
import math
import statistics
import subprocess
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp

A, B, VT, X0 = 0.5, 1.0, 1.0, 1.0


def controlled_rhs(t, y):
    kappa = -X0 / (y[0] * y[0] + X0 * X0)
    return [VT / math.sqrt(1.0 + (B * kappa) ** 2)]


def free_rhs(t, y):
    _, _, phi, sdot, phidot = y
    return [sdot * math.cos(phi), sdot * math.sin(phi), phidot, A * phidot * phidot,
            -A * sdot * phidot / (B * B)]


def catenary_xy(s):
    return np.sqrt(s * s + X0 * X0), X0 * np.arcsinh(s / X0)


def duration():
    # t(5) = integral of sqrt(1 + b^2 kappa^2)/v_T ds, by DOP853 at 1e-13 on dt/ds
    r = solve_ivp(lambda s, t: [math.sqrt(1.0 + (B * X0 / (s * s + X0 * X0)) ** 2) / VT],
                  (0.0, 5.0), [0.0], method="DOP853", rtol=1e-13, atol=1e-13)
    return r.y[0, -1]


def solve(problem, tol, t_end, y0):
    times = np.linspace(0.0, t_end, 100)
    rhs = controlled_rhs if problem == "controlled" else free_rhs
    r = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=tol, atol=tol, t_eval=times)
    if problem == "controlled":
        x, y = catenary_xy(r.y[0])
    else:
        x, y = r.y[0], r.y[1]
    return x, y, r.nfev


def app_medians(bench):
    """Median wall time [s] of the app's two chosen solves, from Google Benchmark's JSON."""
    out = subprocess.run([bench, "--benchmark_filter=BM_Solve/(controlled/quadrature_gauss_newton|free/closed_form)$",
                          "--benchmark_repetitions=5", "--benchmark_min_time=0.2",
                          "--benchmark_format=json"], check=True, capture_output=True, text=True).stdout
    medians = {}
    for b in json.loads(out)["benchmarks"]:
        if b.get("aggregate_name") == "median":
            problem = "controlled" if "/controlled/" in b["run_name"] else "free"
            scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]
            medians[problem] = b["real_time"] * scale
    return medians


def main():
    bench = sys.argv[1] if len(sys.argv) > 1 else None
    sdot0 = VT / math.sqrt(2.0)
    cases = {
        "controlled": (duration(), [0.0]),
        "free": (10.0, [X0, 0.0, math.pi / 2, sdot0, -sdot0]),
    }
    dop = {}
    app = []
    for problem, (t_end, y0) in cases.items():
        xr, yr, _ = solve(problem, 1e-13, t_end, y0)
        samples = []

        def sample_for(seconds):
            # as long as the app's benchmark runs, so that both medians see the same machine
            stop = time.perf_counter() + seconds
            while len(samples) < 21 or time.perf_counter() < stop:
                start = time.perf_counter()
                result = solve(problem, 1e-10, t_end, y0)
                samples.append(time.perf_counter() - start)
            return result

        x, y, nfev = sample_for(0.6)
        if bench:
            app.append(app_medians(bench))  # interleaved: the same load on the machine
            x, y, nfev = sample_for(0.6)
        err = float(np.max(np.hypot(x - xr, y - yr)))
        dop[problem] = statistics.median(samples)
        print(f"{problem},DOP853,1e-10,{err:.3e},{dop[problem]:.6e},{nfev},t_end={t_end:.6f}")
    if bench:
        for problem in cases:
            seconds = statistics.median(a[problem] for a in app)
            print(f"{problem},app_chosen,-,-,{seconds:.6e},0,DOP853/app={dop[problem] / seconds:.0f}x")


if __name__ == "__main__":
    main()
