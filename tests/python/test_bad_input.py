"""Bad input raises chaplygin_lab.InputError, a ValueError with the core's message ("where: what")
and `where`, never a crash: the same words as the command line's, with the Python names."""
import math

import numpy as np
import pytest


def raises(cl, where, words, call):
    with pytest.raises(ValueError) as error:
        call()
    assert isinstance(error.value, cl.InputError)
    assert error.value.where == where
    message = str(error.value)
    assert message.startswith(where + ": ") if where else True, message
    for w in words:
        assert w in message, message
    return message


def test_expressions_name_the_character(cl):
    raises(cl, "y(x), position 4", ["Unexpected end of expression"],
           lambda: cl.Scene(path="y=x^", x_range=(0, 1)).solve())
    raises(cl, "path", ["expected y=EXPR, got 'sin(x)'"],
           lambda: cl.Scene(path="sin(x)", x_range=(0, 1)))
    raises(cl, "path", ['use "y=EXPR" or "x=EXPR;y=EXPR"'],
           lambda: cl.Scene(path="x=u;y=u;z=u", u_range=(0, 1)))


def test_ranges_and_path_kinds(cl):
    raises(cl, "x_range", ["needs x_range"], lambda: cl.Scene(path="y=x"))
    raises(cl, "u_range", ["needs u_range"], lambda: cl.Scene(path="x=u;y=u"))
    raises(cl, "u_range", ["use x_range"],
           lambda: cl.Scene(path="y=x", x_range=(0, 1), u_range=(0, 1)))
    raises(cl, "x_range", ["must differ"], lambda: cl.Scene(path="y=x", x_range=(1, 1)))
    raises(cl, "x_range", ["two numbers"], lambda: cl.Scene(path="y=x", x_range=(0, 1, 2)))
    raises(cl, "x_range", ["expects a number"], lambda: cl.Scene(path="y=x", x_range=(0, "a")))
    raises(cl, "path", ["no path"], lambda: cl.Scene())
    raises(cl, "path", ["not both"], lambda: cl.Scene(path="y=x", x_range=(0, 1), points=[(0, 0)]))
    raises(cl, "points, point 2", ["expects (x, y)"], lambda: cl.Scene(points=[(0, 0), (1,)]))
    raises(cl, "corners", ["applies only to points"],
           lambda: cl.Scene(path="y=x", x_range=(0, 1), corners="smooth"))
    raises(cl, "corners", ["unknown corner mode 'round'"],
           lambda: cl.Scene(points=[(0, 0), (1, 0)], corners="round"))


def test_a_point_on_the_path_is_named(cl):
    # the curve is not defined past x = 1: the place on the path is named
    message = raises(cl, "path at x = 1", [], lambda: cl.Scene(path="y=sqrt(1-x)",
                                                               x_range=(0, 2)).solve())
    assert message


def test_systems_name_the_parameter(cl):
    raises(cl, "parameter b", ["b"], lambda: cl.Sleigh(a=0.5, b=0.1))
    raises(cl, "parameter m", ["must be > 0"], lambda: cl.Sleigh(m=-1))
    raises(cl, "parameter R", ["must be a finite number"], lambda: cl.Disk(R=math.nan))
    raises(cl, "parameter q", ["unknown for the sleigh"], lambda: cl.Sleigh(q=1))
    raises(cl, "parameter m", ["expects a number, got 'heavy'"], lambda: cl.Sleigh(m="heavy"))


def test_motion_and_horizon(cl):
    raises(cl, "mode", ["unknown mode 'fast'"],
           lambda: cl.Scene(path="y=x", x_range=(0, 1), mode="fast"))
    raises(cl, "v_T", ["give v_s"], lambda: cl.Scene(path="y=x", x_range=(0, 1), mode="speed",
                                                     v_T=1))
    raises(cl, "v_s", ["give v_T"], lambda: cl.Scene(path="y=x", x_range=(0, 1), mode="energy",
                                                     v_s=1))
    raises(cl, "v_T", ["not both"], lambda: cl.Scene(path="y=x", x_range=(0, 1), v_T=1, v_s=1))
    raises(cl, "t_end", ["must be a finite number > 0"],
           lambda: cl.Scene(path="y=x", x_range=(0, 1), t_end=-1).solve())
    raises(cl, "replace", ["cannot be replaced"],
           lambda: cl.Scene.preset("line").replace(replace=1))


