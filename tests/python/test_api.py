"""The module's concepts, named as in the docs: the column table (names, units and meanings are
the CSV's), scenes from presets, the gallery, JSON text and files and from Python, solutions and
their summary, the perturbed bodies and their tracking errors."""
import json

import numpy as np
import pytest

from conftest import SOURCE_DIR


def readme_columns():
    rows = {}
    text = (SOURCE_DIR / "README.md").read_text()
    for line in text.splitlines():
        if line.startswith("| `"):
            name, unit, meaning = [c.strip() for c in line.strip("|").split("|")]
            rows[name.strip("`")] = (unit, meaning)
    return rows


def test_the_column_table_is_the_readmes(cl):
    assert [c.name for c in cl.columns] == list(readme_columns())
    for c in cl.columns:
        assert (c.unit, c.meaning) == readme_columns()[c.name]
    assert cl.column("lambda").unit == "kg m/s"
    assert cl.column("fb_error").perturbed and not cl.column("x").perturbed
    assert "Column('x', unit='m'" in repr(cl.column("x"))


def test_presets_and_gallery_are_the_resources(cl):
    assert cl.Scene.preset_names() == ["line", "circle", "catenary", "sinusoid"]
    for name in cl.Scene.preset_names():
        path = SOURCE_DIR / "resources/scenes/presets" / f"{name}.json"
        assert cl.Scene.from_file(path) == cl.Scene.preset(name)
        assert cl.Scene.from_file(str(path)).preset_name == name
        assert cl.Scene.preset_description(name)
    gallery = {p.stem for p in (SOURCE_DIR / "resources/scenes/gallery").glob("*.json")}
    assert set(cl.Scene.gallery_names()) == gallery
    entries = cl.gallery_entries()
    assert [e["name"] for e in entries] == cl.Scene.gallery_names()
    assert all(e["title"] and e["note"] for e in entries)
    for e in entries:
        path = SOURCE_DIR / "resources/scenes/gallery" / f"{e['name']}.json"
        assert cl.Scene.from_file(path) == cl.Scene.gallery(e["name"])


def test_json_round_trip(cl):
    scene = cl.Scene(path="x=cos(u);y=sin(2*u)/2", u_range=(0, 3), system=cl.Disk(m=2),
                     mode="speed", v_s=0.5, t_end=4, perturbation=None, note="# homework 3")
    again = cl.Scene.from_json(scene.to_json())
    assert again == scene
    assert json.loads(scene.to_json())["system"]["kind"] == "disk"
    assert scene.path == "x=cos(u);y=sin(2*u)/2" and scene.path_range == (0.0, 3.0)
    assert scene.mode == "speed" and scene.speed == 0.5 and scene.t_end == 4.0
    assert scene.note == "# homework 3" and scene.points is None
    # pickled as its scene file (multiprocessing sends scenes to workers this way)
    import pickle
    assert pickle.loads(pickle.dumps(scene)) == scene


def test_scenes_built_in_python(cl):
    scene = cl.Scene(path="y=-sin(x)", x_range=(0, 4 * np.pi), system=cl.Sleigh(m=1, a=0.5, b=1),
                     mode="energy", v_T=1)
    assert scene.system == cl.Sleigh()
    assert scene.preset_name is None and scene.t_end is None and scene.perturbation is None
    sinusoid = cl.Scene.preset("sinusoid")
    assert scene.path == sinusoid.path
    assert repr(cl.Sleigh(I=0.5)) == "Sleigh(m=1, a=0.5, I=0.5)"
    assert cl.Sleigh(I=0.75).derived["b"] == pytest.approx(1.0)
    assert cl.Carriage().derived["a"] == 0.0
    poly = cl.Scene(points=np.array([[0, 0], [1, 0], [1, 1]]), corners="smooth", smoothing=0)
    assert poly.points == [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)] and poly.corners == "smooth"
    assert poly.path is None and poly.path_range is None
    speed = cl.Scene(path="y=x", x_range=(0, 1), v_s=2)
    assert speed.mode == "speed" and speed.speed == 2.0
    assert "Scene(path='y=x', x_range=(0, 1)" in repr(speed)


