#!/usr/bin/env python3
"""Independent reference for a sleigh driven through a cusp (docs/physics.md §3), at 30 digits.

Written in the curve parameter u, never in the curvature (which is infinite at the cusp): the body's
signed speed along its heading is sigma(u) = d(u) |r'(u)|, with d = +1 before the cusp and -1 after
it (the knife heading is the tangent line, continuous; the direction of travel reverses), and
dphi/du = (x'y'' - y'x'')/|r'|^2 is finite. Constant energy: dt/du = sqrt(sigma^2 + b^2 phi'^2)/v_T;
sdot = sigma du/dt, phidot = phi' du/dt, Psi = atan2(sdot, b phidot) unwrapped along u, and every
rate by numerical differentiation (mpmath.diff) in u. Forces from Newton-Euler on the sleigh (mass
m at distance a ahead of the knife point P, inertia I = m (b^2 - a^2) about it): drive F along the
heading and knife reaction N across it act at P, the couple tau on the body:
  m (sddot - a phidot^2) = F,  m (sdot phidot + a phiddot) = N,  I phiddot = tau - a N.
Run: python3 tests/core/scene/cusp_reference.py (prints the C++ tables).
"""
import mpmath as mp

mp.mp.dps = 30
SLEIGH = dict(a=mp.mpf("0.5"), b=mp.mpf(1), m=mp.mpf(1))
THETA = mp.mpf("0.3")  # the rotated scene's angle


def semicubical(sign, theta):
    """x = u^2, y = sign u^3 rotated by theta: (x, y, x', y', x'', y'')."""
    c, s = mp.cos(theta), mp.sin(theta)

    def geo(u):
        X, Y, dX, dY, ddX, ddY = u**2, sign * u**3, 2 * u, sign * 3 * u**2, 2, sign * 6 * u
        return (c * X - s * Y, s * X + c * Y, c * dX - s * dY, s * dX + c * dY,
                c * ddX - s * ddY, s * ddX + c * ddY)

    return geo


SCENES = [
    # name, geometry, u range, cusp, v_T, times (negative: the cusp time plus this offset)
    ("x = u^2, y = u^3: turning left", semicubical(1, 0), -1, 1, 0, mp.mpf(1),
     [0.0, 0.6, ("cusp", -0.05), ("cusp", 0.0), ("cusp", 1e-6), ("cusp", 0.3), ("end", 0.0)]),
    ("x = u^2, y = -u^3 rotated by 0.3: turning right", semicubical(-1, THETA), -1, 1.2, 0,
     mp.mpf("0.8"),
     [0.0, 1.1, ("cusp", -1e-4), ("cusp", 0.0), ("cusp", 0.02), ("cusp", 0.9), ("end", 0.0)]),
]


def scene_rows(geo, u0, u1, cusp, v, times):
    a, b, m = SLEIGH["a"], SLEIGH["b"], SLEIGH["m"]
    I = m * (b**2 - a**2)
    u0, u1, cusp = mp.mpf(u0), mp.mpf(u1), mp.mpf(cusp)

    def sigma(u):
        g = geo(u)
        return (1 if u < cusp else -1) * mp.sqrt(g[2]**2 + g[3]**2)

    def dphidu(u):
        g = geo(u)
        q = g[2]**2 + g[3]**2
        if q == 0:  # the cusp itself: the limit (r'' x r''')/(2 |r''|^2), by a short step
            return (dphidu(u - mp.mpf(10)**-12) + dphidu(u + mp.mpf(10)**-12)) / 2
        return (g[2] * g[5] - g[3] * g[4]) / q

    dtdu = lambda u: mp.sqrt(sigma(u)**2 + b**2 * dphidu(u)**2) / v
    sdot = lambda u: sigma(u) / dtdu(u)
    phidot = lambda u: dphidu(u) / dtdu(u)
    g0 = geo(u0)
    phi0 = mp.atan2(g0[3], g0[2])
    psi0 = mp.atan2(sdot(u0), b * phidot(u0))

    def psi(u):
        # atan2 of the signed rates, unwrapped: continuous through the cusp
        raw = mp.atan2(sdot(u), b * phidot(u))
        side = 1 if dphidu(cusp) > 0 else -1
        if u > cusp and side < 0 and raw < 0:
            raw += 2 * mp.pi
        return raw

    t_of = lambda u: mp.quad(dtdu, [u0, u] if u <= cusp else [u0, cusp, u])
    t_cusp, duration = t_of(cusp), t_of(u1)
    rows = []
    for t in times:
        if isinstance(t, tuple):
            t = (t_cusp if t[0] == "cusp" else duration) + mp.mpf(t[1])
        t = mp.mpf(t)
        if t == 0:
            u = u0
        elif t == t_cusp:
            u = cusp
        elif t == duration:
            u = u1
        else:
            lo, hi = (u0, cusp) if t < t_cusp else (cusp, u1)
            u = mp.findroot(lambda w: t_of(w) - t, (lo, hi), solver="anderson")
        h = mp.mpf(10)**-8  # one-sided differences at the cusp, where sigma has a kink in |.|
        side = lambda f: (lambda w: f(w))
        ut = 1 / dtdu(u)
        sd, pd = sdot(u), phidot(u)
        if u == cusp:
            sdd = (sdot(u + h) - sdot(u - h)) / (2 * h) * ut
            pdd = (phidot(u + h) - phidot(u - h)) / (2 * h) * ut
            psd = (psi(u + h) - psi(u - h)) / (2 * h) * ut
        else:
            sdd = mp.diff(sdot, u) * ut
            pdd = mp.diff(phidot, u) * ut
            psd = mp.diff(psi, u) * ut
        ps = psi(u)
        phi = phi0 + mp.quad(dphidu, [u0, u] if u <= cusp else [u0, cusp, u])
        s = mp.quad(lambda w: abs(sigma(w)), [u0, u] if u <= cusp else [u0, cusp, u])
        g = geo(u)
        F = m * (sdd - a * pd**2)
        N = m * (sd * pd + a * pdd)
        tau = I * pdd + a * N
        chi = ps - (a / b) * phi
        lam = m * (b * psd - a * pd)
        energy = m * (sd**2 + b**2 * pd**2) / 2
        rows.append([t, s, g[0], g[1], phi, ps, chi, lam, energy, sd, pd, psd, F, N, tau])
    length = mp.quad(lambda w: abs(sigma(w)), [u0, cusp, u1])
    return rows, t_cusp, duration, length


def main():
    for name, geo, u0, u1, cusp, v, times in SCENES:
        rows, t_cusp, duration, length = scene_rows(geo, u0, u1, cusp, v, times)
        print(f"// {name}: cusp time, duration, path length")
        print("{" + ", ".join(mp.nstr(x, 20) for x in (t_cusp, duration, length)) + "},")
        print("// t, s, x, y, phi, psi, chi, lambda, energy, sdot, phidot, psidot, force_axial, "
              "force_lateral, control_couple")
        for r in rows:
            print("{" + ", ".join(mp.nstr(x, 20) for x in r) + "},")


if __name__ == "__main__":
    main()