def test_perturbations(cl):
    raises(cl, "perturbation dphi", ["less than pi/2"], lambda: cl.Perturbation(dphi=2))
    raises(cl, "perturbation", ["dy, dphi"], lambda: cl.Perturbation(wobble=1))
    raises(cl, "perturbation", ["a Perturbation or a dict"],
           lambda: cl.Scene(path="y=x", x_range=(0, 1), perturbation=3))
    raises(cl, "perturbation", ["constant-energy mode"],
           lambda: cl.Scene.preset("circle").replace(mode="speed", perturbation={"dy": 0.1})
           .solve())


def test_scene_files_name_the_json_path(cl, tmp_path):
    raises(cl, "scene file /system/params/m", [],
           lambda: cl.Scene.from_json(cl.Scene.preset("line").to_json().replace('"m": 1.0',
                                                                                 '"m": "heavy"')))
    raises(cl, "preset", ["unknown preset 'spiral'", "catenary"], lambda: cl.Scene.preset("spiral"))
    raises(cl, "gallery", ["unknown gallery scene 'nope'"], lambda: cl.Scene.gallery("nope"))
    missing = tmp_path / "missing.json"
    with pytest.raises(ValueError) as error:
        cl.Scene.from_file(missing)
    assert str(missing) in str(error.value)
    with pytest.raises(ValueError):
        cl.Scene.from_json("{")


def test_sampling(cl):
    solution = cl.Scene.preset("line").solve()
    horizon = f"is outside [0, {solution.t_end!r}], the scene's horizon t_end"
    raises(cl, "t", ["-1 s at index 1", horizon], lambda: solution.sample([0, -1]))
    raises(cl, "t", ["nan s at index 2", horizon], lambda: solution.sample([0, 1, np.nan]))
    raises(cl, "t", ["inf s at index 0", horizon], lambda: solution.sample(np.inf))
    raises(cl, "t", ["9 s at index 1", horizon], lambda: solution.sample([8.9, 9.0]))
    raises(cl, "columns", ["unknown column 'z'", "t, s, x"],
           lambda: solution.sample([0], columns=["x", "z"]))
    raises(cl, "columns", ["no perturbation"], lambda: solution.sample([0], columns=["fb_x"]))
    raises(cl, "threads", ["whole number"], lambda: solution.sample([0], threads=0))
    raises(cl, "tracking_errors", ["no perturbation"], lambda: solution.tracking_errors([0]))
    raises(cl, "column", ["unknown column"], lambda: cl.column("nope"))
    with pytest.raises(TypeError):  # not a number at all: pybind11's type check
        solution.sample("soon")


def test_sweeps(cl):
    scene = cl.Scene.preset("catenary")
    raises(cl, "sweep b", [], lambda: scene.sweep("b", 0.1, 1, 3))
    raises(cl, "sweep R", ["unknown parameter for the sleigh"],
           lambda: scene.with_parameter("R", 1))


def test_a_scene_that_is_not_finite_is_refused(cl):
    # a stroke drawn at y = 1e308 (the randomized GUI test's seed 90210): its smoothed path's
    # interpolant overflows; solve() raises instead of giving arrays of NaN
    scene = cl.Scene.from_json("""{
      "format": "chaplygin-lab-scene", "version": 1, "mode": "energy", "speed": 1.8023,
      "path": {"kind": "polyline", "corners": "smooth", "smoothing": 18.0,
               "points": [[511419.63480199594, 1e308], [-68580.36519800406, 1e308],
                          [964419.6348019959, 1e308]]},
      "system": {"kind": "disk", "params": {"I1": 0.125, "I2": 0.586, "R": 0.5, "m": 9.0448}}
    }""")
    raises(cl, "path at (202370.34088993404, 1e+308)",
           ["the path's interpolant is not finite here", "overflow double precision"],
           lambda: scene.solve())
