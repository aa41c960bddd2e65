"""Exercises ``depth_test(incoming, stored)`` and ``clip_near(v)`` (lesson 05a).

``depth_test``: the conventions' test, strictly smaller depth passes (ties keep the fragment
already stored). ``clip_near`` clips a clip-space triangle against the near plane z >= -w; the
expected polygon is the core's Sutherland-Hodgman
(:func:`teachraster.pipeline.geometry.clipping.clip_polygon`). Every clip case but one keeps
its vertices inside the far plane (z <= w) and off the eye point, so that the near plane is
the only one that cuts and the core's answer is exactly the near-clipped polygon; the one (a
vertex beyond the far plane, near-clipped by :func:`clip_with`) tells a clip against the far
plane (w − z) from no clip, and z − w from an empty placeholder (r64 04-1, 04-2). A polygon
computed in float32 passes within 1e-5 (relative), as the colours of 06, 07 and 09 do (r64 04-4). The mistakes are
wrong solutions the checker runs itself: a test after the divide, t taken from z alone, the
plane z = 0, the new vertices forgotten... (:func:`clip_with`).
"""

from __future__ import annotations

import re

import numpy as np

from ..pipeline.geometry.clipping import clip_polygon, distances
from ..pipeline.visibility.zbuffer import passes_depth_test
from ..study.hardcases import CASES
from .answers import MAX_VERTICES, as_bool, as_numbers, short
from .cases import DRAWN, SEED, drawn_rng
from .exercise import Exercise, Mistake, PackageAnswer
from .package_answers import CHECKER_WORDS
from .running import WrongAnswerType
from .scalars import num, vec
from .tolerance import TOL, all_close, same_polygon


# -- depth_test -------------------------------------------------------------------------------
def passes_depth(incoming: float, stored: float) -> bool:
    """The expected verdict: strictly nearer (smaller) passes, by the renderer's own test
    (:func:`~teachraster.pipeline.visibility.zbuffer.passes_depth_test`)."""
    return bool(passes_depth_test(incoming, stored))


def depth_test_cases():
    rng = np.random.default_rng(SEED + 3)
    pairs = [(0.5, 0.5), (0.3, 0.7), (0.7, 0.3), (0.0, 0.0), (1.0, 1.0), (0.0, 1.0), (1.0, 0.0)]
    pairs += [(np.nextafter(0.5, 0.0), 0.5), (np.nextafter(0.5, 1.0), 0.5), (-0.0, 0.0)]
    for a, b in rng.uniform(0, 1, size=(10, 2)):
        pairs += [(a, b), (a, a)]
    # the catalogue's coplanar_overlap: two triangles in one plane give equal depths
    label = "coplanar_overlap: equal depths of two coplanar triangles"
    return [
        (
            label if a == b and n == 0 else f"incoming {num(a, b)}, stored {num(b, a)}",
            (float(a), float(b)),
            passes_depth(a, b),
        )
        for n, (a, b) in enumerate(pairs)
    ]


def explain_depth(args, expected, got) -> str:
    a, b = args
    if a == b:
        where = f"the incoming depth {num(a)} equals the stored {num(b)}"
    else:
        side = "nearer" if a < b else "farther"
        where = f"the incoming depth {num(a, b)} is {side} than the stored {num(b, a)} (smaller depth is nearer)"  # fmt: skip
    verdict = "it passes" if expected else "it must fail"
    yours = "your function let it pass" if got else "your function rejected it"
    return f"{where}: {verdict}; {yours}"


def _float32_words(args, expected, got) -> str:
    a, b = args
    return (
        f": in float32 both are {num(float(np.float32(a)))}. Compare the depths as given "
        "(float64), without converting them to float32"
    )


DEPTH_MISTAKES = [
    Mistake("tie", ": a tie keeps the fragment already stored (the conventions: strictly "
            "smaller depth passes, ties keep the earlier triangle): use <, not <=",
            gives=lambda a, b: a <= b),
    Mistake("reversed", ": you test the other way round (incoming > stored); smaller depth is "
            "nearer, and the nearer fragment passes: use incoming < stored",
            gives=lambda a, b: a > b),
    Mistake("reversed", ": you test the other way round (incoming >= stored); smaller depth is "
            "nearer, and the nearer fragment passes: use incoming < stored",
            gives=lambda a, b: a >= b),
    Mistake("equality", ": you test equality; the fragment passes when it is strictly nearer "
            "(incoming < stored)",
            gives=lambda a, b: a == b),
    Mistake("float32", _float32_words,
            gives=lambda a, b: bool(np.float32(a) < np.float32(b))),
]  # fmt: skip


def _draw_depth(ax, case, got):
    from .drawing import draw_bars

    a, b = case[1]
    passes = "passes" if case[2] else "fails"
    artists = draw_bars(ax, ["incoming", "stored"], [a, b], [False, False])
    yours = "" if got is None else f", yours {'passes' if got else 'fails'}"
    artists.append(ax.set_xlabel(f"depth (smaller is nearer): it {passes}{yours}"))
    return artists


DEPTH_TEST = Exercise(
    "depth_test", depth_test_cases, as_bool, lambda g, e, a: g == e, explain_depth,
    lambda *a: ": the fragment passes only when its depth is strictly smaller than the stored one",
    DEPTH_MISTAKES, draw=_draw_depth,
    # r126 (fixex10's note): no answer was listed, so the checker's own functions were not
    # watched: handed in, they passed as the student's
    answers=(PackageAnswer(passes_depth, words=CHECKER_WORDS), PackageAnswer(passes_depth_test)),
)  # fmt: skip


# -- clip_near --------------------------------------------------------------------------------
def near_only(v: np.ndarray) -> bool:
    """True when only the near plane can cut ``v`` (see the module docstring)."""
    d = distances(v)
    return bool((d[:, 1] >= 0).all() and not ((v[:, 2] == 0) & (v[:, 3] == 0)).any())


def _random_clip(rng) -> np.ndarray:
    """Three clip-space vertices (x, y, z, w) on a 1/1000 grid, some behind the near plane."""
    lo, hi = ((0.5, 3.0), (-2.0, 3.0), (-3.0, -0.5))[rng.integers(0, 3)]
    w = np.round(rng.uniform(lo, hi, 3), 3)
    z = np.round(w - rng.uniform(0, 2.5, 3) * np.abs(w), 3)
    return np.column_stack([np.round(rng.uniform(-2, 2, (3, 2)), 3), z, w])


