"""The module is as strict as the C API: values the core could only
misread are refused with the Python exception that says so, and Ctrl-C
stops a long call."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import compatmesh


def test_complex_coordinates_are_refused(octagon, star):
    with pytest.raises(TypeError, match="polygon 1: complex values are not coordinates"):
        compatmesh.triangulate([octagon, star.astype(complex)])


def test_complex_times_and_heights_are_refused(octagon, star):
    with pytest.raises(TypeError, match="complex"):
        compatmesh.morph([octagon, star], t=[0.5 + 1j])
    with pytest.raises(TypeError, match="complex"):
        compatmesh.sweep([octagon, star], heights=[0, 1j])


@pytest.mark.parametrize("value", [float("nan"), float("inf"), -1e-3])
def test_bad_planarity_tolerance_is_a_value_error(octagon, star, value):
    spatial = np.c_[octagon, np.zeros(len(octagon))]
    with pytest.raises(ValueError, match="planarity_tolerance"):
        compatmesh.triangulate([spatial, star], planarity_tolerance=value)


@pytest.mark.parametrize("option", ["min_angle_deg"])
@pytest.mark.parametrize("value", [float("nan"), float("inf"), float("-inf")])
def test_non_finite_numbers_are_value_errors(octagon, star, option, value):
    with pytest.raises(ValueError, match=f"{option} must be finite"):
        compatmesh.triangulate([octagon, star], **{option: value})


@pytest.mark.parametrize("option", ["max_steiner", "k_split", "area_every", "max_iterations"])
def test_ints_that_do_not_fit_are_overflow_errors(octagon, star, option):
    with pytest.raises(OverflowError, match=f"{option} = {2 ** 70} is too large"):
        compatmesh.triangulate([octagon, star], **{option: 2 ** 70})
    with pytest.raises(OverflowError, match="too small"):
        compatmesh.triangulate([octagon, star], **{option: -2 ** 70})


def test_frames_and_sections_are_limited(octagon, star):
    with pytest.raises(ValueError, match="frames must be 2 to 1000, got 10000000"):
        compatmesh.morph([octagon, star], frames=10 ** 7)
    with pytest.raises(ValueError, match="at most 1000 times"):
        compatmesh.morph([octagon, star], t=np.linspace(0, 1, 1001))
    with pytest.raises(ValueError, match="sections must be .auto. or 2 to 10000, got 1000000"):
        compatmesh.sweep([octagon, star], sections=10 ** 6)
    with pytest.raises(ValueError, match="sections must not be negative"):
        compatmesh.sweep([octagon, star], sections=-1)


def big_star(n, inner, wobble):
    a = 2 * np.pi * np.arange(n) / n
    r = np.where(np.arange(n) % 2, inner, 1.0) * (1 + 0.1 * np.sin(wobble * a))
    return np.c_[r * np.cos(a), r * np.sin(a)]


@pytest.mark.parametrize("delay", [0.3, 1.0, 2.0])
def test_ctrl_c_stops_a_long_call_within_a_second(delay):
    a, b = big_star(100_000, 0.6, 0), big_star(100_000, 0.3, 3)
    timer = threading.Timer(delay, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    start = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):
            compatmesh.triangulate([a, b])
    finally:
        timer.cancel()
    assert time.monotonic() - start < delay + 1.0
