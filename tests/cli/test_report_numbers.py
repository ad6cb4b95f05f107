"""The numbers of report.json: every double the writer is given reads back in
Python as the same double, bit for bit, and a value that is not finite
fails the report instead of being written (JSON has no NaN or infinity).
report_probe (report_probe.c) feeds the tool's writer chosen doubles."""
import json
import math
import random
import struct
import subprocess

import pytest

HARD = [0.1, 1 / 3, 2 / 3, 0.30000000000000004, math.pi, -0.0, 0.0, 1.0, -2.5,
        5e-324, 2.2250738585072014e-308, 2.225073858507201e-308, 1.7976931348623157e308,
        1e22, 1e23, 9007199254740993.0, 123456789.12345679, 1e-7, 57.295779513082321]


def bits(x):
    return struct.pack("<d", x)


def test_doubles_read_back_bit_for_bit(report_probe, tmp_path):
    rng = random.Random(7)
    randoms = []
    while len(randoms) < 2000:  # any finite double, from its bits
        x = struct.unpack("<d", rng.getrandbits(64).to_bytes(8, "little"))[0]
        if math.isfinite(x):
            randoms.append(x)
    values = HARD + randoms
    out = tmp_path / "report.json"
    result = subprocess.run([report_probe, str(out), *(x.hex() for x in values)],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr

    def reject(constant):
        raise ValueError(f"non-finite number {constant} in JSON")
    with open(out) as f:
        report = json.load(f, parse_constant=reject)
    frames = report["frames"]
    assert len(frames) == len(values)
    for x, frame in zip(values, frames):
        assert bits(frame["t"]) == bits(x), (x, frame["t"])
        assert bits(frame["min_angle_deg"]) == bits(x)
        assert isinstance(frame["t"], float)  # written as a JSON real, even when integral


@pytest.mark.parametrize("value", ["nan", "inf", "-inf"])
def test_non_finite_value_fails_the_report(report_probe, tmp_path, value):
    out = tmp_path / "report.json"
    result = subprocess.run([report_probe, str(out), "0.5", value], capture_output=True, text=True)
    assert result.returncode == 1
    assert result.stderr == f"report_probe: {out}: t is not a finite number\n"
    assert not out.exists(), "nothing written"