def clip_cases():
    out = []
    for name, said in _HARD.items():
        for v in CASES[name].inputs["clip"]:
            if near_only(v):
                out.append((said, (np.array(v, dtype=float),)))
    rng = np.random.default_rng(SEED + 4)
    counts = [0, 0, 0, 0]  # random cases by how many vertices lie behind the plane
    while min(counts[:3]) < 5:
        v = _random_clip(rng)
        behind = int((v[:, 2] + v[:, 3] < 0).sum())
        if near_only(v) and counts[behind] < 5:
            counts[behind] += 1
            out.append((f"random, {_BEHIND[behind]} the near plane", (v,)))
    now = drawn_rng()  # r46 X1: a few drawn for this check, so a harvested table fails
    for k in range(DRAWN):
        v = _random_clip(now)
        while not near_only(v) or not 0 < (v[:, 2] + v[:, 3] < 0).sum() < 3:
            v = _random_clip(now)  # one or two vertices behind: the clipping cases
        behind = int((v[:, 2] + v[:, 3] < 0).sum())
        out.append((f"drawn for this check {k + 1}, {_BEHIND[behind]} the near plane", (v,)))
    # one vertex exactly on the plane, the others on either side
    v = np.array([[0.0, 0, -1, 1], [1, 0, -2, 0.5], [0, 1, 0.5, 1]])
    out.append(("a vertex on the near plane", (v,)))
    # r448 W2: a vertex a little behind the eye (w < 0, within the far plane): a tolerance in
    # the inside test (`z + w >= -1e-3`) kept it, and passed every other case
    for w in (-2e-4, -2e-5):
        v = np.array([[-1.0, -1, 1.804, 2], [1, -1, 1.804, 2], [0, -1, 1.5 * w, w]])
        out.append((f"a vertex a hair behind the eye (w = {num(w)})", (v,)))
    out += _r456_cases()
    cases = [
        (
            f"{label}: v={vec(a[0][0])}, {vec(a[0][1])}, {vec(a[0][2])}",
            a,
            clip_polygon(a[0], np.zeros((3, 0)))[0],
        )
        for label, a in out
    ]
    # r64 04-1, 04-2: v1 lies beyond the far plane (z > w); clip_near cuts the near plane only
    v = np.array([[0.0, 0, 3, 2], [1, 0, -1.5, 1], [-1, 1, 0.5, 1]])
    label = "v1 beyond the far plane, v2 behind the near plane: only the near plane clips here"
    cases.append((f"{label}: v={vec(v[0])}, {vec(v[1])}, {vec(v[2])}", (v,), clip_with(v)))
    return cases


def _r456_cases() -> list:
    """r456: an edge in the plane (a crossing test `d_a·d_b ≤ 0` divides 0 by 0 there); a
    vertex one float32 step behind the plane, and one 1e-19 behind it close to the eye (a
    tolerance in the inside test kept them: every coordinate and z + w is exact in float32, so
    a float32 answer still passes); crossing edges whose ends share x, y and w, or x, y and z
    (4.3's colour t recovered from one coordinate, or from x else y, is 0/0 there)."""
    # tiny: 2^-40, so that even d_a·d_b (2^-127) stays a normal float32
    one, tiny = 1 - 2.0**-24, 2.0**-40
    return [
        ("an edge lying in the near plane", (np.array([[-1.0, 0, -1, 1], [1, 0, -1, 1],
                                                       [0, 1, 0.5, 1]]),)),
        # `d > 0` for the inside test passed every named case: only a drawn one ever left
        # a vertex on the plane alone (the task keeps it: distance ≥ 0)
        ("a vertex on the near plane, the other two behind it",
         (np.array([[0.0, 0, -1, 1], [1, 0, -2, 0.5], [0, 1, -2, 1]]),)),
        ("a vertex one float32 step behind the near plane (z + w = -6e-08)",
         (np.array([[-1.0, -1, -one, 1], [1, -1, -one, 1], [0, 1, -1, one]]),)),
        ("a vertex 1e-19 behind the near plane, close to the eye (w = 9.1e-13)",
         (np.array([[1.0, 1, -(tiny + 2.0**-63), tiny], [-1, -1, -(tiny - 2.0**-64), tiny],
                    [1, -1, -(tiny - 2.0**-64), tiny]]),)),
        ("a crossing edge whose ends share x, y and w (v1→v2)",
         (np.array([[0.5, 0.5, -2, 1], [0.5, 0.5, 0, 1], [-1, 0, -0.5, 0.8]]),)),
        ("a crossing edge whose ends share x, y and z (v1→v2)",
         (np.array([[0.0, 0, -0.5, 0.2], [0, 0, -0.5, 2], [0, 1, 0.5, 1]]),)),
    ]  # fmt: skip


#: The catalogue's near-plane cases, named in words as the other cases are (r306 S4).
_HARD = {
    "behind_camera": "a vertex behind the camera",
    "eye_plane_vertex": "a vertex on the eye plane (w = 0)",
    "hair_in_front_of_eye": "a vertex a hair in front of the eye",
}
_BEHIND = ("no vertex behind", "one vertex behind", "two vertices behind", "all behind")


def as_polygon(value) -> np.ndarray:
    sized = isinstance(value, (list, tuple)) or (isinstance(value, np.ndarray) and value.ndim)
    if sized and len(value) > MAX_VERTICES:  # before any conversion: a huge answer costs nothing
        raise WrongAnswerType(
            f"returned {short(value)}: a triangle clipped by one plane has at most 4 vertices"
        )
    try:
        empty = sized and np.size(value) == 0
    except ValueError:  # r294 R-cn1: ragged rows; as_numbers says what is wrong with them
        empty = False
    if empty:
        return np.zeros((0, 4))
    return as_numbers(value, (-1, 4), "an (n, 4) array of vertices (x, y, z, w)")


