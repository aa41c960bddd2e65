"""The two checks every reader's variant test makes (one place for the per-report test files).

A reader's report (``rNNN``) lists wrong variants, each with the words its first explanation
must hold and its failure kind, and correct-but-different variants that must pass; each
report's test file asks the same two things of them.
"""

from __future__ import annotations

from teachraster import exercises as ex
from teachraster.exercises import tries


def assert_first_named(name: str, fn, words: str, kind: str, *, every_failure: bool = False):
    """``fn`` fails exercise ``name``; its first explanation holds ``words`` and is of
    ``kind`` (with ``every_failure``: every failure but a raise is of ``kind``). The hints
    are forgotten before and after, so that each variant reads as a fresh kernel's first try.
    Returns the report."""
    tries.forget_hints(name)
    try:
        report = ex.check(name, fn)
    finally:
        tries.forget_hints(name)
    assert not report.passed, str(report)
    first = report.failures[0]
    assert words in first.explanation, (first.kind, first.explanation)
    if every_failure:
        kinds = {f.kind for f in report.failures if "raised" not in f.explanation}
        assert kinds == {kind}, str(report)
    else:
        assert first.kind == kind, (first.kind, first.explanation)
    return report


def assert_passes(name: str, fn):
    """``fn``, a correct-but-different solution, passes exercise ``name``."""
    report = ex.check(name, fn)
    assert report.passed, str(report)
    return report
