"""Exercises ``coverage_fraction(xy, pixel, samples)`` and ``resolve(colours, ids, background)``.

Lesson 08 (Akeley, *Reality Engine Graphics*; Fatahalian, CMU 15-462 *Rasterization*): a
multisampled rasteriser decides coverage at S points of each pixel, each exactly like a pixel
centre (snapped vertices, the top-left rule), and the resolve averages the S samples, the
uncovered ones counting as the background (CONVENTIONS, *Multisampling*).

Expected answers are the package's: :func:`teachraster.rasterize` with ``samples=`` the case's
offsets (its ``sample_coverage``) and :meth:`teachraster.pipeline.render_triangles.Frame.resolve`.
Explanations decide each sample again by the same rules (snapped vertices, exact edge
functions on the 1/256 grid, :func:`teachraster.core.edges.passes`) to name the sample that
decides, and compare the answer with what typical mistakes give.
"""

from __future__ import annotations

import functools
import textwrap
from types import SimpleNamespace

import numpy as np

from ..core.blend_factors import linear_to_srgb, srgb_to_linear
from ..core.edges import edge_function
from ..core.fill import rasterize
from ..core.sample_patterns import sample_pattern
from ..core.snapping import snap
from ..core.triangle import Triangle
from ..pipeline.render_triangles import Frame
from .answers import as_number, as_numbers
from .blend_mistakes import EIGHT_BIT
from .cases import SEED, fixed_and_drawn
from .channel_order import channel_order_mistake
from .coverage import TOP_LEFT, covered, kind_of, owns_kind, owns_variants, owns_words
from .exercise import Exercise, Knobs, Mistake, PackageAnswer, Slip
from .scalars import num, vec
from .tolerance import all_close


# -- coverage_fraction ------------------------------------------------------------------------
def exact(v) -> str:
    """A point with every digit a student needs to reproduce it (off-grid values in full)."""
    return "(" + ", ".join(num(c) if (c * 256).is_integer() else repr(float(c)) for c in v) + ")"


def tri_words(xy) -> str:
    return f"v1={exact(xy[0])}, v2={exact(xy[1])}, v3={exact(xy[2])}"


def expected_fraction(xy, pixel, samples) -> float:
    """The package's fraction of ``pixel``'s samples that triangle ``xy`` covers."""
    # r423 WP4: moved by whole pixels to a 1 × 1 frame (the 1/256 grid and E are the same
    # there), so a 2000 px triangle far from the origin costs one pixel, not a 4K frame
    row, col = pixel
    moved = np.asarray(xy, dtype=float) - [col, row]
    fill = rasterize(Triangle(moved), 1, 1, samples=samples)
    return float(fill.sample_coverage[0, 0].mean())


def sample_points(pixel, samples) -> np.ndarray:
    """(S, 2) positions of the samples of ``pixel`` = (row, col): (col + ox, row + oy), each
    offset on the renderer's 1/512 px grid (r422 C1: it rounds any other offset there, half
    to even, and never past the pixel's last grid line, as ``offsets_in_units`` does)."""
    row, col = pixel
    offsets = np.minimum(np.rint(np.asarray(samples, dtype=float) * 512), 511) / 512
    return offsets + np.array([col, row], dtype=float)


def covered_samples(xy, points) -> np.ndarray:
    """Which ``points`` the triangle covers by the rule (snapped vertices, exact edge functions,
    the top-left rule): :func:`.coverage.covered`."""
    return covered(xy, points)


def _edge_words(xy, point) -> str:
    """Words for the edge(s) a point lies exactly on, with the rule's verdict, or ""."""
    v = np.asarray(xy, dtype=float)
    flip = float(edge_function(v[0], v[1], v[2])) < 0
    found = []
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        if float(edge_function(a, b, point)) == 0:
            kind = kind_of(*((b, a) if flip else (a, b)))
            found.append((f"v{k + 1}→v{(k + 1) % 3 + 1}", kind, kind in TOP_LEFT))
    if len(found) == 1:
        name, kind, owns = found[0]
        verdict = "covers it" if owns else "leaves it uncovered"
        return f"lies exactly on edge {name}, a {kind} edge: the top-left rule {verdict}"
    if len(found) == 2:
        (n1, k1, o1), (n2, k2, o2) = found
        verdict = "covers it" if o1 and o2 else "leaves it uncovered"
        return (
            f"lies exactly on a vertex, where edge {n1} (a {k1} edge) meets edge {n2} (a {k2} "
            f"edge): the top-left rule {verdict} (both edges must own it)"
        )
    return ""


#: r423: cases of 6.1's hard table (kept apart: _coverage_cases stays under 100 lines)
R423_HARD = [
    # r423 WP1: a tolerance on the distance E / |edge| (≤ 5e-4 px) or a relative
    # np.isclose on E's two products passed: E's smallest step, 2⁻¹⁷ px², inside a
    # 512 px right edge (the sample 1.5e-8 px from it)
    ("near a tie: a sample 2⁻¹⁷ px² inside a 512 px right edge",
     [[2.375, -100], [2.37890625, 412], [-50, 150]], (156, 2),
     [[0.376953125, 1 / 512]]),
    # r432 WP1: np.isclose on the distance (atol 1e-8 px) passed: the same step inside a
    # 2048 px right edge (the sample 3.7e-9 px from it; E in float32 as b − a, p − a is exact)
    ("near a tie: a sample 2⁻¹⁷ px² inside a 2048 px right edge",
     [[2.375, -100], [2.37890625, 1948], [-50, 150]], (924, 2),
     [[0.376953125, 1 / 512]]),
    # r423 WP2, WP3: the winding, or an edge's kind, decided before snapping passed: a
    # sliver whose winding flips when snapped; a top edge horizontal only once snapped
    ("a sliver whose winding flips when snapped",
     [[0.19921875, 0.06347656], [2.74609375, 0.35644531], [1.5559431, 0.21826552]],
     (0, 1), [[7 / 512, 80 / 512]]),
    ("a top edge horizontal only once snapped, a sample on it",
     [[0, 1.375], [6, 1.3759765625], [3, 6]], (1, 2), [[0.875, 0.375]]),
    # r423 WP4: a triangle of a 4K frame, a sample 2e-5 px outside a 2000 px edge: E in
    # float32 (24 bits) cannot hold E's 2⁻¹⁷ px² steps at these sizes
    ("a 4K frame's triangle, a sample 2e-5 px outside its long edge",
     [[1578.640625, 929.24609375], [2995.0234375, 2574.8203125], [2903.03125, 331.234375]],
     (1509, 2078), [[0.259765625, 0.7109375]]),
    # r443 WP1: the zero-area test made on the vertices as given passed (a case collinear
    # once snapped only): collinear as given, a sliver once snapped, a sample inside it
    ("collinear as given, a sliver once snapped, a sample inside it",
     [[0.5 / 256, 0], [1.5 / 256, 4], [2.5 / 256, 8]], (5, 0), [[3 / 512, 0.5]]),
    # r482 WP1: the sample positions rounded to 6 decimals passed (every tie's offset had 4
    # decimals at most): a sample on a right edge at x = 2 + 1/512 (9 decimals)
    ("a sample on a right edge at x = 2 + 1/512 px (9 decimals)",
     [[2, 0], [2 + 1 / 256, 2], [0, 1]], (1, 2), [[1 / 512, 0]]),
    # r482 WP2: the area E(v1, v2, v3) alone in float32 passed: a 1880 px sliver whose
    # area is 0 in float32 (−0.078125 px² exactly), a sample on its top-left edge
    ("a long sliver, its area 0 in float32, a sample on a top-left edge",
     [[0, 0], [700, 940], [1400.01171875, 1880.015625]], (47, 35), [[0, 0]]),
    # r499 MN6: sample positions in float16 were told "a tolerance" (they moved only the
    # 512 px edge's sample): row 40, where float16 keeps 1/32 px, a sample 1/512 px above a
    # bottom edge, E = 1/64 px² (no tolerance reaches it), moved below it by float16
    ("a sample 1/512 px inside a bottom edge at row 40",
     [[0, 30], [8, 40.0234375], [0, 40.0234375]], (40, 2), [[0.5, 11 / 512]]),
]  # fmt: skip