def clip_with(v, distance=None, t_from=None, new=True, from_end=False, keep_w=None,
              crossings="both", crossing_first=False, component=3,
              closed=True, point=None) -> np.ndarray:  # fmt: skip
    """Sutherland-Hodgman of a convex polygon (a triangle, or a polygon already clipped)
    against one plane, with the usual mistakes as knobs.

    ``distance(vertex)`` is the signed distance (z + w: the right one); ``t_from(a, b)`` the
    crossing parameter (default d_a / (d_a − d_b)); ``new=False`` adds no vertex where an edge
    crosses; ``from_end`` measures t from the other end of the edge; ``keep_w`` ("inside" or
    "first") gives the new vertex's ``component`` (w: 3) the value of the edge's inside vertex
    or of its first one instead of interpolating it; ``crossings`` ("leaving" or "entering")
    adds the new vertex only where an edge leaves the kept side or only where it comes back;
    ``crossing_first`` puts an edge's new vertex before its first vertex; ``closed=False``
    leaves out the closing edge (v3→v1 of a triangle); ``point(a, b, t)`` makes the new vertex
    from the edge and its t (default a + t·(b − a): 4.3's colour, a crossing found in NDC).
    None where undefined.
    """
    v = np.asarray(v, dtype=float)
    distance = distance or (lambda p: p[2] + p[3])
    out = []
    with np.errstate(divide="ignore", invalid="ignore"):
        for i in range(len(v) if closed else len(v) - 1):
            a, b = v[i], v[(i + 1) % len(v)]
            da, db = distance(a), distance(b)
            kept = [a] if da >= 0 else []
            wanted = {"both": True, "leaving": da >= 0, "entering": da < 0}[crossings]
            if (da >= 0) != (db >= 0) and new and wanted:
                t = da / (da - db) if t_from is None else t_from(a, b)
                t = 1 - t if from_end else t
                c = a + t * (b - a) if point is None else point(a, b, t)
                if keep_w is not None:
                    c[component] = a[component] if keep_w == "first" or da >= 0 else b[component]
                kept = [c] + kept if crossing_first else kept + [c]
            out += kept
    poly = np.array(out).reshape(-1, v.shape[1])  # attributes may ride along (4.3)
    return poly if np.isfinite(poly).all() else None


#: How t is found: the formula the task asks to work out, said once two different answers
#: have failed (r46 C1: the first wrong try printed it; :attr:`.exercise.Exercise.hints`).
_T = " (t = d_a/(d_a − d_b) along edge a→b, with d = z + w)"


def _crossing(v, z_alone: bool = True) -> str:
    """Where the first crossing edge meets the plane, and the t that says it (and the t that
    z alone gives, for the mistake that takes it: r39 04-2)."""
    d = v[:, 2] + v[:, 3]
    for i in range(3):
        j = (i + 1) % 3
        if (d[i] >= 0) != (d[j] >= 0):
            t = d[i] / (d[i] - d[j])
            zt = v[i, 2] / (v[i, 2] - v[j, 2]) if v[i, 2] != v[j, 2] else float("nan")
            at = (
                f"edge v{i + 1}→v{j + 1} crosses the near plane at t = {num(t)}{_T}, at "
                f"{vec(v[i] + t * (v[j] - v[i]))}"
            )
            return (
                f"{at}; z alone gives z{i + 1}/(z{i + 1} − z{j + 1}) = {num(zt)}" if z_alone else at
            )
    return "no edge crosses the near plane"


def _divide_words(args, expected, got) -> str:
    (v,) = args
    d = v[:, 2] + v[:, 3]
    with np.errstate(divide="ignore", invalid="ignore"):
        after = v[:, 2] / v[:, 3] >= -1
    flipped = [k for k in range(3) if after[k] != (d[k] >= 0)]
    if not flipped:
        return "you tested z/w >= -1 after the divide: test z + w >= 0 in clip space, before dividing by w"  # fmt: skip
    k = flipped[0]
    return (
        f"you tested after the divide: v{k + 1} = {vec(v[k])} has w = {num(v[k, 3])}"
        f"{' < 0' if v[k, 3] < 0 else ''}: after "
        f"the divide its z/w = {num(v[k, 2] / v[k, 3])} looks "
        f"{'inside' if after[k] else 'outside'}, but z + w = {num(d[k])} says it is "
        f"{'inside' if d[k] >= 0 else 'behind the near plane'}: test z + w >= 0 in clip space, "
        "before dividing by w"
    )


def _unclipped_words(args, expected, got) -> str:
    (v,) = args
    d = v[:, 2] + v[:, 3]
    k = int(np.argmin(d))
    return (
        f"you returned the triangle unclipped: v{k + 1} = {vec(v[k])} has z + w = {num(d[k])} "
        "< 0, it is behind the near plane z = −w"
    )


def _words_with_crossing(text: str, z_alone: bool = False):
    return lambda args, expected, got: f"{text}: {_crossing(args[0], z_alone)}"


_NAMES = "xyzw"


def _component_words(k: int):
    """Words for a new vertex whose component ``k`` was kept from an end of its edge, not
    interpolated: the student's value and the interpolated one (r39 04-2: w; r306 H3: y)."""

    def words(args, expected, got) -> str:
        g = np.asarray(got, float).reshape(-1, 4)
        (v,) = args
        name, rest = _NAMES[k], [j for j in range(4) if j != k]
        new = [p for p in expected if not any(all_close(p, q) for q in v)]
        if not new:
            return f"interpolate all four components of the new vertices, {name} included"
        p = new[0]
        near = g[int(np.argmin(np.abs(g[:, rest] - p[rest]).sum(axis=1)))] if len(g) else p
        right = ", ".join(_NAMES[j] for j in rest[:2]) + f" and {_NAMES[rest[2]]}"
        shown = ", ".join(num(near[j]) for j in rest)
        return (
            f"your new vertex with ({', '.join(_NAMES[j] for j in rest)}) = ({shown}) has the "
            f"right {right} but "
            f"{name} = {num(near[k])}; interpolated at the same t, {name} is {num(p[k])}: "
            f"interpolate all four components, {name} included"
        )

    return words


def _behind_one(v) -> int | None:
    """The one vertex behind the near plane (None unless exactly one is)."""
    behind = np.flatnonzero(np.asarray(v)[:, 2] + np.asarray(v)[:, 3] < 0)
    return int(behind[0]) if len(behind) == 1 else None


def _moved_onto_plane(v, towards: int = 1) -> np.ndarray:
    """Each vertex behind the plane moved onto it along one of its edges, to the next vertex
    (``towards`` 1) or the previous one (−1) when that one is inside, else the other: one
    crossing per vertex behind (r306 H2, the commonest first attempt)."""
    v = np.asarray(v, dtype=float)
    d = v[:, 2] + v[:, 3]
    if (d < 0).all():
        return np.zeros((0, 4))
    out = []
    for i in range(3):
        if d[i] >= 0:
            out.append(v[i])
            continue
        j = (i + towards) % 3 if d[(i + towards) % 3] >= 0 else (i - towards) % 3
        out.append(v[i] + d[i] / (d[i] - d[j]) * (v[j] - v[i]))
    return np.array(out)


def _moved_words(args, expected, got) -> str:
    (v,) = args
    k = _behind_one(v)
    if k is None:
        return (
            "you moved each vertex behind the plane onto it: with one vertex behind, both "
            "its edges cross the plane, and each crossing is a vertex of the polygon"
        )
    a, b = (k - 1) % 3, (k + 1) % 3
    return (
        f"you moved v{k + 1} (z + w = {num(v[k, 2] + v[k, 3])}) onto the plane along one of "
        f"its edges: both its edges, v{a + 1}→v{k + 1} and v{k + 1}→v{b + 1}, cross the plane, "
        "and each crossing is a vertex of the polygon: one vertex behind leaves a "
        "quadrilateral (4 vertices), not a triangle"
    )


