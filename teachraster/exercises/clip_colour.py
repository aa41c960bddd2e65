"""Exercise ``clipped_colours(v, colours, polygon)`` (lesson 05a, exercise 4.3): the colours
of a clipped polygon's vertices, recovered from their positions (issue 30, r456 "Transcription":
4.3 was 4.2's loop with three columns appended; r310 M2 before it).

A clipper hands over the polygon's positions only, as it made them: any starting vertex,
either direction, a vertex on the plane given twice, float32 or float64, and on some cases cut
by the far plane or the side planes x = ±w too. The student returns each vertex's colour. The
reasoning asked: every point of the clipped polygon is a point of the triangle in clip space,
p = λ1·v1 + λ2·v2 + λ3·v3 with λ1 + λ2 + λ3 = 1, and its colour is the same combination of
the three colours (the clipper interpolates every output linearly in clip space, before the
divide); which equations give the λ on every case (x and y alone do not when the triangle's y
are all equal; the screen's x/w, y/w do not when a vertex has w = 0 or the triangle is edge-on);
that a new vertex may lie inside the triangle (two planes cut there), so a t along one edge
does not reach it; that float32 positions equal the triangle's vertices only within rounding.

Expected answers: the weights solved from all five equations (x, y, z, w and Σλ = 1) by
float64 least squares on the exact (float64) polygon, times the colours
(:func:`reference_colours`); tests/test_exercises_r489.py compares them with the core's
Sutherland-Hodgman carrying the colours as attributes
(:func:`teachraster.pipeline.geometry.clipping.clip_polygon`) on every case.
"""

from __future__ import annotations

from itertools import combinations

import numpy as np

from ..pipeline.geometry.clipping import clip_polygon
from .answers import MAX_VERTICES, as_numbers, short
from .cases import SEED
from .depth_clipping import DISTANCES, clip_cases, clip_with
from .exercise import Exercise, Mistake, PackageAnswer
from .finite_linalg import InfiniteMatrix, refusing_inf
from .running import WrongAnswerType
from .scalars import num, vec
from .tolerance import all_close

#: Colours are compared within this (absolute, for colours of size 1): a float32 polygon moves
#: a colour by a few 1e-7 on these cases; the slips named below move it by 1e-2 or more.
COLOUR_TOL = 1e-4


def weights(v, points) -> np.ndarray:
    """(n, 3) the λ of each point p: p = Σ λ_i v_i, Σ λ_i = 1, from all five equations
    (float64 least squares; exact for a point of the triangle's plane in clip space).

    >>> v = np.array([[0.0, 0, 0, 1], [1, 0, 0, 1], [0, 1, 0, 2]])
    >>> weights(v, [[0.5, 0.25, 0, 1.25]]).round(12).tolist()
    [[0.25, 0.5, 0.25]]
    """
    v = np.asarray(v, float)
    a = np.vstack([v.T, np.ones(3)])
    b = np.vstack(
        [np.asarray(points, float).reshape(-1, 4).T, np.ones(len(np.reshape(points, (-1, 4))))]
    )
    return np.linalg.lstsq(a, b, rcond=None)[0].T


def reference_colours(v, colours, points) -> np.ndarray:
    """The (n, 3) colours at clip-space points of triangle ``v``."""
    return weights(v, points) @ np.asarray(colours, float)


def _flat(v) -> bool:
    """Three clip-space points on one line (no plane of weights: colours undefined)."""
    return np.linalg.matrix_rank(np.vstack([np.asarray(v, float).T, np.ones(3)]), tol=1e-9) < 3


# how a clipper hands its polygon over, in turn over the cases (the task says each may come)
_FORMS = ("as clipped", "starting at its second vertex", "the other way round",
          "in float32, starting at its last vertex")  # fmt: skip


def _order(form: str, n: int) -> np.ndarray:
    """The clipper's rows, in the order ``form`` hands them over."""
    k = np.arange(n)
    if form == _FORMS[1]:
        return np.roll(k, -1)
    if form == _FORMS[2]:
        return k[::-1]
    return np.roll(k, 1) if form == _FORMS[3] else k


def _targeted() -> list:
    """(label, v, polygon) of the cases made for this task: which equations, which planes."""
    out = []
    # w = 2x + y at every vertex: (x, y, w) alone give no weights
    v = np.array([[1.0, 0, -3, 2], [0, 1, 0, 1], [1, 1, 0, 3]])
    out.append(("w = 2x + y at every vertex", v, clip_with(v)))
    # z = w − 2 at every vertex: (z, w, 1) alone give no weights
    v = np.array([[0.0, 0, -1.5, 0.5], [1, 0, 1, 3], [0, 1, 0, 2]])
    out.append(("z = w − 2 at every vertex", v, clip_with(v)))
    # x + y = 1 at every vertex: (x, y, 1) alone give no weights (the screen does)
    v = np.array([[0.0, 1, -2, 1], [1, 0, 0.5, 2], [2, -1, 1, 4]])
    out.append(("x + y = 1 at every vertex", v, clip_with(v)))
    # v3 = v1 + v2: the triangle's plane holds the clip-space origin (edge-on on the screen),
    # so x, y, z, w without Σλ = 1 leave the weights open
    v = np.array([[1.0, 0, -2, 1], [0, 1, 0.5, 1], [1, 1, -1.5, 2]])
    out.append(
        ("v3 = v1 + v2: the triangle's plane holds the origin of clip space", v, clip_with(v))
    )
    # every y the same (and edge-on on the screen): (x, y, 1) and x/w, y/w give no weights
    v = np.array([[0.5, 0, -2, 1], [1, 0, 1, 2], [-1.5, 0, 0.5, 3]])
    out.append(("every y the same, so the triangle is edge-on on the screen", v, clip_with(v)))
    # the dropped vertex on the eye plane (w = 0): it has no projection
    v = np.array([[0.5, 1, -1, 0], [1, -1, 0.5, 1], [-1, -0.5, 0.2, 2]])
    out.append(("the dropped vertex on the eye plane (w = 0)", v, clip_with(v)))
    # a vertex on the plane: kept, and found again as a crossing (given twice)
    v = np.array([[0.0, 0, -1, 1], [1, 0, -2, 0.5], [0, 1, 0.5, 1]])
    p = clip_with(v)
    out.append(("a vertex on the near plane, given twice", v, np.vstack([p[:1], p])))
    # near and side planes: the corner where they meet lies inside the triangle
    for label, v, guard in [
        ("cut by the near plane and the side plane x = w: a corner inside the triangle",
         np.array([[3.0, 0, -3, 1], [3, 0.5, 1, 2], [-1, 1, 0.5, 1.5]]), 1.0),
        ("cut by the near plane and the side planes x = ±w, y = ±w",
         np.array([[-0.2, 0.1, -3, 1], [3, 2, 1, 2], [-2.5, 1.5, 0, 2]]), 1.0),
        ("cut by the near and the far plane", np.array([[0.0, 0, 3, 2], [1, 0, -1.5, 1],
                                                        [-1, 1, 0.5, 1]]), None),
    ]:  # fmt: skip
        out.append((label, v, clip_polygon(v, np.zeros((3, 0)), guard)[0]))
    return out


