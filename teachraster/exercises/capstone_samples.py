"""The MSAA scene's coverage: the student's ``covers`` asked at every sample position.

The pipeline's coverage rule runs at pixel centres only (a one-sample stage:
:mod:`teachraster.pipeline.planning.overrides`), so a ``covers`` that ignores the point it is
given, and tests the pixel's centre instead, drew every other scene right (r148 D12-6). Here
the student's ``covers`` is asked at each of the frame's sample positions (D3D's standard 4×
pattern, the offsets the render used) for every triangle whose box holds the pixel, beside
the package's top-left rule at the same points (:func:`.coverage.covered`): the scene compares
which triangles cover each sample, as well as the resolved image.
"""

from __future__ import annotations

import numpy as np

from ..core.snapping import snap
from .coverage import covered
from .coverage import explain_pixel as explain_coverage


class Sampled:
    """A traced MSAA frame with ``sample_cover`` (H, W, S): Σ 2^t over the triangles t that
    cover each sample; everything else is the frame's."""

    def __init__(self, frame, sample_cover: np.ndarray):
        self.frame, self.sample_cover = frame, sample_cover

    def __getattr__(self, name):
        return getattr(self.frame, name)


def triangles(frame) -> list[tuple[int, np.ndarray]]:
    """(triangle, snapped window x, y (3, 2)) of each piece the frame's trace holds."""
    window = frame.trace.window
    parent = frame.trace.parent
    return [(int(parent[k]), snap(window[k, :, :2])) for k in range(len(window))
            if np.isfinite(window[k, :, :2]).all()]  # fmt: skip


def _points(xy: np.ndarray, offsets: np.ndarray, h: int, w: int):
    """(pixels (n, 2) rows and columns, points (n, S, 2)) of the frame's pixels in the box of
    ``xy`` and their sample positions."""
    lo = np.clip(np.floor(xy.min(axis=0)).astype(int), 0, [w - 1, h - 1])
    hi = np.clip(np.ceil(xy.max(axis=0)).astype(int), 0, [w - 1, h - 1])
    rows, cols = np.mgrid[lo[1] : hi[1] + 1, lo[0] : hi[0] + 1]
    pixels = np.stack([rows.ravel(), cols.ravel()], axis=1)
    points = pixels[:, None, ::-1] + offsets[None, :, :]
    return pixels, points


def sample_cover(frame, covers=None) -> Sampled:
    """``frame`` with which triangles cover each sample: by ``covers(xy, p)`` (the student's,
    read as a bool), or by the package's rule where it is None."""
    ids = frame.sample_triangle_id
    h, w, s = ids.shape
    offsets = np.asarray(frame.trace.debug.offsets, dtype=float)
    out = np.zeros((h, w, s), dtype=np.int64)
    for t, xy in triangles(frame):
        pixels, points = _points(xy, offsets, h, w)
        if covers is None:
            hit = covered(xy, points.reshape(-1, 2)).reshape(len(pixels), s)
        else:
            hit = np.array([[bool(covers(xy.copy(), p.copy())) for p in row] for row in points])
        rows, cols = pixels[:, 0], pixels[:, 1]
        out[rows, cols] |= hit.astype(np.int64) << t
    return Sampled(frame, out)


def point_place(xy, p) -> str:
    """Where point ``p`` lies in triangle ``xy`` (either winding, exact on the snapped grid):
    "vertex" (one of them), "edge" (E = 0 on an edge and inside the others), "inside"
    (strictly) or "outside" (strictly outside some edge); "edge" for a zero-area triangle."""
    v = np.asarray(xy, dtype=float)
    p = np.asarray(p, dtype=float)
    if (v == p).all(axis=1).any():
        return "vertex"

    def e(a, b, q):
        return (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])

    area = e(v[0], v[1], v[2])
    if area == 0:
        return "edge"
    signed = np.sign(area) * np.array([e(v[k], v[(k + 1) % 3], p) for k in range(3)])
    if (signed < 0).any():
        return "outside"
    return "edge" if (signed == 0).any() else "inside"


