"""Exercise ``clip_near_colour(v, colours)`` (lesson 05a, exercise 4.3): a vertex colour
carried through the near-plane clip (r310 M2: the clipped polygon of 4.2 carried nothing, and
"why it must be found in clip space" was asked and never checked).

The student returns the clipped polygon with each vertex's colour, rows (x, y, z, w, r, g, b).
A new vertex's colour is taken at the same t as its position, in clip space, where every
vertex output is linear along the edge; the typical slips take it at the t found after the
divide, from one end of the edge, or perspective-corrected as on the screen (lesson 04).

Expected answers: the core's Sutherland-Hodgman with the colours as attributes
(:func:`teachraster.pipeline.geometry.clipping.clip_polygon`) on 4.2's cases, each with
seeded colours; the one case with a vertex beyond the far plane by :func:`.clip_with`, near
plane only, as in 4.2.
"""

from __future__ import annotations

import numpy as np

from ..pipeline.geometry.clipping import clip_polygon
from .answers import MAX_VERTICES, as_numbers, short
from .cases import SEED
from .depth_clipping import (
    DISTANCES,
    FLOAT32_TOL,
    clip_cases,
    clip_rule,
    clip_with,
    explain_clip,
    ndc_z,
    near_only,
)
from .exercise import Exercise, Mistake, PackageAnswer
from .running import WrongAnswerType
from .scalars import num, vec
from .tolerance import all_close, same_polygon


def with_colours(v, colours) -> np.ndarray:
    """The expected (n, 7) polygon: the core's clip with the colours as attributes (near plane
    only: :func:`.clip_with` where another plane would cut, as 4.2's expected polygon)."""
    v, c = np.asarray(v, float), np.asarray(colours, float)
    if near_only(v):
        return np.column_stack(clip_polygon(v, c))
    return clip_with(np.column_stack([v, c]))


def colour_cases():
    rng = np.random.default_rng(SEED + 43)
    out = []
    for label, (v,), _ in clip_cases():
        c = np.round(rng.uniform(0, 1, (3, 3)), 2)
        out.append((f"{label}; colours {vec(c[0])}, {vec(c[1])}, {vec(c[2])}", (v, c),
                    with_colours(v, c)))  # fmt: skip
    return out


def as_coloured(value) -> np.ndarray:
    sized = isinstance(value, (list, tuple)) or (isinstance(value, np.ndarray) and value.ndim)
    if sized and len(value) > MAX_VERTICES:
        raise WrongAnswerType(
            f"returned {short(value)}: a triangle clipped by one plane has at most 4 vertices"
        )
    if sized and np.size(value) == 0:
        return np.zeros((0, 7))
    return as_numbers(value, (-1, 7), "an (n, 7) array of vertices (x, y, z, w, r, g, b)", 7 * 8)


def colour_with(v, colours, t_colour) -> np.ndarray:
    """The right positions, each new vertex's colour from ``t_colour(a, b, t)`` (a, b: the
    edge's (x, y, z, w, r, g, b) rows; t: the right crossing), a slip each."""

    def point(a, b, t):
        new = a + t * (b - a)
        new[4:] = t_colour(a, b, t)
        return new

    return clip_with(np.column_stack([np.asarray(v, float), np.asarray(colours, float)]),
                     point=point)  # fmt: skip


def _lerp(a, b, t):
    return a[4:] + t * (b[4:] - a[4:])


def _after_divide(a, b, t):
    """The colour at the t where z/w reaches −1 along the edge."""
    s = ndc_z(a) / (ndc_z(a) - ndc_z(b))
    return _lerp(a, b, s)


def _perspective(a, b, t):
    """colour/w and 1/w interpolated at t, then divided: the screen's rule used in clip space."""
    return _lerp(a / a[3], b / b[3], t) / ((1 - t) / a[3] + t / b[3])


def _columns_first(v, colours) -> np.ndarray:
    """The right rows with the colour first, (r, g, b, x, y, z, w) (r319 X2)."""
    p = with_colours(v, colours)
    return np.column_stack([p[:, 4:], p[:, :4]])


