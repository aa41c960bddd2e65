"""Lesson 06 §2: incremental edge functions draw the pixels the direct ones draw.

Review r146 12 moved the lesson's appendix C here: the lesson says in one sentence that over a
box's few hundred steps float32's drift stays far below the edge values it passes and changes
no pixel of the study; this test measures it on the study's own scenes (the random triangles
and the jittered mesh at every offset), as the study's coverage steps E: along each row of
every triangle's box.
"""

from __future__ import annotations

import numpy as np
import pytest

from teachraster.study import bench, precision


def _drift(arith: str) -> dict:
    edge_size = bench.sizes(quick=True)["edges"]
    mesh_size = bench.sizes(quick=True)["mesh"]
    scenes = [(t, edge_size, 0) for t in bench.random_triangles(edge_size)]
    scenes += [(t + float(off), mesh_size, off) for off in bench.MESH_OFFSETS
               for t in bench.jittered_mesh(mesh_size)]  # fmt: skip
    out = dict(drift=0.0, flips=0, differ=0, steps=0, tested=0)
    values = []  # |E| computed directly: the centres that close to an edge
    for xy, n, off in scenes:
        lo, hi = np.floor(xy.min(axis=0)).astype(int), np.ceil(xy.max(axis=0)).astype(int)
        box = dict(width=int(hi[0] - lo[0]), height=int(hi[1] - lo[1]), origin=tuple(lo))
        e = {ev: precision.edge_values(xy, arithmetic=arith, evaluation=ev, **box)
             for ev in ("direct", "incremental")}  # fmt: skip
        out["drift"] = max(out["drift"], float(np.abs(e["incremental"] - e["direct"]).max()))
        out["flips"] += int((np.sign(e["incremental"]) != np.sign(e["direct"])).sum())
        out["steps"] = max(out["steps"], box["width"] - 1)
        out["tested"] += e["direct"].size
        values.append(np.abs(e["direct"]).ravel())
        cover = [precision.coverage(xy, n, n, arith, ev, origin=(off, off))
                 for ev in ("direct", "incremental")]  # fmt: skip
        out["differ"] += int((cover[0] != cover[1]).sum())
    values = np.concatenate(values)
    out["near"] = int(((values > 0) & (values <= out["drift"])).sum())
    return out


@pytest.fixture(scope="module")
def drift():
    return {arith: _drift(arith) for arith in ("float32", "unsnapped")}


def test_stepping_drifts_far_below_the_edge_values_and_changes_no_pixel(drift):
    f32, unsnapped = drift["float32"], drift["unsnapped"]
    # a few thousandths of a px² over a few hundred steps at most
    assert 1e-3 <= f32["drift"] < 1e-2 and f32["steps"] < 1000
    # a handful of the millions of edge values lie that close to 0, and none is moved across
    assert f32["near"] <= 10 and f32["tested"] > 1e6
    for d in (f32, unsnapped):
        assert d["flips"] == 0 and d["differ"] == 0
    assert unsnapped["drift"] * 1e6 < f32["drift"]  # float64's drift: smaller by millions


def test_the_drift_measure_can_fail():
    """The flip count sees a sign change: two arrays that differ in sign at one centre."""
    a, b = np.array([1.0, -1e-9, 2.0]), np.array([1.0, 1e-9, 2.0])
    assert int((np.sign(a) != np.sign(b)).sum()) == 1
