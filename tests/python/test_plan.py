"""plan(), its Motion objects and Scene.from_plan (docs/physics.md §10) against references written
here: an integration of the genuine vakonomic equations (19)-(21) by SciPy's DOP853 at 1e-12 from
each motion's start, the sideways shift's known answer, and the tracking scene's controlled body
against the motion's own closed form."""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

M, A_CM, B, VT = 2.0, 0.3, 0.8, 1.5


def integrated(motion, start, t):
    """(x, y, phi, lambda) at the times t from (19)-(21): m sddot = lc phidot,
    m b^2 phiddot = -lc sdot, lc' = -m sdot phidot, lambda = lc - m a phidot."""
    x0, y0, phi0 = start
    sdot0 = VT * math.sin(motion.psi0)
    phidot0 = VT * math.cos(motion.psi0) / B
    lc0 = motion.lambda0 + M * A_CM * phidot0

    def rhs(_, s):
        x, y, phi, sd, pd, lc = s
        return [sd * math.cos(phi), sd * math.sin(phi), pd, lc * pd / M, -lc * sd / (M * B * B),
                -M * sd * pd]

    sol = solve_ivp(rhs, (0, t[-1]), [x0, y0, phi0, sdot0, phidot0, lc0], method="DOP853",
                    rtol=1e-12, atol=1e-12, t_eval=t)
    x, y, phi, _, pd, lc = sol.y
    return x, y, phi, lc - M * A_CM * pd


def test_motions_end_on_the_target_as_integrated(cl):
    system = cl.Sleigh(m=M, a=A_CM, b=B)
    start, target = (0.3, -0.2, 0.7), (1.1, 0.9, -1.2)
    motions = cl.plan(start, target, system=system, v_T=VT)
    assert len(motions) >= 2
    assert [m.t for m in motions] == sorted(m.t for m in motions)
    assert sum(m.optimal for m in motions) == 1 and motions[0].optimal
    for m in motions:
        assert m.family in ("libration", "rotation", "separatrix", "line", "pivot")
        assert -math.pi < m.psi0 <= math.pi
        assert m.psidot0 == pytest.approx(m.lambda0 / (M * B) + A_CM * VT * math.cos(m.psi0) / B**2,
                                          abs=1e-12)
        t = np.linspace(0, m.t, 41)
        v = m.sample(t)
        assert set(v) == {"t", "vak_x", "vak_y", "vak_phi", "vak_sdot", "vak_phidot", "vak_lambda"}
        x, y, phi, lam = integrated(m, start, t)
        scale = 1 + VT * t
        assert np.max(np.abs(v["vak_x"] - x) / scale) < 1e-9
        assert np.max(np.abs(v["vak_y"] - y) / scale) < 1e-9
        assert np.max(np.abs(v["vak_phi"] - phi)) < 1e-9
        assert np.max(np.abs(v["vak_lambda"] - lam)) < 1e-9
        end = (v["vak_x"][-1] - target[0], v["vak_y"][-1] - target[1],
               math.remainder(v["vak_phi"][-1] - target[2], 2 * math.pi))
        assert abs(end[0]) / B + abs(end[1]) / B + abs(end[2]) < 1e-10
        assert m.optimal == (m.cut_time is not None and m.t <= m.cut_time + 1e-12
                             and m.t == motions[0].t)


def test_sideways_shift_two_mirror_optima(cl):
    motions = cl.plan((0, 0, 0), (0, 1, 0))
    best = [m for m in motions if m.optimal]
    assert len(best) == 2
    for m in best:
        assert m.t == pytest.approx(3.340383019231, abs=1e-11)
        assert m.psidot0 == pytest.approx(1.492853942033, abs=1e-11)
    assert sorted(m.psi0 for m in best) == pytest.approx([-1.107148717794, 2.034443935796],
                                                          abs=1e-11)


def test_scene_from_plan_tracks_the_genuine_vakonomic_body(cl):
    system = cl.Sleigh(m=M, a=A_CM, b=B)
    for target in ((1.1, 0.9, -1.2), (0, B, 0), (0, 0, math.pi), (-1.2, 0, 0)):
        for m in cl.plan((0, 0, 0), target, system=system, v_T=VT)[:3]:
            scene = cl.Scene.from_plan(m)
            assert scene.system == system and scene.speed == VT
            solution = scene.solve()
            assert solution.duration == pytest.approx(m.t, rel=1e-12)
#the track's time law by quadrature and the planned t agree to rounding
            got = solution.sample(np.linspace(0, solution.t_end, 61))
            want = m.sample(np.linspace(0, m.t, 61))
            for a in ("x", "y", "phi", "lambda"):
                assert np.max(np.abs(got[a] - want["vak_" + a])) < 1e-8, (target, m, a)
                assert np.max(np.abs(got["vak_" + a] - want["vak_" + a])) < 1e-8, (target, m, a)


def test_bad_input(cl):
    with pytest.raises(cl.InputError, match="horizon"):
        cl.plan((0, 0, 0), (1, 0, 0), horizon=0)
    with pytest.raises(cl.InputError, match="horizon"):
        cl.plan((0, 0, 0), (1, 0, 0), horizon=-1)
    with pytest.raises(cl.InputError):
        cl.plan((0, 0, float("nan")), (1, 0, 0))
    with pytest.raises(cl.InputError, match="target"):
        cl.plan((0, 0, 0), (1, 0))
    assert cl.plan((0, 0, 0), (30, 1, 0), horizon=1) == []
    m = cl.plan((0, 0, 0), (1, 0.5, 0))[0]
    with pytest.raises(cl.InputError, match="outside"):
        m.sample([m.t + 1])
    rest = cl.plan((0, 0, 0), (0, 0, 0))[0]
    with pytest.raises(cl.InputError, match="no track"):
        cl.Scene.from_plan(rest)
