"""SIGINT and SIGTERM end a long run within a second, with exit status 130,
one message line, and nothing written: no output directory, no staging
directory left beside it. (A signal that comes while the process is still
being loaded ends it the default way, before it has done anything.) The signals come at seeded random moments of
runs on 100,000-vertex pairs, so they land in different stages (reading,
validation, ear clipping, the construction, remeshing)."""
import math
import os
import random
import signal
import subprocess
import time

import pytest

N = 100_000


def star(path, n, inner, wobble):
    with open(path, "w", encoding="utf-8") as f:
        for i in range(n):
            a = 2 * math.pi * i / n
            r = (1.0 if i % 2 == 0 else inner) * (1 + 0.1 * math.sin(wobble * a))
            f.write(f"{r * math.cos(a):.17g} {r * math.sin(a):.17g}\n")


@pytest.fixture(scope="module")
def big_pair(tmp_path_factory):
    folder = tmp_path_factory.mktemp("big")
    a, b = folder / "a.xy", folder / "b.xy"
    star(a, N, 0.6, 0)
    star(b, N, 0.3, 3)
    return a, b


def signal_and_wait(process, signum):
    """Sends the signal; the process must end within a second. Its stderr."""
    sent = time.monotonic()
    process.send_signal(signum)
    try:
        _, stderr = process.communicate(timeout=20)
    finally:
        process.kill()
    took = time.monotonic() - sent
    assert took < 1.0, f"ended {took:.2f} s after the signal"
    return stderr


MOMENTS = random.Random(20261124).sample([0.05 * i for i in range(1, 60)], 6)


@pytest.mark.parametrize("moment", MOMENTS, ids=lambda t: f"{t:.2f}s")
@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
def test_signal_ends_run_within_a_second(compatmesh_path, big_pair, tmp_path, moment, signum):
    out = tmp_path / "out"
    process = subprocess.Popen([compatmesh_path, "triangulate", str(big_pair[0]), str(big_pair[1]),
                                "--out-dir", str(out)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, encoding="utf-8")
    time.sleep(moment)
    stderr = signal_and_wait(process, signum)
    if process.returncode == -signum:  # before the handlers were installed
        assert stderr == ""
    else:
        assert process.returncode == 130, stderr
        assert stderr.strip().splitlines() == ["compatmesh: interrupted; nothing written"]
    assert not out.exists()
    assert [p for p in os.listdir(tmp_path) if p != "out"] == []


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
def test_signal_while_gmsh_writes(compatmesh_path, tmp_path, signum):
    """A sweep's .msh is written by Gmsh, which polls no flag (about 2 s for
    the 120 MB here): a signal once its temporary file exists still ends
    the run within a second (3.7 s before), and removes that file."""
    star(tmp_path / "a.xy", 2000, 0.6, 0)
    star(tmp_path / "b.xy", 2000, 0.3, 3)
    process = subprocess.Popen([compatmesh_path, "sweep", "a.xy", "b.xy", "-o", "out.msh", "--sections", "400"],
                               cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, encoding="utf-8")
    writing = lambda: any(name.startswith(".out.compatmesh-") for name in os.listdir(tmp_path))  # noqa: E731
    started = time.monotonic()
    while process.poll() is None and not writing() and time.monotonic() - started < 60:
        time.sleep(0.005)
    assert process.poll() is None, "the sweep ended before it wrote"
    time.sleep(0.1)
    stderr = signal_and_wait(process, signum)
    assert process.returncode == 130, stderr
    assert stderr.strip().splitlines()[-1] == "compatmesh: interrupted; nothing written"
    assert sorted(os.listdir(tmp_path)) == ["a.xy", "b.xy"]
