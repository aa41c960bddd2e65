"""Cases and explanations of the exercises with a number or a few as the answer.

``edge_function``, ``split_point``, ``barycentric``, ``perspective`` and ``depth_test``:
expected values come from the core (:func:`~teachraster.core.edges.edge_function`,
:func:`~teachraster.core.span_tables.split_point`,
:func:`~teachraster.core.barycentrics.barycentric`,
:func:`~teachraster.core.interpolation.perspective_weights` with
:func:`~teachraster.core.interpolation.blend`); each explanation quotes the case's numbers and,
where a typical mistake reproduces the student's answer, names it.
"""

from __future__ import annotations

import numpy as np

from ..core.barycentrics import barycentric
from ..core.edges import edge_function
from ..core.interpolation import blend, perspective_weights
from ..core.span_tables import split_point
from ..study.hardcases import CASES
from .cases import SEED, proper_triangles, sorted_by_y
from .tolerance import all_close, close


def _readable(x: float, exact_grid: bool) -> str:
    if 0 < abs(x) < 1e-3:  # tiny values (w next to the eye plane) keep their digits
        return f"{x:.3g}"
    if exact_grid and (x * 256).is_integer() and abs(x) < 2**40:
        # on the 1/256 grid (positions): exactly, so that the student can reproduce the case
        return f"{x:.8f}".rstrip("0").rstrip(".")
    if abs(x) >= 1e15:
        return f"{x:.6g}"
    text = f"{x:.3f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


def num(x: float, other: float | None = None) -> str:
    """``x`` with 3 decimals, or with the fewest digits that tell it from ``other``.

    Never more digits than Python's shortest round-trip ``repr``: 0.8 stays 0.8 beside
    0.8000000000000002, and two different numbers never print alike.

    >>> num(3.04545), num(1.0000001, 1.0), num(2.0), num(100009.73828125)
    ('3.045', '1.0000001', '2', '100009.73828125')
    >>> num(0.8, 0.8000000000000002), num(0.8000000000000002, 0.8)
    ('0.8', '0.8000000000000002')
    >>> num(25.0, 25.0000025), num(25.0000025, 25.0)
    ('25', '25.000003')
    """
    x = float(x)
    if not np.isfinite(x):
        return repr(x)
    text = _readable(x, other is None)
    if other is None:
        return text
    o = float(other)
    if not np.isfinite(o) or x == o or text != _readable(o, False):
        return text
    # more digits than the readable form, never fewer: decimals, or significant digits for
    # tiny and huge values (as the readable form has them)
    decimals = 1e-3 <= abs(x) < 1e15
    for digits in range(3, 21 if decimals else 18):
        form = f".{digits}{'f' if decimals else 'g'}"
        text = format(x, form)
        if text != format(o, form):
            break
    if decimals:
        text = text.rstrip("0").rstrip(".")
    return min(text, repr(x), key=len)


def factor(x: float) -> str:
    """A number to multiply by: negative ones in parentheses."""
    return f"({num(x)})" if x < 0 else num(x)


def vec(v, other=None) -> str:
    v = np.asarray(v, dtype=float).ravel()
    o = [None] * len(v) if other is None else np.asarray(other, dtype=float).ravel()
    if len(o) != len(v):
        o = [None] * len(v)
    return "(" + ", ".join(num(a, b) for a, b in zip(v, o)) + ")"


def tri_words(xy) -> str:
    return f"v1={vec(xy[0])}, v2={vec(xy[1])}, v3={vec(xy[2])}"


def _centre_near(p) -> np.ndarray:
    return np.floor(p) + 0.5


# -- edge_function ----------------------------------------------------------------------------
def edge_function_cases():
    out = []
    for n, (label, xy) in enumerate(proper_triangles()):
        k = n % 3
        a, b = xy[k], xy[(k + 1) % 3]
        p = _centre_near(xy.mean(axis=0)) if n % 2 else xy[(k + 2) % 3]
        out.append(
            (f"{label}, edge v{k + 1}→v{(k + 1) % 3 + 1}", (a, b, p), float(edge_function(a, b, p)))
        )
    return out


