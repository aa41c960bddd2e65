"""The capstone's texture filters on the student's ``texel_weights`` (exercise 7.2).

12.7 asks for ``texel_weights(sizes, uv, lod, wrap)`` and gives exercise 7.3's ``trilinear``
(which adds up the texels) and ``bilinear`` (``trilinear`` on a pyramid of one level) beside
it; the texture scenes take those two. Where a scene's filter is built so, what goes wrong
is the student's ``texel_weights``: an unfinished one, a raising one or a wrong one is
reported through it and exercise 7.2's check, never as "your bilinear" (r502).
"""

from __future__ import annotations

from .capstone_reports import own_report
from .diagnosis import PRECISION_KINDS
from .report import Failure
from .scalars import num, vec
from .texel_footprint import reference, same_weights

#: The scenes' texture filters that 12.7 gives on top of ``texel_weights``.
FILTERS = ("bilinear", "trilinear")
#: The call that runs exercise 7.2's check in a notebook cell.
CHECK_CALL = 'ex.check("texel_weights", texel_weights)'


def _named(fn, name: str):
    """The function ``name`` that ``fn`` calls, found in its closure or globals, or None."""
    code = getattr(fn, "__code__", None)
    if code is None or name not in code.co_names + code.co_freevars:
        return None
    held = {}
    for var, cell in zip(code.co_freevars, getattr(fn, "__closure__", None) or ()):
        try:
            held[var] = cell.cell_contents
        except ValueError:  # an empty cell
            continue
    found = held.get(name, getattr(fn, "__globals__", {}).get(name))
    return found if callable(found) else None


def texel_source(fn):
    """The student's ``texel_weights`` that ``fn`` (12.7's given ``bilinear`` or
    ``trilinear``) adds up, directly or through ``trilinear``; None where it calls none.

    >>> def texel_weights(sizes, uv, lod, wrap):
    ...     return {}
    >>> def trilinear(pyramid, uv, lod, wrap):
    ...     return texel_weights([], uv, lod, wrap)
    >>> def bilinear(texture, uv, wrap):
    ...     return trilinear([texture], uv, 0.0, wrap)
    >>> texel_source(bilinear) is texel_weights, texel_source(len)
    (True, None)
    """
    for _ in range(3):  # bilinear -> trilinear -> texel_weights
        found = _named(fn, "texel_weights")
        if found is not None:
            return found
        fn = _named(fn, "trilinear")
        if fn is None:
            return None
    return None


def texels_behind(used: dict) -> dict:
    """{filter name: the student's texel_weights} for each of ``used``'s texture filters
    built on one (12.7's given cell)."""
    out = {}
    for name in FILTERS:
        found = texel_source(used.get(name)) if name in used else None
        if found is not None:
            out[name] = found
    return out


def first_failure(texel_weights) -> Failure | None:
    """The first failure of exercise 7.2's check on ``texel_weights`` that is not float32's
    rounding (the capstone passes that), or None where it passes."""
    report = own_report("texel_weights", texel_weights)
    if report.passed:
        return None
    return next((f for f in report.failures if f.kind not in PRECISION_KINDS), None)


def given(name: str) -> str:
    """How a report names the given filter ``name``: "12.7's bilinear (exercise 7.3's, given)"."""
    return f"12.7's {name} (exercise 7.3's, given), adding up your texel_weights,"


def blame(texel_weights) -> str:
    """ "; words" of what exercise 7.2's check finds wrong in ``texel_weights``, pointing to
    its call; "" where it passes (then the given cell beside it was changed)."""
    failed = first_failure(texel_weights)
    if failed is None:
        return ""
    said = failed.explanation.replace("your function", "your texel_weights")
    return (f"; exercise 7.2's check fails your texel_weights ({failed.kind}) on {failed.case}: "
            f"{said} ({CHECK_CALL} in a new cell runs that check)")  # fmt: skip


def changed_cell(name: str) -> str:
    """What to say where ``texel_weights`` passes 7.2's check but the filter still fails."""
    return (f"; your texel_weights passes exercise 7.2's check, so look at 12.7's {name} below "
            "it: restore exercise 7.3's given cell")  # fmt: skip