def _coverage_cases(rng, word):
    """Hard cases (samples on edges, off-grid vertices, ties of the snapping) then random."""
    four, out = sample_pattern(4), []
    hard = [
        ("the whole pixel covered", [[0, 0], [8, 0], [0, 8]], (1, 1), four),
        ("sample 0 on a left edge", [[2.375, -1], [6, 1.5], [2.375, 5]], (1, 2), four),
        ("sample 0 on a right edge", [[2.375, -1], [2.375, 5], [-2, 1.5]], (1, 2), four),
        ("sample 1 on a top edge", [[0, 1.375], [6, 1.375], [3, 6]], (1, 2), four),
        ("sample 1 on a bottom edge", [[0, 1.375], [3, -4], [6, 1.375]], (1, 2), four),
        ("a vertex on sample 2", [[2.125, 1.625], [5, 0], [5, 4]], (1, 2), four),
        ("counter-clockwise, sample 0 on a left edge", [[2.375, -1], [2.375, 5], [6, 1.5]], (1, 2), four),  # fmt: skip
        ("off the grid: a right edge 1/1024 px right of sample 0",
         [[2.375 + 1 / 1024, -1], [2.375 + 1 / 1024, 5], [-2, 1.5]], (1, 2), four),
        ("off the grid: a left edge 1/1024 px right of sample 0",
         [[2.375 + 1 / 1024, -1], [6, 1.5], [2.375 + 1 / 1024, 5]], (1, 2), four),
        ("off the grid: 3/1024 px right of sample 0 rounds up, away from it",
         [[2.375 + 3 / 1024, -1], [6, 1.5], [2.375 + 3 / 1024, 5]], (1, 2), four),
        # r40 06-1 (issue 30): a vertex off the grid in y too, so that snapping x alone fails
        ("off the grid: a top edge 1/1024 px below sample 1",
         [[0, 1.375 + 1 / 1024], [6, 1.375 + 1 / 1024], [3, 6]], (1, 2), four),
        ("off the grid: a bottom edge 1/1024 px below sample 1",
         [[0, 1.375 + 1 / 1024], [3, -4], [6, 1.375 + 1 / 1024]], (1, 2), four),
        ("off the grid: a half step (1/512 px) rounds to even, onto sample 0",
         [[2.375 + 1 / 512, -1], [6, 1.5], [2.375 + 1 / 512, 5]], (1, 2), four),
        # r293 MN1: a grid of 1/512 px (or 1/128) gave the same answers as rounding half up
        # (or down) on every case: one sample between the grids tells each pair apart
        ("off the grid: a right edge 1/512 px right of the grid, the sample on it",
         [[2.375 + 1 / 512, -1], [2.375 + 1 / 512, 5], [-2, 1.5]], (1, 2),
         [[0.375 + 1 / 512, 0.125]]),
        ("off the grid: 7/1024 px past the grid rounds up, past the sample",
         [[2.375 + 7 / 1024, -1], [6, 1.5], [2.375 + 7 / 1024, 5]], (1, 2),
         [[0.375 + 1 / 256, 0.125]]),
        # r308 WP1: snapping the samples too passed every case (each sample off the 1/256
        # grid was far from an edge): a sample 1/512 px outside a left edge on the grid rounds
        # (half to even) onto it, where the edge owns it
        ("a sample 1/512 px left of a left edge (samples are not snapped)",
         [[2.375, -1], [6, 1.5], [2.375, 5]], (1, 2), [[0.375 - 1 / 512, 0.125]]),
        # r422 WP1: E's smallest sizes on the grid, just outside an owning edge and just
        # inside one that does not own (a tolerance on E, np.isclose, a 1/65536 bias passed)
        ("near a tie: a sample 1/512 px left of a short left edge",
         [[2.375, 1], [3, 1.125], [2.375, 1.25]], (1, 2), [[0.375 - 1 / 512, 0.125]]),
        ("near a tie: a sample 1/512 px inside a 1/128 px right edge",
         [[2.375, 1.125], [2.375, 1.1328125], [2.25, 1.125]], (1, 2),
         [[0.375 - 1 / 512, 0.125 + 1 / 512]]),
        ("near a tie: a sample 1/512 px above a 1/256 px top edge (E = −1/131072)",
         [[2.375, 1.125], [2.375 + 1 / 256, 1.125], [2.375, 1.125 + 1 / 256]], (1, 2),
         [[0.375 + 1 / 512, 0.125 - 1 / 512]]),
        ("near a tie: a sample 1/512 px above a 1/256 px bottom edge (E = 1/131072)",
         [[2.375, 1], [2.375 + 1 / 256, 1.125], [2.375, 1.125]], (1, 2),
         [[0.375 + 1 / 512, 0.125 - 1 / 512]]),
        # a tolerance on the distance E / |edge| (1e-3 px) passed: a long steep edge, its
        # nearest sample 0.00073 px away (|E| = 0.0044), outside an owning edge, inside one
        # that does not own
        ("near a tie: a sample 0.00073 px left of a long left edge",
         [[2.375, -1], [6, 1.5], [2.375 + 1 / 256, 5]], (0, 2), [[0.375, 0.125]]),
        ("near a tie: a sample 0.00073 px inside a long right edge",
         [[2.375, -1], [2.375 + 1 / 256, 5], [-2, 1.5]], (0, 2), [[0.375, 0.125]]),
        # r422 WP2: a vertex where a top edge meets a right one (either owner passed), and a
        # sample on a top edge's line past its end, outside the right edge (the first edge
        # at E = 0 deciding passed)
        ("a sample on the vertex of a top and a right edge",
         [[0, 1.125], [2.375, 1.125], [1, 3]], (1, 2), [[0.375, 0.125]]),
        ("a sample on a top edge's line, past its end",
         [[0, 1.125], [2.5, 1.125], [1, 3]], (1, 2), [[0.875, 0.125]]),
        *R423_HARD,
        ("zero area through the samples", [[2.375, 1.125], [2.875, 1.375], [3.375, 1.625]], (1, 2), four),  # fmt: skip
        ("one sample at the centre, on an edge", [[2.5, 0], [6, 3], [2.5, 6]], (1, 2), sample_pattern(1)),  # fmt: skip
        ("2 samples, a diagonal through both", [[0, 0], [8, 8], [0, 8]], (1, 1), sample_pattern(2)),
        ("8 samples, a thin sliver", [[1.0, 1.0], [3.0, 1.3], [1.0, 1.2]], (1, 1), sample_pattern(8)),  # fmt: skip
        ("16 samples, a small triangle inside", [[1.2, 1.1], [1.9, 1.4], [1.3, 1.8]], (1, 1), sample_pattern(16)),  # fmt: skip
        ("ordered 2×2 grid, an edge along its column", [[1.25, 0], [4, 2], [1.25, 4]], (1, 1), sample_pattern(4, "grid")),  # fmt: skip
        ("a pixel outside the triangle", [[0, 0], [3, 0], [0, 3]], (4, 4), four),
    ]  # fmt: skip
    for label, xy, pixel, samples in hard:
        out.append(_coverage_case(label, np.array(xy, dtype=float), pixel, samples))
    for n in range(16):
        xy = snap(rng.uniform(0, 6, size=(3, 2)))
        lo, hi = np.floor(xy.min(axis=0)).astype(int), np.floor(xy.max(axis=0)).astype(int)
        pixel = (int(rng.integers(lo[1], hi[1] + 1)), int(rng.integers(lo[0], hi[0] + 1)))
        kind = ("standard", "random", "jittered")[n % 3]
        count = (4, 8, 16)[n % 3] if kind == "standard" else (5, 4, 9)[n % 3]
        samples = sample_pattern(count, kind, seed=n)
        label = f"{word} {n + 1}: {count} {kind} samples"
        out.append(_coverage_case(label, xy, pixel, samples))
    return out


# the fixed cases, then a few drawn for each check (r49: a harvested table fails)
coverage_cases = fixed_and_drawn(_coverage_cases, SEED + 60)


def _coverage_case(label, xy, pixel, samples):
    samples = np.array(samples, dtype=float)
    args = (xy, pixel, samples)
    return (f"{label}, pixel {pixel}", args, expected_fraction(*args))


def explain_coverage(args, expected, got) -> str:
    xy, pixel, samples = args
    s = len(samples)
    snapped = snap(xy)
    points = sample_points(pixel, samples)
    inside = covered_samples(snapped, points)
    which = ", ".join(str(k) for k in np.flatnonzero(inside)) or "none"
    return (
        f"pixel (row {pixel[0]}, col {pixel[1]}) of {tri_words(xy)} with {s} sample{'s' * (s != 1)}: the rule "
        f"covers {int(inside.sum())} of {s} (samples {which}), {num(expected)}; yours is "
        f"{num(got, expected)}"
    )


#: r443 MN1: the ways a student rounds the sample positions onto the vertices' 1/256 grid (only
#: ``snap``'s half to even was named; floor(x·256 + ½) was told "a tolerance on E"). Rounding
#: down or up is left out: on the few cases a sample moves there, it gave the answers of the
#: area decided before snapping by coincidence
SAMPLE_SNAPS = {
    "snapped": ("", snap),
    "snapped half up": (
        ", rounding half up",
        lambda p: np.floor(np.asarray(p, float) * 256 + 0.5) / 256,
    ),
    # r508 MN2: floored to the grid, told the vertices' "snapping rounds … not down"
    "floored": (", rounding down", lambda p: np.floor(np.asarray(p, float) * 256) / 256),
}


#: Where a mistaken coverage_fraction puts the points it tests, from (pixel, samples).
POINTS = {
    "samples": lambda pixel, samples: sample_points(pixel, samples),
    "centre": lambda pixel, samples: np.array([[pixel[1] + 0.5, pixel[0] + 0.5]]),
    "from the centre": lambda pixel, samples: sample_points(pixel, samples) + 0.5,
    "minus a half": lambda pixel, samples: sample_points(pixel, samples) - 0.5,
    "y up": lambda pixel, samples: np.asarray(samples, float) * [1, -1] + [pixel[1], pixel[0] + 1],
    "(row, col)": lambda pixel, samples: np.asarray(samples, float) + [pixel[0], pixel[1]],
    "(oy, ox)": lambda pixel, samples: np.asarray(samples, float)[:, ::-1] + [pixel[1], pixel[0]],
    **{
        how: (lambda pixel, samples, f=f: f(sample_points(pixel, samples)))
        for how, (_, f) in SAMPLE_SNAPS.items()
    },
    # r432 HN1: the standard pattern in place of the given offsets; the centre as one more
    "pattern": lambda pixel, samples: sample_pattern(len(samples)) + [pixel[1], pixel[0]],
    # r482 HN4: sample_pattern(4) whatever the samples given
    "pattern 4": lambda pixel, samples: sample_pattern(4) + [pixel[1], pixel[0]],
    "centre too": lambda pixel, samples: np.vstack(
        [sample_points(pixel, samples), [[pixel[1] + 0.5, pixel[0] + 0.5]]]
    ),
}
SNAPPING = {
    "even": snap,
    "none": lambda xy: np.asarray(xy, dtype=float),
    "half up": lambda xy: np.floor(np.asarray(xy, float) * 256 + 0.5) / 256,
    "down": lambda xy: np.floor(np.asarray(xy, float) * 256) / 256,
    "up": lambda xy: np.ceil(np.asarray(xy, float) * 256) / 256,  # r443 MN2: told "unsnapped"
    # one coordinate snapped, the other raw (r40 06-1: x alone passed every case)
    "x only": lambda xy: np.column_stack([snap(xy)[:, 0], np.asarray(xy, float)[:, 1]]),
    "y only": lambda xy: np.column_stack([np.asarray(xy, float)[:, 0], snap(xy)[:, 1]]),
}
#: Sub-pixel bits of the other grids a student may snap to (r293 MN1: 1/16 px, GL's least
#: SUBPIXEL_BITS, was told "not down" and "(ox, oy) the other way round"): whole pixels,
#: 1/16, 1/64, 1/128 and 1/512 px, each rounded half to even as the rule's 1/256.
GRIDS = (0, 4, 6, 7, 9)
SNAPPING.update({f"{b} bits": (lambda xy, b=b: np.rint(np.asarray(xy, float) * 2**b) / 2**b)
                 for b in GRIDS})  # fmt: skip
#: r422 MN2: decimal places a student may round to (np.round(xy, 2): 2.375 → 2.38).
DECIMALS = (1, 2, 3, 4)
SNAPPING.update({f"{d} decimals": (lambda xy, d=d: np.round(np.asarray(xy, float), d))
                 for d in DECIMALS})  # fmt: skip


def _snapped_samples_words(how: str = "snapped"):
    """r308 WP1: the sample positions snapped to the vertices' grid (r443 MN1: by any of
    :data:`SAMPLE_SNAPS`' roundings), named with the sample that snapping moves onto (or
    across) an edge here."""
    rounding, rounded = SAMPLE_SNAPS[how]

    def words(args, expected, got) -> str:
        _, pixel, samples = args
        points = sample_points(pixel, samples)
        moved = ", ".join(f"sample {k} {exact(a)} → {exact(b)}"
                          for k, (a, b) in enumerate(zip(points, rounded(points))) if (a != b).any())  # fmt: skip
        return (
            f"you snapped the sample positions to the 1/256 grid too{rounding}: only the "
            "vertices are snapped; a sample lies where its offset puts it (col + ox, row + oy), "
            f"on the 1/512 grid as given{': here ' + moved if moved else ''}"
        )

    return words


def _any_sample_words(args, expected, got) -> str:
    """The pixel taken as covered (1) as soon as one sample is: a single sample's yes or no."""
    xy, pixel, samples = args
    k, s = int(covered_samples(snap(xy), sample_points(pixel, samples)).sum()), len(samples)
    return (
        f"you returned 1 because a sample is covered (here {k} of the {s}), as a pixel with "
        "one sample is covered or not: with S samples an edge through the pixel covers a "
        "share of it; count the samples covered and divide by S"
    )


def _own_pattern_words(args, expected, got) -> str:
    """r432 HN1: the standard pattern's positions tested, not the ``samples`` given."""
    _, pixel, samples = args
    theirs = sample_pattern(len(samples)) + [pixel[1], pixel[0]]
    moved = next((f"; here sample {k} is at {exact(a)}, the standard pattern's at {exact(b)}"
                  for k, (a, b) in enumerate(zip(sample_points(pixel, samples), theirs))
                  if (a != b).any()), "")  # fmt: skip
    return (
        "you tested other sample positions than the `samples` given (sample_pattern(S)'s?): "
        "the offsets are an argument, any pattern, and sample s lies at (col + ox, row + oy) "
        f"with (ox, oy) = samples[s]{moved}"
    )


def _centre_too_words(args, expected, got) -> str:
    """r432 HN1: the pixel centre counted as an (S + 1)-th sample."""
    _, pixel, samples = args
    s = len(samples)
    return (
        f"you counted the pixel centre as one more sample: {s + 1} points, divided by {s + 1}; "
        f"the fraction is over the {s} samples given only (the centre is no sample unless "
        "the pattern puts one there)"
    )


#: An edge's kind seen from the other end (an edge walked backwards).
_REVERSED_KIND = {"top": "bottom", "bottom": "top", "left": "right", "right": "left"}


def fraction_with(
    xy, pixel, samples, *, snapping="even", owns=TOP_LEFT, winding="both", points="samples",
    count=False,
):  # fmt: skip
    """coverage_fraction with the usual mistakes as knobs (the defaults are the rule)."""
    pts = POINTS[points](pixel, samples)
    v = SNAPPING[snapping](xy)
    if winding == "ties unturned":  # signs flipped for a counter-clockwise triangle, but its
        # edges classified as given, walked backwards: top taken for bottom, left for right
        if float(edge_function(v[0], v[1], v[2])) < 0:
            owns = frozenset(_REVERSED_KIND[k] for k in owns)
        winding = "both"
    inside = covered(v, pts, owns, winding, vertices="exact")
    share = {True: float(inside.sum()), "percent": 100 * float(inside.mean()),
             "uncovered": 1 - float(inside.mean()), "any": float(inside.any())}  # fmt: skip
    return share.get(count, float(inside.mean()))