def edge_function_pattern(results) -> dict:
    """``absolute=True`` when every answer is |E| and some E are negative (``abs(E)`` returned)."""
    values = [(float(e), float(g)) for _, e, g in results]
    negative = any(e < 0 and not close(e, 0) for e, _ in values)
    return {"absolute": negative and all(close(g, abs(e)) for e, g in values)}


def explain_edge_function(args, expected, got, absolute: bool = False):
    a, b, p = args
    where = f"a={vec(a)}, b={vec(b)}, p={vec(p)}"
    formula = "E(a, b, p) = (b.x − a.x)(p.y − a.y) − (b.y − a.y)(p.x − a.x)"
    if absolute and close(got, -expected):
        return "abs", (
            f"for {where} your {num(got)} is |E|: {formula} = {num(expected)} is negative "
            "here, because p lies to the left of a→b as seen on screen (y down). E's sign "
            "carries the side (the interior is where all three E share the sign of "
            "E(v1, v2, v3)): return E itself, not abs(E) (that is right only where E ≥ 0)"
        )
    if close(got, -expected):
        return "negated", (
            f"for {where} your {num(got)} is −E: {formula} = {num(expected)}; you have the two "
            "products (or a and b) the other way round"
        )
    far = float(np.abs([a, b, p]).max())
    hint = ""
    if far > 1e4:
        hint = (
            f" At {num(far)} px from the origin float32 numbers are "
            f"{num(float(np.spacing(np.float32(far))))} px apart and cannot hold the 1/256 grid: "
            "compute in float64"
        )
    return "float32" if hint else "value", (
        f"for {where}, E = (b.x − a.x)(p.y − a.y) − (b.y − a.y)(p.x − a.x) = "
        f"{factor(b[0] - a[0])}·{factor(p[1] - a[1])} − {factor(b[1] - a[1])}·"
        f"{factor(p[0] - a[0])} = "
        f"{num(expected, got)}; yours is {num(got, expected)}." + hint
    )


# -- split_point ------------------------------------------------------------------------------
def split_point_cases():
    v = np.array([[2.5, 1.5], [9.5, 4.5], [4.5, 12.5]])  # issue 10's example
    out = [("a long edge to the left", (v,), split_point(v))]
    for label, xy in proper_triangles():
        v = sorted_by_y(xy)
        if v[0, 1] != v[2, 1]:
            out.append((label, (v,), split_point(v)))
    return out


def explain_split_point(args, expected, got) -> str:
    (v,) = args
    (u1, v1), (u2, v2), (u3, v3) = v  # the notes' points 1, 2, 3, sorted by height
    points = ", ".join(vec(p) for p in v)
    head = f"your u4 is {num(got, expected)} for points 1, 2, 3 = {points}"
    rule = f"the long edge meets v = {num(v2)} at u = {num(expected, got)}"
    if close(got, expected - u1) and not close(u1, 0):
        return "without u1", f"{head}; {rule} (did you add u1?)"
    if close(got, u1 + (v2 - v1) / (v3 - v1) * (u2 - u1)):
        return "short edge", (
            f"{head}; {rule}: u4 lies on the long edge from point 1 to point 3, so use u3 − u1, "
            "not u2 − u1"
        )
    if close(got, u1 + (v3 - v1) / (v2 - v1) * (u3 - u1)) if v2 != v1 else False:
        return "inverse", f"{head}; {rule}: the fraction is (v2 − v1)/(v3 − v1), not its inverse"
    return f"{head}; {rule} = (v2 − v1)/(v3 − v1)·(u3 − u1) + u1 (similar triangles)"


