"""On a terminal, a run longer than two seconds shows its stage and
progress on one stderr line, erased when the run ends; off a terminal
(every other test) stderr stays silent but for errors."""
import os
import pty
import select
import signal
import subprocess
import time

from polygons import star, write_xy


def test_progress_line_on_a_terminal(compatmesh_path, tmp_path):
    write_xy(tmp_path / "a.xy", star(20000, 1))
    write_xy(tmp_path / "b.xy", star(20000, 2))
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
    while True:
        ready, _, _ = select.select([main], [], [], 0.5)
        try:
            chunk = os.read(main, 4096) if ready else b""
        except OSError:  # the other end closed
            chunk = b""
        if not chunk:
            break
        seen += chunk
    os.close(main)
    text = seen.decode()
    assert process.returncode == 130
    assert "\rcompatmesh: " in text and "%" in text, text
    assert text.endswith("\r\x1b[Kcompatmesh: interrupted; nothing written\r\n"), repr(text[-120:])
