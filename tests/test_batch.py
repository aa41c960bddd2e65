"""``rasterize_batch`` fills many triangles at once with exactly ``tr.rasterize``'s pixels.

Every triangle of a batch is compared with its own ``tr.rasterize`` call (coverage exactly,
barycentrics from the trace within 1e-12), over thousands of random triangles of every kind
the core tests use, both windings, partly off-image, and 8, 4 or no sub-pixel bits.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import cases, random_triangles, reference_coverage, signed_area_exact

import teachraster as tr
from teachraster.pipeline.batched_fill import rasterize_batch

W, H = 23, 17
BATCH_KINDS = ("float", "centre", "subpixel", "tie", "outside", "huge")


def _batch_of(rng, n_per_kind: int) -> np.ndarray:
    """Triangles of every kind, each also with its winding reversed (vertices 1, 2 swapped)."""
    xy = np.concatenate([random_triangles(rng, k, n_per_kind, W, H) for k in BATCH_KINDS])
    return np.concatenate([xy, xy[:, [0, 2, 1]]])


def _per_triangle(frags, n):
    """Split a batch's fragments by triangle: list of (rows, cols, lam) in row-major order."""
    order = np.lexsort((frags.col, frags.row, frags.tri))
    tri, row, col, lam = frags.tri[order], frags.row[order], frags.col[order], frags.lam[order]
    bounds = np.searchsorted(tri, np.arange(n + 1))
    return [(row[a:b], col[a:b], lam[a:b]) for a, b in zip(bounds[:-1], bounds[1:])]


@pytest.mark.parametrize("bits", [8, 4, None])
def test_batch_equals_rasterize_per_triangle(rng, bits):
    """Each triangle's fragments are exactly tr.rasterize's coverage, with its barycentrics."""
    xy = _batch_of(rng, cases(120))  # 6 kinds x 120 x 2 windings = 1440 triangles per bit depth
    frags = rasterize_batch(xy, W, H, subpixel_bits=bits)
    assert frags.lam.shape == (len(frags.tri), 3)
    assert len(np.unique(frags.tri)) > len(xy) // 2  # most triangles do cover pixels
    for t, (rows, cols, lam) in enumerate(_per_triangle(frags, len(xy))):
        fill = tr.rasterize(tr.Triangle(xy[t]), W, H, subpixel_bits=bits, trace=True)
        got = np.zeros((H, W), dtype=bool)
        got[rows, cols] = True
        assert len(rows) == got.sum(), f"duplicate fragments for xy={xy[t].tolist()}"
        np.testing.assert_array_equal(got, fill.coverage, err_msg=f"xy={xy[t].tolist()}")
        # The trace's barycentrics are in row-major order of the covered pixels, like ours.
        want = fill.trace.pixel_barycentric
        np.testing.assert_allclose(lam, want, rtol=0, atol=1e-12, err_msg=f"xy={xy[t].tolist()}")


def test_batch_matches_exact_reference(rng):
    """Independent of tr.rasterize: coverage equals conftest's exact rational reference."""
    xy = _batch_of(rng, 25)
    frags = rasterize_batch(xy, W, H)
    for t, (rows, cols, _) in enumerate(_per_triangle(frags, len(xy))):
        got = np.zeros((H, W), dtype=bool)
        got[rows, cols] = True
        np.testing.assert_array_equal(got, reference_coverage(xy[t], W, H), f"xy={xy[t].tolist()}")


def test_no_duplicate_fragments(rng):
    """No (triangle, row, col) appears twice in a batch, and all lie inside the image."""
    xy = _batch_of(rng, 200)
    f = rasterize_batch(xy, W, H)
    key = (f.tri * H + f.row) * W + f.col
    assert len(np.unique(key)) == len(key)
    assert ((f.row >= 0) & (f.row < H) & (f.col >= 0) & (f.col < W)).all()


def test_fragments_in_triangle_order(rng):
    """Fragments come grouped by triangle, in batch order (the drawing order of render)."""
    xy = _batch_of(rng, 50)
    f = rasterize_batch(xy, W, H)
    assert (np.diff(f.tri) >= 0).all()


def test_barycentrics_reproduce_pixel_centres(rng):
    """Σ λ_k v_k is the pixel centre (unsnapped batch) and Σ λ_k = 1: λ is in vertex order."""
    xy = _batch_of(rng, 60)
    f = rasterize_batch(xy, W, H, subpixel_bits=None)
    np.testing.assert_allclose(f.lam.sum(axis=1), 1.0, atol=1e-9)
    p = np.einsum("nk,nkd->nd", f.lam, xy[f.tri])
    scale = np.abs(xy[f.tri]).max(axis=(1, 2))
    err = np.abs(p - np.stack([f.col + 0.5, f.row + 0.5], axis=1)).max(axis=1)
    assert (err <= 1e-9 * np.maximum(scale, 1.0)).all()


def test_skip_drops_exactly_the_skipped_triangles(rng):
    """``skip`` removes all fragments of the flagged triangles and leaves the others as they were."""
    xy = _batch_of(rng, 60)
    skip = rng.random(len(xy)) < 0.4
    full = rasterize_batch(xy, W, H)
    part = rasterize_batch(xy, W, H, skip=skip)
    assert not skip[part.tri].any()
    keep = ~skip[full.tri]
    for name in ("tri", "row", "col", "lam"):
        np.testing.assert_array_equal(getattr(part, name), getattr(full, name)[keep])
    assert (~skip[full.tri]).sum() < len(full.tri)  # the skip really removed something


@pytest.mark.parametrize("bits", [8, None])
def test_facing_sign(rng, bits):
    """facing is +1 clockwise on screen (positive E(v0,v1,v2) on the snapped grid), -1 CCW, 0 flat."""
    xy = np.concatenate([_batch_of(rng, 40), [[[0, 0], [1, 1], [2, 2]], [[1, 1], [1, 1], [3, 0]]]])
    f = rasterize_batch(xy, W, H, subpixel_bits=bits)
    if bits is None:
        a = xy[:, 1] - xy[:, 0]
        b = xy[:, 2] - xy[:, 0]
        want = np.sign(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])
    else:
        want = np.array([np.sign(signed_area_exact(t, bits)) for t in xy])
    np.testing.assert_array_equal(f.facing, want)
    assert f.facing.dtype == np.int8
    assert set(f.facing.tolist()) == {-1, 0, 1}
    # reversing the winding flips every sign
    g = rasterize_batch(xy[:, [0, 2, 1]], W, H, subpixel_bits=bits)
    np.testing.assert_array_equal(g.facing, -f.facing)


def test_doc_example_shared_diagonal():
    """Two triangles splitting a 2x2 square cover each pixel exactly once (top-left rule)."""
    xy = np.array([[[0, 0], [2, 0], [0, 2]], [[2, 0], [2, 2], [0, 2]]], dtype=float)
    f = rasterize_batch(xy, 2, 2)
    owner = np.full((2, 2), -1)
    owner[f.row, f.col] = f.tri
    np.testing.assert_array_equal(owner, [[0, 1], [1, 1]])


def test_empty_batch():
    """A batch of no triangles gives no fragments, not an error."""
    f = rasterize_batch(np.zeros((0, 3, 2)), W, H)
    assert len(f.tri) == len(f.row) == len(f.col) == 0
    assert f.lam.shape == (0, 3)
    assert f.facing.shape == (0,)
