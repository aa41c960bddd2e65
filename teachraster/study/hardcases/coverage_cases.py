"""Coverage cases: split squares, fans, vertex orders, flat, sub-pixel and sliver triangles."""

from __future__ import annotations

import itertools

import numpy as np

from .case import Fills, HardCase, Naive, add_case, frozen_inputs
from .checks import (
    check_finite,
    check_mask,
    check_nothing,
    check_watertight,
    fill_all,
    first_pixels,
    naive_differs,
    naive_double_hits,
    naive_mesh,
    pixel_mask,
    strictly_inside,
    triangles_array,
)
from .naive import naive_counts, naive_coverage

#: Each split of the square: the diagonal's ends on its right or bottom side (left to the
#: neighbouring squares, like the rest of those sides), and who gets how many centres. The
#: \\ split is Direct3D's own example (its *Rasterization Rules* page: triangles (0, 0),
#: (5, 0), (5, 5) and (0, 5), (0, 0), (5, 5), y down: 15 pixels and 10); / is its mirror image.
_SPLITS = {
    "\\": ("the diagonal's lower end (6, 6)",
           "Direct3D's split-square example: the upper-right triangle gets 15 centres, the "
           "lower-left 10"),
    "/": ("both ends of the diagonal ((1, 6) and (6, 1))",
          "Direct3D's example mirrored: the upper-left triangle gets 15 centres, the "
          "lower-right 10"),
}  # fmt: skip


def _split_square(name, diagonal):
    lo, hi = 1.5, 6.5
    tl, tr_, br, bl = (lo, lo), (hi, lo), (hi, hi), (lo, hi)
    tris = (
        triangles_array((tl, tr_, br), (tl, br, bl))
        if diagonal == "\\"
        else triangles_array((tl, tr_, bl), (tr_, br, bl))
    )
    ends, example = _SPLITS[diagonal]

    def check(inputs, result: Fills) -> None:
        # the pixels, and who gets how many: the split's 15 and 10 that ``expect`` quotes
        check_mask(inputs, result)
        got = tuple(int(f.coverage.sum()) for f in result.fills)
        assert got == (15, 10), f"centres per triangle {got}, want (15, 10)"

    expected = pixel_mask(8, 8, lambda i, j: (i >= 1) & (i <= 5) & (j >= 1) & (j <= 5))
    add_case(
        HardCase(
            name,
            f"a square with corners on pixel centres split along its {diagonal} diagonal "
            "(through centres): every edge is a tie",
            "mesh",
            "exactly the 25 centres (1..5, 1..5) covered, each once. A centre on the right or "
            "bottom side goes to no triangle of the square (the squares to the right and below "
            f"own it), {ends} among them; every other centre on the top or left side or on "
            f"the diagonal goes to exactly one triangle ({example})",
            frozen_inputs(
                triangles=tris,
                size=(8, 8),
                expected=expected,
                attrs=np.array([[0.0, 1.0, 2.0], [0.0, 2.0, 3.0]]),
            ),  # fmt: skip
            fill_all,
            check,
            "raw floats with E ≥ 0 (no top-left rule) give the diagonal's centres to both "
            "triangles, and also fill the right and bottom sides",
            naive_mesh("inclusive"),
            naive_double_hits,
        )
    )


_split_square("d3d_split_square", "\\")
_split_square("d3d_split_square_other_diagonal", "/")

# Integer directions in angular order: every spoke from a pixel centre passes through centres.
_LATTICE = [(1, 0), (2, 1), (1, 1), (1, 2), (0, 1), (-1, 2), (-1, 1), (-2, 1),
            (-1, 0), (-2, -1), (-1, -1), (-1, -2), (0, -1), (1, -2), (1, -1), (2, -1)]  # fmt: skip


