"""Exact pixel areas (the antialiasing ground truth) and the sample-count study."""

from __future__ import annotations

import numpy as np
import pytest

import teachraster as tr
from teachraster.study.antialiasing import (
    coverage_error,
    pixel_area,
    sample_error_study,
    study_triangles,
    temporal_history,
)


def test_float_area_equals_rational_area(rng):
    for _ in range(10):
        xy = rng.uniform(-3, 19, (3, 2))
        fast, exact = pixel_area(xy, 16, 16), pixel_area(xy, 16, 16, exact=True)
        np.testing.assert_allclose(fast, exact, rtol=0, atol=1e-12)
        assert ((exact >= 0) & (exact <= 1)).all()


def test_areas_add_up(rng):
    for _ in range(10):
        xy = rng.uniform(0, 16, (3, 2))  # inside the image: every bit of area lands somewhere
        area = abs(tr.Triangle(tr.snap(xy)).signed_area)
        assert pixel_area(xy, 16, 16).sum() == pytest.approx(area, abs=1e-9)
    # a watertight grid of 2 triangles per cell: every pixel under it is covered exactly once
    total = np.zeros((8, 8))
    for x in range(0, 8, 2):
        for y in range(0, 8, 2):
            q = np.array([[x, y], [x + 2, y], [x + 2, y + 2], [x, y + 2]]) + 0.3
            for tri in (q[[0, 1, 2]], q[[0, 2, 3]]):
                total += pixel_area(tri, 8, 8, exact=True)
    np.testing.assert_allclose(total[1:, 1:], 1.0, atol=1e-15)


def test_dense_grid_of_samples_converges_to_the_area(rng):
    """An independent estimate: 32 x 32 ordered samples per pixel."""
    dense = tr.sample_pattern(1024, "grid")
    for _ in range(5):
        xy = rng.uniform(0, 12, (3, 2))
        fill = tr.rasterize(tr.Triangle(xy), 12, 12, samples=dense)
        # each edge crossing a pixel misplaces at most one row or column of 32 samples
        assert np.abs(fill.coverage_fraction - pixel_area(xy, 12, 12)).max() <= 3 / 32


def test_more_samples_less_error():
    rows = sample_error_study(study_triangles(32, 6), size=32, counts=(1, 4, 16),
                              kinds=("standard", "grid"), repeat=1)  # fmt: skip
    err = {(r["kind"], r["samples"]): r["mean_error"] for r in rows}
    assert err["standard", 16] < err["standard", 4] < err["standard", 1]
    assert err["grid", 16] < err["grid", 4]
    assert ("grid", 2) not in err and all(r["time_s"] > 0 for r in rows)
    e = coverage_error(study_triangles(32, 6)[0], 32, 32, 4)
    assert e.shape == (32, 32) and np.abs(e).max() <= 1


def test_study_measures_patterns_of_ones_own():
    """Review r105 08-1: a pattern given by its offsets is measured like the named kinds (the
    lesson prints the 16-sample pattern moved by 1/32 px, its rows centred in their strips)."""
    std16 = tr.sample_pattern(16)
    rows = sample_error_study(study_triangles(32, 6), size=32, counts=(16,), kinds=("standard",),
                              repeat=1, patterns={"same": std16, "centred": std16 + 1 / 32})  # fmt: skip
    err = {r["kind"]: r for r in rows}
    assert err["same"]["mean_error"] == err["standard"]["mean_error"]
    assert err["centred"]["samples"] == 16
    assert err["centred"]["mean_error"] < err["standard"]["mean_error"]
    with pytest.raises(ValueError, match="patterns"):
        sample_error_study(size=8, counts=(), patterns={"bad": [0.5, 0.5]}, repeat=1)
    with pytest.raises(TypeError, match="patterns"):
        sample_error_study(size=8, counts=(), patterns=[[0.5, 0.5]], repeat=1)


def test_bad_input():
    with pytest.raises(ValueError, match="xy"):
        pixel_area([[0, 0], [1, 1]], 4, 4)
    with pytest.raises(ValueError, match="width"):
        pixel_area([[0, 0], [1, 1], [0, 1]], 0, 4)
    with pytest.raises(TypeError, match="exact"):
        pixel_area([[0, 0], [1, 1], [0, 1]], 4, 4, exact="yes")