def _nan_at_w0(args, expected, got) -> bool:
    """Right positions, and NaN colours only where the case has a vertex with w = 0 (r319 H5:
    lesson 04's weights at the fraction found after the divide; right wherever every w > 0)."""
    v, _ = args
    g = np.asarray(got, float).reshape(-1, 7)
    if not (np.asarray(v)[:, 3] == 0).any() or np.isfinite(g[:, 4:]).all():
        return False
    if g.shape != expected.shape or not np.isfinite(g[:, :4]).all():
        return False
    ok = np.isfinite(g).all(axis=1)
    return all_close(g[:, :4], expected[:, :4], FLOAT32_TOL) and all_close(
        g[ok], expected[ok], FLOAT32_TOL
    )


def _nan_at_w0_words(args, expected, got) -> str:
    v, _ = args
    k = int(np.flatnonzero(np.asarray(v)[:, 3] == 0)[0])
    return (
        f"your colour is NaN where an edge ends at v{k + 1} = {vec(v[k])}, whose w = 0: you "
        "took lesson 04's perspective-correct weights at the fraction of the projected edge. "
        "Where every w > 0 that is right (those weights turn the fraction on the screen into "
        "this same t), but a vertex with w = 0 has no projection, so the divide by w fails; in "
        "clip space nothing is divided: colour_a + t·(colour_b − colour_a), at the position's t"
    )


def _kept_colour(args, expected, got) -> tuple[int, np.ndarray] | None:
    """(k, colour): the first kept vertex vk whose colour ``got`` changed, positions right
    (r357: a kept vertex's colour divided by w or clamped was told the rule of a new vertex's
    colour, "which fraction?")."""
    v, c = (np.asarray(a, float) for a in args)
    g = np.asarray(got, float).reshape(-1, 7)
    if not same_polygon(g[:, :4], expected[:, :4], FLOAT32_TOL):
        return None
    for k in np.flatnonzero(v[:, 2] + v[:, 3] >= 0):
        rows = [p for p in g if all_close(p[:4], v[k], FLOAT32_TOL)]
        if rows and not any(all_close(p[4:], c[k], FLOAT32_TOL) for p in rows):
            return int(k), rows[0][4:]
    return None


def _colour_change(q, p, v, c) -> str:
    """What turned colour ``q`` of a kept vertex into ``p``, in words, or ""."""
    k = next(i for i in range(len(v)) if all_close(c[i], q, 0))
    if v[k, 3] not in (0, 1) and all_close(p, q / v[k, 3], FLOAT32_TOL):
        return (
            f"its own divided by its w = {num(v[k, 3])} (divided by w and never multiplied back?)"
        )
    if all_close(p, q * 255, FLOAT32_TOL):  # r456 H7
        return "its own times 255: colours here run from 0 to 1, as given"
    half = np.asarray(q, float).astype(np.float16).astype(float)
    if (p == half).all():  # r456: kept in 16-bit floats
        return "its own rounded to a 16-bit float (half precision, 11 significant bits)"
    other = [j for j in range(len(c)) if j != k and all_close(p, c[j], FLOAT32_TOL)]
    if other:
        return f"the colour of v{other[0] + 1}"
    moved = ~np.isclose(p, q, rtol=FLOAT32_TOL, atol=FLOAT32_TOL)
    if moved.any() and np.allclose(p[moved], p[moved][0]):
        bound = p[moved][0]
        if (q[moved] > bound).all() and (p <= bound + FLOAT32_TOL).all():
            return f"its own cut to at most {num(bound)} (clamped?)"
        if (q[moved] < bound).all() and (p >= bound - FLOAT32_TOL).all():
            return f"its own raised to at least {num(bound)} (clamped?)"
    return ""


def _kept_colour_words(args, expected, got) -> str:
    v, c = (np.asarray(a, float) for a in args)
    k, p = _kept_colour(args, expected, got)
    what = _colour_change(c[k], p, v, c)
    return (
        f"a kept vertex keeps its own colour exactly, as given (row {k + 1} of `colours`)"
        + (f"; yours is {what}" if what else "")
        + ". Only a new vertex's "
        "colour is interpolated"
    )


def _divided_colours(v, colours) -> np.ndarray | None:
    """The colours divided by w, interpolated so and never multiplied back (r357 misnamed 3)."""
    v = np.asarray(v, float)
    if (v[:, 3] == 0).any():
        return None
    return with_colours(v, np.asarray(colours, float) / v[:, 3:4])


def _colours_by_row(v, colours) -> np.ndarray:
    """Row k of the polygon given colours[k % 3] (r357 half-named 6)."""
    p = with_colours(v, colours)
    p[:, 4:] = np.asarray(colours, float)[np.arange(len(p)) % 3]
    return p


