"""Check one exercise: run its cases, compare, explain, and build the report.

Four steps, all within the check's time budget (:mod:`.running`): run every case (the
student's function and the strict reading of its answer), stopping at the first case past its
time limit; compare each answer with the package's; name the mistake behind the failures,
knowing every answer (:mod:`.diagnosis`); and look whether the function merely calls the
package's own answer (:mod:`.package_answers`, watching every case, in any thread). The
report's picture (the exercise's scene) is built here and run only when it is drawn. The same steps check every exercise, described
by an :class:`~.exercise.Exercise`.
"""

from __future__ import annotations

import inspect

import numpy as np

from .diagnosis import Result, diagnose
from .exercise import Exercise, content_key, copies
from .package_answers import names_read, package_note, parameters_read, watching
from .report import Failure, Report
from .running import SKIPPED, current, run_case, run_checker

#: Outcome kinds after which the check stops (the time is spent).
STOPS = ("timeout", "budget")


class Returned:
    """What the student's function returned on each case, before it was read: one value and
    a key of all of them (None: a value without a key), by case (the constant's test,
    :func:`.diagnosis._constant`)."""

    def __init__(self, fn):
        self.fn, self.case, self.raw, self.keys = fn, 0, {}, {}

    def __call__(self, *args, **kwargs):
        value = self.fn(*args, **kwargs)
        self.raw.setdefault(self.case, value)
        keys = self.keys.setdefault(self.case, set())
        if keys is not None:
            key = content_key(value) if _small(value) else None
            if key is None:
                self.keys[self.case] = None
            else:
                keys.add(key)
        return value

    def key(self, case: int) -> frozenset | None:
        keys = self.keys.get(case)
        return None if not keys else frozenset(keys)


#: The most values of an answer whose key is kept (a huge answer costs no time: the answers
#: as read decide whether it is constant).
KEYED = 4096


def _small(value) -> bool:
    if isinstance(value, (list, tuple)):
        return len(value) <= 64 and all(_small(v) for v in value)
    return np.size(value) <= KEYED if isinstance(value, np.ndarray) else True


def run_all(spec: Exercise, fn, cases, returned: Returned | None = None) -> list:
    """(case, outcome) of each case run, in order, until the check stops; what the function
    returned is noted in ``returned``."""
    ran = []
    student = fn if returned is None else returned
    for k, case in enumerate(cases):
        args = case[1]
        if returned is not None:
            returned.case = k
        if spec.call is not None:
            body = lambda args=args: spec.call(student, copies(args))  # noqa: E731
        else:
            body = lambda args=args: spec.convert(student(*copies(args)))  # noqa: E731
        outcome = run_case(body, case=f"{k + 1} of {len(cases)}")
        if outcome.error == SKIPPED:
            break
        ran.append((case, outcome))
        if outcome.kind in STOPS:
            break
    return ran


def parameters(fn) -> tuple:
    """The names of ``fn``'s arguments, as the student wrote them (empty if unreadable)."""
    try:
        return tuple(inspect.signature(fn).parameters)
    except (TypeError, ValueError):
        return ()


def all_not_implemented(ran) -> bool:
    """The untouched stub: every case that ran raised NotImplementedError."""
    return bool(ran) and all(outcome.not_implemented for _, outcome in ran)