def test_edge_error_study_follows_mitchell():
    """Stratified (jittered) error ∝ S^-3/4, random ∝ S^-1/2, the ordered grid S^-1/2 on axis
    edges and better than S^-3/4 over all angles (Mitchell, SIGGRAPH 1996)."""
    from teachraster.study.antialiasing import _half_plane_area, edge_error_study

    rows = edge_error_study(counts=(4, 16, 64), edges=1500)
    slope = {}
    for kind in ("grid", "jittered", "random", "grid, axis edges"):
        r = [x for x in rows if x["kind"] == kind]
        slope[kind] = np.polyfit(np.log([x["samples"] for x in r]),
                                 np.log([x["mean_error"] for x in r]), 1)[0]  # fmt: skip
    assert abs(slope["jittered"] + 0.75) < 0.08, slope
    assert abs(slope["random"] + 0.5) < 0.08 and abs(slope["grid, axis edges"] + 0.5) < 0.05
    assert slope["grid"] < slope["jittered"] + 0.02, slope
    # the standard patterns (every sample on a row of its own) fall like 1/S on axis edges:
    # 1/(4S) with rows centred in their strips (2, 4, 8); the 16-sample rows run 0, 1/16, ...
    # 15/16 from the pixel's top edge, a one-sided quantiser: 1/(2S), no better than 8
    std = {x["samples"]: x["mean_error"] for x in rows if x["kind"] == "standard, axis edges"}
    assert sorted(std) == [2, 4, 8, 16]
    for s in (2, 4, 8):
        assert abs(std[s] * 4 * s - 1) < 0.1, (s, std[s])
    assert abs(std[16] * 2 * 16 - 1) < 0.1 and abs(std[16] / std[8] - 1) < 0.1
    # the exact area: a half-plane through the square's centre at any angle halves it
    th = np.linspace(0.1, 3.0, 7)
    nx, ny = np.cos(th), np.sin(th)
    assert np.allclose(_half_plane_area(nx, ny, 0.5 * (nx + ny)), 0.5)
    with pytest.raises(ValueError, match="squares"):
        edge_error_study(counts=(8,))


def test_temporal_history_averages_jittered_frames_and_reprojects():
    """Lesson 08 §6 (review r240 M): TAA's history, h_t = (1 − α)·h_{t−1} + α·frame_t."""
    rng = np.random.default_rng(5)
    frames = rng.uniform(0, 1, (6, 3, 4))
    h = temporal_history(frames, 0.25)
    expect = frames[0].copy()
    for f in frames[1:]:
        expect = 0.75 * expect + 0.25 * f
    np.testing.assert_allclose(h[-1], expect, rtol=0, atol=1e-15)
    np.testing.assert_array_equal(h[0], frames[0])
    assert (temporal_history(frames, 1.0) == frames).all()  # α = 1: no history kept
    # a whole-pixel motion moves the history by whole pixels (the border repeated)
    image = np.zeros((4, 5))
    image[1, 2] = 1.0
    moved = temporal_history([image, np.zeros((4, 5))], 0.5, motion=(1.0, 1.0))[1]
    assert moved[2, 3] == 0.5 and moved.sum() == 0.5
    # a fraction of a pixel: bilinear, the weights summing to one
    half = temporal_history([image, np.zeros((4, 5))], 0.5, motion=(0.0, 0.5))[1]
    assert half[1, 2] == half[2, 2] == 0.25
    # colour channels share the weights
    rgb = np.stack([frames, 2 * frames], axis=-1)
    np.testing.assert_allclose(temporal_history(rgb, 0.25, motion=(0.3, -0.2))[..., 1],
                               2 * temporal_history(frames, 0.25, motion=(0.3, -0.2)))  # fmt: skip
    for bad in (0.0, 1.5, -0.1):
        with pytest.raises(ValueError, match="alpha"):
            temporal_history(frames, bad)
    with pytest.raises(ValueError, match="frames"):
        temporal_history(frames[0], 0.5)


