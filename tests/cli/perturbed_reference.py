#!/usr/bin/env python3
"""Independent reference for the perturbed bodies (docs/physics.md §9): the CSV's pert_* and fb_*
columns of `chaplygin-lab --headless ... --perturb ...` against scipy's DOP853 (rtol 1e-13,
atol 1e-14) of the same control-input system, written here without the program's formulas:

* the path from its closed form, with kappa, kappa_s and kappa_ss by sympy's exact derivatives in
  the curve parameter; the nominal motion integrated alongside as du_n/dt = sdot_n/|r'(u_n)|,
  sdot_n = v_T/sqrt(1 + b^2 kappa^2), and its lambda = m (b Psidot - a phidot) with
  Psidot = -b kappa_s sdot/(1 + b^2 kappa^2) (docs/physics.md §2);
* the bodies in the paper's variables (x, y, phi, sdot, phidot), eqs. (19)-(20) with
  lambda_c = lambda + m a phidot: m sddot = lambda_c phidot, m b^2 phiddot = -lambda_c sdot
  (so the energy is conserved by the dynamics, not by a parametrisation);
* the feedback: the closest point by Newton from an integrated guess u_p; z3 = (1 - kappa e)
  tan(theta) and z4 = dz3/ds_p, dz4/ds_p by sympy's chain rule through e' = (1 - kappa e)
  tan(theta), theta' = kappa_b (1 - kappa e)/cos(theta) - kappa and kappa(s_p); the input
  u = -P^3 z2 - 3 P^2 z3 - 3 P z4 solved for kappa_b' = d kappa_b/ds_p; the controller turns it
  into lambda with its own b (Psi_c = atan2(sdot, b_c phidot)); |Psidot| clamped when limited;
  beyond the path's ends the osculating circle there.
Usage: perturbed_reference.py CHAPLYGIN_LAB
"""
import csv
import io
import math
import subprocess
import sys

import sympy as sp
from scipy.integrate import solve_ivp

u_sym = sp.symbols("u")


class Path:
    """r(u) = (X(u), Y(u)) on [u0, u1] with exact kappa(u), kappa_s, kappa_ss."""

    def __init__(self, X, Y, u0, u1):
        d1x, d1y = sp.diff(X, u_sym), sp.diff(Y, u_sym)
        d2x, d2y = sp.diff(d1x, u_sym), sp.diff(d1y, u_sym)
        speed = sp.sqrt(d1x**2 + d1y**2)
        kappa = (d1x * d2y - d1y * d2x) / speed**3
        kappa_s = sp.diff(kappa, u_sym) / speed
        kappa_ss = sp.diff(kappa_s, u_sym) / speed
        f = lambda e: sp.lambdify(u_sym, e, "math")
        self.fx, self.fy, self.fdx, self.fdy = f(X), f(Y), f(d1x), f(d1y)
        self.fspeed, self.fk, self.fks, self.fkss = f(speed), f(kappa), f(kappa_s), f(kappa_ss)
        self.u0, self.u1 = u0, u1

    def at(self, u):
        """(x, y, phi, kappa, kappa_s, kappa_ss, ds/du); the osculating circle beyond the ends."""
        if self.u0 <= u <= self.u1:
            return (self.fx(u), self.fy(u), math.atan2(self.fdy(u), self.fdx(u)), self.fk(u),
                    self.fks(u), self.fkss(u), self.fspeed(u))
        ue = self.u0 if u < self.u0 else self.u1
        x, y, phi, k, _, _, v = self.at(ue)
        ds = (u - ue) * v
        if abs(k * ds) < 1e-8:
            fwd, side = ds - k * k * ds**3 / 6, k * ds * ds / 2
        else:
            fwd, side = math.sin(k * ds) / k, (1 - math.cos(k * ds)) / k
        return (x + fwd * math.cos(phi) - side * math.sin(phi),
                y + fwd * math.sin(phi) + side * math.cos(phi), phi + k * ds, k, 0.0, 0.0, v)

    def project(self, x, y, u):
        for _ in range(60):
            px, py, phi, k, _, _, v = self.at(u)
            dx, dy = x - px, y - py
            along = dx * math.cos(phi) + dy * math.sin(phi)
            e = dy * math.cos(phi) - dx * math.sin(phi)
            du = along / (v * (1 - k * e))
            u += du
            if abs(du) * v < 1e-14 * (1 + abs(u) * v):
                break
        else:
            raise RuntimeError("projection does not converge")
        px, py, phi, k, ks, kss, v = self.at(u)
        e = (y - py) * math.cos(phi) - (x - px) * math.sin(phi)
        return u, e, phi, k, ks, kss, v