# -- barycentric ------------------------------------------------------------------------------
def barycentric_cases():
    rng = np.random.default_rng(SEED + 1)
    out = []
    for label, xy in proper_triangles():
        lo, hi = xy.min(axis=0), xy.max(axis=0)
        for p in (_centre_near(xy.mean(axis=0)), _centre_near(rng.uniform(lo, hi))):
            out.append((f"{label}, p={vec(p)}", (xy, p), barycentric(xy, p)))
    return out


def barycentric_pattern(results) -> dict:
    """``absolute_area=True`` when the answers are right on one winding and negated on the
    other (divided by |E(v1, v2, v3)|), not negated on both (edges taken the other way)."""
    flips = [
        all_close(got, -e) and not all_close(got, e)
        for (xy, _), e, got in results
        if float(edge_function(xy[0], xy[1], xy[2])) > 0
    ]
    return {"absolute_area": not any(flips)}


def explain_barycentric(args, expected, got, absolute_area: bool = True):
    xy, p = args
    got = np.asarray(got, dtype=float)
    head = f"at p={vec(p)} in {tri_words(xy)} your λ = {vec(got, expected)}"
    right = f"the weights are {vec(expected, got)}"
    area = float(edge_function(xy[0], xy[1], xy[2]))
    if all_close(got, -expected) and area < 0 and absolute_area:
        return "absolute area", (
            f"{head}; {right}: divide by the signed area E(v1, v2, v3) = {num(area)} (negative: "
            "this triangle runs counter-clockwise on screen), not by its absolute value"
        )
    if all_close(got, -expected):
        return "sign", (
            f"{head}; {right}: every weight has the wrong sign. λ1 = E(v2, v3, p), λ2 = "
            f"E(v3, v1, p), λ3 = E(v1, v2, p), each over E(v1, v2, v3) = {num(area)}: take "
            "each edge in the triangle's order (you have the edges, or the products in E, the "
            "other way round)"
        )
    for perm in ((0, 2, 1), (1, 0, 2), (2, 1, 0), (1, 2, 0), (2, 0, 1)):
        if all_close(got, expected[list(perm)]):
            return "order", (
                f"{head}; {right}: the same numbers in another order. λ_i belongs to v_i: the "
                "area of the sub-triangle opposite v_i (p with the other two) over the whole"
            )
    far = float(np.abs(xy).max())
    if far > 1e4:
        return "float32", (
            f"{head}; {right} (error {num(np.abs(got - expected).max())}). {num(far)} px from "
            f"the origin float32 numbers are {num(float(np.spacing(np.float32(far))))} px apart, "
            "and a plane A·x + B·y + C evaluated in absolute coordinates cancels catastrophically: "
            "compute differences p − v to a vertex first, in float64"
        )
    error = float(np.abs(got - expected).max())
    if error < 1e-5:
        return "float32", (
            f"{head}; {right}: they differ by {error:.1g}, about float32's rounding "
            "(6e-8 relative): compute in float64"
        )
    if not close(got.sum(), 1.0):
        return "sum", f"{head}, which sum to {num(got.sum())}; {right} and always sum to 1"
    return (
        f"{head}; {right}: λ_i = E of the edge opposite v_i at p, divided by "
        f"E(v1, v2, v3) = {num(area)}"
    )


# -- perspective ------------------------------------------------------------------------------
def _perspective(lam, w, f) -> float:
    return float(blend(perspective_weights(np.asarray(lam)[None], np.asarray(w)), np.asarray(f))[0])