def _targeted_r507() -> list:
    """(label, v, polygon[, colours]) of r507's cases, after the others (their forms and
    colours unchanged)."""
    out = []
    # r507 P1: two sets open on one triangle, so a fallback from one to the other fails too:
    # (x, y, Σλ = 1) and x, y, z, w without it; (x, y, Σλ = 1) and (z, w, Σλ = 1)
    v = np.array([[1.0, 0, -2, 1], [-0.5, 0, 1, 1], [0.5, 0, -1, 2]])
    out.append(("every y = 0 and v3 = v1 + v2", v, clip_with(v)))
    v = np.array([[-1.0, 2, -3, -1], [1, 0, 0, 2], [2, -1, 2, 4]])
    out.append(("x + y = 1 and z = w − 2 at every vertex", v, clip_with(v)))
    # r507 P2: new vertices 8e-4 from v1 (t = 3.2e-4), v1 not kept: a kept-vertex look-up
    # with a loose tolerance gives them v1's colour, 3.2e-4 off (primaries: colours differ by 1)
    v = np.array([[0.5, 0.2, -1.0008, 1], [1, -0.5, 1.5, 1], [-1, 0.5, 1.5, 1]])
    out.append(("a vertex 0.0008 behind the near plane: new vertices 8e-4 from it", v,
                clip_with(v), np.eye(3)))  # fmt: skip
    return out


def colour_cases():
    """4.2's cases (the clipper's polygon handed over in the four forms in turn), then this
    task's own; triangles on one line in clip space left out (their colours are undefined)."""
    rng = np.random.default_rng(SEED + 43)
    made = [(label.split(": v=")[0], a[0], p) for label, a, p in clip_cases()]
    out, empty = [], 0
    for k, (label, v, poly, *given) in enumerate([*_targeted(), *made, *_targeted_r507()]):
        if _flat(v) or (not len(poly) and empty):  # one empty polygon is enough
            continue
        empty += not len(poly)
        c = np.round(rng.uniform(0, 1, (3, 3)), 2)
        c = given[0] if given else c  # (drawn all the same: the other cases keep theirs)
        form = _FORMS[k % 4]
        order = _order(form, len(poly))
        given = poly[order].astype(np.float32 if form == _FORMS[3] else float)
        words = f"{label}; the polygon {form}: v={vec(v[0])}, {vec(v[1])}, {vec(v[2])}"
        out.append((words, (v, c, given), reference_colours(v, c, poly)[order]))
    return out


def as_colours(value) -> np.ndarray:
    sized = isinstance(value, (list, tuple)) or (isinstance(value, np.ndarray) and value.ndim)
    if sized and len(value) > MAX_VERTICES + 4:
        raise WrongAnswerType(f"returned {short(value)}: one colour per vertex of `polygon`")
    if sized and np.size(value) == 0:
        return np.zeros((0, 3))
    return as_numbers(value, (-1, 3), "an (n, 3) array of colours (r, g, b), one per vertex "
                      "of `polygon`", 3 * (MAX_VERTICES + 4))  # fmt: skip


def _same(got, expected, args) -> bool:
    return all_close(got, expected, COLOUR_TOL)


def _bad_rows(expected, got) -> list:
    g = np.asarray(got, float).reshape(-1, 3)
    if g.shape != expected.shape:
        return []
    return [k for k in range(len(g)) if not all_close(g[k], expected[k], COLOUR_TOL)]


def _kept(v, p) -> int | None:
    """The vertex of ``v`` that polygon vertex ``p`` is (within float32 rounding), or None."""
    for i in range(3):
        if all_close(p, v[i], 1e-6):
            return i
    return None


def _on_edge(v, p) -> tuple | None:
    """(i, t): ``p`` lies on edge vi→vi+1 at t (within float32 rounding), or None."""
    for i in range(3):
        a, b = v[i], v[(i + 1) % 3]
        lam = weights(v, p)[0]
        if abs(lam[(i + 2) % 3]) < 1e-6 and all_close(p, a + lam[(i + 1) % 3] * (b - a), 1e-5):
            return i, float(lam[(i + 1) % 3])
    return None


def explain_colours(args, expected, got) -> str:
    v, c, poly = (np.asarray(a, float) for a in args)
    g = np.asarray(got, float).reshape(-1, 3)
    if g.shape != expected.shape:
        return f"you returned {len(g)} colours for a polygon of {len(poly)} vertices"
    k = _bad_rows(expected, g)[0]
    where = _kept(v, poly[k])
    edge = _on_edge(v, poly[k]) if where is None else None
    if where is not None:
        what = f"v{where + 1}, kept"
    elif edge is not None:
        t = num(edge[1], float(np.clip(np.round(edge[1]), 0, 1)))  # 0.99968, not 1 (r507)
        what = f"a new vertex, on the edge v{edge[0] + 1}→v{(edge[0] + 1) % 3 + 1} at t = {t}"
    else:
        what = "a new vertex inside the triangle, where two planes cut"
    return (f"polygon[{k}] = {vec(poly[k])} ({what}) has colour {vec(g[k], expected[k])}, "
            f"not {vec(expected[k], g[k])}")  # fmt: skip