def _dropped(v) -> np.ndarray:
    """The triangle whole when no vertex is behind the plane, else nothing (r306 X1)."""
    v = np.asarray(v, dtype=float)
    return v if (v[:, 2] + v[:, 3] >= 0).all() else np.zeros((0, 4))


def _dropped_words(args, expected, got) -> str:
    (v,) = args
    d = v[:, 2] + v[:, 3]
    k = int(np.argmin(d))
    return (
        f"you dropped the whole triangle because v{k + 1} = {vec(v[k])} lies behind the near "
        f"plane (z + w = {num(d[k])}): clip it instead; the part in front of the plane stays, "
        f"cut along it ({len(expected)} vertices here)"
    )


def _closing_words(args, expected, got, v3_kept: bool = False) -> str:
    (v,) = args
    d = v[:, 2] + v[:, 3]
    lost = []
    if d[2] >= 0 and not v3_kept:
        lost.append("v3 is never kept")
    if (d[2] >= 0) != (d[0] >= 0):
        lost.append("the crossing on v3→v1 is never added")
    return (
        "you walked only the edges v1→v2 and v2→v3: the closing edge v3→v1 is missing"
        + (f", so {' and '.join(lost)}" if lost else "")
        + "; walk v1→v2→v3→v1 (the vertex after v3 is v1: index (i + 1) % 3)"
    )


def _open_keeping_v3(v) -> np.ndarray | None:
    """The edges v1→v2 and v2→v3 walked, v3 still kept when inside (r357 half-named 5)."""
    v = np.asarray(v, dtype=float)
    p = clip_with(v, closed=False)
    return p if p is None or v[2, 2] + v[2, 3] < 0 else np.vstack([p, v[2]])


def _own(v: np.ndarray, p: np.ndarray) -> bool:
    """Is ``p`` one of the triangle's own vertices, within a rounding far coarser than
    float32's (r294 M-cn4: a vertex kept but rounded, by float16 or a cast, was called a new
    vertex with a wrong t)?"""
    scale = max(1.0, float(np.abs(v).max()))
    return bool((np.abs(np.asarray(v, float) - p).max(axis=1) <= 1e-3 * scale).any())


def _kept_behind(args, got) -> list:
    """The triangle's own vertices that ``got`` keeps behind the plane (a new vertex behind
    it has a wrong t: :func:`_off_plane` says so, r294 H-cn4)."""
    (v,) = args
    v = np.asarray(v, dtype=float)
    scale = max(1.0, float(np.abs(v).max()))
    g = np.asarray(got, dtype=float).reshape(-1, 4)
    # r456: a vertex of the case 1e-19 behind the plane, returned as it is, is behind too
    exact = [q for q in v if q[2] + q[3] < 0]
    return [p for p in g if (p[2] + p[3] < -TOL * scale and _own(v, p))
            or any((p == q).all() for q in exact)]  # fmt: skip


def _behind(args, expected, got) -> bool:
    return bool(_kept_behind(args, got))


def _behind_words(args, expected, got) -> str:
    bad = _kept_behind(args, got)[0]
    # r456: z = -1 beside w = 0.99999994 printed as (…, -1, 1), which looks on the plane
    said = (
        f"your polygon keeps {vec(bad)}, whose z = {num(bad[2], -bad[3])} and w = "
        f"{num(bad[3], -bad[2])}: z + w = {num(bad[2] + bad[3])} < 0"
    )
    (v,) = args
    if bad[2] + bad[3] > -1e-2 * max(1.0, float(np.abs(v).max())):
        # r448 W2: a tolerance in the inside test keeps a vertex a hair behind the plane
        behind_eye = " and behind the eye (w < 0)" if bad[3] < 0 else ""
        said += (
            f": a tolerance in your inside test (z + w ≥ −ε)? This vertex lies a hair behind "
            f"the near plane{behind_eye}; the kept side is z + w ≥ 0, exactly"
        )
    return said


def _kept_changed(args, expected, got) -> tuple[int, np.ndarray | None] | None:
    """(k, row): the first vertex vk of the triangle in front of the plane that ``got`` does
    not return as it is (within :func:`_own`'s rounding), and the row of ``got`` that stands
    in its place, the one most like it (None: none does); None when every kept vertex is
    there (r357: a kept vertex with w set to 1 or x and y swapped was told "your new vertex
    … its t is wrong")."""
    (v,) = args
    v, g = np.asarray(v, dtype=float), np.asarray(got, dtype=float).reshape(-1, 4)
    if not np.isfinite(g).all():
        return None
    scale = max(1.0, float(np.abs(v).max()))
    stray = [p for p in g if not _own(v, p)
             and not any(all_close(p, q, FLOAT32_TOL) for q in expected)]  # fmt: skip
    for k in np.flatnonzero(v[:, 2] + v[:, 3] >= 0):
        q = v[k]
        if len(g) and (np.abs(g - q).max(axis=1) <= 1e-3 * scale).any():
            continue
        if not stray:
            return int(k), None
        best = max(stray, key=lambda p: (_permuted(q, p) is not None,
                                         int((np.abs(p - q) <= TOL * scale).sum()),
                                         -float(np.abs(p - q).sum())))  # fmt: skip
        return int(k), best
    return None


def _permuted(q: np.ndarray, p: np.ndarray) -> tuple | None:
    """The order of q's components that gives p (fewest moved first), or None."""
    import itertools

    orders = sorted(
        itertools.permutations(range(4)), key=lambda o: sum(i != j for i, j in enumerate(o))
    )
    return next((o for o in orders[1:] if all_close(p, q[list(o)], FLOAT32_TOL)), None)


def what_changed(q: np.ndarray, p: np.ndarray, names: str = _NAMES) -> str:
    """What turned ``q`` (a kept vertex) into ``p``, in words: two components swapped, divided
    by w, w set to 1, or the components that differ."""
    order = _permuted(q, p) if len(q) == 4 else None
    if order is not None:
        moved = [i for i, j in enumerate(order) if i != j]
        if len(moved) == 2:
            return f"its {names[moved[0]]} and {names[moved[1]]} swapped"
        return f"its components in the order ({', '.join(names[j] for j in order)})"
    if len(q) == 4 and q[3] != 0 and all_close(p, q / q[3], FLOAT32_TOL):
        return f"divided by its w = {num(q[3])}"
    changed = [k for k in range(len(q)) if not all_close(p[k], q[k], FLOAT32_TOL)]
    if len(q) == 4 and changed == [3] and p[3] == 1:
        return "its w set to 1"
    return ", ".join(f"{names[k]} {num(q[k], p[k])} → {num(p[k], q[k])}" for k in changed)