def explain_colour(args, expected, got) -> str:
    """Positions first (4.2's words); then the first kept vertex whose colour is wrong (r357),
    then the first new one."""
    v, c = args
    g = np.asarray(got, float).reshape(-1, 7)
    if not same_polygon(g[:, :4], expected[:, :4], FLOAT32_TOL):
        if same_polygon(g[:, 3:], expected[:, :4], FLOAT32_TOL):  # r319 X2: colours first
            return f"your first row is {vec(g[0])}, not {vec(expected[0])}"
        return "your positions are wrong (get 4.2 right first): " + explain_clip(
            (v,), expected[:, :4], g[:, :4]
        )
    kept = _kept_colour(args, expected, g)
    if kept is not None:
        k, p = kept
        return (
            f"your positions are right, but v{k + 1} = {vec(v[k])}, which is kept, has colour "
            f"{vec(p, c[k])}, not its own {vec(c[k], p)}"
        )
    for p in g:
        right = [q for q in expected if all_close(q[:4], p[:4], FLOAT32_TOL)]
        if right and not all_close(p[4:], right[0][4:], FLOAT32_TOL):
            q = right[0]
            return (
                f"your positions are right, but the vertex {vec(p[:4])} has colour "
                f"{vec(p[4:], q[4:])}, not {vec(q[4:], p[4:])}"
            )
    return "your colours are not in the order of your vertices"


def _rule(args, expected, got) -> str:
    g = np.asarray(got, float).reshape(-1, 7)
    if not same_polygon(g[:, :4], expected[:, :4], FLOAT32_TOL):  # 4.2's rule, not a colour's
        return clip_rule((args[0],), expected[:, :4], g[:, :4])
    if _kept_colour(args, expected, got) is not None:
        return ". A kept vertex keeps its own colour exactly, as given"
    return (
        ". A new vertex's colour is interpolated as its position is: at the same t, "
        "colour_a + t·(colour_b − colour_a), in clip space"
    )


def _on_255(args, expected, got) -> bool:
    """Right positions; every colour that differs is a multiple of 1/255 within half a step
    of the right one (r448 H1: told "at the same fraction … (which fraction?)")."""
    g = np.asarray(got, float).reshape(-1, 7)
    if g.shape != expected.shape or not np.isfinite(g).all():
        return False
    if not all_close(g[:, :4], expected[:, :4], FLOAT32_TOL):
        return False
    col, right = g[:, 4:], expected[:, 4:]
    off = np.abs(col - right) > 1e-12
    steps = np.abs(col * 255 - np.round(col * 255)) < 1e-6
    near = np.abs(col - right) <= 0.5 / 255 + 1e-9
    return bool(off.any() and (steps | ~off).all() and near.all())


def _on_255_words(args, expected, got) -> str:
    g = np.asarray(got, float).reshape(-1, 7)
    k = int(np.flatnonzero((np.abs(g[:, 4:] - expected[:, 4:]) > 1e-12).any(axis=1))[0])
    return (
        f"your colours are rounded to 8 bits: the vertex {vec(g[k, :4])} has colour "
        f"{vec(g[k, 4:], expected[k, 4:])}, multiples of 1/255, where the right one is "
        f"{vec(expected[k, 4:], g[k, 4:])}. Return the colours as floats: the clipper "
        "interpolates vertex outputs in full precision (a framebuffer rounds to 8 bits only "
        "when the pixel is written)"
    )


def _shared(a, b) -> str:
    """The coordinates (x, y, z, w) that ends ``a`` and ``b`` of an edge share."""
    return " and ".join("xyzw"[k] for k in range(4) if a[k] == b[k])


def _nan_on_shared(args, expected, got) -> tuple[int, str] | None:
    """(i, coordinates): positions right, and every colour that differs is NaN at a new
    vertex on an edge vi→vi+1 whose ends share a coordinate (r456 W11, W12, H5, H6: the colour
    t recovered from x, y, z or w alone is 0/0 there); None otherwise."""
    v, c = (np.asarray(a, float) for a in args)
    g = np.asarray(got, float).reshape(-1, 7)
    if g.shape != expected.shape or not all_close(g[:, :4], expected[:, :4], FLOAT32_TOL):
        return None
    bad = [k for k in range(len(g)) if not all_close(g[k, 4:], expected[k, 4:], FLOAT32_TOL)]
    if not bad or not all(np.isnan(g[k, 4:]).all() for k in bad):
        return None
    d = v[:, 2] + v[:, 3]
    for i in range(3):
        j = (i + 1) % 3
        if (d[i] >= 0) != (d[j] >= 0) and _shared(v[i], v[j]):
            t = d[i] / (d[i] - d[j])
            if any(all_close(g[k, :4], v[i] + t * (v[j] - v[i]), FLOAT32_TOL) for k in bad):
                return i, _shared(v[i], v[j])
    return None


