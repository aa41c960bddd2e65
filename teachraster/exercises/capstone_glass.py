"""The capstone's sorted glass: an A-buffer resolved by the student's ``a_buffer``.

A GPU blends transparent fragments in drawing order. The glass scene's two triangles pierce
each other, so no order of the two triangles is right at every pixel: where the one drawn
first is the nearer, drawing order lays the farther one over it. An A-buffer (Carpenter,
*The A-buffer, an Antialiased Hidden Surface Method*, 1984; today's per-pixel fragment
lists) keeps every fragment of a pixel and resolves the list after the frame: the student's
``a_buffer(depths, colours, background)`` gets one pixel's fragments in drawing order
(premultiplied RGBA) and returns what the pixel shows, each fragment seen through those in
front of it. The reference composites farthest first with the package's premultiplied over
(:func:`teachraster.blend_equation`, ``render(..., blend="premultiplied")``), onto the
background.

The fragments are read from the frame's pixel histories (the trace), so they are the ones the
pipeline produced; only the resolve is the student's.
"""

from __future__ import annotations

import numpy as np

from ..core.blend_factors import BLEND_MODES, apply_blend
from . import tries
from .blending import blend_answers
from .exercise import Exercise, PackageAnswer
from .front_to_back import as_rgba
from .package_answers import package_note, watching
from .running import run_checker
from .scalars import num, vec

PREMULTIPLIED = BLEND_MODES["premultiplied"]
#: The glass scene's clear colour (premultiplied white: opaque).
BACKGROUND = np.ones(4)


class Sorted:
    """A traced frame whose colour buffer is the A-buffer's resolve (``color``); everything
    else, the pixel histories included, is the frame's."""

    def __init__(self, frame, color: np.ndarray):
        self.frame, self.color = frame, color

    def __getattr__(self, name):
        return getattr(self.frame, name)


def fragments(frame, row: int, col: int) -> tuple[np.ndarray, np.ndarray]:
    """(depths (n,), premultiplied RGBA (n, 4)) of the fragments that reached pixel (row,
    col), in drawing order."""
    records = [r for r in frame.history(row, col).records if r.outcome == "passed"]
    depths = np.array([r.depth for r in records], dtype=float)
    return depths, np.array([r.color for r in records], dtype=float).reshape(-1, 4)


def package_resolve(depths, colours, background) -> np.ndarray:
    """Premultiplied over from the farthest fragment to the nearest, onto ``background``
    (a stable sort: equal depths keep drawing order, the later drawn on top)."""
    out = np.asarray(background, dtype=float)
    for k in np.argsort(-np.asarray(depths), kind="stable"):
        out = apply_blend(colours[k], out, *PREMULTIPLIED)
    return out


def resolved(frame, resolve) -> Sorted:
    """``frame`` with every pixel some fragment reached resolved by ``resolve(depths,
    colours, background)`` (read as an RGBA colour); the rest keep the background."""
    color = np.array(frame.color, dtype=float)
    for row, col in np.argwhere(frame.triangle_id >= 0):
        depths, colours = fragments(frame, row, col)
        color[row, col] = as_rgba(resolve(depths.copy(), colours.copy(), BACKGROUND.copy()))
    return Sorted(frame, color)


def _fold(colours, order, background, step):
    out = np.asarray(background, dtype=float)
    for k in order:
        out = step(colours[k], out)
    return out


def _over(src, dst):
    return apply_blend(src, dst, *PREMULTIPLIED)


def _straight(src, dst):  # the premultiplied colour multiplied by its alpha again
    return np.r_[src[:3] * src[3] + dst[:3] * (1 - src[3]), src[3] + dst[3] * (1 - src[3])]


def _straight_rgba(src, dst):  # r481 HN7: the straight rule on all four channels, alpha too
    return np.asarray(src, dtype=float) * src[3] + np.asarray(dst, dtype=float) * (1 - src[3])


def _previous_alpha(colours, near_first, background):
    """Nearest first, each fragment weighted by (1 − α) of the one just in front of it alone,
    not by the transmittance of all in front (r148 D12-4: right wherever a pixel holds two)."""
    out, prev = np.zeros(4), 0.0
    for k in near_first:
        out = out + (1 - prev) * np.asarray(colours[k], dtype=float)
        prev = float(colours[k][3])
    return out + (1 - out[3]) * np.asarray(background, dtype=float)


