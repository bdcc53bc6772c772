"""plan(), its Motion objects and Scene.from_plan (docs/physics.md §10) against references written
here: an integration of the genuine vakonomic equations (19)-(21) by SciPy's DOP853 at 1e-12 from
each motion's start, the sideways shift's known answer, the tracking scene's controlled body
against the motion's own closed form, and 1 - k^2 against a 40-digit reference and the command
line's summary."""
import json
import math
import sys

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from conftest import SOURCE_DIR, run_cli

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


def end_miss_40_digits(motion, gap, target):
    """|dx| + |dy| + |dphi| at motion.t of the normalised motion (b = v_T = 1) from (0, 0, 0) of
    Psi0 = motion.psi0 with this 1 - k^2, from the pendulum's closed form in mpmath's own elliptic
    functions at 40 digits (tests/core/planning/far_target_reference.py, no code of the program)."""
    import mpmath as mp
    sys.path.insert(0, str(SOURCE_DIR / "tests/core/planning"))
    try:
        import far_target_reference as reference
    finally:
        sys.path.pop(0)
    with mp.workdps(40):
        cos0 = mp.cos(motion.psi0)
        lambda0 = mp.sqrt(cos0**2 - mp.mpf(gap))
        x, y, phi = reference.end_pose(mp.mpf(motion.psi0), lambda0, mp.mpf(motion.t))
        turn = phi - target[2]
        turn -= 2 * mp.pi * mp.nint(turn / (2 * mp.pi))
        return float(abs(x - target[0]) + abs(y - target[1]) + abs(turn))


def test_modulus_gap_is_one_minus_k_squared(cl):
    """1 - k^2 (docs/physics.md §10) against values derived independently of the program: the line
    (k = 1) and pivoting (k = 0) by their definitions, the sideways shift from the shared notes'
    Psi0 = -atan 2 and b Psidot0 / v_T, and a far target whose optimum lies next to the
    separatrix, where 1 - modulus**2 in double has lost its digits and modulus_gap has not."""
    line = cl.plan((0, 0, 0), (3, 0, 0), horizon=3.5)
    assert [m.family for m in line] == ["line"]
    assert line[0].modulus == 1 and line[0].modulus_gap == 0
    pivot = cl.plan((0, 0, 0), (0, 0, 1), horizon=1.5)
    assert [m.family for m in pivot] == ["pivot"]
    assert pivot[0].modulus == 0 and pivot[0].modulus_gap == 1
    # the sideways shift by b: k^2 = sin^2 Psi0 + Psidot0^2 with b = v_T = 1, sin^2 atan 2 = 4/5
    best = [m for m in cl.plan((0, 0, 0), (0, 1, 0)) if m.optimal]
    assert len(best) == 2
    for m in best:
        assert m.modulus_gap == pytest.approx(1 - 0.8 - 1.492853942033**2, abs=1e-11)
        assert m.family == "rotation" and m.modulus_gap < 0
    # (20, 0.5, 0.3): 1 - k^2 of the optimum from the 40-digit mpmath reference
    # (tests/core/planning/far_target_reference.py 20 0.5 0.3, its end checked by mpmath.odefun)
    gap = 2.5941070643728894849e-11
    far = [m for m in cl.plan((0, 0, 0), (20, 0.5, 0.3), horizon=21) if m.optimal]
    assert len(far) == 1 and far[0].family == "libration"
    assert abs(far[0].modulus_gap / gap - 1) < 1e-11, far[0].modulus_gap
    assert abs(far[0].modulus - math.sqrt(1 - gap)) < 1e-15
    # what the modulus alone gives: 1 - k^2 to the spacing of doubles below 1, 1.1e-16, which is
    # 4e-6 of this gap
    assert abs((1 - far[0].modulus**2) / gap - 1) > 1e-8, far[0].modulus
    # at 40 digits, the motion of psi0 with this 1 - k^2 (Lambda0 = +sqrt(cos^2 Psi0 - gap), as
    # psidot0 > 0) ends on the target at t; with 1 - modulus**2 it misses by far more
    assert far[0].psidot0 > 0
    assert end_miss_40_digits(far[0], far[0].modulus_gap, (20, 0.5, 0.3)) < 1e-12
    assert end_miss_40_digits(far[0], 1 - far[0].modulus**2, (20, 0.5, 0.3)) > 1e-8


def test_modulus_gap_is_the_command_lines(cl):
    """The same core number reaches --summary and the module: every listed motion's modulus and
    modulus_gap are the same doubles (the JSON's numbers read back exactly)."""
    for target, horizon in (((20, 0.5, 0.3), 21), ((0, 1, 0), None), ((3, 0, 0), 3.5)):
        args = ["--plan-to", ",".join(map(str, target)), "--summary", "-"]
        if horizon is not None:
            args += ["--plan-horizon", str(horizon)]
        listed = json.loads(run_cli(*args))["plan"]["geodesics"]
        motions = cl.plan((0, 0, 0), target, horizon=horizon)
        assert len(listed) == len(motions) >= 1
        for g, m in zip(listed, motions):
            assert g["t"] == m.t and g["family"] == m.family
            assert g["modulus"] == m.modulus and g["modulus_gap"] == m.modulus_gap, (g, m)


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