def _rule(args, expected, got) -> str:
    return (
        ". Every point of the clipped polygon is a point of the triangle in clip space; "
        "its colour is made of the three colours as its position is of v1, v2, v3"
    )


# --- the typical slips, each as the answer it gives -------------------------------------


def _screen(v, points, strict=True, how="solve"):
    """λ of the points' projections (x/w, y/w) in the projected triangle, lesson 04's
    perspective weights where ``strict`` is False (numpy's solve, garbage where singular; or
    ``how`` "lstsq" / "lstsq z": least squares on (x/w, y/w) or (x/w, y/w, z/w), one of many
    answers where singular, r507); None where a w is 0 or (``strict``) the projection is a
    segment."""
    v, p = np.asarray(v, float), np.asarray(points, float).reshape(-1, 4)
    if (v[:, 3] == 0).any() or (p[:, 3] == 0).any():
        return None
    n = 3 if how == "lstsq z" else 2
    s, q = v[:, :n] / v[:, 3:], p[:, :n] / p[:, 3:]
    m = np.vstack([s.T, np.ones(3)])
    if strict and np.linalg.matrix_rank(m[[0, 1, n]], tol=1e-9) < 3:
        return None
    b = np.vstack([q.T, np.ones(len(q))])
    try:
        with np.errstate(all="ignore"):
            if how == "solve":
                return np.linalg.solve(m, b).T
            return np.linalg.lstsq(m, b, rcond=None)[0].T if np.isfinite(m).all() else None
    except np.linalg.LinAlgError:
        return None


def _after_divide(v, c, poly):
    lam = _screen(v, poly)
    return None if lam is None or not len(poly) else lam @ np.asarray(c, float)


def _screen_fails(args, expected, got) -> str | None:
    """Why the screen cannot give this case's weights, or None."""
    v = np.asarray(args[0], float)
    if (v[:, 3] == 0).any():
        k = int(np.flatnonzero(v[:, 3] == 0)[0])
        return f"v{k + 1} = {vec(v[k])} has w = 0: it has no projection"
    if _screen(v, np.zeros((0, 4))) is None:
        return "the triangle is edge-on: its projection is a segment"
    return None


def _via_screen(args, expected, got) -> str | None:
    """On a case the screen gives no weights for: NaN, inf, or what numpy's solve gives there,
    as they are or perspective-corrected (lesson 04's weights, right wherever every w ≠ 0)."""
    v, c, poly = (np.asarray(a, float) for a in args)
    g = np.asarray(got, float).reshape(-1, 3)
    bad = _bad_rows(expected, g)
    if not bad or not _screen_fails(args, expected, got):
        return None
    if not np.isfinite(g[bad]).all():  # the screen gives NaN at every vertex, not at some;
        # where some equations are open too, NaN cannot tell which was used (r507 M1)
        every = (~np.isfinite(g)).any(axis=1).all()
        return "corrected" if every and not _largest_open(v) else None
    for how in ("solve", "lstsq", "lstsq z"):
        if how != "solve" and _undetermined(args, expected, got) is not None:
            return None  # a set of the five equations gives it too: named as that (r496)
        lam = _screen(v, poly, strict=False, how=how)
        if lam is None or not np.isfinite(lam).all():
            continue
        with np.errstate(all="ignore"):
            fixed = lam / v[:, 3]
            fixed = fixed / fixed.sum(axis=1, keepdims=True)
        if all_close(g, fixed @ c, COLOUR_TOL):
            return "corrected"
        if all_close(g, lam @ c, COLOUR_TOL):
            return "plain"
    return None


def _via_screen_words(args, expected, got) -> str:
    if _via_screen(args, expected, got) == "plain":
        return (
            "you took the weights of the projected point on the screen (x/w, y/w) as they "
            f"are, and on the screen {_screen_fails(args, expected, got)}. Even where it "
            "is not, equal fractions on the screen are not equal fractions of the triangle "
            "(lesson 04); in clip space nothing is divided: which equations give the "
            "weights of a point of the triangle there?"
        )
    return (
        f"you went through the screen (x/w, y/w, lesson 04's weights?), and on the "
        f"screen {_screen_fails(args, expected, got)}. Where every w ≠ 0 that gives the right "
        "weights; in clip space nothing is divided: which equations give the weights of a "
        "point of the triangle there?"
    )


#: The equations a student may solve the weights from: (coordinates, with Σλ = 1?), every set
#: of three or four of the five (r496 M1–M8: a slip that drops one equation, "z is only depth",
#: was named by a smaller set it does not use), largest first.
_SUBSETS = sorted(
    [(cols, one) for n in (3, 4) for one in (True, False)
     for cols in combinations(range(4), n - one)],
    key=lambda s: -(len(s[0]) + s[1]),
)  # fmt: skip


def _subset_words(cols, with_one) -> str:
    return ", ".join("xyzw"[k] for k in cols) + (" and Σλ = 1" if with_one else " (without Σλ = 1)")


def _left_out(cols, with_one) -> str:
    out = ["xyzw"[k] for k in range(4) if k not in cols] + ([] if with_one else ["Σλ = 1"])
    return " and ".join(out)


def _matrix(rows, cols, with_one):
    rows = np.asarray(rows, float).reshape(-1, 4)
    return np.vstack([rows[:, list(cols)].T] + ([np.ones(len(rows))] if with_one else []))