def variants(depths, colours, background) -> dict[str, np.ndarray]:
    """What the typical wrong resolves give for one pixel's fragments."""
    n = len(depths)
    far_first = np.argsort(-np.asarray(depths), kind="stable")
    near_first = np.argsort(np.asarray(depths), kind="stable")
    clear = np.zeros(4)
    return {
        "drawing order": _fold(colours, range(n), background, _over),
        "reversed drawing order": _fold(colours, range(n - 1, -1, -1), background, _over),
        "nearest first": _fold(colours, near_first, background, _over),
        "no background": _fold(colours, far_first, clear, _over),
        "premultiplied twice": _fold(colours, far_first, background, _straight),
        "straight rule, alpha too": _fold(colours, far_first, background, _straight_rgba),
        "nearest only": (_over(colours[near_first[0]], background) if n else background),
        "previous alpha": _previous_alpha(colours, near_first, background),
    }


#: The repair of compositing in drawing order, either way round.
SORT = (
    ", so sort by depth and start from the farthest (each nearer one is laid over what lies "
    "behind it)"
)

NO_BACKGROUND = "you composited the fragments onto transparent black"

#: The words that give 12.5's order away, said only once two different frames of the
#: student's ``a_buffer`` have failed (r84 12-2: every failing pixel said "farthest first,
#: each nearer fragment laid over what lies behind it"; :func:`.tries.hinted_check`).
REPAIRS = {
    "drawing order": SORT,
    "reversed drawing order": SORT,
    "nearest first": "; lay them on farthest first (or go nearest first with the under step "
    "of exercise 9, weighting each by the transmittance left in front)",
}

MISTAKES = {
    "drawing order": "you composited in drawing order, as the GPU blends: at this pixel the "
    "fragment drawn later lies behind the one drawn first" + REPAIRS["drawing order"],
    # r273 12-3: the last drawn laid on first, the first drawn on top, got the rule alone
    "reversed drawing order": "you composited in reverse drawing order (the last drawn at the "
    "bottom, the first drawn on top): drawing order, either way round, says nothing of depth, "
    "and at this pixel the reversed order is not farthest first"
    + REPAIRS["reversed drawing order"],
    "nearest first": "you laid each fragment over the result in order of increasing depth: "
    "the nearest then ends at the bottom" + REPAIRS["nearest first"],
    "no background": NO_BACKGROUND + ": the background "
    "shows through them, so it is the farthest layer, the one to start from",
    "premultiplied twice": "you multiplied each fragment's colour by its alpha again: the "
    "fragments are premultiplied already (your over with straight alpha?)",
    "straight rule, alpha too": "you blended with the straight rule, src·α + dst·(1 − α), on "
    "all four channels: the fragments are premultiplied already, so each colour, and its "
    "alpha too, was multiplied by its alpha again (premultiplied over is src + dst·(1 − α))",
    "nearest only": "you kept the nearest fragment alone: the fragments behind it show "
    "through it where its alpha is below 1",
    "previous alpha": "you weighted each fragment by (1 − α) of the one fragment just in front "
    "of it: it is seen through every fragment in front, so its weight is the product of all "
    "their (1 − α), the transmittance left",
}

#: Stacks on which two mistakes that agree at one pixel part (depth, premultiplied RGBA).
STACKS = [
    ([0.5, 0.2, 0.8], [[0.6, 0.0, 0.0, 0.6], [0.0, 0.3, 0.0, 0.3], [0.0, 0.0, 0.5, 0.5]]),
    ([0.2, 0.7], [[0.0, 0.4, 0.0, 0.4], [0.7, 0.0, 0.0, 0.7]]),
    ([0.9, 0.1], [[0.0, 0.0, 0.8, 0.8], [0.5, 0.5, 0.0, 0.5]]),
]


#: a_buffer's own cases (r148 D12-4: no pixel of the glass holds more than two fragments, so a
#: resolve right for two passed the scene): stacks of three and four fragments, drawing order
#: not depth order, with different alphas. (depths, premultiplied RGBA)
OWN_STACKS = [
    STACKS[0],
    ([0.3, 0.6, 0.1], [[0.6, 0.0, 0.0, 0.6], [0.0, 0.45, 0.0, 0.45], [0.0, 0.0, 0.5, 0.5]]),
    (
        [0.7, 0.2, 0.9, 0.4],
        [[0.5, 0.0, 0.0, 0.5], [0.0, 0.2, 0.0, 0.25], [0.0, 0.0, 0.8, 0.8], [0.3, 0.3, 0.0, 0.6]],
    ),
]


