"""Reference counts and lifetime: a Solution keeps what it needs (its own copy of the scene and the
tabulated path), so it outlives the Scene it was solved from; sample() returns arrays that own
their data (or, from 4 MB, their mapping) and outlive the Solution; nothing is leaked by
sampling."""
import gc
import os
import sys
import tracemalloc

import numpy as np
import pytest


def test_a_solution_outlives_its_scene(cl):
    scene = cl.Scene(path="y=-sin(x)", x_range=(0, 6), system=cl.Sleigh(m=1, a=0.5, b=1))
    solution = scene.solve()
    before = solution.sample([0.0, 1.0, 2.0])
    del scene
    gc.collect()
    after = solution.sample([0.0, 1.0, 2.0])
    for name in before:
        assert np.array_equal(before[name], after[name]), name
    assert solution.scene.path == "y=-sin(x)"


def test_a_solution_from_a_temporary_scene(cl):
    # the done-when line: the Scene is a temporary gone before sample() runs
    x = cl.Scene.preset("catenary").solve().sample([0, 1, 2])["x"]
    gc.collect()
    assert x[0] == pytest.approx(1.0, abs=1e-14) and x.shape == (3,)  # the catenary starts at (1, 0)


def test_arrays_own_their_data_and_outlive_the_solution(cl):
    solution = cl.Scene.preset("circle").solve()
    values = solution.sample(np.linspace(0, 5, 11))
    for name in values:
        array = values[name]
        assert array.flags.owndata and array.flags.writeable, name
        assert array.dtype == np.float64 and array.shape == (11,), name
        del array
        refs = sys.getrefcount(values[name])  # outside the assert, which pytest rewrites
        assert refs == 2, name  # the dict's and the call's argument
    del solution
    gc.collect()
    assert values["x"][0] == 2.0


def resident_bytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def test_long_arrays_hold_their_own_mapping_and_give_it_back(cl):
    # 2^20 times: an 8 MB column, mapped for itself; the same values as short arrays give, of the
    # times' shape, writeable, alive after the Solution and the dict, unmapped with the last view
    solution = cl.Scene.preset("catenary").solve()
    t = np.linspace(0, solution.t_end, 2**20).reshape(2**10, 2**10)
    before = resident_bytes()
    values = solution.sample(t, columns=["x", "psi"])
    x = values["x"]
    assert x.shape == t.shape and x.dtype == np.float64
    assert x.flags.c_contiguous and x.flags.writeable and x.base is not None
    assert not np.shares_memory(x, values["psi"])
    short = solution.sample(t[::97, ::89], columns=["x", "psi"])
    assert short["x"].flags.owndata
    assert np.array_equal(x[::97, ::89], short["x"])
    assert np.array_equal(values["psi"][::97, ::89], short["psi"])
    assert resident_bytes() - before >= 2 * 8 * 2**20  # both columns written
    corner = x[-1:, -1:]  # a view keeps the whole mapping
    del solution, values, x
    gc.collect()
    corner[0, 0] = 1.5
    assert corner[0, 0] == 1.5
    held = resident_bytes()
    del corner
    gc.collect()
    assert held - resident_bytes() >= 8 * 2**20  # the x column's mapping is given back


def test_sampling_holds_no_references(cl):
    solution = cl.Scene.preset("sinusoid").solve()
    t = np.linspace(0, 3, 50)
    refs_solution, refs_t = sys.getrefcount(solution), sys.getrefcount(t)
    for _ in range(20):
        solution.sample(t)
        solution.summary
        solution.scene
    refs = sys.getrefcount(solution), sys.getrefcount(t)
    assert refs == (refs_solution, refs_t)


def test_sampling_does_not_leak(cl):
    solution = cl.Scene.preset("catenary").solve()
    t = np.linspace(0, solution.t_end, 20000)
    solution.sample(t)
    gc.collect()
    tracemalloc.start()
    try:
        base, _ = tracemalloc.get_traced_memory()
        for _ in range(10):
            values = solution.sample(t)  # 27 arrays of 160 kB each time
            del values
        gc.collect()
        now, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak - base > 27 * 20000 * 8  # the arrays were seen
    assert now - base < 100_000, f"{now - base} bytes kept after ten samples"


def test_shapes_follow_the_times(cl):
    solution = cl.Scene.preset("line").solve()
    assert solution.sample(1.5)["x"].shape == ()
    assert solution.sample(np.zeros((2, 3)))["y"].shape == (2, 3)
    assert solution.sample([])["x"].shape == (0,)
    # integers and other dtypes are converted; a non-contiguous view is copied first
    grid = np.arange(9)
    assert np.array_equal(solution.sample(grid)["t"], grid.astype(float))
    strided = np.linspace(0, 8, 20)[::2]
    assert np.array_equal(solution.sample(strided)["x"], solution.sample(strided.copy())["x"])
