"""Coverage by the rules and by the typical wrong rules; a wrong pixel explained by the rules.

The expected coverage is the core's (:func:`teachraster.rasterize`: snapped edge functions and
the one top-left rule). A mistake is reproduced by :func:`covered` with a knob turned: which
kinds of edge own a centre lying exactly on them (:data:`TOP_LEFT` is the rule: top and left
edges; a student's rule may own every edge, none, or the bottom and right ones), which winding
is handled, where the pixel is sampled (its corner instead of its centre), how the vertices are
rounded. Kinds of edges come from the core's :func:`~teachraster.core.edges.top_left_edges`;
edge functions are the core's :func:`~teachraster.core.edges.edge_function` on snapped
vertices (exact on the 1/256 grid). A wrong pixel is explained from the exact edge functions at
its centre (:func:`explain_pixel`): on an edge (which kind, and what the top-left rule says),
on a vertex, outside an edge, or strictly inside.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from ..core.edges import edge_function, passes, top_left_edges
from ..core.fill import rasterize
from ..core.snapping import snap
from ..core.triangle import Triangle
from .cases import CoverageCase
from .scalars import num

#: The kinds of edge, and those the top-left rule lets own a centre lying exactly on them.
KINDS = ("top", "bottom", "left", "right")
TOP_LEFT = frozenset({"top", "left"})


def fmt(x: float) -> str:
    """A position exactly (it is on the 1/256 grid), other numbers with 3 decimals or more.

    >>> fmt(5.5), fmt(100000.00390625), fmt(2.5e-05)
    ('5.5', '100000.00390625', '2.5e-05')
    """
    return num(x)


def point(p) -> str:
    return "(" + ", ".join(fmt(v) for v in p) + ")"


def area2(xy: np.ndarray) -> float:
    """E(v1, v2, v3): twice the signed area (exact on the 1/256 grid)."""
    return float(edge_function(xy[0], xy[1], xy[2]))


def local(case: CoverageCase, xy: np.ndarray) -> np.ndarray:
    return xy - np.array(case.origin, dtype=float)


def expected_coverage(case: CoverageCase, xy: np.ndarray) -> np.ndarray:
    """The core's coverage of one triangle on the case's window."""
    w, h = case.size
    return rasterize(Triangle(local(case, xy)), w, h).coverage


def kind_of(a, b) -> str:
    """ "top", "left", "bottom" or "right" for the directed edge a→b, interior on its
    positive side (y down), by the core's top-left test."""
    owns = bool(top_left_edges(np.asarray(a, dtype=float), np.asarray(b, dtype=float)))
    if a[1] == b[1]:
        return "top" if owns else "bottom"
    return "left" if owns else "right"


def edge_kind(xy: np.ndarray, k: int) -> str:
    """The kind of edge v_k → v_{k+1} of a triangle given in any winding."""
    a, b = xy[k], xy[(k + 1) % 3]
    if area2(xy) < 0:  # the interior is on the negative side: the rule sees the edge b -> a
        a, b = b, a
    return kind_of(a, b)


def edge_name(k: int) -> str:
    return f"v{k + 1}→v{(k + 1) % 3 + 1}"


def ruled_edge(xy: np.ndarray, k: int, note: bool = True) -> str:
    """Edge k named in the direction the top-left rule walks it (r273 12-2: a tie on edge
    v1→v2 of a counter-clockwise triangle sent a student who checks by hand to the opposite
    kind): v1→v2 where the triangle runs clockwise on screen, else v2→v1, with the
    conventions' name E21 (``note``)."""
    if area2(xy) >= 0:
        return edge_name(k)
    a, b = (k + 1) % 3 + 1, k + 1
    return f"v{a}→v{b} (E{a}{b}: this triangle runs the other way)" if note else f"v{a}→v{b}"


# -- coverage under a rule, right or wrong ------------------------------------------------------
def covered(xy, points, owns=TOP_LEFT, winding: str = "both", vertices: str = "snapped"):
    """Which ``points`` (n, 2) triangle ``xy`` covers under a rule, right or wrong.

    ``owns`` is the set of edge kinds that own a point exactly on them (:data:`TOP_LEFT`);
    ``winding`` "both" (the rule), "clockwise only" or "counter-clockwise only" (a student
    testing E ≥ 0, or E ≤ 0, without orienting the triangle: the other winding covers
    nothing); ``vertices`` "snapped" (to 1/256 px, the rule), "rounded" (to whole pixels),
    "truncated" (int()) or "exact" (as given, not snapped).

    >>> xy = np.array([[0.0, 0], [4, 0], [0, 4]])   # on its top, left and right edge:
    >>> covered(xy, np.array([[1.0, 0], [0, 1], [2, 2]])).tolist()
    [True, True, False]
    >>> covered(xy, np.array([[1.0, 0], [2, 2]]), owns=frozenset(KINDS)).tolist()
    [True, True]
    """
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    return _apply(_edge_data(np.asarray(xy, dtype=float), points, vertices), owns, winding)


