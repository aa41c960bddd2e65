"""Exercises ``edge_function(a, b, p)`` (lesson 01) and ``split_point(v)`` (lesson 02).

Expected values come from the core (:func:`~teachraster.core.edges.edge_function`,
:func:`~teachraster.core.span_tables.split_point`). Each mistake in the tables is a wrong
solution the checker runs itself: it is named only where it gives the student's answer
(:mod:`.diagnosis`).
"""

from __future__ import annotations

import re

import numpy as np

from ..core.edges import edge_function
from ..core.span_tables import split_point
from .answers import as_number
from .cases import drawn_coverage, drawn_rng, proper_triangles, sorted_by_y
from .exercise import Exercise, Mistake, PackageAnswer
from .scalars import centre_near, factor, num, vec
from .tolerance import close


# -- edge_function ----------------------------------------------------------------------------
def edge_function_cases():
    out = []
    drawn = [(c.label, c.triangles[0]) for c in drawn_coverage()]  # r46 X1: differ every run
    for n, (label, xy) in enumerate(proper_triangles() + drawn):
        k = n % 3
        a, b = xy[k], xy[(k + 1) % 3]
        p = centre_near(xy.mean(axis=0)) if n % 2 else xy[(k + 2) % 3]
        out.append(
            (f"{label}, edge v{k + 1}→v{(k + 1) % 3 + 1}", (a, b, p), float(edge_function(a, b, p)))
        )
    return out + [_long_edge_case(drawn_rng())]


def _float32_products(a, b, p) -> float:
    """E with its two products rounded to float32 (the differences are exact): what a
    student's float32 arithmetic gives."""
    f = np.float32
    return float(f(b[0] - a[0]) * f(p[1] - a[1]) - f(b[1] - a[1]) * f(p[0] - a[0]))


def _long_edge_case(rng) -> tuple:
    """A long edge (thousands of px, vertices on the 1/256-px grid near the origin) and a
    centre a few px from it, drawn afresh: its products need about 40 bits, exact in float64
    and rounded in float32, so float32 arithmetic misses E by far more than the tolerance
    (r46 E1: float32 differences passed every case, whose differences were all short)."""
    while True:
        a = np.rint(rng.uniform(0, 64, 2) * 256) / 256
        b = a + np.rint(rng.uniform(3000, 4000, 2) * 256) / 256
        t = rng.uniform(0.3, 0.7)
        p = np.floor(a + t * (b - a)) + (0.5, 0.5) + (rng.integers(-3, 4), 0)
        e = _e(a, b, p)
        if abs(_float32_products(a, b, p) - e) > 1e-3:  # far past close()'s 1e-9 of E
            return (f"a long edge drawn for this check, {num(float(np.hypot(*(b - a))))} px, "
                    "a centre near it", (a, b, p), e)  # fmt: skip


def _e(a, b, p) -> float:
    return float(edge_function(a, b, p))


def explain_edge(args, expected, got) -> str:
    a, b, p = args
    return (
        f"for a={vec(a)}, b={vec(b)}, p={vec(p)}, E = (b.x − a.x)(p.y − a.y) − (b.y − a.y)(p.x − "
        f"a.x) = {factor(b[0] - a[0])}·{factor(p[1] - a[1])} − {factor(b[1] - a[1])}·"
        f"{factor(p[0] - a[0])} = {num(expected, got)}; yours is {num(got, expected)}"
    )


EDGE_MISTAKES = [
    Mistake(
        "abs",
        "yours is |E|, but E is negative here: p lies to the left of a→b as seen on screen (y "
        "down). E's sign carries the side (the interior is where all three E share the sign of "
        "E(v1, v2, v3)): return E itself, not abs(E) (that is right only where E ≥ 0)",
        gives=lambda a, b, p: abs(_e(a, b, p)),
    ),
    Mistake(
        "negated",
        "yours is −E: you have the two products (or a and b) the other way round",
        gives=lambda a, b, p: -_e(a, b, p),
    ),
    Mistake(
        "products added",
        "you added the two products; E subtracts the second from the first",
        gives=lambda a, b, p: (b[0] - a[0]) * (p[1] - a[1]) + (b[1] - a[1]) * (p[0] - a[0]),
    ),
    Mistake(
        "halved",
        "yours is E/2, the triangle's area; the edge function is E itself (twice the signed "
        "area), with no ½",
        gives=lambda a, b, p: _e(a, b, p) / 2,
    ),
    # r420 H6 and H1: a distance, and p measured from two vertices (the covers check sends
    # both here)
    Mistake(
        "divided by the edge's length",
        "yours is E divided by the edge's length |b − a|: a signed distance from the edge's "
        "line. The edge function is E itself, twice the signed area of a, b, p, with no "
        "division (its sign and its zero are the same, but its value is not)",
        gives=lambda a, b, p: _e(a, b, p) / float(np.hypot(b[0] - a[0], b[1] - a[1])),
    ),
    Mistake(
        "two anchors",
        "you measured p from b in x (p.x − b.x) but from a in y (p.y − a.y): that adds "
        "(b.x − a.x)(b.y − a.y) to E. Take both differences from the same vertex a",
        gives=lambda a, b, p: (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - b[0]),
    ),
    Mistake(
        "truncated to an integer",
        "yours is E truncated to a whole number (int(), or an integer array?): E is a float, "
        "and its fraction decides the side of a point near the edge",
        gives=lambda a, b, p: float(int(_e(a, b, p))),
    ),
    # r453 H9: the sign alone (np.sign(E)) was told its value only
    Mistake(
        "sign only",
        "yours is E's sign alone (np.sign, or ±1): the edge function is the number E itself, "
        "twice the signed area of a, b, p; its size is used too (a barycentric is "
        "E / E(v1, v2, v3))",
        gives=lambda a, b, p: float(np.sign(_e(a, b, p))),
    ),
    Mistake(
        "x and y swapped",
        "x and y are swapped: a point is (x, y) = (p[0], p[1]); E = (b.x − a.x)(p.y − a.y) − "
        "(b.y − a.y)(p.x − a.x)",
        gives=lambda a, b, p: _e(np.asarray(a)[::-1], np.asarray(b)[::-1], np.asarray(p)[::-1]),
    ),
]


