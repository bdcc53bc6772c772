#!/usr/bin/env python3
"""Independent reference for the rolling disk (App. A) and the two-wheeled carriage (App. B): every
CSV column and summary field, at 30 digits, for the scenes of tests/core/scene/test_systems_columns.cpp.

Independent of the C++ control law: the reference starts from the bodies, not from the reduced
sleigh. Time law from dt/du (constant energy: T of all the bodies fixed; constant speed:
ds/dt = v_s); the rates sdot = ds/dt and phidot = dphi/dt by the chain rule, the accelerations by
numerical differentiation (mpmath.diff) in u; Psi = atan2(sdot, b phidot). The forces come from a
Newton-Euler balance of every body, solved as a linear system for the drive torques:
  carriage: chassis (M, I about the axle centre) and two wheels (m, I1 about the axle, I2 about a
  diameter) at +-a across the heading, rolling without slip: wheel spin rates w+- = (sdot -+ a
  phidot)/R; unknowns: the axle motor torques tau+- and the longitudinal ground forces f+-;
    I1 dw+-/dt = tau+- - R f+-,   (M + 2m) sddot = f+ + f-,   (I + 2 I2 + 2 m a^2) phiddot = a (f- - f+).
  The lateral ground force is (M + 2m) sdot phidot (the centre of mass is the axle centre).
  force_axial is the generalized drive (tau+ + tau-)/R, control_couple a (tau- - tau+)/R
  (virtual power tau+ w+ + tau- w- = force_axial sdot + control_couple phidot).
  disk: m sddot = f, I1 dw/dt = tau_roll - R f (w = sdot/R), I2 phiddot = tau_turn, lateral m sdot phidot;
  force_axial = tau_roll/R, control_couple = tau_turn.
The free motion (no drive torques): the same balance with tau = 0 gives sddot = phiddot = 0, a
uniform circle through the initial state.
Run: python3 tests/core/scene/systems_reference.py (prints the C++ tables).
"""
import mpmath as mp

mp.mp.dps = 30

CARRIAGE = dict(R=0.3, a=0.4, m=0.5, I1=0.02, I2=0.01, M=3.0, I=0.2)  # b = 0.3186 < a
DISK = dict(m=2.0, R=0.6, I1=0.36, I2=0.18)

# path: (x, y, x', y', x'', y'') of u, and the u-range
PARABOLA = (lambda u: (u, u * u / 2, 1, u, 0, 1), -1.0, 1.5)
CIRCLE = (lambda u: (2 * mp.cos(u), 2 * mp.sin(u), -2 * mp.sin(u), 2 * mp.cos(u),
                     -2 * mp.cos(u), -2 * mp.sin(u)), 0.0, float(2 * mp.pi))

SCENES = [
    # name, system, params, path, mode, speed, times
    ("carriage, b < a, parabola, energy", "carriage", CARRIAGE, PARABOLA, "energy", 0.8,
     [0.0, 0.7, 1.9, 3.2, 3.9]),
    ("carriage, b < a, parabola, speed", "carriage", CARRIAGE, PARABOLA, "speed", 0.6,
     [0.0, 1.1, 2.5, 4.0, 5.1]),
    ("carriage, b < a, circle, energy", "carriage", CARRIAGE, CIRCLE, "energy", 1.0,
     [0.0, 1.5, 6.0, 11.0, 12.7]),
    ("disk, parabola, energy", "disk", DISK, PARABOLA, "energy", 0.9, [0.0, 0.8, 2.0, 3.4]),
    ("disk, parabola, speed", "disk", DISK, PARABOLA, "speed", 0.7, [0.0, 1.2, 2.6, 4.1, 4.4]),
]


class Bodies:
    """Masses and inertias of the bodies; T and the Newton-Euler forces."""

    def __init__(self, kind, p):
        self.kind = kind
        self.p = {k: mp.mpf(v) for k, v in p.items()}
        q = self.p
        if kind == "carriage":
            self.meff = q["M"] + 2 * (q["m"] + q["I1"] / q["R"]**2)  # (B10)
            self.J = q["I"] + 2 * q["I2"] + 2 * q["a"]**2 * (q["m"] + q["I1"] / q["R"]**2)
        else:
            self.meff = q["m"] + q["I1"] / q["R"]**2  # (A14)
            self.J = q["I2"]
        self.b = mp.sqrt(self.J / self.meff)

    def energy(self, sd, pd):
        q = self.p
        if self.kind == "carriage":
            wp, wm = (sd - q["a"] * pd) / q["R"], (sd + q["a"] * pd) / q["R"]
            return ((q["M"] + 2 * q["m"]) * sd**2 + (q["I"] + 2 * q["I2"] + 2 * q["m"] * q["a"]**2) *
                    pd**2 + q["I1"] * (wp**2 + wm**2)) / 2
        return (q["m"] * sd**2 + q["I1"] * (sd / q["R"])**2 + q["I2"] * pd**2) / 2

    def forces(self, sd, pd, sdd, pdd):
        """(force_axial, force_lateral, control_couple) from Newton-Euler."""
        q = self.p
        R = q["R"]
        if self.kind == "carriage":
            a, I1 = q["a"], q["I1"]
            # unknowns (tau+, tau-, f+, f-)
            A = mp.matrix([[1, 0, -R, 0], [0, 1, 0, -R], [0, 0, 1, 1], [0, 0, -a, a]])
            rhs = mp.matrix([I1 * (sdd - a * pdd) / R, I1 * (sdd + a * pdd) / R,
                             (q["M"] + 2 * q["m"]) * sdd,
                             (q["I"] + 2 * q["I2"] + 2 * q["m"] * a**2) * pdd])
            tp, tm, _, _ = mp.lu_solve(A, rhs)
            return (tp + tm) / R, (q["M"] + 2 * q["m"]) * sd * pd, a * (tm - tp) / R
        f = q["m"] * sdd
        tau_roll = q["I1"] * sdd / R + R * f
        return tau_roll / R, q["m"] * sd * pd, q["I2"] * pdd