def _edge_data(xy: np.ndarray, points: np.ndarray, vertices: str):
    """(E of each oriented edge at the points (3, n), the edges' kinds, the signed area)."""
    v = MOVES.get(vertices, snap)(xy)
    area = float(edge_function(v[0], v[1], v[2]))
    if area < 0:
        v = v[[0, 2, 1]]
    e = np.array([edge_function(v[k], v[(k + 1) % 3], points) for k in range(3)])
    return e, tuple(kind_of(v[k], v[(k + 1) % 3]) for k in range(3)), area, v


#: How a student may move the vertices before testing ("snapped" is the rule): r347 3 adds
#: "centred", each vertex moved to the nearest pixel centre (round(v - 0.5) + 0.5).
MOVES = {
    "rounded": np.round,
    "truncated": np.trunc,
    "exact": np.asarray,
    "centred": lambda v: np.round(np.asarray(v, dtype=float) - 0.5) + 0.5,
}


def _apply(data, owns, winding: str, skip: int | None = None) -> np.ndarray:
    """``owns``: the kinds of edge that own their ties, or ``owns(a, b) -> bool`` on the
    oriented edge a→b (a student's own tie test, r347 3: ``dy < 0 or dx > 0``); ``skip``: an
    oriented edge never tested (r505 H9: the loop stops before v3→v1)."""
    e, kinds, area, v = data
    n = e.shape[1]
    wrong_side = (winding == "clockwise only" and area < 0) or (
        winding == "counter-clockwise only" and area > 0
    )
    if area == 0 or wrong_side:
        return np.zeros(n, dtype=bool)
    inside = np.ones(n, dtype=bool)
    for k in range(3):
        if k == skip:
            continue
        own = owns(v[k], v[(k + 1) % 3]) if callable(owns) else kinds[k] in owns
        inside &= passes(e[k], bool(own))
    return inside


@lru_cache(maxsize=512)
def _cached_edges(xy: bytes, origin: tuple, size: tuple, at: str, swap, vertices: str):
    w, h = size
    rows, cols = np.indices((h, w))
    # "corners": (j, i); "x at corners" / "y at corners": half a pixel off in one axis (r64 01-1)
    ox = 0.0 if at in ("corners", "x at corners") else 0.5
    oy = 0.0 if at in ("corners", "y at corners") else 0.5
    if at == "past p":  # r273 12-3: half a pixel added to p, a centre, again (j + 1, i + 1)
        ox = oy = 1.0
    if isinstance(at, tuple):  # r347 2: any other sampling point (j + ox, i + oy)
        ox, oy = at
    points = np.stack([cols + origin[0] + ox, rows + origin[1] + oy], axis=-1)
    points = points.reshape(-1, 2)
    v = np.frombuffer(xy, dtype=float).reshape(3, 2)
    if swap:  # "points": only p's x and y swapped (r273 12-3), the vertices as given
        v, points = (v if swap == "points" else v[:, ::-1]), points[:, ::-1]
    return _edge_data(v, points, vertices)


def rule_image(
    case: CoverageCase, xy, *, at="centres", swap=False, vertices="snapped", **rule
) -> np.ndarray:
    """(h, w) coverage of one triangle on the case's window under a rule (:func:`covered`);
    ``at="corners"`` samples pixel (i, j) at (j, i) instead of its centre ("x at corners":
    at (j, i + 0.5), "y at corners": at (j + 0.5, i), "past p": at (j + 1, i + 1)), ``swap``
    swaps x and y in the vertices and the points ("points": in the points alone, a student's
    p[1], p[0])."""
    w, h = case.size
    key = np.ascontiguousarray(xy, dtype=float).tobytes()
    data = _cached_edges(key, tuple(case.origin), (w, h), at, swap, vertices)
    owns, winding = rule.get("owns", TOP_LEFT), rule.get("winding", "both")
    return _apply(data, owns, winding, rule.get("skip")).reshape(h, w)