def _kept_fits(args, expected, got) -> bool:
    return _kept_changed(args, expected, got) is not None


def _kept_words(args, expected, got) -> str:
    (v,) = args
    k, p = _kept_changed(args, expected, got)
    q = v[k]
    where = f"v{k + 1} = {vec(q)} lies in front of the near plane (z + w = {num(q[2] + q[3])} ≥ 0)"
    if p is None:
        return f"{where}, and your polygon leaves it out: a vertex on the kept side stays"
    return (
        f"{where}, so it is kept as it is, but yours changed it to {vec(p, q)}: "
        f"{what_changed(q, p)}. A kept vertex is returned unchanged, all four of x, y, z and w; "
        "only the new vertices are interpolated"
    )


def _w_one(v) -> np.ndarray | None:
    """The right polygon with w set to 1 at every vertex (r357 misnamed 1)."""
    p = clip_with(v)
    if p is not None:
        p[:, 3] = 1.0
    return p


def _kept_shown(args, expected, got, template: str) -> str:
    """``template`` filled with the first kept vertex that changed (``{v}``, ``{was}``,
    ``{now}``), or "" where none did."""
    change = _kept_changed(args, expected, got)
    if not change or change[1] is None:
        return ""
    return template.format(v=change[0] + 1, was=vec(args[0][change[0]]), now=vec(change[1]))


def _w_one_words(args, expected, got) -> str:
    shown = _kept_shown(args, expected, got, " (v{v} = {was} comes back as {now})")
    return (
        f"your w is 1 at every vertex{shown}: you set w to 1, as after the divide, but left x, y "
        "and z undivided. Return the polygon in clip space: a kept vertex as it is, w included, "
        "and each new vertex's w interpolated at its t, as x, y and z are"
    )


def _xy_words(args, expected, got) -> str:
    shown = _kept_shown(args, expected, got, ": v{v} = {was} comes back as {now}")
    return (
        f"your x and y columns are swapped{shown}. Each row is one vertex (x, y, z, w), in the "
        "order the triangle's vertices are given; a kept vertex comes back as it is"
    )


def _new_vertices(args, got) -> list:
    """The vertices of ``got`` that are none of the triangle's own."""
    (v,) = args
    g = np.asarray(got, dtype=float).reshape(-1, 4)
    return [p for p in g if not _own(v, p)]


def _off_plane_by(args) -> float:
    """How far off the plane a new vertex may lie: the comparison's own tolerance (a float32
    answer's t is within it; r294 H-cn4: at 1e-4, a t 0.01 % off was told only "keeps a
    vertex behind")."""
    return FLOAT32_TOL * max(1.0, float(np.abs(args[0]).max()))


def _off_plane(args, expected, got) -> bool:
    """A new vertex that is not on the near plane (r85 04: t = ½ or a wrong sign of t was
    told only its symptom, or a generic rule); not where a kept vertex came back changed
    (r357: that is said first, :func:`_kept_changed`)."""
    if _kept_changed(args, expected, got) is not None:
        return False
    return any(abs(p[2] + p[3]) > _off_plane_by(args) for p in _new_vertices(args, got))


def _off_plane_words(args, expected, got) -> str:
    p = next(p for p in _new_vertices(args, got) if abs(p[2] + p[3]) > _off_plane_by(args))
    return (
        f"your new vertex {vec(p)} is not on the near plane: its z + w is {num(p[2] + p[3])}, "
        "not 0, so its t is wrong (a crossing lies where z + w, which changes linearly along "
        "the edge, reaches 0)"
    )


def _w_plane(args, expected, got) -> float | None:
    """The w of a plane w = ε every new vertex lies on, each where an edge crosses it (the
    distance taken as w − ε, a guard against the eye plane; r496 H10), or None."""
    v = np.asarray(args[0], float)
    new = _new_vertices(args, got)
    if not new or any(abs(p[2] + p[3]) <= _off_plane_by(args) for p in new):
        return None
    eps = float(new[0][3])
    if any(abs(p[3] - eps) > 1e-9 for p in new):
        return None
    for p in new:
        on = [a + (eps - a[3]) / (b[3] - a[3]) * (b - a)
              for a, b in ((v[i], v[(i + 1) % 3]) for i in range(3)) if a[3] != b[3]]  # fmt: skip
        if not any(all_close(p, q, 1e-6) for q in on):
            return None
    return eps


def _w_plane_words(args, expected, got) -> str:
    eps = _w_plane(args, expected, got)
    return (
        f"your new vertices all lie where the edges cross w = {num(eps)}, not the near plane: "
        f"you measured the distance as w − {num(eps)} (a guard against the eye plane?); the "
        "near plane is z = −w, and the distance to it z + w"
    )


def _one_component_off(args, expected, got) -> tuple | None:
    """(q, p, k): the first vertex q of ``got`` that is no vertex of the polygon but the new
    vertex p in all components but ``k`` (the crossing's t right, one component changed
    after: r448 M3, told "its t is wrong"); None unless every other vertex is right."""
    (v,) = args
    g = np.asarray(got, dtype=float).reshape(-1, 4)
    if len(g) != len(expected):
        return None
    new = [p for p in expected if not _own(v, p)]
    found = None
    for q in g:
        if any(all_close(q, p, FLOAT32_TOL) for p in expected):
            continue
        rest = [
            (p, k) for p in new for k in range(4)
            if all_close(np.delete(q, k), np.delete(p, k), FLOAT32_TOL)
        ]  # fmt: skip
        if not rest:
            return None
        found = found or (q, *rest[0])
    return found


def _one_component_words(args, expected, got) -> str:
    q, p, k = _one_component_off(args, expected, got)
    others = ", ".join(_NAMES[j] for j in range(4) if j != k)
    return (
        f"your new vertex {vec(q, p)} has the {others} of the crossing, but {_NAMES[k]} = "
        f"{num(q[k], p[k])}, not {num(p[k], q[k])}: its t is right, and one component was "
        f"changed after. All four components are interpolated at that t, a + t·(b − a), and "
        "left as they come (the new vertex lies on the plane, z + w = 0, because its z and w "
        "are both interpolated)"
    )


def _edge_in_plane(v) -> int | None:
    """The first edge i→i+1 with both ends on the near plane (z + w = 0), else None."""
    d = np.asarray(v, dtype=float)[:, 2] + np.asarray(v, dtype=float)[:, 3]
    return next((i for i in range(3) if d[i] == 0 and d[(i + 1) % 3] == 0), None)


def _in_plane_nan(args, expected, got) -> bool:
    g = np.asarray(got, dtype=float)
    return _edge_in_plane(args[0]) is not None and bool(np.isnan(g).any())


