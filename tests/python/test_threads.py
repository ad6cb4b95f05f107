"""The GIL is released during the C call: other Python threads keep running,
and calls in separate threads give the same answers."""
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import compatmesh
from conftest import ring


def timed_call(polygons):
    """Runs triangulate in a thread while this thread keeps ticking; returns
    the call's duration and the longest pause between ticks during it."""
    done = threading.Event()
    span = {}

    def work():
        span["start"] = time.perf_counter()
        compatmesh.triangulate(polygons, remesh=False)
        span["end"] = time.perf_counter()
        done.set()

    worker = threading.Thread(target=work)
    ticks = []
    worker.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
    worker.join()
    inside = [t for t in ticks if span["start"] <= t <= span["end"]]
    stamps = [span["start"], *inside, span["end"]]
    return span["end"] - span["start"], max(b - a for a, b in zip(stamps, stamps[1:]))


def test_other_threads_run_during_the_call():
    # Grow the input until the call is long enough to tell a released GIL
    # (pauses of a few ms) from a held one (one pause as long as the call).
    for n in (400, 800, 1600, 3200):
        duration, longest_pause = timed_call([ring(n, 1.0), ring(n, 0.5)])
        if duration >= 0.3:
            break
    else:
        pytest.skip("the core is too fast here to observe the GIL")
    # A held GIL stops this thread for about the whole call.
    assert longest_pause < 0.5 * duration, (duration, longest_pause)


def test_threads_agree():
    polygons = [[ring(12, inner), ring(12, 0.5)] for inner in (1.0, 0.8, 0.6, 0.4)]
    expected = [compatmesh.triangulate(p).faces for p in polygons]
    with ThreadPoolExecutor(max_workers=4) as pool:
        results = list(pool.map(lambda p: compatmesh.triangulate(p).faces, polygons * 2))
    for got, want in zip(results, expected * 2):
        assert np.array_equal(got, want)
