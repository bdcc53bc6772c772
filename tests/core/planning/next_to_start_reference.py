#!/usr/bin/env python3
"""Independent references for targets next to the start (docs/physics.md §10).

Multi-start shooting for the motions to a target (X, Y, Phi) of the normalised problem
(b = v_T = 1, from (0, 0, 0)): scipy's least_squares on (Psi0, Lambda0, t), the end pose from
scipy's DOP853 integration of x' = sin Psi cos phi, y' = sin Psi sin phi, phi' = cos Psi,
Psi' = Lambda, Lambda' = -sin Psi cos Psi at 1e-12 (no code of the program). Prints the distinct
motions found, fastest first; the first is the reference embedded in test_pose_planner.cpp.

usage: next_to_start_reference.py X Y PHI STARTS LAMBDA_SCALE
(LAMBDA_SCALE: the spread of the random Lambda0, about the target's distance)
"""
import sys

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import least_squares


def main():
    X, Y, PHI = map(float, sys.argv[1:4])
    starts, scale = int(sys.argv[4]), float(sys.argv[5])

    def rhs(_, u):
        _, _, phi, psi, lam = u
        s, c = np.sin(psi), np.cos(psi)
        return [s * np.cos(phi), s * np.sin(phi), c, lam, -s * c]

    def residual(p):
        psi0, lam0, t = p
        if t <= 0:
            return [1e3 * (1 - t)] * 3
        sol = solve_ivp(rhs, (0, t), [0, 0, 0, psi0, lam0], method='DOP853', rtol=1e-12,
                        atol=1e-14)
        x, y, phi = sol.y[:3, -1]
        return [x - X, y - Y, np.remainder(phi - PHI + np.pi, 2 * np.pi) - np.pi]

    rng = np.random.default_rng(1)
    found = []
    for _ in range(starts):
        p0 = [rng.uniform(-np.pi, np.pi), rng.normal() * scale, rng.uniform(0.1, 7)]
        r = least_squares(residual, p0, xtol=1e-15, ftol=1e-15, gtol=1e-15)
        if np.sum(np.abs(r.fun)) < 1e-9:
            found.append((r.x[2], np.remainder(r.x[0] + np.pi, 2 * np.pi) - np.pi, r.x[1]))
    found.sort()
    seen = []
    for f in found:
        if not any(abs(f[0] - g[0]) < 1e-7 and abs(f[1] - g[1]) < 1e-6 for g in seen):
            seen.append(f)
            print('t = %.12f  psi0 = %.12f  psidot0 = %.12g  k = %.3g' %
                  (f[0], f[1], f[2], np.hypot(np.sin(f[1]), f[2])))


if __name__ == '__main__':
    main()
