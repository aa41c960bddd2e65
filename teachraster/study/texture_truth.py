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
from ..pipeline.texturing.mip_pyramid import mipmap
from ..pipeline.texturing.texel_fetch import lookup
from ..pipeline.texturing.texture_filters import (
    MIPMAP_FILTERS,
    footprint_axes,
    linear_levels,
    mip_level,
)
from .bench import time_interleaved

#: The filters the study compares by default, cheapest first.
STUDY_FILTERS = (
    "nearest",
    "bilinear",
    "nearest_mipmap_nearest",
    "linear_mipmap_nearest",
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
    """
    tex = np.asarray(texture, dtype=np.float64)
    tex3 = tex.reshape(*tex.shape[:2], -1)
    clip, uv = np.asarray(clip, dtype=np.float64), np.asarray(uv, dtype=np.float64)
    height, width = triangle_id.shape
    rows, cols = np.nonzero(triangle_id >= 0)
    out = np.full((height, width, tex3.shape[2]), np.nan)
    rng = np.random.default_rng(seed)
    s = int(samples)
    grid = (np.arange(s) + 0.0) / s
    # About 500 bytes of temporaries per point: 100,000 points keep this under 60 MiB, so a
    # classroom kernel stays small (lesson 09); larger chunks are no faster.
    chunk = max(1, 100_000 // (s * s))
    for start in range(0, len(rows), chunk):
        r, c = rows[start : start + chunk], cols[start : start + chunk]
        n = len(r)
        jit = rng.uniform(0, 1 / s, size=(n, s, s, 2))
        x = (c[:, None, None] + grid[None, None, :] + jit[..., 0]).reshape(-1)
        y = (r[:, None, None] + grid[None, :, None] + jit[..., 1]).reshape(-1)
        tri = np.repeat(triangle_id[r, c], s * s)
        coords, w = exact_uv(clip[tri], uv[tri], x, y, width, height)
        ok = w > 0  # points beyond the horizon see nothing of the plane
        vals = lookup(tex3, coords[:, 0], coords[:, 1], "nearest", "repeat")
        vals[~ok] = 0.0
        count = ok.reshape(n, -1).sum(axis=1)
        total = vals.reshape(n, s * s, -1).sum(axis=1)
        with np.errstate(invalid="ignore", divide="ignore"):
            out[r, c] = total / count[:, None]
    return out if tex.ndim == 3 else out[..., 0]


def texel_reads(filter: str, ddx, ddy, texture_shape, max_anisotropy: int = 16) -> float:
    """Mean texels read per pixel by ``filter``, given the (n, 2) derivatives of (u, v).

    Nearest reads 1, bilinear 4; a linear-between-levels filter reads its within-level count
    twice where λ falls between two levels (once where it is clamped); anisotropic reads a
    trilinear footprint per probe.

    >>> texel_reads("trilinear", [[0.25, 0.0]], [[0.0, 0.25]], (8, 8))   # λ = 1: one level
    4.0
    """
    within = 1 if filter.startswith("nearest") else 4
    if filter in ("nearest", "bilinear") or filter.endswith("mipmap_nearest"):
        return float(within)
    px, py = footprint_axes(ddx, ddy, texture_shape)
    q = len(mipmap(np.zeros(texture_shape[:2]))) - 1
    pmax, pmin = np.maximum(px, py), np.minimum(px, py)
    probes = np.ones(len(px))
    if filter == "anisotropic":
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = np.minimum(np.ceil(pmax / pmin), max_anisotropy)
        probes = np.where(pmax <= 1, 1, ratio)
        pmax = pmax / probes
    with np.errstate(divide="ignore"):
        _, _, t = linear_levels(np.log2(pmax), q)
    return float(np.mean(probes * within * np.where(t > 0, 2, 1)))


def filter_study(
    scene, width: int, height: int, *, filters=STUDY_FILTERS, samples: int = 16, repeat: int = 3
) -> list[dict]:
    """Each filter's error against :func:`footprint_average` and its render time, on ``scene``.

    Returns one row per filter: ``filter``, ``error`` (root-mean-square difference from the
    truth over covered pixels and channels), ``error_minified`` (the same over the pixels
    where the texture is minified, λ > 0, where aliasing lives), ``time_median_s`` (the whole ``tr.render`` of the
    scene, timed round-robin with the others), ``texel_reads`` (mean per pixel) and
    ``uses_mipmaps``.
    """
    frames = {f: render_scene(scene, None, width, height, texture_filter=f) for f in filters}
    first = next(iter(frames.values()))
    clip = scene.clip(width / height)
    truth = footprint_average(clip, scene.mesh.corner("uv"), scene.texture, first.triangle_id,
                              samples=samples)  # fmt: skip
    probe = render_scene(scene, None, width, height, derivatives=True)
    uv = probe.layout["uv"]
    lam = mip_level(probe.ddx[..., uv], probe.ddy[..., uv], scene.texture.shape)
    minified = probe.coverage & (lam > 0)
    fns = [
        (lambda f=f: render_scene(scene, None, width, height, texture_filter=f)) for f in filters
    ]
    times = time_interleaved(fns, repeat)
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
            "time_median_s": t,
            "texel_reads": reads,
            "uses_mipmaps": f in MIPMAP_FILTERS,
        })  # fmt: skip
    return rows