def _open_subsets(v) -> list:
    """The subsets of :data:`_SUBSETS` that leave the weights open on triangle ``v``."""
    return [(c, o) for c, o in _SUBSETS
            if np.linalg.matrix_rank(_matrix(v, c, o), tol=1e-9) < 3]  # fmt: skip


def _largest_open(v) -> list:
    """The open subsets no larger open subset holds (a part of an open set is open too)."""
    sets = _open_subsets(v)
    return [(c, o) for c, o in sets
            if not any((set(c) < set(c2) and o <= o2) or (set(c) == set(c2) and o < o2)
                       for c2, o2 in sets)]  # fmt: skip


def _from_subset(v, c, poly, cols, with_one, solve, scaled=False):
    """The colours from the weights solved from these equations only (``solve``: numpy's
    solve where square, else least squares; ``scaled``: then divided by their sum, r496 H1),
    None where that raises."""
    a, b = _matrix(v, cols, with_one), _matrix(poly, cols, with_one)
    try:
        with np.errstate(all="ignore"):
            lam = (np.linalg.solve(a, b) if solve and a.shape[0] == 3 else
                   np.linalg.lstsq(a, b, rcond=None)[0])  # fmt: skip
    except np.linalg.LinAlgError:
        return None
    if scaled:
        with np.errstate(all="ignore"):
            lam = lam / lam.sum(axis=0)
    return lam.T @ np.asarray(c, float)


def _undetermined(args, expected, got) -> tuple | None:
    """The largest open subset whose weights give ``got`` at its wrong rows (or NaN/inf, or
    wild numbers), or None."""
    v, c, poly = args
    g = np.asarray(got, float).reshape(-1, 3)
    bad = _bad_rows(expected, g)
    if not bad or _screen_fails(args, expected, got) and not np.isfinite(g[bad]).all():
        return None
    for cols, one in _open_subsets(v):
        for solve, scaled in ((True, False), (False, False), (True, True), (False, True)):
            mine = _from_subset(v, c, poly, cols, one, solve, scaled and not one)
            if (mine is not None and mine.shape == g.shape
                    and all_close(g[bad], mine[bad], COLOUR_TOL)):  # fmt: skip
                return cols, one, scaled and not one
    # numpy's solve on a nearly singular system: huge numbers (a NaN has other causes: r496 M9)
    wild = np.isfinite(g[bad]).all() and np.abs(g[bad]).max() > 1e3
    return (*_open_subsets(v)[0], False) if wild and _open_subsets(v) else None


def _open_why(v, cols, with_one) -> str:
    v = np.asarray(v, float)
    names = "xyzw"
    for i, j in ((0, 1), (1, 2), (0, 2)):
        if all(v[i, k] == v[j, k] for k in cols):
            same = ", ".join(names[k] for k in cols)
            return f"v{i + 1} and v{j + 1} have the same {same}: these equations cannot tell them apart"
    if with_one:
        return "in these coordinates the three vertices lie on one line"
    return "the three vertices, as vectors, are not independent in these coordinates"


def _undetermined_words(args, expected, got) -> str:
    cols, one, scaled = _undetermined(args, expected, got)
    then = ", then scaled them to sum to 1 (that picks none of the many answers)" if scaled else ""
    return (
        f"you solved for the weights from {_subset_words(cols, one)} only (or some of these), "
        f"leaving out {_left_out(cols, one)}{then}, and on this triangle those equations leave them "
        f"open ({_open_why(args[0], cols, one)}): a singular system, so 0/0, wild numbers or one "
        "of many answers. Which equations fix the weights on every triangle?"
    )


def _open_words(args) -> str:
    """Every largest set of equations open on this case's triangle, and the screen where it
    fails; "" where none is."""
    sets = _largest_open(args[0])
    why = ["; ".join(_subset_words(c, o) for c, o in sets) + " (or any part of one of them)"
           ] if sets else []  # fmt: skip
    fails = _screen_fails(args, None, None)
    if fails:
        why.append(f"on the screen {fails}")
    return "; and ".join(why)


def _nan_open(args, expected, got) -> bool:
    """NaN (or ±inf) at every vertex, on a triangle some equations leave open (r507 M1)."""
    g = np.asarray(got, float).reshape(-1, 3)
    return (g.shape == expected.shape and len(g) > 0 and bool(_largest_open(args[0]))
            and (~np.isfinite(g)).any(axis=1).all())  # fmt: skip


def _nan_open_words(args, expected, got) -> str:
    return (
        f"your colours are NaN (or infinite) at every vertex, and on this triangle these leave "
        f"the weights open: {_open_words(args)}: a singular system, 0/0. Did you solve for the "
        "weights from some of the equations only (or on the screen)? Which equations fix them "
        "on every triangle?"
    )


def _raised(args, error: str) -> str:
    """A singular solve, named (numpy's LinAlgError on a triangle some equations leave open, or
    that is edge-on on the screen): every largest open set of equations is said, since the
    error does not show which the student used (r496 M5–M7)."""
    if InfiniteMatrix.__name__ in error:
        fails = _screen_fails(args, None, None)
        where = f"on the screen {fails}, so x/w is ±inf there" if fails else "a division by 0?"
        return (
            f"; your matrix holds inf: {where}. Where every w ≠ 0 lesson 04's weights are "
            "right; in clip space nothing is divided: which equations give the weights of a "
            "point of the triangle there?"
        )
    if "LinAlgError" not in error and "Singular" not in error:
        return ""
    why = _open_words(args)
    if not why:
        return ""
    return (
        "; on this triangle these leave the weights open: " + why + ". Did you "
        "solve for the weights from some of the equations only, or on the screen? Which "
        "equations fix them on every triangle?"
    )


def _near_crossing(v, p) -> tuple | None:
    """(i, t): ``p`` is where edge vi→vi+1 crosses the near plane, or None."""
    d = v[:, 2] + v[:, 3]
    for i in range(3):
        j = (i + 1) % 3
        if (d[i] >= 0) != (d[j] >= 0):
            t = d[i] / (d[i] - d[j])
            if all_close(p, v[i] + t * (v[j] - v[i]), 1e-5):
                return i, t
    return None


