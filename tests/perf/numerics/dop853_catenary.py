#!/usr/bin/python3
"""DOP853 (scipy.integrate.solve_ivp) on the catenary preset, for comparison with the method
registry (docs/numerics.md §5): the controlled time law ds/dt = v_T/sqrt(1 + b^2 kappa(s)^2) with
kappa = -x0/(s^2 + x0^2) (docs/physics.md §7, erratum to paper (99)), s in [0, 5], and the free sleigh,
eqs. (D12)-(D13), from the catenary's initial state over [0, 10]. Both at rtol = atol = 1e-10,
100 evenly spaced outputs from DOP853's own dense output. Prints the median wall time of one
solve, its RHS count and its error against DOP853 at 1e-13."""
import math
import statistics
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


def main():
    sdot0 = VT / math.sqrt(2.0)
    cases = {
        "controlled": (duration(), [0.0]),
        "free": (10.0, [X0, 0.0, math.pi / 2, sdot0, -sdot0]),
    }
    for problem, (t_end, y0) in cases.items():
        xr, yr, _ = solve(problem, 1e-13, t_end, y0)
        samples = []
        for _ in range(21):
            start = time.perf_counter()
            x, y, nfev = solve(problem, 1e-10, t_end, y0)
            samples.append(time.perf_counter() - start)
        err = float(np.max(np.hypot(x - xr, y - yr)))
        print(f"{problem},DOP853,1e-10,{err:.3e},{statistics.median(samples):.6e},{nfev},t_end={t_end:.6f}")


if __name__ == "__main__":
    main()