def _snap_words(args, expected, got) -> str:
    xy = args[0]
    moved = ", ".join(f"{exact(a)} → {exact(b)}" for a, b in zip(xy, snap(xy)) if (a != b).any())
    return (
        "you tested the unsnapped vertices; snap them to the 1/256 grid first (round half to "
        f"even): {moved or 'here they are on the grid already'}"
    )


def _one_axis_words(snapped: str, raw: str):
    def words(args, expected, got) -> str:
        xy = np.asarray(args[0], float)
        k = {"x": 0, "y": 1}[raw]
        moved = ", ".join(f"{exact([a])[1:-1]} → {exact([b])[1:-1]}"
                          for a, b in zip(xy[:, k], snap(xy)[:, k]) if a != b)  # fmt: skip
        return (
            f"you snapped {snapped} but left {raw} unsnapped: snap both coordinates of "
            f"every vertex to the 1/256 grid (here {raw}: {moved})"
        )

    return words


def _grid_words(bits: int):
    def words(args, expected, got) -> str:
        xy = np.asarray(args[0], float)
        grid = "whole pixels" if bits == 0 else f"1/{2**bits} px ({bits} sub-pixel bits)"
        theirs = SNAPPING[f"{bits} bits"](xy)
        moved = ", ".join(f"{exact(a)} → {exact(b)}, not {exact(c)}"
                          for a, b, c in zip(xy, snap(xy), theirs) if (b != c).any())  # fmt: skip
        return (
            f"you snapped the vertices to {grid}; the grid is 1/256 px (8 sub-pixel bits, as "
            f"Direct3D requires), rounded half to even{': ' + moved if moved else ''}"
        )

    return words


def _tie_words(owns):
    def words(args, expected, got):
        xy, pixel, samples = args
        snapped = snap(xy)
        points = sample_points(pixel, samples)
        on = next(((k, w) for k, p in enumerate(points) if (w := _edge_words(snapped, p))), None)
        where = f"; here sample {on[0]} at {vec(points[on[0]])} {on[1]}" if on else ""
        # here the points decided are samples, not centres (r40 06-6)
        return owns_words(owns).replace("centres", "samples").replace("centre", "sample") + where

    return words


_WINDING = (
    "this triangle runs {which} on screen (E(v1, v2, v3) {sign} 0) and you covered none of its "
    "samples: handle both windings (flip the signs, or swap two vertices)"
)

COVERAGE_KNOBS = Knobs(fraction_with, {
    "snapping": [
        Slip("no snapping", _snap_words, "none"),
        Slip("snapping half up", "snapping rounds half to even (np.rint), not half up "
             "(floor(x + ½))", "half up"),
        Slip("snapping down", "snapping rounds to the nearest 1/256 px (half to even), not down",
             "down"),
        Slip("snapping up", "snapping rounds to the nearest 1/256 px (half to even), not up "
             "(np.ceil)", "up"),
        Slip("x snapped only", _one_axis_words("x", "y"), "x only"),
        Slip("y snapped only", _one_axis_words("y", "x"), "y only"),
    ],
    "winding": [
        Slip("one winding only", _WINDING.format(which="counter-clockwise", sign="<"),
             "clockwise only"),
        Slip("one winding only", _WINDING.format(which="clockwise", sign=">"),
             "counter-clockwise only"),
    ],
    "points": [
        Slip("centre only", "you tested the pixel centre only; test each of the samples",
             "centre"),
        Slip("offsets from the centre", "the offsets are from the pixel's top-left corner "
             "(col, row), not its centre: sample s lies at (col + ox, row + oy)",
             "from the centre"),
        Slip("offsets minus a half", "sample s lies at (col + ox, row + oy): the offsets are "
             "from the top-left corner, do not subtract ½", "minus a half"),
        Slip("offsets y up", "the offsets are y down (like window coordinates): y = row + oy, "
             "not row + 1 − oy", "y up"),
        Slip("offsets (oy, ox)", "each offset is (ox, oy), x first: sample s lies at "
             "(col + ox, row + oy); you added them the other way round", "(oy, ox)"),
        Slip("(row, col) order", "pixel is (row, col): a sample lies at x = col + ox, "
             "y = row + oy", "(row, col)"),
    ],
    "count": [
        Slip("count, not fraction", "that is the number of samples covered; the fraction is "
             "(samples covered) / S", True),
    ],
})  # fmt: skip
#: r293 MN1, HN4: slips named alone, never combined with the others (each combination is
#: one more run of every case: the check's CPU)
ALONE_KNOBS = Knobs(fraction_with, {
    "winding": [
        # r293 MN2: told "you cover the samples on top edges and leave out … left and right"
        Slip("tie rule before turning", "this triangle runs counter-clockwise on screen: you "
             "flipped the signs of E but decided which edges are top and left on its edges as "
             "given, each walked backwards (a left edge taken for a right one, a top for a "
             "bottom); decide them on the edges as they run once the triangle is turned "
             "(swap two vertices first)", "ties unturned"),
    ],
    "points": [
        Slip("own sample pattern", _own_pattern_words, "pattern"),
        Slip("own sample pattern", lambda args, expected, got: (
            f"you tested the 4 points of sample_pattern(4), not this pixel's {len(args[2])} "
            f"sample{'s' * (len(args[2]) != 1)}: the offsets are an argument (`samples`), any pattern of any S; sample "
            "s lies at (col + ox, row + oy) with (ox, oy) = samples[s], and the fraction "
            "divides by S = len(samples)"), "pattern 4"),
        Slip("centre as an extra sample", _centre_too_words, "centre too"),
    ],
    "count": [
        Slip("percentage", "that is a percentage (100 × the fraction); return the fraction "
             "itself, between 0 and 1", "percent"),
        Slip("uncovered share", "that is the share of samples the triangle leaves uncovered "
             "(1 − the fraction); return the covered share", "uncovered"),
        # r315 HN: told only the rule, whose "like a pixel centre" pointed at another slip
        Slip("1 if any sample", _any_sample_words, "any"),
    ],
}, most=1)  # fmt: skip
TIE_KNOBS = Knobs(
    fraction_with,
    {"owns": [Slip(owns_kind(o), _tie_words(o), o) for o in owns_variants()]},
    most=1,
)


# -- r422 WP1, WP2, MN1, MN2: a tolerance on E, a tie decided by one edge, decimal grids ------
def _oriented(xy) -> tuple[np.ndarray, list[bool]]:
    """The snapped vertices turned clockwise on screen, and whether each edge owns its ties."""
    v = snap(np.asarray(xy, dtype=float))
    if float(edge_function(v[0], v[1], v[2])) < 0:
        v = v[[0, 2, 1]]
    return v, [kind_of(v[k], v[(k + 1) % 3]) in TOP_LEFT for k in range(3)]


def _edge_table(xy, pixel, samples) -> tuple[np.ndarray, list[bool], float]:
    """E of each oriented edge at each sample (3, S), exact, which edges own, the area."""
    v, own = _oriented(xy)
    points = sample_points(pixel, samples)
    e = np.array([edge_function(v[k], v[(k + 1) % 3], points) for k in range(3)], dtype=float)
    return e, own, float(edge_function(v[0], v[1], v[2]))


def _within(e, own, area, eps_own: float, eps_other: float) -> float:
    if area == 0:
        return 0.0
    eps = np.where(own, -eps_own, eps_other)[:, None]
    return float(np.where(np.asarray(own)[:, None], e >= eps, e > eps).all(axis=0).mean())


def fraction_within(xy, pixel, samples, eps_own: float, eps_other: float) -> float:
    """The fraction with a tolerance on E: E ≥ −eps_own on owning edges, E > eps_other on the
    others (np.isclose(E, 0, atol=ε) as the tie test is eps_own = eps_other = ε)."""
    return _within(*_edge_table(xy, pixel, samples), eps_own, eps_other)


def _tolerances(e) -> list[tuple[float, float]]:
    """(eps_own, eps_other) pairs that give every answer a tolerance on E can give where the
    edge values are ``e``: each ε just above one nonzero |E| (below 1/8 px²), on both sides,
    on one side."""
    small = np.unique(np.abs(e[(e != 0) & (np.abs(e) < 0.125)]))
    out = []
    for lo in small:
        eps = float(lo) * (1 + 1e-9)
        out += [(eps, eps), (0.0, eps), (eps, 0.0)]
    return out


def _tolerances_giving(args, got) -> list[tuple[float, float]]:
    """The tolerances of :func:`_tolerances` that give ``got`` on case ``args``."""
    table = _edge_table(*args)
    g = as_fraction(got)
    return [t for t in _tolerances(table[0]) if abs(_within(*table, *t) - g) <= 1e-6]


def _tolerance_fits(args, expected, got) -> bool | None:
    """Some tolerance ε on E (one side or both) gives this answer, and it is wrong."""
    try:
        return bool(_tolerances_giving(args, got))
    except (TypeError, ValueError):
        return None


def _tolerance_words(args, expected, got) -> str:
    """The sample a tolerance on E (the smallest that gives this answer) decides otherwise
    than the rule, its exact E on the edge it is near, and the rule."""
    xy, pixel, samples = args
    e, own, _ = _edge_table(xy, pixel, samples)
    fits = _tolerances_giving(args, got)
    a, b = min(fits, key=max) if fits else (0.0, 0.0)
    eps = np.array([a if o else b for o in own])[:, None]
    flipped = (e != 0) & (np.abs(e) <= eps)
    k, s = np.argwhere(flipped)[0] if flipped.any() else np.unravel_index(
        int(np.argmin(np.where(e == 0, np.inf, np.abs(e)))), e.shape)  # fmt: skip
    v, _ = _oriented(xy)
    side = "inside" if e[k, s] > 0 else "outside"
    units = int(round(float(e[k, s]) * 131072))
    return (
        f"you took E within a small ε of 0 as a tie (a tolerance on E or on the distance "
        f"E / |edge|, or np.isclose): here "
        f"sample {s} at {exact(sample_points(pixel, samples)[s])} has E = {units}/131072 px² "
        f"({num(float(e[k, s]))}) on a {kind_of(v[k], v[(k + 1) % 3])} edge: {side} it, not on "
        "it. With the vertices on the 1/256 grid and the samples on the 1/512 grid E is exact "
        "and never nearer 0 than 1/131072 without being 0: decide E > 0, or E ≥ 0 on top and "
        f"left edges, with no tolerance{_moved_samples_words(args, got)}"
    )


def _moved_samples_words(args, got) -> str:
    """r499 MN5: sample positions rounded to 4 decimals give the same answers as a tolerance
    on the check's cases: said beside it where they give this one."""
    xy, pixel, samples = args
    points = sample_points(pixel, samples)
    v = snap(np.asarray(xy, dtype=float))
    said = []
    for moved, how in ((np.round(points, 4), "rounded them to 4 decimals"),):
        gives = covered(v, moved, vertices="exact").mean()
        if (moved != points).any() and np.isclose(gives, as_fraction(got)):
            k = int(np.argmax((moved != points).any(axis=1)))
            said.append(f"{how} (sample {k} {exact(points[k])} became {exact(moved[k])})")
    if not said:
        return ""
    return (
        f"; or, with the same answers here, you moved the sample positions: {' or '.join(said)}; "
        "a sample lies exactly where its offset puts it"
    )


def _half_points(xy, pixel, samples):
    """r499 MN6: the sample positions computed in float16 (156.001953125 held as 156)."""
    row, col = pixel
    half = (np.asarray(samples, np.float16) + np.array([col, row], np.float16)).astype(float)
    return float(covered(snap(np.asarray(xy, dtype=float)), half, vertices="exact").mean())