def explain(call, named, mine, reference, row: int, col: int) -> str | None:
    """Why the samples of pixel (row, col) are covered otherwise than the package's rule
    covers them (the first triangle and sample that differ), or None where they agree.
    ``call(xy, p)``: the student's covers, (answer, "") or (None, why not); ``named(where,
    centre)``: the words for its mistake at a point ``where`` (:func:`point_place`),
    ``centre`` those of a covers that tests the pixel's
    centre, offered where :func:`as_at_centre` holds (the grid's order, one place for it)."""
    ours, yours = reference.sample_cover[row, col], mine.sample_cover[row, col]
    offsets = np.asarray(reference.trace.debug.offsets, dtype=float)
    for t, xy in triangles(reference):
        for k, offset in enumerate(offsets):
            mine_k, ours_k = int(yours[k]) >> t & 1, int(ours[k]) >> t & 1
            if mine_k == ours_k:
                continue
            p = np.array([col, row], dtype=float) + offset
            got, error = call(xy, p)
            said = error or f"your covers({_xy(xy)}, ({p[0]:g}, {p[1]:g})) returned {got!r}"
            why, _, _ = explain_coverage(xy, p, bool(ours_k))
            why = why.replace("centre (", "sample (", 1)
            centre = ""
            if not error and as_at_centre(mine, reference):
                centre = (f"; your covers answers as at the pixel's centre ({col + 0.5:g}, "
                          f"{row + 0.5:g}), not at the point p it is given: with 4 samples "
                          "it is asked at each sample position, so test p itself")  # fmt: skip
            likely = named(point_place(xy, p), centre)
            return (f"triangle {t}, sample {k} at ({p[0]:g}, {p[1]:g}) (offset "
                    f"({offset[0]:g}, {offset[1]:g}) from the pixel's corner): {said}; the "
                    f"package: {why}{likely}")  # fmt: skip
    return None


def as_at_centre(mine, reference) -> bool:
    """Whether the student's covers answers as the rule does at the pixel's centre on every
    sample of every pixel where the frames' sample coverage differs (r273 12-1: a covers
    returning False, or handling one winding, matched the centre at the one sample shown and
    was told it tests the centre): only a covers that tests the centre gives that."""
    differ = np.argwhere((mine.sample_cover != reference.sample_cover).any(axis=2))
    if not len(differ):
        return False
    centres = differ[:, ::-1] + 0.5
    yours = mine.sample_cover[differ[:, 0], differ[:, 1]]
    for t, xy in triangles(reference):
        at_centre = covered(xy, centres.astype(float))
        if not ((yours >> t & 1).astype(bool) == at_centre[:, None]).all():
            return False
    return True


def _xy(xy) -> str:
    return "[" + ", ".join(f"({x:g}, {y:g})" for x, y in xy) + "]"


def ids_as_rows(used: dict, name: str) -> str:
    """r504 RAW1: "; words" where the student's ``resolve`` reads ``sample_ids`` as rows of
    ``sample_colours`` (exercise 6.2's ``resolve_fragments`` pasted as it is): it raises on a
    triangle id beyond the samples (or gives another sample's colour), and is right once
    sample k points at row k; else "".

    >>> def resolve(colours, ids, background):
    ...     rows = np.asarray(colours)
    ...     return np.mean([rows[i] if i >= 0 else background for i in ids], axis=0)
    >>> ids_as_rows({"resolve": resolve}, "resolve")[:42]
    '; sample_ids[k] is the id of the triangle '
    """
    if name != "resolve":
        return ""
    colours = np.array([[1.0, 0, 0], [np.nan] * 3, [0, 0, 1.0], [0, 1.0, 0]])
    ids, background = np.array([5, -1, 5, 7]), np.ones(3)
    rows = np.where(ids >= 0, np.arange(len(ids)), -1)
    right = np.where(ids[:, None] >= 0, colours, background).mean(axis=0)
    try:
        if np.allclose(used[name](colours, ids, background), right):
            return ""  # it reads the ids some other way
    except IndexError:
        pass
    except Exception:  # noqa: BLE001 (the student's code: anything may go wrong)
        return ""
    try:
        if not np.allclose(used[name](colours, rows, background), right):
            return ""
    except Exception:  # noqa: BLE001 (the student's code: anything may go wrong)
        return ""
    return ("; sample_ids[k] is the id of the triangle that covers sample k in the scene (5 or"
            " 7, say), not a row of sample_colours: sample k's colour is sample_colours[k]. "
            "As 12.9 says, 6.2's resolve_fragments needs sample k pointing at fragment k: "
            "np.where(sample_ids >= 0, np.arange(S), -1)")  # fmt: skip


def _answers(fn, *args) -> np.ndarray | None:
    """``fn(*args)`` as 3 floats, or None where it raises or answers otherwise."""
    try:
        return np.asarray(fn(*args), dtype=float).reshape(3)
    except Exception:  # noqa: BLE001 (the student's code: anything may go wrong)
        return None


