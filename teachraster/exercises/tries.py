"""Failing checks of one task, counted in this kernel, and the wait past a generous number.

Exercise 11's verdict is an oracle: a loop over the ten causes and a few dozen generic history
readers ("the depth of the first culled record", "the colour after of the last passed one")
finds every frame's point without a diagnosis (r12 11-2: 2,096 checks in 51 s passed frames 1
to 5). A diagnosis needs a few checks; that blind product needs hundreds (a loop that reads
the verdict, a wrong cause first, needs a few dozen: r13, docs/grading.md; this does not stop
it). So an exercise may set
:attr:`~.exercise.Exercise.tries`: past that many failing checks of the same task in one
kernel, the report says a diagnosis does not need that many, and each further failing check
of the task waits, once judged and before it answers, :data:`WAIT_STEP` more for each failing check past the number,
at most :data:`WAIT_MOST` (a search of 300 checks then takes hours; a student past the number
waits seconds). A passing check starts the count again and never waits (a blind search is slow
by its failing checks; r22 D3: a right answer after 27 failing checks waited 2.1 s, where the
notebook says a right cause never waits).

The wait is a sleep after the check's budget closed: it takes no CPU and none of the student's
budget, and it never hangs (capped). A check run inside the student's function (inside another
check) does not wait: it never passes anyway. The environment variable
``TEACHRASTER_CHECK_TRIES`` sets the number for a class (``0``: no counting, no wait; the test
suite sets it). It is read once, when :mod:`teachraster.exercises` is first imported (the
notebooks import it in their first locked cell, before any student cell), into
:data:`SETTING`: a student's cell that sets the variable later changes nothing (r13: one line
``os.environ[...] = "0"`` switched the wait off, under ``nbgrader autograde`` too). What this
does not stop: a new kernel starts the count at 0 (docs/grading.md says so), and code that
rebinds this module's names; it makes a blind search slow, not impossible.

A second brake counts *causes*, not checks (r14 11-4: a loop over the ten causes and five
generic readers, told "not the frame's cause" and moving to the next, passed four frames in
65 checks, under the 25 allowed). A diagnosis names one or two wrong causes at most; past
:data:`FREE_CAUSES` distinct wrong causes of one task, every check that names a wrong cause
waits, once judged and before it answers, :data:`CAUSE_STEP` seconds for each distinct wrong
cause past that number, at most :data:`CAUSE_MOST` (a blind loop over the ten causes then
pays minutes a frame; a check that names the right cause never waits for it). A pass starts
this count again too, and the same setting switches it off. An exercise may allow fewer
(:attr:`~.exercise.Exercise.free_causes`): exercise 11's frames 7 to 9 come after six
diagnoses, and generic readers written for frames 1 to 6 passed them by trial with one wrong
cause each (r21 D2), so there every wrong cause waits.
"""

from __future__ import annotations

import os
import re
import threading
import time

#: The environment variable that sets the failing checks of one task before the wait (0: off).
TRIES_VARIABLE = "TEACHRASTER_CHECK_TRIES"
#: Seconds of wait added by each failing check past the number, and the longest wait.
WAIT_STEP, WAIT_MOST = 1.0, 30.0

#: The variable's text as the kernel started (read once, at import: see the module's note).
SETTING = os.environ.get(TRIES_VARIABLE, "")

#: Distinct wrong causes of one task that cost nothing, the wait for each one past them, the
#: longest such wait (seconds).
FREE_CAUSES, CAUSE_STEP, CAUSE_MOST = 2, 30.0, 300.0

_FAILED: dict[str, int] = {}
_WRONG: dict[str, set] = {}
_HINTED: dict[str, set] = {}  # each task's different failing answers, whatever the setting (hints)
#: How many different failing answers of a task come before its full words (r46 S2, X2).
HINTED_ANSWERS = 2
_LOCK = threading.Lock()
_sleep = time.sleep  # the tests replace it


def allowed(default: int | None) -> int | None:
    """The failing checks of one task allowed before the wait: ``default`` (an exercise's
    :attr:`~.exercise.Exercise.tries`), or ``TEACHRASTER_CHECK_TRIES`` when it was set as the
    package was imported (:data:`SETTING`); None: no limit (the exercise sets none, or the
    variable is 0). A value that is not a whole number of 0 or more is a ``ValueError``
    naming the variable."""
    if default is None:
        return None
    text = SETTING.strip()
    if not text:
        return default
    if not text.isdigit():
        raise ValueError(
            f"the environment variable {TRIES_VARIABLE} must be a whole number of failing "
            f"checks (0: no limit), got {text!r}"
        )
    return int(text) or None


def wait(name: str, default: int | None) -> float:
    """Wait before checking task ``name`` if it failed more than allowed; the seconds waited."""
    limit = allowed(default)
    if limit is None:
        return 0.0
    with _LOCK:
        past = _FAILED.get(name, 0) - limit
    seconds = min(WAIT_MOST, WAIT_STEP * past) if past > 0 else 0.0
    if seconds > 0:
        _sleep(seconds)
    return seconds


def counted(name: str, default: int | None, passed: bool) -> str | None:
    """Count one check of task ``name``; the report's note once it failed more than allowed."""
    limit = allowed(default)
    if limit is None:
        return None
    with _LOCK:
        failed = _FAILED[name] = 0 if passed else _FAILED.get(name, 0) + 1
    if failed <= limit:
        return None
    return (
        f"{failed} failing checks of {name} in this kernel: a diagnosis does not need that "
        "many tries (read the two histories of one changed pixel, stage by stage). Each "
        f"further failing check waits {WAIT_STEP:g} s more before it answers (at most "
        f"{WAIT_MOST:g} s), until one passes; a passing check never waits"
    )