def _fan_case():
    centre = np.array([9.5, 9.5])
    rim = [centre + 3 * np.array(d, dtype=float) for d in _LATTICE]
    tris = triangles_array(*[(centre, rim[k], rim[(k + 1) % len(rim)]) for k in range(len(rim))])
    add_case(
        HardCase(
            "fan_spokes_through_centres",
            "16 triangles around a pixel centre whose spokes and rim pass through pixel centres",
            "mesh",
            "no pixel centre covered twice (the shared centre vertex included), every centre "
            "strictly inside the fan's outline covered exactly once",
            frozen_inputs(triangles=tris, size=(20, 20), interior=strictly_inside(rim, 20, 20)),
            fill_all,
            check_watertight,
            "raw floats with E ≥ 0 hit every spoke's centres twice and the hub 16 times",
            naive_mesh("inclusive"),
            naive_double_hits,
        )
    )


_fan_case()


def _six_orders():
    base = np.array([[1.5, 1.5], [13.5, 4.5], [4.5, 13.5]])  # every edge passes through centres
    f = np.array([[0.0, 1.0], [10.0, -2.0], [3.0, 7.5]])
    perms = list(itertools.permutations(range(3)))
    tris = np.array([base[list(p)] for p in perms])
    attrs = np.array([f[list(p)] for p in perms])
    w = np.array([np.array([1.0, 2.5, 4.0])[list(p)] for p in perms])

    def check(inputs, result: Fills) -> None:
        check_finite(result)
        first = result.fills[0]
        assert first.coverage.any(), "the triangle covers nothing"
        for k, fill in enumerate(result.fills[1:], start=1):
            bad = fill.coverage != first.coverage
            assert not bad.any(), f"vertex order {perms[k]} changes coverage at {first_pixels(bad)}"
            err = np.nanmax(np.abs(fill.attrs["f"] - first.attrs["f"]))
            assert err <= 1e-12, f"vertex order {perms[k]} changes attributes by {err:.3g}"

    def shows(inputs, ours: Fills, naive: Naive) -> str | None:
        empty = [perms[k] for k in range(6) if not naive.values["coverage"][k].any()]
        # the vertices by their names, v1 v2 v3 (CONVENTIONS), not by 0-based index
        names = ", ".join(" ".join(f"v{i + 1}" for i in p) for p in empty)
        return f"naive covers nothing for orders {names}" if empty else None

    def naive(inputs) -> Naive:
        cov = [naive_coverage(xy, 16, 16, rule="top_left", orient="none") for xy in tris]
        return Naive(values={"coverage": cov})

    add_case(
        HardCase(
            "six_vertex_orders",
            "the same triangle given in all 6 vertex orders (both windings), edges through centres",
            "triangles",
            "identical coverage for all 6 orders (both windings are filled; ties follow the "
            "geometry, not the order) and attributes (perspective, unequal w) equal within "
            "1e-12",
            frozen_inputs(triangles=tris, size=(16, 16), attrs=attrs, w=w),
            fill_all,
            check,
            "assuming one winding (no re-orientation) covers nothing for the 3 reversed orders",
            naive,
            shows,
        )
    )


_six_orders()

add_case(
    HardCase(
        "flat_top",
        "a flat-top triangle (top edge on a row of centres): point 4, where spans split, is "
        "the top vertex (lesson 01 §6)",
        "triangle",
        "exactly the centres with i >= 1, j >= 1, i + j < 8 (21 pixels): the top and left "
        "edges' centres covered, the hypotenuse's (a right edge) not",
        frozen_inputs(
            triangles=triangles_array(((1.5, 1.5), (7.5, 1.5), (1.5, 7.5))),
            size=(10, 10),
            attrs=np.array([[0.0, 6.0, 12.0]]),
            expected=pixel_mask(10, 10, lambda i, j: (i >= 1) & (j >= 1) & (i + j < 8)),
        ),
        fill_all,
        check_mask,
        "raw floats with E > 0 drop the whole top row and left column",
        naive_mesh("strict"),
        naive_differs,
    )
)