def _nan_on_shared_words(args, expected, got) -> str:
    i, shared = _nan_on_shared(args, expected, got)
    j = (i + 1) % 3
    return (
        f"your new vertex on the edge v{i + 1}→v{j + 1} has a NaN colour, and both ends of that "
        f"edge have the same {shared}: did you recover its fraction of the edge from one "
        f"coordinate, such as ({shared[0]} − {shared[0]}_a)/({shared[0]}_b − {shared[0]}_a)? "
        "That is 0/0 on such an edge. Which quantity is sure to differ between the ends of "
        "every edge that crosses the plane? Take the colour at that fraction"
    )


def _far_too(v, colours):
    """Clipped against the far plane too, the colours riding along (r456 H8: the package's
    clip_polygon)."""
    p = clip_with(np.column_stack([np.asarray(v, float), np.asarray(colours, float)]))
    return p if p is None or not len(p) else clip_with(p, lambda q: q[3] - q[2])


_WHY = (
    "a vertex's colour, like its position, changes linearly along the edge in clip space, so "
    "the new vertex takes its colour at its own t"
)

COLOUR_MISTAKES = [
    Mistake("colour after the divide", "you took the colour at the fraction where z/w reaches "
            f"−1, found after the divide: {_WHY}. After the divide equal fractions of the "
            "projected edge are not equal fractions of the edge itself (lesson 04's "
            "perspective weighting), so that t is another point's",
            gives=lambda v, c: colour_with(v, c, _after_divide)),
    Mistake("colour perspective-corrected", "you interpolated colour/w and 1/w and divided, "
            "the perspective-correct rule for steps on the screen: before the divide there is "
            f"nothing to correct, {_WHY}",
            gives=lambda v, c: colour_with(v, c, _perspective)),
    Mistake("colour of the inside end", "your new vertices keep the colour of their edge's "
            f"inside end, not interpolated: {_WHY}",
            gives=lambda v, c: colour_with(v, c, lambda a, b, t: (a if a[2] + a[3] >= 0 else b)[4:])),
    Mistake("colour of the first end", "your new vertices keep the colour of their edge's "
            f"first end, not interpolated: {_WHY}",
            gives=lambda v, c: colour_with(v, c, lambda a, b, t: a[4:])),
    Mistake("colour t from the other end", "you took the colour at 1 − t, measured from the "
            f"edge's other end: {_WHY}, colour_a + t·(colour_b − colour_a)",
            gives=lambda v, c: colour_with(v, c, lambda a, b, t: _lerp(a, b, 1 - t))),
    Mistake("colour halfway", "you gave each new vertex the colour halfway along its edge "
            f"(t = ½): {_WHY}", gives=lambda v, c: colour_with(v, c, lambda a, b, t: _lerp(a, b, 0.5))),
    # r319: the colour columns first (X2, told "your positions are wrong"); a kept vertex given
    # another vertex's colour or BGR (H3, H4, told the rule about new vertices); lesson 04's
    # weights at the fraction after the divide, NaN at w = 0 (H5, told only "holds NaN")
    Mistake("colour columns first", "your rows are (r, g, b, x, y, z, w), the colour first: "
            "each row is the position, then its colour, (x, y, z, w, r, g, b)",
            gives=_columns_first),
    *(Mistake("colours on the wrong vertex", "your colours sit one vertex off: a kept vertex "
              "keeps its own colour (row i of `colours` goes with row i of `v`), and a new "
              "vertex takes its colour between its own edge's two ends",
              gives=lambda v, c, k=k: with_colours(v, np.roll(np.asarray(c, float), k, axis=0)))
      for k in (1, -1)),
    Mistake("colours BGR", "your colours are reversed, (b, g, r): a kept vertex keeps its own "
            "colour as given, (r, g, b) in the last three columns",
            gives=lambda v, c: with_colours(v, np.asarray(c, float)[:, ::-1])),
    Mistake("colour perspective-corrected after the divide", _nan_at_w0_words, fits=_nan_at_w0,
            only_whole=True),
    # r357: colours divided by w and never multiplied back (misnamed 3); row k's colour from
    # colours[k % 3] (H6); any other change to a kept vertex's colour (a clamp: misnamed 4)
    Mistake("colours divided by w", "you divided the colours by w and never multiplied back: "
            "lesson 04 divides by w to interpolate on the screen, then multiplies back; in "
            "clip space nothing is divided: a kept vertex keeps its own colour, and a new "
            "vertex takes its colour at its own t between its edge's two ends",
            gives=_divided_colours),
    Mistake("colours by row number", "your row k takes the colour of row k of `colours` "
            "(colours[k % 3]), but the polygon's rows are not the triangle's: a vertex behind "
            "is dropped and new vertices come between. A kept vertex keeps the colour of its "
            "own row of `v`, and a new vertex takes its colour between its own edge's two ends",
            gives=_colours_by_row),
    # r448 H1, H3: colours rounded to 8 bits, and the triangle's mean colour at new vertices,
    # were told only "at the same fraction of the edge (which fraction?)"
    Mistake("colours rounded to 8 bits", _on_255_words, fits=_on_255, only_whole=True),
    Mistake("mean colour", "your new vertices take the mean of the triangle's three colours: "
            f"a new vertex lies on one edge, between its two ends only; {_WHY}",
            gives=lambda v, c: colour_with(v, c, lambda a, b, t, c=c: np.mean(np.asarray(c, float), axis=0))),
    Mistake("colour t from one coordinate", _nan_on_shared_words,
            fits=lambda a, e, g: _nan_on_shared(a, e, g) is not None),
    Mistake("far plane too", "you clipped against the far plane too (w − z ≥ 0): this "
            "exercise clips against the near plane only, z + w ≥ 0, so a vertex beyond the far "
            "plane stays", gives=_far_too),
    Mistake("kept colour changed", _kept_colour_words, fits=lambda a, e, g: _kept_colour(a, e, g)
            is not None, symptom=True),
]  # fmt: skip


