"""Quad derivatives under MSAA, for mipmapped texture filtering of a multisampled scene.

With multisampling a GPU still shades once per pixel and triangle, at the pixel centre, in
2×2 quads: a pixel is a lane of a triangle's quad when the triangle covers at least one of
its samples (and passes the depth test there); the quad's other lanes are helper pixels,
extrapolated on the triangle's own interpolation (CONVENTIONS, "Quads, derivatives and level
of detail"). So the coarse differences are those of the one-sample render, taken over the
(pixel, triangle) pairs the samples show — a pixel on an edge belongs to the quads of every
triangle it shows, each with its own derivatives (Fatahalian, CMU 15-462 *Texture*).
"""

from __future__ import annotations

import numpy as np

from ..planning.render_plan import Effect, derivatives_effect
from ..texturing.quad_derivatives import attribute_planes, quad_derivatives, shared_quad_pairs
from .stages import clip_stage, viewport_stage


def sample_derivatives(sample_ids, clip, attrs, bits, perspective: bool):
    """Per-sample ``ddx``, ``ddy`` (H, W, S, k) of ``attrs`` and the "derivatives" effect.

    Parameters
    ----------
    sample_ids : (H, W, S) int
        The input triangle each sample shows (-1: none), ``frame.sample_triangle_id``.
    clip, attrs : (N, 3, 4), (N, 3, k) float64
        The scene's clip-space triangles and the attributes to differentiate (e.g. uv).
    bits : int or None
        ``subpixel_bits`` of the render (it sizes the clipper's guard band, as in ``render``).
    perspective : bool
        Perspective-correct interpolation (``interpolation="perspective"``) or affine.

    Samples that show no triangle get NaN.
    """
    height, width, n_samples = sample_ids.shape
    k = attrs.shape[2]
    clipped, _ = clip_stage(clip, attrs, width, height, bits, frozenset())
    window = viewport_stage(clipped, width, height)
    # Any clipped piece of a triangle carries its whole projective interpolation (f/w and
    # 1/w are the same planes on every piece): the first piece stands for its parent.
    first_piece = np.full(len(clip), -1, dtype=np.int64)
    first_piece[clipped.parent[::-1]] = np.arange(len(clipped.parent))[::-1]
    i, j, s = np.nonzero(sample_ids >= 0)
    parent = sample_ids[i, j, s]
    keys, pair = np.unique((i * width + j) * len(clip) + parent, return_inverse=True)
    rows, cols = np.divmod(keys // len(clip), width)
    tris = first_piece[keys % len(clip)]
    w = clipped.clip[:, :, 3]
    planes = attribute_planes(window[:, :, :2], w, clipped.attrs, perspective)
    pairs = shared_quad_pairs(rows, cols, tris, width, height)
    dx, dy, moved = quad_derivatives(rows, cols, tris, planes, "coarse", pairs)
    ddx = np.full((height, width, n_samples, k), np.nan)
    ddy = np.full((height, width, n_samples, k), np.nan)
    ddx[i, j, s], ddy[i, j, s] = dx[pair.ravel()], dy[pair.ravel()]
    effect = derivatives_effect(
        "coarse", len(keys), len(keys), len(pairs[0]), int((~pairs[3]).sum()),
        int(moved.sum()), False,
    )  # fmt: skip
    why = (
        f"samples={n_samples}: shaded once per (pixel, triangle) pair a sample shows, at the "
        f"pixel centre, in 2x2 quads; {effect.why}"
    )
    return ddx, ddy, Effect(effect.name, effect.ran, effect.count, effect.total, "pairs", why)