def check_exercise(spec: Exercise, fn) -> Report:
    """Run, compare, explain (see the module docstring): the report of exercise ``spec``."""
    cases = spec.cases()
    returned = Returned(fn)
    with watching(spec) as seen:  # the listed answers, called from any thread (r11 09-B2)
        ran = run_all(spec, fn, cases, returned)
    scene = _scene(spec, fn)
    if all_not_implemented(ran):
        # issue 30 (r46): the stub's picture draws a case's inputs only, or nothing (most
        # drawings show the answer, which no try has earned yet: Report.plot says so)
        inputs = _drawer(spec, cases[0], None) if spec.inputs_drawn else None
        return Report(spec.name, [], len(cases), True, inputs, scene=scene)
    results = []
    for k, (case, outcome) in enumerate(ran):
        if outcome.error is None:
            label, args, expected = case
            value = outcome.value
            ok = run_checker(lambda v=value, e=expected, a=args: bool(spec.same(v, e, a)), False)
            raw, key = returned.raw.get(k), returned.key(k)
            results.append(Result(k, args, expected, outcome.value, ok, raw, key))
    reads = run_checker(lambda: names_read(fn) | parameters_read(fn), frozenset())
    said = diagnose(spec, results, run_checker(lambda: parameters(fn), ()), reads)
    answers = {r.index: r.got for r in results}
    failures = []
    # r439 M4: a None on every case is a forgotten return, whatever the exercise's none_words
    some = any(outcome.kind != "none" for _, outcome in ran)
    for k, (case, outcome) in enumerate(ran):
        label, _, expected = case
        if outcome.error is not None:
            draw = _drawer(spec, case, None)
            text = _without_answer(spec, case[1], outcome, expected if some else None)
            failures.append(Failure(label, text, expected, None, draw, outcome.kind))
        elif k in said:
            kind, text = said[k]
            got = answers[k]
            failures.append(Failure(label, text, expected, got, _drawer(spec, case, got), kind))
    stopped = current().stopped
    if scene is not None and stopped is not None:
        scene.blocked = f"not run: {stopped}"
    package = None
    if stopped is None and spec.answers:
        package = package_note(spec, fn, seen)
    shown = cases[spec.example] if spec.example < len(cases) else cases[0]
    # r164: a function that is not counted has no answer of its own to draw ("yours" was
    # drawn in the passing green beside the note that it does not count)
    example = _drawer(spec, shown, shown[2] if package is None else None)
    precision = None if failures else _low_precision(results)
    if not failures and package is None and spec.tool_note is not None:
        tool = run_checker(lambda: spec.tool_note(fn), None)
        precision = "; ".join(t for t in (precision, tool) if t) or None
    return Report(
        spec.name, failures, len(cases), False, example, stopped, len(ran), package,
        precision=precision, scene=scene,
    )  # fmt: skip


def _without_answer(spec: Exercise, args, outcome, expected=None) -> str:
    """The words of a case that gave no answer: with the exercise's ``call_words``, the call
    first and, for an exception, the traceback's last line in the student's code (r248 S1);
    a None the exercise's ``none_words`` explain, where they do (r439 M4)."""
    error = outcome.error
    if spec.none_words is not None and outcome.kind == "none" and expected is not None:
        error = run_checker(lambda: spec.none_words(args, expected), "") or error
    if spec.raised_words is not None and outcome.kind == "raised":
        error += run_checker(lambda: spec.raised_words(args, outcome.error), "")
    if spec.call_words is None or outcome.kind in STOPS or outcome.error == SKIPPED:
        return error
    call = run_checker(lambda: spec.call_words(*args), "")
    where = f"; the traceback's last line in your code: {outcome.where}" if outcome.where else ""
    return f"{call}: {error}{where}" if call else f"{error}{where}"


def _low_precision(results) -> str | None:
    """The note for answers computed in float32 (float16) that pass within its rounding."""
    for r in results:
        name = float_type(r.got)
        if name is not None:
            return (f"your answers are {name}: right within {name}'s rounding, so they pass; "
                    "in float64 they would match to the last digit")  # fmt: skip
    return None


def float_type(value) -> str | None:
    """ "float32" or "float16" when ``value`` (or a number in it) has that type, else None."""
    dtype = getattr(value, "dtype", None)
    if dtype is not None and dtype.kind == "f" and dtype.itemsize <= 4:
        return f"float{dtype.itemsize * 8}"
    if isinstance(value, tuple | list):
        return next((t for t in map(float_type, value) if t is not None), None)
    return None


def _scene(spec: Exercise, fn):
    if spec.scene is None:
        return None
    scene = spec.scene(fn)
    scene.seconds, scene.slow = current().seconds, current().slow
    return scene


def _drawer(spec: Exercise, case, got):
    if spec.draw is None:
        return None

    def drawing(ax):
        return spec.draw(ax, case, got)

    return drawing