def _draw(ax, case, got):
    """4.2's figure of the positions, each vertex a disc of its colour: expected large, yours
    a square inside it (a wrong colour is a square of another colour)."""
    from .drawing import clip_panels, draw_clip

    (v, colours), expected = case[1], case[2]
    g = None if got is None else np.asarray(got, float).reshape(-1, 7)
    artists = draw_clip(ax, v, expected[:, :4], None if g is None else g[:, :4], colours)
    panels = clip_panels(ax)
    for k, panel in enumerate(panels):
        for p, marker, size in [(expected, "o", 360), *([(g, "s", 70)] if g is not None else [])]:
            if len(p) and np.isfinite(p).all():
                artists.append(panel.scatter(p[:, k], p[:, 2] + p[:, 3], s=size, marker=marker,
                                             c=np.clip(p[:, 4:], 0, 1), edgecolors="black",
                                             zorder=5))  # fmt: skip
        for label in panel.texts:  # r357 FIG3: "v1" was half under the disc
            if hasattr(label, "xyann") and "off the panel" not in label.get_text():
                label.xyann = (12 if label.xyann[0] > 0 else -12, 12)
    # under the x axis: the report's title holds the top
    panel = panels[0]
    artists.append(panel.set_xlabel(f"{panel.get_xlabel()}\ndiscs: the expected colours; "
                                    "squares: yours"))  # fmt: skip
    return artists


CLIP_NEAR_COLOUR = Exercise(
    "clip_near_colour", colour_cases, as_coloured,
    lambda g, e, a: same_polygon(g, e, FLOAT32_TOL), explain_colour, _rule, COLOUR_MISTAKES,
    # r456 H8, W10: the package's clip with colours as attributes, and its distances
    answers=(PackageAnswer(with_colours), PackageAnswer(clip_polygon), DISTANCES), draw=_draw,
    # 4.2's cases and clip: a student's call into them does not count
    reference=("teachraster.exercises.depth_clipping",),
    # issue 30: the formula the task asks to work out is said once two wrong answers failed
    hints=((": at the same t, colour_a + t·(colour_b − colour_a), in clip space",
            ": at the same fraction of the edge, in clip space (which fraction?)"),
           (", colour_a + t·(colour_b − colour_a)", ""),),
)  # fmt: skip
