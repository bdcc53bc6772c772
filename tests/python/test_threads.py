"""Thread safety: sample() releases the GIL, and concurrent samples of one Solution from several
Python threads give exactly the values of a single-threaded run, as do samples spread over
threads inside C++ (threads=...)."""
import threading

import numpy as np


def test_concurrent_samples_are_identical(cl):
    solution = cl.Scene.gallery("pushed-off-path").solve()  # every body, the perturbed ones too
    t = np.linspace(0, solution.t_end, 4001)
    want = solution.sample(t, threads=1)
    results = [None] * 6

    def work(k):
        # each thread in its own order, so their per-thread caches see different histories
        order = t[::-1] if k % 2 else t
        got = solution.sample(order, threads=1)
        results[k] = {n: (a[::-1] if k % 2 else a) for n, a in got.items()}

    workers = [threading.Thread(target=work, args=(k,)) for k in range(len(results))]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    for k, got in enumerate(results):
        assert got is not None, f"thread {k} failed"
        for name in want:
            assert np.array_equal(got[name], want[name]), (k, name)


def test_threads_inside_cpp_give_the_same_values(cl):
    solution = cl.Scene.preset("sinusoid").solve()
    t = np.linspace(0, solution.t_end, 50001)
    one = solution.sample(t, threads=1)
    for threads in (2, 3, 7):
        many = solution.sample(t, threads=threads)
        for name in one:
            assert np.array_equal(one[name], many[name]), (threads, name)


def test_the_gil_is_released_while_sampling(cl):
    # a Python thread counts while another samples a long array: with the GIL held for the whole
    # call the counter could not move
    solution = cl.Scene.preset("catenary").solve()
    t = np.linspace(0, solution.t_end, 400000)
    counter = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counter[0] += 1

    counting = threading.Thread(target=count)
    counting.start()
    try:
        before = counter[0]
        solution.sample(t, threads=1)
        during = counter[0] - before
    finally:
        stop.set()
        counting.join()
    assert during > 1000, f"the counter moved {during} times while sampling"
