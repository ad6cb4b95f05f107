"""bench/remesh_curve.py: the stage shares, the reach times and the
rescue's curve worked out by hand on written traces (the trace build,
-DCM_REMESH_TRACE=ON, is not part of the test build)."""
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "bench"))
import remesh_curve as rc  # noqa: E402

GREEDY = """\
compatmesh: some other line
cm_trace 0 start 0.10 1.0 4 0
cm_trace 0 cleanup 0.12 2.0 4 0
cm_trace 0 refine 0.20 5.0 5 0
cm_trace 0 refine 0.30 8.0 6 0
cm_trace 0 refine 0.34 8.0 7 0
cm_trace 0 polish 0.36 9.0 7 0
cm_trace 0 step 0.44 9.5 7 10
cm_trace 0 step 0.50 9.5 7 20
cm_trace 0 step_none 0.70 9.5 7 45
cm_trace 0 end 0.72 10.0 7 45
"""


def test_greedy_run():
    a = rc.analyse(rc.parse_trace(GREEDY), 0.80)
    shares = {"pre": 0.10, "clean": 0.02, "refine": 0.22, "polish": 0.02, "forced": 0.34, "late": 0.02,
              "rescue": 0.0, "post": 0.08}
    assert a["stages"] == pytest.approx({k: v / 0.80 for k, v in shares.items()})
    # final 10: 9 (90 %) at the polish, 9.5 (95 %) after the first forced
    # round, 9.9 and 10 only at the end
    assert [a["reach"][lv] for lv in rc.LEVELS] == pytest.approx([0.36 / 0.8, 0.44 / 0.8, 0.9, 0.9])
    assert a["final"] == 10.0 and a["steiner"] == 7 and a["rounds"] == 3 and not a["rescued"]
    assert a["refine_tail"] == pytest.approx(0.04 / 0.8)  # the last round did not raise the angle
    assert a["forced_gain"] == pytest.approx(1.0)
    assert a["forced_rounds"] == 3 and a["forced_tries"] == 45


def test_rescue_counts_the_greedy_result_till_it_is_beaten():
    trace = rc.parse_trace("""\
cm_trace 0 start 0.1 0.5 0 0
cm_trace 0 cleanup 0.2 1.0 0 0
cm_trace 0 polish 0.4 2.0 3 0
cm_trace 0 end 0.5 2.0 3 0
cm_trace 1 start 0.5 0.1 0 0
cm_trace 1 cleanup 0.55 0.2 0 0
cm_trace 1 map 0.6 1.0 2 0
cm_trace 1 polish 0.7 2.5 4 0
cm_trace 1 end 0.9 3.0 4 0
""")
    a = rc.analyse(trace, 1.0)
    assert a["rescued"] and a["final"] == 3.0
    assert a["stages"]["rescue"] == pytest.approx(0.4)
    assert a["stages"]["post"] == pytest.approx(0.1)
    # 2.7 (90 %) only at the rescue's end; 2.0 of the greedy run held till then
    assert [a["reach"][lv] for lv in rc.LEVELS] == pytest.approx([0.9, 0.9, 0.9, 0.9])
    assert min(angle for _, angle, _ in a["curve"][4:]) == 2.0
