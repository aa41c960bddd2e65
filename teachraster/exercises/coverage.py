"""Coverage exercises (``covers``, ``fill``): run them, and explain each wrong pixel by the rules.

The expected coverage is the core's (:func:`teachraster.rasterize`: snapped edge functions and
the one top-left rule). A wrong pixel is explained from the exact edge functions at its centre:
on an edge (which kind, and what the top-left rule says), on a vertex, outside an edge, or
strictly inside. A whole case is also compared with the coverage a typical mistake would give
(sampling at pixel corners, a bottom-right rule, every edge or no edge owning its centres, one
winding only), each computed with the core on a moved or mirrored triangle, so that the
explanation can name the mistake.
"""

from __future__ import annotations

import numpy as np

from ..core.edges import edge_function, edge_values_at, is_top_left, setup_edges
from ..core.fill import rasterize
from ..core.triangle import Triangle
from .cases import CoverageCase
from .report import Failure
from .scalars import num


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


def edge_kind(xy: np.ndarray, k: int) -> str:
    """ "top", "bottom", "left" or "right" for edge v_k -> v_{k+1}, by the top-left rule."""
    a, b = xy[k], xy[(k + 1) % 3]
    if area2(xy) < 0:  # the interior is on the negative side: the rule sees the edge b -> a
        a, b = b, a
    if a[1] == b[1]:
        return "top" if is_top_left(a, b) else "bottom"
    return "left" if is_top_left(a, b) else "right"


def edge_name(k: int) -> str:
    return f"v{k + 1}→v{(k + 1) % 3 + 1}"


