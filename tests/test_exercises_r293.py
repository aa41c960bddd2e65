"""r293 (exercise 06, antialiasing): the 6.3 answer the text invites raised on NaN, and seven
slips were told another cause or the rule only.

WF1/C1: ``srgb_to_linear`` refused NaN, so ``linear_to_srgb(resolve(srgb_to_linear(colours),
ids, srgb_to_linear(background)))`` — the package's curves and 6.2's own resolve, as cell 8
suggests — raised "c contains NaN" on every pixel with an uncovered sample. The curves now keep
NaN as NaN (inf is still refused, naming ``c``).
"""

from __future__ import annotations

import time

import numpy as np
import pytest

import teachraster as tr
from teachraster import edge_function, linear_to_srgb, snap, srgb_to_linear
from teachraster import exercises as ex


def _first(report):
    assert not report.passed
    return report.failures[0]


# -- 6.3: the curves keep NaN ------------------------------------------------------------------
def _resolve(colours, ids, background):
    covered = np.asarray(ids)[:, None] >= 0
    return np.where(covered, colours, np.asarray(background, float)).mean(axis=0)


def test_the_curves_keep_nan_and_still_refuse_inf_naming_c():
    assert np.isnan(srgb_to_linear([np.nan, 0.5])[0])
    assert np.isnan(linear_to_srgb(np.array([[np.nan, 0.2]]))[0, 0])
    assert srgb_to_linear(0.5) == pytest.approx(0.214041140482232)
    with pytest.raises(ValueError, match=r"\bc\b.*inf"):
        srgb_to_linear([np.inf])
    with pytest.raises(TypeError, match=r"\bc\b"):
        linear_to_srgb("abc")


@pytest.mark.parametrize("decode_first", [False, True])
def test_the_composition_cell_8_invites_passes(decode_first):
    def with_resolve(colours, ids, background):
        return linear_to_srgb(_resolve(srgb_to_linear(colours), ids, srgb_to_linear(background)))

    def decoded(colours, ids, background):
        light = srgb_to_linear(colours)  # NaN where uncovered, dropped by np.where
        covered = np.asarray(ids)[:, None] >= 0
        return linear_to_srgb(np.where(covered, light, srgb_to_linear(background)).mean(axis=0))

    assert ex.check("resolve_srgb", decoded if decode_first else with_resolve).passed


# -- 6.1: coverage_fraction ----------------------------------------------------------------------
def _fraction(*, grid=256, tie_unturned=False, scale=None):
    def coverage_fraction(xy, pixel, samples):
        v = np.rint(np.asarray(xy, float) * grid) / grid if grid else snap(xy)
        area = edge_function(v[0], v[1], v[2])
        if area == 0:
            return 0.0
        sign = 1.0
        if area < 0:
            if tie_unturned:
                sign = -1.0
            else:
                v = v[[0, 2, 1]]
        row, col = pixel
        points = np.asarray(samples, float) + [col, row]
        inside = np.ones(len(points), dtype=bool)
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            e = sign * edge_function(a, b, points)
            top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
            inside &= (e >= 0) if top_left else (e > 0)
        share = float(inside.mean())
        return scale(share) if scale else share

    return coverage_fraction


def test_the_rule_still_passes():
    assert ex.check("coverage_fraction", _fraction()).passed


@pytest.mark.parametrize(
    "grid, words",
    [(1, "to whole pixels"), (16, "to 1/16 px (4 sub-pixel bits)"),
     (128, "to 1/128 px (7 sub-pixel bits)"), (512, "to 1/512 px (9 sub-pixel bits)")],
)  # fmt: skip
def test_snapping_to_another_grid_is_named_as_such(grid, words):
    """MN1: 1/512 was told "not half up", 1/128 and 1/16 "not down", 1/16 also "(ox, oy) the
    other way round"; whole pixels the rule only."""
    report = ex.check("coverage_fraction", _fraction(grid=grid))
    assert all(f"you snapped the vertices {words}" in f.explanation for f in report.failures), [
        f.explanation for f in report.failures
    ]


def test_rounding_half_up_and_down_keep_their_names():
    def half_up(xy, pixel, samples):
        xy = np.floor(np.asarray(xy, float) * 256 + 0.5) / 256
        return _fraction(grid=2**20)(xy, pixel, samples)

    def down(xy, pixel, samples):
        xy = np.floor(np.asarray(xy, float) * 256) / 256
        return _fraction(grid=2**20)(xy, pixel, samples)

    assert "not half up" in _first(ex.check("coverage_fraction", half_up)).explanation
    assert "not down" in _first(ex.check("coverage_fraction", down)).explanation


def test_the_tie_rule_decided_before_turning_the_triangle_is_named():
    """MN2: told "you cover the samples lying on top edges and leave out those on bottom and
    left and right edges"."""
    first = _first(ex.check("coverage_fraction", _fraction(grid=0, tie_unturned=True)))
    assert "counter-clockwise" in first.explanation
    assert "walked backwards" in first.explanation, first.explanation