def test_drawn_points_pivot_where_they_turn_by_more_than_the_corner_angle(cl):
    # 81 points 5 cm apart on four 1 m strokes turning by 90 degrees, each moved by up to 5 mm
    rng = np.random.default_rng(27)
    c = np.sqrt(0.5)
    f = np.linspace(0, 4, 81)
    k = np.minimum(np.floor(f), 3)
    frac = f - k
    pts = np.column_stack([f * c, np.where(k % 2 == 0, frac, 1 - frac) * c])
    pts += rng.uniform(-0.005, 0.005, pts.shape)
    zig = cl.Scene(points=pts, corners="pivot")
    assert zig.corner_angle == 35.0
    assert zig.solve().summary["pivots"] == 3
    wide = cl.Scene(points=pts, corner_angle=100)
    assert wide.corner_angle == 100.0 and wide.solve().summary["pivots"] == 0
    with pytest.raises(cl.InputError, match="corner_angle"):
        cl.Scene(points=pts, corner_angle=-5)
    with pytest.raises(cl.InputError, match="corner_angle"):
        cl.Scene(path="y=x", x_range=(0, 1), corner_angle=30)


def test_a_solution(cl):
    solution = cl.Scene.preset("catenary").solve()
    assert solution.duration == pytest.approx(5.346171118810, rel=1e-12)  # docs/numerics.md §2
    assert solution.t_end == solution.duration and not solution.perturbed
    summary = solution.summary
    assert summary["preset"] == "catenary" and summary["b"] == 1.0
    assert solution.models == summary["models"]
    assert set(solution.models) == {"path", "time_law", "inversion", "control", "free_velocity",
                                    "free_position", "vakonomic"}
    assert [c.name for c in solution.columns] == [c.name for c in cl.columns if not c.perturbed]
    assert solution.scene == cl.Scene.preset("catenary")


def test_a_perturbation_with_feedback(cl):
    p = cl.Perturbation(dy=0.3, feedback_rate=1)
    assert p.dy == 0.3 and p.feedback_rate == 1 and p.t_push is None
    assert p.fields == {"dy": 0.3, "dphi": 0.0, "dpsi": 0.0, "feedback_rate": 1.0}
    scene = cl.Scene(path="x=2*cos(u);y=2*sin(u)", u_range=(0, 30), perturbation={"dy": 0.3})
    assert scene.perturbation == p
    solution = scene.solve()
    assert solution.perturbed and set(solution.models) >= {"perturbed", "feedback"}
    t = np.linspace(0, 20, 201)
    values = solution.sample(t)
    assert list(values) == [c.name for c in cl.columns]
    errors = solution.tracking_errors(t)
    assert set(errors) == {"t", "open_e", "open_theta", "fb_e", "fb_theta"}
    # the feedback body's error is the fb_error column, and it decays (docs/physics.md §9)
    np.testing.assert_allclose(errors["fb_e"], values["fb_error"], atol=1e-9)
    assert abs(errors["fb_e"][0] - 0.3) < 1e-12 and abs(errors["fb_e"][-1]) < 1e-3
    # the open loop keeps an oscillating error on the circle (docs/physics.md §9)
    assert np.max(np.abs(errors["open_e"][100:])) > 0.1
    assert scene.replace(perturbation=None).perturbation is None


def test_version(cl):
    assert cl.__version__.count(".") == 2
    assert isinstance(cl.InputError("x"), ValueError)


def test_the_readmes_example_runs(cl, capsys):
    text = (SOURCE_DIR / "README.md").read_text()
    section = text[text.index("## From Python"):]
    start = section.index("```python\n") + len("```python\n")
    block = section[start:section.index("\n```", start)]
    assert len(block.splitlines()) == 5
    exec(compile(block, "README.md, From Python", "exec"), {})
    duration, peak, unit = capsys.readouterr().out.split(maxsplit=2)
    assert float(duration) == pytest.approx(cl.Scene.preset("sinusoid").solve().duration)
    assert float(peak) > 0 and unit.strip() == "kg m/s"


def test_every_gallery_scene_solves_or_is_refused_as_the_program_says(cl):
    for e in cl.gallery_entries():
        scene = cl.Scene.gallery(e["name"])
        if e["rejected"]:
            with pytest.raises(cl.InputError) as error:
                scene.solve()
            assert e["message"] in str(error.value), e["name"]
        else:
            solution = scene.solve()
            values = solution.sample(np.linspace(0, solution.t_end, 101))
            assert all(np.all(np.isfinite(a)) for a in values.values()), e["name"]
