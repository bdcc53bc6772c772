#!/usr/bin/env python3
"""Independent reference for `--preset sinusoid --sweep b=0.6:2.4:8 --csv -`.

The sinusoid y = -sin(x), x in [0, 4 pi] (paper (108)-(113)), sleigh m = 1, a = 0.5, v_T = 1.
Duration: the time law, paper (112), t = int sqrt(1 + b^2 kappa^2) ds / v_T, integrated with
mpmath's tanh-sinh quadrature at 30 digits in x (ds = sqrt(1 + y'^2) dx).
max |lambda|: lambda = m (b Psidot - a phidot) (docs/physics.md §2) with sdot =
v_T / sqrt(1 + b^2 kappa^2), phidot = kappa sdot, Psidot = -b kappa_s sdot / (1 + b^2 kappa^2);
kappa and kappa_s from sympy's exact derivatives; a 20001-point grid in x, then golden-section
refinement of every local maximum of the grid.
Usage: sweep_reference.py CHAPLYGIN_LAB
"""
import csv
import io
import subprocess
import sys

import mpmath as mp
import sympy as sp

mp.mp.dps = 30
M, A, VT = 1.0, 0.5, 1.0
X0, X1 = 0.0, 4 * mp.pi

x = sp.symbols("x")
y = -sp.sin(x)
yp, ypp = sp.diff(y, x), sp.diff(y, x, 2)
kappa = ypp / (1 + yp**2) ** sp.Rational(3, 2)
speed = sp.sqrt(1 + yp**2)  # ds/dx
kappa_s = sp.diff(kappa, x) / speed
f_kappa = sp.lambdify(x, kappa, "mpmath")
f_kappa_s = sp.lambdify(x, kappa_s, "mpmath")
f_speed = sp.lambdify(x, speed, "mpmath")
g_kappa = sp.lambdify(x, kappa, "math")
g_kappa_s = sp.lambdify(x, kappa_s, "math")


def duration(b):
    integrand = lambda u: mp.sqrt(1 + (b * f_kappa(u)) ** 2) * f_speed(u) / VT
    # split where the curvature changes sign and at its extremes
    knots = [k * mp.pi / 2 for k in range(9)]
    return mp.quad(integrand, knots)


def lam(b, u, kap, kap_s):
    k, ks = kap(u), kap_s(u)
    root2 = 1 + (b * k) ** 2
    sdot = VT / (root2 ** 0.5 if isinstance(root2, float) else mp.sqrt(root2))
    psidot = -b * ks * sdot / root2
    return abs(M * (b * psidot - A * k * sdot))


def max_abs_lambda(b):
    n = 20001
    xs = [float(X1) * i / (n - 1) for i in range(n)]
    vs = [lam(b, u, g_kappa, g_kappa_s) for u in xs]
    best = max(vs)
    g = (mp.sqrt(5) - 1) / 2
    for i in range(n):
        left = vs[i - 1] if i > 0 else -1
        right = vs[i + 1] if i + 1 < n else -1
        if not (vs[i] >= left and vs[i] >= right and vs[i] > 0.5 * best):
            continue
        lo, hi = mp.mpf(xs[max(i - 1, 0)]), mp.mpf(xs[min(i + 1, n - 1)])
        f = lambda u: lam(b, u, f_kappa, f_kappa_s)
        c, d = hi - g * (hi - lo), lo + g * (hi - lo)
        fc, fd = f(c), f(d)
        for _ in range(120):
            if fc >= fd:
                hi, d, fd = d, c, fc
                c = hi - g * (hi - lo)
                fc = f(c)
            else:
                lo, c, fc = c, d, fd
                d = lo + g * (hi - lo)
                fd = f(d)
        best = max(best, float(max(fc, fd, f(lo), f(hi))))
    return best


def main():
    exe = sys.argv[1]
    out = subprocess.run([exe, "--headless", "--preset", "sinusoid", "--sweep", "b=0.6:2.4:8",
                          "--csv", "-"], capture_output=True, text=True, check=True).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    assert len(rows) == 8, f"expected 8 rows, got {len(rows)}"
    assert list(rows[0].keys())[:5] == ["b", "duration", "max_abs_lambda",
                                        "max_abs_control_couple", "max_abs_force_lateral"], rows[0]
    worst_t = worst_l = 0.0
    for i, row in enumerate(rows):
        b = 0.6 + (2.4 - 0.6) * i / 7
        assert abs(float(row["b"]) - b) < 1e-12, row
        t_ref = float(duration(b))
        l_ref = max_abs_lambda(b)
        et = abs(float(row["duration"]) - t_ref) / t_ref
        el = abs(float(row["max_abs_lambda"]) - l_ref) / l_ref
        print(f"b={b:.4f} duration {row['duration']} ref {t_ref:.15g} rel {et:.1e}; "
              f"max|lambda| {row['max_abs_lambda']} ref {l_ref:.15g} rel {el:.1e}")
        worst_t, worst_l = max(worst_t, et), max(worst_l, el)
    assert worst_t < 1e-9, f"duration off by {worst_t:.2e} relative"
    assert worst_l < 1e-6, f"max |lambda| off by {worst_l:.2e} relative"
    print(f"worst relative errors: duration {worst_t:.1e}, max |lambda| {worst_l:.1e}")


if __name__ == "__main__":
    main()