def wrong_causes(name: str, default: int | None, causes, passed: bool,
                 free: int = FREE_CAUSES) -> str | None:  # fmt: skip
    """Note the wrong ``causes`` one check of task ``name`` was given, and wait past
    ``free`` distinct ones (:data:`FREE_CAUSES`, or the exercise's
    :attr:`~.exercise.Exercise.free_causes`: see the module's note); the report's note, if
    any."""
    if allowed(default) is None:
        return None
    with _LOCK:
        seen = _WRONG.setdefault(name, set())
        if passed:
            seen.clear()
        seen.update(causes)
        past = len(seen) - free
    if not causes or past <= 0:
        return None
    seconds = min(CAUSE_MOST, CAUSE_STEP * past)
    _sleep(seconds)
    return (
        f"{len(seen)} different wrong cause{'s' if len(seen) > 1 else ''} for {name} in this "
        f"kernel{'' if free else ' (none is free on this frame)'}: the cause is found by "
        "reading the two histories of one changed pixel, not by trying the names. This check "
        f"waited {seconds:g} s, and each further wrong cause waits {CAUSE_STEP:g} s more (at "
        f"most {CAUSE_MOST:g} s), until one passes"
    )


def hinted_check(name: str, answer: object) -> bool:
    """Count one failing check of task ``name`` whose words would give the answer away; True
    (hints instead of those words, :attr:`~.exercise.Exercise.hints`) until
    :data:`HINTED_ANSWERS` different failing ``answer`` s (a fingerprint of what the student's
    function returned) have been seen in this kernel. Rerunning the same wrong cell never
    brings the full words (r46 S2: the second identical try printed the formula). Unlike the
    wait, this count is not switched off by ``TEACHRASTER_CHECK_TRIES`` and never starts
    again: a student who saw the full words once has seen them."""
    with _LOCK:
        seen = _HINTED.setdefault(name, set())
        seen.add(answer)
        return len(seen) < HINTED_ANSWERS


def hints_spent(name: str) -> bool:
    """Have :data:`HINTED_ANSWERS` different answers of task ``name`` failed in this kernel
    (its checks now give the full words)? A case figure that draws the method (7.2's four
    texels and their weights) draws it only then (r64 07 D2)."""
    with _LOCK:
        return len(_HINTED.get(name, ())) >= HINTED_ANSWERS


def spend_hints(names) -> None:
    """Count task ``names``' hints as used: their checks give the full words from the first
    failing try (the tests: whether a check hints must not depend on which tests ran before
    it in the same process)."""
    with _LOCK:
        for name in names:
            _HINTED[name] = {("spent", k) for k in range(HINTED_ANSWERS)}


def forget_hints(name: str | None = None) -> None:
    """Start the hints' count of task ``name`` (of every task: None) again (the tests)."""
    with _LOCK:
        if name is None:
            _HINTED.clear()
        else:
            _HINTED.pop(name, None)


def apply_hints(words: str, hints) -> str:
    """``words`` with each ``(text, hint)`` of ``hints`` put in: ``text`` a string replaced
    where it occurs, or a compiled pattern substituted (the one way every staged hint is put
    in, in a report and in words said outside it: :func:`.level_of_detail.hinted`). It lives
    here, not in :mod:`.checks`, which imports every exercise: there, level_of_detail and the
    checks imported each other.

    >>> apply_hints("level 2 because rho = 4", [("level 2", "level ?")])
    'level ? because rho = 4'
    """
    for text, hint in hints:
        words = text.sub(hint, words) if isinstance(text, re.Pattern) else words.replace(text, hint)
    return words


#: What a report (or a capstone quoting an exercise's check) adds to words given as a hint. Only
#: failures whose words were hinted count (:func:`hinted_check`): r317 C1, "2 different answers
#: have failed" read as any two failures, and a third still got the hint; r421 S1: the second
#: different answer already gets the full words, which "once 2 ... have failed with a hint like
#: this one" did not say.
HINT_ONLY = (
    "a hint only: work from it and the numbers of the case (the full words come once "
    f"{HINTED_ANSWERS} different answers of yours have failed, this one counted: a rerun of "
    "the same answer keeps the hint)"
)


def staged(name: str, words: str, hints) -> tuple[str, bool]:
    """``words`` as task ``name``'s check says them now: with ``hints`` in place of the words
    that give the answer away until :data:`HINTED_ANSWERS` different answers of the task have
    failed in this kernel (the one rule, for the check's report, a picture's pixel and the
    capstone quoting the exercise: r107 N12-1); and whether a hint was put in. The answer is
    counted by the check (:func:`hinted_check`), not here."""
    if hints_spent(name):
        return words, False
    said = apply_hints(words, hints)
    return said, said != words


def tells(text, words: str) -> bool:
    """Do ``words`` hold ``text``, a hint's string or compiled pattern (one whose numbers
    differ from case to case: r64 04, a crossing's t and point)? The same string-or-pattern
    rule as :func:`apply_hints`.

    >>> tells(re.compile(r"t = [0-9.]+"), "at t = 0.25"), tells("level 2", "level 3")
    (True, False)
    """
    return bool(text.search(words)) if isinstance(text, re.Pattern) else text in words
