"""Exercise ``hiz_rejects`` (lesson 10): a tighter Hi-Z bound for one tile.

Hi-Z keeps, per tile, the farthest depth stored there, and rejects a triangle's block in the
tile when a lower bound on the triangle's depth there is at or behind it (every fragment would
fail the depth test, strictly nearer passes). Lesson 10 §7 builds the bound from the plane's
minimum over all the tile's pixel centres (at one of its four extreme centres) and the nearest
vertex's depth. The exercise asks for a tighter one, still a few numbers per tile: no fragment
lies outside the triangle's bounding box, so the plane is minimised over only the tile's pixel
centres inside that box (its border included), at the four extreme centres of that smaller
rectangle, and no nearer than the nearest vertex; a box holding no centre of the tile leaves
the triangle no fragment there (the bound is +inf: the block is rejected). The lesson's bound
is safe but looser: named, not taken (r126 N8-1); so is the bound clamped to the vertices'
depth range at the far end too (r214: the farthest vertex bounds a fragment from behind only),
while +inf where the plane lies beyond the farthest vertex at every centre in question (no
fragment there) is accepted as tighter. A tile with an empty pixel (+inf) rejects only a
triangle with no fragment in it; read as GL's clear value 1.0 instead, it also rejects one at
exactly depth 1.0, which GL_LESS fails there, and that verdict is accepted too (r248 S2).
Two mistakes in one answer (:data:`PAIRS`: "strict" beside a bound's slip, ``int()`` at both
ends of the box) are each named on the failures they decide (r376 F2, F5).

Expected answers: the renderer's own pieces, as :mod:`teachraster.pipeline.visibility.hierarchical_z`
uses them: the depth plane :meth:`~teachraster.pipeline.rasterization.batched_fill.Fragments.plane`
(clamped to the vertices' depth range) at the extreme centres of the tile cut to the box,
against the tile's largest stored depth.
"""

from __future__ import annotations

import re
from dataclasses import replace

import numpy as np

from ..core.edges import setup_edges
from ..core.snapping import SUBPIXEL_BITS
from ..pipeline.rasterization.batched_fill import Fragments, weight_source
from .answers import as_bool
from .cases import SEED, seeded
from .coverage import covered
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .package_answers import CHECKER_WORDS
from .scalars import full_number, num

#: Tile side of the cases (hardware Hi-Z uses 8 × 8).
TILE = 8
#: How far a near tie's farthest stored depth lies from the triangle's nearest depth: far
#: beyond float64's rounding of any form of the plane (r114 D8-2 measured at most 1e-15 over
#: 5400 ties for the gradients, a 3×3 solve, the normal and the notes' A x + B y + D), far
#: within float32's (1e-8 typically).
NEAR_TIE = 2.0**-36


def _corners(row0: int, col0: int, size: int):
    last_r, last_c = row0 + size - 1, col0 + size - 1
    return np.array([row0, row0, last_r, last_r]), np.array([col0, last_c, col0, last_c])


def plane_at(xyz: np.ndarray, rows, cols, clamp: bool = True) -> np.ndarray:
    """The triangle's depth plane at pixel centres (rows, cols), as the renderer evaluates it
    (``clamp``: within its vertices' depths, the renderer's own; else the bare plane)."""
    xyz = np.asarray(xyz, dtype=float)
    if clamp:  # the renderer's set-up (its weights from the unsnapped positions) and plane
        xy = xyz[None, :, :2]
        src, area, _, _ = weight_source(xy, setup_edges(xy, SUBPIXEL_BITS), False)
        probe = Fragments(np.zeros(len(rows), np.int64), np.asarray(rows), np.asarray(cols),
                          np.zeros(1, np.int8), src, area)  # fmt: skip
        return probe.plane(xyz[None, :, 2])
    return _bare_plane(xyz, rows, cols)


