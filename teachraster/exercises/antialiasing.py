"""Exercises ``coverage_fraction(xy, pixel, samples)`` and ``resolve(colours, ids, background)``.

Lesson 08 (Akeley, *Reality Engine Graphics*; Fatahalian, CMU 15-462 *Rasterization*): a
multisampled rasteriser decides coverage at S points of each pixel, each exactly like a pixel
centre (snapped vertices, the top-left rule), and the resolve averages the S samples, the
uncovered ones counting as the background (CONVENTIONS, *Multisampling*).

Expected answers are the package's: :func:`teachraster.rasterize` with ``samples=`` the case's
offsets (its ``sample_coverage``) and :meth:`teachraster.pipeline.render_triangles.Frame.resolve`.
Explanations decide each sample again by the same rules (snapped vertices, exact edge
functions on the 1/256 grid, :func:`teachraster.core.edges.passes`) to name the sample that
decides, and compare the answer with what typical mistakes give.
"""

from __future__ import annotations

from functools import cache
from types import SimpleNamespace

import numpy as np

from ..core.edges import edge_function, passes, top_left_edges
from ..core.fill import rasterize
from ..core.sample_patterns import sample_pattern
from ..core.snapping import snap
from ..core.triangle import Triangle
from ..pipeline.render_triangles import Frame
from .cases import SEED
from .running import WrongAnswerType
from .scalars import num, vec
from .scene_report import refuse_non_answers
from .tolerance import all_close, close


# -- coverage_fraction ------------------------------------------------------------------------
def exact(v) -> str:
    """A point with every digit a student needs to reproduce it (off-grid values in full)."""
    return "(" + ", ".join(num(c) if (c * 256).is_integer() else repr(float(c)) for c in v) + ")"


def tri_words(xy) -> str:
    return f"v1={exact(xy[0])}, v2={exact(xy[1])}, v3={exact(xy[2])}"


def expected_fraction(xy, pixel, samples) -> float:
    """The package's fraction of ``pixel``'s samples that triangle ``xy`` covers."""
    row, col = pixel
    fill = rasterize(Triangle(np.asarray(xy, dtype=float)), col + 1, row + 1, samples=samples)
    return float(fill.sample_coverage[row, col].mean())


def sample_points(pixel, samples) -> np.ndarray:
    """(S, 2) positions of the samples of ``pixel`` = (row, col): (col + ox, row + oy)."""
    row, col = pixel
    return np.asarray(samples, dtype=float) + np.array([col, row], dtype=float)