def _in_plane_words(args, expected, got) -> str:
    i = _edge_in_plane(args[0])
    return (
        f"your polygon holds NaN: the edge v{i + 1}→v{(i + 1) % 3 + 1} lies in the near plane "
        "(z + w = 0 at both ends), and your t = d_a/(d_a − d_b) there is 0/0. Such an edge "
        "does not cross the plane: both its ends are kept (test the crossing as one end "
        "inside and the other behind, not by d_a·d_b ≤ 0)"
    )


def _float16(args, expected, got) -> bool | None:
    """Every number of ``got`` a float16, and the polygon right within float16's rounding (of
    the triangle too: a vertex 6e-8 behind the plane is on it in float16)."""
    g = np.asarray(got, dtype=float).reshape(-1, 4)
    with np.errstate(over="ignore", under="ignore"):
        held = g.astype(np.float16).astype(float)
        rounded = clip_with(np.asarray(args[0], float).astype(np.float16).astype(float))
    if not len(g):
        return None  # nothing to round: no say
    if not (np.isfinite(g).all() and (held == g).all()):
        return False
    return same_polygon(g, expected, 1e-2) or (
        rounded is not None and same_polygon(g, rounded, 1e-2)
    )


def _float16_words(args, expected, got) -> str:
    # the fit is the evidence (every number a half, the polygon right within its rounding):
    # the answer's dtype (float64 after a cast back) cannot tell the diagnosis's own guard
    return (
        "your polygon is right to about 3 significant digits, and every number in it is a "
        "16-bit float (half precision, 11 significant bits): computed in halves? The check "
        "compares within 1e-5 (a GPU clips in 32-bit floats); compute in 32 or 64 bits"
    )


def _ndc_crossing(v) -> np.ndarray | None:
    """The crossing found after the divide (r310 H4): t where z/w reaches −1 along the edge
    in NDC, the NDC point there lifted back by the w interpolated at that t; on the plane,
    off the edge."""
    v = np.asarray(v, dtype=float)
    if (v[:, 3] == 0).any():
        return None

    def lifted(a, b, _t):
        na, nb = a[:3] / a[3], b[:3] / b[3]
        t = (na[2] + 1) / (na[2] - nb[2])
        wt = a[3] + t * (b[3] - a[3])
        return np.r_[(na + t * (nb - na)) * wt, wt]

    return clip_with(v, point=lifted)


def _one_too_many(args, expected, got) -> bool:
    """One vertex more than the polygon, and without it the polygon (r310 X1: an extra
    vertex, off every edge, was told "its t is wrong")."""
    g = np.asarray(got, dtype=float).reshape(-1, 4)
    return len(g) == len(expected) + 1 and any(
        same_polygon(np.delete(g, k, axis=0), expected, FLOAT32_TOL) for k in range(len(g))
    )


def _one_too_many_words(args, expected, got) -> str:
    g = np.asarray(got, dtype=float).reshape(-1, 4)
    k = next(
        k for k in range(len(g)) if same_polygon(np.delete(g, k, axis=0), expected, FLOAT32_TOL)
    )
    return (
        f"your polygon has one vertex too many: without {vec(g[k])} it is right. The clipped "
        "polygon's vertices are the triangle's kept vertices and the crossings of its edges, "
        "nothing else"
    )


def ndc_z(a) -> float:
    return a[2] / a[3] + 1


def _divided_polygon(v) -> np.ndarray | None:
    """The right polygon divided by w (NDC), where no vertex has w = 0."""
    p = clip_with(v)
    if p is None or (p[:, 3] == 0).any():
        return None
    return p / p[:, 3:4]


def _clip_t(a, b) -> float:
    """The right crossing's t, d_a/(d_a − d_b) with d = z + w (for a test made otherwise)."""
    return (a[2] + a[3]) / ((a[2] + a[3]) - (b[2] + b[3]))


def _divided_first(v) -> np.ndarray | None:
    """The triangle divided by w, then clipped by the right code (r319 X1: told "its t is
    wrong" about a vertex only divided): w = 1 after the divide, so z + w ≥ 0 is z/w ≥ −1."""
    v = np.asarray(v, dtype=float)
    return None if (v[:, 3] == 0).any() else clip_with(v / v[:, 3:4])


def _divided_first_words(args, expected, got) -> str:
    (v,) = args
    behind = [k for k in range(3) if v[k, 3] < 0]
    why = (
        f": v{behind[0] + 1} = {vec(v[behind[0]])} has w = {num(v[behind[0], 3])} < 0, and the "
        f"divide turns it into {vec(v[behind[0]] / v[behind[0], 3])}, in front of the plane"
        if behind
        else ""
    )
    return (
        f"you divided your vertices by w before clipping{why}; clip in clip space, (x, y, z, w) "
        "as the triangle's vertices are given, and return the polygon there: the divide by w "
        "comes after clipping"
    )


def _transposed(args, expected, got) -> bool:
    """A square answer (4 vertices) whose columns are the polygon's vertices."""
    g = np.asarray(got, dtype=float)
    return g.shape == (4, 4) and not same_polygon(g, expected) and same_polygon(g.T, expected)


def _far_too(v) -> np.ndarray | None:
    """Clipped against the near plane, then against the far plane (w − z ≥ 0) too."""
    p = clip_with(v)
    return p if p is None or not len(p) else clip_with(p, lambda q: q[3] - q[2])


