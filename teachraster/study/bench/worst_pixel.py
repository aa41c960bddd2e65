"""Lesson 06's Your turn: the law a student's estimate of the floor's worst pixel followed.

Kept out of the lesson's cell (review r252 P1): its source names the law that is right, and
the student's cell should hold only the answer and the call.
"""

from __future__ import annotations

import textwrap

import numpy as np

from .groups import floor_errors, floor_quad


def steepest_piece(size: int, n: int) -> dict:
    """The study's floor at ``size``², subdivided by ``n`` as ``tr.rasterize`` does (an exact
    divide at every n-th pixel of a span from its first, and at its last): the piece whose
    ends' depths differ most. Returns its depth ratio ``rho`` (≥ 1), ``row``, anchor columns
    ``x0``, ``x1`` and the ``span``'s length in pixels (a span shorter than n + 1 pixels is one
    piece: the divide every n never happens there).

    >>> p = steepest_piece(256, 16)
    >>> round(p["rho"], 2), p["x1"] - p["x0"], p["span"]
    (3.51, 14, 15)
    """
    import teachraster as tr

    xy, w, _ = floor_quad(size)
    best = {"rho": 0.0}
    for t in range(2):
        cov = tr.rasterize(tr.Triangle(xy[t], w=w[t]), size, size).coverage
        for row in np.flatnonzero(cov.any(axis=1)):
            cols = np.flatnonzero(cov[row])
            at = np.unique(np.r_[cols[0] : cols[-1] + 1 : n, cols[-1]])
            if len(at) < 2:
                continue
            centres = np.column_stack([at + 0.5, np.full(len(at), row + 0.5)])
            w_at = 1 / (tr.barycentric(xy[t], centres) / w[t]).sum(axis=1)  # 1/w is affine
            rho = np.maximum(w_at[1:] / w_at[:-1], w_at[:-1] / w_at[1:])
            k = int(np.argmax(rho))
            if rho[k] > best["rho"]:
                best = {"rho": float(rho[k]), "row": int(row), "x0": int(at[k]),
                        "x1": int(at[k + 1]), "span": len(cols)}  # fmt: skip
    return best


def check_worst_px(estimate, n: int = 16, size: int = 1024, errors=floor_errors):
    """Judge ``estimate``, the worst screen error (px) of the study's floor subdivided by
    ``n`` at ``size``²: the law it followed from the worst pixel at half that size (cut by 4,
    by 2 — the square law, the mean's —, by what doubling the pixels across did the time
    before, or not cut), the law whose value lies nearest by ratio. Prints the measured worst
    pixels and the verdict; returns ``(right, verdict)``. ``errors`` is
    :func:`~.groups.floor_errors` (a cached one in tests).

    >>> check_worst_px(None)
    Give my_px your estimate in pixels (a number above 0), then run this cell.
    (False, 'no answer yet')
    """
    if isinstance(estimate, bool) or not isinstance(estimate, (int, float)) or not estimate > 0:
        print("Give my_px your estimate in pixels (a number above 0), then run this cell.")
        return False, "no answer yet"
    sizes = (size // 4, size // 2, size)
    worst = {s: float(errors(s, "subdivided", n)[1].max()) for s in sizes}
    quarter, half = sizes[:2]
    cut = worst[quarter] / worst[half]  # what doubling the pixels across did last time
    laws = {"cut by 4": worst[half] / 4, "the square law": worst[half] / 2,
            "the measured cut": worst[half] / cut, "no cut": worst[half]}  # fmt: skip
    followed = min(laws, key=lambda law: abs(np.log(estimate / laws[law])))
    print(f"N = {n}'s worst pixel: " + ", ".join(f"{s}² {worst[s]:.2f} px" for s in sizes))
    why = (f"lies where w changes most across a piece, where halving a piece cuts its miss "
           f"by less: from {quarter}² to {half}² it fell by {cut:.2f}")  # fmt: skip
    verdict = {
        "the measured cut": f"Right: {half}²'s {worst[half]:.2f} px cut by {cut:.2f} again is "
        f"{laws[followed]:.2f}, and {size}² measures {worst[size]:.2f}: not the square law's "
        f"halving, since the worst pixel {why}.",
        "the square law": f"Not quite: {estimate:g} px is {half}²'s {worst[half]:.2f} halved, "
        f"the square law. The mean follows it; the worst pixel does not: it {why}, and to "
        f"{worst[size]:.2f} px at {size}².",
        "cut by 4": f"Not quite: {estimate:g} px is {half}²'s {worst[half]:.2f} cut by 4, what "
        f"halving N does to the mean, not doubling the pixels across: the worst pixel {why}, "
        f"and to {worst[size]:.2f} px at {size}².",
        "no cut": f"Not quite: {estimate:g} px is about {half}²'s {worst[half]:.2f}, as if more "
        f"pixels did not help; the worst pixel {why}, and to {worst[size]:.2f} px at {size}².",
    }[followed]  # fmt: skip
    print("\n".join(textwrap.wrap(verdict, 78)))
    return followed == "the measured cut", verdict