def rule_images(case: CoverageCase, **rule) -> np.ndarray:
    """(n, h, w): :func:`rule_image` of every triangle of the case."""
    return np.array([rule_image(case, xy, **rule) for xy in case.triangles])


def owns_words(owns) -> str:
    """Words for a tie rule given by the kinds of edges that own the centres on them."""
    owns = frozenset(owns)
    named = {
        frozenset(): "you cover no centre on an edge (E > 0 on all three edges): a centre on "
        "an edge shared by two triangles is then covered by neither",
        frozenset(KINDS): "you cover every centre on an edge (E ≥ 0 on all three edges): a "
        "centre on an edge shared by two triangles is then covered twice",
        frozenset({"bottom", "right"}): "your coverage follows a bottom-right rule (centres on "
        "bottom and right edges covered, on top and left edges left out)",
        frozenset({"top", "right"}): "your coverage follows a top-right rule (centres on top "
        "and right edges covered, on bottom and left edges left out)",
        frozenset({"bottom", "left"}): "your coverage follows a bottom-left rule (centres on "
        "bottom and left edges covered, on top and right edges left out)",
    }
    text = named.get(owns)
    if text is None:
        yes = " and ".join(k for k in KINDS if k in owns) or "no"
        no = " and ".join(k for k in KINDS if k not in owns) or "no"
        text = f"you cover the centres lying on {yes} edges and leave out those on {no} edges"
    if owns and owns != frozenset(KINDS):
        text += ": the conventions use the top-left rule (top and left edges own their centres)"
    return text


def owns_kind(owns) -> str:
    """A few words for a tie rule: "bottom-right rule", "no edge owns its centres"..."""
    owns = frozenset(owns)
    if not owns:
        return "no edge owns its centres"
    if owns == frozenset(KINDS):
        return "every edge owns its centres"
    return "-".join(k for k in KINDS if k in owns) + " rule"


def owns_variants() -> list[frozenset]:
    """Every wrong tie rule, the named ones first."""
    first = [frozenset(), frozenset(KINDS), frozenset({"bottom", "right"}),
             frozenset({"top", "right"}), frozenset({"bottom", "left"})]  # fmt: skip
    rest = [
        frozenset(k for bit, k in enumerate(KINDS) if n >> bit & 1)
        for n in range(16)
        if frozenset(k for bit, k in enumerate(KINDS) if n >> bit & 1) not in first
    ]
    return [o for o in first + rest if o != TOP_LEFT]