def _shared(a, b) -> str:
    return " and ".join("xyzw"[k] for k in range(4) if a[k] == b[k])


def _t_one_coordinate(args, expected, got) -> tuple | None:
    """(k, i, shared): NaN only at near-plane crossings on edges whose ends share a coordinate
    (the t recovered from one coordinate: 0/0 there; r456 W11, W12, H5, H6), or None."""
    v = np.asarray(args[0], float)
    poly = np.asarray(args[2], float)
    g = np.asarray(got, float).reshape(-1, 3)
    bad = _bad_rows(expected, g)
    if not bad or not np.isnan(g[bad]).all():
        return None
    for k in bad:
        e = _near_crossing(v, poly[k])
        if e is None or not _shared(v[e[0]], v[(e[0] + 1) % 3]):
            return None
    e = _near_crossing(v, poly[bad[0]])
    return bad[0], e[0], _shared(v[e[0]], v[(e[0] + 1) % 3])


def _t_one_coordinate_words(args, expected, got) -> str:
    k, i, shared = _t_one_coordinate(args, expected, got)
    return (
        f"polygon[{k}] lies on the edge v{i + 1}→v{(i + 1) % 3 + 1}, whose ends have the "
        f"same {shared}: did you recover its fraction of the edge from one coordinate, "
        f"such as ({shared[0]} − {shared[0]}_a)/({shared[0]}_b − {shared[0]}_a)? That is 0/0 "
        "there. Which quantity is sure to differ between the ends of every edge that "
        "crosses the plane?"
    )


def _not_near(args) -> list:
    """Rows of the polygon that are neither the triangle's vertices nor near-plane crossings:
    another plane cut there (on an edge, or inside the triangle)."""
    v, _, poly = (np.asarray(a, float) for a in args)
    return [
        k
        for k in range(len(poly))
        if _kept(v, poly[k]) is None and _near_crossing(v, poly[k]) is None
    ]


def _near_only(args, expected, got) -> bool:
    bad, other = _bad_rows(expected, got), _not_near(args)
    return bool(bad and other and set(bad) <= set(other))


def _near_only_words(args, expected, got) -> str:
    v, _, poly = (np.asarray(a, float) for a in args)
    k = next(k for k in _not_near(args) if k in _bad_rows(expected, got))
    where = (
        "on no edge of the triangle: two planes cut there, so it lies inside it, and "
        "no fraction along one edge reaches it"
        if _on_edge(v, poly[k]) is None
        else "on an edge, but not where that edge crosses the near plane: another plane cut it"
    )
    return (
        f"polygon[{k}] has z + w = {num(poly[k, 2] + poly[k, 3])}, and it is {where}. The polygon is the clipper's, and it may cut other planes too: which "
        "weights of v1, v2, v3 give that point?"
    )


def _float32_kept(args, expected, got) -> bool:
    """Wrong only at vertices that are the triangle's own, rounded to float32 (an exact
    comparison missed them)."""
    v, _, poly = args
    if np.asarray(poly).dtype != np.float32:
        return False
    bad = _bad_rows(expected, got)
    v = np.asarray(v, float)
    p = np.asarray(poly, float)
    return bool(bad) and all(_kept(v, p[k]) is not None and not (p[k] == v).all(axis=1).any()
                             for k in bad)  # fmt: skip


def _float32_kept_words(args, expected, got) -> str:
    v, _, poly = args
    k = _bad_rows(expected, got)[0]
    i = _kept(np.asarray(v, float), np.asarray(poly, float)[k])
    return (
        f"polygon[{k}] = {vec(np.asarray(poly[k], float))} is v{i + 1} = {vec(v[i])} "
        "rounded to float32 (this polygon is float32): it is kept, but not equal to v"
        f"{i + 1} bit for bit. Did you look vertices up by exact equality?"
    )


def _loose_kept(args, expected, got) -> list | None:
    """[(k, i, distance)] where each wrong row is a new vertex near vi (within 0.05, not
    within float32's rounding) that took vi's colour (r507 P2: a kept-vertex look-up with a
    loose tolerance), or None."""
    v, c, poly = (np.asarray(a, float) for a in args)
    g = np.asarray(got, float).reshape(-1, 3)
    bad = _bad_rows(expected, g)
    out = []
    for k in bad:
        d = np.abs(v - poly[k]).max(axis=1)
        i = int(np.argmin(d))
        if _kept(v, poly[k]) is not None or d[i] > 0.05 or not all_close(g[k], c[i], COLOUR_TOL):
            return None
        out.append((k, i, float(d[i])))
    return out or None


def _loose_kept_words(args, expected, got) -> str:
    v, c, poly = (np.asarray(a, float) for a in args)
    k, i, d = _loose_kept(args, expected, got)[0]
    return (
        f"polygon[{k}] = {vec(poly[k], v[i])} is a new vertex {num(d)} from v{i + 1} = "
        f"{vec(v[i], poly[k])}, "
        f"not v{i + 1} itself, and your colour there is v{i + 1}'s own: did you look the kept "
        f"vertices up with a tolerance of {num(d)} or more? Only a vertex equal to v{i + 1} "
        "up to its last digits (about 1e-7 of its size) is v"
        f"{i + 1}; one this close still has its own weights (here they move the colour by "
        f"{num(float(np.abs(expected[k] - c[i]).max()))})"
    )


def _own_order(v, c, poly):
    """The colours of the student's own near-plane clip, in its own order (not polygon's)."""
    own = clip_with(np.column_stack([np.asarray(v, float), np.asarray(c, float)]))
    if own is None or len(own) != len(poly):
        return None
    return own[:, 4:]


