#!/usr/bin/env python3
"""High-precision reference for the free (Lagrange-d'Alembert) sleigh in the two ill-conditioned
cases: a tiny CM offset (b/a = 1e9) and a tiny initial curvature (kappa0 = 1e-7, 1e-9).

Independent of the C++ code: velocities and heading from the textbook closed form (docs/physics.md
sec. 4) with c = atanh(sdot0/V) and gd(kt + c) - gd(c) evaluated directly, at 60 digits (where the
cancellation that double precision suffers is harmless); positions by mpmath quadrature of
sdot e^{i phi}. Each case is cross-checked against mpmath's Taylor-series ODE solver (odefun) of
sddot = a phidot^2, phiddot = -a sdot phidot/b^2 at one time. Inputs are the exact doubles the C++
test uses. Run: python3 tests/core/motion/free_motion_reference.py (prints the rows of
tests/core/motion/test_free_motion.cpp's precision tables).
"""
import mpmath as mp

mp.mp.dps = 60

CASES = [
    # name, a, b, (x0, y0, phi0, sdot0, phidot0), times
    ("tiny offset", 1e-9, 1.0, (0.3, -0.2, 0.4, 0.6, 0.9), [0.5, 2.0, 10.0, 30.0]),
    ("tiny offset backwards", -1e-9, 0.8, (0.0, 0.0, -1.0, -0.4, -1.3), [0.5, 2.0, 10.0, 30.0]),
    ("curvature 1e-7", 0.5, 1.0, (0.0, 0.0, 0.1, 1.0, 1e-7), [0.5, 2.0, 10.0, 30.0]),
    ("curvature 1e-9", 0.5, 1.0, (1.0, 2.0, -0.3, 1.0, -1e-9), [0.5, 2.0, 10.0, 30.0]),
]


def closed_form(a, b, init):
    x0, y0, phi0, sd0, pd0 = (mp.mpf(v) for v in init)
    a, b = mp.mpf(a), mp.mpf(b)
    V = mp.sqrt(sd0**2 + b**2 * pd0**2)
    k = a * V / b**2
    c = mp.atanh(sd0 / V)
    sigma = mp.sign(pd0)
    beta = b / a
    gd = lambda tau: 2 * mp.atan(mp.tanh(tau / 2))

    def vel(t):
        tau = k * t + c
        return (V * mp.tanh(tau), sigma * V / b * mp.sech(tau),
                phi0 + sigma * beta * (gd(tau) - gd(c)))

    def pos(t):
        f = lambda u: vel(u)[0] * mp.expj(vel(u)[2])
        nodes = mp.linspace(0, t, int(mp.ceil(t)) + 1)
        z = mp.quad(f, nodes)
        return mp.mpf(x0) + z.real, mp.mpf(y0) + z.imag

    limit = mp.pi / 2 if k > 0 else -mp.pi / 2
    total = sigma * beta * (limit - gd(c))
    return vel, pos, total


def ode_check(a, b, init, t):
    a, b = mp.mpf(a), mp.mpf(b)
    F = lambda _, y: [y[3] * mp.cos(y[2]), y[3] * mp.sin(y[2]), y[4], a * y[4]**2,
                      -a * y[3] * y[4] / b**2]
    with mp.workdps(30):
        return mp.odefun(F, 0, [mp.mpf(v) for v in init])(t)


def main():
    for name, a, b, init, times in CASES:
        vel, pos, total = closed_form(a, b, init)
        # cross-check against the ODE at t = 2
        sd, pd, phi = vel(2)
        x, y = pos(2)
        ode = ode_check(a, b, init, 2)
        for mine, other in zip((x, y, phi, sd, pd), ode):
            assert abs(mine - other) < mp.mpf(10)**-20, (name, mine, other)
        print(f"// {name}: a = {a!r}, b = {b!r}, initial {init}")
        print(f"// total turn {mp.nstr(total, 20)}; rows t, x, y, phi - phi0, sdot, phidot")
        for t in times:
            sd, pd, phi = vel(t)
            x, y = pos(t)
            turn = phi - mp.mpf(init[2])
            print("{" + ", ".join([repr(t)] + [mp.nstr(v, 20) for v in (x, y, turn, sd, pd)]) +
                  "},")


if __name__ == "__main__":
    main()
