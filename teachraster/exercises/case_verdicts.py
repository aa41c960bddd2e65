"""The verdicts of a task whose answer is a case: a triangle that breaks one repair (10.3
``breaking_case``), a triangle and point each defect alone gets wrong (3.1b ``defect_case``).

Such a check has no expected answer to compare with: every case is judged by what the
repaired and the unrepaired code do on it. That judgement, a ``(kind, words)`` pair or None for
a case that does the job, is the one rule of the task; the comparison, the mistakes (one per
kind of verdict) and the report's words all read it from here. It is remembered for the
check's few answers (the check asks for it to compare, to name and to explain).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from .exercise import Mistake

#: Verdicts remembered at most (a check asks about a handful of cases).
LIMIT = 256


class CaseVerdicts:
    """``verdict(name, case)``: the remembered ``verdict_of(name, case)``.

    Parameters
    ----------
    verdict_of : callable
        ``verdict_of(name, case) -> (kind, words) or None``: what is wrong with ``case`` as an
        answer for ``name`` (a repair, a defect), None when it is right.
    key : callable
        ``key(case)``: a hashable stand-in for the case (its arrays' bytes).

    Examples
    --------
    >>> seen = []
    >>> def judge(name, case):
    ...     seen.append(case)
    ...     return None if case > 0 else ("not positive", f"{case} <= 0")
    >>> verdict = CaseVerdicts(judge, key=lambda case: case)
    >>> verdict("sign", -2), verdict("sign", -2), len(seen)
    (('not positive', '-2 <= 0'), ('not positive', '-2 <= 0'), 1)
    >>> verdict.same(3, None, ("sign",)), [m.kind for m in verdict.mistakes(["not positive"])]
    (True, ['not positive'])
    """

    def __init__(self, verdict_of: Callable, key: Callable) -> None:
        self._verdict_of, self._key, self._known = verdict_of, key, {}

    def __call__(self, name: str, case) -> tuple[str, str] | None:
        key = (name, self._key(case))
        if key not in self._known:
            if len(self._known) > LIMIT:
                self._known.clear()
            self._known[key] = self._verdict_of(name, case)
        return self._known[key]

    def same(self, got, expected, args) -> bool:
        """The check's comparison: ``got`` does the job for ``args[0]`` (no verdict)."""
        return self(args[0], got) is None

    def mistakes(self, kinds: Sequence[str]) -> list[Mistake]:
        """One mistake per kind of verdict, most specific first, named by the verdict's words."""
        return [self._mistake(kind) for kind in kinds]

    def _mistake(self, kind: str) -> Mistake:
        def fits(args, expected, got) -> bool:
            found = self(args[0], got)
            return found is not None and found[0] == kind

        return Mistake(kind, lambda args, expected, got: self(args[0], got)[1], fits=fits)