CLIP_MISTAKES = [
    Mistake("unclipped", _unclipped_words, gives=lambda v: np.asarray(v, dtype=float)),
    Mistake("after the divide", _divide_words, gives=lambda v: clip_with(v, ndc_z)),
    # r319 H1: the test after the divide, the crossing's t still from z + w (told only "keeps
    # a vertex behind")
    Mistake("after the divide", _divide_words,
            gives=lambda v: clip_with(v, ndc_z, t_from=_clip_t)),
    # r85 04: the hinted words said where the vertex lies twice
    Mistake("t from z only", _words_with_crossing("you took t from z alone, as if the plane "
            "were z = 0", z_alone=True),
            gives=lambda v: clip_with(v, t_from=lambda a, b: a[2] / (a[2] - b[2]))),
    Mistake("t from the divide", _words_with_crossing("you took t from z/w after the divide; "
            "the new vertex is interpolated in clip space, at t = d1/(d1 − d2) with d = z + w"),
            gives=lambda v: clip_with(v, t_from=lambda a, b: ndc_z(a) / (ndc_z(a) - ndc_z(b)))),
    Mistake("t from the other end", _words_with_crossing("you measured t from the other end "
            "of the edge: the new vertex is a + t·(b − a) with t = d_a/(d_a − d_b)"),
            gives=lambda v: clip_with(v, from_end=True)),
    Mistake("plane z = 0", "you clipped against z = 0 (Direct3D's near plane); GL's clip space "
            "keeps z ≥ −w: the distance to the near plane is z + w",
            gives=lambda v: clip_with(v, lambda p: p[2])),
    Mistake("far plane's distance", "you measured the distance as z − w, the far plane's "
            "expression with its sign turned: it keeps z ≥ w, beyond the far plane, so nothing "
            "is left of a triangle in front of it; the near plane keeps z + w ≥ 0",
            gives=lambda v: clip_with(v, lambda p: p[2] - p[3])),
    Mistake("far plane", "you clipped against the far plane: w − z ≥ 0 keeps z ≤ w, the far "
            "plane's side (it cuts nothing of a triangle in front of the far plane, and cuts "
            "off a vertex beyond it); the near plane keeps z ≥ −w: the distance to it is z + w",
            gives=lambda v: clip_with(v, lambda p: p[3] - p[2])),
    Mistake("eye plane", "your new vertices lie on w = 0, the plane through the eye: you "
            "measured the distance as w alone; the near plane is z = −w, the distance to it "
            "z + w", gives=lambda v: clip_with(v, lambda p: p[3])),
    *(Mistake(f"{_NAMES[k]} not interpolated", _component_words(k),
              gives=lambda v, k=k, how=how: clip_with(v, keep_w=how, component=k))
      for k in (3, 0, 1, 2) for how in ("inside", "first")),
    Mistake("no new vertices", "you dropped the vertices behind the near plane but added none "
            "where the edges cross it: each crossing edge gives a new vertex, on the plane",
            gives=lambda v: clip_with(v, new=False)),
    Mistake("reversed", "your polygon has the right vertices in reverse order: keep the "
            "triangle's order (walk the edges v1→v2→v3→v1)",
            fits=lambda args, e, g: len(g) > 0 and same_polygon(np.asarray(g)[::-1], e)),
    # r294: answers of the wrong form were told "its t is wrong" (M-cn1..3), a missing
    # crossing only by its shape (H-cn1), the crossing's place and the turned test by the rule
    # or a symptom (H-cn2, H-cn3)
    Mistake("divided by w", "you divided your vertices by w: return the clipped polygon in "
            "clip space, (x, y, z, w) as the triangle's vertices are given; the divide by w "
            "comes after clipping", gives=_divided_polygon),
    Mistake("divided by w", _divided_first_words, gives=_divided_first),
    Mistake("far plane too", "you clipped against the far plane too (w − z ≥ 0): this "
            "exercise clips against the near plane only, z + w ≥ 0, so a vertex beyond the far "
            "plane stays", gives=_far_too),
    Mistake("inside turned round", "you kept the side behind the near plane: your inside "
            "test is turned round; the kept side is z + w ≥ 0",
            gives=lambda v: clip_with(v, lambda p: -(p[2] + p[3]))),
    Mistake("one crossing", "you added a new vertex only where an edge leaves the kept side "
            "(inside → behind): an edge that comes back (behind → inside) crosses the plane "
            "too, and its crossing is a vertex of the polygon",
            gives=lambda v: clip_with(v, crossings="leaving")),
    Mistake("one crossing", "you added a new vertex only where an edge comes back to the kept "
            "side (behind → inside): an edge that leaves it (inside → behind) crosses the "
            "plane too, and its crossing is a vertex of the polygon",
            gives=lambda v: clip_with(v, crossings="entering")),
    Mistake("crossing before its edge", "your vertices are right, but each new vertex comes "
            "before the first vertex a of its edge a→b: keep a (when it is inside), then add "
            "the edge's crossing, so that the vertices stay in order around the polygon",
            gives=lambda v: clip_with(v, crossing_first=True)),
    # r294 M-cn2: a 4 × 4 answer transposed was told "its t is wrong" (the shared transposed
    # mistake is named only where every failing answer is one: a 3 × 4 one is refused first)
    Mistake("transposed", "your polygon is transposed: each row must be one vertex (x, y, z, "
            "w), not one component of every vertex (np.array([xs, ys, zs, ws]) needs a .T, or "
            "np.column_stack)", fits=_transposed),
    # r306: the triangle dropped whole (X1, told "z − w"), the closing edge forgotten (H1)
    # and a vertex moved onto the plane (H2), told only the shape; t = ½ and d_a/(d_a + d_b)
    # told only "its t is wrong"
    Mistake("dropped whole", _dropped_words, gives=_dropped),
    Mistake("closing edge missing", _closing_words, gives=lambda v: clip_with(v, closed=False)),
    # r357: the closing edge skipped but v3 still kept (H5); a kept vertex's w set to 1 and x
    # and y swapped (misnamed 1, 2); the distance z + 1 (w forgotten, H3); t's sign (H4)
    Mistake("closing edge missing", lambda a, e, g: _closing_words(a, e, g, v3_kept=True),
            gives=_open_keeping_v3),
    Mistake("w set to 1", _w_one_words, gives=_w_one),
    Mistake("x and y swapped", _xy_words,
            gives=lambda v: None if clip_with(v) is None else clip_with(v)[:, [1, 0, 2, 3]]),
    Mistake("distance z + 1", _words_with_crossing("you measured the distance to the plane as "
            "z + 1, the bound z/w ≥ −1 of NDC with w forgotten: in clip space the near plane "
            "is z + w = 0, so w belongs in the distance, z + w"),
            gives=lambda v: clip_with(v, lambda p: p[2] + 1)),
    Mistake("t sign slip", _words_with_crossing("you took t = d_a/(d_b − d_a), its sign turned: "
            "at a crossing it comes out negative, so your new vertex lies off the edge, beyond "
            "its first end a; t must lie between 0 and 1"),
            gives=lambda v: clip_with(v, t_from=lambda a, b: -_clip_t(a, b))),
    Mistake("vertex moved onto the plane", _moved_words, gives=_moved_onto_plane),
    Mistake("vertex moved onto the plane", _moved_words,
            gives=lambda v: _moved_onto_plane(v, towards=-1)),
    Mistake("t = ½", _words_with_crossing("you put each new vertex halfway along its edge "
            "(t = ½)"),
            gives=lambda v: clip_with(v, t_from=lambda a, b: 0.5)),
    Mistake("t with d_a + d_b", _words_with_crossing("you took t = d_a/(d_a + d_b): at a "
            "crossing d_a and d_b have opposite signs, so their sum is not how much the "
            "distance changes along the edge"),
            gives=lambda v: clip_with(v, t_from=lambda a, b: (a[2] + a[3]) / (a[2] + a[3] + b[2] + b[3]))),
    # r310 H4: the crossing found in NDC and lifted back was told the rule; X1: an extra
    # vertex (the centroid) appended was told "its t is wrong"
    Mistake("crossing found after the divide", _words_with_crossing("you found the crossing "
            "after the divide: you interpolated x/w, y/w, z/w along the edge (in NDC) and "
            "multiplied back by w; the divide is not linear along the edge, so t in NDC is not "
            "t in clip space, the w you took at it is wrong, and your new vertex lies on the "
            "near plane but off the edge. Find t from z + w in clip space and "
            "interpolate x, y, z and w there"), gives=_ndc_crossing),
    Mistake("vertex too many", _one_too_many_words, fits=_one_too_many),
    # r456 W9: a crossing test `d_a·d_b ≤ 0` divided 0 by 0 on an edge in the plane
    Mistake("edge in the plane", _in_plane_words, fits=_in_plane_nan),
    # r456 M4: computed in float16 (3 digits): told "its t is wrong"
    Mistake("computed in 16 bits", _float16_words, fits=_float16),
    # r448 M3: w set to 1, z set to −1 or nudged inside after a right t: told "its t is wrong"
    Mistake("new vertex changed", _one_component_words,
            fits=lambda a, e, g: _one_component_off(a, e, g) is not None),
    Mistake("kept vertex changed", _kept_words, fits=_kept_fits, symptom=True),
    Mistake("a plane w = ε", _w_plane_words, fits=lambda a, e, g: _w_plane(a, e, g) is not None),
    Mistake("crossing off the plane", _off_plane_words, fits=_off_plane, symptom=True),
    Mistake("keeps a vertex behind", _behind_words, fits=_behind, symptom=True),
]  # fmt: skip


