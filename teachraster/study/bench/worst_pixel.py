"""Lesson 06's Your turn: will doubling the pixels across cut N = 32's worst pixel by more,
about as much, or less than it did the last time, and why.

Kept out of the lesson's cell (review r252 P1): its source names the answer, and the student's
cell should hold only the answer and the call. The answer is not one division of printed
numbers (r268 P2): it turns on where N's steepest piece lies, a whole span shorter than N + 1
pixels or a piece of N pixels (:func:`steepest_piece`).
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


#: The estimate's cut counts as "about the same" as the last one within this factor
SAME = 1.1


def _trend(cut: float, before: float) -> str:
    """More than, about as much as, or less than the cut ``before``."""
    if cut > before * SAME:
        return "more than"
    return "less than" if cut < before / SAME else "about as much as"


def check_doubling_cut(estimate, n: int = 32, size: int = 1024, errors=floor_errors):
    """Judge ``estimate``, the worst screen error (px) of the study's floor subdivided by ``n``
    at ``size``², against the worst at ``size``/2 and ``size``/4: does the cut it implies
    (from ``size``/2 to ``size``) exceed the one before, match it, or fall short, as measured?
    Right when it moves the same way as the measurement, and by no more than the mean's 2
    allows (+10 %: on screen the mean goes like N² over the pixels across). Prints the measured worst pixels, their steepest pieces and the verdict;
    returns ``(right, verdict)``. ``errors`` is :func:`~.groups.floor_errors` (a cached one in
    tests).

    >>> check_doubling_cut(None)
    Give my_px your estimate in pixels (a number above 0), then run this cell.
    (False, 'no answer yet')
    """
    if isinstance(estimate, bool) or not isinstance(estimate, (int, float)) or not estimate > 0:
        print("Give my_px your estimate in pixels (a number above 0), then run this cell.")
        return False, "no answer yet"
    sizes = (size // 4, size // 2, size)
    worst = {s: float(errors(s, "subdivided", n)[1].max()) for s in sizes}
    piece = {s: steepest_piece(s, n) for s in sizes}
    before, cut = worst[sizes[0]] / worst[sizes[1]], worst[sizes[1]] / worst[size]
    yours = worst[sizes[1]] / estimate
    print(f"N = {n}'s worst pixel: " + ", ".join(f"{s}² {worst[s]:.2f} px" for s in sizes))
    print(f"doubling the pixels across cut it {before:.2f}x, then {cut:.2f}x; yours {yours:.2f}x")
    print(f"N = {n}'s steepest piece (depth ratio ρ, length, its span's length in px):")
    for s in sizes:
        p = piece[s]
        print(f"  {s:4d}²: ρ = {p['rho']:.2f}, {p['x1'] - p['x0']} px of a span of {p['span']} px")
    short = [f"{s}²" for s in sizes if piece[s]["x1"] - piece[s]["x0"] < n]
    less = [piece[s]["rho"] - 1 for s in sizes]
    rho1 = "ρ\u00a0−\u00a01"  # kept on one line by the wrap
    why = (f"N = {n}'s steepest piece is "
           + (f"a whole span, shorter than N, at {' and '.join(short)}: no divide every {n} "
              "happens there, and twice the pixels across make that piece longer in pixels, "
              "not shorter on the floor. " if short else f"{n} pixels long at every size. ")
           + f"Its {rho1} went {less[0]:.2f}, {less[1]:.2f}, {less[2]:.2f} (x{less[1] / less[0]:.2f}, "
           f"then x{less[2] / less[1]:.2f}); a cut near the mean's 2 needs it to halve, as "
           "when a piece of N pixels covers half as much floor.")  # fmt: skip
    right = _trend(yours, before) == _trend(cut, before) and yours <= 2 * SAME
    if yours > 2 * SAME:
        verdict = (f"Not quite: your estimate cuts it {yours:.2f}x, more than the 2 that even "
                   "the mean only follows (it goes like N² over the pixels across). " + why)  # fmt: skip
    else:
        verdict = (f"{'Right' if right else 'Not quite'}: your cut, {yours:.2f}x, is "
                   f"{_trend(yours, before)} the {before:.2f}x before; the measured one, "
                   f"{cut:.2f}x, is {_trend(cut, before)} it. " + why)  # fmt: skip
    print("\n".join(textwrap.wrap(verdict, 78)))
    return right, verdict
