"""Exercise 11, broken frames: the answer is a cause, a pixel where the frames differ and the
evidence read off that pixel's history; a blind loop over the causes with made-up values never
passes, a wrong pixel, cause or evidence is told which (never the wrong one), the key is not in
the package in readable form, and the frames' hints are true without giving the answer away.
(Moved here from test_reasoning_exercises.py, r8 must-fix 2.)"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import numpy as np
import pytest
import reasoning_solutions as sol

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import broken_frame_steps as bfs
from teachraster.exercises import broken_frames as bf

#: The key, for the tests only (the package keeps salted hashes).
ANSWERS = {1: "depth function", 2: "culled winding", 3: "z-fighting",
           4: "missing premultiplication", 5: "blend order", 6: "sliver",
           7: "depth function", 8: "sliver", 9: "blend order"}  # fmt: skip
STAGE = {1: "depth test", 2: "culling", 3: "depth test", 4: "blending", 5: "blending",
         6: "coverage", 7: "depth test", 8: "coverage", 9: "blending"}  # fmt: skip
#: The frames that look alike, pixel for pixel (rendered and intended), and the look-alikes
#: whose causes differ (r16 11-2: frames 6 and 8 share a cause, so no pair's causes are
#: known to differ; each frame's twin below is a look-alike with another cause).
GROUPS = [(1, 2), (3, 4, 9), (5, 6, 7, 8)]
PAIRS = [(1, 2), (3, 4), (5, 6), (7, 8), (9, 3)]
#: A made-up value of each kind of evidence.
MADE_UP = {"depth": 0.5, "number": 0.25, "colour": (0.5, 0.5, 0.5), "pair": (0.25, 0.5),
           "triangle": 11}  # fmt: skip
NUMBER_WORDS = {6: "six", 7: "seven", 8: "eight", 9: "nine"}
NOTEBOOK = Path(__file__).parents[1] / "notebooks/exercises/11_broken_frames.ipynb"
README = Path(__file__).parents[1] / "README.md"


@pytest.fixture(autouse=True)
def _no_wait(monkeypatch):
    """These tests fail the frames' checks hundreds of times: no count, no wait (r12 11-2;
    the variable is read once, at import, into ``tries.SETTING``: r13)."""
    from teachraster.exercises import tries

    monkeypatch.setattr(tries, "SETTING", "0")


def _cells():
    nb = json.loads(NOTEBOOK.read_text())
    return {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"]) for c in nb["cells"]}


def _passes(name, fn):
    report = ex.check(name, fn)
    assert report.passed, str(report)


def _first(number, answer):
    report = ex.check(f"broken_frame_{number}", lambda b: answer)
    assert not report.passed, answer
    return report.failures[0]


def _marks(number, row, col):
    p, b = bf._pixel(number, row, col), ex.broken_frame(number)
    return {c for c in bf.CAUSES if bf._SIGNS[c][0](p, b)}


def _showing(number):
    """The first changed pixel of frame ``number`` whose histories bear its cause's mark."""
    return next((int(r), int(c)) for r, c in np.argwhere(bf._differs(number))
                if ANSWERS[number] in _marks(number, int(r), int(c)))  # fmt: skip


def _right(number, row, col):
    """A right diagnosis at (row, col): the evidence read off the histories of the frame it is
    given (the one shown, or one redrawn for the check)."""
    return sol.diagnosis(number, row, col)


# -- the answer needs the evidence ------------------------------------------------------------
@pytest.mark.parametrize("number", list(ANSWERS))
def test_a_blind_loop_over_the_causes_with_made_up_values_never_passes(number):
    """r8: 77 blind calls (every cause and stage at a changed pixel) solved all six. Now every
    cause with a made-up value of its kind fails, at the solution's pixel and another changed
    one, and says which part is wrong: the cause for the nine others, the evidence for the
    frame's own (whose mark the pixel bears)."""
    row, col = sol.BROKEN_FRAMES[number][1]
    other = _showing(number)
    for pixel in {(row, col), other}:
        for cause in bf.CAUSES:  # the verdicts (fast); the words of two below
            want = "evidence" if cause == ANSWERS[number] else "cause"
            answer = (cause, pixel, MADE_UP[bf.EVIDENCE[cause][0]])
            assert bf._judged(number, answer)[0] == want, (cause, pixel)
        for cause in (ANSWERS[number], "texture filtering"):
            failure = _first(number, (cause, pixel, MADE_UP[bf.EVIDENCE[cause][0]]))
            want = "evidence" if cause == ANSWERS[number] else "cause"
            assert failure.kind == want, (cause, pixel, failure.explanation)
            assert "read right" not in failure.explanation, failure.explanation


@pytest.mark.parametrize("number", list(ANSWERS))
def test_the_right_answer_passes_and_each_wrong_part_is_told_which(number):
    """The solution (numbers as the history prints them) passes; the right evidence under the
    pair's other cause is told the cause is wrong, never that the value is read right or
    another cause's evidence (r18-2: each evidence is one cause's, so that named it); the
    right cause with a value off by more than the printed digits is told the evidence is
    wrong, never the cause; a pixel where the pictures agree is told so."""
    answer = sol.BROKEN_FRAMES[number]
    _passes(f"broken_frame_{number}", sol.diagnosis(number))
    assert bf._judged(number, bf.as_diagnosis(answer))[0] == "right"  # as printed
    cause, pixel, value = answer
    twin = ANSWERS[next(b if a == number else a for a, b in PAIRS if number in (a, b))]
    # r16 N1: the twin's cause with this frame's own evidence, of whatever kind, is told the
    # cause is wrong (it was told the evidence's type, for the twin's cause, was wrong)
    for given in {value, MADE_UP[bf.EVIDENCE[twin][0]]}:
        failure = _first(number, (twin, pixel, given))
        assert failure.kind == "cause" and f"{twin!r} is not what the two" in failure.explanation
        assert "mark of" not in failure.explanation and "stage by stage" in failure.explanation
        assert "returned the evidence" not in failure.explanation, failure.explanation
    failure = _first(number, (twin, pixel, value))
    for telling in ("read right", "another cause", "evidence of"):
        assert telling not in failure.explanation, failure.explanation
    # the same words as for a made-up value of the stated cause's kind: the value is not judged
    made_up = _first(number, (twin, pixel, MADE_UP[bf.EVIDENCE[twin][0]])).explanation
    start = f"{twin!r} is not what"
    assert failure.explanation.split(start)[1] == made_up.split(start)[1], (failure, made_up)
    assert failure.explanation.endswith(
        "Your value is not judged while the cause is not the frame's"
    ), failure.explanation
    off = (value + 1 if isinstance(value, int) else value + 1e-3 if isinstance(value, float)
           else tuple(v + 1e-3 for v in value))  # fmt: skip
    failure = _first(number, (cause, pixel, off))
    assert failure.kind == "evidence", failure.explanation
    assert f"do bear the mark of {cause!r}" in failure.explanation
    assert f"history({pixel[0]}, {pixel[1]})" in failure.explanation
    same = tuple(int(v) for v in np.argwhere(~bf._differs(number))[0])
    failure = _first(number, (cause, same, value))
    assert failure.kind == "pixel" and "same colour" in failure.explanation


def _harvest(h) -> list:
    """Every value a loop can read off one history (r9's g11.py): depths, distances, colours
    and "after" colours, and (distance, depth) pairs."""
    out = []
    for r in h.records:
        out += [v for v in (r.depth, r.outside) if v is not None] + [r.triangle]
        out += [tuple(c[:3]) for c in (r.color, r.color_after) if c]
    return out