def edge_float32(args) -> float:
    """Float32 rounding of E: the inputs' rounding (far from the origin) times the edge."""
    a, b, p = (np.asarray(x, dtype=float) for x in args)
    far = float(np.abs([a, b, p]).max())
    extent = float(np.abs([b - a, p - a]).max())
    return far * extent + abs(_e(a, b, p))


def _draw_edge(ax, case, got):
    from .drawing import draw_values

    return draw_values(ax, ["E(a, b, p)"], [case[2]], None if got is None else [got])


#: r85 01: every failure printed E's formula, factor by factor, the answer of 1.1: the first
#: failing tries print E's value only (the full words come after two different answers).
EDGE_HINTS = (
    (re.compile(r"E = \(b\.x − a\.x\)\(p\.y − a\.y\) − \(b\.y − a\.y\)\(p\.x − a\.x\) = .+? = "),
     "E = "),
    (re.compile(r"; E = \(b\.x − a\.x\)\(p\.y − a\.y\) − \(b\.y − a\.y\)\(p\.x − a\.x\)$"), ""),
)  # fmt: skip

EDGE_FUNCTION = Exercise(
    "edge_function", edge_function_cases, as_number, lambda g, e, a: close(g, e),
    explain_edge, lambda *a: "", EDGE_MISTAKES, float32=edge_float32,
    answers=(PackageAnswer(edge_function),), draw=_draw_edge, hints=EDGE_HINTS,
)  # fmt: skip


# -- split_point ------------------------------------------------------------------------------
def split_point_cases():
    v = np.array([[2.5, 1.5], [9.5, 4.5], [4.5, 12.5]])  # issue 10's example
    out = [("a long edge to the left", (v,), split_point(v))]
    for label, xy in proper_triangles():
        v = sorted_by_y(xy)
        if v[0, 1] != v[2, 1]:
            out.append((label, (v,), split_point(v)))
    return out


def explain_split(args, expected, got) -> str:
    (v,) = args
    points = ", ".join(vec(p) for p in v)
    return (
        f"your u4 is {num(got, expected)} for points 1, 2, 3 = {points}; the long edge meets "
        f"v = {num(v[1][1])} at u = {num(expected, got)}"
    )


def _points(v):
    return (float(c) for p in np.asarray(v, dtype=float) for c in p)


def _fraction_of(f):
    """A split-point mistake written as ``f(u1, v1, u2, v2, u3, v3)``; None where undefined."""

    def gives(v):
        with np.errstate(divide="ignore", invalid="ignore"):
            value = f(*_points(v))
        return value if np.isfinite(value) else None

    return gives


SPLIT_MISTAKES = [
    Mistake("without u1", " (did you add u1?)",
            gives=_fraction_of(lambda u1, v1, u2, v2, u3, v3: (v2 - v1) / (v3 - v1) * (u3 - u1))),
    Mistake("short edge", ": u4 lies on the long edge from point 1 to point 3, so use u3 − u1, "
            "not u2 − u1",
            gives=_fraction_of(lambda u1, v1, u2, v2, u3, v3: u1 + (v2 - v1) / (v3 - v1) * (u2 - u1))),
    Mistake("inverse", ": the fraction is (v2 − v1)/(v3 − v1), not its inverse",
            gives=_fraction_of(lambda u1, v1, u2, v2, u3, v3: u1 + (v3 - v1) / (v2 - v1) * (u3 - u1))),
    Mistake("from point 3", ": the fraction (v2 − v1)/(v3 − v1) is measured from point 1: start "
            "at u1 and add it times (u3 − u1)",
            gives=_fraction_of(lambda u1, v1, u2, v2, u3, v3: u3 - (v2 - v1) / (v3 - v1) * (u3 - u1))),
    Mistake("u and v swapped", ": a point is (u, v) = (x, y), u across and v down; you took "
            "them the other way round (u4 is the u where the long edge reaches height v2)",
            gives=_fraction_of(lambda u1, v1, u2, v2, u3, v3: v1 + (u2 - u1) / (u3 - u1) * (v3 - v1))),
    Mistake("midpoint", ": that is the long edge's midpoint; u4 is where it reaches v2, at the "
            "fraction (v2 − v1)/(v3 − v1) of the way",
            gives=_fraction_of(lambda u1, v1, u2, v2, u3, v3: (u1 + u3) / 2)),
]  # fmt: skip


def _split_rule(args, expected, got) -> str:
    return " = (v2 − v1)/(v3 − v1)·(u3 − u1) + u1 (similar triangles)"


def split_float32(args) -> float:
    return 4 * float(np.abs(args[0]).max())


def _draw_split(ax, case, got):
    from .drawing import draw_split

    return draw_split(ax, case[1][0], case[2], got)


SPLIT_POINT = Exercise(
    "split_point", split_point_cases, as_number, lambda g, e, a: close(g, e), explain_split,
    _split_rule, SPLIT_MISTAKES, float32=split_float32, answers=(PackageAnswer(split_point),),
    draw=_draw_split,
)  # fmt: skip
