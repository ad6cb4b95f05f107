"""bench/remesh_curve.py: the stage shares, the reach times, the budgets
and the curves of rescues, restarts and auto's pairings worked out by hand
on written traces (the trace build, -DCM_REMESH_TRACE=ON, is not part of
the test build)."""
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
    shares = dict.fromkeys(rc.STAGES, 0.0)
    shares.update(pre=0.10, clean=0.02, refine=0.22, polish=0.02, forced=0.34, late=0.02, post=0.08)
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


# The first run written, polished jointly and by moves, then a restart.
RESTARTED = GREEDY + """\
cm_trace 0 joint 0.80 11.0 7 45
cm_trace 0 moves 0.84 11.5 7 45
cm_trace 0 restart 0.90 3.0 12 45
cm_trace 0 polish 1.20 10.0 14 45
cm_trace 0 end 1.30 11.0 14 45
cm_trace 0 joint 1.50 %s 14 45
cm_trace 0 moves 1.60 %s 14 45
"""


def test_a_restart_counts_only_where_it_is_kept():
    kept = rc.analyse(rc.parse_trace(RESTARTED % ("11.9", "12.0")), 2.0, cgal_cpu=0.0104)
    assert kept["final"] == 12.0
    curve = [a for _, a, _ in kept["curve"]]
    # the first run's result (11.5) holds through the restart's working mesh
    assert curve[11:16] == [11.5] * 5 and curve[16] == 12.0
    shares = {k: v * 2.0 for k, v in kept["stages"].items()}
    assert shares["joint"] == pytest.approx(0.08) and shares["moves"] == pytest.approx(0.04)
    assert shares["restart"] == pytest.approx(1.60 - 0.84) and shares["post"] == pytest.approx(0.40)
    # 10.8 (90 % of 12) when the first joint polish ends; 12 only at the restart's end
    assert kept["reach"][0.90] == pytest.approx(0.40) and kept["reach"][1.00] == pytest.approx(0.80)
    # budgets of 5 ... 160 times 0.0104 s: 0.052 s before the first start
    # (nothing yet), 0.104 s 1 degree, 0.208 s 5, 0.416 s 9, 0.832 s 11, 1.664 s 12
    assert kept["budget"] == pytest.approx({5: 0, 10: 1 / 12, 20: 5 / 12, 40: 9 / 12, 80: 11 / 12, 160: 1})
    # 11.7 is not 2 % above 11.5: the first result stands
    undone = rc.analyse(rc.parse_trace(RESTARTED % ("11.6", "11.7")), 2.0)
    assert undone["final"] == 11.5 and undone["budget"] == {}
    assert max(a for _, a, _ in undone["curve"][11:]) == 11.5


def test_auto_s_later_pairing_counts_when_higher():
    trace = rc.parse_trace("""\
cm_trace 0 start 0.1 0.5 0 0
cm_trace 0 end 0.2 6.0 3 0
cm_trace 0 moves 0.3 7.0 3 0
cm_trace 0 start 0.4 0.5 0 0
cm_trace 0 end 0.6 7.05 5 0
cm_trace 0 moves 0.7 7.1 5 0
cm_trace 0 start 0.8 0.5 0 0
cm_trace 0 moves 0.9 6.5 5 0
""")
    a = rc.analyse(trace, 1.0)
    # a later pairing's gain counts at its end, however small; a lower one not
    assert [v for _, v, _ in a["curve"]] == [0.5, 6.0, 7.0, 7.0, 7.0, 7.1, 7.1, 7.1]
    assert a["final"] == 7.1 and a["stages"]["pairings"] == pytest.approx(0.6)
