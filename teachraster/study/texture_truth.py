"""Ground truth for texture filtering: the texture averaged over each pixel's true footprint.

A filter is an *estimate* of one number per pixel: the mean of the texture over the region of
texture space the pixel square maps to (Fatahalian, CMU 15-462 *Texture*: the pixel's
footprint). Here that number is computed the slow, honest way: many jittered points inside
the pixel square, each mapped *exactly* onto the pixel's triangle (the projective map of its
clip-space plane, solved in float64 without the rasteriser's λ/w set-up), the texture read
there as the box-shaped texels it is made of (nearest), and averaged. The filters' errors
against it, next to their times, continue lesson 06's accuracy-versus-cost story (lesson 09).

>>> import teachraster as tr
>>> scene = tr.get_scene("textured_floor")
>>> rows = filter_study(scene, 48, 36, filters=("nearest", "trilinear"), samples=4, repeat=1)
>>> [r["filter"] for r in rows], rows[0]["error"] > rows[1]["error"]
(['nearest', 'trilinear'], True)
"""

from __future__ import annotations

import numpy as np

from ..pipeline.rendering.render_scenes import render_scene
from ..pipeline.texturing.texture_filters import MIPMAP_FILTERS, levels_read, mip_level
from .bench import time_interleaved

#: The filters the study compares by default: every filter, unmipmapped first.
STUDY_FILTERS = (
    "nearest",
    "bilinear",
    "nearest_mipmap_nearest",
    "linear_mipmap_nearest",
    "nearest_mipmap_linear",
    "trilinear",
    "anisotropic",
)


def exact_uv(clip, uv, x, y, width: int, height: int):
    """Texture coordinates (n, 2) and clip w (n,) at window points (x, y) (n,) on triangles.

    ``clip`` (n, 3, 4) and ``uv`` (n, 3, 2) are each point's triangle. The point on the
    triangle's plane that projects to NDC (x_n, y_n) has clip-space barycentrics
    ``b ∝ A⁻¹ (x_n, y_n, 1)`` with ``A`` the vertices' (x, y, w) as columns; ``w = Σ b_i w_i``
    is ≤ 0 beyond the triangle's horizon (no point of the plane is seen there).
    """
    clip = np.asarray(clip, dtype=np.float64)
    a = np.stack([clip[:, :, 0], clip[:, :, 1], clip[:, :, 3]], axis=1)  # rows x, y, w
    ndc = np.stack([2 * x / width - 1, 1 - 2 * y / height, np.ones_like(x)], axis=1)
    b = np.linalg.solve(a, ndc[..., None])[..., 0]
    b /= b.sum(axis=1, keepdims=True)
    return np.einsum("ni,nik->nk", b, uv), np.einsum("ni,ni->n", b, clip[:, :, 3])


def window_to_uv(clip, uv, width: int, height: int) -> np.ndarray:
    """Each triangle's projective map from window points to texture coordinates: (N, 3, 3).

    Row ``k`` of triangle ``t``'s matrix ``P`` gives, for a window point (x, y),
    ``P[k] @ (x, y, 1)``: the numerators of u (k = 0) and v (k = 1), and the denominator
    (k = 2), so that ``u = P[0] @ p / P[2] @ p``. It is :func:`exact_uv` folded into one matrix
    per triangle: the clip-space barycentrics ``b = A⁻¹ (x_n, y_n, 1)`` enter u, v and their
    sum linearly, and the window-to-NDC map is affine. Since the last row of ``A`` holds the
    w's, ``Σ b_i w_i = 1`` before normalising: the point's w is ``1 / (P[2] @ p)``, positive
    exactly where the plane is seen.
    """
    clip = np.asarray(clip, dtype=np.float64)
    uv = np.asarray(uv, dtype=np.float64)
    a = np.stack([clip[:, :, 0], clip[:, :, 1], clip[:, :, 3]], axis=1)  # rows x, y, w
    rows = np.concatenate([np.swapaxes(uv, 1, 2), np.ones((len(uv), 1, 3))], axis=1)
    to_ndc = np.array([[2.0 / width, 0.0, -1.0], [0.0, -2.0 / height, 1.0], [0.0, 0.0, 1.0]])
    # one 3 x 3 inverse per triangle (not one solve per point)
    return rows @ np.linalg.inv(a) @ to_ndc