def test_temporal_history_clamps_to_the_new_frames_neighbourhood():
    """Review r245 M1 (lesson 08 §6): with ``clamp`` the fetched history is clamped to the
    new frame's 3 × 3 neighbourhood range before the blend (Karis 2014): a stale value left
    where the new frame shows nothing nearby is gone, and the history stays within the range."""
    from teachraster.study.antialiasing import _neighbourhood_range

    ghost = np.zeros((2, 6, 7))
    ghost[0, 1, 1] = 1.0  # covered in frame 0 only, far from anything in frame 1
    ghost[1, 4, 5] = 1.0
    kept = temporal_history(ghost, 0.1)[1]
    clamped = temporal_history(ghost, 0.1, clamp=True)[1]
    assert kept[1, 1] == pytest.approx(0.9) and clamped[1, 1] == 0.0
    assert clamped[4, 5] == pytest.approx(0.1)  # its neighbourhood holds 1: 0.9·0 + 0.1·1
    rng = np.random.default_rng(3)
    frames = rng.uniform(0, 1, (5, 4, 6, 3))
    h = temporal_history(frames, 0.2, motion=(0.4, -0.3), clamp=True)
    for t in range(1, 5):
        lo, hi = _neighbourhood_range(frames[t])
        blended_lo = 0.8 * lo + 0.2 * frames[t]
        blended_hi = 0.8 * hi + 0.2 * frames[t]
        assert (h[t] >= blended_lo - 1e-12).all() and (h[t] <= blended_hi + 1e-12).all()
    # the range is the 3 × 3 neighbourhood's, per channel, the border repeated
    image = np.arange(12.0).reshape(3, 4)
    lo, hi = _neighbourhood_range(image)
    assert lo[1, 1] == 0 and hi[1, 1] == 10 and lo[0, 0] == 0 and hi[0, 0] == 5
    # no clamp: exactly the old history
    np.testing.assert_array_equal(temporal_history(frames, 0.2, clamp=False),
                                  temporal_history(frames, 0.2))  # fmt: skip


def test_edge_error_study_tries_the_standard_patterns_at_any_angle():
    """Review r245 M3 (lesson 08 §7): the GPU's own patterns against the random edges too,
    with the other kinds' edges unchanged (the fixed patterns draw nothing from the rng)."""
    from teachraster.study.antialiasing import _half_plane_area, edge_error_study

    rows = edge_error_study(counts=(4, 16), edges=800, seed=2)
    plain = edge_error_study(counts=(4, 16), edges=800, seed=2, standard=())
    others = [r for r in rows if "standard" not in r["kind"]]
    assert others == plain
    any_angle = {r["samples"]: r["mean_error"] for r in rows if r["kind"] == "standard"}
    assert sorted(any_angle) == [2, 4, 8, 16]
    # redone: the same 800 edges, drawn as the study draws them
    rng = np.random.default_rng(2)
    theta = rng.uniform(0.0, np.pi, 800)
    nx, ny = np.cos(theta), np.sin(theta)
    c = np.minimum(nx, 0) + np.minimum(ny, 0) + rng.uniform(0, 1, 800) * (abs(nx) + abs(ny))
    area = _half_plane_area(nx, ny, c)
    for s, e in any_angle.items():
        p = tr.sample_pattern(s)
        inside = (nx[:, None] * p[:, 0] + ny[:, None] * p[:, 1] <= c[:, None]).mean(1)
        assert e == pytest.approx(float(np.abs(inside - area).mean()), rel=1e-12)


def test_ghost_sides_tells_a_trail_from_a_blur():
    """Review r254 C1 (lesson 08 §6): ghost pixels counted behind and ahead of the motion."""
    from teachraster.study.antialiasing import ghost_sides

    target = np.zeros((1, 6, 3))
    target[0, 3, 1] = 1.0  # the shape: one pixel, moving down
    trail = np.zeros_like(target)
    trail[0, :3, 1] = 0.5  # left above it: behind the motion
    assert ghost_sides(trail, target, (0.0, 0.1)) == {"behind": 3, "ahead": 0, "beside": 0}
    assert ghost_sides(trail, target, (0.0, -0.1)) == {"behind": 0, "ahead": 3, "beside": 0}
    blur = np.zeros_like(target)
    blur[0, 2:5, :] = 0.5  # around it: above, below and beside
    assert ghost_sides(blur, target, (0.0, 0.1)) == {"behind": 1, "ahead": 1, "beside": 6}
    faint = np.full_like(target, 1 / 16)  # the least step is not a ghost
    assert ghost_sides(faint, target, (0.0, 0.1))["behind"] == 0
    # review r313 FIG1: the masks the figure outlines are the pixels counted
    from teachraster.study.antialiasing import ghost_masks

    marks = ghost_masks(trail, target, (0.0, 0.1))
    assert np.array_equal(np.argwhere(marks["behind"][0]), [[0, 1], [1, 1], [2, 1]])
    assert not marks["ahead"].any() and not marks["beside"].any()
    with pytest.raises(ValueError, match="motion"):
        ghost_sides(trail, target, (0.0, 0.0))
    with pytest.raises(ValueError, match="alike"):
        ghost_sides(trail, target[:, :5], (0.0, 0.1))