def _edge_t(v, c, poly, t_of):
    """Each vertex: kept -> its colour; on an edge at t -> the colour ``t_of(ca, cb, t, i)``;
    else the right colour (a slip of the edge rule only)."""
    v, c = np.asarray(v, float), np.asarray(c, float)
    out = reference_colours(v, c, poly) if len(poly) else np.zeros((0, 3))
    for k, p in enumerate(np.asarray(poly, float)):
        i = _kept(v, p)
        e = _on_edge(v, p) if i is None else None
        if e is not None:
            out[k] = t_of(c[e[0]], c[(e[0] + 1) % 3], e[1], v[e[0]], v[(e[0] + 1) % 3])
    return out


def _nearest_vertex(v, c, poly):
    v, c = np.asarray(v, float), np.asarray(c, float)
    p = np.asarray(poly, float).reshape(-1, 4)
    return c[np.argmin(((p[:, None, :] - v[None]) ** 2).sum(-1), axis=1)] if len(p) else None


_WHY = (
    "a point of the triangle takes its colour as its position is made of v1, v2, v3 in "
    "clip space: along an edge, colour_a + t·(colour_b − colour_a) at the position's own t"
)


def _ndc_t(ca, cb, t, a, b):
    s = (a[2] / a[3] + 1) / (a[2] / a[3] - b[2] / b[3]) if a[3] and b[3] else np.nan
    return ca + s * (cb - ca)


def _right(v, c, poly):
    return reference_colours(v, c, poly) if len(poly) else None


def _inside_end(ca, cb, t, a, b):
    return ca if a[2] + a[3] >= 0 else cb


def _over_w(v, c, poly):
    """The right weights divided by each vertex's w and normalised: lesson 04's correction
    used in clip space, where there is nothing to correct."""
    v = np.asarray(v, float)
    if not len(poly) or (v[:, 3] == 0).any():
        return None
    lam = weights(v, poly) / v[:, 3]
    return (lam / lam.sum(axis=1, keepdims=True)) @ np.asarray(c, float)


def _nan_on_edge(args, expected, got) -> bool:
    """NaN (or inf) only at vertices on an edge, where the opposite vertex's weight is 0: an
    unsigned area from a Gram determinant that rounding made negative (r496 M9), or a 0/0."""
    v, _, poly = (np.asarray(a, float) for a in args)
    g = np.asarray(got, float).reshape(-1, 3)
    if g.shape != expected.shape:
        return False
    nan = [k for k in range(len(g)) if not np.isfinite(g[k]).all()]
    bad = _bad_rows(expected, g)
    edges = [None if _kept(v, poly[k]) is not None else _on_edge(v, poly[k]) for k in nan]
    # (ends that share a coordinate: a t from that coordinate is 0/0 there, named apart)
    return (
        bool(nan)
        and set(bad) == set(nan)
        and all(e is not None and not _shared(v[e[0]], v[(e[0] + 1) % 3]) for e in edges)
    )


def _nan_on_edge_words(args, expected, got) -> str:
    v, _, poly = (np.asarray(a, float) for a in args)
    g = np.asarray(got, float).reshape(-1, 3)
    k = next(k for k in range(len(g)) if not np.isfinite(g[k]).all())
    i = _on_edge(v, poly[k])[0]
    return (
        f"polygon[{k}] lies on the edge v{i + 1}→v{(i + 1) % 3 + 1}, where v{(i + 2) % 3 + 1}'s "
        f"weight is 0, and your colour there is {vec(g[k])}: NaN only where a weight is 0. A "
        "square root of a number rounding made slightly negative (an unsigned area, "
        "√(|e1|²|e2|² − (e1·e2)²)?), or a 0/0 there? Clamp at 0, or solve for signed weights"
    )


_PERMS = ((2, 1, 0), (1, 2, 0), (2, 0, 1), (1, 0, 2), (0, 2, 1))


def _permuted_colours(args, expected, got) -> tuple | None:
    """The permutation of the colours' rows the answer's weights took (r496 H2, H4), or None."""
    v, c, poly = (np.asarray(a, float) for a in args)
    g = np.asarray(got, float).reshape(-1, 3)
    if not len(poly) or g.shape != expected.shape:
        return None
    lam = weights(v, poly)
    return next((p for p in _PERMS if all_close(g, lam @ c[list(p)], COLOUR_TOL)), None)


def _permuted_words(args, expected, got) -> str:
    p = _permuted_colours(args, expected, got)
    took = ", ".join(f"v{i + 1}'s weight with colour {j + 1}" for i, j in enumerate(p) if i != j)
    rev = " (the colours in reverse order?)" if p == (2, 1, 0) else ""
    return (
        f"your weights are right, but they took the wrong colours: {took}{rev}. Row i of "
        "`colours` is vi's colour, and vi's weight goes with it"
    )


def _one_colour(args, expected, got) -> int | None:
    """The vertex whose colour every row of the answer is (r496 H3), or None."""
    c = np.asarray(args[1], float)
    g = np.asarray(got, float).reshape(-1, 3)
    if len(g) < 2 or g.shape != expected.shape:
        return None
    return next((i for i in range(3) if all(all_close(r, c[i], COLOUR_TOL) for r in g)), None)


def _grey(args, expected, got) -> bool:
    """Every row the same colour, none of the vertices' (r507 H1: a placeholder such as
    ``np.full((n, 3), 0.5)``), where the right colours differ."""
    c = np.asarray(args[1], float)
    g = np.asarray(got, float).reshape(-1, 3)
    return (len(g) > 1 and g.shape == expected.shape and np.isfinite(g).all()
            and all(all_close(r, g[0], COLOUR_TOL) for r in g)
            and not any(all_close(g[0], ci, COLOUR_TOL) for ci in c)
            and not all(all_close(e, expected[0], COLOUR_TOL) for e in expected))  # fmt: skip


