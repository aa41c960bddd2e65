"""The ``clip_near`` exercise: clip a clip-space triangle against the near plane z >= -w.

The expected polygon is the core's Sutherland-Hodgman (:func:`teachraster.pipeline.geometry.clipping.
clip_polygon`). Every case keeps its vertices inside the far plane (z <= w) and off the eye
point, so that the near plane is the only one that cuts and the core's answer is exactly the
near-clipped polygon.
"""

from __future__ import annotations

import numpy as np

from ..pipeline.geometry.clipping import clip_polygon, distances
from ..study.hardcases import CASES
from .cases import SEED
from .scalars import num, vec
from .tolerance import TOL, all_close, same_polygon


def near_only(v: np.ndarray) -> bool:
    """True when only the near plane can cut ``v`` (see the module docstring)."""
    d = distances(v)
    return bool((d[:, 1] >= 0).all() and not ((v[:, 2] == 0) & (v[:, 3] == 0)).any())


def clip_cases():
    out = []
    for name in ("behind_camera", "eye_plane_vertex", "hair_in_front_of_eye"):
        for v in CASES[name].inputs["clip"]:
            if near_only(v):
                out.append((name, (np.array(v, dtype=float),)))
    rng = np.random.default_rng(SEED + 4)
    counts = [0, 0, 0, 0]  # random cases by how many vertices lie behind the plane
    while min(counts[:3]) < 5:
        lo, hi = ((0.5, 3.0), (-2.0, 3.0), (-3.0, -0.5))[rng.integers(0, 3)]
        w = np.round(rng.uniform(lo, hi, 3), 3)
        z = np.round(w - rng.uniform(0, 2.5, 3) * np.abs(w), 3)
        v = np.column_stack([np.round(rng.uniform(-2, 2, (3, 2)), 3), z, w])
        behind = int((z + w < 0).sum())
        if near_only(v) and counts[behind] < 5:
            counts[behind] += 1
            out.append((f"random, {_BEHIND[behind]} the near plane", (v,)))
    # one vertex exactly on the plane, the others on either side
    v = np.array([[0.0, 0, -1, 1], [1, 0, -2, 0.5], [0, 1, 0.5, 1]])
    out.append(("a vertex on the near plane", (v,)))
    return [
        (
            f"{label}: v={vec(a[0][0])}, {vec(a[0][1])}, {vec(a[0][2])}",
            a,
            clip_polygon(a[0], np.zeros((3, 0)))[0],
        )
        for label, a in out
    ]


_BEHIND = ("no vertex behind", "one vertex behind", "two vertices behind", "all behind")


def explain_clip(args, expected, got) -> str:
    (v,) = args
    got = np.asarray(got, dtype=float).reshape(-1, 4)
    d = v[:, 2] + v[:, 3]  # signed distance to the near plane
    outside = [k for k in range(3) if d[k] < 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        after = v[:, 2] / v[:, 3] >= -1  # what a test after the divide says
    # a vertex the divide misclassifies, and the student's polygon agrees with the divide
    flipped = [k for k in range(3) if after[k] != (d[k] >= 0) and _has(got, v[k]) == bool(after[k])]
    divide = ""
    if flipped:
        k = flipped[0]
        divide = (
            f"v{k + 1} = {vec(v[k])} has w = {num(v[k, 3])} < 0: after the divide its z/w = "
            f"{num(v[k, 2] / v[k, 3])} looks {'inside' if after[k] else 'outside'}, but "
            f"z + w = {num(d[k])} says it is {'inside' if d[k] >= 0 else 'behind the near plane'}: "
            "test z + w >= 0 in clip space, before dividing by w"
        )
    if got.shape == v.shape and np.allclose(got, v) and outside:
        k = outside[0]
        text = (
            f"you returned the triangle unclipped: v{k + 1} = {vec(v[k])} has z + w = "
            f"{num(d[k])} < 0, it is behind the near plane z = −w"
        )
        if set(outside) <= set(flipped):  # a test after the divide would also keep them all
            text += f". If you tested after the divide: {divide}"
        return "unclipped", text
    if divide:
        return "after the divide", divide
    scale = max(1.0, float(np.abs(v).max()))
    bad = [p for p in got if p[2] + p[3] < -TOL * scale]
    if bad:
        return "keeps a vertex behind", (
            f"your polygon keeps {vec(bad[0])}, whose z + w = {num(bad[0][2] + bad[0][3])} < 0"
        )
    if len(got) and same_polygon(got[::-1], expected):
        return "reversed", (
            "your polygon has the right vertices in reverse order: keep the triangle's order "
            "(walk the edges v1→v2→v3→v1)"
        )
    cuts = []
    for i in range(3):
        j = (i + 1) % 3
        if (d[i] >= 0) != (d[j] >= 0):
            t = d[i] / (d[i] - d[j])
            cuts.append(
                f"edge v{i + 1}→v{j + 1} crosses the near plane at t = d{i + 1}/(d{i + 1} − d{j + 1}) = "
                f"{num(t)} (d = z + w), at {vec(v[i] + t * (v[j] - v[i]))}"
            )
    where = "; ".join(cuts) if cuts else "no edge crosses the near plane"
    return "value", (
        f"your polygon {_poly(got, expected)} should be {_poly(expected, got)}: {where}. "
        "Interpolate the new vertices in clip space, before the divide, and keep the inside "
        "vertices in order"
    )


def _has(poly: np.ndarray, vertex: np.ndarray) -> bool:
    return any(np.allclose(p, vertex, rtol=TOL, atol=TOL) for p in poly)


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