def footprint_average(clip, uv, texture, triangle_id, *, samples: int = 16, seed: int = 0):
    """The texture's mean over each covered pixel's footprint: (H, W, C), NaN where uncovered.

    Parameters
    ----------
    clip : (N, 3, 4) array-like
        The clip-space triangles that were rendered.
    uv : (N, 3, 2) array-like
        Their texture coordinates.
    texture : (h, w) or (h, w, C) array
        Level 0, read as box texels (``nearest``), wrapped (``repeat``).
    triangle_id : (H, W) int
        Which triangle each pixel shows (``frame.triangle_id``); its plane is extended over
        the whole pixel square (texture filters do not antialias edges either).
    samples : int
        ``samples`` × ``samples`` jittered points per pixel (one per stratum).
    seed : int
        Seed of the jitter, so the truth is repeatable.

    Notes
    -----
    Each point is mapped by its triangle's projective map (:func:`window_to_uv`, one 3 × 3
    matrix per triangle), the same numbers :func:`exact_uv` gives up to rounding, without a
    linear solve per point; ``tests/test_texture_truth.py`` checks the two against each other
    on random triangles. The texel is read here, not by the engine's filters.
    """
    return _weighted_average(clip, uv, texture, triangle_id, samples, seed, sigma=None)


def gaussian_average(clip, uv, texture, triangle_id, *, sigma: float = 0.5,
                     samples: int = 12, seed: int = 0):  # fmt: skip
    """The texture under a Gaussian of ``sigma`` px around each pixel centre: (H, W, C).

    A second reference beside :func:`footprint_average`'s box (lesson 09): the box passes
    frequencies above the Nyquist limit (its sinc's side lobes), so a filter that keeps the
    box's own moiré scores well against it. This one weights points of the window by
    ``exp(-d² / 2σ²)``, ``d`` their distance from the pixel centre, cut at 3σ, each mapped
    exactly onto the pixel's triangle's plane and read as a box texel: Greene and Heckbert's
    elliptical weighted average, without its local linear approximation. σ = 0.5 px is lesson
    08's Gaussian one pixel wide. ``samples`` × ``samples`` jittered points cover the 6σ square.
    """
    return _weighted_average(clip, uv, texture, triangle_id, samples, seed, sigma=sigma)