add_case(
    HardCase(
        "flat_bottom",
        "a flat-bottom triangle (horizontal bottom edge through centres): no lower half",
        "triangle",
        "exactly the centres with 1 <= j < i <= 6 (15 pixels): the left edge's centres "
        "covered; the hypotenuse (the interior is below-left of it: a right edge) and the "
        "bottom edge not",
        frozen_inputs(
            triangles=triangles_array(((1.5, 1.5), (1.5, 7.5), (7.5, 7.5))),
            size=(10, 10),
            attrs=np.array([[0.0, 6.0, 12.0]]),
            expected=pixel_mask(10, 10, lambda i, j: (j >= 1) & (j < i) & (i <= 6)),
        ),
        fill_all,
        check_mask,
        "raw floats with E ≥ 0 also fill the bottom row and the diagonal",
        naive_mesh("inclusive"),
        naive_differs,
    )
)

add_case(
    HardCase(
        "near_flat",
        "the flat-top triangle with one top vertex 1/256 px lower: the split point, "
        "point 4 = (u4, v_mid), lies 1/256 px below v1",
        "triangle",
        "the top edge now slopes down (not a top edge): row 1 loses every centre, the "
        "vertex pixel (1, 1) included; the hypotenuse moved right by < 1/256 px, so its "
        "centres i + j = 8 are now strictly inside: 2 <= i <= 6, j >= 1, i + j <= 8 (20)",
        frozen_inputs(
            triangles=triangles_array(((1.5, 1.5), (7.5, 1.5 + 1 / 256), (1.5, 7.5))),
            size=(10, 10),
            attrs=np.array([[0.0, 6.0, 12.0]]),
            expected=pixel_mask(10, 10, lambda i, j: (i >= 2) & (i <= 6) & (j >= 1) & (i + j <= 8)),
        ),
        fill_all,
        check_mask,
        "raw floats with E ≥ 0 and no tie rule keep the vertex (1, 1) and (7, 1) on the "
        "sloped edges",
        naive_mesh("inclusive"),
        naive_differs,
    )
)

add_case(
    HardCase(
        "collinear",
        "three distinct vertices on one line through pixel centres: zero area",
        "triangle",
        "covers nothing, attributes NaN everywhere, no warning or division by zero",
        frozen_inputs(
            triangles=triangles_array(((1.5, 1.5), (4.5, 4.5), (7.5, 7.5))),
            size=(10, 10),
            attrs=np.array([[0.0, 1.0, 2.0]]),
        ),
        fill_all,
        check_nothing,
        "raw floats with E ≥ 0 and no bounding box fill every centre on the line through the "
        "vertices, in the whole image, beyond the vertices too (every E is 0 on it)",
        naive_mesh("inclusive"),
        naive_differs,
    )
)

add_case(
    HardCase(
        "coincident_vertices",
        "two vertices in the same place: zero area, and an edge of length 0",
        "triangle",
        "covers nothing, attributes NaN everywhere",
        frozen_inputs(
            triangles=triangles_array(((2.5, 2.5), (2.5, 2.5), (6.5, 4.5))),
            size=(10, 10),
            attrs=np.array([[0.0, 1.0, 2.0]]),
        ),
        fill_all,
        check_nothing,
        "raw floats with E ≥ 0 and no bounding box fill every centre on the line through the two "
        "distinct points, in the whole image, beyond the segment's ends too",
        naive_mesh("inclusive"),
        naive_differs,
    )
)


