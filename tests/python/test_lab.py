"""The method lab from Python: a parameter sweep is the command line's --sweep table to the last
bit (its CSV prints shortest round-trip doubles), and the work-precision table has the program's
rows, with the error formatted as its CSV prints it (%.6e)."""
import numpy as np

from conftest import cli_csv, floats


def test_sweep_is_the_programs(cl):
    header, csv = cli_csv("--preset", "sinusoid", "--sweep", "b=0.6:2.4:8")
    got = cl.Scene.preset("sinusoid").sweep("b", 0.6, 2.4, 8)
    assert list(got) == header
    for name in header:
        assert got[name].dtype == np.float64 and got[name].shape == (8,)
        assert np.array_equal(got[name], floats(csv[name])), name


def test_sweep_parameters_and_speed(cl):
    scene = cl.Scene.preset("circle")
    assert scene.sweep_parameters == ["m", "a", "I", "b", "vT"]
    got = scene.sweep("vT", 0.5, 2.0, 4)
    # on the circle the duration is 2 pi sqrt(b^2 + R^2)/v_T (paper (95))
    np.testing.assert_allclose(got["duration"], 2 * np.pi * np.sqrt(5.0) / got["vT"], rtol=1e-13)
    assert scene.with_parameter("b", 2.0).parameter("b") == 2.0
    assert "I" not in scene.with_parameter("b", 2.0).system.parameters


def test_work_precision_has_the_programs_rows(cl):
    header, csv = cli_csv("--preset", "circle", "--t-end", "3", "--work-precision")
    got = cl.Scene.preset("circle").replace(t_end=3).work_precision()
    assert list(got)[:7] == header and "energy_drift" in got
    n = len(got["method"])
    assert n > 20 and all(len(a) == n for a in got.values())
    assert got["chosen"].dtype == bool and got["rhs_evals"].dtype.kind == "i"
    ours = {(p, m, f"{s:.6g}"): f"{e:.6e}"
            for p, m, s, e in zip(got["problem"], got["method"], got["tolerance"], got["error"])}
    theirs = {(p, m, s): e for p, m, s, e in
              zip(csv["problem"], csv["method"], csv["tolerance"], csv["error"])}
    # a method's sweep stops after a slow solve, so the rows present depend on the machine's
    # speed; those present in both have the same error
    shared = ours.keys() & theirs.keys()
    assert len(shared) > 20
    for key in shared:
        assert ours[key] == theirs[key], key
    chosen = {(p, m) for p, m, c in zip(got["problem"], got["method"], got["chosen"]) if c}
    assert chosen == {(p, m) for p, m, c in zip(csv["problem"], csv["method"], csv["chosen"])
                      if c == "1"}