def scene_rows(system, params, path, mode, speed, times):
    bodies = Bodies(system, params)
    b, meff = bodies.b, bodies.meff
    geo, u0, u1 = path
    u0, u1, v = mp.mpf(u0), mp.mpf(u1), mp.mpf(speed)

    def dsdu(u):
        g = geo(u)
        return mp.sqrt(g[2]**2 + g[3]**2)

    def dphidu(u):
        g = geo(u)
        return (g[2] * g[5] - g[3] * g[4]) / (g[2]**2 + g[3]**2)

    def dtdu(u):
        if mode == "speed":
            return dsdu(u) / v
        # constant T: (meff/2)(sdot^2 + b^2 phidot^2) = (meff/2) v^2 with sdot = ds/du du/dt
        return mp.sqrt(dsdu(u)**2 + b**2 * dphidu(u)**2) / v

    sdot = lambda u: dsdu(u) / dtdu(u)
    phidot = lambda u: dphidu(u) / dtdu(u)
    psi = lambda u: mp.atan2(sdot(u), b * phidot(u))
    g0 = geo(u0)
    phi0 = mp.atan2(g0[3], g0[2])
    t_of = lambda u: mp.quad(dtdu, [u0, u])
    duration = t_of(u1)
    length = mp.quad(dsdu, [u0, u1])
    rows = []
    free0 = (mp.mpf(g0[0]), mp.mpf(g0[1]), phi0, sdot(u0), phidot(u0))
    for t in times:
        assert t <= duration, (t, duration)
        t = mp.mpf(t)
        u = u0 if t == 0 else mp.findroot(lambda w: t_of(w) - t, u0 + (u1 - u0) * t / duration)
        g = geo(u)
        ut = 1 / dtdu(u)  # du/dt
        sd, pd = sdot(u), phidot(u)
        sdd = mp.diff(sdot, u) * ut
        pdd = mp.diff(phidot, u) * ut
        ps = psi(u)
        psd = mp.diff(psi, u) * ut
        phi = phi0 + mp.quad(dphidu, [u0, u])
        s = mp.quad(dsdu, [u0, u])
        chi = ps  # centre-of-mass offset 0
        lam = meff * b * psd
        axial, lateral, couple = bodies.forces(sd, pd, sdd, pdd)
        x0, y0, f0, sd0, pd0 = free0
        rho = sd0 / pd0
        fx = x0 + rho * (mp.sin(f0 + pd0 * t) - mp.sin(f0))
        fy = y0 - rho * (mp.cos(f0 + pd0 * t) - mp.cos(f0))
        rows.append([t, s, g[0], g[1], phi, ps, chi, lam, bodies.energy(sd, pd), fx, fy,
                     f0 + pd0 * t, sd0, pd0, bodies.energy(sd0, pd0), sd, pd, psd, axial,
                     lateral, couple])
    summary = dict(a=0, b=b, m_eff=meff, I=bodies.J, path_length=length, duration=duration)
    return rows, summary


def main():
    for name, system, params, path, mode, speed, times in SCENES:
        rows, summary = scene_rows(system, params, path, mode, speed, times)
        print(f"// {name}: summary a, b, m_eff, I, path_length, duration")
        print("{" + ", ".join(mp.nstr(summary[k], 20) for k in
                              ("a", "b", "m_eff", "I", "path_length", "duration")) + "},")
        print("// rows: t, s, x, y, phi, psi, chi, lambda, energy, free_x, free_y, free_phi, "
              "free_sdot, free_phidot, free_energy, sdot, phidot, psidot, force_axial, "
              "force_lateral, control_couple")
        for r in rows:
            print("{" + ", ".join(mp.nstr(v, 20) for v in r) + "},")


if __name__ == "__main__":
    main()