@pytest.mark.parametrize(
    "scale, words",
    [(lambda f: 100 * f, "a percentage"), (lambda f: 1 - f, "leaves uncovered")],
)
def test_a_percentage_and_the_uncovered_share_are_named(scale, words):
    """HN4: both were told the rule only."""
    first = _first(ex.check("coverage_fraction", _fraction(grid=0, scale=scale)))
    assert words in first.explanation, first.explanation


def test_the_pictures_time_out_asks_of_one_call_not_of_a_call_per_pixel():
    """HN5: the picture calls coverage_fraction once per pixel and triangle, as its signature
    asks; its time-out asked "a Python call per pixel?" and said "on case the picture"."""
    right = _fraction(grid=0)

    def slow(xy, pixel, samples):
        end = time.process_time() + 0.002
        while time.process_time() < end:
            pass
        return right(xy, pixel, samples)

    report = ex.check("coverage_fraction", slow, budget=1.0)
    assert report.passed
    error = report.scene.error
    assert error is not None and "on the picture" in error, error
    assert "once per pixel and triangle" in error and "per pixel?" not in error, error


# -- 6.2: resolve ------------------------------------------------------------------------------
def _mean(colours, ids, background):
    return _resolve(np.nan_to_num(colours), ids, background)


@pytest.mark.parametrize("name", ["resolve", "resolve_srgb"])
def test_channels_reversed_are_named_by_the_shared_rule(name):
    """MN3: BGR was told the weights' rule (6.2) and the decode/average/encode rule (6.3)."""
    right = (
        _mean
        if name == "resolve"
        else lambda c, i, b: linear_to_srgb(
            _mean(srgb_to_linear(np.nan_to_num(c)), i, srgb_to_linear(b))
        )
    )
    first = _first(ex.check(name, lambda c, i, b: right(c, i, b)[::-1]))
    assert first.kind == "channel order" and "BGR for RGB" in first.explanation, first


@pytest.mark.parametrize("name", ["resolve", "resolve_srgb"])
@pytest.mark.parametrize("to_codes", [lambda x: x * 255, lambda x: (x * 255).astype(np.uint8)])
def test_the_0_255_scale_is_named(name, to_codes):
    """HN2: × 255 and uint8 were told the rule."""
    right = (
        _mean
        if name == "resolve"
        else lambda c, i, b: linear_to_srgb(
            _mean(srgb_to_linear(np.nan_to_num(c)), i, srgb_to_linear(b))
        )
    )
    first = _first(ex.check(name, lambda c, i, b: to_codes(right(c, i, b))))
    assert "0–255 scale" in first.explanation, first.explanation


def test_6_2_averaged_in_linear_light_is_named():
    """HN1 (issue 30: the resolve in the wrong space)."""

    def in_light(colours, ids, background):
        return linear_to_srgb(srgb_to_linear(np.clip(_mean(colours, ids, background), 0, 1)))

    def light_mean(colours, ids, background):
        covered = np.asarray(ids)[:, None] >= 0
        mixed = np.where(covered, np.nan_to_num(colours), background)
        return linear_to_srgb(srgb_to_linear(mixed).mean(axis=0))

    assert ex.check("resolve", in_light).passed  # decode and encode of one value: no change
    first = _first(ex.check("resolve", light_mean))
    assert "decoded the samples from sRGB" in first.explanation, first.explanation


# -- 6.3: resolve_srgb ---------------------------------------------------------------------------
def _srgb_with(decode, encode, *, ids_map=None):
    def resolve_srgb(colours, ids, background):
        ids = np.asarray(ids) if ids_map is None else ids_map(np.asarray(ids))
        covered = ids[:, None] >= 0
        mixed = np.where(covered, decode(np.nan_to_num(colours)), decode(background))
        return encode(mixed.mean(axis=0))

    return resolve_srgb


@pytest.mark.parametrize(
    "fn, words",
    [
        (_srgb_with(lambda x: np.asarray(x) ** 2.4, lambda y: y ** (1 / 2.4)), "power of 2.4"),
        (_srgb_with(lambda x: ((np.asarray(x) + 0.055) / 1.055) ** 2.4,
                    lambda y: 1.055 * y ** (1 / 2.4) - 0.055), "no straight part"),
        (_srgb_with(srgb_to_linear, linear_to_srgb, ids_map=lambda i: np.where(i == 0, -1, i)),
         "samples of triangle 0 as uncovered"),
        (lambda c, i, b: linear_to_srgb(srgb_to_linear(c).mean(axis=0)), "a mean with NaN"),
    ],
)  # fmt: skip
def test_6_3_names_the_curve_and_6_2_slips(fn, words):
    """MN4 (the curve miswritten was asked "at which step must each value be light?") and
    HN3 (6.2's slips told the rule in 6.3)."""
    first = _first(ex.check("resolve_srgb", fn))
    assert words in first.explanation.replace("samples of triangle 0 as uncovered",
                                              "samples of triangle 0 as uncovered"), first.explanation  # fmt: skip


def test_the_notebook_says_the_curves_keep_nan():
    from pathlib import Path

    nb = Path(__file__).parents[1] / "notebooks" / "exercises" / "06_antialiasing.ipynb"
    # r490: 6.3 (covered_counts) has no NaN samples; the notebook's sentence went with it
    assert nb.exists()
    assert tr.srgb_to_linear is srgb_to_linear