def each_other(fn, name: str) -> str:
    """r510 WF2: "; words" where the student's own filter ``name`` and the other of
    :data:`FILTERS` call each other (a ``trilinear`` built on ``bilinear``, as exercise 7 once
    asked, beside 12.7's given ``bilinear``, which is ``trilinear`` on one level): the render
    recursed without end; else "".

    >>> def bilinear(texture, uv, wrap):
    ...     return trilinear([texture], uv, 0.0, wrap)
    >>> def trilinear(pyramid, uv, lod, wrap):
    ...     return bilinear(pyramid[0], uv, wrap)
    >>> each_other(trilinear, "trilinear")[:36]
    "; 12.7's bilinear is trilinear on a "
    """
    if name not in FILTERS:
        return ""
    other = FILTERS[1 - FILTERS.index(name)]
    partner = _named(fn, other)
    if partner is None or _named(partner, name) is None:
        return ""
    if name == "trilinear":
        return ("; 12.7's bilinear is trilinear on a pyramid of one level, and your trilinear "
                "calls bilinear: each calls the other without end. Your trilinear may be "
                "right: keep 12.7's given trilinear (it adds up your texel_weights), or write "
                "a bilinear of your own that does not call trilinear")  # fmt: skip
    return ("; your bilinear calls trilinear, and the trilinear it finds calls bilinear: each "
            "calls the other without end. Keep 12.7's given pair as it is (bilinear is "
            "trilinear on one level, and trilinear adds up your texel_weights)")  # fmt: skip


def at_pixel(texel_weights, sizes, uv, lod, wrap) -> str:
    """r510: "; words" where ``texel_weights`` passes exercise 7.2's check but reads other
    texels than the fetch at this pixel's (sizes, uv, λ) (a λ snapped near whole levels,
    which 7.2's cases do not hold, was told to restore 12.7's given cell); else "".

    >>> def snapped(sizes, uv, lod, wrap):
    ...     return reference(sizes, uv, float(round(lod)), wrap)
    >>> said = at_pixel(snapped, [(4, 4), (2, 2), (1, 1)], (0.3, 0.6), 1.04, "repeat")
    >>> "your texels weigh level 1 1 where λ = 1.04 weighs level 1 0.96, level 2 0.04" in said
    True
    """
    args = (sizes, uv, lod, wrap)
    right, got = reference(*args), texel_weights(*args)
    if same_weights(got, right, args) or not isinstance(got, dict):
        return ""
    mine, theirs = _per_level(got), _per_level(right)
    if any(abs(mine.get(k, 0.0) - theirs.get(k, 0.0)) > 1e-6 for k in set(mine) | set(theirs)):
        how = f"your texels weigh {_levels(mine)} where λ = {num(lod)} weighs {_levels(theirs)}"
    else:
        how = f"your texels are {_texels(got)} where the fetch reads {_texels(right)}"
    shapes = ", ".join(f"{h}×{w}" for h, w in sizes)
    return (f"; your texel_weights passes exercise 7.2's check, but not at this pixel: on "
            f"levels {shapes}, uv = {vec(uv)}, λ = {num(lod)}, {wrap!r}, {how}. 7.2's cases "
            "hold no such λ or uv: compare your code with the rule at these numbers "
            f"({CHECK_CALL} passing is not enough)")  # fmt: skip


def _per_level(weights: dict) -> dict:
    out: dict = {}
    for key, weight in weights.items():
        out[int(key[0])] = out.get(int(key[0]), 0.0) + float(weight)
    return out


def _levels(split: dict) -> str:
    return ", ".join(f"level {k} {num(w)}" for k, w in sorted(split.items()) if abs(w) > 1e-9)


def _texels(weights: dict) -> str:
    shown = sorted((k, w) for k, w in weights.items() if abs(w) > 1e-9)
    return "{" + ", ".join(f"{tuple(int(i) for i in k)}: {num(w)}" for k, w in shown) + "}"