def own_cases(fn) -> str | None:
    """What is wrong with ``fn`` on :data:`OWN_STACKS` (the first stack it resolves wrongly,
    with the typical mistake that gives its answer where one does), or None when it is right
    on all of them."""
    for depths, colours in OWN_STACKS:
        d, c = np.array(depths, dtype=float), np.array(colours, dtype=float)
        ours = package_resolve(d, c, BACKGROUND)
        got, error = _answer(fn, d, c)
        if not error and np.allclose(got, ours, rtol=1e-6, atol=1e-6):
            continue
        said = error or f"your a_buffer returned {vec(got, ours)}"
        head = (f"{len(d)} fragments in drawing order with depths {vec(d)} and premultiplied "
                f"colours {', '.join(vec(x) for x in c)} over the background {vec(BACKGROUND)}: "
                f"{said}, the A-buffer's resolve gives {vec(ours, got)}")  # fmt: skip
        if error:
            return head
        words = _mistake(fn, d, c, got, ours)
        if not tries.hints_spent(NAME):
            for text in REPAIRS.values():
                words = words.replace(text, "")
        return head + words
    return None


def explain(fn, frame, row: int, col: int) -> str:
    """Why the student's ``a_buffer`` resolves pixel (row, col) of ``frame`` wrongly."""
    depths, colours = fragments(frame, row, col)
    ours = package_resolve(depths, colours, BACKGROUND)
    yours, error = run_checker(lambda: _answer(fn, depths, colours),
                               (None, "your a_buffer did not answer here in time"))  # fmt: skip
    said = error or f"your a_buffer returned {vec(yours, ours)}"
    full = tries.hints_spent(NAME)
    how = ("farthest first, each nearer fragment laid over what lies behind it" if full else
           "every fragment seen through those nearer than it, the background through all")  # fmt: skip
    head = (f"its fragments in drawing order have depths {vec(depths)} and premultiplied "
            f"colours {', '.join(vec(c) for c in colours)} over the background "
            f"{vec(BACKGROUND)}: {said}, the A-buffer's resolve gives {vec(ours, yours)} "
            f"({how})")  # fmt: skip
    if yours is None:
        return head
    words = _mistake(fn, depths, colours, yours, ours)
    if not full:  # a hint: the mistake, not its repair
        for text in REPAIRS.values():
            words = words.replace(text, "")
    return head + words


#: The task whose words are staged (:func:`.tries.hinted_check`).
NAME = "a_buffer"


def count_try(frame) -> None:
    """Count one failing frame of the student's ``a_buffer`` (its repair is said in full
    once two different ones have failed in this kernel, as ``ex.check``'s hints are)."""
    colour = getattr(frame, "color", None)
    tries.hinted_check(NAME, repr(frame) if colour is None else np.asarray(colour).tobytes())


def _answer(fn, depths, colours, background=BACKGROUND):
    try:
        return as_rgba(fn(depths.copy(), colours.copy(), background.copy())), ""
    except Exception as exc:  # noqa: BLE001 - a student's bug is reported, not raised
        from .running import last_line

        return None, f"your a_buffer raised {last_line(exc)} here"


def _mistake(fn, depths, colours, yours, ours) -> str:
    """ ": words" of the one typical mistake that gives ``yours`` here (and, where several
    do, on :data:`STACKS` too), or ""."""
    if np.allclose(yours, ours, rtol=1e-6, atol=1e-6):
        return ""
    here = variants(depths, colours, BACKGROUND)
    fits = [k for k, v in here.items() if np.allclose(v, yours, rtol=1e-6, atol=1e-6)]
    if fits:  # r199 12-5: one fit at a pixel of two fragments may be chance (sorted by alpha
        # was told "increasing depth"): it must give the student's answers on STACKS too
        fits = run_checker(lambda: _fit_on_stacks(fn, fits), fits)
    if len(fits) == 1:
        return f"; the likely mistake: {MISTAKES[fits[0]]}"
    if yours[3] > 1 + 1e-6:  # r137 D12-3 (r131): a transmittance reset, not multiplied
        return (f"; your alpha {num(float(yours[3]))} is above 1: the fragments and the "
                "background share the pixel once, so their weights sum to 1 and alpha ends at "
                "most 1 (did a weight start afresh at each fragment instead of carrying on "
                "what the fragments in front leave?)")  # fmt: skip
    if run_checker(lambda: _constant(fn, yours), False):
        if run_checker(lambda: _background_in_front(fn, yours), False):
            return "; the likely mistake: " + BACKGROUND_IN_FRONT
        return (f"; the likely mistake: your a_buffer returns {vec(yours)} whatever the "
                "fragments (a placeholder such as `return background` left in, or a `return` "
                "reached too early?)")  # fmt: skip
    return ""