def _values(xy: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Edge functions at centre ``c``, signed so that inside is positive (exact)."""
    s = 1.0 if area2(xy) >= 0 else -1.0
    return np.array([s * float(edge_function(xy[k], xy[(k + 1) % 3], c)) for k in range(3)])


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
    e = _values(xy, c)
    zeros = [k for k in range(3) if e[k] == 0]
    if (e < 0).any():
        k = int(np.argmin(e))
        return (
            f"centre {point(c)} is outside edge {edge_name(k)} (E = {fmt(-e[k])} px² on the "
            f"side away from the interior): it is not covered; {yours}",
            k,
            "outside",
        )
    if len(zeros) == 1:
        k = zeros[0]
        kind = edge_kind(xy, k)
        rule = "covers it" if kind in ("top", "left") else "leaves it uncovered"
        return (
            f"centre {point(c)} lies exactly on edge {edge_name(k)}, a {kind} edge: the "
            f"top-left rule {rule}, {yours}",
            k,
            f"on a {kind} edge",
        )
    if len(zeros) == 2:
        kinds = [f"{edge_name(k)} ({edge_kind(xy, k)})" for k in zeros]
        return (
            f"centre {point(c)} is a vertex, on edges {kinds[0]} and {kinds[1]}: the top-left "
            f"rule covers it only when both are top or left edges; {yours}",
            zeros[0],
            "vertex",
        )
    k = int(np.argmin(e))
    text = (
        f"centre {point(c)} is strictly inside all three edges (E = "
        f"{', '.join(fmt(v) for v in e)} px², all on the interior side): it is covered; {yours}"
    )
    return text, k, "inside"


def _rule_variants(case: CoverageCase, xy: np.ndarray) -> dict[str, np.ndarray]:
    """Coverage under the typical wrong rules, each computed with the core."""
    w, h = case.size
    xy_local = local(case, xy)
    out = {"corners": rasterize(Triangle(xy_local + 0.5), w, h).coverage}
    mirrored = np.array([w, h], dtype=float) - xy_local  # 180° turn: top-left -> bottom-right
    out["bottom-right"] = rasterize(Triangle(mirrored), w, h).coverage[::-1, ::-1]
    setup = setup_edges(xy_local, 8)
    rows, cols = np.indices((h, w)).reshape(2, -1)
    e = edge_values_at(setup, rows, cols)
    out["closed"] = (e >= 0).all(axis=1).reshape(h, w)
    out["open"] = (e > 0).all(axis=1).reshape(h, w) & (setup.area2 != 0)
    return out


MISTAKES = {
    "corners": "your coverage is the triangle sampled at pixel corners (j, i) instead of "
    "the pixel centres (j + 0.5, i + 0.5)",
    "bottom-right": "your coverage follows a bottom-right rule (centres on bottom and right "
    "edges covered, on top and left edges left out): the conventions use the top-left rule",
    "closed": "you cover every centre on an edge (E ≥ 0 on all three edges): a centre on an "
    "edge shared by two triangles is then covered twice",
    "open": "you cover no centre on an edge (E > 0 on all three edges): a centre on an edge "
    "shared by two triangles is then covered by neither",
}


def diagnose(case: CoverageCase, xy: np.ndarray, got: np.ndarray, expected: np.ndarray):
    """(kind, one sentence) naming the mistake when a typical wrong rule explains the case,
    or ("", "")."""
    if area2(xy) < 0 and not got.any() and expected.any():
        return "one winding only", (
            f"you covered nothing of a triangle whose vertices run counter-clockwise on screen "
            f"(E(v1, v2, v3) = {fmt(area2(xy))} < 0): handle both windings (swap two vertices, "
            "or accept all-negative edge functions)"
        )
    matches = [
        name
        for name, cov in _rule_variants(case, xy).items()
        if not np.array_equal(cov, expected) and np.array_equal(cov, got)
    ]
    if matches:  # several wrong rules can give the same pixels on one triangle: name each
        return " or ".join(matches), "; or ".join(MISTAKES[name] for name in matches)
    far = max(case.origin)
    if far > 1e4:
        ulp = float(np.spacing(np.float32(far)))
        return "float32", (
            f"this triangle lies {fmt(far)} px from the origin, where float32 numbers are "
            f"{fmt(ulp)} px apart and cannot hold the 1/256-px grid: compute the edge functions "
            "in float64 (or exact integers), relative to a vertex"
        )
    return "", ""


def coverage_failure(case, k: int, got_all: np.ndarray, expected_all: np.ndarray) -> Failure:
    """The failure of triangle ``k`` of ``case`` (got_all, expected_all: (n, h, w) bool)."""
    xy = case.triangles[k]
    got, expected = got_all[k], expected_all[k]
    # the example pixel: preferably one exactly on a single edge (the top-left rule's case)
    centres = [
        np.array([case.origin[0] + j + 0.5, case.origin[1] + i + 0.5])
        for i, j in np.argwhere(got != expected)
    ]
    wrong = np.argwhere(got != expected)
    mistake_kind, mistake = diagnose(case, xy, got, expected)
    zeros = [int((_values(xy, c) == 0).sum()) for c in centres] if area2(xy) else [0]
    # a winding mistake shows best inside the triangle, a tie rule on a single edge
    want = 0 if mistake.startswith("you covered nothing") else 1
    n = zeros.index(want) if want in zeros else 0
    (i, j), c = wrong[n], centres[n]
    text, edge, pixel_kind = explain_pixel(xy, c, bool(expected[i, j]))
    if case.mesh:
        times = int(got_all[:, i, j].sum())
        if times != 1:
            text += (
                f"; over this mesh your function covers {point(c)} {times} times, a watertight "
                "mesh must cover it exactly once"
            )
    n_missing = int((expected & ~got).sum())
    n_extra = int((got & ~expected).sum())
    counts = f" ({n_missing} pixel(s) missing, {n_extra} extra)"
    explanation = (f"{mistake}. For example, " if mistake else "") + text + counts
    label = case.label + (f", triangle {k}" if len(case.triangles) > 1 else "")

    def draw(ax):
        from .drawing import draw_coverage

        return draw_coverage(ax, case, xy, expected, got, edge, (i, j))

    return Failure(label, explanation, expected, got, draw, mistake_kind or pixel_kind)


def example_drawing(case: CoverageCase, expected_only: bool = False):
    """A drawing of the case's first triangle: a passing case, or (``expected_only``) the
    rule's pixels alone, for a function that gave no answer."""
    xy = case.triangles[0]
    expected = expected_coverage(case, xy)

    def draw(ax):
        from .drawing import draw_coverage

        got = None if expected_only else expected
        return draw_coverage(ax, case, xy, expected, got, None, None)

    return draw
