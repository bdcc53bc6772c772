"""The sleigh's "b or I" rule and the speed's mode rules (docs/physics.md §1, §2) read the same way
by the module, the command line and the sweep: each gives the last of b and I that was set, and
b² = a² + I/m decides the other."""
import json
import math

import pytest

from conftest import run_cli


@pytest.fixture(scope="module")
def cl():
    import chaplygin_lab
    return chaplygin_lab


# (m, a, the settings in order, the b that follows from the last of b and I)
CASES = [
    (2.0, 0.3, [("b", 1.0), ("I", 0.5)], math.sqrt(0.3 ** 2 + 0.5 / 2.0)),
    (2.0, 0.3, [("I", 0.5), ("b", 1.0)], 1.0),
    (1.0, 0.5, [("I", 0.75)], 1.0),
]


def cli_summary(m, a, settings):
    params = ["--param", f"m={m}", "--param", f"a={a}"]
    for name, value in settings:
        params += ["--param", f"{name}={value}"]
    return json.loads(run_cli("--preset", "circle", *params, "--summary", "-"))


@pytest.mark.parametrize("m, a, settings, b", CASES)
def test_module_command_line_and_sweep_agree_on_b_or_I(cl, m, a, settings, b):
    module = cl.Sleigh(m=m, a=a, **dict(settings))
    swept = cl.Scene.preset("circle").replace(system=cl.Sleigh(m=m, a=a))
    for name, value in settings:
        swept = swept.with_parameter(name, value)
    summary = cli_summary(m, a, settings)
    inertia = m * (b * b - a * a)
    assert module.derived["b"] == pytest.approx(b, rel=1e-14)
    assert module.derived["I"] == pytest.approx(inertia, rel=1e-13, abs=1e-15)
    assert swept.system.derived["b"] == pytest.approx(b, rel=1e-14)
    assert swept.parameter("b") == pytest.approx(b, rel=1e-14)
    assert summary["b"] == pytest.approx(b, rel=1e-14)
    assert summary["I"] == pytest.approx(inertia, rel=1e-13, abs=1e-15)
    last = settings[-1][0]
    other = "I" if last == "b" else "b"
    assert f"{last}=" in repr(module) and f"{other}=" not in repr(module)
    assert f"{last}=" in repr(swept.system) and f"{other}=" not in repr(swept.system)


def test_speed_rules_name_the_setting(cl):
    with pytest.raises(ValueError, match="v_T.*not both"):
        cl.Scene.preset("circle").replace(v_T=1, v_s=1)
    with pytest.raises(ValueError, match='v_T.*in mode "speed" give v_s'):
        cl.Scene.preset("circle").replace(mode="speed", v_T=1)
    with pytest.raises(ValueError, match='v_s.*in mode "energy" give v_T'):
        cl.Scene.preset("circle").replace(mode="energy", v_s=1)
    assert cl.Scene.preset("circle").replace(v_s=2).mode == "speed"