def _weighted_average(clip, uv, texture, triangle_id, samples, seed, sigma):
    """The box mean over the pixel square (``sigma`` None) or the Gaussian mean around it."""
    tex = np.asarray(texture, dtype=np.float64)
    th, tw = tex.shape[:2]
    table = tex.reshape(th * tw, -1)
    height, width = triangle_id.shape
    maps = window_to_uv(clip, uv, width, height)
    rows, cols = np.nonzero(triangle_id >= 0)
    out = np.full((height, width, table.shape[1]), np.nan)
    s = int(samples)
    # the points' square around the pixel: the pixel itself, or ±3σ about its centre
    lo, span = (0.0, 1.0) if sigma is None else (0.5 - 3 * sigma, 6 * sigma)
    grid = span * np.arange(s) / s + lo
    jitter = _jitter(seed, s, len(rows)) * span
    # About 200 bytes of temporaries per point: 100,000 points keep this near 20 MiB, so a
    # classroom kernel stays small (lesson 09); larger chunks are no faster.
    chunk = max(1, 100_000 // (s * s))
    for start in range(0, len(rows), chunk):
        r, c = rows[start : start + chunk], cols[start : start + chunk]
        jit = jitter[start : start + chunk]
        dx, dy = grid[None, None, :] + jit[..., 0], grid[None, :, None] + jit[..., 1]
        weight = (np.ones_like(dx) if sigma is None
                  else np.exp(-((dx - 0.5) ** 2 + (dy - 0.5) ** 2) / (2 * sigma**2)))  # fmt: skip
        x, y = c[:, None, None] + dx, r[:, None, None] + dy
        m = maps[triangle_id[r, c]][:, :, :, None, None]  # (n, 3, 3, 1, 1)
        u_num, v_num, den = (m[:, k, 0] * x + m[:, k, 1] * y + m[:, k, 2] for k in range(3))
        out[r, c] = _box_mean(table, th, tw, u_num, v_num, den, weight)
    return out if tex.ndim == 3 else out[..., 0]


def _box_mean(table, th: int, tw: int, u_num, v_num, den, weight) -> np.ndarray:
    """Weighted mean over each pixel's (s, s) points of the texel (nearest, repeat) each sees."""
    n = len(den)
    # NaN, infinity and points beyond the horizon get some texel index (never used)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        u, v = u_num / den, v_num / den
        index = _texel(v, th) * tw + _texel(u, tw)
    ok = (den > 0) & np.isfinite(u) & np.isfinite(v)  # w = 1 / den > 0: the plane is seen
    vals = np.take(table, index.reshape(n, -1), axis=0)  # (n, s * s, C)
    w = np.where(ok, weight, 0.0).reshape(n, -1)
    total = np.einsum("np,npc->nc", w, vals)
    with np.errstate(invalid="ignore", divide="ignore"):
        return total / w.sum(axis=1)[:, None]


def _texel(u: np.ndarray, size: int) -> np.ndarray:
    """Index of the box texel holding coordinate ``u`` along a side of ``size``, tiled."""
    # A coordinate too large to keep a fraction of a texel (u * size overflowing) is reduced
    # by whole periods first, which picks the same texel.
    big = np.abs(u) > 2.0**40
    if big.any():
        u = np.where(big, np.mod(u, 1.0), u)
    i = np.floor(u * size).astype(np.intp)
    # floor-mod (-1 -> size - 1, like GL_REPEAT); for a power of two a mask, much faster
    return i & (size - 1) if size & (size - 1) == 0 else np.mod(i, size)


#: Jitter streams kept between calls (a widget asks for the truth at every new angle), up to
#: this many numbers (32 MiB).
JITTER_CACHE_LIMIT = 4_000_000
_JITTER: dict = {}


def _jitter(seed: int, s: int, n: int) -> np.ndarray:
    """The (n, s, s, 2) jitter of the first n pixels: the seed's stream, cached (see below)."""
    key = (seed, s)
    have = _JITTER.get(key)
    if have is None or len(have) < n:
        if n * s * s * 2 > JITTER_CACHE_LIMIT:  # too big to keep: draw it afresh
            return np.random.default_rng(seed).uniform(0, 1 / s, size=(n, s, s, 2))
        _JITTER.clear()  # one stream at a time: a widget uses one seed and one s
        have = np.random.default_rng(seed).uniform(0, 1 / s, size=(n, s, s, 2))
        _JITTER[key] = have
    return have[:n]


def texel_reads(filter: str, ddx, ddy, texture_shape, max_anisotropy: int = 16) -> float:
    """Mean texels read per pixel by ``filter``, given the (n, 2) derivatives of (u, v).

    Nearest reads 1, bilinear 4; a linear-between-levels filter reads its within-level count
    twice where λ falls between two levels (once where it is clamped); anisotropic reads a
    trilinear footprint per probe. The levels and probes are the engine's
    (:func:`~teachraster.pipeline.texturing.texture_filters.levels_read`).

    >>> texel_reads("trilinear", [[0.25, 0.0]], [[0.0, 0.25]], (8, 8))   # λ = 1: one level
    4.0
    """
    within = 1 if filter.startswith("nearest") else 4
    read = levels_read(filter, ddx, ddy, texture_shape, max_anisotropy)
    return float(np.mean(read.probes * within * np.where(read.weight > 0, 2, 1)))


def filter_study(
    scene, width: int, height: int, *, filters=STUDY_FILTERS, samples: int = 16, repeat: int = 3
) -> list[dict]:
    """Each filter's error against :func:`footprint_average` and its render time, on ``scene``.

    Returns one row per filter: ``filter``, ``error`` (root-mean-square difference from the
    truth over covered pixels and channels), ``error_minified`` (the same over the pixels
    where the texture is minified, λ > 0, where aliasing lives), ``error_minified_gaussian``
    (the same against :func:`gaussian_average`, σ = 0.5 px: a target without the box's
    moiré), ``time_median_s`` (the whole ``tr.render`` of the
    scene, timed round-robin with the others), ``texel_reads`` (mean per pixel) and
    ``uses_mipmaps``.
    """
    frames = {}

    def render(f):  # the frame of each timed call is kept (they are all the same): no extra run
        frames[f] = render_scene(scene, None, width, height, texture_filter=f)

    times = time_interleaved([(lambda f=f: render(f)) for f in filters], repeat)
    first = next(iter(frames.values()))
    clip = scene.clip(width / height)
    truth = footprint_average(clip, scene.mesh.corner("uv"), scene.texture, first.triangle_id,
                              samples=samples)  # fmt: skip
    # the smoother second reference, over a 3 x 3 px square: twice the points each way
    smooth = gaussian_average(clip, scene.mesh.corner("uv"), scene.texture, first.triangle_id,
                              samples=2 * samples)  # fmt: skip
    probe = render_scene(scene, None, width, height, derivatives=True)
    uv = probe.layout["uv"]
    lam = mip_level(probe.ddx[..., uv], probe.ddy[..., uv], scene.texture.shape)
    minified = probe.coverage & (lam > 0)
    rows = []
    for f, t in zip(filters, times):
        frame = frames[f]
        if frame.ddx is None:  # no mipmaps, or magnified everywhere: level 0 only
            reads = 1.0 if f.startswith("nearest") else 4.0
        else:
            d = frame.layout["uv"]
            cov = frame.coverage
            reads = texel_reads(f, frame.ddx[..., d][cov], frame.ddy[..., d][cov],
                                scene.texture.shape)  # fmt: skip
        err = frame.image - truth
        cov = frame.coverage
        rows.append({
            "filter": f,
            "error": float(np.sqrt(np.nanmean(err[cov] ** 2))),
            "error_minified": float(np.sqrt(np.nanmean(err[minified] ** 2))),
            "error_minified_gaussian": float(
                np.sqrt(np.nanmean((frame.image - smooth)[minified] ** 2))
            ),
            "time_median_s": t,
            "texel_reads": reads,
            "uses_mipmaps": f in MIPMAP_FILTERS,
        })  # fmt: skip
    return rows