def perspective_cases():
    rng = np.random.default_rng(SEED + 2)
    ws = [np.array([1.0, 2.0, 4.0])]
    for name in ("perspective_w_ratio_1e6", "perspective_w_scale"):
        # subnormal w (1e-310) is left to the catalogue's own test: there 1/w overflows and a
        # straightforward correct formula would fail for a reason the exercise does not teach
        ws += [w for w in CASES[name].inputs["ws"] if w.min() >= np.finfo(float).tiny]
    ws += list(np.exp(rng.uniform(np.log(0.1), np.log(100.0), size=(8, 3))))
    lams = [np.array([0.2, 0.3, 0.5]), np.array([1.0, 0, 0]), np.array([0, 0.5, 0.5])]
    out = []
    for n, w in enumerate(ws):
        f = np.array([0.0, 1.0, 2.0]) if n == 0 else np.round(rng.uniform(-5, 5, 3), 2)
        for lam in lams + [rng.dirichlet(np.ones(3))]:
            args = (lam, np.asarray(w, dtype=float), f)
            out.append((f"λ={vec(lam)}, w={vec(w)}, f={vec(f)}", args, _perspective(*args)))
    return out


def explain_perspective(args, expected, got) -> str:
    lam, w, f = args
    head = f"at λ={vec(lam)}, w={vec(w)}, f={vec(f)} your {num(got, expected)}"
    right = f"the perspective-correct value is {num(expected, got)}"
    affine = float(lam @ f)
    times_w = float((lam * w) @ f / (lam @ w))
    unnormalised = float((lam / w) @ f)
    if close(got, affine) and not close(affine, expected):
        return "affine", f"{head} is the affine Σλf; {right}: divide by w"
    if close(got, times_w) and not close(times_w, expected):
        return "times w", (
            f"{head} is Σλ·f·w / Σλ·w: you multiplied by w; {right}: divide by w instead"
        )
    if close(got, unnormalised) and not close(unnormalised, expected):
        return "unnormalised", (
            f"{head} is Σλf/w; {right}: divide it by Σλ/w = {num(lam @ (1 / w))} (the "
            "interpolated 1/w)"
        )
    return f"{head}; {right} = Σλf/w ÷ Σλ/w = {num((lam / w) @ f)} ÷ {num(lam @ (1 / w))}"


# -- depth_test -------------------------------------------------------------------------------
def depth_test_cases():
    rng = np.random.default_rng(SEED + 3)
    pairs = [(0.5, 0.5), (0.3, 0.7), (0.7, 0.3), (0.0, 0.0), (1.0, 1.0), (0.0, 1.0), (1.0, 0.0)]
    pairs += [(np.nextafter(0.5, 0.0), 0.5), (np.nextafter(0.5, 1.0), 0.5), (-0.0, 0.0)]
    for a, b in rng.uniform(0, 1, size=(10, 2)):
        pairs += [(a, b), (a, a)]
    # the catalogue's coplanar_overlap: two triangles in one plane give equal depths
    label = "coplanar_overlap: equal depths of two coplanar triangles"
    out = [
        (
            label if a == b and n == 0 else f"incoming {num(a, b)}, stored {num(b, a)}",
            (float(a), float(b)),
            bool(a < b),
        )
        for n, (a, b) in enumerate(pairs)
    ]
    return out


def _float32_depths(a: float, b: float) -> str:
    """A note when float32 cannot tell the two depths apart (or orders them otherwise)."""
    a32, b32 = np.float32(a), np.float32(b)
    if a != b and (a32 < b32) != (a < b):
        return (
            f" In float32 both are {num(float(a32))}: compare the depths as given (float64), "
            "without converting them to float32"
        )
    return ""


def explain_depth_test(args, expected, got):
    a, b = args
    if a == b:
        return "tie", (
            f"the incoming depth {num(a)} equals the stored {num(b)}: a tie keeps the fragment "
            "already stored (the conventions: strictly smaller depth passes, ties keep the "
            "earlier triangle); your function let it pass: use <, not <="
        )
    note = _float32_depths(a, b)
    kind = "float32" if note else None
    if a > b:
        return kind or "farther passes", (
            f"the incoming depth {num(a, b)} is farther than the stored {num(b, a)} (smaller "
            "depth is nearer): it must fail; your function let it pass" + note
        )
    return kind or "nearer fails", (
        f"the incoming depth {num(a, b)} is nearer than the stored {num(b, a)} (smaller depth "
        "is nearer): it passes; your function rejected it" + note
    )