def covered_samples(xy, points, tie: str = "top-left", orient: bool = True) -> np.ndarray:
    """Which ``points`` the triangle covers with exact edge functions and a tie rule.

    ``tie`` decides a point exactly on an edge: ``"top-left"`` (the rule), ``"both"`` (every
    edge owns it), ``"none"``, ``"bottom-right"``. ``orient=False`` skips re-orienting a
    counter-clockwise triangle (the one-winding mistake).
    """
    v = np.asarray(xy, dtype=float)
    area = float(edge_function(v[0], v[1], v[2]))
    if area == 0:
        return np.zeros(len(points), dtype=bool)
    if area < 0 and orient:
        v = v[[0, 2, 1]]
    out = np.ones(len(points), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        e = edge_function(a, b, points)
        owns = {"top-left": top_left_edges(a, b), "both": True, "none": False}.get(
            tie, not top_left_edges(a, b)
        )
        out &= passes(e, owns)
    return out


def _edge_words(xy, point) -> str:
    """Words for the edge(s) a point lies exactly on, with the rule's verdict, or ""."""
    v = np.asarray(xy, dtype=float)
    flip = float(edge_function(v[0], v[1], v[2])) < 0
    found = []
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        if float(edge_function(a, b, point)) == 0:
            ra, rb = (b, a) if flip else (a, b)
            owns = bool(top_left_edges(ra, rb))
            kind = (
                ("top" if owns else "bottom") if ra[1] == rb[1] else ("left" if owns else "right")
            )
            found.append((f"v{k + 1}→v{(k + 1) % 3 + 1}", kind, owns))
    if len(found) == 1:
        name, kind, owns = found[0]
        verdict = "covers it" if owns else "leaves it uncovered"
        return f"lies exactly on edge {name}, a {kind} edge: the top-left rule {verdict}"
    if len(found) == 2:
        (n1, k1, o1), (n2, k2, o2) = found
        verdict = "covers it" if o1 and o2 else "leaves it uncovered"
        return (
            f"lies exactly on a vertex, where edge {n1} (a {k1} edge) meets edge {n2} (a {k2} "
            f"edge): the top-left rule {verdict} (both edges must own it)"
        )
    return ""


@cache  # the same cases on every check: built once
def coverage_cases():
    """Hard cases (samples on edges, off-grid vertices, ties of the snapping) then random."""
    four, out = sample_pattern(4), []
    hard = [
        ("the whole pixel covered", [[0, 0], [8, 0], [0, 8]], (1, 1), four),
        ("sample 0 on a left edge", [[2.375, -1], [6, 1.5], [2.375, 5]], (1, 2), four),
        ("sample 0 on a right edge", [[2.375, -1], [2.375, 5], [-2, 1.5]], (1, 2), four),
        ("sample 1 on a top edge", [[0, 1.375], [6, 1.375], [3, 6]], (1, 2), four),
        ("sample 1 on a bottom edge", [[0, 1.375], [3, -4], [6, 1.375]], (1, 2), four),
        ("a vertex on sample 2", [[2.125, 1.625], [5, 0], [5, 4]], (1, 2), four),
        ("counter-clockwise, sample 0 on a left edge", [[2.375, -1], [2.375, 5], [6, 1.5]], (1, 2), four),  # fmt: skip
        ("off the grid: a right edge 1/1024 px right of sample 0",
         [[2.375 + 1 / 1024, -1], [2.375 + 1 / 1024, 5], [-2, 1.5]], (1, 2), four),
        ("off the grid: a left edge 1/1024 px right of sample 0",
         [[2.375 + 1 / 1024, -1], [6, 1.5], [2.375 + 1 / 1024, 5]], (1, 2), four),
        ("off the grid: 3/1024 px right of sample 0 rounds up, away from it",
         [[2.375 + 3 / 1024, -1], [6, 1.5], [2.375 + 3 / 1024, 5]], (1, 2), four),
        ("off the grid: a half step (1/512 px) rounds to even, onto sample 0",
         [[2.375 + 1 / 512, -1], [6, 1.5], [2.375 + 1 / 512, 5]], (1, 2), four),
        ("zero area through the samples", [[2.375, 1.125], [2.875, 1.375], [3.375, 1.625]], (1, 2), four),  # fmt: skip
        ("one sample at the centre, on an edge", [[2.5, 0], [6, 3], [2.5, 6]], (1, 2), sample_pattern(1)),  # fmt: skip
        ("2 samples, a diagonal through both", [[0, 0], [8, 8], [0, 8]], (1, 1), sample_pattern(2)),
        ("8 samples, a thin sliver", [[1.0, 1.0], [3.0, 1.3], [1.0, 1.2]], (1, 1), sample_pattern(8)),  # fmt: skip
        ("16 samples, a small triangle inside", [[1.2, 1.1], [1.9, 1.4], [1.3, 1.8]], (1, 1), sample_pattern(16)),  # fmt: skip
        ("ordered 2×2 grid, an edge along its column", [[1.25, 0], [4, 2], [1.25, 4]], (1, 1), sample_pattern(4, "grid")),  # fmt: skip
        ("a pixel outside the triangle", [[0, 0], [3, 0], [0, 3]], (4, 4), four),
    ]  # fmt: skip
    for label, xy, pixel, samples in hard:
        out.append(_coverage_case(label, np.array(xy, dtype=float), pixel, samples))
    rng = np.random.default_rng(SEED + 60)
    for n in range(16):
        xy = snap(rng.uniform(0, 6, size=(3, 2)))
        lo, hi = np.floor(xy.min(axis=0)).astype(int), np.floor(xy.max(axis=0)).astype(int)
        pixel = (int(rng.integers(lo[1], hi[1] + 1)), int(rng.integers(lo[0], hi[0] + 1)))
        kind = ("standard", "random", "jittered")[n % 3]
        count = (4, 8, 16)[n % 3] if kind == "standard" else (5, 4, 9)[n % 3]
        samples = sample_pattern(count, kind, seed=n)
        label = f"random {n + 1}: {count} {kind} samples"
        out.append(_coverage_case(label, xy, pixel, samples))
    return out


def _coverage_case(label, xy, pixel, samples):
    samples = np.array(samples, dtype=float)
    args = (xy, pixel, samples)
    return (f"{label}, pixel {pixel}", args, expected_fraction(*args))


def explain_coverage(args, expected, got) -> str:
    xy, pixel, samples = args
    s = len(samples)
    snapped = snap(xy)
    points = sample_points(pixel, samples)
    inside = covered_samples(snapped, points)
    which = ", ".join(str(k) for k in np.flatnonzero(inside)) or "none"
    head = (
        f"pixel (row {pixel[0]}, col {pixel[1]}) of {tri_words(xy)} with {s} samples: the rule "
        f"covers {int(inside.sum())} of {s} (samples {which}), {num(expected)}; yours is "
        f"{num(got, expected)}"
    )
    return head + _coverage_mistake(xy, snapped, pixel, samples, got)


def _coverage_mistake(xy, snapped, pixel, samples, got) -> str:
    points = sample_points(pixel, samples)
    frac = lambda cov: float(np.mean(cov))  # noqa: E731
    if float(edge_function(*snapped)) == 0:
        return (
            ": its vertices are collinear once snapped, and a zero-area triangle covers no sample"
        )
    if not (snapped == xy).all():
        if close(got, frac(covered_samples(xy, points))):
            return (
                ": you tested the unsnapped vertices; snap them to the 1/256 grid first "
                "(round half to even): "
                + ", ".join(
                    f"{exact(a)} → {exact(b)}" for a, b in zip(xy, snapped) if (a != b).any()
                )
            )
        half_up = np.floor(xy * 256 + 0.5) / 256
        if close(got, frac(covered_samples(half_up, points))):
            return ": snapping rounds half to even (np.rint), not half up (floor(x + ½))"
        down = np.floor(xy * 256) / 256
        if close(got, frac(covered_samples(down, points))):
            return ": snapping rounds to the nearest 1/256 px (half to even), not down"
    for tie in ("both", "none", "bottom-right"):
        if close(got, frac(covered_samples(snapped, points, tie))):
            on = [(k, _edge_words(snapped, p)) for k, p in enumerate(points)]
            k, words = next(((k, w) for k, w in on if w), (None, ""))
            if words:
                return f": sample {k} at {vec(points[k])} {words}"
    if close(got, frac(covered_samples(snapped, points, orient=False))):
        return (
            ": this triangle runs counter-clockwise on screen (E(v1, v2, v3) < 0): handle both "
            "windings (flip the signs, or swap two vertices)"
        )
    row, col = pixel
    centre = covered_samples(snapped, np.array([[col + 0.5, row + 0.5]]))
    if close(got, float(centre[0])):
        return ": you tested the pixel centre only; test each of the samples"
    for shift, words in (
        ((0.5, 0.5), "the offsets are from the pixel's top-left corner (col, row), not its centre"),
        ((-0.5, -0.5), "sample s lies at (col + ox, row + oy), offsets from the top-left corner"),
    ):
        if close(got, frac(covered_samples(snapped, points + shift))):
            return f": {words}"
    flipped = np.asarray(samples) * [1, -1] + np.array([col, row + 1], dtype=float)
    if close(got, frac(covered_samples(snapped, flipped))):
        return ": the offsets are y down (like window coordinates): y = row + oy, not row + 1 − oy"
    swapped = np.asarray(samples) + np.array([row, col], dtype=float)
    if row != col and close(got, frac(covered_samples(snapped, swapped))):
        return ": pixel is (row, col): a sample lies at x = col + ox, y = row + oy"
    return "; the fraction is (samples covered) / S, each sample decided like a pixel centre"


def draw_coverage_case(ax, case, got):
    """The pixel, its samples (filled where the rule covers them) and the snapped triangle."""
    xy, (row, col), samples = case[1]
    snapped = snap(xy)
    points = sample_points((row, col), samples)
    inside = covered_samples(snapped, points)
    ring = np.vstack([snapped, snapped[:1]])
    artists = list(ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1))
    artists += ax.plot(*points[inside].T, "o", color="#2b7bba", label="covered")
    artists += ax.plot(*points[~inside].T, "o", mfc="none", mec="#888888", label="not covered")
    box = np.array([[col, row], [col + 1, row], [col + 1, row + 1], [col, row + 1], [col, row]])
    artists += ax.plot(box[:, 0], box[:, 1], color="#ff9f1c", linewidth=2)
    yours = "" if got is None else f", yours {num(got, case[2])}"
    ax.set_xlabel(f"fraction {num(case[2])}{yours}")
    ax.set_xlim(col - 1, col + 2)
    ax.set_ylim(row + 2, row - 1)
    ax.set_aspect("equal")
    artists.append(ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1)))
    return artists


