#!/usr/bin/env python3
"""High-precision references for the planner's far targets (docs/physics.md §10).

For a target (X, Y, Phi) of the normalised problem (b = v_T = 1, from (0, 0, 0)) it solves the
three end equations for (Psi0, Lambda0, t) at 40 digits with mpmath, the end pose from the
pendulum's closed form in mpmath's own Jacobi functions and elliptic integrals (no code of the
program), started from a rough guess given on the command line (any start within the basin: the
answer does not depend on it). It then checks the answer by integrating (19)-(21) with
mpmath.odefun at 30 digits, and prints one row of the table embedded in test_pose_planner.cpp:
X, Y, Phi, t, Psi0, 1 - k^2 = cos^2 Psi0 - Lambda0^2, Lambda0, and the end error of the ODE check.

With --bound it prints instead the end error that the test's tolerances allow at most: the sum
of the columns of the end's Jacobian in (Psi0, log |1 - k^2|, t) times 1e-12, 1e-11, 1e-11.

With --end T PSI0 GAP SIGN it prints the end error at 40 digits of the motion of Psi0 with
1 - k^2 = GAP, Lambda0 of the sign SIGN, at T (the planner's t, psi0, modulusGap and the sign of
psidot0): how far the planner's own motion ends from the target.

usage: far_target_reference.py X Y PHI T0 PSI0 LAMBDA0 [--no-ode] [--bound]
       far_target_reference.py X Y PHI --end T PSI0 GAP SIGN
"""
import sys

import mpmath as mp

mp.mp.dps = 40


def am(w, m, K):
    """The amplitude am(w | m), continuous in w."""
    j = mp.nint(w / (2 * K))
    r = w - 2 * K * j
    return j * mp.pi + mp.atan2(mp.ellipfun('sn', r, m=m), mp.ellipfun('cn', r, m=m))


def D(theta, m):
    """int_0^theta sin^2/sqrt(1 - m sin^2) = (F - E)/m, for any theta."""
    return (mp.ellipf(theta, m) - mp.ellipe(theta, m)) / m


def end_pose(psi0, lam0, t):
    """(x, y, phi) at t of x' = sin Psi cos phi, y' = sin Psi sin phi, phi' = cos Psi,
    Psi'' = -sin Psi cos Psi, from the pendulum's closed form."""
    S0, C0 = mp.sin(psi0), mp.cos(psi0)
    gap = (C0 - lam0) * (C0 + lam0)  # 1 - k^2
    if gap > 0:  # libration: sn w = eps sin Psi / k, cn w = Lambda / k, w = w0 + t
        m = 1 - gap
        k = mp.sqrt(m)
        eps = 1 if C0 >= 0 else -1
        K = mp.ellipk(m)
        a0 = mp.atan2(eps * S0, lam0)
        w = mp.ellipf(a0, m) + t
        a1 = am(w, m, K)
        sn0, sn1 = mp.sin(a0), mp.sin(a1)
        dn0, dn1 = mp.sqrt(1 - m * sn0**2), mp.sqrt(1 - m * sn1**2)
        alpha = -eps * a0
        z = k * mp.expj(alpha) * mp.mpc(eps * (sn1**2 - sn0**2) / (dn1 + dn0), D(a1, m) - D(a0, m))
        return z.real, z.imag, eps * (a1 - a0)
    # rotation: Psi = sigma am(W | 1/k^2), W = W0 + k t
    k = mp.sqrt(1 - gap)
    m = 1 / k**2
    q = 1 / k
    sigma = 1 if lam0 >= 0 else -1
    K = mp.ellipk(m)
    a0 = sigma * psi0
    W = mp.ellipf(a0, m) + k * t
    a1 = am(W, m, K)
    beta0 = mp.atan2(q * mp.sin(a0), mp.sqrt(1 - m * mp.sin(a0)**2))
    beta1 = mp.atan2(q * mp.sin(a1), mp.sqrt(1 - m * mp.sin(a1)**2))
    z = sigma * q * mp.expj(-beta0) * mp.mpc(-(mp.cos(a1) - mp.cos(a0)), q * (D(a1, m) - D(a0, m)))
    return z.real, z.imag, beta1 - beta0