def _bare_plane(xyz, rows, cols, at: float = 0.5, signs=(1, 1), swapped: bool = False):
    """The plane through the three vertices at (cols + ``at``, rows + ``at``), the pixel
    centres by default, in the arrays' own precision; ``signs`` multiply its gradient's
    components (a student's slip in solving for it, r198 B); ``swapped``: dz/dx and dz/dy
    exchanged (r267 half-named 4)."""
    (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = xyz
    area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    a = signs[0] * ((z2 - z1) * (y3 - y1) - (z3 - z1) * (y2 - y1)) / area
    b = signs[1] * ((z3 - z1) * (x2 - x1) - (z2 - z1) * (x3 - x1)) / area
    if swapped:
        a, b = b, a
    half = np.asarray(at, dtype=np.asarray(xyz).dtype)
    return z1 + a * (cols + half - x1) + b * (rows + half - y1)


def box_span(lo: float, hi: float, first: int, size: int, open_high: bool = False):
    """The pixels (first … first + size − 1) whose centres lie in [lo, hi] (``open_high``:
    in [lo, hi)), as (first, last), or None when no centre does."""
    last = int(np.ceil(hi - 0.5)) - 1 if open_high else int(np.floor(hi - 0.5))
    a, b = max(first, int(np.ceil(lo - 0.5))), min(first + size - 1, last)
    return (a, b) if a <= b else None


def _box_corners(xyz, row0: int, col0: int, size: int, open_high: bool = False):
    """The extreme centres (rows, cols) of the tile's centres inside the triangle's bounding
    box (r126 N8-1; ``open_high``: without its right and bottom border), or None when the
    box holds none of them."""
    xy = np.asarray(xyz, dtype=float)[:, :2]
    cs = box_span(xy[:, 0].min(), xy[:, 0].max(), col0, size, open_high)
    rs = box_span(xy[:, 1].min(), xy[:, 1].max(), row0, size, open_high)
    if cs is None or rs is None:
        return None
    return np.array([rs[0], rs[0], rs[1], rs[1]]), np.array([cs[0], cs[1], cs[0], cs[1]])


def lower_bound(
    xyz, row0: int, col0: int, size: int, open_high: bool = False, far_empty: bool = False
) -> float:
    """The task's bound: the larger of the plane's minimum over the extreme centres of the tile
    cut to the triangle's bounding box and the nearest vertex's depth (+inf: no centre of the
    tile lies in the box). The renderer's plane is also clamped *above*, to the farthest
    vertex's depth; where all four centres lie beyond it that clamp lowered the bound below
    the task's rule (r114 D8-6, a tile the rule rejects and the reference kept): there the
    bare plane's minimum is the bound. ``open_high``: the box without its right and bottom
    border, whose centres the top-left rule never covers (r137 D8-2: accepted too).
    ``far_empty``: +inf where the plane lies beyond the farthest vertex at every one of those
    centres, which then holds no fragment (r214 item 10: accepted too, as safe and tighter)."""
    box = _box_corners(xyz, row0, col0, size, open_high)
    if box is None:
        return float("inf")
    if far_empty and _beyond_far(xyz, *box):
        return float("inf")
    return _bound_at(xyz, *box)


def _beyond_far(xyz, rows, cols) -> bool:
    """Does the bare plane lie beyond the farthest vertex at every centre of the rectangle
    whose extreme centres are (rows, cols)? (Its minimum there is at one of them.)"""
    far = float(np.max(np.asarray(xyz, dtype=float)[:, 2]))
    return bool(plane_at(xyz, rows, cols, clamp=False).min() > far)


def _bound_at(xyz, rows, cols) -> float:
    """The plane's minimum at centres (rows, cols), no nearer than the nearest vertex."""
    near = float(plane_at(xyz, rows, cols).min())
    if near >= float(np.max(np.asarray(xyz, dtype=float)[:, 2])):
        near = max(near, float(plane_at(xyz, rows, cols, clamp=False).min()))
    return near


def bound_site(xyz, row0: int, col0: int, size: int):
    """Where :func:`lower_bound` is taken, for the figure: ``(row, col, bound, by_vertex)``,
    the extreme centre of the tile cut to the box where the plane is nearest, the bound, and
    whether the nearest vertex's depth sets it there (the plane runs nearer than any vertex);
    None when the box holds no centre of the tile."""
    box = _box_corners(xyz, row0, col0, size)
    if box is None:
        return None
    rows, cols = box
    bare = plane_at(xyz, rows, cols, clamp=False)
    # r214: the bare plane's nearest centre (the renderer's plane, clamped at the farthest
    # vertex, ties all four where the plane lies beyond it there)
    k = int(np.argmin(bare))
    by_vertex = float(bare[k]) < float(np.min(np.asarray(xyz, dtype=float)[:, 2]))
    return int(rows[k]), int(cols[k]), _bound_at(xyz, rows, cols), by_vertex


def tile_bound(xyz, row0: int, col0: int, size: int) -> float:
    """Lesson 10 §7's bound: the same over all the tile's pixel centres (safe, looser)."""
    return _bound_at(xyz, *_corners(row0, col0, size))


def expected_reject(xyz, row0, col0, size, buffer) -> bool:
    return bool(lower_bound(xyz, row0, col0, size) >= np.max(buffer))


def _hiz_cases(rng, word) -> list[tuple[str, tuple, bool]]:
    """(label, (xyz, row0, col0, size, buffer), rejected): named tiles and random ones."""
    slope = np.array([[0.0, 0.0, 0.30], [40.0, 0.0, 0.70], [0.0, 40.0, 0.50]])
    flat = np.array([[0.0, 0.0, 0.5], [40.0, 0.0, 0.5], [0.0, 40.0, 0.5]])
    full = np.full((TILE, TILE), 0.45)
    named = [
        ("a flat triangle behind a full tile", (flat, 8, 8, TILE, full)),
        ("the same triangle at exactly the tile's farthest depth", (flat, 8, 8, TILE,
                                                                    np.full((TILE, TILE), 0.5))),
        ("in front of the tile", (flat - [0, 0, 0.2], 8, 8, TILE, full)),
        ("behind, but one pixel of the tile is still empty", (flat, 8, 8, TILE,
                                                              _with(full, (3, 4), np.inf))),
        ("a sloped triangle, nearest vertex in front, the tile's part behind",
         (slope, 16, 16, TILE, np.full((TILE, TILE), 0.45))),
        ("a sloped triangle reaching in front at the tile's near corner",
         (slope, 0, 0, TILE, np.full((TILE, TILE), 0.33))),
        # the farthest vertex behind the tile, the tile's part of the plane in front: tells
        # "the farthest vertex" from "the plane's farthest corner" (both reject the case above)
        ("a sloped triangle whose far vertex lies behind the tile, its part here in front",
         (slope, 0, 0, TILE, full)),
        ("the tile's farthest pixel decides", (slope, 8, 16, TILE,
                                               _with(np.full((TILE, TILE), 0.2), (7, 7), 0.6))),
        # r49/r64 08-5: the plane alone failed one random tie only
        ("a tile beyond a vertex: the plane there runs nearer than any fragment",
         (slope + [10, 10, 0], 8, 8, TILE, np.full((TILE, TILE), 0.29))),
        # r64 08-4: the plane's minimum over the covered centres only is tighter (and safe),
        # but costs a test per pixel: the bound asked is the corners' and the nearest vertex's
        ("a sliver crossing the tile: its covered centres all lie behind",
         (_SLIVER, 0, 0, TILE, np.full((TILE, TILE), 0.1662))),
        *_steep_cases(),
        *_box_cases(),
        *_tile_size_cases(),  # r141 D8.2-1
        *_border_cases(),  # r131 D8-1
        *_one_axis_cases(),  # r131 D8-6
        *_r137_cases(),
        *_beyond_far_cases(),  # r214 item 1
        *_one_line_cases(),  # r221 items 2, 4
        *_odd_border_cases(),  # r232 wrongly passed 2
        *_int_both_cases(),  # r376 F2
    ]  # fmt: skip
    for k in range(18):
        row0, col0 = (int(v) * TILE for v in rng.integers(0, 4, 2))
        # vertices around the tile's middle, less than half a turn apart: the middle (a pixel
        # centre of the tile) is inside, so the triangle has a block here
        centre = np.array([col0 + TILE / 2 - 0.5, row0 + TILE / 2 - 0.5])
        turn = (
            rng.uniform(0, 2 * np.pi) + np.array([0, 2, 4]) * np.pi / 3 + rng.uniform(-0.4, 0.4, 3)
        )
        reach = rng.uniform(5, 30, 3)
        xy = centre + reach[:, None] * np.column_stack([np.cos(turn), np.sin(turn)])
        xyz = np.column_stack([np.round(xy * 256) / 256, rng.uniform(0.1, 0.9, 3)])
        near = lower_bound(xyz, row0, col0, TILE)
        # near ties only in the fixed cases (checked once): float32's rounding (about 1e-8
        # here) decides them, float64's (at most 1e-15, r114 D8-2) never. r114 D8-2: ties set
        # to the renderer's plane bit for bit failed a right float64 plane in the notes' own
        # form (A x + B y + D), which rounds otherwise by an ulp, and called it float32
        tie = k % 3 == 0 and word == "random"
        gap = NEAR_TIE * (1 if k % 2 == 0 else -1)  # kept, rejected
        buffer = near + (gap if tie else rng.uniform(-0.05, 0.05, (TILE, TILE)))
        buffer = np.broadcast_to(buffer, (TILE, TILE)).copy()
        buffer[rng.integers(0, TILE), rng.integers(0, TILE)] += rng.choice([-0.01, 0.0, 0.01])
        named.append((f"{word} {k + 1}", (xyz, row0, col0, TILE, buffer)))
    return [(label, args, expected_reject(*args)) for label, args in named]


#: A steep triangle (its depth grows 0.05 per px along one axis, 0.025 along the other) seen
#: from four sides: (words, x mirrored, y mirrored, x and y swapped, the tile beside it
#: (row0, col0)).
_STEEP = np.array([[0.0, 0.0, 0.1], [16.0, 0.0, 0.9], [0.0, 16.0, 0.5]])
#: r126 N8-1: a steep triangle whose nearest vertex (8, 0) is no corner of its bounding box.
_APEX = np.array([[8.0, 0.0, 0.1], [16.0, 16.0, 0.9], [0.0, 16.0, 0.5]])
_SIDES = (
    ("growing right and down", False, False, False, (0, 8)),
    ("growing left and down", True, False, False, (0, 16)),
    ("growing right and up", False, True, False, (24, 8)),
    ("growing down and right", False, False, True, (8, 0)),
)


def _steep_cases() -> list[tuple[str, tuple]]:
    """r126 D8-3: the outer-corner and plane-only mistakes were each caught by one case (one
    a random tie 1.5e-11 wide). Beside the triangle its plane is 0.0375 nearer at the tile's
    outer corners than at its extreme pixel centres (0.5 against 0.5375), and the farthest
    stored depth 0.5188 lies between. :data:`_APEX`'s nearest vertex (depth 0.1) lies in the
    middle of its box's side: in the tile in the box's corner beside it the bare plane at the
    extreme centres runs to -0.069, and the stored depth 0.05 lies between."""
    out = []
    for words, fx, fy, swap, beside in _SIDES:
        xyz = _STEEP[:, [1, 0, 2]] if swap else _STEEP.copy()
        xyz[:, 0] = 32 - xyz[:, 0] if fx else xyz[:, 0]
        xyz[:, 1] = 32 - xyz[:, 1] if fy else xyz[:, 1]
        out.append((f"a steep plane {words}: behind at the tile's extreme pixel centres, in "
                    "front at its outer corners", (xyz, *beside, TILE, np.full((TILE, TILE), 0.5188))))  # fmt: skip
        if not (fx or fy or swap):  # r149 M3: the stored depth between the outer corners'
            # bound (0.5, rejects) and the nearest vertex's (0.1, keeps) tells them apart
            out.append(("a steep plane growing right and down, the stored depth between the "
                        "plane at the tile's outer corners and the nearest vertex",
                        (xyz.copy(), *beside, TILE, np.full((TILE, TILE), 0.3))))  # fmt: skip
        # r126 N8-1: the nearest vertex in the middle of its box's side, the tile in the box's
        # corner beside it (inside the box: the box alone does not lift the plane there)
        apex = _APEX[:, [1, 0, 2]] if swap else _APEX.copy()
        apex[:, 0] = 32 - apex[:, 0] if fx else apex[:, 0]
        apex[:, 1] = 32 - apex[:, 1] if fy else apex[:, 1]
        out.append((f"a tile in a corner of the bounding box of a steep plane {words}, beside "
                    "its nearest vertex: the plane runs nearer there than any fragment",
                    (apex, 24 if fy else 0, 24 if fx else 0, TILE, np.full((TILE, TILE), 0.05))))  # fmt: skip
    return out


#: r126 N8-1: a small right triangle (legs 3.6 px), its depth growing 0.02 per px along x and
#: y from its nearest vertex (0.3). Moved to (4.2, 4.2) in an 8-px tile at (0, 0), the tile's
#: centres inside its box run from (4.5, 4.5) to (7.5, 7.5): the plane's minimum there is
#: 0.312, over the whole tile 0.152, so lesson 10's bound is the vertex's 0.3.
_SMALL = np.array([[0.2, 0.2, 0.3], [3.8, 0.2, 0.372], [0.2, 3.8, 0.372]])


#: r126 N8-1: a large triangle whose box starts at x = 3.5, the centre of the tile's column 3,
#: its depth growing with x: over the tile's centres inside the box the plane is nearest at
#: (3.5, 0.5), 0.4005; over the whole tile at (0.5, 0.5), 0.34, below the nearest vertex's 0.38.
_AT_CENTRE = np.array([[3.5, -20.0, 0.38], [40.0, -20.0, 1.11], [3.5, 30.0, 0.43]])


def _box_cases() -> list[tuple[str, tuple]]:
    """r126 N8-1: tiles where the triangle's bounding box decides: lesson 10's bound over the
    whole tile keeps them, the box's rejects; the box's own corners, or the pixels it touches,
    keep the second; the third's box holds no centre of the tile at all."""
    near_corner = _SMALL + [4, 4, 0]  # its box's centres: (4.5, 4.5) … (7.5, 7.5)
    # mirrored: (0.5, 0.5) … (3.5, 3.5); rounded, as below: the sums' float noise
    # (0.20000000000000018) was printed in each failure (r232 C2)
    far_corner = np.round(_SMALL * [-1, -1, 1] + [4, 4, 0], 12)
    past = _SMALL * [0.8, 0.8, 1] + [4.54, 4.54, 0]  # box from 4.7: first centre 5.5, not 4.5
    # box from x = 15.7: past the centre 15.5
    beyond = np.round(_SMALL * [4, 4, 1] + [14.9, 1, 0], 12)
    big = _SMALL * [2, 2, 1] + [6, 6, 0]  # a 16-px tile around a 7-px triangle
    buffer = np.full((TILE, TILE), 0.305)
    return [
        ("a small triangle in the tile's bottom-right corner, its depth growing away from "
         "the tile's middle", (near_corner, 0, 0, TILE, buffer)),
        ("a small triangle in the tile's top-left corner, its depth growing away from the "
         "tile's middle", (far_corner, 0, 0, TILE, buffer)),
        ("a triangle whose bounding box starts 0.2 px past the centre of a pixel",
         (past, 0, 0, TILE, np.full((TILE, TILE), 0.32))),
        # r198 C1: the box starts at x = 15.7, inside the tile's last column (it ends at
        # x = 16): it misses that column's centre (15.5), not the tile
        ("a triangle whose bounding box holds no centre of the tile (it starts 0.2 px past "
         "the last one), one pixel still empty",
         (beyond, 0, 8, TILE, _with(np.full((TILE, TILE), 0.45), (2, 7), np.inf))),
        ("a large triangle whose bounding box starts exactly at a pixel centre of the tile",
         (_AT_CENTRE, 0, 0, TILE, np.full((TILE, TILE), 0.39))),
        ("a 16-px tile around a small triangle", (big, 0, 0, 2 * TILE,
                                                  np.full((2 * TILE, 2 * TILE), 0.301))),
    ]  # fmt: skip


def _tile_size_cases() -> list[tuple[str, tuple]]:
    """r141 D8.2-1: the 16-px box case decides inside the tile's first 8 × 8 pixels, so a tile
    taken as 8 px wide (size = 8, col0 + 7) passed every case. Here the bound (0.302) lies at
    the centre (13.5, 13.5) and the farthest stored depth (0.35) at pixel (12, 12): the tile
    is kept; cut at 8 px the bound is 0.422 and the first 8 × 8 store only 0.2 (rejected)."""
    big_far = _SMALL * [-2, -2, 1] + [14, 14, 0]  # nearest at (13.6, 13.6)
    far_buffer = _with(np.full((2 * TILE, 2 * TILE), 0.2), (12, 12), 0.35)
    return [
        ("a 16-px tile, the triangle's depth nearest beyond the tile's first 8 × 8 pixels, "
         "its farthest stored depth there too", (big_far, 0, 0, 2 * TILE, far_buffer)),
    ]  # fmt: skip


#: r131 D8-1: a vertex exactly on the pixel centre (2.5, 0.5), the triangle's nearest point:
#: that centre lies on the box's left and top border, and the triangle covers it (a top and
#: a left edge meet there). Without it the bound is 0.247, at (3.5, 1.5), behind 0.2.
_ON_CENTRE = np.array([[2.5, 0.5, 0.1], [7.5, 0.5, 0.5], [2.5, 6.5, 0.5]])
#: An axis-aligned edge on the column of centres x = 2.5, the plane nearest along it (0.1)
#: and growing 0.05 per px to the right; turned to lie on each side of its box in turn.
_ON_COLUMN = np.array([[2.5, -4.0, 0.1], [12.5, 4.0, 0.6], [2.5, 12.0, 0.1]])


def _border_cases() -> list[tuple[str, tuple]]:
    """r131 D8-1: centres exactly on the triangle's bounding box, where its depth is nearest:
    a bound leaving them out (a strict inequality, or ⌊xmin + ½⌋) was 0.05 or more too far,
    behind the stored 0.13 or 0.2, and passed every case: on the left and top sides a
    rejection there drops a covered fragment."""
    out = [
        (
            "a vertex exactly on a pixel centre, the triangle's nearest point: the box's "
            "top-left corner holds it",
            (_ON_CENTRE, 0, 0, TILE, np.full((TILE, TILE), 0.2)),
        )
    ]
    for side, (fx, swap) in {"left": (False, False), "right": (True, False),
                             "top": (False, True), "bottom": (True, True)}.items():  # fmt: skip
        xyz = _ON_COLUMN.copy()
        xyz[:, 0] = 8 - xyz[:, 0] if fx else xyz[:, 0]  # the column x = 5.5 for the right
        xyz = xyz[:, [1, 0, 2]] if swap else xyz
        out.append(
            (
                f"an edge exactly on a line of pixel centres, the box's {side} side, "
                "where the depth is nearest",
                (xyz, 0, 0, TILE, np.full((TILE, TILE), 0.13)),
            )
        )
    return out


#: r131 D8-6: a triangle reaching beyond the tile's right side, its box's rows 2 … 4 of the
#: tile, nearest at (7.5, 2.5) (0.35); the tile's top row, outside the box, runs to 0.29.
_BEYOND_RIGHT = np.array([[4.5, 2.2, 0.401], [20.0, 2.2, 0.091], [20.0, 5.2, 0.181]])


def _one_axis_cases() -> list[tuple[str, tuple]]:
    """r131 D8-6: the box cut from the tile in x only (or y only) failed the same cases as
    the box's own corners; here the box's corners lie on the extreme centres in the axis
    the tile cuts, and only the other axis's cut decides."""
    return [("a triangle beyond the tile's right side, its box over the tile's middle rows",
             (_BEYOND_RIGHT, 0, 0, TILE, np.full((TILE, TILE), 0.32))),
            ("a triangle beyond the tile's bottom side, its box over the tile's middle columns",
             (_BEYOND_RIGHT[:, [1, 0, 2]], 0, 0, TILE, np.full((TILE, TILE), 0.32)))]  # fmt: skip


#: r137 D8-1: the nearest vertex (depth 0.1) far outside the tile, the two inside it at 0.5,
#: farther than the plane's minimum there (0.363 at the covered centre (7.5, 1.5)).
_NEAR_OUTSIDE = np.array([[1.0, 1.0, 0.5], [20.0, 1.0, 0.1], [1.0, 20.0, 0.5]])
#: r137 D8-6: a triangle left of the tile whose box ends at x = 0.3, between −½ and ½: no
#: centre of the tile lies in it (int(0.3 − ½) is 0, not −1).
_LEFT_OF = np.array([[-4.0, 1.0, 0.9], [0.3, 2.0, 0.9], [-2.0, 6.0, 0.9]])
#: r137 D8-5: a triangle whose box ends at x = 5.2, 0.3 px before the centre 5.5, its depth
#: falling to the right and rising downwards: over the box's centres the plane is nearest at
#: (4.5, 0.5), 0.265; at the box's own corner (5.2, 0.5) 0.258, at the centre one column
#: past the box (5.5, 0.5) 0.255; the stored 0.2565 lies between the last two.
_ENDS_BEFORE = np.array([[5.2, 20.0, 0.648], [-8.0, -10.0, 0.18], [-8.0, 30.0, 0.98]])
#: r137 D8-10: a small triangle in the tile's top-left corner (its box's pixels 1 … 3).
_CORNER = np.array([[1.2, 1.2, 0.5], [3.8, 1.2, 0.5], [1.2, 3.8, 0.5]])


def _r137_cases() -> list[tuple[str, tuple]]:
    """r137: four wrong answers passed every case: the nearest vertex taken inside the tile
    (unsafe, D8-1), an empty box tested in x only (D8-3), ``int()`` for floor (D8-6), the
    stored depths read inside the box only (D8-10); and one past the box's end was named the
    box's own corners (D8-5)."""
    one_empty = _with(np.full((TILE, TILE), 0.3), (0, 0), np.inf)
    below = np.array([[2.0, 7.7, 0.5], [6.0, 7.7, 0.5], [4.0, 12.0, 0.2]])
    thin = np.array([[1.0, 3.6, 0.5], [7.0, 3.6, 0.5], [4.0, 4.4, 0.2]])
    left_buffer = _with(np.full((TILE, TILE), 0.5), (3, 3), np.inf)
    return [
        ("the triangle's nearest vertex far outside the tile, the two inside it farther than "
         "the plane there", (_NEAR_OUTSIDE, 0, 0, TILE, np.full((TILE, TILE), 0.4))),
        ("a triangle whose bounding box starts 0.2 px below the tile's last row of centres, "
         "one pixel still empty", (below, 0, 0, TILE, one_empty)),
        ("a thin triangle between two rows of the tile's centres, one pixel still empty",
         (thin, 0, 0, TILE, one_empty)),
        ("a triangle left of the tile, its bounding box ending at x = 0.3, before the first "
         "centre", (_LEFT_OF, 0, 0, TILE, left_buffer)),
        ("a triangle above the tile, its bounding box ending at y = 0.3, before the first "
         "centre", (_LEFT_OF[:, [1, 0, 2]], 0, 0, TILE, left_buffer)),
        ("a triangle whose bounding box ends 0.3 px before a centre, its depth falling towards "
         "it", (_ENDS_BEFORE, 0, 0, TILE, np.full((TILE, TILE), 0.2565))),
        ("a small triangle in the tile's corner, the tile's last pixel still empty",
         (_CORNER, 0, 0, TILE, _with(np.full((TILE, TILE), 0.4), (7, 7), np.inf))),
        ("a small triangle in the tile's corner, the tile's farthest pixel outside its box",
         (_CORNER, 0, 0, TILE, _with(np.full((TILE, TILE), 0.45), (7, 7), 0.6))),
    ]  # fmt: skip


#: r214 item 1: a right triangle (legs 32 px, its depth growing 0.01875 per px in x and 0.009375
#: in y from its nearest vertex, 0.1 … 0.7) and one turned (its nearest vertex at (40, 4)): a tile
#: inside its bounding box, beyond its long edge, where the plane at every centre of the tile lies
#: beyond the farthest vertex (0.789 against 0.7; 0.904 against 0.8).
_BEYOND_FAR = (
    (np.array([[0.0, 0.0, 0.1], [32.0, 0.0, 0.7], [0.0, 32.0, 0.4]]), 24, 24, 0.75),
    (np.array([[40.0, 4.0, 0.15], [40.0, 36.0, 0.55], [8.0, 4.0, 0.8]]), 24, 8, 0.85),
)


def _beyond_far_cases() -> list[tuple[str, tuple]]:
    """r214 item 1: the bound clamped to the vertices' depth range, [z_min, z_max], passed every
    case: none had the plane beyond the farthest vertex over the tile's centres in the box. Here
    it is, and the stored depth lies between the farthest vertex and the plane there: the task's
    bound rejects (so does +inf, the tile holding no fragment), the clamped one keeps."""
    return [
        (f"{words} in the bounding box beyond the long edge, where the plane lies beyond every "
         "vertex", (xyz, row0, col0, TILE, np.full((TILE, TILE), far)))
        for (xyz, row0, col0, far), words in zip(_BEYOND_FAR, ("a tile", "turned: a tile"))
    ]  # fmt: skip


#: r221 item 2: a thin triangle (depth 0.1) whose bounding box meets tile (0, 0, 8) in its last
#: column of centres only (x = 7.5; the box starts at x = 7.2): its pixels (7, 1) … (7, 6) are
#: drawn, in front of the stored 0.5.
_ONE_COLUMN = np.array([[7.2, 1.0, 0.1], [30.0, 4.0, 0.1], [7.2, 7.0, 0.1]])


def _one_line_cases() -> list[tuple[str, tuple]]:
    """r221 item 2: a box ∩ tile of one column (one row) read as empty (``first >= last``)
    passed every case: none met the tile in a single column or row. Here it does, the triangle
    in front of the stored depth: the block is kept. r221 item 4: the second's first stored
    pixel is neither the tile's nearest nor its farthest, so comparing with ``buffer[0, 0]``
    and with the tile's nearest depth give different verdicts on some case."""
    stored = np.full((TILE, TILE), 0.5)
    stored[0, 0], stored[5, 6] = 0.3, 0.05
    return [("a thin triangle whose bounding box meets the tile in one column of centres, in "
             "front of the stored depth", (_ONE_COLUMN, 0, 0, TILE, np.full((TILE, TILE), 0.5))),
            ("a thin triangle whose bounding box meets the tile in one row of centres, in front "
             "of the stored depth", (_ONE_COLUMN[:, [1, 0, 2]], 0, 0, TILE, stored))]  # fmt: skip


def _odd_border_cases() -> list[tuple[str, tuple]]:
    """r232 wrongly passed 2: round() (half to even) for the box's first column passed every
    case: :func:`_border_cases` put the box's left and top sides at 2.5 and 0.5, where half to
    even gives the right column (2, 0). :data:`_ON_COLUMN` moved one column right (x = 3.5,
    round gives 4, skipping column 3, where the depth is nearest, 0.1) and turned (y = 3.5):
    the triangle covers those centres at 0.1, in front of the stored 0.13; the column after
    lies at 0.15, behind it. Kept; round() rejects (a hole)."""
    xyz = _ON_COLUMN + [1.0, 0.0, 0.0]
    return [
        (f"an edge exactly on the {what} of pixel centres {at} = 3.5, the box's {side} side, "
         "where the depth is nearest", (v, 0, 0, TILE, np.full((TILE, TILE), 0.13)))
        for what, at, side, v in (("column", "x", "left", xyz),
                                  ("row", "y", "top", xyz[:, [1, 0, 2]]))
    ]  # fmt: skip


#: r376 F2: a triangle whose box starts at x = 2.3, inside the tile, and runs past its bottom,
#: its depth falling left and down (0.5 + 0.01·x − 0.01·y): over the tile's centres in the box
#: the plane is nearest at (2.5, 7.5), 0.45; at the box's own corner kept within the tile,
#: (2.3, 7.5), 0.448; at the centre one column before the box, (1.5, 7.5), 0.44 (int(2.3 − ½)
#: is 1). The stored 0.445 lies between the last two: the box's own corners reject, as the task
#: does, and int() at both ends keeps (both were told "the bounding box's own corners").
_BEFORE_BOX = np.array([[2.3, 2.0, 0.503], [12.0, 20.0, 0.42], [2.3, 20.0, 0.323]])


def _int_both_cases() -> list[tuple[str, tuple]]:
    """r376 F2: :data:`_BEFORE_BOX`, a column before the box nearer than the box's corner."""
    return [("a triangle whose bounding box starts 0.2 px before a centre, inside the tile, "
             "its depth falling towards the box's left side",
             (_BEFORE_BOX, 0, 0, TILE, np.full((TILE, TILE), 0.445)))]  # fmt: skip


#: r64 08-4's triangle: over tile (0, 0, 8) it covers 24 centres, all behind 0.1662, while the
#: plane at the extreme centres (and the nearest vertex) lie in front: the block is kept.
_SLIVER = np.array([[-707 / 256, -1852 / 256, 0.3494], [-1511 / 256, 5853 / 256, 0.7552],
                    [3242 / 256, 5709 / 256, 0.0654]])  # fmt: skip

# r162 C2: every case seeded (r49 drew some afresh per check: the count moved on a re-run)
hiz_cases = seeded(_hiz_cases, SEED + 60)


def _with(buffer: np.ndarray, at, value) -> np.ndarray:
    out = buffer.copy()
    out[at] = value
    return out


def same_verdict(got: bool, expected: bool, args=None) -> bool:
    """The task's verdict, or that of a bound as safe and tighter: (r137 D8-2) the half-open
    box (on the box's right and bottom border the top-left rule covers no centre: a right or
    bottom edge, or the rightmost or bottom vertex, lies there), or (r214 item 10) +inf where
    the plane lies beyond the farthest vertex at every centre in question (no fragment there);
    each with an empty pixel (+inf) read as GL's clear value too (:func:`gl_cleared`, r248 S2)."""
    if got == expected:
        return True
    if args is None:
        return False
    xyz, row0, col0, size, buffer = args
    buffers = [buffer] if np.isfinite(buffer).all() else [buffer, gl_cleared(buffer)]
    return any(
        got == tighter_reject(xyz, row0, col0, size, b, open_high=o, far_empty=f)
        for b in buffers for o in (False, True) for f in (False, True)
        if o or f or b is not buffer
    )  # fmt: skip


#: GL's default depth clear value (``glClearDepth``, lesson 05a): what a GPU's pixel that
#: nothing was drawn to holds.
GL_CLEAR_DEPTH = 1.0


def gl_cleared(buffer) -> np.ndarray:
    """The tile as GL holds it: an empty pixel (+inf, this exercise's and lesson 10's replay's
    *not yet known*) at GL's clear value, 1.0. r248 S2: a student who models the GPU (the
    tile's farthest depth after a clear is the clear value, as AMD's HTILE fast clear keeps
    it) was marked wrong on a triangle at exactly depth 1.0, which GL_LESS fails against 1.0:
    the two readings differ only there, and both verdicts are accepted."""
    return np.where(np.isinf(buffer), GL_CLEAR_DEPTH, buffer)


def tighter_reject(xyz, row0, col0, size, buffer, open_high=True, far_empty=False) -> bool:
    """The verdict of :func:`lower_bound` with its options (the half-open box by default)."""
    bound = lower_bound(xyz, row0, col0, size, open_high=open_high, far_empty=far_empty)
    return bool(bound >= np.max(buffer))


def _variants(xyz, row0, col0, size, buffer) -> dict[str, bool]:
    xyz = np.asarray(xyz, dtype=float)
    box = _box_corners(xyz, row0, col0, size)
    rows, cols = box if box is not None else _corners(row0, col0, size)
    near = lower_bound(xyz, row0, col0, size)
    far = buffer.max()
    mid_r, mid_c = row0 + (size - 1) / 2, col0 + (size - 1) / 2  # the centre x0 + size/2
    zmin = xyz[:, 2].min()
    with np.errstate(all="ignore"):
        bare = plane_at(xyz, rows, cols, clamp=False).min() if box is not None else np.inf
        return {
            # r126 N8-1: lesson 10's bound, the plane over every centre of the tile
            "whole tile": bool(tile_bound(xyz, row0, col0, size) >= far),
            "pixel box": bool(_pixel_box_bound(xyz, row0, col0, size) >= far),
            "box corners": bool(_box_own_corners(xyz, row0, col0, size) >= far),
            # r162 M2: the box's own corners and no rejection of an empty box, together (the
            # plane at the clipped corners of a box beside the tile)
            "box corners, empty kept": bool(
                _box_own_corners(xyz, row0, col0, size, empty_kept=True) >= far
            ),
            # r162: the tile's columns and rows run one past its last (col0 + size)
            "one past the tile": bool(_cut_bound(xyz, row0, col0, size, past_tile=1) >= far),
            # r131 D8-2, D8-3, D8-6: an empty box kept, the box not cut to the tile, cut in
            # one axis only; D8-1: the centres on the box's border left out
            "empty kept": bool(box is not None and near >= far),
            "box uncut": bool(_cut_bound(xyz, row0, col0, size, cut="") >= far),
            "box in x only": bool(_cut_bound(xyz, row0, col0, size, cut="x") >= far),
            "box in y only": bool(_cut_bound(xyz, row0, col0, size, cut="y") >= far),
            "border": bool(_cut_bound(xyz, row0, col0, size, border="none") >= far),
            "border low": bool(_cut_bound(xyz, row0, col0, size, border="high") >= far),
            # r137 D8-5, D8-6: one column (row) past the box's far end; int() for floor
            "one past": bool(_cut_bound(xyz, row0, col0, size, border="past") >= far),
            # r173 M1: one column (row) before the box's first, ⌈xmin − ½⌉ − 1 (was told "the
            # tile's outer corners", which gives the same verdicts on every case)
            "one before": bool(_cut_bound(xyz, row0, col0, size, border="before") >= far),
            # r206 M1: the box rounded outward (⌊xmin − ½⌋ … ⌈xmax − ½⌉, floor and ceil swapped)
            # was told "the tile's outer corners": a column (row) outside the box at both ends
            "box outward": bool(_cut_bound(xyz, row0, col0, size, border="outward") >= far),
            # r173: three answers told the rule only: the box's ½ taken the wrong way
            # (⌈xmin + ½⌉ … ⌊xmax + ½⌋), the tile one column short (col0 + size − 2), and
            # lesson 10's bound without the nearest vertex
            "half shifted": bool(_cut_bound(xyz, row0, col0, size, border="shifted") >= far),
            # r446 H5: the columns whose left edge c lies in the box, ⌈xmin⌉ … ⌊xmax⌋
            "no half": bool(_cut_bound(xyz, row0, col0, size, border="no half") >= far),
            "one short of the tile": bool(_cut_bound(xyz, row0, col0, size, past_tile=-1) >= far),
            "whole tile, bare": bool(_bare_plane(xyz, *_corners(row0, col0, size)).min() >= far),
            "int for floor": bool(_cut_bound(xyz, row0, col0, size, border="trunc") >= far),
            # r137 D8-1, D8-10: the nearest vertex inside the tile; the stored depths read
            # inside the box only
            "vertex in tile": bool(_vertex_in_tile_bound(xyz, row0, col0, size, bare) >= far),
            # r141 D8.2-2: the tile taken half-open (a vertex on its right or bottom side out)
            "vertex in tile, half-open": bool(
                _vertex_in_tile_bound(xyz, row0, col0, size, bare, open_high=True) >= far
            ),
            # r141 D8.2-2: int(xmin + ½) for ⌈xmin − ½⌉ and int(xmax − ½) for ⌊xmax − ½⌋
            "int round": bool(_cut_bound(xyz, row0, col0, size, border="int") >= far),
            # r232 wrongly passed 2: round() / np.round for the box's ends, half to even
            "round half even": bool(_cut_bound(xyz, row0, col0, size, border="round") >= far),
            "box buffer": bool(near >= _box_buffer_far(xyz, row0, col0, size, buffer)),
            # r94 D8-6: the smaller of the two bounds, the plane's farthest extreme centre
            "smaller bound": bool(min(bare, zmin) >= far),
            # r214: the bare plane, no nearer than the nearest vertex (the renderer's clamp
            # at the far end told a student's max(plane, z_min) apart where the plane there
            # runs beyond the farthest vertex)
            "plane farthest": bool(
                box is None or max(_bare_plane(xyz, rows, cols).max(), zmin) >= far
            ),
            # r206 M2: the mean of the plane at the box's four extreme centres was told "the
            # plane's largest value at the corners"
            "corner mean": bool(
                box is None or max(_bare_plane(xyz, rows, cols).mean(), zmin) >= far
            ),
            # r114 D8-3: the plane at the tile's middle (the mean of the extreme centres') was
            # told "the plane's largest value at the corners"
            "tile middle": bool(max(_bare_plane(xyz, mid_r, mid_c), zmin) >= far),
            "vertex": bool(zmin >= far),
            # r248 half-named 8: "the nearest vertex" read as the one nearest the tile on
            # screen (by its distance to the tile, or to the tile's middle)
            **{
                key: bool(
                    max(bare, float(xyz[_screen_nearest(xyz, row0, col0, size, to), 2])) >= far
                )
                for key, to in SCREEN_NEAREST.items()
            },  # fmt: skip
            "no clamp": bool(bare >= far),
            # r214 item 1: the bound clamped to the vertices' depth range, at both ends
            "clamped to range": bool(
                (np.inf if box is None else min(max(bare, zmin), xyz[:, 2].max())) >= far
            ),
            "outer corners": bool(_outer_bound(xyz, box) >= far),
            # r149 M3: lesson 10's bound at the tile's outer corners, or the box's corners
            # kept within them, was told "you compared the triangle's nearest vertex"
            "tile outer corners": bool(_tile_outer_bound(xyz, row0, col0, size) >= far),
            "box in outer corners": bool(_box_outer_bound(xyz, row0, col0, size) >= far),
            **_read_slips(xyz, row0, col0, size, buffer, box, near),
        }


def _read_slips(xyz, row0, col0, size, buffer, box, near) -> dict[str, bool]:
    """The verdicts of the mistakes in what is compared or where the tile is read (the stored
    depths taken, the row and column order, the tile's size, the centres): ``_variants``'s
    second half."""
    finite = buffer[np.isfinite(buffer)]
    far = buffer.max()
    with np.errstate(all="ignore"):
        return {
            "tile min": bool(near >= buffer.min()),
            # r221 item 4: the tile's first stored depth (was told "the nearest depth")
            "first stored": bool(near >= buffer[0, 0]),
            # r221 item 2: a box ∩ tile of one column or one row read as empty (first >= last)
            "one line empty": bool(_one_line(xyz, row0, col0, size) or near >= far),
            "strict": bool(near > far),
            "empty ignored": bool(len(finite) and near >= finite.max()),
            "farthest vertex": bool(xyz[:, 2].max() >= far),
            "tile mean": bool(len(finite) and near >= finite.mean()),
            "row col swapped": bool(lower_bound(xyz, col0, row0, size) >= far),
            # r141 D8.2-1: the tile taken as 8 px wide whatever its size (size = 8, col0 + 7)
            "tile of 8": bool(lower_bound(xyz, row0, col0, TILE) >= far),
            # r131 D8-4: the centres at integer coordinates (8.1 names the same slip)
            "integer centres": bool(_integer_bound(xyz, row0, col0, size) >= far),
            "covered centres": _covered_bound(xyz, row0, col0, size, buffer),
            # r198 B: the box's columns and rows right, the plane at (c, r), not the centres;
            # a gradient solved with one sign slipped
            "plane at integer points": bool(_slipped_bound(xyz, box, at=0.0) >= far),
            "dz/dx sign": bool(_slipped_bound(xyz, box, signs=(-1, 1)) >= far),
            "dz/dy sign": bool(_slipped_bound(xyz, box, signs=(1, -1)) >= far),
            # r446 H6: both signs (the area's sign flipped, or its order of vertices)
            "gradient signs": bool(_slipped_bound(xyz, box, signs=(-1, -1)) >= far),
            # r267 half-named 3-5: the box not cut to the tile, an empty box judged on the
            # whole box; a and b exchanged; the plane at the first centre only (8.1's E₀)
            "box uncut, whole box empty": bool(_uncut_bound(xyz) >= far),
            "gradients swapped": bool(_slipped_bound(xyz, box, swapped=True) >= far),
            "first centre only": bool(_slipped_bound(xyz, box, first=True) >= far),
        }


#: r248 half-named 8: the two readings of "the vertex nearest the tile" on screen.
SCREEN_NEAREST = {"vertex nearest on screen": "tile", "vertex nearest the tile's middle": "middle"}


def _screen_nearest(xyz, row0: int, col0: int, size: int, to: str = "tile") -> int:
    """The vertex nearest the tile on screen: by its distance to the tile (``to`` "tile", 0
    inside it; ties: the first) or to the tile's middle ("middle")."""
    xy = np.asarray(xyz, dtype=float)[:, :2]
    lo, hi = np.array([col0, row0], float), np.array([col0 + size, row0 + size], float)
    if to == "middle":
        gap = xy - (lo + hi) / 2
    else:
        gap = np.maximum(lo - xy, 0.0) + np.maximum(xy - hi, 0.0)
    return int(np.argmin(np.hypot(gap[:, 0], gap[:, 1])))


def _screen_words(args, expected, got) -> str:
    """r248 half-named 8: which vertex was taken, and which one bounds the depth."""
    xyz, row0, col0, size, _ = args
    xyz = np.asarray(xyz, dtype=float)
    near = int(np.argmin(xyz[:, 2]))
    taken = next((_screen_nearest(xyz, row0, col0, size, to) for to in SCREEN_NEAREST.values()
                  if _screen_nearest(xyz, row0, col0, size, to) != near), near)  # fmt: skip
    return (
        f"you took the depth of the vertex nearest the tile on screen, v{taken + 1} "
        f'({num(float(xyz[taken, 2]))}): "the nearest vertex" means the one nearest the eye, '
        f"with the smallest depth, here v{near + 1} ({num(float(xyz[near, 2]))}); no fragment "
        "of the triangle is nearer than that vertex, wherever it lies on screen, while the "
        "vertex nearest the tile can lie behind fragments in it (a bound from it can reject a "
        "fragment that is drawn)"
    )


def _one_line(xyz, row0: int, col0: int, size: int) -> bool:
    """Does the tile's part inside the triangle's bounding box hold one column or one row of
    centres only (first == last)?"""
    box = _box_corners(xyz, row0, col0, size)
    return box is not None and (box[0][0] == box[0][3] or box[1][0] == box[1][3])


def _cut_bound(xyz, row0, col0, size, cut="xy", border="both", past_tile=0) -> float:
    """The task's bound with the box cut to the tile only in the axes of ``cut`` (the other
    axes: the whole box, or the whole tile where the box is not cut at all: ``cut=""`` takes
    the box's own extreme centres, beyond the tile too) and the centres on the box's border
    kept on ``border``'s sides ("both"; "high": the right and bottom only, as ⌊xmin + ½⌋
    leaves the left and top; "none": a strict inequality; "past": one more, ⌊xmax + ½⌋;
    "trunc": ``int(xmax − ½)``, truncated toward 0; "before": one more on the low side,
    ⌈xmin − ½⌉ − 1; "shifted": the ½ the wrong way, ⌈xmin + ½⌉ … ⌊xmax + ½⌋; "outward": floor
    and ceil swapped, ⌊xmin − ½⌋ … ⌈xmax − ½⌉; "round": round(xmin) … round(xmax) − 1, a half
    rounded to the even integer, r232). +inf where the tile and the box share
    no centre (as the task's). ``past_tile``: the tile's last column and row taken that many
    past its own (r162: ``col0 + size``)."""
    judged = (
        border
        in ("past", "trunc", "int", "before", "shifted", "outward", "round", "int both", "no half")
        or past_tile
    )
    if not judged and _box_corners(xyz, row0, col0, size) is None:
        return np.inf  # (the others judge the box empty or not their own way)
    xy = np.asarray(xyz, dtype=float)[:, :2]
    spans = []
    for axis, first in ((0, col0), (1, row0)):
        lo, hi = xy[:, axis].min(), xy[:, axis].max()
        a = int(np.floor(lo + 0.5)) if border in ("none", "high") else int(np.ceil(lo - 0.5))
        a = int(lo + 0.5) if border == "int" else a
        a = a - 1 if border == "before" else a
        a = int(np.ceil(lo + 0.5)) if border == "shifted" else a
        a = int(np.floor(lo - 0.5)) if border == "outward" else a
        a = int(np.round(lo)) if border == "round" else a  # half to even, as round() does
        a = int(lo - 0.5) if border == "int both" else a  # r376 F2: int() at both ends
        a = int(np.ceil(lo)) if border == "no half" else a  # r446 H5: ⌈xmin⌉ … ⌊xmax⌋
        b = {"none": int(np.ceil(hi - 0.5)) - 1, "past": int(np.floor(hi + 0.5)),
             "trunc": int(hi - 0.5), "int": int(hi - 0.5), "int both": int(hi - 0.5),
             "shifted": int(np.floor(hi + 0.5)), "outward": int(np.ceil(hi - 0.5)),
             "round": int(np.round(hi)) - 1, "no half": int(np.floor(hi))}.get(
            border, int(np.floor(hi - 0.5)))  # fmt: skip
        if not cut:
            spans.append((a, b))
        elif "xy"[axis] in cut:
            spans.append((max(first, a), min(first + size - 1 + past_tile, b)))
        else:
            spans.append((first, first + size - 1))
    (c0, c1), (r0, r1) = spans
    if c0 > c1 or r0 > r1:
        return np.inf
    return _bound_at(xyz, np.array([r0, r0, r1, r1]), np.array([c0, c1, c0, c1]))


def _uncut_bound(xyz) -> float:
    """r267 half-named 3: the plane's minimum at the extreme centres of the whole bounding box,
    not cut to the tile (+inf only where the box holds no pixel centre at all), no nearer than
    the nearest vertex."""
    xy = np.asarray(xyz, dtype=float)[:, :2]
    lo, hi = np.ceil(xy.min(axis=0) - 0.5), np.floor(xy.max(axis=0) - 0.5)
    if (lo > hi).any():
        return np.inf
    rows, cols = np.array([lo[1], lo[1], hi[1], hi[1]]), np.array([lo[0], hi[0], lo[0], hi[0]])
    return _bound_at(xyz, rows, cols)


def _vertex_in_tile_bound(xyz, row0, col0, size, bare: float, open_high=False) -> float:
    """The plane's minimum over the box's centres, no nearer than the nearest vertex *inside
    the tile* (the bare plane where none is; ``open_high``: the tile without its right and
    bottom side)."""
    end = np.less if open_high else np.less_equal
    inside = ((xyz[:, 0] >= col0) & end(xyz[:, 0], col0 + size) & (xyz[:, 1] >= row0)
              & end(xyz[:, 1], row0 + size))  # fmt: skip
    return max(bare, float(xyz[inside, 2].min())) if inside.any() else bare


def _box_buffer_far(xyz, row0, col0, size, buffer) -> float:
    """The farthest depth stored in the tile's pixels inside the box only (-inf: none)."""
    box = _box_corners(xyz, row0, col0, size)
    if box is None:
        return -np.inf
    rows, cols = box
    return float(
        buffer[rows[0] - row0 : rows[3] - row0 + 1, cols[0] - col0 : cols[3] - col0 + 1].max()
    )


def _slipped_bound(xyz, box, at: float = 0.5, signs=(1, 1), swapped=False, first=False) -> float:
    """The task's bound over the box's extreme centres (+inf: none) with the plane slipped
    (:func:`_bare_plane`'s ``at``, ``signs`` and ``swapped``), no nearer than the nearest
    vertex; ``first``: at the rectangle's first centre only (r267 half-named 5)."""
    if box is None:
        return np.inf
    rows, cols = (np.asarray(v)[:1] if first else np.asarray(v) for v in box)
    low = float(_bare_plane(np.asarray(xyz, dtype=float), rows, cols, at, signs, swapped).min())
    return max(low, float(np.asarray(xyz, dtype=float)[:, 2].min()))


def _sign_words(axis: str, k: int):
    """r198 B: the plane's gradient with one sign slipped: where it misses the vertices
    (``k`` 2: both signs, r446 H6)."""

    def words(args, expected, got):
        xyz = np.asarray(args[0], dtype=float)
        signs = ((-1, 1), (1, -1), (-1, -1))[k]
        z = _bare_plane(xyz, xyz[:, 1] - 0.5, xyz[:, 0] - 0.5, signs=signs)
        j = int(np.argmax(np.abs(z - xyz[:, 2])))
        what = (
            "dz/dx and dz/dy both have the wrong sign (the area, or the determinant, with its "
            "sign flipped?)"
            if k == 2
            else f"dz/d{axis} has the wrong sign (a slip in solving for it?)"
        )
        return (
            f"your plane's {what}: that "
            f"plane gives {num(float(z[j]))} at v{j + 1}, whose depth is {num(float(xyz[j, 2]))}; "
            "the plane passes through all three vertices: check your a and b against them"
        )

    return words


def _uncut_words(xyz, row0, col0, size) -> str:
    """r267 half-named 3: the whole box's extreme centres, not cut to the tile."""
    xyz = np.asarray(xyz, dtype=float)
    lo, hi = np.ceil(xyz[:, :2].min(axis=0) - 0.5), np.floor(xyz[:, :2].max(axis=0) - 0.5)
    lo, hi = lo.astype(int) + 0, hi.astype(int) + 0  # (no "-0")
    spans = (f"the whole box's centres run over columns {lo[0]} to {hi[0]} and rows "
             f"{lo[1]} to {hi[1]}, but this tile holds columns {col0} to "
             f"{col0 + size - 1} and rows {row0} to {row0 + size - 1}")  # fmt: skip
    cut = ("; cut the box to the tile: its columns max(col0, ⌈xmin − ½⌉) … "
           "min(col0 + size − 1, ⌊xmax − ½⌋), its rows alike")  # fmt: skip
    if _box_corners(xyz, row0, col0, size) is None:
        return (f"you took the whole bounding box, not cut to the tile: {spans}, so none of "
                "the box's centres lies in this tile and no fragment of the triangle can be "
                f"here (reject the block), yet your bound is taken outside it{cut}")  # fmt: skip
    rows = np.array([lo[1], lo[1], hi[1], hi[1]])
    cols = np.array([lo[0], hi[0], lo[0], hi[0]])
    k = int(np.argmin(_bare_plane(xyz, rows, cols)))
    return (f"you took the extreme centres of the whole bounding box, not cut to the tile: "
            f"{spans}; over the whole box the plane is nearest at ({num(cols[k] + 0.5)}, "
            f"{num(rows[k] + 0.5)}), outside this tile, so your bound falls to "
            f"{num(_uncut_bound(xyz))}, where no fragment in this tile is that near (a safe "
            f"bound, but looser: it keeps blocks Hi-Z could reject){cut}")  # fmt: skip


def _swapped_words(xyz) -> str:
    """r267 half-named 4: dz/dx and dz/dy exchanged: where that plane misses the vertices."""
    xyz = np.asarray(xyz, dtype=float)
    z = _bare_plane(xyz, xyz[:, 1] - 0.5, xyz[:, 0] - 0.5, swapped=True)
    j = int(np.argmax(np.abs(z - xyz[:, 2])))
    return (
        "your plane's dz/dx and dz/dy are exchanged (a and b swapped: a multiplies x − x1, b "
        f"multiplies y − y1): that plane gives {num(float(z[j]))} at v{j + 1}, whose depth is "
        f"{num(float(xyz[j, 2]))}; the plane passes through all three vertices: check your a "
        "and b against them"
    )


def _first_centre_words(xyz, row0, col0, size) -> str:
    """r267 half-named 5: the plane at the first centre of the tile cut to the box only."""
    xyz = np.asarray(xyz, dtype=float)
    rows, cols = _box_corners(xyz, row0, col0, size)
    bare = _bare_plane(xyz, rows, cols)
    k = int(np.argmin(bare))
    slope = _bare_plane(xyz, np.array([0.0, 0.0, 1.0]), np.array([0.0, 1.0, 0.0]))
    return (
        f"you took the plane at one centre only, ({num(cols[0] + 0.5)}, {num(rows[0] + 0.5)}), "
        "the first of the tile's centres inside the box (as 8.1's E₀): that is the plane's "
        "minimum only where it grows right and down, and here dz/dx = "
        f"{num(float(slope[1] - slope[0]))}, dz/dy = {num(float(slope[2] - slope[0]))}: over "
        f"the rectangle of centres it is nearest at ({num(cols[k] + 0.5)}, {num(rows[k] + 0.5)}), "
        f"{num(float(bare[k]))} (which of its four extreme centres is that, for each sign of "
        "the slopes?)"
    )


def _integer_bound(xyz, row0, col0, size) -> float:
    """The task's bound with pixel c's centre taken at x = c (not c + ½), rows alike."""
    xy = np.asarray(xyz, dtype=float)[:, :2]
    spans = []
    for axis, first in ((0, col0), (1, row0)):
        a = max(first, int(np.ceil(xy[:, axis].min())))
        b = min(first + size - 1, int(np.floor(xy[:, axis].max())))
        if a > b:
            return np.inf
        spans.append((a, b))
    (c0, c1), (r0, r1) = spans
    rows, cols = np.array([r0, r0, r1, r1]) - 0.5, np.array([c0, c1, c0, c1]) - 0.5
    return max(float(_bare_plane(xyz, rows, cols).min()), float(xyz[:, 2].min()))


def _outer_bound(xyz, box) -> float:
    """The box's extreme pixels' outer corners instead of their centres."""
    if box is None:
        return np.inf
    rows, cols = box
    out_r = rows + np.where(rows == rows.min(), -0.5, 0.5)
    out_c = cols + np.where(cols == cols.min(), -0.5, 0.5)
    return max(float(_bare_plane(xyz, out_r, out_c).min()), float(xyz[:, 2].min()))


def _tile_outer_bound(xyz, row0, col0, size) -> float:
    """Lesson 10's bound taken at the tile's outer corners, not its extreme pixel centres."""
    edge = np.array([-0.5, size - 0.5])  # _bare_plane adds the ½ of a centre
    plane = _bare_plane(xyz, row0 + edge[:, None], col0 + edge[None, :])
    return max(float(plane.min()), float(xyz[:, 2].min()))


def _box_outer_bound(xyz, row0, col0, size) -> float:
    """The plane at the box's corners kept within the tile's outer corners (an empty box
    rejected where the box kept so is empty: r206, the reader's w13 keeps a box beside the
    tile's last centres, as this code does; the task's emptiness test told it otherwise on
    five cases and it fell to words of the nearest vertex)."""
    lo, hi = xyz[:, :2].min(axis=0), xyz[:, :2].max(axis=0)
    xs = np.clip([lo[0], hi[0]], col0, col0 + size)
    ys = np.clip([lo[1], hi[1]], row0, row0 + size)
    if lo[0] > col0 + size or hi[0] < col0 or lo[1] > row0 + size or hi[1] < row0:
        return np.inf
    plane = _bare_plane(xyz, ys[None, :] - 0.5, xs[:, None] - 0.5)
    return max(float(plane.min()), float(xyz[:, 2].min()))


def _pixel_box_bound(xyz, row0, col0, size) -> float:
    """The tile cut to the pixels the box touches (not the centres inside it)."""
    lo, hi = xyz[:, :2].min(axis=0), xyz[:, :2].max(axis=0)
    spans = [box_span(np.floor(a) + 0.5, np.ceil(b) - 0.5, first, size)
             for a, b, first in ((lo[0], hi[0], col0), (lo[1], hi[1], row0))]  # fmt: skip
    if None in spans:
        return np.inf
    (c0, c1), (r0, r1) = spans
    return max(float(_bare_plane(xyz, np.array([r0, r0, r1, r1]),
                                 np.array([c0, c1, c0, c1])).min()), float(xyz[:, 2].min()))  # fmt: skip


def _box_own_corners(xyz, row0, col0, size, empty_kept=False) -> float:
    """The plane at the box's own corners clipped to the tile's extreme centres (not at the
    centres inside the box): safe, up to half a pixel looser. ``empty_kept``: a box holding
    no centre of the tile is clipped the same way, not rejected (r162 M2)."""
    if not empty_kept and _box_corners(xyz, row0, col0, size) is None:
        return np.inf  # an empty box rejected, as the task's
    lo, hi = xyz[:, :2].min(axis=0), xyz[:, :2].max(axis=0)
    xs = np.clip([lo[0], hi[0]], col0 + 0.5, col0 + size - 0.5)
    ys = np.clip([lo[1], hi[1]], row0 + 0.5, row0 + size - 0.5)
    plane = _bare_plane(xyz, ys[None, :] - 0.5, xs[:, None] - 0.5)
    return max(float(plane.min()), float(xyz[:, 2].min()))


def _covered_bound(xyz, row0, col0, size, buffer) -> bool | None:
    """The verdict from the plane's minimum over the centres the triangle covers (None where
    it covers none): safe and tighter, but a coverage test per pixel (r64 08-4)."""
    rows, cols = np.indices((size, size))
    points = np.stack([cols.ravel() + col0 + 0.5, rows.ravel() + row0 + 0.5], axis=1)
    inside = covered(np.asarray(xyz, dtype=float)[:, :2], points)
    if not inside.any():
        return None
    r, c = rows.ravel()[inside] + row0, cols.ravel()[inside] + col0
    return bool(plane_at(xyz, r, c, clamp=False).min() >= buffer.max())


_BORDER = (
    "a vertex or an axis-aligned edge can lie exactly on a pixel centre, and the triangle's "
    "depth can be nearest there; on the box's left or top side the triangle can cover such a "
    "centre (the top-left rule), so a bound without it can reject a fragment that is drawn. "
    "The bound counts every centre inside the box, its border included (which border centres "
    "can the rule cover at all? leaving out only those it never covers is accepted too)"
)

MISTAKES = {
    "whole tile": "you took lesson 10's bound, the plane over all the tile's pixel centres: "
    "safe, but no fragment of the triangle lies outside its bounding box, and here the plane "
    "is nearest at centres outside it; the bound asked minimises the plane over the tile's "
    "centres inside the box (lesson 10's keeps blocks this one rejects)",
    "pixel box": "you cut the tile to the pixels the triangle's bounding box touches: a "
    "fragment sits at a pixel centre, and here the centre of the box's first or last pixel "
    "lies outside the box; take only the centres inside it",
    "box corners": "you took the plane at the bounding box's own corners (kept within the "
    "tile): fragments sit at pixel centres, and the nearest centre inside the box lies up to "
    "½ px further in; take the plane's minimum over the tile's centres inside the box",
    "empty kept": "you kept the block where the triangle's bounding box holds no centre of "
    "the tile: every fragment sits at a pixel centre inside the box, so the triangle has no "
    "fragment in this tile and nothing of it can pass here: reject it, whatever the tile stores",
    "box uncut": "you took the extreme centres of the whole bounding box, not cut to the tile: "
    "here the plane is nearest at centres of the box outside this tile (a safe bound, but "
    "looser: it keeps blocks Hi-Z could reject); which of the box's centres lie in this tile?",
    # r267 half-named 3-5 (their words, :func:`_uncut_words` …, follow the table)
    "box uncut, whole box empty": lambda a, e, g: _uncut_words(*a[:4]),
    "gradients swapped": lambda a, e, g: _swapped_words(a[0]),
    "first centre only": lambda a, e, g: _first_centre_words(*a[:4]),
    "box in x only": "you cut the tile to the box in x only: your rows run over the whole "
    "tile, and here the plane is nearest in rows above or below the box, where no fragment "
    "lies (a safe bound, but looser); cut the rows to the box too",
    "box in y only": "you cut the tile to the box in y only: your columns run over the whole "
    "tile, and here the plane is nearest in columns beside the box, where no fragment lies "
    "(a safe bound, but looser); cut the columns to the box too",
    "border": "you left out the centres on the box's border (a strict inequality?): " + _BORDER,
    "one past": "you took a column (or row) past the box's far end (⌊xmax + ½⌋?): its "
    "centre lies beyond the box, where no fragment can be, and here the plane is nearest "
    "there; the box's last column is the last whose centre c + ½ is at most xmax",
    "one before": "your bound is taken over a column (or row) before the box's first: that "
    "centre lies left of (or above) the bounding box, where no fragment can be, and here the "
    "plane is nearest there (a safe bound, but looser: it keeps blocks Hi-Z could reject); "
    "which is the first column whose centre lies inside the box?",
    "box outward": "you rounded the box outward (⌊xmin − ½⌋ … ⌈xmax − ½⌉: floor and ceil "
    "swapped?): where the box does not start or end exactly on a pixel centre, your columns "
    "(rows) reach one past it there, to a centre outside the box, where no fragment can be, "
    "and here the plane is nearest there (a safe bound, but looser: it keeps blocks Hi-Z "
    "could reject); which columns have their centre c + ½ between xmin and xmax?",
    "half shifted": "you took the box's ½ the wrong way (⌈xmin + ½⌉ … ⌊xmax + ½⌋?): column c "
    "has its centre at c + ½, so your columns (and rows) start and end one past the box's own: "
    "you leave out its first column, where a fragment can lie, and take one beyond it, where "
    "none can (your bound can reject a block holding a fragment that is drawn: a hole); which "
    "columns have their centre c + ½ between xmin and xmax?",
    "one short of the tile": "your columns (or rows) stop at col0 + size − 2, one short of the "
    "tile's last: here the plane is nearest in the tile's last column (or row), where a "
    "fragment of the triangle can lie, so your bound is not safe: it can reject a block "
    "holding a fragment that is drawn (a hole); the tile's columns are col0 … col0 + size − 1",
    "whole tile, bare": "you took the plane's minimum over all the tile's pixel centres alone "
    "(lesson 10's bound without the nearest vertex): safe, but here the plane is nearest at "
    "centres where no fragment of the triangle can be; the bound asked is higher: which of "
    "the tile's centres can hold a fragment, and what else bounds how near a fragment can be?",
    "int for floor": "you rounded with int(): it truncates toward 0, so for a box ending "
    "between x = −½ and ½ (or y), int(xmax − ½) is 0, not −1, and takes the tile's first "
    "column, whose centre lies beyond the box: use math.floor (or np.floor)",
    "vertex in tile": "you took the nearest vertex among those inside the tile: no fragment "
    "is nearer than the nearest vertex of the whole triangle, wherever that vertex lies, but a "
    "vertex inside the tile can be farther than fragments beside it (a bound from it can "
    "reject a fragment that is drawn)",
    "int round": "you rounded the box's ends with int(): int(xmin + ½) for its first column "
    "skips the column whose centre lies exactly at xmin (⌈xmin − ½⌉ keeps it), and int() "
    "truncates toward 0 where floor rounds down: use math.ceil(xmin − ½) and "
    "math.floor(xmax − ½) (and y alike); " + _BORDER,
    "box buffer": "you compared with the depths stored in the tile's pixels inside the box "
    "only: Hi-Z keeps one number per tile, its farthest stored depth, and never reads the "
    "pixels (reading them is the per-pixel work it skips); compare with the tile's farthest "
    "depth",
    "border low": "you left out the centres on the box's left or top border (⌊xmin + ½⌋ skips "
    "the column whose centre lies exactly at xmin, ⌊ymin + ½⌋ the row): " + _BORDER,
    "smaller bound": "you took the smaller of the two bounds (the plane at the corners, the "
    "nearest vertex): no fragment is nearer than either, so none is nearer than the larger "
    "of the two (the smaller keeps blocks Hi-Z could reject)",
    "plane farthest": "you took the plane's largest value at the corners, its farthest: the "
    "block is hidden only if even its nearest fragment is, so take the plane's smallest "
    "value there",
    "corner mean": "you took the mean of the plane's values at the box's extreme centres: "
    "the plane's smallest value there lies nearer than that mean, and the block is hidden "
    "only if even its nearest fragment is, so take the plane's smallest value there",
    "tile middle": "you took the plane at the tile's middle: that is its mean over the tile, "
    "and fragments elsewhere in the tile lie nearer: the block is hidden only if even its "
    "nearest fragment is (where in the tile is the plane nearest?)",
    # r267 half-named 3: the whole box, uncut, has words of its own now (it was said here)
    "vertex": "you compared the triangle's nearest vertex (or a bound never above it): in "
    "this tile its depth plane is "
    "farther than that vertex; evaluate the plane at the extreme centres of the tile's part "
    "inside the triangle's bounding box (the "
    "vertex alone is a safe bound, but the larger of the two bounds is asked: the vertex "
    "alone keeps blocks Hi-Z could reject)",
    "no clamp": "you took the bare plane at the corners: where it runs nearer than the "
    "triangle's nearest vertex (a corner outside the triangle), no fragment can be that near; "
    "the bound asked is the larger of the two (either alone is safe, but the larger "
    "is asked: either alone keeps blocks Hi-Z could reject)",
    # r137 D8-9: the triangle clipped to the rectangle of centres (no per-pixel test) gives
    # the same verdicts here: both are said
    "covered centres": "you took the plane's minimum over the triangle's own part of the "
    "tile (over the centres it covers, or over the triangle clipped to the box's centres): a "
    "safe bound, and tighter here, but not the one asked: a coverage test per centre is the "
    "work Hi-Z is there to skip, and clipping costs more than the few numbers asked; the bound asked is the one a few tests give: the plane at the extreme "
    "centres of the tile's part inside the triangle's bounding box, no nearer than the "
    "nearest vertex",
    "outer corners": "you evaluated the plane at the outer corners of the extreme pixels; "
    "fragments sit at pixel centres, the extreme ones ½ px inside",
    "tile outer corners": "you evaluated the plane at the tile's outer corners: fragments sit "
    "at pixel centres, and the tile's extreme centres lie ½ px inside them, where a steep "
    "plane is already farther; take the plane at the extreme centres of the tile's part inside "
    "the triangle's bounding box",
    "box in outer corners": "you took the plane at the bounding box's corners kept within the "
    "tile's outer corners: fragments sit at pixel centres, ½ px or more inside those corners; "
    "take the plane's minimum over the tile's centres inside the box",
    "tile min": "you compared with the nearest depth stored in the tile: a fragment is hidden "
    "only if it is behind the depth at its own pixel, and only the tile's farthest depth "
    "bounds all of them",
    # r221 item 4: buffer[0, 0] held the tile's minimum on every case it failed
    "first stored": lambda a, e, g: (
        "you compared with the tile's first stored depth, buffer[0, 0] "
        f"({num(float(a[4][0, 0]))} here), not the farthest ({num(float(np.max(a[4])))}): a "
        "fragment is hidden only if it is behind the depth at its own pixel, and only the "
        "tile's farthest stored depth bounds every pixel of the tile"
    ),
    "one line empty": lambda a, e, g: _one_line_words(*a[:4]),
    "strict": "a fragment exactly at the stored depth fails the test (strictly nearer "
    "passes), so a block at exactly the tile's farthest depth is rejected too: use ≥",
    # r248 S2: GL's clear value (1.0) fails only a fragment at exactly 1.0: said both ways
    "empty ignored": "a pixel of the tile is still empty (+inf here: nothing drawn yet; GL "
    "holds its clear value, 1.0): a fragment there passes whatever its depth (under GL, any "
    "nearer than 1.0), so a triangle that can have a fragment in this tile nearer than that "
    "may not be rejected",
    "farthest vertex": "you compared the triangle's farthest vertex: the block is hidden only "
    "if even the triangle's nearest possible depth in the tile lies at or behind the tile's "
    "farthest stored depth",
    "tile mean": "you compared with the tile's mean depth: only its farthest stored depth "
    "bounds every pixel of the tile",
    "integer centres": "you put the pixel centres at integer coordinates: pixel column c "
    "has its centre at x = c + ½ and row r at y = r + ½, so both which centres lie in the box "
    "and the plane's value there move by ½ px",
    "tile of 8": lambda a, e, g: (
        "you took the tile as 8 × 8 pixels (size = 8, or col0 + 7, "
        f"written in): this case's tile is {a[3]} px wide, and here the plane is nearest at centres "
        "beyond your 8; the tile is size × size, its last column col0 + size − 1 and its last row "
        "row0 + size − 1"
    ),
    # r232 half-named 4: the vertices read as (y, x, depth) give the same verdicts (the
    # bound and the tile's farthest depth are the same mirrored about the diagonal)
    "row col swapped": "you swapped the tile's row and column, or read each vertex as (y, x, "
    "depth): the two give the same verdicts (the tile mirrored about the diagonal x = y, or the "
    "triangle), so the check cannot tell which; col0 is the tile's first column (x), row0 its "
    "first row (y), and each row of xyz is one vertex's (x, y, depth); its pixel centres lie at "
    "x = col0 + ½ … col0 + size − ½, y = row0 + ½ … row0 + size − ½",
}


def _one_line_words(xyz, row0, col0, size) -> str:
    """r221 item 2: the box ∩ tile of one column (row) taken as empty."""
    box = _box_corners(xyz, row0, col0, size)
    if box is None or not _one_line(xyz, row0, col0, size):
        return "a box ∩ tile of one column or one row still holds centres: it is empty only where its first column (row) lies past its last"  # fmt: skip
    rows, cols = box
    what, k, at = (
        ("column", int(cols[0]), "x") if cols[0] == cols[3] else ("row", int(rows[0]), "y")
    )
    return (
        f"you read the tile's part inside the triangle's bounding box as empty, yet here it is "
        f"one {what} of centres, {what} {k} ({at} = {num(k + 0.5)}), and a fragment can lie "
        f"there: a box ∩ tile of one {what} still holds centres; it is empty only where its "
        f"first {what} lies past its last (first > last), not where they are equal"
    )


def _round_words(xyz, row0, col0, size) -> str:
    """r232 wrongly passed 2: round() for the box's first column (row), half to even."""
    xy = np.asarray(xyz, dtype=float)[:, :2]
    for axis, first, what in ((0, col0, "column"), (1, row0, "row")):
        lo = float(xy[:, axis].min())
        if (
            int(np.round(lo)) != int(np.ceil(lo - 0.5))
            and first <= np.ceil(lo - 0.5) < first + size
        ):
            at, k = "xy"[axis], int(np.ceil(lo - 0.5))
            return (
                f"you rounded the box's ends with round() (or np.round), which rounds a half to "
                f"the even integer: here {at}min = {num(lo)} and round gives {int(np.round(lo))}, "
                f"skipping {what} {k}, whose centre lies exactly at {at}min, on the box's "
                f"{'left' if axis == 0 else 'top'} side, where the triangle can cover it (the "
                "top-left rule) and its depth is nearest: your bound can reject a block holding "
                f"a fragment that is drawn (a hole); the box's first {what} is the first whose "
                f"centre lies at or after {at}min, ⌈{at}min − ½⌉"
            )
    return (
        "you rounded the box's ends with round() (or np.round), which rounds a half to the even "
        "integer: at xmin = 3.5 it gives 4, skipping column 3, whose centre lies exactly at xmin; "
        "the box's first column is the first whose centre lies at or after xmin, ⌈xmin − ½⌉"
    )


def _clamped_words(args, expected, got) -> str:
    """r214 item 1: the bound clamped to the vertices' depth range, at the far end too."""
    xyz = np.asarray(args[0], dtype=float)
    k = int(np.argmax(xyz[:, 2]))
    far = num(float(xyz[k, 2]))
    return (
        "you clamped the bound to the vertices' depth range, at the far end too (no farther "
        f"than v{k + 1}'s depth, {far}): no fragment is nearer than the nearest vertex, so "
        "clamping there is right, but the farthest vertex bounds a fragment's depth from "
        f"behind, never from in front; here the plane lies beyond {far} at every centre of the "
        "tile inside the box, so no fragment of the triangle lies in this tile at all, and your "
        "clamp pulls the bound in front of the tile's farthest stored depth: clamp at the "
        "nearest vertex only"
    )


MISTAKES["clamped to range"] = _clamped_words
MISTAKES.update(dict.fromkeys(SCREEN_NEAREST, _screen_words))  # r248 half-named 8
#: r141 D8.2-2: the tile half-open or closed, the same mistake
MISTAKES["vertex in tile, half-open"] = MISTAKES["vertex in tile"]
MISTAKES["plane at integer points"] = (
    "you took the right columns and rows of the box, but evaluated the plane at (c, r), the "
    "pixels' top-left corners: pixel column c has its centre at x = c + ½ and row r at "
    "y = r + ½, so your plane's values move by half a step of its gradient in each direction"
)
MISTAKES["dz/dx sign"] = _sign_words("x", 0)
MISTAKES["round half even"] = lambda a, e, g: _round_words(*a[:4])
MISTAKES["dz/dy sign"] = _sign_words("y", 1)
MISTAKES["gradient signs"] = _sign_words("", 2)
MISTAKES["no half"] = (
    "you took the columns whose left edge x = c lies in the box (⌈xmin⌉ … ⌊xmax⌋): column c "
    "has its centre at c + ½, so here you leave out a column whose centre lies in the box, or "
    "take one whose centre lies beyond it; which columns have their centre c + ½ between xmin "
    "and xmax (⌈xmin − ½⌉ … ⌊xmax − ½⌋, rows alike)?"
)


def _corners_or_empty(args, expected, got) -> str:
    """r162 M2, r173 M2: the box's own corners with an empty box kept: on a case whose box
    holds no centre of the tile the empty box decides, elsewhere the corners (each said only
    where it decides the case)."""
    xyz, row0, col0, size, _ = args
    if _box_corners(xyz, row0, col0, size) is None:
        return MISTAKES["empty kept"]
    return MISTAKES["box corners"]


MISTAKES["box corners, empty kept"] = _corners_or_empty
#: r162: the tile's last column and row one past its own
MISTAKES["one past the tile"] = (
    "your columns (or rows) run to col0 + size (row0 + size), one past the tile's last: that "
    "centre lies in the next tile, and here the plane is nearest there (a safe bound, but "
    "looser); the tile's columns are col0 … col0 + size − 1, its rows row0 … row0 + size − 1"
)
#: r162 M2: lesson 10's bound is never above the box's corners' (or the task's), so on every
#: case the task rejects and a looser bound keeps it gives the same answer: named only where
#: it gives every answer of the check (a box-corner bound that also keeps empty boxes was told
#: "you took lesson 10's bound", the same 0.300 there, though it rejects where lesson 10's keeps)
ONLY_WHOLE = ("whole tile", "whole tile, bare")
#: r206 M1, M2 (issue 30): the words of these say *where* the plane was evaluated or *which*
#: of its values was taken; a bool answer shares its verdicts with many other bounds, and
#: "every failing answer" let a box rounded outward be told "the tile's outer corners" (it
#: contradicted 8 passing answers) and the corners' mean "the plane's largest value" (2): named
#: only where the mistake gives every answer of the check, passing ones included
EXACT = (
    "outer corners", "tile outer corners", "box in outer corners", "box outward",
    "plane farthest", "corner mean", "tile middle", "clamped to range",
    # r221 item 4: buffer[0, 0] and the tile's minimum share every failing verdict
    "tile min", "first stored", "one line empty",
)  # fmt: skip


#: How close (relative) the nearest depth and the farthest stored one must be for float32's
#: rounding to decide the verdict: a few float32 operations' worth.
TIE = 8 * 2.0**-24


def _tie_gap(args) -> float | None:
    """The case's nearest depth minus its farthest stored one, when float32 cannot tell them
    apart (an exact or near tie, :data:`TIE`); else None."""
    xyz, row0, col0, size, buffer = args
    near = lower_bound(xyz, row0, col0, size)
    far = float(np.max(buffer))
    if not np.isfinite(far) or abs(near - far) > TIE * max(1.0, abs(far)):
        return None
    # a tie float32 holds exactly (a flat triangle at 0.5) is no place for its rounding: there
    # ">" is the mistake ("strict")
    box = _box_corners(xyz, row0, col0, size)
    if box is None:
        return None
    rows, cols = box
    low = _bare_plane(np.asarray(xyz, np.float32), rows.astype(np.float32),
                      cols.astype(np.float32))  # fmt: skip
    if np.array_equal(low.astype(float), plane_at(xyz, rows, cols, clamp=False)):
        return None
    return near - far


def _float32_words(args, expected, got) -> str:
    gap = _tie_gap(args)
    if gap == 0:
        tie = ("exactly equal here (a tie: the fragment would fail the test, so the block is "
               "rejected)")  # fmt: skip
    else:  # r114 D8-2: a near tie, on either side
        tie = f"only {abs(gap):.1e} apart here (the block is {'rejected' if expected else 'kept'})"
    return (f"the task's bound on the triangle's depth and the tile's farthest stored one are {tie}, and "
            "float32's rounding (about 6e-08 of a depth) decides it the other way: did you "
            "compute in float32? Compute the plane in float64")  # fmt: skip


#: r40 08-1: hiz_rejects in float32 was refused and blamed on "bare plane" or "outer corners".
FLOAT32 = Mistake("float32", _float32_words, fits=lambda a, e, g: _tie_gap(a) is not None)


_full = full_number  # (8.1's lines quote their cases the same way, r248 S1)


#: The most pixels a tile's stored depths may differ from their commonest value and still be
#: quoted one by one (the named cases: one or two; the random ones: all of them).
QUOTED = 3


def case_words(xyz, row0, col0, size, buffer) -> str:
    """The case's arguments, as Python a student can paste to call the function on it again
    (r232 C2: 8.2's lines quoted the stored depth only). A buffer of random depths is said by
    its range and its farthest pixel (the only one a right answer reads)."""
    rows = ", ".join(
        "[" + ", ".join(_full(v) for v in vertex) + "]" for vertex in np.asarray(xyz, float)
    )
    buffer = np.asarray(buffer, dtype=float)
    values, counts = np.unique(buffer, return_counts=True)
    common = values[int(np.argmax(counts))]
    odd = np.argwhere(buffer != common)
    if len(odd) <= QUOTED:
        stored = f"buffer = np.full(({size}, {size}), {_full(common)})"
        stored += "".join(f"; buffer[{r}, {c}] = {_full(buffer[r, c])}" for r, c in odd)
    else:
        r, c = np.unravel_index(int(np.argmax(buffer)), buffer.shape)
        stored = (f"buffer: {buffer.size} depths drawn at random from {num(buffer.min())} to "
                  f"{num(buffer.max())}, the farthest buffer[{r}, {c}] = {_full(buffer[r, c])}")  # fmt: skip
    # r248 S1: statements separated by ";", pasted as one line they run
    return f"xyz = np.array([{rows}]); row0 = {row0}; col0 = {col0}; size = {size}; {stored}"


def call_words(xyz, row0, col0, size, buffer) -> str:
    """:func:`case_words` and the call, said where a case gave no answer (r248 S1)."""
    return (
        f"{case_words(xyz, row0, col0, size, buffer)}; hiz_rejects(xyz, row0, col0, size, buffer)"
    )


def explain_hiz(args, expected, got) -> str:
    """The case's arguments, the extreme centres, the triangle's nearest depth there, the
    tile's farthest, verdicts."""
    return f"{case_words(*args)}; {_explain_bound(args, expected, got)}"


def _explain_bound(args, expected, got) -> str:
    xyz, row0, col0, size, buffer = args
    box = _box_corners(xyz, row0, col0, size)
    verdict = (
        f"the block is {'rejected' if expected else 'kept'}, you {'rejected' if got else 'kept'} it"
    )
    if box is None:
        return (f"the triangle's bounding box holds no pixel centre of the tile (columns {col0} to "
                f"{col0 + size - 1}, rows {row0} to {row0 + size - 1}): no fragment of it lies "
                f"here, and {verdict}")  # fmt: skip
    rows, cols = box
    corner = plane_at(xyz, rows, cols)
    nearest, farthest = lower_bound(xyz, row0, col0, size), np.max(buffer)
    k = int(np.argmin(corner))
    far = num(farthest)
    if far == num(nearest) and farthest != nearest:  # r114: a near tie printed as equal
        far += f" ({abs(farthest - nearest):.1e} {'farther' if farthest > nearest else 'nearer'})"
    return (f"the tile's centres inside the triangle's bounding box run from ({cols[0] + 0.5}, "
            f"{rows[0] + 0.5}) to ({cols[3] + 0.5}, {rows[3] + 0.5}); the plane is nearest at "
            f"({cols[k] + 0.5}, {rows[k] + 0.5}), so the bound (no nearer than the nearest "
            f"vertex) is {num(nearest)}; the tile's farthest stored "
            f"depth is {far}: {verdict}")  # fmt: skip


def _rule(args, expected, got) -> str:
    return (
        ". The block is rejected when the task's lower bound on the triangle's depth in the "
        "tile (its plane's minimum over the tile's centres inside its bounding box, no nearer "
        "than its nearest vertex; +inf where the box holds none) is at or behind the farthest "
        "depth stored there"
    )


def draw_hiz(ax, case, got):
    """The tile's stored depths, the triangle, its bounding box (ex30a: drawn on every try,
    with a legend), the verdicts; the centre where the bound is taken and the depth at the
    extreme centres once the hints are spent (r173 G1)."""
    from matplotlib.patches import Polygon

    from .tries import hints_spent

    _, (xyz, row0, col0, size, buffer), expected = case
    artists = _stored(ax, buffer, row0, col0, size)
    # the triangle itself, outlined (r40 08-4: only an edge or none of it showed in the view;
    # r94 D8-12: a translucent fill tinted the stored depths under it, as if two were held)
    artists.append(ax.add_patch(Polygon(xyz[:, :2], closed=True, fill=False, hatch="//",
                                        edgecolor="#d7301f", linewidth=1.5,
                                        label="the triangle")))  # fmt: skip
    artists += _box_and_site(ax, xyz, row0, col0, size)
    verdict = "rejected" if expected else "kept"
    yours = "" if got is None else f"; yours: {'rejected' if got else 'kept'}"
    far = f"farthest stored {num(np.max(buffer))}: {verdict}{yours}"
    # r94 D8-3: the plane's depth at the extreme centres is the task's answer: drawn only once
    # two different answers have failed (as classify_block's figure does)
    if hints_spent("hiz_rejects"):
        artists += _extreme_centres(ax, xyz, row0, col0, size)
    # r149 E3: the tile's pixel centres (which lie in the box is the task), ticks on whole pixels
    cy, cx = np.mgrid[row0 : row0 + size, col0 : col0 + size] + 0.5
    # (dark on the flat light tile, light on the coloured one, r232 FIG2)
    dots = "#636363" if _uniform(buffer) else "#d9d9d9"
    artists += ax.plot(cx.ravel(), cy.ravel(), ".", color=dots, ms=2.5, zorder=3)
    # r214 item 8: the legend's marker larger and darker than the centres' (a 2.5-pt light dot
    # on white could not be seen)
    artists += ax.plot([], [], "o", color="#969696", ms=4, label="pixel centres")
    if not np.isfinite(buffer).all():  # r198 C.5: the white pixels, outside the colour bar
        artists += ax.plot([], [], "s", mfc="white", mec="0.5", ms=8,
                           label="nothing drawn yet (+∞)")  # fmt: skip
    ax.set_xlim(col0 - VIEW_MARGIN, col0 + size + VIEW_MARGIN)
    ax.set_ylim(row0 + size + VIEW_MARGIN, row0 - VIEW_MARGIN)
    from matplotlib.ticker import MultipleLocator

    step = 4 if size > 8 else 2
    ax.xaxis.set_major_locator(MultipleLocator(step))
    # r198 C.4: no tick label at the view's top edge, where the title's second line sat on it
    ax.set_yticks(np.arange(row0, row0 + size + VIEW_MARGIN + 1, step))
    ax.set_aspect("equal")
    artists += _vertex_depths(ax, xyz, _in_view(xyz, row0, col0, size))
    artists += _whole_triangle(ax, xyz, row0, col0, size)
    artists.append(_legend(ax, far))
    return artists


#: The colour of a tile whose drawn pixels all store one depth (no colour bar then).
STORED_COLOUR = "#c6dbef"


def _stored(ax, buffer, row0: int, col0: int, size: int) -> list:
    """The tile's stored depths (+∞ white): one flat colour, its depth in the legend, where
    every drawn pixel stores the same depth (r232 FIG2: a 0–1 colour bar over one value said
    nothing); else coloured over their own range, with a colour bar, and the farthest pixel
    outlined (the one the verdict reads)."""
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Rectangle

    extent = (col0, col0 + size, row0 + size, row0)
    drawn = np.isfinite(buffer)
    finite = buffer[drawn]
    if _uniform(buffer):
        flat = ListedColormap([STORED_COLOUR]).with_extremes(bad="white")
        image = ax.imshow(np.where(drawn, 0.0, np.nan), cmap=flat, vmin=0, vmax=1, extent=extent,
                          interpolation="nearest")  # fmt: skip
        if finite.size == 0:
            return [image]
        every = "every pixel" if drawn.all() else "every pixel drawn"
        key = ax.plot([], [], "s", color=STORED_COLOUR, ms=9,
                      label=f"stored depth {num(finite[0])}, {every}")  # fmt: skip
        return [image, *key]
    image = ax.imshow(np.where(drawn, buffer, np.nan), cmap="viridis", vmin=finite.min(),
                      vmax=finite.max(), extent=extent, interpolation="nearest")  # fmt: skip
    out = [image, ax.figure.colorbar(image, ax=ax, label="stored depth", shrink=0.6)]
    if drawn.all():  # (else the farthest is an empty pixel, white and in the legend)
        r, c = np.unravel_index(int(np.argmax(buffer)), buffer.shape)
        out.append(ax.add_patch(Rectangle((col0 + c, row0 + r), 1, 1, fill=False, lw=2.0,
                                          edgecolor="black", zorder=4,
                                          label="the farthest stored depth")))  # fmt: skip
    return out


def _uniform(buffer) -> bool:
    """Do the tile's drawn pixels (those not +∞) all store one depth (or is none drawn)?"""
    finite = np.asarray(buffer, dtype=float)[np.isfinite(buffer)]
    return finite.size == 0 or bool(finite.min() == finite.max())


def _in_view(xyz, row0: int, col0: int, size: int) -> np.ndarray:
    """Which vertices lie in the figure's view of the tile (the tile and :data:`VIEW_MARGIN`
    px around it)."""
    xy = np.asarray(xyz, dtype=float)[:, :2]
    lo = np.array([col0, row0], float) - VIEW_MARGIN
    hi = np.array([col0 + size, row0 + size], float) + VIEW_MARGIN
    return ((xy >= lo) & (xy <= hi)).all(axis=1)


def _vertex_depths(ax, xyz, which, reach: float = 9.0, named: bool = True) -> list:
    """Each vertex of ``which`` as a dot and "vk: depth" (``named``; else the depth, in the
    narrow inset), set outward from the triangle's
    centroid, its box aligned on the side facing the vertex (r214 item 7: a small triangle's
    labels no longer cover one another; r232 FIG2: the main panel labelled none, and the
    inset's labels, with no dot, read as the tile's corners')."""
    xyz = np.asarray(xyz, dtype=float)
    centre = xyz[:, :2].mean(axis=0)
    artists = []
    for k in np.flatnonzero(which):
        x, y, z = xyz[k]
        d = np.array([x, y]) - centre
        d = d / (np.hypot(*d) or 1.0)
        ha = "center" if abs(d[0]) < 0.38 else ("left" if d[0] > 0 else "right")
        va = "center" if abs(d[1]) < 0.38 else ("top" if d[1] > 0 else "bottom")  # y down
        artists += ax.plot([x], [y], "o", color="#7f0000", ms=3.5, zorder=6)
        text = f"v{k + 1}: {num(float(z))}" if named else num(float(z))
        artists.append(ax.annotate(text, (x, y),
                                   xytext=(reach * d[0], -reach * d[1]), textcoords="offset points",
                                   ha=ha, va=va, fontsize="small", color="#7f0000", zorder=6,
                                   bbox={"boxstyle": "round,pad=0.1", "facecolor": "white",
                                         "edgecolor": "none", "alpha": 0.85}))  # fmt: skip
    return artists


def _legend(ax, title: str):
    """The figure's legend, headed by the verdicts, below the tile's tick labels (a fixed
    distance in points: the axes' height changes with its equal aspect)."""
    from matplotlib.transforms import ScaledTranslation

    below = ax.transAxes + ScaledTranslation(0, -32 / 72, ax.figure.dpi_scale_trans)
    return ax.legend(loc="upper center", bbox_to_anchor=(0.5, 0.0), bbox_transform=below,
                     ncols=2, fontsize="small", title=title, title_fontsize="small",
                     borderaxespad=0.0)  # fmt: skip


#: The colours of the figure's box and of the centre where the bound is taken.
BOX_COLOUR, SITE_COLOUR = "#ff9f1c", "#ffffff"


def _box_and_site(ax, xyz, row0, col0, size) -> list:
    """The triangle's bounding box (dashed) and, once the hints are spent, the centre where the
    check's bound is taken (:func:`bound_site`), each with its legend entry; the centre is not
    drawn where the box holds no centre of the tile (the legend says so)."""
    from matplotlib.patches import Rectangle

    lo, hi = xyz[:, :2].min(axis=0), xyz[:, :2].max(axis=0)
    # r162 D4 (r149 E4): a box whose sides all lie beyond the view drew no line, yet the legend
    # listed it: said in words there instead
    seen = _box_seen(lo, hi, row0, col0, size)
    label = "its bounding box" if seen else "_nolegend_"
    artists = [ax.add_patch(Rectangle(lo, *(hi - lo), fill=False, edgecolor=BOX_COLOUR, lw=2.0,
                                      linestyle="--", label=label))]  # fmt: skip
    if not seen:  # r248 FIG1: with the box's own dashed key (an empty slot before)
        artists += ax.plot([], [], color=BOX_COLOUR, lw=2.0, linestyle="--",
                           label="its bounding box: beyond this view")  # fmt: skip
    from .tries import hints_spent

    # r173 G1: where the bound is taken (and whether the nearest vertex sets it) is the task's
    # answer on this case: drawn only once two different answers have failed, as the depths
    # at the extreme centres are
    if not hints_spent("hiz_rejects"):
        return artists
    site = bound_site(xyz, row0, col0, size)
    if site is None:
        artists += ax.plot([], [], " ", label="no centre of the tile in the box")
        return artists
    row, col, _, by_vertex = site
    what = "the plane, no nearer than\nthe nearest vertex" if by_vertex else "the plane"
    artists += ax.plot(col + 0.5, row + 0.5, "*", color=SITE_COLOUR, mec="black", mew=1.2, ms=18,
                       zorder=5, label=f"where the bound is taken\n({what})")  # fmt: skip
    return artists


#: How far the figure's view reaches beyond the tile on each side (px).
VIEW_MARGIN = 2


def _box_seen(lo, hi, row0: int, col0: int, size: int) -> bool:
    """Does a side of the box [lo, hi] cross the figure's view of the tile (the tile and
    :data:`VIEW_MARGIN` px around it)?"""
    v_lo = np.array([col0, row0], float) - VIEW_MARGIN
    v_hi = np.array([col0 + size, row0 + size], float) + VIEW_MARGIN
    for axis in (0, 1):  # the sides across ``axis``, at lo and hi along it
        other = 1 - axis
        spans = lo[other] <= v_hi[other] and hi[other] >= v_lo[other]
        if spans and any(v_lo[axis] <= at <= v_hi[axis] for at in (lo[axis], hi[axis])):
            return True
    return False


def _extreme_centres(ax, xyz, row0, col0, size) -> list:
    """The triangle's depth at the four extreme centres of the tile cut to its box (circles,
    labelled; nothing where the box holds no centre of the tile)."""
    box = _box_corners(xyz, row0, col0, size)
    if box is None:
        return []
    rows, cols = box
    # r214: the plane no nearer than the nearest vertex, as the bound takes it (the renderer's
    # clamp at the farthest vertex drew 0.7 at all four where the bound is 0.789)
    zmin = float(np.min(np.asarray(xyz, dtype=float)[:, 2]))
    depth = np.maximum(plane_at(xyz, rows, cols, clamp=False), zmin)
    k = int(np.argmin(depth))
    artists = ax.plot(cols + 0.5, rows + 0.5, "o", mfc="none", mec=BOX_COLOUR, mew=1.5, ms=10,
                      label="circles: the triangle's depth at\nthe extreme centres in the box")  # fmt: skip
    # the triangle's depth at each extreme centre; in a box under 4 px the labels would
    # overlap: the nearest one only (r126 N8-1's small triangles)
    small = cols.max() - cols.min() < 4 or rows.max() - rows.min() < 4
    for j, (r, c, z) in enumerate(zip(rows, cols, depth)):
        if small and j != k:
            continue
        # r149 E3: outward, beside its own circle (inward, a 7-px box's labels met in its middle)
        out = (-1 if c == cols.min() else 1, -1 if r == rows.min() else 1)  # y points down
        # r214: at most 4 significant digits (0.7890625 ran over the tick labels)
        artists.append(ax.annotate(f"{float(z):.4g}", (c + 0.5, r + 0.5), xytext=(18 * out[0], 11 * out[1]),
                                   textcoords="offset points", ha="center", va="center",
                                   fontsize="small", bbox={"boxstyle": "round,pad=0.15",
                                   "facecolor": "white", "edgecolor": "none", "alpha": 0.85}))  # fmt: skip
    return artists


def _whole_triangle(ax, xyz, row0, col0, size) -> list:
    """An inset with the whole triangle, the depths of the vertices beyond the main view and
    the tile (r49: a triangle larger than the tile's close-up tinted all of it, and could not be
    seen)."""
    from matplotlib.patches import Polygon, Rectangle

    inset = ax.inset_axes([-0.62, 0.5, 0.45, 0.45])  # outside: no label hidden
    inset.add_patch(Polygon(xyz[:, :2], closed=True, facecolor="#d7301f", alpha=0.25,
                            edgecolor="#d7301f", linewidth=1))  # fmt: skip
    inset.add_patch(Rectangle((col0, row0), size, size, fill=False, edgecolor="black", lw=1))
    lo = np.minimum([col0, row0], xyz[:, :2].min(axis=0))
    hi = np.maximum([col0 + size, row0 + size], xyz[:, :2].max(axis=0))
    # room for a vertex's label (r64: cut at the border; r214: labels now reach away from
    # their vertex, a little further; r248 FIG1: their white halos still cut the frame at 0.3)
    pad = 0.5 * float((hi - lo).max()) + 3
    lo, hi = lo - pad, hi + pad
    # r198 C.6: the depth of every vertex the main panel does not show (which way the plane
    # rises), beside a dot at the vertex (r232 FIG2); r149 E3: "small", on a white ground
    _vertex_depths(inset, xyz, ~_in_view(xyz, row0, col0, size), reach=3.0, named=False)
    inset.set_xlim(lo[0], hi[0])
    inset.set_ylim(hi[1], lo[1])
    inset.set_aspect("equal")
    inset.set_xticks([])
    inset.set_yticks([])
    # r94 D8-9: a title above the inset sat on the main axes' first tick label
    inset.set_xlabel("whole triangle", fontsize="x-small")
    return [inset]


#: The words that say where the triangle's depth is nearest in the tile (the task's question),
#: hints until two different answers have failed (r64 08-3: every first failure's header gave
#: the extreme centres and the nearest one; :attr:`.exercise.Exercise.hints`).
HIZ_HINTS = (
    # r267 half-named 3: the cause is said on the first try, the cut itself asked
    ("; cut the box to the tile: its columns max(col0, ⌈xmin − ½⌉) … min(col0 + size − 1, "
     "⌊xmax − ½⌋), its rows alike", "; cut the box to the tile: which of its centres lie in "
     "this tile?"),
    # r122 N8-2: "the nearest depth the triangle can have" named the bound, which may lie
    # nearer than any fragment of the triangle in the tile
    # r162 C.1: the bound's value is the task's answer on this case: not printed until two
    # different answers have failed (it was, in words of its own)
    (re.compile(r"the tile's centres inside the triangle's bounding box run from \([^()]*\) to "
                r"\([^()]*\); the plane is nearest at \([^()]*\), so the bound \(no nearer than "
                r"the nearest vertex\) is [^;]*; the tile's farthest stored depth is ([^:]*):"),
     # not "(the larger of the two)": that is what the "smaller bound" mistake is asked (r94)
     r"the tile's farthest stored depth is \1:"),
    # r173 M1: the outer-corner words ended on the task's answer
    ("; take the plane at the extreme centres of the tile's part inside the triangle's "
     "bounding box", ": where in the tile can a fragment of the triangle lie?"),
    # r173 G2: which border centres the rule can cover is cell 5's own question
    ("; on the box's left or top side the triangle can cover such a centre (the top-left "
     "rule), so", "; the triangle can cover such a centre, so"),
    (" (its plane's minimum over the tile's centres inside its bounding box, no nearer than "
     "its nearest vertex; +inf where the box holds none)",
     " (where in the tile can a fragment lie, where is its depth smallest, and how near can "
     "a fragment be?)"),
    # r73 08-2: the named mistakes stated the bound asked; a question until two have failed
    ("; evaluate the plane at the extreme centres of the tile's part inside the triangle's "
     "bounding box (the vertex alone is a safe "
     "bound, but the larger of the two bounds is asked: the vertex alone keeps blocks Hi-Z "
     "could reject)", ": a safe bound, but not the one asked (it keeps blocks Hi-Z could "
     "reject): what else bounds the triangle's depth in the tile?"),
    ("; the bound asked is the larger of the two (either alone is safe, but the "
     "larger is asked: either alone keeps blocks Hi-Z could reject)",
     ": what else bounds how near a fragment of the triangle can be?"),
    ("; the bound asked is the one a few tests give: the plane at the extreme centres of the "
     "tile's part inside the triangle's bounding box, no nearer than the nearest vertex",
     "; the bound asked is the one a few tests give (which few points, and what else?)"),
    # r126 N8-1: the new mistakes ask before they tell
    ("; the bound asked minimises the plane over the tile's centres inside the box (lesson "
     "10's keeps blocks this one rejects)", ": which of the tile's centres can hold a fragment "
     "of the triangle at all?"),
    ("; take only the centres inside it", ""),
    # r232: round() half to even: which column (row) is the box's first is the task's question
    (re.compile(r"; the box's first (column|row) is the first whose centre lies at or after "
                r"[xy]min, ⌈[xy]min − ½⌉"), r"; which \1 is the box's first?"),
    ("; take the plane's minimum over the tile's centres inside the box", ""),
    # r94 D8-3: the swapped row and column gave the tile's extreme centres on the first try
    ("; its pixel centres lie at x = col0 + ½ … col0 + size − ½, y = row0 + ½ … row0 + size "
     "− ½", ""),
    (", so none is nearer than the larger of the two (the smaller keeps "
     "blocks Hi-Z could reject)", ": which of the two, then, bounds how near a fragment can be?"),
)  # fmt: skip


def _strict_bounds(xyz, row0: int, col0: int, size: int) -> dict[str, float]:
    """r376 F5: the bounds of the table's mistakes that "strict" (> for ≥) is combined with."""
    xyz = np.asarray(xyz, dtype=float)
    box = _box_corners(xyz, row0, col0, size)
    zmin = float(xyz[:, 2].min())
    with np.errstate(all="ignore"):
        bare = np.inf if box is None else float(plane_at(xyz, *box, clamp=False).min())
        return {
            "whole tile": tile_bound(xyz, row0, col0, size),
            "whole tile, bare": float(_bare_plane(xyz, *_corners(row0, col0, size)).min()),
            "no clamp": bare,
            "vertex": zmin,
            "smaller bound": min(bare, zmin),
            "box corners": _box_own_corners(xyz, row0, col0, size),
            "box uncut": _cut_bound(xyz, row0, col0, size, cut=""),
            "border": _cut_bound(xyz, row0, col0, size, border="none"),
            "one before": _cut_bound(xyz, row0, col0, size, border="before"),
            "one past": _cut_bound(xyz, row0, col0, size, border="past"),
            "int for floor": _cut_bound(xyz, row0, col0, size, border="trunc"),
        }


#: r376 F2, F5: two mistakes of the table in one answer, each named on the failures it
#: decides: "strict" beside a bound's mistake (lesson 10's bound with > got only the rule), and
#: int() at both ends of the box (int(xmin − ½), one column before it, and int(xmax − ½)),
#: which was told "the bounding box's own corners", a mistake the code does not contain.
PAIRS = {
    **{f"{kind} and strict": (kind, "strict") for kind in _strict_bounds(_SMALL, 0, 0, TILE)},
    "one before and int for floor": ("one before", "int for floor"),
}


def _pair_variants(xyz, row0, col0, size, buffer) -> dict[str, bool]:
    far = np.max(buffer)
    # (an empty box, +inf, rejected whatever the tile stores, an empty pixel's +inf too)
    bounds = _strict_bounds(xyz, row0, col0, size)
    out = {f"{k} and strict": bool(b == np.inf or b > far) for k, b in bounds.items()}
    out["one before and int for floor"] = bool(
        _cut_bound(xyz, row0, col0, size, border="int both") >= far
    )
    return out


def _pairs(singles: list[Mistake]) -> list[Mistake]:
    """:data:`PAIRS` as combinations (:attr:`.exercise.Mistake.parts`): without one part, the
    other's answer, so that each failure is told the part that decides it."""
    gives = {m.kind: m.gives for m in singles}
    out = []
    for m in variant_mistakes(_pair_variants, dict.fromkeys(PAIRS, "")):
        first, second = PAIRS[m.kind]
        parts = (Mistake(first, MISTAKES[first]), Mistake(second, MISTAKES[second]))
        other = {first: gives[second], second: gives[first]}
        out.append(replace(m, parts=parts, without=lambda part, o=other: o[part.kind], only_whole=True))  # fmt: skip
    return out


_SINGLES = [replace(m, only_whole=True) if m.kind in ONLY_WHOLE + EXACT else m
            for m in variant_mistakes(_variants, MISTAKES, (FLOAT32,))]  # fmt: skip

HIZ_REJECTS = Exercise(
    "hiz_rejects", hiz_cases, as_bool, same_verdict, explain_hiz, _rule,
    [*_SINGLES, *_pairs(_SINGLES)],
    draw=draw_hiz, hints=HIZ_HINTS, call_words=call_words,  # r248 S1
    # r94 D8-6: a bool answer agrees with many mistakes on any one case: "use ≥" was said to
    # a function using ≥ (the smaller of the two bounds); name only a mistake giving every
    # failing answer
    partial_names=False,
    # r114 D8-1: the checker's own verdict, handed in or called, passed all cases: listed as
    # an answer, every function of this module is watched and not counted
    answers=(PackageAnswer(expected_reject, words=CHECKER_WORDS),),
)  # fmt: skip
