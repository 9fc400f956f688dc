"""Child exit status + output -> Result fields, per the plan/solve --json contract."""

import json
import signal

from tampcli.batch.outcome import classify


def _plan_json(status, plans=()):
    return json.dumps({"status": status, "plans": list(plans), "stats": {"expanded": 7}})


def test_plan_solved_takes_the_best_plan():
    out = _plan_json("solved", [{"cost": 4, "actions": ["(a)", "(b)"]},
                                {"cost": 5, "actions": ["(a)", "(b)", "(c)"]}])
    o = classify(0, False, out + "\n", "", 10, None)
    assert (o.status, o.cost, o.plan_length, o.stats, o.error) == ("solved", 4, 2, {"expanded": 7},
                                                                    None)


def test_plan_unsolvable_and_limit_keep_their_status():
    assert classify(1, False, _plan_json("unsolvable"), "", 10, None).status == "unsolvable"
    limit = classify(1, False, _plan_json("limit"), "", 10, None)
    assert limit.status == "limit" and limit.cost is None and limit.error == "limit"


def test_solve_json_uses_trajectory_cost_and_keeps_symbolic_cost():
    out = json.dumps({"status": "solved", "reason": None, "plan": ["(pick a)", "(place a t)"],
                      "scene": "p01.scene.toml", "symbolic_cost": 2, "cost": 1.25,
                      "stats": {"total": 3.0}})
    o = classify(0, False, out, "", None, None)
    assert (o.status, o.cost, o.plan_length) == ("solved", 1.25, 2)
    assert o.stats == {"total": 3.0, "symbolic_cost": 2}


def test_solve_without_a_scene_reports_the_symbolic_cost():
    # What `solve` prints for a problem without a scene: an empty trajectory of cost 0.
    out = json.dumps({"status": "solved", "plan": ["(a)", "(b)"], "scene": None,
                      "symbolic_cost": 2.0, "cost": 0.0, "trajectory": []})
    assert classify(0, False, out, "", None, None).cost == 2.0
    out = json.dumps({"status": "solved", "plan": ["(a)"], "scene": "s.toml", "symbolic_cost": 1,
                      "cost": None})
    assert classify(0, False, out, "", None, None).cost == 1


def test_solve_limit_reports_its_reason():
    out = json.dumps({"status": "limit", "reason": "time limit after 3 skeletons", "plan": None})
    o = classify(1, False, out, "", 5, None)
    assert o.status == "limit" and o.error == "time limit after 3 skeletons"


def test_bad_input_takes_the_located_message():
    out = json.dumps({"status": "error", "error": {"kind": "syntax"},
                      "message": "p.pddl:4:2: unexpected \"(\""})
    o = classify(2, False, out, "p.pddl:4:2: unexpected", None, None)
    assert o.status == "error" and o.error.startswith("p.pddl:4:2:")
    assert classify(2, False, "", "usage: x\n", None, None).error == "usage: x"


def test_internal_error_signal_and_garbage_are_crashes():
    assert "ValueError" in classify(70, False, "", "error: internal error: ValueError: x",
                                    None, None).error
    killed = classify(-signal.SIGSEGV, False, "", "", None, 100)
    assert killed.status == "crashed" and "SIGSEGV" in killed.error and "100 MB" in killed.error
    assert classify(0, False, "not json", "", None, None).status == "crashed"
    assert classify(3, False, "", "", None, None).error == "exit code 3"
    assert "expected unsolvable" in classify(1, False, _plan_json("solved"), "", None, None).error


def test_memory_error_is_named_but_a_quoted_word_in_a_file_is_not():
    oom = classify(70, False, "", "error: internal error: MemoryError:  (rerun with --traceback)",
                   None, 64)
    assert oom.error == "out of memory (memory limit 64 MB)"
    quoted = classify(2, False, "", "p.pddl:1:1: bad\n  (MemoryError\n  ^", None, 64)
    assert quoted.status == "error"


def test_timeout_wins_over_the_signal_that_killed_it():
    o = classify(-signal.SIGKILL, True, "", "", 2, None)
    assert o.status == "timeout" and "(2 s)" in o.error


def test_internal_error_message_skips_library_noise_on_stderr():
    stderr = ("pybullet build time: Jan 29 2025 23:17:20\n"
              "error: internal error: ValueError: bad shape (rerun with --traceback)\n")
    o = classify(70, False, "", stderr, None, None)
    assert o.error == "internal error: ValueError: bad shape (rerun with --traceback)"