def nan_weighed(used: dict, name: str) -> str:
    """r510 WF1: "; words" where the student's ``resolve`` weighs each uncovered sample's NaN
    colour by 0 (6.2's ``resolve_fragments`` summing every fragment row times the samples it
    shows, through 12.9's mapping): NaN with the NaN rows as they are, right with any
    numbers there (0 × NaN is NaN); else "".

    >>> def resolve(colours, ids, background):
    ...     ids, total = np.asarray(ids), (np.asarray(ids) < 0).sum() * np.asarray(background)
    ...     for k, colour in enumerate(np.asarray(colours)):
    ...         total = total + (ids == k).sum() * colour
    ...     return total / len(ids)
    >>> nan_weighed({"resolve": resolve}, "resolve")[:40]
    '; the uncovered samples hold NaN colours'
    """
    if name != "resolve":
        return ""
    colours = np.array([[1.0, 0, 0], [np.nan] * 3, [0, 0, 1.0], [np.nan] * 3])
    ids, background = np.array([0, -1, 2, -1]), np.array([1.0, 1.0, 0.5])
    right = np.where(ids[:, None] >= 0, colours, background).mean(axis=0)
    got = _answers(used[name], colours.copy(), ids.copy(), background.copy())
    if got is None or not np.isnan(got).any():
        return ""
    for filler in (0.0, 7.0):
        filled = np.where(np.isnan(colours), filler, colours)
        again = _answers(used[name], filled, ids.copy(), background.copy())
        if again is None or not np.allclose(again, right):
            return ""
    return ("; the uncovered samples hold NaN colours (no triangle wrote them), and your "
            "resolve still multiplies each by its weight of 0: 0 × NaN is NaN, not 0 (with "
            "any number in those rows it answers right; exercise 6.2's fragments are never "
            "NaN). Read only the covered samples' colours: sample_colours[sample_ids >= 0], "
            "or those rows replaced by the background before you weigh them")  # fmt: skip


def resolve_slip(used: dict, name: str) -> str:
    """r510 HN2/HN3: "; words" where the student's ``resolve`` shows one colour for many
    samples: the first covered sample's colour for every covered sample, or each triangle
    id's first colour for all of that id's samples (samples of one triangle differ: each is
    shaded at its own position); else "".

    >>> def resolve(colours, ids, background):
    ...     first = np.asarray(colours)[np.flatnonzero(np.asarray(ids) >= 0)[0]]
    ...     n = (np.asarray(ids) >= 0).sum()
    ...     return (n * first + (len(ids) - n) * np.asarray(background)) / len(ids)
    >>> resolve_slip({"resolve": resolve}, "resolve")[:38]
    '; you gave every covered sample the co'
    """
    if name != "resolve":
        return ""
    colours = np.array([[0.8, 0.1, 0], [0.1, 0.7, 0.2], [np.nan] * 3, [0, 0.2, 0.9],
                        [0.5, 0.4, 0.3], [np.nan] * 3])  # fmt: skip
    # six samples: a median of an even count is no sample's colour (r449 W22 is named so)
    ids, background = np.array([3, 3, -1, 5, 5, -1]), np.array([1.0, 1.0, 1.0])
    covered = ids >= 0
    got = _answers(used[name], colours.copy(), ids.copy(), background.copy())
    if got is None:
        return ""
    first = colours[np.flatnonzero(covered)[0]]
    one_colour = (covered.sum() * first + (~covered).sum() * background) / len(ids)
    per_id = np.array([colours[np.flatnonzero(ids == t)[0]] if t >= 0 else background
                       for t in ids]).mean(axis=0)  # fmt: skip
    shown = [k for k in np.flatnonzero(covered) if np.allclose(got, colours[k])]
    if np.allclose(got, one_colour):
        what = ("every covered sample the colour of the first covered sample: each sample "
                "shows its own colour (other triangles' differ, and one triangle's too, each "
                "shaded at its own position)")  # fmt: skip
    elif np.allclose(got, per_id):
        what = ("every covered sample the colour of the first sample of its triangle (one "
                "colour per id): the samples of one triangle have colours of their own (each "
                "is shaded at its own position)")  # fmt: skip
    elif shown:
        what = (f"the pixel one sample's colour (sample {shown[0]}'s) alone: it shows its whole "
                "area, each of the S samples standing for an equal share of it")  # fmt: skip
    else:
        return ""
    return (f"; you gave {what}, so weigh each sample's own colour, sample_colours[k], and the "
            "background for each uncovered one, and take their mean")  # fmt: skip