def as_fraction(value) -> float:
    refuse_non_answers(value, "a number")
    arr = np.asarray(value)
    if arr.size != 1 or arr.dtype.kind not in "uifb":
        try:
            return float(value)  # a Fraction, say
        except (TypeError, ValueError):
            raise WrongAnswerType(f"returned {value!r:.60}, not one number") from None
    return float(arr.item())


def same_number(got, expected, args) -> bool:
    return close(got, expected)


def same_fraction(got, expected, args) -> bool:
    """A fraction k/S: any answer nearer than 1e-6 (a wrong count is 1/S ≥ 1/16 away)."""
    return abs(got - expected) <= 1e-6


# -- resolve ----------------------------------------------------------------------------------
def expected_resolve(colours, ids, background) -> np.ndarray:
    """The package's resolve of one pixel (:meth:`Frame.resolve` on a 1 × 1 frame)."""
    pixel = SimpleNamespace(sample_triangle_id=np.asarray(ids)[None, None])
    return Frame.resolve(pixel, np.asarray(colours, dtype=float)[None, None], background)[0, 0]


def _resolve_case(label, ids, colours, background):
    ids = np.asarray(ids, dtype=np.int64)
    colours = np.asarray(colours, dtype=float).copy()
    colours[ids < 0] = np.nan  # no triangle wrote these samples (CONVENTIONS: NaN outside)
    background = np.asarray(background, dtype=float)
    args = (colours, ids, background)
    return (label, args, expected_resolve(*args))