_CLIP_HINTS = (
    # r64 04: the hint gave no formula but still the crossing's t and point
    (re.compile(r"crosses the near plane at t = \S+ \(t = d_a/\(d_a − d_b\) along edge a→b, "
                r"with d = z \+ w\), at \([^)]*\)"),
     "crosses the near plane where the distance to the plane, z + w, reaches 0 along the edge "
     "(at what fraction t of the edge, from its first end?)"),
    (_T, " (where the distance to the plane, z + w, reaches 0 along the edge)"),
    ("at t = d1/(d1 − d2) with d = z + w (the signed distance to the plane z = −w)",
     "where z + w, the signed distance to the plane z = −w, is 0 (by what fraction of the "
     "edge?)"),
    ("at t = d1/(d1 − d2) with d = z + w", "where z + w, the distance to the near plane, is 0"),
    ("the new vertex is a + t·(b − a) with t = d_a/(d_a − d_b)", "the new vertex is "
     "a + t·(b − a), so t is the fraction of the way from a (its own end) to b"),
)  # fmt: skip


#: A polygon computed in float32 is right within its rounding (r64 04-4: every GPU clips in
#: float32), as a colour is in 06, 07 and 09; a wrong t or plane is off by far more. Not 1e-6:
#: float32 loses digits inside a distance z + w whose z and w nearly cancel (a vertex near the
#: plane), and in a + t·(b − a) where the new vertex is much shorter than the edge's ends (at
#: a crossing d_a − d_b adds two magnitudes: it never cancels; r306 F1), and a fresh drawn
#: case failed float32 by 2e-6 at |v| = 1.75 (about 1 check in 25, found at merge).
FLOAT32_TOL = 1e-5


def _constant_polygon(value) -> str:
    """A placeholder (r64 04-1: an empty polygon was called the far plane's z − w)."""
    p = np.asarray(value, dtype=float).reshape(-1, 4) if np.size(value) % 4 == 0 else None
    shown = "an empty polygon" if p is not None and not len(p) else short(value)
    return (
        f"your function returns {shown} on every case, whatever the triangle: a placeholder "
        "left in, or a `return` reached too early?"
    )


def explain_clip(args, expected, got) -> str:
    g = np.asarray(got, float).reshape(-1, 4)
    e = _without_repeats(expected)
    # r306 S5: a vertex on the plane is kept and is its edge's crossing too: quoted once
    again = " (the vertex on the plane may also be given twice)" if len(e) < len(expected) else ""
    return f"your polygon {_poly(g, e)} should be {_poly(e, g)}{again}"


def _without_repeats(p: np.ndarray) -> np.ndarray:
    """``p`` without a vertex equal to the one before it (the last compared with the first)."""
    keep = [k for k in range(len(p)) if k == 0 or not all_close(p[k], p[k - 1])]
    if len(keep) > 1 and all_close(p[keep[-1]], p[0]):
        keep.pop()
    return p[keep]


def clip_rule(args, expected, got) -> str:
    return (
        f": {_crossing(args[0], z_alone=False)}. Interpolate the new vertices in clip space, "
        "before the divide, "
        "and keep the inside vertices in order"
    )


def _poly(p: np.ndarray, other: np.ndarray) -> str:
    """The polygon's vertices, each with the digits that tell it from the nearest of ``other``.

    >>> a = np.array([[0.0, 0, 0, 1], [1, 0, 0, 1], [0, 1, 0, 1]])
    >>> b = a + np.array([0, 0, 0, 1e-7])
    >>> _poly(a, b) != _poly(b, a)
    True
    """
    if not len(p):
        return "empty"
    if not len(other):
        return "[" + ", ".join(vec(q) for q in p) + "]"
    near = [other[int(np.argmin(np.abs(other - q).sum(axis=1)))] for q in p]
    # a vertex that matches (within the tolerance) needs no more digits than usual
    near = [None if all_close(q, r) else r for q, r in zip(p, near)]
    return "[" + ", ".join(vec(q, r) for q, r in zip(p, near)) + "]"


def _draw_clip(ax, case, got):
    from .drawing import draw_clip

    return draw_clip(ax, case[1][0], case[2], got)


#: r456 W10: the package's distances to the clip planes, the distance the task asks to work
#: out, passed unflagged
DISTANCES = PackageAnswer(
    distances, what="the signed distance to the near plane, a part of this very answer"
)

CLIP_NEAR = Exercise(
    "clip_near", clip_cases, as_polygon, lambda g, e, a: same_polygon(g, e, FLOAT32_TOL), explain_clip,
    clip_rule, CLIP_MISTAKES, float32=lambda args: float(np.abs(args[0]).max()) * 4,
    answers=(PackageAnswer(clip_polygon), DISTANCES), draw=_draw_clip, hints=_CLIP_HINTS,
    constant=_constant_polygon,
    match=lambda got, answer, args: same_polygon(np.asarray(got, float).reshape(-1, 4), answer, 1e-6),
)  # fmt: skip