def _half_words(args, expected, got) -> str:
    _, pixel, samples = args
    points = sample_points(pixel, samples)
    row, col = pixel
    half = (np.asarray(samples, np.float16) + np.array([col, row], np.float16)).astype(float)
    k = int(np.argmax((half != points).any(axis=1)))
    return (
        f"you computed the sample positions in float16 (11 significant bits): sample {k} "
        f"{exact(points[k])} became {exact(half[k])}; a sample lies exactly where its offset "
        "puts it: compute in float64"
    )


HALF_POINTS = Mistake("float16 samples", _half_words, gives=_half_points, only_whole=True)


def _transposed_points(xy, pixel, samples):
    """r499 HN12 (r482 HN5): ``samples.T.reshape(-1, 2)``: the x of two samples paired."""
    row, col = pixel
    offsets = np.asarray(samples, dtype=float)
    if len(offsets) < 2:
        return None
    points = offsets.T.reshape(-1, 2) + np.array([col, row], dtype=float)
    return float(covered(snap(np.asarray(xy, dtype=float)), points, vertices="exact").mean())


TRANSPOSED_POINTS = Mistake(
    "samples paired wrong",
    "you paired the coordinates wrongly (samples.T.reshape(-1, 2) puts two x offsets in one "
    "sample): sample s is the row samples[s] = (ox, oy), at (col + ox, row + oy)",
    gives=_transposed_points,
    only_whole=True,
)


TOLERANCE = Mistake("tolerance on E", _tolerance_words, fits=_tolerance_fits, only_whole=True)


def fraction_one_edge(xy, pixel, samples, how: str) -> float:
    """A tie decided by one edge: ``"first k"`` stops at the first edge (from edge k) where
    E < 0 (out) or E = 0 (its own tie rule decides, the edges after it untested); ``"any"``
    covers a sample on a vertex if either of its two edges owns it."""
    e, own, area = _edge_table(xy, pixel, samples)
    if area == 0:
        return 0.0
    own = np.array(own)
    if how == "any":
        zero = e == 0
        ok = (e >= 0).all(axis=0) & (~zero.any(axis=0) | (zero & own[:, None]).any(axis=0))
        return float(ok.mean())
    start = int(how.split()[-1])
    inside = []
    for s in range(e.shape[1]):
        verdict = True
        for k in (start, (start + 1) % 3, (start + 2) % 3):
            if e[k, s] < 0 or e[k, s] == 0:
                verdict = bool(e[k, s] == 0 and own[k])
                break
        inside.append(verdict)
    return float(np.mean(inside))


def _one_edge_words(how: str):
    def words(args, expected, got) -> str:
        xy, pixel, samples = args
        e, _, _ = _edge_table(xy, pixel, samples)
        points = sample_points(pixel, samples)
        on = next(((s, w) for s in range(e.shape[1])
                   if (e[:, s] == 0).any() and (w := _edge_words(snap(xy), points[s]))), None)  # fmt: skip
        beyond = next((s for s in range(e.shape[1]) if (e[:, s] == 0).any() and (e[:, s] < 0).any()), None)  # fmt: skip
        if how == "any":
            head = ("at a vertex, where E = 0 on two edges, you covered the sample if either "
                    "edge owns it: each edge decides its own tie, so both must own it")  # fmt: skip
        else:
            head = ("you let the first edge with E = 0 decide the sample by its tie rule and "
                    "tested no further edge: a sample is covered only if it passes all three, "
                    "each by its own rule (E > 0, or E = 0 on a top or left edge)")  # fmt: skip
        if beyond is not None and how != "any":
            return head + (f"; here sample {beyond} at {exact(points[beyond])} lies on one "
                           "edge's line beyond its end, outside another edge (E < 0 there)")  # fmt: skip
        return head + (f"; here sample {on[0]} at {exact(points[on[0]])} {on[1]}" if on else "")

    return words


ONE_EDGE_KNOBS = Knobs(lambda *a, how: fraction_one_edge(*a, how), {"how": [
    Slip("tie decided by one edge", _one_edge_words(h), h)
    for h in ("first 0", "first 1", "first 2")] + [
    Slip("vertex owned by either edge", _one_edge_words("any"), "any")]}, most=1)  # fmt: skip


def _decimal_words(places: int):
    def words(args, expected, got) -> str:
        xy = np.asarray(args[0], float)
        theirs = np.round(xy, places)
        moved = ", ".join(f"{exact(a)} became {exact(c)}, on the grid {exact(b)}"
                          for a, b, c in zip(xy, snap(xy), theirs) if (b != c).any())  # fmt: skip
        return (
            f"you rounded the vertices to {places} decimal place{'s' * (places != 1)} (a grid "
            f"of 1/{10**places} px), not to the 1/256 px grid (np.rint(v * 256) / 256)"
            f"{': ' + moved if moved else ''}"
        )

    return words


#: r422 MN1, MN2: a grid (binary or decimal) is named only where it gives every answer
#: (a tolerance on E was told "1/16 px"; rounding to 2 decimals "a bottom-right rule").
GRID_MISTAKES = [
    *(Mistake("another snapping grid", _grid_words(b),
              gives=functools.partial(fraction_with, snapping=f"{b} bits"), only_whole=True)
      for b in GRIDS),
    *(Mistake("decimal rounding", _decimal_words(d),
              gives=functools.partial(fraction_with, snapping=f"{d} decimals"), only_whole=True)
      for d in DECIMALS),
    Mistake("samples snapped", _snapped_samples_words("snapped"),
              gives=functools.partial(fraction_with, points="snapped"), only_whole=True),
]  # fmt: skip


# -- r423 WP2, WP3, WP4, MN2, HN1: decisions before snapping, float32 E, //, rounded samples --
def fraction_unsnapped(xy, pixel, samples, decided: str) -> float:
    """E on the snapped vertices, but ``decided`` ("winding" or "kinds") on the vertices as
    given: the triangle turned by the unsnapped winding, or its edges' kinds (top, left…)
    taken from the unsnapped edges."""
    raw = np.asarray(xy, dtype=float)
    v = snap(raw)
    if float(edge_function(v[0], v[1], v[2])) == 0:
        return 0.0
    turn = v if decided == "kinds" else raw
    if float(edge_function(turn[0], turn[1], turn[2])) < 0:
        v, raw = v[[0, 2, 1]], raw[[0, 2, 1]]
    judge = raw if decided == "kinds" else v
    points = sample_points(pixel, samples)
    inside = np.ones(len(points), dtype=bool)
    for k in range(3):
        e = edge_function(v[k], v[(k + 1) % 3], points)
        owns = kind_of(judge[k], judge[(k + 1) % 3]) in TOP_LEFT
        inside &= (e >= 0) if owns else (e > 0)
    return float(inside.mean())


def _winding_words(args, expected, got) -> str:
    raw = np.asarray(args[0], dtype=float)
    before, after = float(edge_function(*raw)), float(edge_function(*snap(raw)))
    return (
        "you decided the winding on the vertices as given, before snapping: snapping moves "
        f"them, and here the snapped triangle runs the other way (E(v1, v2, v3) = "
        f"{num(before)} before snapping, {num(after)} after); snap first, then decide the "
        "winding, the edges' kinds and E on the snapped vertices"
    )


def _kinds_words(args, expected, got) -> str:
    raw = np.asarray(args[0], dtype=float)
    v = snap(raw)
    turn = [0, 2, 1] if float(edge_function(*v)) < 0 else [0, 1, 2]
    changed = [(k, kind_of(raw[turn[k]], raw[turn[(k + 1) % 3]]),
                kind_of(v[turn[k]], v[turn[(k + 1) % 3]])) for k in range(3)]  # fmt: skip
    here = "".join(f"; here edge v{turn[k] + 1}→v{turn[(k + 1) % 3] + 1} is a {a} edge as "
                   f"given but a {b} edge once snapped" for k, a, b in changed if a != b)  # fmt: skip
    return (
        "you decided which edges are top or left on the vertices as given, before snapping: "
        "snapping can make an edge horizontal (a top edge) or turn its direction; decide the "
        f"kinds on the snapped vertices, as E is{here}"
    )


def _e_float32(a, b, p, origin):
    """E in float32, from coordinates taken relative to ``origin`` (float32 throughout)."""
    a, b = (np.asarray(a) - origin).astype(np.float32), (np.asarray(b) - origin).astype(np.float32)
    p = (np.asarray(p) - origin).astype(np.float32)
    return (b[0] - a[0]) * (p[..., 1] - a[1]) - (b[1] - a[1]) * (p[..., 0] - a[0])


def _e_plane32(a, b, p, origin):
    """E in float32 as the plane A·x + B·y + C (r432 MN1): A = −(by − ay), B = bx − ax,
    C = (by − ay)·ax − (bx − ax)·ay, summed (A·x + B·y) + C, float32 throughout."""
    a, b = (np.asarray(a) - origin).astype(np.float32), (np.asarray(b) - origin).astype(np.float32)
    p = (np.asarray(p) - origin).astype(np.float32)
    big_a, big_b = -(b[1] - a[1]), b[0] - a[0]
    c = (b[1] - a[1]) * a[0] - (b[0] - a[0]) * a[1]
    return big_a * p[..., 0] + big_b * p[..., 1] + c


#: E's float32 forms a student writes: (b − a)·(p − a) and the plane A·x + B·y + C
FLOAT32_FORMS = {"difference": _e_float32, "plane": _e_plane32}


def fraction_float32(xy, pixel, samples, local: bool, form: str = "difference") -> float:
    """The rule with E computed in float32 (``form``: :data:`FLOAT32_FORMS`), in window
    coordinates or (``local``) relative to the pixel's corner."""
    origin = np.array([pixel[1], pixel[0]], dtype=float) if local else np.zeros(2)
    v = snap(np.asarray(xy, dtype=float))
    e_of = FLOAT32_FORMS[form]
    area = float(e_of(v[0], v[1], v[2], origin))
    if area == 0:
        return 0.0
    if area < 0:
        v = v[[0, 2, 1]]
    points = sample_points(pixel, samples)
    inside = np.ones(len(points), dtype=bool)
    for k in range(3):
        e = e_of(v[k], v[(k + 1) % 3], points, origin)
        inside &= (e >= 0) if kind_of(v[k], v[(k + 1) % 3]) in TOP_LEFT else (e > 0)
    return float(inside.mean())


def _float32_words(form: str = "difference"):
    def words(args, expected, got) -> str:
        xy, pixel, samples = args
        e, _, _ = _edge_table(xy, pixel, samples)
        k, s = np.unravel_index(int(np.argmin(np.where(e == 0, np.inf, np.abs(e)))), e.shape)
        size = int(np.abs(np.asarray(xy, dtype=float)).max())
        bits = 2 * size.bit_length() + 17  # two products of (1/256)- and (1/512)-grid lengths
        # r432 MN1: the plane form in float32 was told "a tolerance on E"
        plane = (
            " In the form A·x + B·y + C the terms A·x and C are products of whole coordinates, "
            "far larger than E, and E is what is left when they cancel: float32 loses E's last "
            "bits there sooner than in the form (b − a)·(p − a)."
            if form == "plane" else ""
        )  # fmt: skip
        return (
            "you computed E in float32: its 24 bits hold E exactly only in small triangles; "
            f"here the coordinates reach {size} px and E's products, in steps of 2⁻¹⁷ px², "
            f"need about {bits} bits, so a sample just off an edge lands on the wrong side "
            f"(sample {s} has E = {int(round(float(e[k, s]) * 131072))}/131072 px² exactly)."
            f"{plane} Compute E in float64 (53 bits: exact in any frame up to 2¹⁷ px) or in "
            "integers"
        )

    return words


def _floor_words(args, expected, got) -> str:
    xy, pixel, samples = args
    k = int(covered_samples(snap(xy), sample_points(pixel, samples)).sum())
    return (
        f"your fractions are only ever 0 or 1: here {k} of {len(samples)} samples are covered "
        f"and you returned {num(as_fraction(got))}. Integer division (k // S) rounds every "
        "partly covered pixel down to 0: divide with / (or you covered the pixel only where "
        "all its samples are?)"
    )