@cache  # the same cases on every check: built once
def resolve_cases():
    red, green, blue = np.eye(3)
    white, grey = np.ones(3), np.array([0.2, 0.3, 0.4])
    hard = [
        ("4 samples, all covered", [0, 0, 0, 0], [red] * 4, white),
        ("4 samples, none covered", [-1, -1, -1, -1], [red] * 4, grey),
        ("4 samples, one covered", [-1, 0, -1, -1], [green] * 4, white),
        ("4 samples, two triangles meet", [0, 1, 1, 0], [red, blue, blue, red], grey),
        ("4 samples, three covered", [2, 2, -1, 2], [blue] * 4, white),
        ("1 sample, covered", [0], [green], white),
        ("1 sample, not covered", [-1], [green], grey),
        ("2 samples, one covered", [-1, 3], [red, red], np.zeros(3)),
        ("16 samples, five covered", [-1] * 11 + [0] * 5, [red] * 16, white),
    ]
    out = [_resolve_case(*case) for case in hard]
    rng = np.random.default_rng(SEED + 61)
    for n in range(14):
        s = (2, 4, 8, 16)[n % 4]
        ids = rng.integers(-1, 3, size=s)
        palette = rng.uniform(0, 1, size=(3, 3))
        colours = palette[np.maximum(ids, 0)]
        out.append(
            _resolve_case(f"random {n + 1}: {s} samples", ids, colours, rng.uniform(0, 1, 3))
        )
    return out


def as_colour(value) -> np.ndarray:
    refuse_non_answers(value, "a colour")
    if np.asarray(value, dtype=object).dtype.kind == "O" and any(
        isinstance(v, str | bytes) for v in np.ravel(np.asarray(value, dtype=object))
    ):
        raise WrongAnswerType(f"returned {value!r:.60}: text, not a colour")
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise WrongAnswerType(f"returned {value!r:.60}, not a colour") from None
    if arr.size != 3:
        raise WrongAnswerType(f"returned {value!r:.60}; expected one colour of 3 channels")
    return arr.reshape(3)


def same_colour(got, expected, args) -> bool:
    return all_close(got, expected)


def explain_resolve(args, expected, got) -> str:
    colours, ids, background = args
    s, covered = len(ids), ids >= 0
    k = int(covered.sum())
    head = (
        f"ids {ids.tolist()} ({k} of {s} samples covered), background {vec(background)}: the "
        f"resolve is {vec(expected, got)}; yours is {vec(got, expected)}"
    )
    rule = (
        f"the mean over all {s} samples, the {s - k} uncovered one{'s' * (s - k != 1)} "
        "counting as the background"
    )
    if np.isnan(got).any():
        return f"{head}: uncovered samples hold NaN (no triangle wrote them); {rule}"
    if k and all_close(got, colours[covered].mean(axis=0)):
        return f"{head}: you averaged the {k} covered sample{'s' * (k > 1)} only; {rule}"
    if all_close(got, np.where(covered[:, None], colours, 0.0).mean(axis=0)):
        return f"{head}: the uncovered samples count as the background {vec(background)}, not as black; {rule}"
    if k:
        owner = np.bincount(ids[covered]).argmax()
        if all_close(got, colours[ids == owner][0]):
            return (
                f"{head}: that is the colour of the triangle owning most samples; the resolve "
                f"mixes them all: {rule}"
            )
    return f"{head}; {rule}: (Σ covered colours + {s - k}·background) / {s}"


def draw_resolve_case(ax, case, got):
    from .drawing import draw_values

    return draw_values(ax, ["R", "G", "B"], case[2], got)