def _subpixel():
    tris = triangles_array(
        ((3.3, 2.3), (3.8, 2.4), (3.45, 2.9)),  # contains the centre (3.5, 2.5)
        ((6.6, 2.6), (7.4, 2.7), (7.0, 3.4)),  # between centres
        ((5.5, 5.5), (5.8, 5.5), (5.5, 5.8)),  # vertex on a centre, top and left edges there
        ((9.5, 9.5), (9.2, 9.5), (9.5, 9.2)),  # vertex on a centre, bottom and right edges
    )
    expected = np.zeros((12, 12), dtype=bool)
    expected[2, 3] = expected[5, 5] = True

    def naive(inputs) -> Naive:
        rounded = np.rint(inputs["triangles"])  # no sub-pixel bits: whole-pixel vertices
        return Naive(
            counts=naive_counts(rounded, 12, 12, rule="top_left"), values={"triangles": rounded}
        )  # what it fills, for the picker

    add_case(
        HardCase(
            "subpixel_triangles",
            "triangles smaller than a pixel: each covers one centre or none",
            "triangles",
            "exactly pixels (2, 3) (contains its centre) and (5, 5) (a vertex on the centre "
            "with a top and a left edge there); the one between centres and the one with a "
            "bottom and a right edge at its centre vertex cover nothing",
            frozen_inputs(triangles=tris, size=(12, 12), expected=expected),
            fill_all,
            check_mask,
            "vertices rounded to whole pixels (no sub-pixel precision) change the coverage "
            "both ways: the first and the third triangles lose their centres (two collapse to "
            "zero area), and the fourth, rounded larger, covers a centre not its own",
            naive,
            naive_differs,
        )
    )


_subpixel()


def _slivers():
    g = 1 / 256
    tris = triangles_array(
        ((0.5, 1.5), (60.5, 1.5), (60.5, 1.5 - g)),  # above the shared edge y = 1.5
        ((0.5, 1.5), (60.5, 1.5 + g), (60.5, 1.5)),  # below it
    )
    interior = pixel_mask(4, 64, lambda i, j: (i == 1) & (j >= 1) & (j <= 59))
    add_case(
        HardCase(
            "sliver_pair",
            "two slivers (60 px long, 1/256 px high, area 0.12 px²) sharing an edge along "
            "a row of centres",
            "mesh",
            "the 60 centres of row 1 on the shared edge, columns 0..59 (the shared left "
            "vertex's centre included), covered exactly once (by the sliver below it: a top "
            "edge), none twice; the right vertex's centre (1, 60) lies on both slivers' "
            "right edge and belongs to the neighbour",
            frozen_inputs(
                triangles=tris,
                size=(64, 4),
                interior=interior,
                attrs=np.array([[0.0, 1.0, 2.0], [0.0, 1.0, 2.0]]),
            ),  # fmt: skip
            fill_all,
            check_watertight,
            "raw floats with E ≥ 0 draw the whole row twice, both vertices' centres "
            "included (columns 0..60)",
            naive_mesh("inclusive"),
            naive_double_hits,
        )
    )

    xy = triangles_array(((0.5, 0.5), (63.5, 63.5), (63.5, 63.5 - g)))

    def check(inputs, result: Fills) -> None:
        check_finite(result)
        cov = result.fills[0].coverage
        want = pixel_mask(64, 64, lambda i, j: (i == j) & (i >= 1) & (i <= 62))
        bad = cov != want
        assert not bad.any(), f"diagonal sliver: coverage wrong at {first_pixels(bad)}"
        f = result.fills[0].attrs["f"][cov]
        assert (f >= 0).all() and (f <= 2).all(), "attributes outside the vertex range"

    add_case(
        HardCase(
            "diagonal_sliver",
            "an 89 px diagonal sliver of area 0.12 px² whose long edge runs through 64 centres",
            "triangle",
            "exactly the diagonal centres (k, k) for k = 1..62: the long edge goes up (a left "
            "edge, so its centres count); the end centres (0, 0) and (63, 63) are vertices "
            "that also lie on a down-going (right) edge; barycentrics in [0, 1], attributes "
            "finite and in range",
            frozen_inputs(triangles=xy, size=(64, 64), attrs=np.array([[0.0, 1.0, 2.0]])),
            fill_all,
            check,
            "raw floats with E > 0 lose every diagonal centre: the sliver vanishes",
            naive_mesh("strict"),
            naive_differs,
        )
    )


_slivers()