def _rounded_samples(places: int, said: str = ""):
    def gives(xy, pixel, samples):
        points = np.round(sample_points(pixel, samples), places)
        return float(covered(snap(np.asarray(xy, dtype=float)), points, vertices="exact").mean())

    def words(args, expected, got) -> str:
        _, pixel, samples = args
        points = sample_points(pixel, samples)
        moved = ", ".join(f"sample {k} {exact(a)} became {exact(b)}" for k, (a, b)
                          in enumerate(zip(points, np.round(points, places))) if (a != b).any())  # fmt: skip
        return (
            f"you rounded the sample positions to {said or places} decimal "
            f"place{'s' * (places != 1)}: "
            "a sample lies exactly where its offset puts it, (col + ox, row + oy); only the "
            f"vertices are snapped (to 1/256 px){': here ' + moved if moved else ''}"
        )

    return Mistake("samples rounded to decimals", words, gives=gives, only_whole=True)


R423_MISTAKES = [
    Mistake(
        "winding before snapping",
        _winding_words,
        gives=functools.partial(fraction_unsnapped, decided="winding"),
        only_whole=True,
    ),
    Mistake(
        "edge kinds before snapping",
        _kinds_words,
        gives=functools.partial(fraction_unsnapped, decided="kinds"),
        only_whole=True,
    ),
    # a float32 computation that gives this very answer (gives, not fits): float32 named
    # as the cause however far a whole sample moves the fraction (diagnosis._honest)
    # r432 MN1: the plane form A·x + B·y + C too (it fell through to "tolerance on E"),
    # before TOLERANCE, which also fits it
    *(
        Mistake(
            "float32",
            _float32_words(form),
            gives=functools.partial(fraction_float32, local=s, form=form),
            only_whole=True,
            # the plane form gives the answers of a relative np.isclose of E's two products
            # on every case: named float32 only where the code reads float32
            reads="float32" if form == "plane" else None,
        )
        for form in FLOAT32_FORMS
        for s in (False, True)
    ),
    Mistake(
        "integer division",
        _floor_words,
        gives=lambda *a: float(fraction_with(*a) == 1),
        only_whole=True,
    ),
    # the reader's w37: the count over 4 (the standard pattern's S), told only the rule
    Mistake(
        "divided by 4",
        lambda args, expected, got: (
            f": you divided the samples covered "
            f"by 4, not by this pixel's S = {len(args[2])} samples (len(samples))"
        ),
        gives=lambda *a: fraction_with(*a, count=True) / 4,
        only_whole=True,
    ),
    # r423 HN2: 1.0 on every case but a zero-area one, told only the rule
    Mistake(
        "1 unless zero area",
        ": your function returns 1 on every case but the zero-area "
        "one, whatever the samples: it covers the pixel without testing them (a `return` "
        "reached too early?)",
        gives=lambda xy, pixel, samples: float(
            float(edge_function(*snap(np.asarray(xy, dtype=float)))) != 0
        ),
        only_whole=True,
    ),
]


# -- r443 WP1, HN1-HN3: the zero area decided before snapping; ÷ 2S, the edge tests averaged,
# one sample's verdict alone ---------------------------------------------------------------
def _zero_before_snapping(xy, pixel, samples) -> float:
    """The rule, but 0 wherever the vertices as given are collinear (snapped or not)."""
    raw = np.asarray(xy, dtype=float)
    return 0.0 if float(edge_function(*raw)) == 0 else fraction_with(xy, pixel, samples)


def _zero_words(args, expected, got) -> str:
    xy, pixel, samples = args
    after = float(edge_function(*snap(np.asarray(xy, dtype=float))))
    k = int(covered_samples(snap(xy), sample_points(pixel, samples)).sum())
    return (
        "you refused the triangle as zero-area on its vertices as given, before snapping: "
        f"here they are collinear as given (E(v1, v2, v3) = 0) but not once snapped (E = "
        f"{num(after)} px², a sliver covering {k} of the {len(samples)} samples); snap first, "
        "then decide the area, the winding, the edges' kinds and E on the snapped vertices"
    )


def _edge_tests_mean(xy, pixel, samples) -> float:
    """Each sample's three edge tests (each by its own tie rule) averaged, not and-ed."""
    e, own, area = _edge_table(xy, pixel, samples)
    if area == 0:
        return 0.0
    return float(np.where(np.asarray(own)[:, None], e >= 0, e > 0).mean())


def _edge_tests_words(args, expected, got) -> str:
    e, own, _ = _edge_table(*args)
    passed = np.where(np.asarray(own)[:, None], e >= 0, e > 0)
    return (
        f": you averaged the edge tests ({int(passed.sum())} of the {passed.size} tests, 3 "
        "per sample, pass here), so a sample inside two of its three edges counts as ⅔: a "
        "sample is covered only where it passes all three; count those samples, divide by S"
    )


def _one_sample(which: int):
    name = "sample 0" if which == 0 else "the last sample"

    def gives(xy, pixel, samples):
        return float(fraction_with(xy, pixel, np.asarray(samples)[[which]]))

    words = (f": that is {name}'s verdict alone (1 if it is covered, else 0): the fraction "
             "counts every one of the S samples covered and divides by S")  # fmt: skip
    return Mistake(f"{name} alone", words, gives=gives, only_whole=True)


def _area_before_snapping(xy, pixel, samples) -> float:
    """The area taken once on the vertices as given, before snapping, and both the zero-area
    refusal and the winding decided by it (E and the edges' kinds on the snapped vertices)."""
    if float(edge_function(*np.asarray(xy, dtype=float))) == 0:
        return 0.0
    return fraction_unsnapped(xy, pixel, samples, decided="winding")


def _area_words(args, expected, got) -> str:
    raw = np.asarray(args[0], dtype=float)
    before, after = float(edge_function(*raw)), float(edge_function(*snap(raw)))
    return (
        "you took the area E(v1, v2, v3) on the vertices as given, before snapping, and "
        "decided by it whether the triangle has zero area and which way it runs: snapping "
        f"moves the vertices, and here E(v1, v2, v3) = {num(before)} before snapping, "
        f"{num(after)} after; snap first, then take the area (its zero and its sign), the "
        "edges' kinds and E on the snapped vertices"
    )


R443_MISTAKES = [
    Mistake("area before snapping", _area_words, gives=_area_before_snapping, only_whole=True),
    Mistake("zero area before snapping", _zero_words, gives=_zero_before_snapping,
            only_whole=True),
    Mistake("divided by 2S", lambda args, expected, got: (
        f": you divided by {2 * len(args[2])}, twice the {len(args[2])} samples "
        "(samples.size counts both coordinates of each offset): divide the samples covered "
        "by S = len(samples)"),
        gives=lambda *a: fraction_with(*a, count=True) / (2 * len(a[2])), only_whole=True),
    Mistake("edge tests averaged", _edge_tests_words, gives=_edge_tests_mean, only_whole=True),
    _one_sample(0),
    _one_sample(-1),
    Mistake("samples snapped", _snapped_samples_words("snapped half up"),
            gives=functools.partial(fraction_with, points="snapped half up"), only_whole=True),
    Mistake("samples snapped", _snapped_samples_words("floored"),
            gives=functools.partial(fraction_with, points="floored"), only_whole=True),
]  # fmt: skip