def _grey_words(args, expected, got) -> str:
    g = np.asarray(got, float).reshape(-1, 3)
    open_here = _open_words(args)
    if open_here:  # r507 H2: a fallback where the student's system was singular?
        return (
            f"every vertex of your polygon has the colour {vec(g[0])} here, none of the "
            "triangle's colours: a placeholder left in, or a fallback of yours where your "
            f"system was singular? On this triangle these leave the weights open: {open_here}. "
            "Which equations fix the weights on every triangle?"
        )
    return (
        f"every vertex of your polygon has the colour {vec(g[0])}, whatever its position, "
        f"and it is none of the triangle's colours: a placeholder left in? {_WHY}"
    )


def _over_w_times_w(v, c, poly):
    """Colours divided by w, interpolated with the right weights, times the vertex's w
    (r507 H4: lesson 04's perspective-correct attributes, in clip space); None where w = 0."""
    v, p = np.asarray(v, float), np.asarray(poly, float).reshape(-1, 4)
    if not len(p) or (v[:, 3] == 0).any():
        return None
    return (weights(v, p) @ (np.asarray(c, float) / v[:, 3:])) * p[:, 3:]


def _lstsq_of(a, b):
    with np.errstate(all="ignore"):
        return np.linalg.lstsq(a, b, rcond=None)[0]


def _sum_row_zero(v, c, poly):
    """The polygon's Σλ row written as 0 (r507 H6): the weights of a point summing to 0."""
    p = np.asarray(poly, float).reshape(-1, 4)
    if not len(p):
        return None
    a = np.vstack([np.asarray(v, float).T, np.ones(3)])
    return _lstsq_of(a, np.vstack([p.T, np.zeros(len(p))])).T @ np.asarray(c, float)


def _lstsq_swapped(v, c, poly):
    """``lstsq(B, A)`` for ``lstsq(A, B)`` (r507 H7): the polygon fitted to the triangle."""
    p = np.asarray(poly, float).reshape(-1, 4)
    if not len(p):
        return None
    a = np.vstack([np.asarray(v, float).T, np.ones(3)])
    return _lstsq_of(np.vstack([p.T, np.ones(len(p))]), a) @ np.asarray(c, float)


def _one_colour_words(args, expected, got) -> str:
    i = _one_colour(args, expected, got) + 1
    return (
        f"every vertex of your polygon has v{i}'s colour, whatever its position: only a kept "
        f"vertex keeps its own colour; {_WHY}"
    )


def _over_w_raw(v, c, poly):
    """The screen's weights divided by w, not renormalised (r496 H6), None where w = 0."""
    lam = _screen(v, poly, strict=False)
    if lam is None or not len(poly):
        return None
    with np.errstate(all="ignore"):
        return (lam / np.asarray(v, float)[:, 3]) @ np.asarray(c, float)


def _rounded(v, c, poly, how):
    right = _right(v, c, poly)
    return None if right is None else how(right)