def chained_form():
    """kappa_b' as a function of (e, theta, kappa_b, kappa, kappa', kappa'', P), by sympy."""
    e, th, kb, k, k1, k2, P = sp.symbols("e theta kappa_b kappa kappa1 kappa2 P")
    de = (1 - k * e) * sp.tan(th)
    dth = kb * (1 - k * e) / sp.cos(th) - k
    z3 = (1 - k * e) * sp.tan(th)

    def d_ds(expr, dkb=0):
        return (sp.diff(expr, e) * de + sp.diff(expr, th) * dth + sp.diff(expr, k) * k1 +
                sp.diff(expr, k1) * k2 + sp.diff(expr, kb) * dkb)

    z4 = d_ds(z3)
    dkb = sp.symbols("dkb")
    dz4 = d_ds(z4, dkb)
    u = -P**3 * e - 3 * P**2 * z3 - 3 * P * z4
    sol = sp.solve(sp.Eq(dz4, u), dkb)[0]
    return sp.lambdify((e, th, kb, k, k1, k2, P), sol, "math")


KB_RATE = chained_form()


def run_case(exe, name, args, path, system, pert, rate=1.0, limit=None, vT=1.0):
    """system: (m_eff, a, b); pert: dy, dphi, dpsi, t_push, push_psi, push_dy, controller_b."""
    m, a, b = system
    bc = pert.get("controller_b", b)
    out = subprocess.run([exe, "--headless"] + args + ["--samples", "41", "--csv", "-"],
                         capture_output=True, text=True, check=True).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    times = [float(r["t"]) for r in rows]

    def nominal(un):
        k, ks, v = path.fk(un), path.fks(un), path.fspeed(un)
        sdot = vT / math.sqrt(1 + (b * k)**2)
        psidot = -b * ks * sdot / (1 + (b * k)**2)
        return sdot / v, m * (b * psidot - a * k * sdot)

    def body(state, lam):
        # (19)-(20) with lambda_c = lambda + m a phidot
        x, y, phi, sd, pd = state
        lc = lam + m * a * pd
        return [sd * math.cos(phi), sd * math.sin(phi), pd, lc * pd / m, -lc * sd / (m * b * b)]

    def feedback_lambda(state, up):
        x, y, phi, sd, pd = state
        up, e, phip, k, ks, kss, v = path.project(x, y, up)
        th = phi - phip
        kb = pd / sd
        spd = sd * math.cos(th) / (1 - k * e)
        kbdot = spd * KB_RATE(e, th, kb, k, ks, kss, rate)
        psic = math.atan2(sd, bc * pd)
        lam = m * (bc * (-bc * math.sin(psic)**2 * kbdot) - a * pd)
        psidot = (lam / m + a * pd) / b
        if limit is not None:
            psidot = max(-limit, min(limit, psidot))
        return m * (b * psidot - a * pd), spd / v, up, e

    def rhs(t, z):
        un = z[0]
        dun, lam_n = nominal(un)
        lam_fb, dup, _, _ = feedback_lambda(z[6:11], z[11])
        return [dun] + body(z[1:6], lam_n) + body(z[6:11], lam_fb) + [dup]

    x0, y0, phi0, k0 = path.fx(path.u0), path.fy(path.u0), None, path.fk(path.u0)
    phi0 = math.atan2(path.fdy(path.u0), path.fdx(path.u0))
    psi = math.atan2(1, b * k0) + pert.get("dpsi", 0)
    dy = pert.get("dy", 0)
    start = [x0 - dy * math.sin(phi0), y0 + dy * math.cos(phi0), phi0 + pert.get("dphi", 0),
             vT * math.sin(psi), vT / b * math.cos(psi)]
    up0 = path.project(start[0], start[1], path.u0)[0]
    z0 = [path.u0] + start + start + [up0]

    def push(z):
        z = list(z)
        for i in (1, 6):
            x, y, phi, sd, pd = z[i:i + 5]
            p = math.atan2(sd, b * pd) + pert.get("push_psi", 0)
            d = pert.get("push_dy", 0)
            z[i:i + 5] = [x - d * math.sin(phi), y + d * math.cos(phi), phi, vT * math.sin(p),
                          vT / b * math.cos(p)]
        z[11] = path.project(z[6], z[7], z[11])[0]
        return z

    tp = pert.get("t_push")
    pieces = [(0.0, tp), (tp, times[-1])] if tp else [(0.0, times[-1])]
    sol_at = {}
    z = z0
    for i, (ta, tb) in enumerate(pieces):
        if i > 0:
            z = push(z)
        ts = [t for t in times if ta <= t <= tb and (i + 1 == len(pieces) or t < tb)]
        s = solve_ivp(rhs, (ta, tb), z, method="DOP853", rtol=1e-13, atol=1e-14,
                      t_eval=ts + ([tb] if not ts or ts[-1] != tb else []))
        assert s.success, s.message
        for j, t in enumerate(s.t):
            if t in ts:
                sol_at[t] = s.y[:, j]
        z = s.y[:, -1]

    worst = {}
    for r, t in zip(rows, times):
        zz = sol_at[t]
        lam_fb, _, _, e = feedback_lambda(zz[6:11], zz[11])
        ref = {"pert_x": zz[1], "pert_y": zz[2], "pert_phi": zz[3], "pert_sdot": zz[4],
               "pert_phidot": zz[5], "fb_x": zz[6], "fb_y": zz[7], "fb_phi": zz[8],
               "fb_sdot": zz[9], "fb_phidot": zz[10], "fb_lambda": lam_fb, "fb_error": e}
        for key, v in ref.items():
            worst[key] = max(worst.get(key, 0.0), abs(float(r[key]) - v))
        energy = 0.5 * m * (zz[9]**2 + b * b * zz[10]**2)
        worst["ref_energy_drift"] = max(worst.get("ref_energy_drift", 0.0),
                                        abs(energy - 0.5 * m * vT * vT))
    top = max(v for k, v in worst.items() if k != "ref_energy_drift")
    print(f"{name}: max |difference| {top:.2e} over {len(rows)} rows "
          f"(pert {max(v for k, v in worst.items() if k.startswith('pert')):.1e}, "
          f"fb {max(v for k, v in worst.items() if k.startswith('fb')):.1e}; "
          f"reference energy drift {worst['ref_energy_drift']:.1e})")
    return top


