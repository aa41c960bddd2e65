"""Vulkan's and Direct3D's anisotropic level of detail (teachraster.study.anisotropic_lod),
against float64 references written from the specifications one point at a time (review r233
F2: lesson 09's "jump" is GL's example formula; Vulkan's preferred level has none)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import teachraster as tr
from teachraster.study.anisotropic_lod import continuous_probes, sample_continuous


def _reference(tex, uv, dx, dy, cap, minor):
    """One point: Vulkan's Scale Factor and LOD Operations (minor "lengths"), or D3D11.3
    §7.18.11 (minor "area"), then N trilinear probes at i / (N + 1) - 1/2 along the major
    vector (ARB_texture_filter_anisotropic's placement), averaged."""
    h, w = tex.shape[:2]
    ax, ay = (dx[0] * w, dx[1] * h), (dy[0] * w, dy[1] * h)
    px, py = math.hypot(*ax), math.hypot(*ay)
    rho_max = max(px, py)
    if minor == "lengths":
        rho_min = min(px, py)
    else:
        rho_min = abs(ax[0] * ay[1] - ax[1] * ay[0]) / rho_max
    eta = min(rho_max / rho_min, min(cap, 16.0))
    n = math.ceil(eta)
    lam = math.log2(rho_max / eta)
    major = dx if px >= py else dy
    total = 0.0
    for i in range(1, n + 1):
        t = i / (n + 1) - 0.5
        p = [[uv[0] + t * major[0], uv[1] + t * major[1]]]
        total += float(tr.sample(tex, p, "trilinear", lod=[lam])[0])
    return n, lam, total / n


@pytest.mark.parametrize("minor", ["lengths", "area"])
def test_continuous_probes_match_the_specifications_point_by_point(minor):
    rng = np.random.default_rng(233)
    tex = rng.uniform(size=(32, 32))
    uv = rng.uniform(size=(60, 2))
    dx = rng.normal(scale=0.2, size=(60, 2))  # up to several texels, any shear
    dy = rng.normal(scale=0.05, size=(60, 2))
    caps = rng.choice([1, 2, 4, 8, 16, 40], size=60)
    for k in range(60):
        n, lam, major = continuous_probes(dx[k : k + 1], dy[k : k + 1], tex.shape, caps[k], minor)
        value = sample_continuous(tex, uv[k : k + 1], dx[k : k + 1], dy[k : k + 1], caps[k],
                                  minor)  # fmt: skip
        ref_n, ref_lam, ref_value = _reference(tex, uv[k], dx[k], dy[k], caps[k], minor)
        assert int(n[0]) == ref_n and float(lam[0]) == pytest.approx(ref_lam, rel=1e-12, abs=1e-12)
        assert float(value[0]) == pytest.approx(ref_value, rel=1e-12, abs=1e-12)


def test_the_level_is_not_rounded_with_the_count():
    """Vulkan's level follows the ratio: a footprint 8.000008 x 8 texels reads level 3 with
    two probes, where GL's formula reads level 2 (the lesson's question)."""
    n, lam, _ = continuous_probes([[8.000008 / 64, 0]], [[0, 8 / 64]], (64, 64))
    assert n.tolist() == [2] and lam[0] == pytest.approx(3.0, abs=1e-12)
    from teachraster.plotting.footprint import footprint

    gl = footprint([0.5, 0.5], [8.000008 / 64, 0], [0, 8 / 64], (64, 64))
    assert gl.probes == 2 and gl.probe_lam == pytest.approx(2.0, abs=1e-5)
    # square: one probe, trilinear itself; a line (ρ_min = 0): the cap's count
    n, lam, _ = continuous_probes([[8 / 64, 0], [8 / 64, 0]], [[0, 8 / 64], [0, 0]], (64, 64), 4)
    assert n.tolist() == [1, 4] and lam.tolist() == [3.0, 1.0]


def test_lengths_and_area_agree_on_perpendicular_vectors_and_part_on_sheared_ones():
    perpendicular = continuous_probes([[0.3, 0.0]], [[0.0, 0.05]], (16, 16), 16, "lengths")
    assert np.allclose(perpendicular[1],
                       continuous_probes([[0.3, 0.0]], [[0.0, 0.05]], (16, 16), 16, "area")[1])  # fmt: skip
    # sheared: the parallelogram's width across its long side is narrower than the short
    # vector, so Direct3D reads a finer level than Vulkan's lengths
    dx, dy = [[0.3, 0.0]], [[0.2, 0.05]]
    _, lam_lengths, _ = continuous_probes(dx, dy, (16, 16), 16, "lengths")
    _, lam_area, _ = continuous_probes(dx, dy, (16, 16), 16, "area")
    assert lam_area[0] < lam_lengths[0]


def test_the_engine_keeps_gls_formula_on_the_same_probes():
    """sample_probes is shared: with GL's count and level it is tr.sample's anisotropic."""
    from teachraster.pipeline.texturing.mip_pyramid import mipmap
    from teachraster.pipeline.texturing.texture_filters import anisotropic_probes, sample_probes

    rng = np.random.default_rng(9)
    tex = rng.uniform(size=(32, 32))
    uv = rng.uniform(size=(200, 2))
    dx, dy = rng.normal(scale=0.2, size=(200, 2)), rng.normal(scale=0.05, size=(200, 2))
    n, lam, major = anisotropic_probes(dx, dy, 32, 32, 16)
    shared = sample_probes(mipmap(tex), uv[:, 0], uv[:, 1], n, lam, major, "repeat")[:, 0]
    assert np.array_equal(shared, tr.sample(tex, uv, "anisotropic", ddx=dx, ddy=dy))


def test_continuous_probes_refuses_an_unknown_minor():
    with pytest.raises(ValueError, match="minor"):
        continuous_probes([[0.1, 0]], [[0, 0.1]], (8, 8), minor="ellipse")