COLOUR_MISTAKES = [
    Mistake("colours all zero", "every colour you return is (0, 0, 0), whatever the case: a "
            "placeholder left in?", gives=lambda v, c, p: np.zeros((len(p), 3)) if len(p) else None),
    Mistake("float32 vertices compared exactly", _float32_kept_words, fits=_float32_kept),
    Mistake("kept by a loose tolerance", _loose_kept_words,
            fits=lambda a, e, g: _loose_kept(a, e, g) is not None),
    Mistake("colour from the screen", _via_screen_words,
            fits=lambda a, e, g: _via_screen(a, e, g) is not None),
    Mistake("colour t from one coordinate", _t_one_coordinate_words,
            fits=lambda a, e, g: _t_one_coordinate(a, e, g) is not None),
    Mistake("new vertices on the near plane only", _near_only_words, fits=_near_only),
    Mistake("weights from some equations", _undetermined_words,
            fits=lambda a, e, g: _undetermined(a, e, g) is not None),
    Mistake("NaN where a weight is 0", _nan_on_edge_words, fits=_nan_on_edge),
    Mistake("NaN where some equations are open", _nan_open_words, fits=_nan_open),
    Mistake("colours of other vertices", _permuted_words,
            fits=lambda a, e, g: _permuted_colours(a, e, g) is not None),
    Mistake("one colour for all", _one_colour_words,
            fits=lambda a, e, g: _one_colour(a, e, g) is not None),
    Mistake("one grey for all", _grey_words, fits=_grey),
    Mistake("colours are positions", "your colours are the polygon's x, y, z: row k is the "
            "colour of polygon[k], made of the three colours as polygon[k] is made of v1, v2, v3",
            gives=lambda v, c, p: np.asarray(p, float).reshape(-1, 4)[:, :3] if len(p) else None),
    Mistake("colour over w, times w", "you divided the colours by w, interpolated them and "
            "multiplied by the vertex's w (lesson 04's perspective-correct attributes, for the "
            f"screen); the clipper works in clip space, before any divide: {_WHY}",
            gives=_over_w_times_w),
    Mistake("sum row zero", "your weights were solved with the polygon's row of Σλ set to 0, "
            "not 1: every point of the triangle has λ1 + λ2 + λ3 = 1, so its row of ones is "
            "[p; 1], like the triangle's", gives=_sum_row_zero),
    Mistake("lstsq's arguments swapped", "you solved the triangle's vertices from the polygon's "
            "(`lstsq(B, A)`): the unknowns are the weights λ of each polygon vertex, A·λ = B with A "
            "the triangle's [v; 1] and B the polygon's [p; 1]", gives=_lstsq_swapped),
    Mistake("weights divided by w, not renormalised", "you divided the screen's weights by "
            "each vertex's w (lesson 04's correction) but did not divide them by their sum "
            f"again, and here there is nothing to correct anyway: {_WHY}", gives=_over_w_raw),
    Mistake("colour after the divide", "you took the weights of the projected point on the "
            "screen (x/w, y/w) as they are: after the divide equal fractions on the screen "
            f"are not equal fractions of the triangle (lesson 04); {_WHY}",
            gives=_after_divide),
    Mistake("colour t after the divide", "your new vertex takes the colour at the fraction "
            f"where z/w reaches −1, found after the divide: {_WHY}",
            gives=lambda v, c, p: _edge_t(v, c, p, _ndc_t)),
    Mistake("weights divided by w", "you divided the weights by each vertex's w and "
            "normalised them (lesson 04's perspective correction): that turns fractions on the "
            f"screen into fractions in clip space; here there is nothing to correct: {_WHY}",
            gives=_over_w),
    Mistake("colours in own order", "your colours are in the order of your own clip, not of "
            "`polygon`: row k is the colour of polygon[k], and the clipper may start anywhere "
            "and run either way", gives=_own_order),
    Mistake("colour t from the other end", f"you took the colour at 1 − t: {_WHY}",
            gives=lambda v, c, p: _edge_t(v, c, p, lambda ca, cb, t, a, b: ca + (1 - t) * (cb - ca))),
    Mistake("colour halfway", f"you gave a new vertex the colour halfway along its edge: {_WHY}",
            gives=lambda v, c, p: _edge_t(v, c, p, lambda ca, cb, t, a, b: (ca + cb) / 2)),
    Mistake("colour of the inside end", "your new vertex keeps the colour of its edge's "
            f"inside end: {_WHY}", gives=lambda v, c, p: _edge_t(v, c, p, _inside_end)),
    Mistake("mean colour", "your new vertex takes the mean of the triangle's three colours: "
            f"{_WHY}", gives=lambda v, c, p: _edge_t(
                v, c, p, lambda ca, cb, t, a, b, c=c: np.mean(np.asarray(c, float), axis=0))),
    Mistake("colour of the nearest vertex", "each vertex takes the colour of the triangle's "
            f"nearest vertex: only a kept vertex keeps its own colour; {_WHY}",
            gives=_nearest_vertex),
    Mistake("colours by row number", "your row k takes colours[k % 3], but the polygon's rows "
            "are not the triangle's: find which point of the triangle each row is",
            gives=lambda v, c, p: np.asarray(c, float)[np.arange(len(p)) % 3] if len(p) else None),
    Mistake("colours transposed", "you multiplied the weights by the transposed colours "
            "(a column of `colours` per vertex): row i of `colours` is vi's (r, g, b)",
            gives=lambda v, c, p: None if not len(p) else weights(v, p) @ np.asarray(c, float).T),
    Mistake("weights returned", "you returned the weights (λ1, λ2, λ3), not the colour they "
            "make: colour = λ1·colour1 + λ2·colour2 + λ3·colour3",
            gives=lambda v, c, p: None if not len(p) else weights(v, p)),
    Mistake("colours times 255", "your colours are 255 times the right ones: colours here run "
            "from 0 to 1, as given", gives=lambda v, c, p: _rounded(v, c, p, lambda x: x * 255)),
    Mistake("colours rounded to 8 bits", "your colours are rounded to 8 bits (multiples of "
            "1/255): return them as floats; the clipper interpolates in full precision",
            gives=lambda v, c, p: _rounded(v, c, p, lambda x: np.round(x * 255) / 255)),
    Mistake("colours cut to 8 bits", "your colours are cut down to 8 bits (multiples of "
            "1/255, rounded down: `astype(np.uint8)` truncates): return them as floats; the "
            "clipper interpolates in full precision",
            gives=lambda v, c, p: _rounded(v, c, p, lambda x: np.floor(x * 255) / 255)),
    Mistake("weights in float16", "your weights are rounded to 16-bit floats (half precision, "
            "11 significant bits) before they make the colour: keep them in float64 (or the "
            "precision you were given)", gives=lambda v, c, p: None if not len(p) else
            weights(v, p).astype(np.float16).astype(float) @ np.asarray(c, float)),
    Mistake("colours in float16", "your colours are rounded to 16-bit floats (half precision, "
            "11 significant bits): keep them in the precision you were given",
            gives=lambda v, c, p: _rounded(v, c, p, lambda x: x.astype(np.float16).astype(float))),
]  # fmt: skip


def _draw(ax, case, got):
    """4.2's figure of the polygon, each vertex a disc of its right colour, yours a square
    inside it (a wrong colour is a square of another colour)."""
    from .drawing import clip_panels, draw_clip

    (v, colours, poly), expected = case[1], case[2]
    poly = np.asarray(poly, float)
    artists = draw_clip(ax, v, poly, None if got is None else poly, colours)
    g = None if got is None else np.asarray(got, float).reshape(-1, 3)
    for k, panel in enumerate(clip_panels(ax)):
        for c, marker, size in [(expected, "o", 360), *([(g, "s", 70)] if g is not None else [])]:
            if len(poly) and c.shape == (len(poly), 3) and np.isfinite(c).all():
                artists.append(panel.scatter(poly[:, k], poly[:, 2] + poly[:, 3], s=size,
                                             marker=marker, c=np.clip(c, 0, 1),
                                             edgecolors="black", zorder=5))  # fmt: skip
    legend = clip_panels(ax)[-1].get_legend()
    for text in legend.get_texts() if legend is not None else []:  # the polygon is given
        text.set_text(
            {"clipped (expected)": "the polygon handed in", "yours": "(the same)"}.get(
                text.get_text(), text.get_text()
            )
        )
    panel = clip_panels(ax)[0]
    artists.append(panel.set_xlabel(f"{panel.get_xlabel()}\ndiscs: the right colours,\n"
                                    "squares: yours"))  # fmt: skip
    return artists


def _call(fn, args):
    """The student's colours, numpy's SVD solvers refusing ±inf meanwhile (r507 T1: on the
    w = 0 case, lesson 04's weights by ``np.linalg.lstsq`` would never return)."""
    with refusing_inf():
        value = fn(*args)
    return as_colours(value)


CLIPPED_COLOURS = Exercise(
    "clipped_colours", colour_cases, as_colours, _same, explain_colours, _rule, COLOUR_MISTAKES,
    answers=(PackageAnswer(clip_polygon), DISTANCES), draw=_draw, raised_words=_raised,
    call=_call, reference=("teachraster.exercises.depth_clipping",),
)  # fmt: skip