# -- r482 WP2, MN1-MN3, HN1-HN3: the area in float32, the zero area by a tolerance, E in
# int32, a tie counted as half, two edges, the third edge walked backwards ---------------------
def _turned_fraction(v, area, points, e_of) -> float:
    """The rule on vertices ``v`` whose area (as the student computed it) is ``area``: 0 where
    it is 0, turned where it is negative, each edge's E by ``e_of(a, b, points)``."""
    if area == 0:
        return 0.0
    if area < 0:
        v = v[[0, 2, 1]]
    inside = np.ones(len(points), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        e = e_of(a, b, points)
        inside &= (e >= 0) if kind_of(a, b) in TOP_LEFT else (e > 0)
    return float(inside.mean())


def _area_float32(xy, pixel, samples) -> float:
    """E exact, but the area E(v1, v2, v3), its zero and its sign, taken in float32."""
    v = snap(np.asarray(xy, dtype=float))
    area = float(_e_float32(v[0], v[1], v[2], np.zeros(2)))
    return _turned_fraction(v, area, sample_points(pixel, samples), edge_function)


def _area_float32_words(args, expected, got) -> str:
    v = snap(np.asarray(args[0], dtype=float))
    exact_area = float(edge_function(v[0], v[1], v[2]))
    area32 = float(_e_float32(v[0], v[1], v[2], np.zeros(2)))
    did = "refused it as zero-area" if area32 == 0 else "turned it the wrong way round"
    return (
        f"you computed the area E(v1, v2, v3) in float32: here it is {num(exact_area)} px² "
        f"exactly but {num(area32)} in float32 (its two products, about "
        f"{num(abs(float((v[1] - v[0])[0] * (v[2] - v[0])[1])))} px² each, need more than "
        f"float32's 24 bits), so you {did}; compute the area in float64 (or in integers), as E"
    )


def _zero_area_fits(args, expected, got) -> bool | None:
    """0 for a small triangle (0 < |E(v1, v2, v3)| < ½ px², snapped) the rule covers: refused
    as zero-area by some tolerance (one description for every tolerance: a `gives` per
    tolerance cost the check a run of every case each)."""
    area = abs(float(edge_function(*snap(np.asarray(args[0], dtype=float)))))
    try:
        return 0 < area < 0.5 and expected != 0 and as_fraction(got) == 0
    except (TypeError, ValueError):
        return None


def _zero_area_words(args, expected, got) -> str:
    area = float(edge_function(*snap(np.asarray(args[0], dtype=float))))
    return (
        "you refused the triangle as zero-area by a tolerance: its snapped vertices give "
        f"E(v1, v2, v3) = {int(round(area * 65536))}/65536 px² ({num(area)}), a small "
        "triangle but not a degenerate one; on the 1/256 grid E is exact, so refuse the "
        "triangle only where E(v1, v2, v3) == 0"
    )


def _e_int32(a, b, p):
    """E in 32-bit integers of 1/512 px (numpy's int32 wraps around past 2³¹ − 1)."""
    a, b, p = (np.rint(np.asarray(x, dtype=float) * 512).astype(np.int32) for x in (a, b, p))
    with np.errstate(over="ignore"):
        return (b[0] - a[0]) * (p[..., 1] - a[1]) - (b[1] - a[1]) * (p[..., 0] - a[0])


def _fraction_int32(xy, pixel, samples) -> float:
    v = snap(np.asarray(xy, dtype=float))
    area = float(_e_int32(v[0], v[1], v[2]))
    return _turned_fraction(v, area, sample_points(pixel, samples), _e_int32)


def _int32_words(args, expected, got) -> str:
    v = snap(np.asarray(args[0], dtype=float)) * 512
    p = sample_points(args[1], args[2]) * 512
    pts = np.vstack([v, p])
    reach = float(np.ptp(pts[:, 0]) * np.ptp(pts[:, 1]))
    return (
        "you computed E in 32-bit integers (in 1/512 px units): here E's products reach about "
        f"{reach:.3g}, past int32's 2³¹ − 1 = 2147483647, and wrap around to numbers of the "
        "wrong size and sign; take the integers as int64 (exact up to 2⁶³) or E in float64"
    )


def _ties_halved(xy, pixel, samples) -> float:
    """A sample with E == 0 on an edge counted as half covered (a tie split, not owned)."""
    e, _, area = _edge_table(xy, pixel, samples)
    if area == 0:
        return 0.0
    return float(np.where(e > 0, 1.0, np.where(e == 0, 0.5, 0.0)).prod(axis=0).mean())


def _ties_halved_words(args, expected, got) -> str:
    xy, pixel, samples = args
    points = sample_points(pixel, samples)
    on = next(((k, w) for k, p in enumerate(points) if (w := _edge_words(snap(xy), p))), None)
    where = f" (here sample {on[0]} at {vec(points[on[0]])} {on[1]})" if on else ""
    return (
        f"you counted a sample lying exactly on an edge as half covered{where}: a tie is not "
        "split; the top-left rule gives the whole sample to one of the two triangles that "
        "share the edge, so their two fractions still add up"
    )


def _edges_tested(pairs):
    """The rule with the edges ``pairs`` (indices into the turned vertices) tested only."""

    def gives(xy, pixel, samples):
        v, _ = _oriented(xy)
        if float(edge_function(v[0], v[1], v[2])) == 0:
            return 0.0
        points = sample_points(pixel, samples)
        inside = np.ones(len(points), dtype=bool)
        for i, j in pairs:
            e = edge_function(v[i], v[j], points)
            inside &= (e >= 0) if kind_of(v[i], v[j]) in TOP_LEFT else (e > 0)
        return float(inside.mean())

    return gives


R482_MISTAKES = [
    Mistake("area in float32", _area_float32_words, gives=_area_float32, only_whole=True),
    Mistake("zero area by a tolerance", _zero_area_words, fits=_zero_area_fits, only_whole=True),
    # named only where the code reads int32: it gives a tolerance on the distance's answers
    Mistake("E in int32", _int32_words, gives=_fraction_int32, only_whole=True, reads="int32"),
    Mistake("tie as half", _ties_halved_words, gives=_ties_halved, only_whole=True),
    Mistake("two edges", ": you tested 2 of the 3 edges (your loop stops before the third): "
            "a sample is covered only where it lies inside all three",
            gives=_edges_tested(((0, 1), (1, 2))), only_whole=True),
    Mistake("third edge backwards", ": your third edge runs v1→v3, against the other two "
            "(v1→v2, v2→v3): its E has the opposite sign inside the triangle, so no sample "
            "passes all three; walk the edges round the triangle, the third from v3 back to v1 "
            "(v[(k + 1) % 3])", gives=_edges_tested(((0, 1), (1, 2), (0, 2))), only_whole=True),
]  # fmt: skip


#: after TOLERANCE: 3 decimals moves a sample by ≤ 5e-4 px, as a tolerance on the distance
#: does (the 512 px edge's case), and the tolerance is the likelier
#: r482 WP1: 6 decimals passed; 5 to 8 move only a sample of 9 decimals (k/512, k odd), all
#: the same way on the check's cases: one mistake, named by its range
ROUNDED_SAMPLES = [*(_rounded_samples(d) for d in DECIMALS),
                   _rounded_samples(6, said="a few (5 to 8)")]  # fmt: skip

#: r423: before TOLERANCE, which also gives the sliver's and the 4K triangle's answers (each
#: is named only where it gives every answer of the check, so never for a real tolerance)
COVERAGE_MISTAKES = [COVERAGE_KNOBS, TIE_KNOBS, ALONE_KNOBS, ONE_EDGE_KNOBS, *GRID_MISTAKES,
                     *R423_MISTAKES, *R443_MISTAKES, *R482_MISTAKES, HALF_POINTS, TRANSPOSED_POINTS,
                     TOLERANCE,
                     *ROUNDED_SAMPLES]  # fmt: skip


def coverage_mistakes() -> list[Mistake]:
    """Every mistake of 6.1's table, the knobs' combinations spelt out."""
    return [m for f in COVERAGE_MISTAKES for m in (f.mistakes() if isinstance(f, Knobs) else [f])]


def _coverage_rule(args, expected, got) -> str:
    xy = args[0]
    if float(edge_function(*snap(xy))) == 0:
        return ": its vertices are collinear once snapped, and a zero-area triangle covers no sample"  # fmt: skip
    return "; the fraction is (samples covered) / S, each sample decided like a pixel centre"


def draw_coverage_case(ax, case, got):
    """The pixel, its samples (filled where the rule covers them) and the snapped triangle."""
    xy, (row, col), samples = case[1]
    snapped = snap(xy)
    points = sample_points((row, col), samples)
    inside = covered_samples(snapped, points)
    ring = np.vstack([snapped, snapped[:1]])
    # r308 FIG2: the inside shaded (an outline alone, one edge in view, showed no side)
    artists = ax.fill(*snapped.T, color="#2b7bba", alpha=0.15, linewidth=0, label="triangle")
    artists += ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1)
    if got is None:  # before any answer the samples undecided (r64: the stub shows no answer)
        inside = np.zeros(len(points), dtype=bool)
    else:
        artists += ax.plot(*points[inside].T, "o", color="#2b7bba", label="covered")
    label = "not covered" if got is not None else "the samples"
    artists += ax.plot(*points[~inside].T, "o", mfc="none", mec="#888888", label=label)
    box = np.array([[col, row], [col + 1, row], [col + 1, row + 1], [col, row + 1], [col, row]])
    artists += ax.plot(box[:, 0], box[:, 1], color="#ff9f1c", linewidth=2)
    if got is None:
        ax.set_xlabel(f"pixel (row {row}, col {col}), {len(points)} samples")
    else:
        tie = _tie_caption(snapped, points)
        ax.set_xlabel(f"fraction {num(case[2])}, yours {num(got, case[2])}{tie}", fontsize="small")
    ax.set_xlim(col - 1, col + 2)
    ax.set_ylim(row + 2, row - 1)
    ax.set_aspect("equal")
    artists.append(ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1)))
    return artists


def _tie_caption(snapped, points) -> str:
    """A second line under the case: the first sample exactly on an edge and the rule's
    verdict, or "" (r308 FIG2: "sample 0 on a left edge" said nothing of its tie)."""
    on = next(((k, w) for k, p in enumerate(points) if (w := _edge_words(snapped, p))), None)
    if on is None:
        return ""
    k, words = on
    # r422: a vertex's sentence ran past both sides of the figure: wrapped
    return "\n" + textwrap.fill(f"sample {k} {words.replace('lies exactly', 'lies')}", 80)


def as_fraction(value) -> float:
    """A number (a bool counts as 0 or 1: one sample covered, or not)."""
    if isinstance(value, (bool, np.bool_)):
        return float(value)
    return float(as_number(value))


def same_fraction(got, expected, args) -> bool:
    """A fraction k/S: any answer nearer than 1e-6 (a wrong count is 1/S ≥ 1/16 away)."""
    return abs(got - expected) <= 1e-6


#: The time-out's question where the picture calls the function once per pixel and triangle,
#: as its signature asks (r293 HN5: "a Python call per pixel?" asked of such a function).
COVERAGE_SLOW = (
    " (the picture calls coverage_fraction once per pixel and triangle, as it must: is one "
    "call doing far more than snapping three vertices and testing S samples?)"
)


def coverage_exercise(scene) -> Exercise:
    return Exercise(
        "coverage_fraction", coverage_cases, as_fraction, same_fraction, explain_coverage,
        _coverage_rule, COVERAGE_MISTAKES, answers=(PackageAnswer(rasterize),),
        draw=draw_coverage_case, scene=scene, inputs_drawn=True, example=1,
        slow=COVERAGE_SLOW,
        # r422 WP3: the explanations decide each sample by coverage.covered, the checker's
        # own rule: handed in, it is not counted (as exercise 1's check says of it)
        reference=("teachraster.exercises.coverage",),
    )  # fmt: skip


# -- resolve ----------------------------------------------------------------------------------
def expected_resolve(colours, ids, background) -> np.ndarray:
    """The package's resolve of one pixel (:meth:`Frame.resolve` on a 1 × 1 frame)."""
    pixel = SimpleNamespace(sample_triangle_id=np.asarray(ids)[None, None])
    return Frame.resolve(pixel, np.asarray(colours, dtype=float)[None, None], background)[0, 0]


def resolve_case(label, ids, colours, background, dtype=float):
    ids = np.asarray(ids, dtype=np.int64)
    colours = np.asarray(colours, dtype=dtype).copy()
    colours[ids < 0] = np.nan  # no triangle wrote these samples (CONVENTIONS: NaN outside)
    background = np.asarray(background, dtype=float)
    args = (colours, ids, background)
    return (label, args, expected_resolve(*args))


def _resolve_cases(rng, word):
    red, green, blue = np.eye(3)
    white, grey = np.ones(3), np.array([0.2, 0.3, 0.4])
    hard = [
        ("4 samples, all covered", [0, 0, 0, 0], [red] * 4, white),
        ("4 samples, none covered", [-1, -1, -1, -1], [red] * 4, grey),
        ("4 samples, one covered", [-1, 0, -1, -1], [green] * 4, white),
        ("4 samples, two triangles meet", [0, 1, 1, 0], [red, blue, blue, red], grey),
        ("4 samples, three covered", [2, 2, -1, 2], [blue] * 4, white),
        ("1 sample, covered", [0], [green], white),
        ("1 sample, not covered", [-1], [green], grey),
        ("2 samples, one covered", [-1, 3], [red, red], np.zeros(3)),
        ("16 samples, five covered", [-1] * 11 + [0] * 5, [red] * 16, white),
    ]
    out = [resolve_case(*case) for case in hard]
    for n in range(14):
        s = (2, 4, 8, 16)[n % 4]
        ids = rng.integers(-1, 3, size=s)
        palette = rng.uniform(0, 1, size=(3, 3))
        colours = palette[np.maximum(ids, 0)]
        out.append(resolve_case(f"{word} {n + 1}: {s} samples", ids, colours, rng.uniform(0, 1, 3)))
    # colours as matplotlib's imread gives them: float32 (a float32 mean is right, too)
    ids, colours = rng.integers(-1, 3, size=8), rng.uniform(0, 1, size=(8, 3))
    label = "8 samples, float32 colours (as from imread)"
    out.append(resolve_case(label, ids, colours, rng.uniform(0, 1, 3), np.float32))
    return out


resolve_cases = fixed_and_drawn(_resolve_cases, SEED + 61)  # r49: some drawn per check


def as_colour(value) -> np.ndarray:
    return as_numbers(value, (3,), "one colour of 3 channels (R, G, B)")


def _sample_counts(ids) -> tuple[int, int]:
    """A pixel's samples and how many of them are covered (id >= 0), as every resolve
    explanation counts them."""
    return len(ids), int((np.asarray(ids) >= 0).sum())


def same_colour(got, expected, args) -> bool:
    """Within 1e-6: a colour computed in float32 (an image from imread) is right."""
    return all_close(got, expected, 1e-6)


def explain_resolve(args, expected, got) -> str:
    colours, ids, background = args
    s, k = _sample_counts(ids)
    return (
        f"ids {ids.tolist()} ({k} of {s} sample{'s' * (s != 1)} covered), background "
        f"{vec(background)}: the "
        f"resolve is {vec(expected, got)}; yours is {vec(got, expected)}"
    )


def _mean_rule(args) -> str:
    _, ids, _ = args
    s, k = _sample_counts(ids)
    if k == s:  # r308 S3: "the 0 uncovered ones counting as the background" said of none
        return f"the mean over all {s} samples"
    return (
        f"the mean over all {s} samples, the {s - k} uncovered one{'s' * (s - k != 1)} "
        "counting as the background"
    )


def _covered_mean(colours, ids, background):
    """The mean of the covered samples alone; NaN where none is covered, as a mean of no
    samples is (``np.nanmean`` over the samples, the uncovered ones NaN: r85 06, the
    no-sample case was told only "your answer holds NaN")."""
    c = ids >= 0
    return colours[c].mean(axis=0) if c.any() else np.full(colours.shape[-1], np.nan)