# -- one wrong pixel, explained by the rules ------------------------------------------------------
def values_at(xy: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Edge functions at centre ``c``, signed so that inside is positive (exact): for
    deciding, never for printing as E (:func:`edge_values`)."""
    s = 1.0 if area2(xy) >= 0 else -1.0
    return s * edge_values(xy, c)


def edge_values(xy: np.ndarray, c: np.ndarray) -> np.ndarray:
    """E12, E23, E31 at ``c`` as the conventions define E (exact): what the student's own
    ``edge_function`` gives, whatever the winding (r222 C: the oriented values were printed
    as E, their sign flipped for a triangle running counter-clockwise on screen)."""
    return np.array([float(edge_function(xy[k], xy[(k + 1) % 3], c)) for k in range(3)])


def interior_side(xy: np.ndarray) -> str:
    """Which sign of E the interior of ``xy`` has, and why, in words (one place for them)."""
    if area2(xy) > 0:
        return "the interior is where E > 0"
    return (
        f"this triangle runs counter-clockwise on screen, E(v1, v2, v3) = {fmt(area2(xy))} < 0, "
        "so its interior is where E < 0, and a test for E > 0 must flip the sign first or swap "
        "two vertices"
    )


def explain_pixel(xy: np.ndarray, c: np.ndarray, covered: bool) -> tuple[str, int | None, str]:
    """Why the rule covers (``covered``) or leaves out centre ``c``, the deciding edge, and the
    kind of pixel ("zero area", "outside", "on a top edge"..., "vertex", "inside")."""
    yours = "your function left it uncovered" if covered else "your function covered it"
    if area2(xy) == 0:
        return (
            f"v1, v2, v3 = {point(xy[0])}, {point(xy[1])}, {point(xy[2])} are collinear "
            f"(E(v1, v2, v3) = 0): a zero-area triangle covers nothing, not even a centre on "
            f"its line such as {point(c)}; {yours}",
            None,
            "zero area",
        )
    e, signed = values_at(xy, c), edge_values(xy, c)
    zeros = [k for k in range(3) if e[k] == 0]
    if (e < 0).any():
        k = int(np.argmin(e))
        return (
            f"centre {point(c)} is outside edge {edge_name(k)} (E = {fmt(signed[k])} px²: "
            f"{interior_side(xy)}): it is not covered; {yours}",
            k,
            "outside",
        )
    if len(zeros) == 1:
        k = zeros[0]
        kind = edge_kind(xy, k)
        rule = "covers it" if kind in ("top", "left") else "leaves it uncovered"
        return (
            f"centre {point(c)} lies exactly on edge {ruled_edge(xy, k)}, a {kind} edge: the "
            f"top-left rule {rule}, {yours}",
            k,
            f"on a {kind} edge",
        )
    if len(zeros) == 2:
        kinds = [f"{ruled_edge(xy, k, note=False)} ({edge_kind(xy, k)})" for k in zeros]
        return (
            f"centre {point(c)} is a vertex, on edges {kinds[0]} and {kinds[1]}: the top-left "
            f"rule covers it only when both are top or left edges; {yours}",
            zeros[0],
            "vertex",
        )
    k = int(np.argmin(e))
    sign = "positive" if area2(xy) > 0 else "negative"
    text = (
        f"centre {point(c)} is strictly inside all three edges (E = "
        f"{', '.join(fmt(v) for v in signed)} px², all {sign}: {interior_side(xy)}): it is "
        f"covered; {yours}"
    )
    return text, k, "inside"


def example_pixel(case: CoverageCase, k: int, got: np.ndarray, expected: np.ndarray):
    """((i, j), centre) of a wrong pixel of triangle ``k`` that shows the rule best: one
    exactly on a single edge (a tie), else one strictly inside, else the first. Where the
    answer covers none of the triangle's pixels (one winding handled, r114/r122 D12-3: the
    example was a tie), one strictly inside first: the tie is not the mistake there."""
    wrong = np.argwhere(got != expected)
    xy = case.triangles[k]
    centres = [np.array([case.origin[0] + j + 0.5, case.origin[1] + i + 0.5]) for i, j in wrong]
    if area2(xy) == 0:
        return tuple(wrong[0]), centres[0]
    zeros = [int((values_at(xy, c) == 0).sum()) for c in centres]
    inside = [bool((values_at(xy, c) > 0).all()) for c in centres]
    missed_all = bool(np.any(expected)) and not np.any(np.logical_and(got, expected))
    if missed_all and True in inside:
        n = inside.index(True)
    elif 0 in zeros:  # r347 2: a tie is the example only where every wrong centre is one
        n = next((m for m, z in enumerate(zeros) if z == 0 and inside[m]), zeros.index(0))
    else:
        n = zeros.index(1) if 1 in zeros else 0
    return tuple(int(v) for v in wrong[n]), centres[n]


def wrong_triangle(got, expected) -> int:
    """The first triangle of a case whose image differs (a transposed one, transposed back)."""
    for k, (g, e) in enumerate(zip(got, expected)):
        g = np.asarray(g)
        if g.shape != e.shape:
            g = g.T
        if g.shape != e.shape or not np.array_equal(g, e):
            return k
    return 0


def vertices(xy) -> str:
    """ "v1, v2, v3 = (x, y), (x, y), (x, y)": the numbers a student calls ``covers`` with."""
    return f"v1, v2, v3 = {point(xy[0])}, {point(xy[1])}, {point(xy[2])}"


def which_triangle(case: CoverageCase, k: int) -> str:
    """How an example begins: the triangle's number in a mesh and its vertices (r420 C1: a
    tie was explained with no coordinates, so a student could not call ``covers`` on it),
    but where the sentence quotes them itself (zero area)."""
    xy = case.triangles[k]
    tri = f"triangle {k}, " if len(case.triangles) > 1 else ""
    return "" if area2(xy) == 0 and not tri else f"{tri}{vertices(xy)}: "


def head(case: CoverageCase, got, expected) -> tuple[str, int, tuple, int | None]:
    """The example of a failing case: (text, triangle, pixel (i, j), deciding edge)."""
    k = wrong_triangle(got, expected)
    g, e = np.asarray(got[k]), expected[k]
    if g.shape != e.shape:
        g = g.T
    (i, j), c = example_pixel(case, k, g, e)
    xy = case.triangles[k]
    text, edge, _ = explain_pixel(xy, c, bool(e[i, j]))
    text = f"{which_triangle(case, k)}{text}"
    if case.mesh:
        times = sum(
            int(np.asarray(x if np.shape(x) == e.shape else np.asarray(x).T)[i, j]) for x in got
        )
        if times != 1:
            text += (
                f"; over this mesh your function covers {point(c)} {times} times, a watertight "
                "mesh must cover it exactly once"
            )
    missing, extra = int((e & ~g).sum()), int((g & ~e).sum())
    return f"{text} ({missing} pixel(s) missing, {extra} extra)", k, (i, j), edge


# -- what differs, when no typical mistake gives the answer (r347 2) ------------------------------
def _lines(indices, what: str, last: int) -> str:
    """ "row 0 (the first row)", "columns 3 to 7" ... for the sorted distinct ``indices``."""
    lo, hi = int(indices[0]), int(indices[-1])
    if lo == hi:
        side = " (the first)" if lo == 0 else (" (the last)" if lo == last else "")
        return f"{what} {lo}{side}"
    return f"{what}s {lo} to {hi}"


def centre_values(case: CoverageCase, xy) -> tuple:
    """(E of each oriented edge at every centre of the window, (3, h, w), interior positive;
    the edges' lengths): one numpy pass for a whole image's wrong pixels."""
    w, h = case.size
    rows, cols = np.indices((h, w))
    points = np.stack([cols + case.origin[0] + 0.5, rows + case.origin[1] + 0.5], axis=-1)
    e, _, _, v = _edge_data(np.asarray(xy, dtype=float), points.reshape(-1, 2), "snapped")
    lengths = np.array([np.hypot(*(v[(k + 1) % 3] - v[k])) for k in range(3)])
    return e.reshape(3, h, w), lengths


def differences(case: CoverageCase, got, expected, causes: str = "") -> str:
    """What differs on this case, in facts only (r347 2: the fallback named the tie rule
    whatever the mistake): how many pixels, where, and how many of their centres lie exactly
    on an edge. Where every wrong centre is one, it says it cannot tell the cause and lists
    ``causes`` as possibilities (r352 C: it proposed the tie rule for a box one short)."""
    got = np.asarray(got)
    if got.shape != expected.shape:
        return ""
    wrong = np.argwhere(got != expected)
    if not len(wrong):
        return ""
    ties, far = 0, 0.0
    for t, xy in enumerate(case.triangles):
        mask = got[t] != expected[t]
        if area2(xy) == 0 or not mask.any():
            continue
        e, lengths = centre_values(case, xy)
        e = e[:, mask]
        ties += int(((e == 0).any(axis=0) & (e >= 0).all(axis=0)).sum())
        far = max(far, float((np.abs(e) / lengths[:, None]).min(axis=0).max()))
    n, h, w = expected.shape
    missing, extra = int((expected & ~got).sum()), int((got & ~expected).sum())
    rows, cols = np.unique(wrong[:, 1]), np.unique(wrong[:, 2])
    where = f"in {_lines(rows, 'row', h - 1)}, {_lines(cols, 'column', w - 1)}"
    text = (
        f"{len(wrong)} pixel(s) differ from the rule's ({missing} missing, {extra} extra) {where}"
    )
    if ties == len(wrong):
        return (
            f"{text}, and every one of their centres lies exactly on an edge (E = 0). None of "
            "the typical mistakes this check knows gives your image, so it cannot tell the "
            f"cause; mistakes that change only such centres include {causes}"
        )
    return (
        f"{text}; {ties} of these centres lie exactly on an edge and {len(wrong) - ties} off "
        f"every edge (the farthest {fmt(far)} px from the nearest edge's line), so "
        "the tie rule alone does not explain it. None of the typical mistakes this check "
        "knows gives your image: compare it with the rule's in the figure"
    )


def where_point(xy: np.ndarray, p: np.ndarray) -> str:
    """Where point ``p`` lies for triangle ``xy``, by its exact edge functions (the words of
    every coverage explanation that places a point)."""
    if area2(xy) == 0:
        return "on a triangle of no area (it covers nothing)"
    e = values_at(xy, p)
    if (e < 0).any():
        return f"outside edge {edge_name(int(np.argmin(e)))}"
    on = [edge_name(k) for k in range(3) if e[k] == 0]
    if len(on) == 2:
        return f"exactly on a vertex, on edges {on[0]} and {on[1]}"
    return f"exactly on edge {on[0]}" if on else "inside the triangle"


def ties_of(*where: str) -> int:
    """How many of the points :func:`where_point` placed lie on an edge (a vertex counts
    twice): an example without ties is clearer, it shows the mistake, not the top-left rule."""
    return sum(2 if "vertex" in w else "exactly on" in w for w in where)