#: r199 12-5: `over(result, colours[k])` (over's arguments swapped) and the background
#: composited last, over the fragments, both return the opaque background everywhere; they
#: were told "a placeholder left in"
BACKGROUND_IN_FRONT = (
    "the background ends in front of the fragments, and being opaque it hides them all: "
    "over(src, dst) lays src over dst, so the fragment is src and what lies behind it is dst "
    "(over's two arguments swapped, or the background laid last, over the fragments?)"
)


def _background_in_front(fn, yours) -> bool:
    """Whether ``fn``, which gives ``yours`` on every stack over the opaque background, shows
    its fragments over a clear one: the background laid over them, not a placeholder (which
    gives ``yours``, or the clear background, there too)."""
    depths, colours = STACKS[0]
    clear = np.zeros(4)
    got, error = _answer(fn, np.array(depths, float), np.array(colours, float), clear)
    return not error and not (np.allclose(got, clear) or np.allclose(got, yours))


def _constant(fn, yours) -> bool:
    """Does ``fn`` give ``yours`` on every stack of :data:`STACKS` too?"""
    for depths, colours in STACKS:
        got, error = _answer(fn, np.array(depths, float), np.array(colours, float))
        if error or not np.allclose(got, yours, rtol=1e-9, atol=1e-9):
            return False
    return True


def _fit_on_stacks(fn, fits) -> list[str]:
    keep = list(fits)
    for depths, colours in STACKS:
        d, c = np.array(depths, float), np.array(colours, float)
        got, error = _answer(fn, d, c)
        if error:
            return fits
        wrong = variants(d, c, BACKGROUND)
        keep = [k for k in keep if np.allclose(wrong[k], got, rtol=1e-6, atol=1e-6)]
    return keep


def _stack_cases() -> list:
    """:data:`OWN_STACKS` as cases (label, (depths, colours, background), the resolve)."""
    out = []
    for k, (depths, colours) in enumerate(OWN_STACKS):
        d, c = np.array(depths, dtype=float), np.array(colours, dtype=float)
        out.append((f"stack {k + 1}", (d, c, BACKGROUND.copy()), package_resolve(d, c, BACKGROUND)))
    return out


def _same(got, expected, args) -> bool:
    return bool(np.allclose(got, expected, rtol=1e-6, atol=1e-6))


def _no_words(args, expected, got) -> str:
    return ""


#: What the report says of the package's blend inside ``a_buffer``.
BLEND_WORDS = (
    "the package's blend, which 12.5 asks of your own over (let your a_buffer "
    "call your over; the package's blend is there to compare with, not to hand in)"
)

#: ``a_buffer`` as the rule of :mod:`.package_answers` reads an exercise (one place for the
#: rule of every task): the package's resolve is its answer, and the checker's functions of
#: this module compute the expected frames (r163 12-5: ``package_resolve`` imported as
#: ``a_buffer``, or wrapped, passed glass_sorted as the student's own).
A_BUFFER = Exercise(
    NAME, _stack_cases, as_rgba, _same, _no_words, _no_words,
    answers=(PackageAnswer(package_resolve, label="capstone_glass.package_resolve",
                           what="the A-buffer's resolve of a pixel"),
             # r174 12-3: tr.blend_equation inside a_buffer passed, refused as over (12.5)
             *blend_answers(BLEND_WORDS)),
)  # fmt: skip


def package_use(fn) -> str | None:
    """Why ``fn`` does not count as the student's ``a_buffer`` (it is, calls, or copies the
    package's resolve or the checker's code: :func:`.package_answers.package_note`, watched
    while it resolves its own stacks), or None."""
    cases = _stack_cases()  # the package's resolves, outside the window: not the student's
    with watching(A_BUFFER) as seen:  # the guard of each call inside the window, as ex.check's
        for _, (depths, colours, _), _ in cases:
            run_checker(lambda d=depths, c=colours: _answer(fn, d, c), None)
    return run_checker(lambda: package_note(A_BUFFER, fn, seen), None)