def _covered_words(args, expected, got) -> str:
    """The covered samples averaged alone: the background's share of the pixel left out (and,
    with no sample covered, a mean of nothing)."""
    _, ids, _ = args
    s, k = _sample_counts(ids)
    if k == 0:
        said = (": you averaged the covered samples only (np.nanmean over the samples does "
                "so), and none is covered here: the mean of no samples is NaN, but the "
                "background's share here is the whole pixel")  # fmt: skip
    else:
        said = (
            f": you averaged the {k} covered sample{'s' * (k != 1)} only, leaving out the "
            f"background's share of the pixel ({s - k} of its {s} samples), so the "
            "covered ones weigh too much where a triangle's edge crosses the pixel"
        )
    return said + "; " + _mean_rule(args)


def _majority(colours, ids, background):
    c = ids >= 0
    return colours[ids == np.bincount(ids[c]).argmax()][0] if c.any() else None


def _majority_of_ids(colours, ids, background):
    """The id most samples hold, the background's −1 among them, shown alone: the background
    where most samples are uncovered, else that triangle's colour (r361, capstone 12.9: told
    only the hint on a pixel with 1 of 4 samples covered)."""
    ids = np.asarray(ids)
    values, counts = np.unique(ids, return_counts=True)
    top = values[np.argmax(counts)]
    return np.asarray(background, dtype=float) if top < 0 else colours[ids == top].mean(axis=0)


def _resolve_words(text: str, rule: bool = True):
    """A slip's words, then (``rule``) how the mean is taken here; a placeholder's slip (the
    background alone, sample 0 alone) gets no rule: it names what is wrong and leaves the
    resolve to work out (r64 06 D2: the first try of a placeholder printed the answer)."""

    def words(args, expected, got):
        _, ids, background = args
        k = int((ids >= 0).sum())
        said = ": " + text.format(k=k, s="s" * (k != 1), bg=vec(background))
        return said + "; " + _mean_rule(args) if rule else said

    return words


def _with_background(colours, ids, background):
    return np.where((ids >= 0)[:, None], colours, background)


def _fixed_count(args, expected, got, decode=None, mean=False) -> float | None:
    """N ≠ S where ``got`` is the samples (the uncovered ones as the background) summed and
    divided by N, or None; with ``decode`` (6.3: ``srgb_to_linear``) summed in light, the
    sum over N encoded again; with ``mean`` N = S too (6.3: the codes averaged, a mistake)."""
    colours, ids, background = args
    try:
        if decode is not None:
            colours = decode(np.nan_to_num(np.asarray(colours, dtype=float)))
            background, got = decode(background), decode(got)
        total = _with_background(colours, ids, background).sum(axis=0)
        g = np.asarray(got, dtype=float).reshape(total.shape)
    except (TypeError, ValueError):
        return None
    big = int(np.argmax(np.abs(total)))
    if not np.isfinite(g).all() or total[big] == 0 or g[big] == 0:
        return None
    n = float(total[big] / g[big])
    if n <= 1 + 1e-9 or (abs(n - len(ids)) < 1e-9 and not mean):  # 1: the sum, a mistake
        return None
    return n if np.allclose(g * n, total, rtol=1e-9, atol=1e-12) else None


def fixed_count_mistake(words: str = "", decode=None) -> Mistake:
    """The samples summed and divided by one N whatever S (r199 12-9: ``sum / 4``), in 6.2's
    numbers or (``decode``) in 6.3's light; ``words`` come first (6.3: the codes averaged,
    where N = S is a mistake too)."""

    def parameter(args, expected, got):
        return _fixed_count(args, expected, got, decode, mean=bool(words))

    def said(args, expected, got):
        n, s = num(parameter(args, expected, got)), len(args[1])
        if words:
            return (f"{words}, dividing by {n} whatever the number of samples (this pixel has "
                    f"S = {s}, len(sample_ids)): decode first, average over the S samples in "
                    "linear light, encode the mean")  # fmt: skip
        return (f": you divided by {n} whatever the number of samples: this pixel has S = {s}, "
                "and the mean divides by the samples the pixel has (len(sample_ids))")  # fmt: skip

    # only_whole: every failing answer (a max is one sum / 2 by chance)
    return Mistake("fixed count", said, fits=lambda a, e, g: parameter(a, e, g) is not None,
                   parameter=parameter, only_whole=True)  # fmt: skip


#: The uncovered samples taken as black (np.nan_to_num), said in 6.2 and 6.3 (r308 MN1: 6.3
#: asked at which step each value must be light, though the steps were right).
UNCOVERED_AS_BLACK = "the uncovered samples count as the background {bg}, not as black"


def uncovered_as_black(colours, ids, background):
    return np.where((np.asarray(ids) >= 0)[:, None], colours, 0.0).mean(axis=0)


def _per_triangle(colours, ids, background):
    """One equal weight for each triangle a sample shows (and for the background, where a
    sample is uncovered), whatever the share of the samples each has (r315 HN)."""
    ids = np.asarray(ids)
    shown = [colours[ids == t][0] for t in np.unique(ids[ids >= 0])]
    shown += [np.asarray(background, dtype=float)] if (ids < 0).any() else []
    return np.mean(shown, axis=0)


def _per_triangle_words(args, expected, got) -> str:
    _, ids, _ = args
    ids = np.asarray(ids)
    shares = [f"triangle {t} has {int((ids == t).sum())}" for t in np.unique(ids[ids >= 0])]
    shares += [f"the background {int((ids < 0).sum())}"] if (ids < 0).any() else []
    return (
        f": you gave each colour the pixel shows one equal weight ({len(shares)} colours "
        f"averaged), whatever share of the samples it has (of the {len(ids)}: "
        f"{', '.join(shares)}): each sample counts the same, so each colour weighs by its "
        "samples; " + _mean_rule(args)
    )


def _background_if_any_words(args, expected, got) -> str:
    _, ids, _ = args
    s, k = _sample_counts(ids)
    return (
        f": you returned the background because a sample is uncovered: it fills only the "
        f"uncovered samples' share ({s - k} of {s}), and the {k} covered "
        f"{'ones count' if k != 1 else 'one counts'} too; " + _mean_rule(args)
    )


def _by_majority(at_half: bool):
    """The background where too few samples are covered (fewer than half; ``at_half``: half
    or fewer), else the covered samples' mean alone (r341, capstone 12.10: told the covered
    mean only, on a pixel that got the background)."""

    def gives(colours, ids, background):
        s, k = _sample_counts(ids)
        few = 2 * k <= s if at_half else 2 * k < s
        return np.asarray(background, dtype=float) if few else _covered_mean(colours, ids, 0)

    return gives


def _by_majority_words(args, expected, got) -> str:
    _, ids, _ = args
    s, k = _sample_counts(ids)
    return (
        f": you decided the pixel by a vote of its samples ({k} of {s} covered here): the "
        "background where about half or fewer are covered, else the covered samples' mean "
        "alone; a pixel is neither all one nor all the other, each sample is an equal share "
        "of it, covered or not; " + _mean_rule(args)
    )


def _in_light(colours, ids, background):
    """6.3's resolve where 6.2's numbers are plain: decoded from sRGB, averaged, encoded."""
    light = srgb_to_linear(_with_background(np.nan_to_num(colours), ids, background))
    return linear_to_srgb(light.mean(axis=0))


def _on_255(args, expected, got) -> bool:
    """``got`` is the right colour × 255 (unrounded, rounded, or truncated as uint8 does)."""
    g, e = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    if g.shape != e.shape or not np.isfinite(g).all() or g.max() <= 1 + 1e-6:
        return False
    return bool(np.all(np.abs(g - 255 * e) < 1))


def _background_once_words(args, expected, got) -> str:
    """r422 S1: on a pixel whose samples are all covered the background does not count."""
    _, ids, _ = args
    s, k = _sample_counts(ids)
    if k == s:
        return (f": you added the background once to the covered samples and divided by "
                f"k + 1 = {k + 1}: it counts once for every uncovered sample, not once in all, "
                "and here every sample is covered, so the background has no share at all; "
                + _mean_rule(args))  # fmt: skip
    return _resolve_words("the background counts once for every uncovered sample, not once "
                          "in all")(args, expected, got)  # fmt: skip


def _power_mean(g: float):
    """The samples (the uncovered ones the background) raised to g, averaged, the mean
    taken back by the power 1/g (a gamma of g)."""
    return lambda c, i, b: (
        (np.clip(_with_background(c, i, b), 0, None) ** g).mean(axis=0) ** (1 / g)
    )


def _power_mean_words(g: float):
    def words(args, expected, got) -> str:
        return (
            f": you averaged the samples raised to the power {num(g)} and took the mean back "
            f"by 1/{num(g)} (a gamma curve); the uncovered share is right, but 6.2's colours "
            "are plain numbers, to average as they are (6.3 is where a curve comes in, and "
            "there it is sRGB's); " + _mean_rule(args)
        )

    return words


def _share_squared(colours, ids, background):
    s, k = _sample_counts(ids)
    if k == 0:
        return None
    a = k / s
    return a * a * _covered_mean(colours, ids, background) + (1 - a) * np.asarray(background, float)


def _share_squared_words(args, expected, got) -> str:
    _, ids, _ = args
    s, k = _sample_counts(ids)
    return (
        f": you weighted the covered samples' mean by a² = ({k}/{s})², their share twice (as "
        f"a premultiplied colour multiplied again); the background's share 1 − a = "
        f"{s - k}/{s} is right; the covered mean weighs by its share a = {k}/{s} once; "
        + _mean_rule(args)
    )


#: r293 HN2: `* 255` and uint8 answers were told the rule (6.2 and 6.3).
ON_255 = Mistake("0–255 scale", ": that is the colour on the 0–255 scale of 8-bit codes (× 255); "
                 "the colours here are numbers from 0 to 1: return the mean on that scale, "
                 "unrounded", fits=_on_255, only_whole=True)  # fmt: skip
#: r293 MN3: a right colour in BGR was told the weights' rule (the rule shared with 7.2, 9.2).
CHANNEL_ORDER = channel_order_mistake(": the right colour in another channel order", ": return "
                                      "(R, G, B), in the samples' own order", tol=1e-6)  # fmt: skip


