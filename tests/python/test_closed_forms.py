"""The module's values against the paper's closed forms (docs/physics.md §2, §7): the line preset
y = 0.5 x + 1 from x = 0, paper (80)-(81), and the circle preset of radius R = 2 from (2, 0),
paper (89)-(96), for the sleigh m = 1, a = 0.5, b = 1 at v_T = 1 and for the disk. Written from
the formulas here, not from the program."""
import math

import numpy as np
import pytest

M, A_CM, B, VT = 1.0, 0.5, 1.0, 1.0
SLOPE, OFFSET, X_END = 0.5, 1.0, 8.0
R = 2.0


def close(got, want, scale=1.0, tol=1e-12):
    """|got - want| <= tol * scale at every time (scale: 1 + v_T t for positions)."""
    error = np.abs(np.asarray(got) - want) / scale
    assert np.max(error) <= tol, f"max error {np.max(error):.3g} of the scale, at index {np.argmax(error)}"


def test_line(cl):
    solution = cl.Scene.preset("line").solve()
    length = X_END * math.hypot(1.0, SLOPE)
    assert solution.duration == pytest.approx(length / VT, rel=1e-14)
    assert solution.path_length == pytest.approx(length, rel=1e-14)
    t = np.linspace(0.0, solution.duration, 1001)
    v = solution.sample(t)
    x = VT * t / math.sqrt(1.0 + SLOPE**2)  # paper (80)
    close(v["x"], x, 1.0 + VT * t)
    close(v["y"], SLOPE * x + OFFSET, 1.0 + VT * t)  # paper (81)
    close(v["s"], VT * t, 1.0 + VT * t)
    close(v["phi"], math.atan(SLOPE))
    close(v["psi"], math.pi / 2)  # Psi = atan2(1, b kappa) with kappa = 0
    close(v["lambda"], 0.0)
    close(v["energy"], M * VT**2 / 2)
    close(v["sdot"], VT)
    # the free body from the same state (phidot = 0) runs the same line
    close(v["free_x"], x, 1.0 + VT * t)
    close(v["free_y"], SLOPE * x + OFFSET, 1.0 + VT * t)


@pytest.mark.parametrize("system", ["sleigh", "disk"])
def test_circle(cl, system):
    scene = cl.Scene.preset("circle")
    if system == "disk":
        scene = scene.replace(system=cl.Disk(m=2, R=0.3, I1=0.09, I2=0.045))
    derived = scene.system.derived
    m, a, b = derived["m_eff"], derived["a"], derived["b"]
    solution = scene.solve()
    omega = VT / math.sqrt(b * b + R * R)  # paper (95)
    assert solution.duration == pytest.approx(2 * math.pi / omega, rel=1e-13)
    t = np.linspace(0.0, solution.duration, 1001)
    v = solution.sample(t)
    close(v["x"], R * np.cos(omega * t), 1.0 + VT * t)  # paper (93)
    close(v["y"], R * np.sin(omega * t), 1.0 + VT * t)  # paper (94)
    close(v["phi"], math.pi / 2 + omega * t, 1.0 + omega * t)
    close(v["psi"], math.atan2(1.0, b / R))
    close(v["sdot"], R * omega)
    close(v["phidot"], omega)
    close(v["psidot"], 0.0)
    # lambda = m b chidot with chi = Psi - (a/b) phi: -m a phidot (docs/physics.md §2; 0 for the
    # disk, whose centre of mass is above the contact point)
    close(v["lambda"], -m * a * omega)
    close(v["energy"], m * VT**2 / 2)
    close(v["free_energy"], m * VT**2 / 2)


def test_circle_in_constant_speed_mode(cl):
    # App. C: sdot = v_s, so phi turns at v_s/R and the period is 2 pi R/v_s
    vs = 0.7
    solution = cl.Scene.preset("circle").replace(mode="speed", v_s=vs).solve()
    assert solution.duration == pytest.approx(2 * math.pi * R / vs, rel=1e-13)
    t = np.linspace(0.0, solution.duration, 101)
    v = solution.sample(t, columns=["x", "y", "sdot"])
    assert list(v) == ["x", "y", "sdot"]
    close(v["x"], R * np.cos(vs * t / R), 1.0 + vs * t)
    close(v["y"], R * np.sin(vs * t / R), 1.0 + vs * t)
    close(v["sdot"], vs)