def main():
    exe = sys.argv[1]
    sleigh = (1.0, 0.5, 1.0)
    line = Path(u_sym, 0.5 * u_sym + 1, 0.0, 8.0)
    circle = Path(2 * sp.cos(u_sym), 2 * sp.sin(u_sym), 0.0, 30.0)
    sinusoid = Path(u_sym, -sp.sin(u_sym), 0.0, 4 * math.pi)
    disk = (3.0, 0.0, math.sqrt(0.18 / 3.0))  # m = 2, R = 0.6, I1 = 0.36, I2 = 0.18
    circle_args = ["--path", "x=2*cos(u);y=2*sin(u)", "--u-range", "0,30", "--param", "a=0.5",
                   "--param", "b=1", "--param", "m=1"]
    cases = [
        ("line, dy = 1e-5", ["--preset", "line", "--perturb", "dy=1e-5"], line, sleigh,
         {"dy": 1e-5}, {}),
        ("line, dy = 0.3, dphi = 0.1, dpsi = 0.05, push", ["--preset", "line", "--perturb",
         "dy=0.3", "--perturb", "dphi=0.1", "--perturb", "dpsi=0.05", "--perturb", "t_push=4",
         "--perturb", "push_psi=-0.2", "--perturb", "push_dy=0.1"], line, sleigh,
         {"dy": 0.3, "dphi": 0.1, "dpsi": 0.05, "t_push": 4.0, "push_psi": -0.2, "push_dy": 0.1},
         {}),
        ("circle R = 2, u in [0, 30], dy = 1e-5", circle_args + ["--perturb", "dy=1e-5"], circle,
         sleigh, {"dy": 1e-5}, {}),
        ("circle R = 2, u in [0, 30], dy = 0.3", circle_args + ["--perturb", "dy=0.3"], circle,
         sleigh, {"dy": 0.3}, {}),
        ("circle, controller b = 0.7, |Psidot| <= 0.15, P = 2", circle_args + [
            "--perturb", "dy=0.2", "--perturb", "controller_b=0.7", "--feedback-rate", "2",
            "--feedback-limit", "0.15"], circle, sleigh, {"dy": 0.2, "controller_b": 0.7},
         {"rate": 2.0, "limit": 0.15}),
        ("sinusoid, dy = 0.2, dpsi = -0.1, push", ["--preset", "sinusoid", "--perturb",
         "dy=0.2", "--perturb", "dpsi=-0.1", "--perturb", "t_push=5", "--perturb",
         "push_psi=0.2"], sinusoid, sleigh, {"dy": 0.2, "dpsi": -0.1, "t_push": 5.0,
                                             "push_psi": 0.2}, {}),
        ("disk on the sinusoid, dy = 0.1, dphi = 0.05, P = 1.5", ["--preset", "sinusoid",
         "--system", "disk", "--param", "m=2", "--param", "R=0.6", "--param", "I1=0.36",
         "--param", "I2=0.18", "--perturb", "dy=0.1", "--perturb", "dphi=0.05",
         "--feedback-rate", "1.5"], sinusoid, disk, {"dy": 0.1, "dphi": 0.05}, {"rate": 1.5}),
    ]
    worst = 0.0
    for name, args, path, system, pert, opts in cases:
        worst = max(worst, run_case(exe, name, args, path, system, pert, **opts))
    assert worst <= 1e-9, f"the perturbed bodies differ from the reference by {worst:.2e}"
    print(f"worst difference {worst:.2e} (bound 1e-9)")


if __name__ == "__main__":
    main()