# -- r443 HN4-HN7: 6.2's slips told only the rule ---------------------------------------------
def _shares_floored(colours, ids, background):
    """The shares k / S and (S − k) / S taken by integer division: 0 on a partly covered pixel."""
    s, k = _sample_counts(ids)
    covered = _covered_mean(colours, ids, background) if k else np.zeros(np.shape(colours)[-1])
    return (k // s) * covered + ((s - k) // s) * np.asarray(background, dtype=float)


def _shares_floored_words(args, expected, got) -> str:
    _, ids, _ = args
    s, k = _sample_counts(ids)
    return (
        f": your answer is 0 where {k} of the {s} samples {'is' if k == 1 else 'are'} "
        "covered: the shares k / S and "
        f"(S − k) / S taken by integer division ({k} // {s} = {k // s}, {s - k} // {s} = "
        f"{(s - k) // s}) are 0 wherever some but not all samples are covered; divide with /"
    )


def _background_once_partly(colours, ids, background):
    """r443 HN7: the background added once (÷ k + 1) where a sample is uncovered, the plain
    mean where none is (the "background once" slip with its all-covered case right)."""
    s, k = _sample_counts(ids)
    if k == s:
        return np.asarray(colours, dtype=float).mean(axis=0)
    return (np.nansum(colours[ids >= 0], axis=0) + background) / (k + 1)


# -- r482 HN7-HN9: lesson 08's white background pasted, the channels averaged together, the
# background as one more share ------------------------------------------------------------
def _channels_mixed(colours, ids, background):
    """The covered samples' mean over every number (np.nanmean with no axis: one grey), by
    its share, and the background by its own."""
    s, k = _sample_counts(ids)
    if k == 0:
        return None
    grey = float(np.mean(np.asarray(colours, dtype=float)[ids >= 0]))
    return (k * grey + (s - k) * np.asarray(background, dtype=float)) / s


R482_RESOLVE = [
    Mistake("background white", _resolve_words("the uncovered samples count as white (1, 1, "
            "1), not as the background {bg}: lesson 08's cube was cleared to white, and here "
            "the background is an argument (`background`)"),
            gives=lambda c, i, b: _with_background(c, i, np.ones(np.shape(c)[-1])).mean(axis=0)),
    Mistake("channels mixed", _resolve_words("your three channels are one number: the mean ran "
            "over the channels too (np.nanmean or np.mean with no axis); average each channel "
            "over the samples (axis=0)"), gives=_channels_mixed),
    Mistake("background as one more share", lambda a, e, g: (
            f": you counted the background as one more share, S + 1 = {len(a[1]) + 1} in "
            "all, even where every sample is covered: the pixel is the S samples' shares "
            "alone, an uncovered sample's share the background's; " + _mean_rule(a)),
            gives=lambda c, i, b: (_with_background(c, i, b).sum(axis=0) + b) / (len(i) + 1)),
]  # fmt: skip


R443_RESOLVE = [
    Mistake("integer division", _shares_floored_words, gives=_shares_floored),
    Mistake("background once", _background_once_words, gives=_background_once_partly),
    Mistake("last sample", _resolve_words("that is the last sample alone: the resolve mixes "
            "all the samples", rule=False),
            gives=lambda c, i, b: _with_background(c, i, b)[-1]),
    Mistake("triangle 0 only", _resolve_words("you counted only the samples of triangle 0 as "
            "covered (ids == 0): ids number the triangles from 0, every id ≥ 0 is a triangle "
            "that covers the sample, and only −1 marks an uncovered one"),
            gives=lambda c, i, b: np.where((i == 0)[:, None], c, b).mean(axis=0)),
]  # fmt: skip


RESOLVE_MISTAKES = [
    Mistake("covered only", _covered_words, gives=_covered_mean),
    Mistake("uncovered as black", _resolve_words(UNCOVERED_AS_BLACK), gives=uncovered_as_black),
    Mistake("NaN samples", _resolve_words("uncovered samples hold NaN (no triangle wrote "
            "them), and a mean with NaN is NaN"), gives=lambda c, i, b: c.mean(axis=0)),
    Mistake("majority", _resolve_words("that is the colour of the triangle owning most "
            "samples; the resolve mixes them all"), gives=_majority),
    Mistake("majority", _resolve_words("that is the colour most samples hold, the background "
            "counted as one more id (it wins where most samples are uncovered); the resolve "
            "mixes them all"), gives=_majority_of_ids),
    Mistake("background once", _background_once_words,
            gives=lambda c, i, b: (np.nansum(c[i >= 0], axis=0) + b) / ((i >= 0).sum() + 1)),
    Mistake("sum", _resolve_words("that is the sum of the samples; the resolve is their mean"),
            gives=lambda c, i, b: _with_background(c, i, b).sum(axis=0)),
    Mistake("first sample", _resolve_words("that is sample 0 alone: the resolve mixes all "
            "the samples", rule=False),
            gives=lambda c, i, b: _with_background(c, i, b)[0]),
    # r423 HN3: sample 0 as given, NaN where uncovered, was told only "NaN at [0]"
    Mistake("first sample", _resolve_words("that is sample 0's colour as given (NaN where "
            "no triangle covered it, as here): the resolve mixes all the samples, an "
            "uncovered one counting as the background", rule=False),
            gives=lambda c, i, b: np.asarray(c, dtype=float)[0] if i[0] < 0 else None),
    # r40/r49: ids <= 0 taken as uncovered (a test of ids > 0), so triangle 0 turned background
    Mistake("triangle 0 as background", _resolve_words("you counted the samples of triangle 0 "
            "as uncovered: ids number the triangles from 0, and only −1 marks an uncovered "
            "sample (covered is ids ≥ 0, not ids > 0)"),
            gives=lambda c, i, b: np.where((i > 0)[:, None], c, b).mean(axis=0)),
    Mistake("background only", _resolve_words("that is the background alone: the covered "
            "samples' colours count too", rule=False),
            gives=lambda c, i, b: np.asarray(b, dtype=float)),
    # r163 12-7: the samples, the background in the uncovered ones, over the covered count
    Mistake("divided by covered", _resolve_words("you divided by the {k} covered sample{s}, "
            "not by all the samples: each stands for an equal share of the pixel, the "
            "uncovered ones too"),
            gives=lambda c, i, b: _with_background(c, i, b).sum(axis=0) / (i >= 0).sum()
            if (i >= 0).any() else None),
    # r199 12-9: `sum / 4` (the capstone's 4 samples) failed 6.2's cases of other S, asked
    # about an uncovered share on a pixel whose samples were all covered
    fixed_count_mistake(),
    # r308 MN2, HN: the median, the background wherever a sample is uncovered, S − 1
    Mistake("median", _resolve_words("that is the median of the samples (the uncovered ones "
            "rightly the background): the resolve is their mean, each sample an equal share "
            "of the pixel"),
            gives=lambda c, i, b: np.median(_with_background(c, i, b), axis=0)),
    # r315 HN: told only the rule
    Mistake("equal weight per triangle", _per_triangle_words, gives=_per_triangle),
    Mistake("maximum", _resolve_words("that is the largest value of each channel over the "
            "samples (a max, the uncovered ones rightly the background): the resolve is their "
            "mean, each sample an equal share of the pixel"),
            gives=lambda c, i, b: _with_background(c, i, b).max(axis=0)),
    Mistake("background if any uncovered", _background_if_any_words,
            gives=lambda c, i, b: np.asarray(b, dtype=float) if (i < 0).any()
            else c.mean(axis=0)),
    Mistake("background unless most covered", _by_majority_words, gives=_by_majority(False)),
    Mistake("background unless most covered", _by_majority_words, gives=_by_majority(True)),
    Mistake("divided by S − 1", lambda a, e, g: f": you divided by S − 1 = {len(a[1]) - 1}, "
            f"not by the S = {len(a[1])} samples the pixel has (len(sample_ids))",
            gives=lambda c, i, b: _with_background(c, i, b).sum(axis=0) / (len(i) - 1)
            if len(i) > 1 else None),
    # r163 12-9: a mean rounded to 8 bits, round(x·255)/255, was told to count the background
    EIGHT_BIT,
    CHANNEL_ORDER,
    ON_255,
    # r422 HN1: a mean of powers, and the covered share counted twice, were asked about the
    # uncovered share, which they had right
    *(Mistake("mean of powers", _power_mean_words(g), gives=_power_mean(g)) for g in (2, 2.2, 2.4)),
    Mistake("covered share squared", _share_squared_words, gives=_share_squared),
    # r293 HN1: the resolve of 6.3 (in linear light) handed in for 6.2 was told the rule
    Mistake("in linear light", _resolve_words("you decoded the samples from sRGB, averaged "
            "and encoded again, as 6.3 does; here the colours are plain numbers (linear), to "
            "average as they are"), gives=_in_light),
    *R443_RESOLVE,
    *R482_RESOLVE,
]  # fmt: skip


#: 6.2's rule, said for an answer no mistake explains, and the question asked instead on the
#: first failing tries (r64 06 D2: the formula came with the first wrong answer).
RESOLVE_RULE = (
    "; every one of the S samples counts the same, an uncovered one as the background: "
    "(Σ covered colours + (S − k)·background) / S"
)
RESOLVE_HINT = (
    # r422 HN1: asked alone, the uncovered share sent answers that had it right back to it
    "; each sample stands for an equal share of the pixel: what does the pixel show in the "
    "share where no triangle covered the sample, and is your answer the plain mean of the S "
    "colours, that share counted in? Work this case's numbers through by hand"
)
#: The rule and its question where every sample is covered (r199 12-9: the question above was
#: asked of a pixel with no uncovered share, of a sum over 3 or a median).
RESOLVE_RULE_COVERED = "; every one of the S samples counts the same: (Σ colours) / S"
RESOLVE_HINT_COVERED = (
    "; every sample is covered here, each standing for an equal share of the pixel: what "
    "does the pixel show? Work this case's numbers through by hand"
)


def _resolve_rule(args, expected, got) -> str:
    """6.2's rule in the words that fit the case: with or without an uncovered share."""
    return RESOLVE_RULE_COVERED if bool((np.asarray(args[1]) >= 0).all()) else RESOLVE_RULE


def resolve_exercise(scene) -> Exercise:
    return Exercise(
        "resolve", resolve_cases, as_colour, same_colour, explain_resolve,
        _resolve_rule, RESOLVE_MISTAKES,
        answers=(PackageAnswer(Frame.resolve),), draw=draw_resolve_case, scene=scene,
        hints=((RESOLVE_RULE, RESOLVE_HINT), (RESOLVE_RULE_COVERED, RESOLVE_HINT_COVERED)),
        inputs_drawn=True,
        once=((RESOLVE_RULE, "; as said for the first failing case"),
              (RESOLVE_RULE_COVERED, "; as said for the first failing case")),
        example=2,  # one green sample on white: the background's share shows
    )  # fmt: skip


def swatch_words(rgb: str) -> str:
    """ "(r, g, b)" under a swatch: one number where the three are equal (a grey), else one
    a line (r64: three labels of "(0.881, 0.881, 0.881)" ran into each other)."""
    parts = rgb.strip("()").split(", ")
    if len(set(parts)) == 1:
        shade = {"0": "black", "1": "white"}.get(parts[0], "grey")
        return f"{parts[0]}\n({shade})" if len(parts) == 3 else parts[0]
    return "\n".join(parts)


def draw_resolve_case(ax, case, got, extra=None):
    """The case's samples as one strip of colour swatches (an uncovered sample in the
    background's colour, hatched), then the expected colour and yours as swatches with their
    numbers (r49, r64: R/G/B bars showed no colour). Before any answer (``got`` None) the
    samples only: the figure of an untouched stub shows no answer. ``extra`` is a further
    (name, colour) swatch drawn after yours (6.3: the encoded numbers averaged)."""
    from matplotlib.patches import Rectangle

    from .blend_display import colour_texts

    colours, ids, background = case[1]
    s = len(ids)
    covered = np.asarray(ids) >= 0
    strip = np.where(covered[:, None], np.nan_to_num(np.asarray(colours, float)), background)
    width = 3.0 / s  # the strip is 3 units wide whatever S
    artists = [ax.imshow(np.clip(strip[None], 0, 1), extent=(0, 3, 1, 0), interpolation="nearest",
                         aspect="auto")]  # fmt: skip
    for k in np.flatnonzero(~covered):
        artists.append(ax.add_patch(Rectangle((k * width, 0), width, 1, fill=False, hatch="//",
                                              edgecolor="0.5", linewidth=0)))  # fmt: skip
    for k in range(1, s):
        artists += ax.plot([k * width] * 2, [0, 1], color="white", linewidth=0.8)
    ticks = [1.5]
    # r308 S4: "hatched: none" under a strip with no hatching read as the key
    # r422 FIG1: "hatched = uncovered" under a strip with none hatched read as a mistake
    names = [f"{s} samples, {int(covered.sum())} covered\n(hatched = uncovered:\n"
             f"the background {vec(background)})" if not covered.all() else
             f"{s} samples, all covered\n(no sample shows\nthe background {vec(background)})"]  # fmt: skip
    cells = []
    if got is not None:
        want, yours = colour_texts(case[2], got)
        cells = [(f"expected\n{swatch_words(want)}", case[2]),
                 (f"yours\n{swatch_words(yours)}", got)]  # fmt: skip
        cells += [extra] if extra is not None else []
    for k, (name, colour) in enumerate(cells):
        left = 3.6 + 1.6 * k
        rgb = np.clip(np.nan_to_num(np.asarray(colour, float).ravel()[:3], nan=0.5), 0, 1)
        artists.append(ax.imshow(rgb[None, None], extent=(left, left + 1, 1, 0), aspect="auto"))
        ticks.append(left + 0.5)
        names.append(name)
    ax.set_xlim(-0.1, 3.6 + 1.6 * max(len(cells), 2))
    ax.set_ylim(1.05, -0.05)
    ax.set_box_aspect(0.25)  # a row of swatches, the axes' full width for the labels
    ax.set_xticks(ticks, names, fontsize="x-small")
    ax.set_yticks([])
    return artists
