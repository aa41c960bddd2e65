"""Is the student's answer the package's own? (``from teachraster import edge_function``)

The package computes every exercise's answer; a student may hand it in as their own: the
function itself (``edge_function = tr.edge_function``), or a wrapper that calls it
(``return tr.mip_level(ddx, ddy, size)``). Each :class:`~.exercise.Exercise` lists the
package functions that are its answer (:class:`~.exercise.PackageAnswer`; the same
``tr.sample`` is bilinear's answer only with ``filter="bilinear"``). :func:`package_note`
looks at the function, and runs it once on a case while a profile hook
(``sys.setprofile``, in the thread that runs the case) watches for a call into one of
those functions. Package functions that are *tools* for an exercise (``edge_function`` inside
``barycentric``) are not listed, so they are free to use.
"""

from __future__ import annotations

import inspect
import sys

from .exercise import Exercise, PackageAnswer, copies
from .running import run_case


def _code(function):
    return getattr(inspect.unwrap(function), "__code__", None)


def _name(answer: PackageAnswer) -> str:
    f = inspect.unwrap(answer.function)
    return f"teachraster's {getattr(f, '__qualname__', getattr(f, '__name__', 'function'))}"


def _words(spec: Exercise, answer: PackageAnswer, how: str) -> str:
    if answer.words is not None:  # a checker's private function (exercise 11)
        return f"your {spec.name} {how} {_name(answer)}: {answer.words}"
    return (
        f"your {spec.name} {how} {_name(answer)}, which computes {answer.what}: the check "
        "does not count the package's own function as your work. Write the computation "
        "yourself (the package's function is there to compare with, not to hand in)"
    )


def _matches(answer: PackageAnswer, arguments: dict) -> bool:
    return answer.when is None or bool(answer.when(arguments))


def package_note(spec: Exercise, fn, case) -> str | None:
    """Why ``fn`` does not count (it is, or calls, the package's answer), or None."""
    target = inspect.unwrap(fn) if callable(fn) else fn
    for answer in spec.answers:
        if target is inspect.unwrap(answer.function) and answer.when is None:
            return _words(spec, answer, "is")
    codes = {_code(a.function): a for a in spec.answers if _code(a.function) is not None}
    seen: list[PackageAnswer] = []

    def profile(frame, event, arg):
        if event == "call" and frame.f_code in codes:
            answer = codes[frame.f_code]
            if answer not in seen and _matches(answer, dict(frame.f_locals)):
                seen.append(answer)

    def body():
        previous = sys.getprofile()
        sys.setprofile(profile)
        try:
            if spec.call is not None:
                return spec.call(fn, copies(case[1]))
            return fn(*copies(case[1]))
        finally:
            sys.setprofile(previous)

    run_case(body, case="the look for the package's own function")
    if seen:
        return _words(spec, seen[0], "calls")
    return None