def wrap(a):
    return a - 2 * mp.pi * mp.nint(a / (2 * mp.pi))


def solve(X, Y, Phi, t0, psi0, lam0):
    def residual(p, l, t):
        x, y, phi = end_pose(p, l, t)
        return [x - X, y - Y, wrap(phi - Phi)]
    p, l, t = mp.findroot(residual, (psi0, lam0, t0), tol=mp.mpf(10)**-34, maxsteps=60)
    r = residual(p, l, t)
    assert sum(abs(v) for v in r) < mp.mpf(10)**-30, r
    return p, l, t


def ode_end(psi0, lam0, t):
    mp.mp.dps = 30
    f = mp.odefun(lambda s, u: [mp.sin(u[3]) * mp.cos(u[2]), mp.sin(u[3]) * mp.sin(u[2]),
                                mp.cos(u[3]), u[4], -mp.sin(u[3]) * mp.cos(u[3])],
                  0, [0, 0, 0, psi0, lam0])
    u = f(t)
    mp.mp.dps = 40
    return u[0], u[1], u[2]


def bound(p, l, t):
    """|J_Psi0| 1e-12 + |J_log gap| 1e-11 + |J_t| 1e-11, the 1-norms of the end's columns."""
    gap = (mp.cos(p) - l) * (mp.cos(p) + l)
    sigma = 1 if l > 0 else -1

    def end(psi0, log_gap, time):
        g = mp.sign(gap) * mp.exp(log_gap)
        return end_pose(psi0, sigma * mp.sqrt(mp.cos(psi0)**2 - g), time)

    h = mp.mpf(10)**-12
    lg = mp.log(abs(gap))
    total = 0
    for d, tol in (((h, 0, 0), 1e-12), ((0, h, 0), 1e-11), ((0, 0, h), 1e-11)):
        a = end(p + d[0], lg + d[1], t + d[2])
        b = end(p - d[0], lg - d[1], t - d[2])
        total += sum(abs(u - v) for u, v in zip(a, b)) / (2 * h) * tol
    return total


def main():
    if sys.argv[4] == '--end':
        X, Y, Phi, t, psi0, gap, sign = (mp.mpf(a) for a in sys.argv[1:4] + sys.argv[5:9])
        x, y, phi = end_pose(psi0, sign * mp.sqrt(mp.cos(psi0)**2 - gap), t)
        print('(%s, %s, %s): end error %s' % (sys.argv[1], sys.argv[2], sys.argv[3], mp.nstr(
            abs(x - X) + abs(y - Y) + abs(wrap(phi - Phi)), 3)))
        return
    X, Y, Phi, t0, psi0, lam0 = (mp.mpf(a) for a in sys.argv[1:7])
    p, l, t = solve(X, Y, Phi, t0, psi0, lam0)
    gap = (mp.cos(p) - l) * (mp.cos(p) + l)
    if '--bound' in sys.argv:
        print('(%s, %s, %s): the tolerances allow an end error of at most %s' % (
            sys.argv[1], sys.argv[2], sys.argv[3], mp.nstr(bound(p, l, t), 3)))
        return
    err = mp.nan
    if '--no-ode' not in sys.argv:
        x, y, phi = ode_end(p, l, t)
        err = abs(x - X) + abs(y - Y) + abs(wrap(phi - Phi))
    print('{%s, %s, %s, %s, %s, %s, %s}, // ODE check %s' % (
        sys.argv[1], sys.argv[2], sys.argv[3], mp.nstr(t, 20), mp.nstr(p, 20),
        mp.nstr(gap, 20), mp.nstr(l, 20), mp.nstr(err, 3)))


if __name__ == '__main__':
    main()
