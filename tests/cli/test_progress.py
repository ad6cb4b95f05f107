"""On a terminal, a run longer than two seconds shows its stage and
progress on one stderr line, erased when the run ends; off a terminal
(every other test) stderr stays silent but for errors. --progress shows it
from the start (off a terminal as plain lines), --quiet shows nothing, not
even the summary on stdout."""
import os
import pty
import re
import select
import signal
import subprocess
import time

import pytest

from polygons import star, write_xy


def drain(main, process):
    """What is left to read on the terminal `main` until the process has
    ended and the terminal is empty or closed; closes it."""
    seen = b""
    while True:
        ready, _, _ = select.select([main], [], [], 0.5)
        try:
            chunk = os.read(main, 4096) if ready else b""
        except OSError:  # the other end closed
            chunk = b""
        if not chunk and process.poll() is not None:
            break
        seen += chunk
    os.close(main)
    return seen


def test_progress_line_on_a_terminal(compatmesh_path, tmp_path):
    # large enough to run well past the two-second grace (about 8 s of CPU)
    write_xy(tmp_path / "a.xy", star(100000, 1))
    write_xy(tmp_path / "b.xy", star(100000, 2))
    main, sub = pty.openpty()
    process = subprocess.Popen([compatmesh_path, "triangulate", "a.xy", "b.xy", "-o", "out"],
                               cwd=tmp_path, stdout=subprocess.DEVNULL, stderr=sub)
    os.close(sub)
    seen = b""
    deadline = time.monotonic() + 60
    while b"%" not in seen and process.poll() is None and time.monotonic() < deadline:
        ready, _, _ = select.select([main], [], [], 0.2)
        if ready:
            seen += os.read(main, 4096)
    process.send_signal(signal.SIGINT)
    process.wait(timeout=10)
    seen += drain(main, process)
    text = seen.decode()
    assert process.returncode == 130
    assert "\rcompatmesh: " in text and "%" in text, text
    assert text.endswith("\r\x1b[Kcompatmesh: interrupted; nothing written\r\n"), repr(text[-120:])


def run_on_terminal(args, cwd):
    """stderr of a run whose stderr is a terminal (read until it closes)."""
    main, sub = pty.openpty()
    process = subprocess.Popen(args, cwd=cwd, stdout=subprocess.DEVNULL, stderr=sub)
    os.close(sub)
    seen = drain(main, process)
    return process.wait(timeout=60), seen.decode()


def test_progress_shows_a_short_run_on_a_terminal(compatmesh_path, tmp_path):
    # Without --progress a run this short prints nothing (two-second grace).
    write_xy(tmp_path / "a.xy", star(60, 1))
    write_xy(tmp_path / "b.xy", star(60, 2))
    code, text = run_on_terminal([compatmesh_path, "triangulate", "a.xy", "b.xy", "-o", "quiet"],
                                 tmp_path)
    assert code == 0 and text == "", repr(text)
    code, text = run_on_terminal([compatmesh_path, "triangulate", "a.xy", "b.xy", "-o", "out",
                                  "--progress"], tmp_path)
    assert code == 0
    assert re.search(r"\rcompatmesh: .+ +\d+%", text), repr(text)
    assert "\n" not in text.replace("\r\n", ""), repr(text)  # one line, rewritten in place
    assert text.endswith("\r\x1b[K"), repr(text[-80:])  # erased at the end


PLAIN_LINE = re.compile(r"compatmesh: (\S.*?) +(\d+)%  \(\d+\.\d s\)")


@pytest.mark.parametrize("command", ["triangulate", "morph"])
def test_progress_off_a_terminal_is_plain_lines(cm, tmp_path, command):
    write_xy(tmp_path / "a.xy", star(200, 1))
    write_xy(tmp_path / "b.xy", star(200, 2))
    result = cm(command, "a.xy", "b.xy", "-o", "out", "--progress")
    assert result.returncode == 0, result.stderr
    assert "\r" not in result.stderr and "\x1b" not in result.stderr
    matches = [PLAIN_LINE.fullmatch(line) for line in result.stderr.splitlines()]
    assert matches, "--progress printed nothing"
    assert all(m and 0 <= int(m.group(2)) <= 100 for m in matches), result.stderr
    # A line per stage and per tenth, not one per call: each stretch of one
    # stage prints at most 11 lines (0 % .. 100 %).
    stretches = 1 + sum(a.group(1) != b.group(1) for a, b in zip(matches, matches[1:]))
    assert len(matches) <= 11 * stretches, result.stderr
    assert result.stdout.startswith("wrote ")


def test_auto_progress_is_one_bar_over_its_pairings(cm, tmp_path):
    # Auto builds a second pairing of these glyphs (tests/cli/glyph_pairs):
    # each pairing runs every stage again, but the bar never goes back,
    # names the later pairings, and says "done" once, at the end.
    a, b = (os.path.join(os.path.dirname(__file__), "glyph_pairs", "Z003_G_Z_n48_" + s + ".xy") for s in "ab")
    result = cm("triangulate", a, b, "-o", "out", "--correspondence", "auto", "--progress")
    assert result.returncode == 0, result.stderr
    matches = [PLAIN_LINE.fullmatch(line) for line in result.stderr.splitlines()]
    assert matches and all(matches), result.stderr
    percents = [int(m.group(2)) for m in matches]
    stages = [m.group(1) for m in matches]
    assert percents == sorted(percents), result.stderr
    assert stages.count("done") == 1 and stages[-1] == "done" and percents[-1] == 100, result.stderr
    assert any(s.startswith("pairing 2: ") for s in stages), result.stderr


@pytest.mark.parametrize("command", ["triangulate", "morph"])
def test_quiet_prints_nothing_but_writes_everything(cm, tmp_path, command):
    write_xy(tmp_path / "a.xy", star(200, 1))
    write_xy(tmp_path / "b.xy", star(200, 2))
    loud = cm(command, "a.xy", "b.xy", "-o", "loud")
    assert loud.returncode == 0 and loud.stdout.startswith("wrote "), loud.stderr
    result = cm(command, "a.xy", "b.xy", "-o", "out", "--quiet")
    assert result.returncode == 0
    assert result.stdout == "" and result.stderr == ""
    assert sorted(os.listdir(tmp_path / "out")) == sorted(os.listdir(tmp_path / "loud"))


def test_quiet_still_reports_errors(cm, tmp_path):
    write_xy(tmp_path / "a.xy", star(20, 1))
    (tmp_path / "b.xy").write_text("0 0\n1 x\n")
    result = cm("triangulate", "a.xy", "b.xy", "-o", "out", "--quiet")
    assert result.returncode == 2
    assert result.stdout == ""
    assert result.stderr.startswith("compatmesh: ") and "b.xy" in result.stderr
    assert result.stderr.count("\n") == 1
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("command", ["triangulate", "morph", "sweep"])
def test_progress_and_quiet_exclude_each_other(cm, tmp_path, command):
    write_xy(tmp_path / "a.xy", star(20, 1))
    write_xy(tmp_path / "b.xy", star(20, 2))
    result = cm(command, "a.xy", "b.xy", "-o", "out", "--quiet", "--progress")
    assert result.returncode == 2
    assert result.stdout == ""
    assert result.stderr == f"compatmesh: {command}: give --progress or --quiet, not both\n"
    assert not (tmp_path / "out").exists()