@pytest.mark.parametrize("number", list(ANSWERS))
def test_a_loop_over_one_pixels_history_values_fails_the_redrawn_frame(number):
    """r9 11-1: the ten causes × every value of one changed pixel's two histories passed all
    six in 137 calls. The values a loop finds on the frame shown (it does find them: the
    verdict is an oracle there) fail each frame the check redraws, and a function returning
    them is told the value is the frame shown's, typed in."""
    b = ex.broken_frame(number)
    pixels = np.argwhere(bf._differs(number))
    row, col = (int(v) for v in pixels[len(pixels) // 2])
    if ANSWERS[number] not in _marks(number, row, col):  # frame 8: the sliver misses it
        row, col = _showing(number)
    values = _harvest(b.frame.history(row, col)) + _harvest(b.intended.history(row, col))
    depths = [v for v in values if isinstance(v, float)]
    values += [(a, d) for a in depths for d in depths]
    found = []
    for cause, (kind, _) in bf.EVIDENCE.items():
        for v in values:
            if ((kind in ("depth", "number")) != isinstance(v, float)
                or (kind == "triangle") != isinstance(v, int)
                or (kind == "pair") != (isinstance(v, tuple) and len(v) == 2)):  # fmt: skip
                continue
            answer = (cause, (row, col), v)
            if bf._judged(number, answer)[0] == "right":
                found.append(answer)
    assert found, "the loop finds the frame shown's answer"
    for look in bf._REDRAWN:
        redrawn = bf._redrawn(number, look)
        assert np.array_equal(bf._differs(redrawn), bf._differs(number))  # the same pixels
        assert all(bf._judged(redrawn, a)[0] == "copied" for a in found), look
        honest = bf.as_diagnosis(sol.diagnosis(number)(redrawn))  # read off its histories
        assert bf._judged(redrawn, honest)[0] == "right", look
    report = ex.check(f"broken_frame_{number}", lambda b: found[0])
    assert not report.passed and [f.kind for f in report.failures] == ["typed in"], str(report)
    assert "never typed in" in report.failures[0].explanation


def test_the_checkers_private_readers_are_not_counted():
    """r9 11-2: the salted hash and ``_evidence`` gave 6/6 in 6 calls; on the redrawn frame
    they still give the evidence, so the report says they were called and does not count it."""

    def private(b):
        cause = next(c for c in bf.CAUSES if bf._is_cause(b.number, c))
        return cause, (22, 40), bf._evidence(b, cause, bf._pixel(b, 22, 40))[0]

    report = ex.check("broken_frame_6", private)
    assert not report.failures and not report.passed
    assert "read from the checker's private functions: not counted" in report.package
    with pytest.raises(AssertionError, match="not counted"):
        report.assert_passed()
    assert ex.check("broken_frame_6", sol.diagnosis(6)).package is None  # history only


def test_the_private_readers_called_from_a_worker_thread_are_not_counted():
    """r11 09-B2: ``pool.submit(bf._is_cause, ...)`` from a pool made before the check passed
    with no "not counted" (the profile hook watched the case's own thread only)."""
    from concurrent.futures import ThreadPoolExecutor

    pool = ThreadPoolExecutor(1)
    pool.submit(int).result(timeout=5)  # its thread exists before the check starts
    honest = sol.diagnosis(6)

    def private(b):
        pool.submit(bf._is_cause, 6, "sliver").result(timeout=5)
        return honest(b)

    try:
        report = ex.check("broken_frame_6", private)
    finally:
        pool.shutdown(wait=False, cancel_futures=True)
    assert not report.failures and not report.passed, str(report)
    assert "read from the checker's private functions: not counted" in report.package


def test_a_clone_of_a_private_reader_or_the_judge_with_a_warm_cache_is_not_counted():
    """r12 11-4: a ``types.FunctionType`` clone of ``_is_cause`` made before the check, and
    the judge ``_same`` (not listed) with its cache warmed for the ten causes, picked the cause
    inside ``broken_frame_1`` uncounted. Now both are named, and the honest answer is not."""
    import types

    f = bf._is_cause
    clone = types.FunctionType(f.__code__, f.__globals__, "is_it")
    read = sol.READ[1]

    def by_clone(b):
        cause = next(c for c in bf.CAUSES if clone(1, c))
        return cause, (24, 28), read(b, 24, 28)

    report = ex.check("broken_frame_1", by_clone)
    assert not report.passed and "a copy of the code of teachraster's _is_cause" in (
        report.package or ""
    ), str(report)
    value = read(ex.broken_frame(1), 24, 28)
    for c in bf.CAUSES:  # warmed in a cell before the check
        bf._same((c, (24, 28), value), 1)

    def by_judge(b):
        cause = next(c for c in bf.CAUSES if bf._same((c, (24, 28), value), 1))
        return cause, (24, 28), read(b, 24, 28)

    report = ex.check("broken_frame_1", by_judge)
    assert not report.passed and "teachraster's _same" in (report.package or ""), str(report)
    assert "read from the checker's private functions" in report.package
    assert ex.check("broken_frame_1", sol.diagnosis(1)).passed


def test_an_answer_that_reads_the_salted_key_is_not_counted():
    """r11 11-E: hashing the ten causes with ``_SALT`` against ``_KEY`` gave the cause with no
    private call, and passed."""
    import hashlib

    honest = sol.diagnosis(6)

    def cause_of(n):  # a helper of the student's own, read too
        return next(c for c in bf.CAUSES
                    if hashlib.sha256(f"{bf._SALT}|{n}|{c}".encode()).hexdigest()[:32]
                    == bf._KEY[n])  # fmt: skip

    def salted(b):
        return (cause_of(b.number), *honest(b)[1:])

    report = ex.check("broken_frame_6", salted)
    assert not report.failures and not report.passed, str(report)
    assert "reads the checker's _KEY" in report.package, report.package
    salt = "_SALT"  # read by its name as a text

    def by_name(b):
        return (getattr(bf, salt) and "sliver", *honest(b)[1:])

    report = ex.check("broken_frame_6", by_name)
    assert "reads the checker's _SALT" in str(report.package)


_KEY = {1: "a constant of the student's own, named like the checker's key"}


def test_the_key_is_known_by_its_value_never_by_its_name():
    """r13 11-4: judged by the name, a student's own constant named ``_KEY`` was refused and
    the real key copied under another name passed. Now the key's object, a copy of it, or
    one of its texts, under any name, is refused, and an honest ``_KEY`` is not."""
    honest = sol.diagnosis(1)

    def own_key(b):
        return honest(b) if _KEY else None

    report = ex.check("broken_frame_1", own_key)
    assert report.passed and report.package is None, str(report)
    hashes = dict(bf._KEY)  # a copy, under another name
    typed = bf._KEY[1]  # one of its texts

    def copied(b):
        return honest(b) if hashes else None

    def one_text(b):
        return honest(b) if typed else None

    for fn in (copied, one_text):
        report = ex.check("broken_frame_1", fn)
        assert not report.passed and "reads the checker's _KEY" in str(report.package), fn


def test_the_look_alike_frames_1_and_2_take_evidence_of_different_kinds():
    """r11 11-D: frames 1 and 2 both took the depth shown, so one reader served both causes
    and the cause was a coin flip. Frame 2's evidence is the triangle culled in it and drawn
    in the intended frame, which the redrawn frame numbers otherwise (typed in, it fails)."""
    for a, b in PAIRS:
        assert bf.EVIDENCE[ANSWERS[a]][0] != bf.EVIDENCE[ANSWERS[b]][0], (a, b)
    depth = ex.check("broken_frame_2", lambda b: ("culled winding", (24, 28),
                                                  sol.READ[1](b, 24, 28)))  # fmt: skip
    assert not depth.passed and "triangle's number" in depth.failures[0].explanation
    assert bf._judged(2, ("culled winding", (24, 28), 9))[0] == "right"
    for look in bf._REDRAWN:
        redrawn = bf._redrawn(2, look)
        assert bf._judged(redrawn, ("culled winding", (24, 28), 9))[0] == "copied", look
    _passes("broken_frame_2", sol.diagnosis(2))


def test_a_triangle_number_read_off_the_intended_history_is_named():
    """r84 11-2: frame 2's triangle, numbered as the intended frame's history numbers it,
    passed both cases, the two frames of each pair numbering alike: "a number the list asks
    for is the one in the frame's own history" was never needed. The redrawn cube pair numbers
    them apart, so the slip fails there, told what it read (never the right number)."""

    def read_off_the_intended(b):
        meant = b.intended.history(24, 28).records
        return "culled winding", (24, 28), next(r.triangle for r in meant if r.outcome == "passed")

    report = ex.check("broken_frame_2", read_off_the_intended)
    assert [f.case for f in report.failures] == ["the frame redrawn"], str(report)
    failure = report.failures[0]
    assert failure.kind == "the intended frame's number", failure.explanation
    text = failure.explanation
    assert "you found the right triangle, but" in text and "its number in the intended" in text
    assert "frame.trace.window[k, :, :2]" in text and "b.frame.history(24, 28)" in text, text
    for look in bf._REDRAWN:  # whichever look the check draws, at every pixel with the mark
        redrawn = bf._redrawn(2, look)
        assert look.meant_order not in (None, 0, look.order), look
        for row, col in np.argwhere(bf._differs(redrawn))[::37]:
            p = bf._pixel(redrawn, int(row), int(col))
            if not bf._SIGNS["culled winding"][0](p, redrawn):
                continue
            for value in bf._meant_numbers(redrawn, "culled winding", p):
                answer = ("culled winding", (int(row), int(col)), value)
                assert bf._judged(redrawn, answer)[0] == "intended", (look, answer)
        right = bf.as_diagnosis(sol.diagnosis(2)(redrawn))
        assert bf._judged(redrawn, right)[0] == "right", look


def test_a_pixel_given_as_floats_is_told_it_is_a_float():
    """r11 11-H: (24.0, 28.0) was told "row 24.0 is not an integer"."""
    failure = _first(1, ("depth function", (24.0, 28), 0.026233))
    assert "row 24.0 is a float, not an int: give int(row)" in failure.explanation
    assert "not an integer" in _first(1, ("depth function", (24.5, 28), 0.1)).explanation


def test_a_check_run_inside_the_answer_never_passes():
    """A function that tries answers against the checker from inside itself learns nothing:
    the check it runs fails every case with the same words."""
    inner = []

    def searching(b):
        inner.append(ex.check("broken_frame_1", sol.diagnosis(1)))
        return sol.diagnosis(1)(b)

    assert ex.check("broken_frame_1", searching).passed
    assert inner and not any(r.passed for r in inner)
    assert {f.kind for r in inner for f in r.failures} == {"check inside"}
    assert ex.check("broken_frame_1", sol.diagnosis(1)).passed  # nothing left behind


def test_a_swapped_pixel_or_pair_is_named():
    """r9 M7 and M20: (col, row) and the sliver's pair in the other order were half-named."""
    failure = _first(1, ("depth function", (28, 24), sol.READ[1](ex.broken_frame(1), 24, 28)))
    assert "the evidence at (24, 28): a pixel is (row, col)" in failure.explanation
    pair = sol.READ[6](ex.broken_frame(6), 22, 40)[::-1]
    assert "in the other order" in _first(6, ("sliver", (22, 40), pair)).explanation
    wrong = _first(6, ("sliver", (22, 40), (0.5, 0.5))).explanation
    assert "other order" not in wrong and "row first" not in wrong


def test_a_blind_search_meets_a_growing_wait_past_the_failing_checks_allowed(monkeypatch):
    """r12 11-2: ten causes × 40 generic history readers passed all six frames in 2,100 checks,
    51 s. Past the failing checks allowed (3 here, 25 for a class) each check of the same
    frame that fails waits, 1 s more each time, at most 30 s, outside the student's budget;
    the report says why; a pass never waits (r22 D3) and starts the count again; another frame keeps its own count; a
    check inside the student's function does not wait; 0 turns it off; a typo is refused."""
    from teachraster.exercises import tries

    waits = []
    monkeypatch.setattr(tries, "_sleep", waits.append)
    monkeypatch.setattr(tries, "_FAILED", {})
    monkeypatch.setattr(tries, "SETTING", "3")
    wrong = lambda b: ("texture filtering", (24, 28), (0.5, 0.5, 0.5))  # noqa: E731
    notes = [ex.check("broken_frame_1", wrong).tries for _ in range(5)]
    assert waits == [1.0] and notes[:3] == [None] * 3, (waits, notes)
    assert "5 failing checks of broken_frame_1" in notes[4]
    assert "does not need that many tries" in notes[4] and "at most 30 s" in notes[4]
    assert "- 6 failing checks of broken_frame_1" in str(ex.check("broken_frame_1", wrong))
    assert waits == [1.0, 2.0]
    assert ex.check("broken_frame_2", wrong).tries is None and waits == [1.0, 2.0]
    report = ex.check("broken_frame_1", sol.diagnosis(1))  # r22 D3: a pass never waits
    assert report.passed and report.tries is None and waits == [1.0, 2.0], waits
    assert "a passing check never waits" in notes[4]
    assert ex.check("broken_frame_1", wrong).tries is None and len(waits) == 2
    tries._FAILED["broken_frame_1"] = 1000
    assert tries.wait("broken_frame_1", 25) == 30.0  # capped
    inner = []
    ex.check("broken_frame_1", lambda b: inner.append(ex.check("broken_frame_1", wrong)) or 0)
    assert waits.count(30.0) == 2 and inner, waits  # the outer check waited, the inner not
    assert ex.check("edge_function", lambda *a: 0).tries is None  # other exercises: no limit
    tries._FAILED.clear()
    for _ in range(5):  # the stub not written yet is no try
        ex.check("broken_frame_3", lambda b: (_ for _ in ()).throw(NotImplementedError()))
    assert "broken_frame_3" not in tries._FAILED
    monkeypatch.setattr(tries, "SETTING", "0")
    assert (
        tries.wait("broken_frame_1", 25) == 0.0 and ex.check("broken_frame_1", wrong).tries is None
    )
    monkeypatch.setattr(tries, "SETTING", "many")
    with pytest.raises(ValueError, match="TEACHRASTER_CHECK_TRIES"):
        tries.allowed(25)
    assert bf.frame_exercise(1).tries == bf.TRIES == 25


def test_a_blind_loop_over_the_causes_waits_for_each_wrong_cause_past_two(monkeypatch):
    """r14 11-4: a loop over the ten causes × five generic readers, moving on when told "not
    the frame's cause", passed frames 1, 3, 4, 5 in 65 checks (38 s), under the 25 failing
    checks allowed. Now past two distinct wrong causes of one frame, every check naming a
    wrong cause waits 30 s more for each (at most 300 s) before it answers; the right cause
    never waits for it; a pass starts again; inside the student's function no wait; 0: off."""
    from teachraster.exercises import tries

    waits = []
    monkeypatch.setattr(tries, "_sleep", waits.append)
    monkeypatch.setattr(tries, "_FAILED", {})
    monkeypatch.setattr(tries, "_WRONG", {})
    monkeypatch.setattr(tries, "SETTING", "25")
    depth = lambda b: next(r.depth for r in b.frame.history(24, 28).records if r.shown)  # noqa: E731

    def naming(cause):
        return lambda b: (cause, (24, 28), depth(b))

    notes = [ex.check("broken_frame_1", naming(c)).tries for c in ("z-fighting", "depth test off")]
    assert notes == [None, None] and waits == []
    report = ex.check("broken_frame_1", naming("affine interpolation"))
    assert waits == [30.0] and "3 different wrong causes" in report.tries, report.tries
    assert "not by trying the names" in str(report)
    ex.check("broken_frame_1", naming("near-plane clipping"))
    ex.check("broken_frame_1", naming("z-fighting"))  # a wrong cause again waits too
    assert waits == [30.0, 60.0, 60.0]
    report = ex.check("broken_frame_1", naming("depth function"))  # the right cause: no wait
    assert report.passed and report.tries is None and waits == [30.0, 60.0, 60.0]
    for cause in ("z-fighting", "depth test off", "affine interpolation"):  # counted afresh
        ex.check("broken_frame_1", naming(cause))
    assert waits[3:] == [30.0]
    ex.check("broken_frame_2", naming("z-fighting"))  # another frame, its own count
    assert waits[3:] == [30.0]
    tries._WRONG["broken_frame_1"] = set(ex.CAUSES) - {"depth function"}
    note = tries.wrong_causes("broken_frame_1", 25, {"sliver"}, False)  # all nine wrong
    assert "waited 210 s" in note and waits[-1] == 210.0, note
    inner = []

    def searching(b):  # a check inside the student's function: it does not wait
        inner.append(ex.check("broken_frame_1", naming("sliver")))
        return naming("z-fighting")(b)

    ex.check("broken_frame_1", searching)
    assert inner and waits[-2:] == [210.0, 210.0] and len(waits) == 6  # the outer one only
    monkeypatch.setattr(tries, "SETTING", "0")
    assert ex.check("broken_frame_1", naming("sliver")).tries is None and len(waits) == 6


def test_a_student_cell_setting_the_tries_variable_changes_nothing(monkeypatch):
    """r13: ``os.environ["TEACHRASTER_CHECK_TRIES"] = "0"`` in a student's cell switched the
    wait off (the variable was read at every check). Now it is read once, as the package is
    imported (the suite sets it before: tests/conftest.py)."""
    from teachraster.exercises import tries

    assert tries.SETTING == os.environ.get("TEACHRASTER_CHECK_TRIES") == "0"  # the suite's
    monkeypatch.setattr(tries, "SETTING", "3")
    monkeypatch.setenv("TEACHRASTER_CHECK_TRIES", "0")  # the student's line
    assert tries.allowed(25) == 3
    monkeypatch.delenv("TEACHRASTER_CHECK_TRIES")
    assert tries.allowed(25) == 3


def test_a_wrong_cause_is_told_the_same_whether_or_not_the_pixel_bears_its_mark():
    """r13 11-2: a wrong cause was told whether the pixel's histories "do (or do not) bear the
    mark of" it: a loop over the ten causes and nine readers passed all six frames in 58
    checks. Now every wrong cause at a pixel gets the same words but for its own name and
    mark: the histories do not explain it, compare them stage by stage."""
    for number, (_, pixel, _) in sol.BROKEN_FRAMES.items():
        words = set()
        for cause in bf.CAUSES:
            if bf._is_cause(number, cause):
                continue
            failure = _first(number, (cause, pixel, MADE_UP[bf.EVIDENCE[cause][0]]))
            assert failure.kind == "cause", (number, cause, failure.explanation)
            text = failure.explanation.replace(repr(cause), "C").replace(bf._SIGNS[cause][1], "S")
            assert "bear" not in text and "another cause" not in text, text
            words.add(text[text.index("C is not what") :].split(". Your value")[0])
        assert len(words) == 1, (number, words)


def test_the_first_culled_triangle_is_told_what_it_is_never_expected_n_nor_a_swap():
    """r12 11-1: 11.2's commonest mistake (the first culled triangle at (24, 28), 8) was told
    "expected 2" (the frame's number, read as "triangle 2"), "the four digits it prints" and a
    row/column swap it did not make (8 is also the evidence at (28, 24)). Both cases: the frame
    named as a frame, the triangle as a triangle, what it is in both histories, no swap."""

    def first_culled(row, col):
        def fn(b):
            records = b.frame.history(row, col).records
            culled = next(r.triangle for r in records if r.outcome == "culled")
            return "culled winding", (row, col), culled

        return fn

    # r377 F1: the redrawn cube lists its triangles backwards, so the first culled triangle
    # is wrong in one of the two cases wherever a pixel's history culls two: at (24, 28) in
    # the frame shown, at (24, 32) in the frame redrawn
    shown = ex.check("broken_frame_2", first_culled(24, 28))
    redrawn = ex.check("broken_frame_2", first_culled(24, 32))
    assert [f.case for f in shown.failures] == ["the frame shown"], str(shown)
    assert [f.case for f in redrawn.failures] == ["the frame redrawn"], str(redrawn)
    for failure in (*shown.failures, *redrawn.failures):
        text = failure.explanation
        assert failure.kind == "evidence", text
        assert re.match(r"(redrawn )?frame 2: 'culled winding' at pixel \(24, (28|32)\) with "
                        r"triangle \d+:", text), text  # fmt: skip
        assert not re.search(r"expected \d", text), text
        assert "culled here, but the intended frame's history shows it not_covered" in text
        assert "digits" not in text and "row first" not in text, text
    assert bf._explain((), 2, ("culled winding", (28, 24), 11)).endswith("with triangle 11")
    # r12 11-5: the redrawn frame's failure says where its values are read
    text = redrawn.failures[0].explanation
    assert "b.intended.history(24, 32) inside your function (this is the frame redrawn" in text


def test_the_evidence_needs_the_digits_the_history_prints():
    """A depth to three decimals is not the evidence (it would make a loop over a thousand
    values enough); a depth as printed, or exactly as the record holds it, is."""
    kept = next(r for r in ex.broken_frame(1).frame.history(24, 28).records if r.shown)
    assert _first(1, ("depth function", (24, 28), round(kept.depth, 3))).kind == "evidence"
    read = sol.READ[1]
    _passes("broken_frame_1", lambda b: ("depth function", (24, 28), round(read(b, 24, 28), 6)))
    _passes("broken_frame_1", lambda b: ("depth function", (np.int64(24), 28), read(b, 24, 28)))
    assert bf._TOLERANCE["depth"] < 1e-5 and bf._TOLERANCE["number"] < 1e-4
    # one number would be a short loop for the distance: the sliver also needs the depth
    assert bf.EVIDENCE["sliver"][0] == "pair"


@pytest.mark.parametrize("number", list(ANSWERS))
def test_each_changed_pixel_bears_the_mark_of_its_frames_cause_only(number):
    """The check judges a cause by its mark at the student's pixel: on a sample of every
    frame's changed pixels, only the frame's own cause's mark is there (frames 6 and 8: or
    none, where the sliver does not cross the pixel), and where it is, so is its evidence."""
    pixels = np.argwhere(bf._differs(number))
    for r, c in pixels[:: max(1, len(pixels) // 25)]:
        marks = _marks(number, int(r), int(c))
        assert marks <= {ANSWERS[number]}, (number, r, c, marks)
        if ANSWERS[number] != "sliver":
            assert marks == {ANSWERS[number]}, (number, r, c)
        if marks:
            assert bf._evidence(number, ANSWERS[number], bf._pixel(number, int(r), int(c)))


def test_the_answers_are_not_importable_in_readable_form():
    """r8 11-3: ``ex.broken_frames._answer(n)`` gave the key one Tab away. Now the module is
    no attribute of ``ex``, has no answer function, and none of its values maps a frame to
    its cause or lists the six causes in the frames' order (the key is salted hashes)."""
    assert not hasattr(ex, "broken_frames") and "broken_frames" not in dir(ex)
    for name in ("_answer", "_CAUSE_OF", "_TRIES", "parts_at", "SIGNATURES", "hint"):
        assert not hasattr(bf, name), name
    in_order = [ANSWERS[n] for n in sorted(ANSWERS)]
    for name, value in vars(bf).items():
        if isinstance(value, dict):
            assert not any(value.get(n) == ANSWERS[n] for n in ANSWERS), name
        if isinstance(value, list | tuple):
            texts = [v for v in value if isinstance(v, str) and v in bf.CAUSES]
            assert texts != in_order, name
    specs = repr(bf._SPECS) + "".join(s for s, *_ in bf._SPECS)
    assert not any(c in specs for c in bf.CAUSES)
    assert all(bf._is_cause(n, c) == (c == ANSWERS[n]) for n in ANSWERS for c in bf.CAUSES)
    assert len(set(bf._KEY.values())) == len(ANSWERS) == len(bf._KEY)


def test_the_module_docstring_lists_the_mistakes_out_of_the_frames_order():
    """r8 11-3: ``help(ex.broken_frames)`` listed the six mistakes in the frames' order."""
    doc = " ".join(bf.__doc__.split())
    words = ["reversed depth", "culling the wrong", "too close", "straight colours",
             "transparent geometry drawn", "thinner than a pixel"]  # frames 1 to 6  # fmt: skip
    at = [doc.index(w) for w in words]
    assert at != sorted(at), at


# -- the notebook --------------------------------------------------------------------------------
def test_the_notebook_asks_for_the_evidence_and_lists_it_with_the_causes():
    cells = _cells()
    assert "sorted(ex.CAUSES.items())" in cells["setup"] and "ex.EVIDENCE" in cells["setup"]
    intro, how = cells["intro"], cells["how_text"]
    assert "**evidence**" in intro and "not drawn at all" in how
    assert "tells nothing" not in intro + how and "tries" not in intro + how  # r8 10b
    assert len(intro.split()) < 200  # r9 11-6: 543 words before a frame
    # r14 11-2: frames 1, 3 and 4 need lesson 05b and lesson 12, which lesson 11 does not
    # teach: the intro and README say so. r18-14: in neutral words, naming no mechanism (the
    # symptoms beside "reverse-Z" or "premultiplied alpha" named three frames' causes)
    flat = " ".join(intro.split())
    assert "after lesson 12b" in flat and "05b's depth mapping" in flat, flat
    assert "lesson 12b's blending" in flat, flat
    for telling in ("reverse", "16-bit", "ties", "premultipl", "§9"):
        assert telling not in flat, telling
    row = next(
        line for line in README.read_text().splitlines() if "diagnose nine broken frames" in line
    )
    assert "lesson 11)" not in row and "after lesson 12b" in row, row
    assert "**redrawn**" in how and "typed in" in how and "private functions" in how
    for n in ANSWERS:
        task = cells[f"frame_{n}_task"]
        assert "evidence the list names" in task and ANSWERS[n] not in task
        assert f"broken_frame_{n}(b)" in task and f"`broken[{n}]`" in task
        solution = cells[f"broken_frame_{n}_solution"]
        assert f"def broken_frame_{n}(b):" in solution, n  # a function of the frame pair
        assert "b.frame" in solution and "broken[" not in solution.split("SOLUTION")[1], n
    # r11 11-A: the worked form, on a frame pair no task grades (it solved frame 1)
    assert "def broken_frame_example(b):" in cells["example"] and "broken[" not in cells["example"]


def test_the_notebook_says_in_the_tasks_what_the_solutions_knew():
    """r9 11-3, 11-4: frame 1's depth order and frame 4's contrivance are said where the
    student reads (the solution cells are stripped from the student version). r11 11-A, 11-B:
    the order, not "near 0, not near 1", with the depths printed by a cell, and no question
    naming which cause is at fault."""
    cells = _cells()
    task = " ".join(cells["frame_1_task"].split())
    assert "near 0" not in task and "at fault" not in task
    depths = cells["frame_1_depths"]
    # r22 D4: the source (shown before any answer) names neither the pixel nor the faces: the
    # depths are frame 1's note, printed once its check passes
    assert "ex.frame_note(1, " in depths, depths
    for told in ("24", "28", "9", "3", "in front", "behind"):
        assert told not in depths, told
    # r13: the comment no longer tells the order (it ships to students before any answer)
    assert "smaller" not in depths and "larger" not in depths
    # 11-C: triangle 3 (0.973767 in the intended frame) is the face behind, hidden by 9
    assert "the face behind (0.973767" in cells["broken_frame_1_solution"]
    # r14 11-1: "the pane's straight colour is exactly its alpha times the wall's … usually
    # a pane too bright" named frame 4's cause (and frame 3's by elimination) before any
    # history was read: the task says only that the pair is contrived; the rest is printed
    # by a locked cell after 11.4's check, once it has passed
    task4 = " ".join(cells["frame_4_task"].split())
    # r18-5: "(Like others here, this frame is contrived …)" singled frame 4 out: said nowhere
    assert "ontrived" not in task4 and "Like others" not in task4, task4
    for telling in ("too bright", "straight colour", "alpha times", "premultipl"):
        assert telling not in task4, telling
    order = list(cells)
    assert order.index("frame_4_note") == order.index("broken_frame_4_check") + 1
    # r12 11-6: lesson 12 §9 is the dark fringe of filtering straight alpha: no pane too bright
    assert "lesson 12" not in cells["frame_4_task"]
    assert "ontrived" not in cells["broken_frame_4_solution"]


def test_the_frame_4_note_is_printed_only_once_its_check_has_passed(capsys):
    """r14 11-1: why frames 3 and 4 look alike (the pane's straight colour is its alpha times
    the wall's; the mistake usually shows as a pane too bright) is said after 11.4 passes."""
    source = _cells()["frame_4_note"]
    # r16 N2: the words are the package's, not in the cell's source (readable before 11.4)
    for telling in ("too bright", "straight colour", "alpha times", "premultipl"):
        assert telling not in source, telling
    wrong = lambda b: ("texture filtering", (13, 52), (0.5, 0.5, 0.5))  # noqa: E731
    for namespace in ({"ex": ex}, {"ex": ex, "report": ex.check("broken_frame_4", wrong)},
                      {"ex": ex, "report": ex.check("broken_frame_3", sol.diagnosis(3))}):  # fmt: skip
        exec(source, namespace)
        shown = capsys.readouterr().out
        assert "once the check of broken_frame_4" in shown and "too bright" not in shown, shown
    # r18-10: only a report the checker made: not an object with passed=True, not a Report
    # built by hand
    from types import SimpleNamespace

    from teachraster.exercises.report import Report

    for fake in (SimpleNamespace(exercise="broken_frame_4", passed=True),
                 Report("broken_frame_4", [], 2)):  # fmt: skip
        assert fake.passed
        exec(source, {"ex": ex, "report": fake})
        shown = capsys.readouterr().out
        assert "once the check of broken_frame_4" in shown and "too bright" not in shown, shown
    exec(source, {"ex": ex, "report": ex.check("broken_frame_4", sol.diagnosis(4))})
    shown = capsys.readouterr().out
    assert "too bright" in shown and "alpha times" in shown, shown
    # r18-4: a "pair" is a frame and its intended frame, which do not look alike here;
    # r18-3: nor "like frame 3", which told frame 3's cause is another
    assert "so that the pane vanishes into the wall" in shown and "the pair" not in shown, shown


def test_every_frame_has_its_note_after_its_check_none_singled_out(capsys):
    """r18-5: "a cell after the check says how" came after frame 4's check alone, singling it
    out as the contrived frame. Now every frame's check is followed by a cell of the same
    code (frame 1's prints its depths), each note printed only once that frame's check has
    passed, the placeholders the same words but for the number."""
    cells, order = _cells(), list(_cells())
    placeholders = set()
    for n in ANSWERS:
        after = order[order.index(f"broken_frame_{n}_check") + 1]
        if n == 1:
            assert after == "frame_1_depths"
            continue
        assert after == f"frame_{n}_note", (n, after)
        source = cells[after]
        assert source == cells["frame_4_note"].replace("4", str(n)), source
        exec(source, {"ex": ex})
        shown = capsys.readouterr().out
        placeholders.add(shown.replace(str(n), "n"))
        assert f"A note on frame {n} is printed here once" in shown, shown
        other = 3 if n != 3 else 4  # another frame's passed report shows nothing
        exec(source, {"ex": ex, "report": ex.check(f"broken_frame_{other}", sol.diagnosis(other))})
        assert capsys.readouterr().out == shown
        exec(source, {"ex": ex, "report": ex.check(f"broken_frame_{n}", sol.diagnosis(n))})
        note = capsys.readouterr().out
        assert note.startswith(f"Frame {n} is ") and "contrived" in note, note
        assert not re.search(rf"frame (?!{n}\b)\d", note.lower()), note  # names no other frame
    assert len(placeholders) == 1, placeholders
    assert "ontrived" not in " ".join(v for k, v in cells.items() if k.endswith("_task"))
    # r22 D4: frame 1's note is its two faces' depths (the cell's source named the pixel)
    assert ex.frame_note(1, None).replace("1", "n") in {p.strip() for p in placeholders}
    with pytest.raises(ValueError, match="number must be one of"):
        ex.frame_note(10, None)


def test_the_frame_1_task_asks_and_the_depths_are_printed_after_the_check():
    """r12 11-3: the task named the pixel and said which face had the larger depth in frame 1,
    so ``return "depth function", (24, 28), b.frame.depth[24, 28]`` passed without reading a
    history. Now the task asks, names no pixel or triangle, and the cell printing the two
    faces' depths comes after the check. r23 D1: its question "which face lies in front, which
    has the smaller depth" was the definition of the cause: it asks where the histories part."""
    cells = _cells()
    task = " ".join(cells["frame_1_task"].split())
    for told in ("(24, 28)", "triangle 9", "the larger", "in front has the smaller",
                 "smaller depth", "lies in front"):  # fmt: skip
        assert told not in task, told
    assert "stage by stage" in task and "first part" in task and "Once the check passes" in task
    order = list(cells)
    assert order.index("frame_1_depths") == order.index("broken_frame_1_check") + 1


def test_the_frame_1_depths_are_printed_only_once_its_check_has_passed(capsys):
    """r13: the locked cell after 11.1's check printed both faces' depths at (24, 28) whatever
    the check said (and its comment told which face has the smaller depth): 11.1 given away.
    Now it prints them only when the last report is broken_frame_1's and passed."""
    source = _cells()["frame_1_depths"]
    wrong = lambda b: ("texture filtering", (24, 28), (0.5, 0.5, 0.5))  # noqa: E731
    for namespace in ({}, {"report": ex.check("broken_frame_1", wrong)},
                      {"report": ex.check("broken_frame_2", sol.diagnosis(2))}):  # fmt: skip
        exec(source, {"ex": ex, **namespace})
        shown = capsys.readouterr().out
        assert "once the check of broken_frame_1" in shown and "0.9" not in shown, shown
        assert "in front" not in shown, shown
    exec(source, {"ex": ex, "report": ex.check("broken_frame_1", sol.diagnosis(1))})
    shown = capsys.readouterr().out
    assert shown.count("in front (triangle 9)") == 2 and "0.973767" in shown, shown
    assert "frame 1 at (24, 28): in front (triangle 9) 0.039988, behind (3) 0.026233" in shown
    assert (
        "intended frame at (24, 28): in front (triangle 9) 0.960012, behind (3) 0.973767" in shown
    )


def test_broken_frame_causes_are_listed_alphabetically_never_in_the_frames_order():
    """r8: cell 1 printed the causes in the frames' order (causes 1-6 = frames 1-6)."""
    assert list(bf.CAUSES) == sorted(bf.CAUSES) and list(bf.EVIDENCE) == list(bf.CAUSES)
    shown = [c for c in bf.CAUSES if c in ANSWERS.values()]
    assert shown != [ANSWERS[n] for n in sorted(ANSWERS)]
    with pytest.raises(Exception) as info:  # a misspelt cause lists them, in the same order
        bf.as_diagnosis(("no such cause", (1, 1), 0.5))
    listed = [c for c in bf.CAUSES if c in str(info.value)]
    assert listed == sorted(listed) and len(listed) == len(bf.CAUSES)


def test_broken_frame_texts_do_not_pair_a_task_with_its_cause():
    """The symptoms say what is seen, never the mechanism, and frame 1's task text shares no
    telling word with the cause list (r5: "mapping" in both gave frame 1 away)."""
    cells = _cells()
    tasks = {k: v.lower() for k, v in cells.items() if k.endswith("_task")}
    for word in (r"mapping", r"reversed", r"1 − d", r"\bless\b"):
        assert not re.search(word, tasks["frame_1_task"] + tasks["frame_7_task"]), word
        assert not re.search(word, bf.CAUSES["depth function"].lower()), word
    symptoms = " ".join(ex.broken_frame(n).symptom.lower() for n in ANSWERS)
    for telling in ("depth write", "dotted", "gap", "too bright", "wrong faces", "hidden",
                    "behind", "in front", "vanish", "thin", "stripe", "glow", "dash"):  # fmt: skip
        assert telling not in symptoms, telling
    for key, gloss in bf.CAUSES.items():  # a cause, never the symptom it leaves
        for telling in ("vanish", "shows only", "stripe", "dark", "bright", "missing"):
            assert telling not in gloss, (key, gloss)


# -- the frames ----------------------------------------------------------------------------------
def _strings(value, depth=0, seen=None):
    """Every text reachable from ``value``'s public attributes, dict values and items."""
    seen = set() if seen is None else seen
    if id(value) in seen or depth > 6 or isinstance(value, np.ndarray | int | float):
        return
    seen.add(id(value))
    if isinstance(value, str):
        yield value
        return
    if isinstance(value, dict):
        for k, v in value.items():
            yield from _strings(k, depth + 1, seen)
            yield from _strings(v, depth + 1, seen)
        return
    if isinstance(value, tuple | list | frozenset | set):
        for v in value:
            yield from _strings(v, depth + 1, seen)
        return
    yield repr(value) if type(value).__repr__ is not object.__repr__ else ""
    for name in dir(value):
        if name.startswith("_") or name in ("cache",):
            continue
        try:
            attr = getattr(value, name)
        except Exception:
            continue
        if not callable(attr):
            yield from _strings(attr, depth + 1, seen)


@pytest.mark.parametrize("number", list(ANSWERS))
def test_broken_frame_objects_students_get_do_not_carry_the_answer(number):
    """The frame, the intended frame and the symptom only; no public attribute, repr or
    __dict__ value names the cause; both frames rendered with the same settings."""
    b = ex.broken_frame(number)
    public = {a for a in dir(b) if not a.startswith("_")}
    assert public == {"number", "symptom", "frame", "intended"}, public
    texts = " ".join([repr(b), str(b), *map(repr, vars(b).values()), *_strings(b)]).lower()
    cause = ANSWERS[number]
    for telling in {cause, cause.replace("-", " "), cause.replace(" ", "_")}:
        assert telling not in texts, telling

    def settings(frame):
        i, blend = frame.trace.debug.inputs, frame.trace.debug.blend
        return (i.width, i.height, i.depth_test, i.cull, i.depth_format, i.interpolation,
                i.subpixel_bits, frame.samples is None, blend.mode, blend.color_format,
                tuple(blend.clear_color))  # fmt: skip

    assert settings(b.frame) == settings(b.intended)
    assert str(b.frame.plan) == str(b.intended.plan) == bf.WITHHELD
    with pytest.raises(KeyError, match="withheld"):
        b.frame.plan["culling"]


def test_broken_frames_come_in_look_alike_groups_told_apart_only_by_their_histories():
    look_alike = [(a, b) for g in GROUPS for i, a in enumerate(g) for b in g[i + 1 :]]
    for a, b in look_alike:
        one, two = ex.broken_frame(a), ex.broken_frame(b)
        assert one.symptom == two.symptom
        assert np.array_equal(bf._rgb(one.frame), bf._rgb(two.frame))
        assert np.array_equal(bf._rgb(one.intended), bf._rgb(two.intended))
        assert not np.array_equal(bf._rgb(one.frame), bf._rgb(one.intended))
        assert {bf._parts_at(n, *_showing(n)) for n in (a, b)} == {STAGE[a], STAGE[b]}
    assert not ex.broken_frame(1).frame.trace.culled.any()
    assert ex.broken_frame(2).frame.trace.culled.any()


def _look_alike_groups(frames) -> list:
    """The frames' numbers grouped by their two pictures, pixel for pixel."""
    groups = {}
    for b in frames:
        key = (bf._rgb(b.frame).tobytes(), bf._rgb(b.intended).tobytes())
        groups.setdefault(key, []).append(b.number)
    return [tuple(g) for g in groups.values()]


def test_a_look_alikes_cause_tells_nothing_of_the_frames_cause():
    """r14/r16 11-2: each look-alike pair held two different causes, so a student who had
    solved one frame of a pair ruled its cause out for the other (and the picture narrowed
    the other to the few causes left). Now the strip's four look-alikes hold one cause twice
    and two others once: knowing a look-alike's cause tells neither that the frame has it nor
    that it has not, in the data and in what the checker says."""
    assert _look_alike_groups(bf.broken_frames()) == GROUPS
    for look in bf._REDRAWN:  # the frames redrawn for a check look alike in the same groups
        redrawn = [bf._redrawn(n, look) for n in ANSWERS]
        assert _look_alike_groups(redrawn) == GROUPS, look
    assert all(len({ANSWERS[n] for n in g}) > 1 for g in GROUPS)  # no picture names a cause
    for n in (6, 8):  # one look-alike shares the frame's cause, others do not
        others = {ANSWERS[m] == ANSWERS[n] for g in GROUPS if n in g for m in g if m != n}
        assert others == {True, False}, n
    # frame 2's cause, the cube look-alike's, is no answer for frame 1, nor frame 1's for 2
    failure = _first(2, ("depth function", (24, 28), sol.READ[1](ex.broken_frame(2), 24, 28)))
    assert failure.kind == "cause", failure.explanation
    failure = _first(8, ("blend order", (21, 39), sol.READ[5](ex.broken_frame(5), 21, 39)))
    assert failure.kind == "cause", failure.explanation


def test_a_diagnosis_copied_from_a_frame_with_the_same_cause_fails():
    """r18-3: frame 7 was frame 1's mistake at the same pixels, and frame 1's function passed
    11.7 unread. Frames that share a cause now bear its mark at other pixels: each solution,
    run on every other frame with its cause, fails there (the pictures agree at its pixel, or
    its histories lack the mark), and what each frame's solution reads is its own frame's."""
    same = [(m, n) for m in ANSWERS for n in ANSWERS if m != n and ANSWERS[m] == ANSWERS[n]]
    assert sorted(same) == [(1, 7), (5, 9), (6, 8), (7, 1), (8, 6), (9, 5)], same
    kinds = {}
    for m, n in same:
        report = ex.check(f"broken_frame_{n}", sol.diagnosis(m))
        assert not report.passed, (m, n)
        kinds[m, n] = report.failures[0].kind
    # off the other frame's changed pixels its history holds no glass (or no fragment): it raises
    assert kinds == {(1, 7): "pixel", (7, 1): "raised", (6, 8): "pixel without the mark",
                     (8, 6): "pixel without the mark", (5, 9): "raised", (9, 5): "raised"}, kinds  # fmt: skip
    # the cube's and the strip's changed pixels, and the two slivers' marked ones, differ
    marked = {n: {(int(r), int(c)) for r, c in np.argwhere(bf._differs(n))
                  if ANSWERS[n] in _marks(n, int(r), int(c))} for n in (1, 6, 7, 8)}  # fmt: skip
    assert marked[6] != marked[8] and marked[1] != marked[7]
    assert sol.BROKEN_FRAMES[6][1] not in marked[8] and sol.BROKEN_FRAMES[8][1] not in marked[6]
    assert sol.BROKEN_FRAMES[1][1] not in marked[7] and sol.BROKEN_FRAMES[7][1] not in marked[1]
    # the pane lies off the cube's and the strip's changed pixels: no copy between groups
    pane, cube, strip = (set(map(tuple, np.argwhere(bf._differs(n)).tolist())) for n in (3, 1, 5))
    assert pane and not pane & cube and not pane & strip


def test_reading_a_history_lists_every_field_an_evidence_is_read_from():
    """r18-6: the record's fields listed lacked ``outside`` (11.6's evidence, found only by
    ``dir(record)``) and ``piece`` (which cell 4 uses); each is a field of a history record."""
    text = _cells()["example_text"]
    record = ex.broken_frame(6).frame.history(22, 40).records[0]
    for name in ("outcome", "triangle", "piece", "depth", "depth_before", "outside",
                 "color_before", "color", "color_after", "shown"):  # fmt: skip
        assert f"`{name}`" in text and hasattr(record, name), name


def test_where_to_look_is_said_once_for_every_frame_never_in_one_task():
    """r18-1: "Not every pixel … shows every cause's mark: the list says where to look" stood
    in 11.6 alone, and the only cause the list places at some changed pixels is the sliver:
    frame 6's cause told, and frame 5's told not to be it. Said once, in how to diagnose."""
    cells = _cells()
    sentence = "the list says where to look"
    assert sentence in " ".join(cells["how_text"].split())
    for name, text in cells.items():
        if name != "how_text":
            assert sentence not in " ".join(text.split()), name


def test_the_notebook_never_says_look_alikes_differ_in_cause(capsys):
    """r16 11-2: the text says look-alike frames may or may not share a cause, never that each
    cause is used once; the numbers it gives (the count, the groups) are the ones a cell
    prints from the frames."""
    cells = _cells()
    intro = " ".join(cells["intro"].split())
    assert "may or may not share a cause" in intro, intro
    assert f"Here are {NUMBER_WORDS[len(ANSWERS)]} frames" in intro, intro
    text = " ".join(" ".join(v.split()) for k, v in cells.items() if k.endswith("text")
                    or k.endswith("task") or k == "intro").lower()  # fmt: skip
    for promise in ("each cause once", "a different cause", "another cause", "two causes",
                    "six causes", "each of the causes", "different causes"):  # fmt: skip
        assert promise not in text, promise
    # what the figure cell prints, run on the frames: the count and the look-alike groups
    import types

    import matplotlib.pyplot as plt

    # the cell's plt with a silent show: under another test's backend (ipympl, in the same
    # worker) plt.show() printed the canvas' repr into what the cell prints
    quiet = types.SimpleNamespace(subplots=plt.subplots, show=lambda *a, **k: None)
    broken = {b.number: b for b in bf.broken_frames()}
    exec(cells["frames_figure"], {"broken": broken, "np": np, "plt": quiet})
    plt.close("all")
    printed = capsys.readouterr().out
    assert printed == (f"{len(ANSWERS)} frames; alike pixel for pixel, rendered and intended: "
                       + ", ".join(map(str, GROUPS)) + "\n"), printed  # fmt: skip
    # frame 4 "contrived so that the pair looks alike" / "made to look like frame 3" hinted
    # that its cause is not frame 3's: said of frame 4 alone, before its check passes
    before = " ".join(
        (cells["frame_4_task"] + cells["frame_4_note"] + ex.frame_note(4, None)).split()
    )
    assert "the pair" not in before and "like frame 3" not in before, before
    assert "ontrived" not in before, before  # r18-5: nor that frame 4 alone was contrived
    task = " ".join(cells["frame_7_task"].split())
    assert "frames 5 and 6 pixel for pixel" in " ".join(task.split()), task
    # r21 D10: said once, in the intro, for all frames; repeated at 11.7 alone it read as a nudge
    tasks = [" ".join(v.split()) for k, v in cells.items() if k.endswith("task")]
    assert not any("may or may not share a cause" in t for t in tasks)


def test_the_frame_3_solution_says_the_glass_pane_is_drawn_not_stored():
    """r18-9: "The intended pane is stored at 0.598993": the pane is glass and writes no depth
    (its record's 'after' stays the wall's 0.600000)."""
    solution = _cells()["broken_frame_3_solution"].split("SOLUTION")[1]
    assert "drawn at 0.598993" in solution and "stored at 0.598993" not in solution
    pane = next(r for r in ex.broken_frame(3).intended.history(13, 52).records if r.shown)
    assert f"{pane.depth:.6f}" == "0.598993" and f"{pane.depth_after:.6f}" == "0.600000"


@pytest.mark.parametrize("number", [7, 8])
def test_the_frame_7_and_8_solutions_quote_the_values_their_histories_print(number):
    """Each solution's comment gives the values at its pixel as the two histories print them
    (r18-3: frame 7's now at the strip's (23, 41), frame 8's new)."""
    solution = _cells()[f"broken_frame_{number}_solution"].split("SOLUTION")[1]
    _, (row, col), _ = sol.BROKEN_FRAMES[number]
    assert f"({row}, {col})" in solution
    b = ex.broken_frame(number)
    printed = str(b.frame.history(row, col)) + str(b.intended.history(row, col))
    quoted = re.findall(r"0\.\d{4,6}", solution)
    assert len(quoted) >= 2 and all(q in printed for q in quoted), quoted


def test_broken_frame_6_accepts_only_pixels_the_sliver_crosses():
    """r8: 36 of the 96 changed pixels lie in the sliver's bounding box only. Each pixel that
    bears its mark holds a point of the sliver (found by sampling its edges densely, not by
    the check's own test), and (23, 40) is refused as a pixel, never as a cause (r9 11.6)."""
    frame = ex.broken_frame(6).frame
    xy = frame.trace.window[int(np.argmin(bf._altitudes(frame))), :, :2]
    t = np.linspace(0, 1, 200_001)[:, None]  # along its three edges: it is 0.1 px thick
    points = np.concatenate([a + t * (b - a) for a, b in zip(xy, np.roll(xy, -1, axis=0))])
    crossed = {(int(y), int(x)) for x, y in points}
    marked = {(int(r), int(c)) for r, c in np.argwhere(bf._differs(6))
              if "sliver" in _marks(6, int(r), int(c))}  # fmt: skip
    assert marked and marked <= crossed, sorted(marked - crossed)
    assert (22, 40) in marked and (23, 40) not in marked
    failure = _first(6, ("sliver", (23, 40), (0.78, 0.3)))
    assert failure.kind == "pixel without the mark", failure.explanation
    assert "the cause is another" not in failure.explanation
    assert "crosses" in bf.EVIDENCE["sliver"][1] or "passes" in bf.EVIDENCE["sliver"][1]


def test_broken_frame_5_compares_triangles_by_their_corners_not_their_records():
    """r7: at (20, 31) of frame 5 the first records differ (the strip is drawn first, so
    triangle 0 is another triangle in each frame), yet the histories first part at blending."""
    b = ex.broken_frame(5)
    first = [h.records[0].outcome for h in (b.frame.history(20, 31), b.intended.history(20, 31))]
    assert first == ["not_covered", "passed"]
    assert bf._parts_at(5, 20, 31) == "blending"
    _passes("broken_frame_5", _right(5, 20, 31))


def test_broken_frame_1_and_6_causes_say_what_their_frames_show():
    one = ex.broken_frame(1)
    row, col = _showing(1)
    rec = [r for r in one.frame.history(row, col).records
           if r.outcome in ("passed", "failed_depth")]  # fmt: skip
    kept = [r for r in rec if r.shown][0]
    assert all(kept.depth < r.depth for r in rec if r.outcome == "failed_depth")
    meant = {r.triangle: r.depth for r in one.intended.history(row, col).records
             if r.outcome in ("passed", "failed_depth")}  # fmt: skip
    assert meant[kept.triangle] == max(meant.values())  # the farther surface, as meant
    assert "farther surface" in bf.CAUSES["depth function"]
    six = ex.broken_frame(6)
    assert bf._thinnest(six.frame) < 0.2 and bf._thinnest(six.intended) > 1
    assert not (six.frame.triangle_id == 2).any()
    assert "modelled thinner" in bf.CAUSES["sliver"]
    assert six.frame.samples is None and six.intended.samples is None
    assert "stitches" in bf.CAUSES["z-fighting"]  # r8 11-6: the name's pattern, said
    # r18-7: the name is the fight, not the stitches; "it" is the thin triangle, not the pixel
    assert (
        "fight" in bf.CAUSES["z-fighting"] and "stitches: the name" not in bf.CAUSES["z-fighting"]
    )
    assert "lies outside that triangle" in bf.EVIDENCE["sliver"][1]


def test_every_causes_mark_describes_the_histories_not_its_own_name():
    """r18-7: "'depth test off' would show as: its depth test is off" said the name again."""
    words = bf._SIGNS["depth test off"][1]
    assert "its depth test is off" not in words and "says depth test off" in words, words
    assert "a fragment passes though the depth stored before it is nearer" in words, words
    # the history's first line does say so, where the test is off
    off = tr.render(tr.get_scene("intersecting_triangles"), None, 16, 12, trace=True,
                    depth_test=False)  # fmt: skip
    assert "depth test off" in str(off.history(6, 8)).splitlines()[0]


def test_broken_frames_3_to_6_draw_their_glass_without_depth_writes():
    b = ex.broken_frame(5)
    records = [r for r in b.frame.history(23, 41).records if r.outcome != "not_covered"]
    glass = [r for r in records if r.color and r.color[3] < 1]
    assert glass and not any(r.depth_write for r in glass)
    assert all(r.outcome == "passed" for r in records)
    four = ex.broken_frame(4)
    pane = [r.color for r in four.frame.history(13, 52).records if r.color and r.color[3] < 1]
    meant = [r.color for r in four.intended.history(13, 52).records
             if r.color and r.color[3] < 1]  # fmt: skip
    assert np.allclose(np.array(meant[0][:3]), np.array(pane[0][:3]) * pane[0][3])


# -- the form of an answer -----------------------------------------------------------------------
def test_broken_frame_answers_are_read_strictly():
    def said(answer, number=1):
        report = ex.check(f"broken_frame_{number}", lambda b: answer)
        assert report.failures[0].kind == "type", str(report)
        return report.failures[0].explanation

    assert "not one of the causes" in said(("the depth", (3, 4), 0.5))
    assert "only the cause" in said("depth function")
    assert "without the evidence" in said(("depth function", (24, 28)))
    assert "outside" in said(("depth function", (99, 4), 0.5))
    assert "row 24.7 is not an integer" in said(("depth function", (24.7, 31.2), 0.5))
    assert "col is a bool" in said(("depth function", (24, True), 0.5))
    stage = said(("depth function", (24, 28), "depth test"))  # r8's answer form
    assert "returned the stage 'depth test' as the evidence" in stage, stage
    assert "one number" in said(("depth function", (24, 28), (0.1, 0.2, 0.3)))
    # the evidence's form is read strictly for the frame's own cause (r16 N1: for another
    # cause, that the cause is wrong comes first: test_the_right_answer_passes_...)
    assert "a colour (r, g, b), three numbers" in said(
        ("missing premultiplication", (13, 52), 0.4), 4
    )
    # r309 S2: RGBA passed where the list asks (r, g, b); refused now, saying why
    rgba = said(("missing premultiplication", (13, 52), (0.31, 0.28, 0.24, 0.5)), 4)
    assert "it is (r, g, b): three numbers; yours has 4 (alpha?" in rgba, rgba
    assert "two numbers" in said(("sliver", (22, 40), 0.12), 6)
    wrong_cause = ex.check("broken_frame_1", lambda b: ("sliver", (22, 40), 0.12))
    assert wrong_cause.failures[0].kind == "cause", str(wrong_cause)
    assert "one number" in said(("depth function", (24, 28), float("nan")))
    assert "one number" in said(("depth function", (24, 28), True))


def test_broken_frame_cause_alone_reads_plainly():
    said = ex.check("broken_frame_1", lambda b: "depth function").failures[0].explanation
    assert "only the cause" in said and "(cause, (row, col), evidence)" in said, said
    assert "not a string" not in said, said


def test_broken_frame_numbers_are_checked():
    assert ex.broken_frame(np.int64(3)).number == 3
    with pytest.raises(TypeError, match="number must be an int"):
        ex.broken_frame(True)
    with pytest.raises(TypeError, match="number must be an int"):
        ex.broken_frame(3.0)
    with pytest.raises(ValueError, match="1 to 9"):
        ex.broken_frame(10)


def test_broken_frame_figure_marks_the_pixel_on_both_pictures_under_a_short_title():
    """r7 11-10: the pixel was marked on the broken frame only, and the title was cut."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    report = ex.check("broken_frame_5", lambda b: ("blend order", (20, 31), (0.1, 0.2, 0.3)))
    fig, ax = plt.subplots(figsize=(7, 4))
    report.plot(ax)
    xs = sorted(min(line.get_xdata()) for line in ax.lines)
    assert xs == [31, 31 + bf.W + 12], xs
    assert ax.get_title() == "broken_frame_5 fails: the frame shown", ax.get_title()
    plt.close(fig)


def test_the_check_figure_is_the_strip_of_two_frames_without_white_bands():
    """r18-15: a 7 x 4 in canvas held a strip of two 64 x 48 frames: a third of it was white.
    The notebook's figure is as tall as the strip with its title and labels, and the chosen
    pixel has a white halo (a projector)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    size = re.search(r"figsize=\(7, ([\d.]+)\)", _cells()["setup"])
    assert size and float(size[1]) <= 3.2, _cells()["setup"]
    report = ex.check("broken_frame_5", lambda b: ("blend order", (20, 31), (0.1, 0.2, 0.3)))
    fig, ax = plt.subplots(figsize=(7, float(size[1])))
    try:
        report.plot(ax)
        fig.canvas.draw()
        frames = ax.get_window_extent()
        assert frames.height / fig.bbox.height > 0.55, frames  # was 0.46 of 4 in
        for text in (ax.title, ax.xaxis.label):  # inside the figure
            box = text.get_window_extent()
            assert box.y0 >= 0 and box.y1 <= fig.bbox.height, (text.get_text(), box)
        assert all(line.get_path_effects() for line in ax.lines)
    finally:
        plt.close(fig)


def test_the_paired_history_tables_fit_a_592_px_column_at_12_px():
    """r18-11: at 1024 x 768 (JupyterLab, file browser open: a 592-px column) the two tables of
    "its pair beside" were 613-615 px wide, and the widget scrolled sideways ("outside E12 by
    6.1611 p" cut); set at 0.75em (9.75 px) they fitted, below the course's 12 px. Now each
    table is the narrow history (at most 80 characters a line: the header on two lines, no
    piece and sample columns where they repeat the triangle, a long "why" and each colour's
    "after" under their row) at 12 px, never wider than the column (a flex item is as wide
    as its longest line unless min-width:0). DejaVu Sans Mono, 0.602 em a character: 80
    characters at 12 px are 578 px."""
    pytest.importorskip("ipywidgets")
    from teachraster.pipeline.debugging.frame_history import NARROW, history_table
    from teachraster.widgets import FrameInspector
    from teachraster.widgets import frame_inspector as fi

    w = FrameInspector(frames=ex.frames_to_inspect(), pairs=ex.frame_pairs(), backend="image")
    try:
        w.scene.value = "frame 2"
        w.click_at(20.5, 30.5)  # the reviewer's pixel, (30, 20)
        assert "<b>intended 2</b>" in w.table.value
        markup = w.table.value
        assert "tri piece smp" not in markup and "tri  outcome" in markup
        w.beside.value = False
        assert "tri  outcome" in w.table.value and f"font-size:{fi.TABLE_FONT}" in w.table.value
    finally:
        w.close()
    assert markup.count(f"font-size:{fi.PAIRED_FONT}") == 2 and markup.count("min-width:0") == 2
    assert "max-width:100%" in markup and "overflow-x:auto" in markup
    # review r82 11-B: 14 px in a wide window, never under 12 px; 12 px up to a 1043-px one
    # (the 592-px column at 1024 x 768 holds an 80-character line only at 12 px)
    assert fi.PAIRED_FONT == fi.TABLE_FONT == "clamp(12px, 1.15vw, 14px)"
    assert 1043 * 0.0115 < 12 and 1218 * 0.0115 >= 14
    pixels = [(30, 20), (22, 40), (14, 10), (24, 28), (14, 47), (12, 20)]
    pixels += [a[1] for a in sol.BROKEN_FRAMES.values()]
    longest = max(len(line) for n in ANSWERS for frame in (ex.broken_frame(n).frame,
                  ex.broken_frame(n).intended) for r, c in pixels
                  for line in history_table(frame.history(r, c), narrow=True).splitlines())  # fmt: skip
    assert longest <= NARROW and NARROW * 0.602 * 12 <= 592, longest
    # the numbers are the table's own: every line of the wide table's values is in the narrow
    h = ex.broken_frame(7).frame.history(25, 52)
    narrow = " ".join(history_table(h, narrow=True).split())
    for value in re.findall(r"\d+\.\d+|\(.*?\)", str(h)):
        assert value in narrow or " ".join(value.split()) in narrow, value
    assert str(h) == history_table(h)  # print(h) is unchanged


def test_the_frame_inspector_shows_the_broken_frames():
    pytest.importorskip("ipywidgets")
    from teachraster.widgets import FrameInspector

    frames = ex.frames_to_inspect()
    assert list(frames)[:4] == ["frame 1", "intended 1", "frame 2", "intended 2"]
    assert frames["intended 5"] is ex.broken_frame(5).intended and len(frames) == 2 * len(ANSWERS)
    w = FrameInspector(frames=frames, backend="image")
    try:
        assert list(w.scene.options) == list(frames) and w.frame is frames["frame 1"]
        assert w.samples.disabled and w.glass.disabled and not w.scene.disabled
        w.scene.value = "frame 2"
        w.click_at(30.5, 20.5)
        assert w.history.outcomes == frames["frame 2"].history(20, 30).outcomes
        assert "culled" in w.table.value
        w.scene.value = "intended 2"
        w.click_at(30.5, 20.5)
        assert w.history.outcomes == frames["intended 2"].history(20, 30).outcomes
    finally:
        w.close()
    untraced = tr.render(tr.get_scene("cube").clip(4 / 3), 8, 6)
    with pytest.raises(ValueError, match="trace=True"):
        FrameInspector(frames={"a": untraced})
    with pytest.raises(TypeError, match="non-empty dict"):
        FrameInspector(frames={})


def test_the_passing_figure_marks_the_accepted_pixel_of_its_own_report():
    """r8 11-9: the passing figure marked nothing. It marks the pixel of the answer its own
    report accepted (a later check with another pixel does not move it)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    first = ex.check("broken_frame_5", _right(5, 20, 31))
    ex.check("broken_frame_5", sol.diagnosis(5))
    assert first.passed
    fig, ax = plt.subplots(figsize=(7, 4))
    first.plot(ax)
    xs = sorted(min(line.get_xdata()) for line in ax.lines)
    assert xs == [31, 31 + bf.W + 12], xs
    plt.close(fig)


def test_the_history_plot_says_smaller_down_not_nearer():
    """r11 11-F: "depth (nearer ↓)" on every frame, frame 1's too, whose nearer face has the
    larger depth: the axis states the order, not which is near."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.pipeline.debugging.frame_history import draw_history

    fig, ax = plt.subplots()
    try:
        draw_history(ax, ex.broken_frame(1).frame.history(24, 28))
        assert ax.get_ylabel() == "depth (smaller ↓)"
    finally:
        plt.close(fig)


def test_the_how_text_indexes_the_trace_by_piece():
    """r14: cell 4 said ``frame.trace.window[k, :, :2]`` "for triangle k", but the trace is
    indexed by clipped piece (``r.piece``, as the checker reads it); the two agree only where
    nothing is clipped, as in these frames."""
    how = " ".join(_cells()["how_text"].split())
    assert "window[r.piece, :, :2]" in how and "for triangle k" not in how, how
    assert "clipped piece" in how


def test_the_how_text_says_when_matching_by_corners_matters():
    """r32 D11-1: cell 4 taught matching triangles by their corners, which no graded answer
    needed where the numbers agree. It says the rule matters only where the numbers differ,
    which happens in some pairs and not others (no frame named: that would tell a cause),
    and that corners match in any order. Both claims hold for the frames shown and the
    redrawn ones."""

    def corners(frame):
        window = frame.trace.window[:, :, :2]
        return [tuple(sorted(map(tuple, np.round(t, 6)))) for t in window], window

    kinds = set()
    for n in ANSWERS:
        for b in (ex.broken_frame(n), bf._redrawn(n)):
            (mine, ordered), (theirs, _) = corners(b.frame), corners(b.intended)
            match = [theirs.index(k) if k in theirs else None for k in mine]
            if match == list(range(len(mine))) and len(mine) == len(theirs):
                kinds.add("alike")
                if not np.allclose(ordered, b.intended.trace.window[:, :, :2]):
                    kinds.add("same numbers, corners listed in another order")
            else:
                kinds.add("lacks one" if None in match else "another order")
    assert kinds == {"alike", "same numbers, corners listed in another order", "lacks one",
                     "another order"}, kinds  # fmt: skip
    how = " ".join(_cells()["how_text"].split())
    assert "in whatever order they are listed" in how, how
    assert "This matters only where the numbers differ: in some pairs here" in how, how
    for n in range(1, 10):
        assert f"frame {n}" not in how.split("The stages:")[0], n


def test_a_wrong_cause_is_told_where_to_look_first():
    """r14 (cosmetic): a wrong cause's ~400 characters began with the same sentence and put
    the instruction last; now it says first that the cause is not what the histories show and
    to find the first stage where they part, and the stated cause's own mark last."""
    failure = _first(6, ("z-fighting", (22, 40), 0.299992))
    text = failure.explanation
    assert failure.kind == "cause", text
    head = text[text.index("'z-fighting' is not what") :]
    assert head.index("find the first stage where they part") < 120, head
    assert head.index("find the first stage") < head.index("would show as"), head


def test_grading_says_the_source_names_the_causes():
    """r14 11-3: ``inspect.getsource`` of the frames' specs names every mistake; grading.md
    said the cause was hidden (no attribute or repr names it) without saying the source does."""
    import inspect

    source = inspect.getsource(bf)
    assert "reverse_depth=True" in source and "winding_reversed=True" in source
    text = " ".join((Path(__file__).parents[1] / "docs/grading.md").read_text().split())
    assert "the cause is not secret from a student who opens the checker's source" in text


def test_a_pixel_the_sliver_misses_is_told_how_far_its_square_reaches():
    """r18-8: "its centre lies 0.6063 px outside it" puzzled a student who knows a unit square
    reaches 0.707 px along a diagonal. The message says how far the square reaches towards
    that edge (0.5 (|cos| + |sin|) of its normal), or that it only touches it at a corner."""
    touching = _first(6, ("sliver", (14, 10), (0.1, 0.2))).explanation
    assert "lies 0.6063 px outside E12, and the square touches it at a corner" in touching
    beyond = _first(6, ("sliver", (15, 14), (0.1, 0.2))).explanation
    assert re.search(r"lies 0\.\d{4} px outside E\d\d, and the square reaches only 0\.60\d\d px",
                     beyond) or "touches it at a corner" in beyond, beyond  # fmt: skip
    thin = next(r for r in ex.broken_frame(6).frame.history(14, 10).records if r.triangle == 2)
    assert abs(bf._reach(ex.broken_frame(6).frame, thin) - 0.5 * 1.25 / np.hypot(1, 0.25)) < 1e-3


@pytest.mark.parametrize("number", [1, 7])
def test_history_legend_covers_no_tile_or_marker(number):
    """Review r21 D1: at frames 1 and 7 the rejected nearer fragment (the mark of 'depth
    function', the highest depth) lay under the legend, which had room for two rows and had
    three. At the inspector's figure size, after a draw, no legend overlaps a tile or a
    buffer marker at any changed pixel (every third, at most ~60), in either frame of the pair."""
    import matplotlib
    import matplotlib.pyplot as plt

    from teachraster.plotting import plot_history, use_style

    # the style within a block: set for good it leaks into this worker's later tests (CI
    # failed test_style_applies_to_the_widget_only after it, rcParams' font at 18)
    with matplotlib.rc_context():
        use_style("classroom")
        covered = _legend_covers(ex.broken_frame(number), plot_history, plt)
    assert not covered, f"frame {number}: the legend covers a tile or marker at {covered[:5]}"


def _legend_covers(broken, plot_history, plt) -> list:
    """The changed pixels (every third) whose history plot's legend covers a tile or marker."""
    fig = plt.figure(figsize=(4.6, 3.9), dpi=96)  # as FrameInspector's history figure
    ax = fig.add_axes((0.26, 0.24, 0.71, 0.66))
    covered = []
    try:
        for frame in (broken.frame, broken.intended):
            rows, cols = np.nonzero((frame.color != broken.intended.color).any(axis=2)
                                    | (broken.frame.color != frame.color).any(axis=2))  # fmt: skip
            pixels = sorted(zip(rows.tolist(), cols.tolist()))
            changed = [p for p in pixels if broken.frame.history(*p).records]
            # every third, at most ~60 spread over the frame: frame 1 changes 839 pixels,
            # and every third of them took 286 s of one CI worker (stop 43's durations)
            changed = changed[:: max(3, len(changed) // 60)]
            assert changed
            for row, col in changed:
                ax.clear()
                plot_history(ax, frame.history(row, col))
                # the layout (the legend's best place) without painting pixels: the same boxes
                # as canvas.draw(), for ~30 % less CPU (measured on frame 1)
                fig.draw_without_rendering()
                box = ax.get_legend().get_window_extent()
                tiles = [p for p in ax.patches if p.get_width() == 0.7]  # the depth tiles
                hit = [p for p in tiles if p.get_window_extent().overlaps(box)]
                for line in ax.lines:
                    xy = ax.transData.transform(np.c_[line.get_xdata(), line.get_ydata()])
                    hit += [tuple(q) for q in xy if np.isfinite(q).all() and box.contains(*q)]
                if hit:
                    covered.append((row, col))
    finally:
        plt.close(fig)
    return covered


def test_frames_7_to_9_have_no_free_wrong_cause(monkeypatch):
    """r21 D2: generic readers written for frames 1 to 6 passed frames 7, 8 and 9 by trial,
    one wrong cause each, free (two were). From frame 7 on every wrong cause waits 30 s more
    for each distinct one; a reader returning the right cause never waits; frames 1 to 6
    keep two free."""
    from teachraster.exercises import tries

    waits = []
    monkeypatch.setattr(tries, "_sleep", waits.append)
    monkeypatch.setattr(tries, "_FAILED", {})
    monkeypatch.setattr(tries, "_WRONG", {})
    monkeypatch.setattr(tries, "SETTING", "25")
    assert [bf.frame_exercise(n).free_causes for n in range(1, 10)] == [2] * 6 + [0] * 3
    for number in (7, 8, 9):
        name = f"broken_frame_{number}"
        wrong = next(c for c in ex.CAUSES if c != ANSWERS[number])
        pixel = sol.BROKEN_FRAMES[number][1]  # a changed pixel: the cause is judged there
        report = ex.check(name, lambda b, c=wrong, p=pixel: (c, p, 0.5))
        assert not report.passed and waits[-1:] == [30.0], (number, waits)
        assert "1 different wrong cause for" in report.tries and "none is free" in report.tries
        before = len(waits)
        assert (
            ex.check(name, sol.diagnosis(number)).passed and len(waits) == before
        )  # the right one: no wait
    report = ex.check("broken_frame_1", lambda b: ("sliver", (24, 28), 0.5))
    assert report.tries is None and len(waits) == 3  # frames 1 to 6: two still free
    # r22 D2: told in 11.7's own text, not only in the collapsed box; D3: the box's "a right
    # cause never waits" is said exactly (the count of failing checks waits too, never a pass)
    cells = _cells()
    task = " ".join(cells["frame_7_task"].split())
    assert (
        f"no wrong cause is free: a check naming a wrong cause waits {tries.CAUSE_STEP:g} s" in task
    )
    how = " ".join(cells["how_text"].split())
    assert "A check that passes never waits, and a right cause never waits for the wrong" in how
    assert "A right cause never waits." not in how


def test_the_text_says_what_starts_the_wait_counts_again(monkeypatch):
    """r32 D11-4: a student who set off the 30 s brake on frame 7 was not told how to reset
    it. The counts live in the kernel (:mod:`teachraster.exercises.tries`): a pass starts
    them again (checked here), a new kernel does (a new process); cell 4 and 11.7 say so."""
    from teachraster.exercises import tries

    waits = []
    monkeypatch.setattr(tries, "_sleep", waits.append)
    monkeypatch.setattr(tries, "_FAILED", {})
    monkeypatch.setattr(tries, "_WRONG", {})
    monkeypatch.setattr(tries, "SETTING", "25")
    pixel = sol.BROKEN_FRAMES[7][1]
    wrong = [c for c in ex.CAUSES if c != ANSWERS[7]][:2]
    for cause in wrong:
        assert not ex.check("broken_frame_7", lambda b, c=cause: (c, pixel, 0.5)).passed
    assert waits == [30.0, 60.0], waits
    assert ex.check("broken_frame_7", sol.diagnosis(7)).passed
    assert not ex.check("broken_frame_7", lambda b: (wrong[1], pixel, 0.5)).passed
    assert waits[-1] == 30.0 and tries._FAILED["broken_frame_7"] == 1, waits
    cells = _cells()
    how = " ".join(cells["how_text"].split())
    assert "Both counts live in the kernel: a passing check of the frame starts them again" in how
    assert "and so does a new kernel (restart it" in how, how
    task = " ".join(cells["frame_7_task"].split())
    assert "until a check of this frame passes or the kernel restarts" in task, task


def test_messages_say_what_the_redrawn_frame_changes_and_round_and_are_not_repeated():
    """r21 D6, D8: the cube's frames were said to be redrawn "with another wall, strip and
    depths" (the cube has neither); a wrong cause's value was quoted unrounded
    ("0.29999237048905164"); the same ~700-character message stood twice (frame shown and
    frame redrawn)."""
    typed = ex.check("broken_frame_2", lambda b: ("culled winding", (24, 28), 9))
    assert "other depths and another drawing order" in str(typed) and "wall" not in str(typed)
    pixel = sol.BROKEN_FRAMES[3][1]
    value = sol.READ[3](ex.broken_frame(3), *pixel)  # the frame shown's, typed in
    pane = ex.check("broken_frame_3", lambda b: ("z-fighting", pixel, value))
    assert "another wall and pane" in str(pane), str(pane)
    row, col = sol.BROKEN_FRAMES[5][1]
    report = str(
        ex.check("broken_frame_5", lambda b: ("sliver", (row, col), (None, 0.29999237048905164)))
    )
    assert "0.29999237" not in report and "0.299992" in report, report
    assert report.count("would show as") == 1 and "again" in report, report


def test_frame_5_note_says_the_glass_writes_no_depth():
    """r21 D7: "replaced wherever an opaque surface is drawn after it" holds because the glass
    writes no depth."""
    assert "writes no depth" in " ".join(bf._NOTES[5].split())


def test_inspector_names_a_frame_by_its_key_and_offers_no_empty_nan_view():
    """r21 D9: the title read "frame 1: the frame"; the view list offered "nan" (an empty map)
    in an exercise with no NaN pixel."""
    from teachraster.widgets import FrameInspector

    def values(dropdown) -> list:  # an option is a value or a (label, value) pair
        return [o[1] if isinstance(o, tuple) else o for o in dropdown.options]

    w = FrameInspector(frames=ex.frames_to_inspect(), pairs=ex.frame_pairs(), backend="image")
    try:
        assert "nan" not in values(w.view) and "depth_complexity" in values(w.view)
        assert w.ax.get_title() == w.scene.value, w.ax.get_title()
    finally:
        w.close()
    scene = FrameInspector("cube", backend="image")
    try:  # offered on the built-in scenes, labelled "nan (0 on built-in scenes)" (r112)
        assert "nan" in values(scene.view) and scene.ax.get_title().endswith(": the frame")
    finally:
        scene.close()


def test_a_pairs_two_tables_have_the_same_columns_and_wrap_alike():
    """r21 D4: the outcome column's width in each table decided which rows wrapped: at frame 1
    (24, 32) the broken table broke "9 not_covered … / outside E21 by 2.0690 px", the intended
    one did not. Laid out ``like`` each other, the header is the same and a triangle's row
    wraps in both or in neither; the inspector does so."""
    from teachraster.pipeline.debugging.frame_history import history_table
    from teachraster.widgets import FrameInspector

    broken = ex.broken_frame(1)
    for row, col in [(24, 32), (24, 28), (30, 20)]:
        a, b = broken.frame.history(row, col), broken.intended.history(row, col)
        one = history_table(a, narrow=True, like=b).splitlines()
        two = history_table(b, narrow=True, like=a).splitlines()
        assert one[2] == two[2], (one[2], two[2])  # the column header

        def wrapped(lines):
            rows = {}
            for i, line in enumerate(lines[3:], 3):
                if line[:3].strip().isdigit():
                    nxt = lines[i + 1] if i + 1 < len(lines) else ""
                    rows[int(line[:3])] = nxt.startswith(" " * 6) and not nxt[6:7].isspace()
                if line.startswith("colour buffer"):
                    break
            return rows

        first, second = wrapped(one), wrapped(two)
        for tri in set(first) & set(second):
            if broken.frame.history(row, col).records and first[tri] != second[tri]:
                why = [r for r in a.records if r.triangle == tri] + [
                    r for r in b.records if r.triangle == tri]  # fmt: skip
                assert len({r.outcome for r in why}) > 1, (row, col, tri, one, two)
    w = FrameInspector(frames=ex.frames_to_inspect(), pairs=ex.frame_pairs(), backend="image",
                       row=24, col=32)  # fmt: skip
    try:
        assert w.table.value.count("outside E21 by 2.0690 px") == 2
        assert w.table.value.count("tri  outcome                   depth") == 2, w.table.value
    finally:
        w.close()


def test_the_pair_view_puts_the_tables_under_the_picture():
    """r21 D3: the two tables stood below both figures, ~700 px under the picture clicked in a
    narrow column: with pairs they come right after the picture, the history chart after them
    (without pairs, picture and chart side by side as before)."""
    from teachraster.widgets import FrameInspector
    from teachraster.widgets.common import SLIDER_COLUMN_WIDTH

    w = FrameInspector(frames=ex.frames_to_inspect(), pairs=ex.frame_pairs(), backend="image")
    try:
        parts = list(w.widget.children)
        holding = [next(i for i, c in enumerate(parts) if c is x or x in getattr(c, "children", ()))
                   for x in (w.frame_widget, w.table, w.hist_display.widget)]  # fmt: skip
        assert holding == sorted(holding) and len(set(holding)) == 3, holding
    finally:
        w.close()
    text = " ".join(_cells()["inspector_text"].split())
    assert "right under the picture" in text, text
    # r62 (lesson 11 #4): without pairs too, the table comes right after the picture (not in
    # its row: the table's lines were cut there at 1024 x 768 and 150 %), the chart after it
    w = FrameInspector("intersecting_triangles", 32, 24, backend="image")
    try:
        parts = list(w.widget.children)
        holding = [next(i for i, c in enumerate(parts) if c is x or x in getattr(c, "children", ()))
                   for x in (w.frame_widget, w.table, w.hist_display.widget)]  # fmt: skip
        assert holding[0] < holding[1] < holding[2] and holding[1] == holding[0] + 1, holding
        # as wide as the column less ipywidgets' margins (r103 10-D: "100%" overflowed by 4 px)
        assert w.row.layout.width == w.col.layout.width == SLIDER_COLUMN_WIDTH
    finally:
        w.close()


def test_the_history_chart_names_the_frame_it_shows():
    """r22 D1: with the pair beside, the one chart stood under the intended frame's table,
    titled only "pixel (row 23, col 41)", and showed the frame on display: a student read it
    as the intended frame's. Its title names the frame drawn, and says "on display" while the
    pair's table stands beside; it follows the frame chosen and lies inside its figure."""
    import matplotlib

    from teachraster.plotting import use_style
    from teachraster.widgets import FrameInspector

    with matplotlib.rc_context():
        use_style("classroom")  # the notebook's style: the title keeps its size (>= 12 px)
        w = FrameInspector(frames=ex.frames_to_inspect(), pairs=ex.frame_pairs(),
                           backend="image", row=23, col=41)  # fmt: skip
        try:
            w.scene.value = "frame 5"
            assert w.hist_ax.get_title() == "frame 5 (on display): row 23, col 41"
            w.scene.value = "intended 5"
            assert w.hist_ax.get_title().startswith("intended 5 (on display): ")
            w.beside.value = False  # one table: nothing to tell apart
            assert w.hist_ax.get_title() == "intended 5: pixel (row 23, col 41)"
            w.beside.value = True
            w.row.value = 24
            title = w.hist_ax.title
            assert title.get_text() == "intended 5 (on display): row 24, col 41"
            w.hist_fig.canvas.draw()
            box = title.get_window_extent(w.hist_fig.canvas.get_renderer())
            assert 0 <= box.x0 and box.x1 <= w.hist_fig.bbox.width, box
            assert title.get_fontsize() * w.hist_fig.dpi / 72 >= 12, title.get_fontsize()
        finally:
            w.close()


def test_each_frame_opens_at_a_pixel_where_its_pair_differs():
    """r32 D11-2: every frame opened at (24, 32), where frames 3 to 9 agree with their
    intended frames, so the two tables were the same. A frame chosen in the list opens at a
    pixel where its pair differs and that bears the mark of its mistake (r298 W2: frame 6
    opened at (23, 47), which its sliver misses): the pixel on show if it is one (so a pixel
    carries over to a look-alike), else the nearest that is; the notebook says so."""
    from teachraster.widgets import FrameInspector
    from teachraster.widgets.frame_inspector import changed_pixel

    w = FrameInspector(frames=ex.frames_to_inspect(), pairs=ex.frame_pairs(),
                       marks=ex.frame_marks(), backend="image")  # fmt: skip
    try:
        assert bf._differs(1)[w.row.value, w.col.value]
        for n in ANSWERS:
            for name in (f"frame {n}", f"intended {n}"):
                w.row.value, w.col.value = 24, 32  # a pixel of plain wall in frames 3 to 9
                w.scene.value = name
                at = (w.row.value, w.col.value)
                assert bf._differs(n)[at], (name, at)
                assert ANSWERS[n] in _marks(n, *at), (name, at)
                assert (w.history.row, w.history.col) == at
                assert f"row {at[0]}, col {at[1]}" in w.hist_ax.get_title()
                assert w.table.value.count("<b>") == 2 and f"<b>{name}</b>" in w.table.value
                tables = re.findall(r"<pre[^>]*>(.*?)</pre>", w.table.value, re.S)
                assert tables[0] != tables[1], (name, at)  # the two histories differ there
        w.scene.value = "frame 1"
        w.row.value, w.col.value = 30, 20  # differs in frame 1 and its look-alike frame 2
        w.scene.value = "frame 2"
        assert (w.row.value, w.col.value) == (30, 20)
        w.scene.value = "frame 5"  # (30, 20) agrees there: the nearest changed pixel
        at = (w.row.value, w.col.value)
        rows, cols = np.nonzero(bf._differs(5))
        nearest = min((r - 30) ** 2 + (c - 20) ** 2 for r, c in zip(rows, cols))
        assert (at[0] - 30) ** 2 + (at[1] - 20) ** 2 == nearest, at
    finally:
        w.close()
    # a pair that agrees everywhere keeps the pixel
    f = ex.broken_frame(1).frame
    assert changed_pixel(f, f, 3, 4) == (3, 4)
    text = " ".join(_cells()["inspector_text"].split())
    assert "opens at a pixel where it and its pair differ" in text, text
    assert "ex.frame_marks()" in _cells()["inspector"]
    # r298 W2: without the marks, frame 6 opened from (24, 32) where its sliver does not pass
    six = ex.broken_frame(6)
    assert ANSWERS[6] not in _marks(6, *changed_pixel(six.frame, six.intended, 24, 32))


def test_a_next_that_finds_nothing_is_told_what_happened():
    """Review r23 D4: a diagnosis whose ``next(...)`` found no record was told only "your
    function raised StopIteration"; the report says a next(...) found nothing."""

    def copied(b):
        records = b.frame.history(0, 0).records
        return "depth function", (0, 0), next(r.depth for r in records if r.outcome == "x")

    text = str(ex.check("broken_frame_1", copied))
    assert "StopIteration: a next(...) found no item" in text, text


def test_the_sliver_is_outlined_dashed_and_drawn_in_the_failure_picture():
    """r298 W1, FIG1: the sliver of frames 6 and 8 covers no pixel centre, so no view showed
    it. Every submitted triangle is outlined from the trace, the sliver dashed and the others
    solid; a "sliver" answer's failure picture adds the pixel's square and the thin triangle,
    enlarged, which its explanation names."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Polygon

    from teachraster.plotting.frame_debug import plot_triangle_edges

    fig, ax = plt.subplots()
    try:
        for n in (6, 8):
            frame = ex.broken_frame(n).frame
            thin = int(np.argmin(bf._altitudes(frame)))
            lines = plot_triangle_edges(ax, frame)
            dashed = [dashes is not None for _, dashes in lines.get_linestyles()]
            assert len(dashed) == 3 * len(frame.trace.window), n
            assert [i // 3 for i, d in enumerate(dashed) if d] == [thin] * 3, n
        ax.clear()
        report = ex.check("broken_frame_6", lambda b: ("sliver", (23, 47), (0.8489, 0.299992)))
        assert "does not pass through this pixel's square" in report.failures[0].explanation
        report.plot(ax)
        assert ax.get_xlim()[1] == 2 * bf.W + 12 + 12 + bf.ZOOM_SIZE
        needle = [p for p in ax.patches if isinstance(p, Polygon)]
        assert len(needle) == 1  # clipped to the zoom, not the whole strip
        # r309 S5: drawn in the strip's blue it read as the strip; a colour of its own, keyed
        assert matplotlib.colors.to_hex(needle[0].get_edgecolor()) == bf.THIN_COLOUR.lower()
        key = [t.get_text() for t in ax.get_legend().get_texts()]
        assert key == ["the thin triangle"], key
        assert needle[0].get_clip_box().width < ax.bbox.width / 3
        assert "(23, 47) rendered, enlarged" in ax.get_xlabel()
    finally:
        plt.close(fig)


def test_the_history_header_names_the_compare_and_the_depth_format():
    """r298 M1, S1: frame 3's tie comes from a 16-bit depth buffer and frames 1 and 7 keep the
    smaller depth (LESS) of data mapped the other way; the header said neither."""
    first = ex.broken_frame(3).frame.history(13, 52).table().splitlines()[0]
    assert first.endswith("depth test on (LESS), unorm16 depth:"), first
    off = tr.render(tr.get_scene("intersecting_triangles"), None, 64, 48, trace=True,
                    depth_test=False).history(24, 32).table().splitlines()[0]  # fmt: skip
    assert off.endswith("depth test off (ALWAYS), float64 depth:"), off


def test_a_triangle_number_as_an_integral_float_is_read():
    """r298 S4: 9.0 was refused as "not an int"; 9.5 still is."""
    assert bf._as_evidence("culled winding", 9.0) == 9
    assert bf._as_evidence("culled winding", np.float64(9.0)) == 9
    with pytest.raises(Exception, match="triangle's number"):
        bf._as_evidence("culled winding", 9.5)


def test_r309_the_text_says_four_decimals_and_asks_frame_3_in_the_buffers_steps():
    """r309 S4: "four digits" for values printed to four decimals; S2: a colour is (r, g, b);
    M3: 11.3b asks frame 3's tie in unorm16 steps, its question printed only in frame 3's note
    (asked before 11.3 passes, it would tell the cause), its solution's number the reference's."""
    cells, order = _cells(), list(_cells())
    how = " ".join(cells["how_text"].split())
    assert "four decimals they print" in how and "four digits" not in how, how
    assert "a colour as (r, g, b), three numbers" in how, how
    assert order.index("frame_3_steps_task") == order.index("frame_3_note") + 1
    assert order[order.index("frame_3_steps_task") + 1 :][:2] == [
        "broken_frame_3_steps_solution",
        "broken_frame_3_steps_check",
    ]
    task = " ".join(cells["frame_3_steps_task"].split()).lower()
    # r318 C2: neither heading nor text names the depth format or lesson 05b before 11.3
    for telling in ("unorm", "z-fight", "tie", "16-bit", "precision", "buffer", "05b", "format"):
        assert telling not in task, telling
    assert "unorm16" not in cells["broken_frame_3_steps_solution"].split("### BEGIN")[0]
    # r377 F4: 11.3b asks the fewest depth bits in which frame 3's pane wins wherever the
    # wall lies (the question before was a transcription); the solution reasons it out
    bits = sol.broken_frame_3_steps(ex.broken_frame(3))
    assert "gap * (2**n - 1) > 1" in cells["broken_frame_3_steps_solution"]  # r388 G6
    note = ex.frame_note(3, ex.check("broken_frame_3", sol.diagnosis(3)))
    # r318 M1: the formula is the check's hint, not the question's; the drawn depths are the
    # trace's (the histories print the pane's as stored, tied)
    assert "11.3b asks:" in note and "round(" not in note and "trace.window[k, :, 2]" in note
    assert "11.3b" not in ex.frame_note(3, None)
    # r318: the redrawn frames' panes lie other distances from the wall (typed in, it fails)
    cases = bfs.BROKEN_FRAME_3_STEPS.cases()
    assert [c[2] for c in cases] == [bits, 22, 19, 21, 18], cases  # r388 G1-G3, r395 N1
