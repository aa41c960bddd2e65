"""Lesson 02, review r466: the raw-float figure draws the shared edge in a colour of its own
(FIG1), the player's zoom no longer says the sample-only pixels "gather" there (S1), and the
standards table's front-face column no longer promises a default Vulkan lacks (S2)."""

from __future__ import annotations

import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from notebook_runs import lesson  # noqa: E402

NOTEBOOK = Path(__file__).resolve().parent.parent / "notebooks" / "02_half_planes.ipynb"


def _cells():
    return ["".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"]]


def test_r466_fig1_the_shared_edge_is_drawn_apart_from_a_sliver_beside_it():
    ns = lesson("02_half_planes")
    a, b, c, d = (np.asarray(q, dtype=float) / 10 for q in ns.first_pair)
    # why it is needed: one triangle of the pictured pair lies within half a pixel of the edge
    u, v = b - a
    near = min(abs(u * (q[1] - a[1]) - v * (q[0] - a[0])) / np.hypot(u, v) for q in (c, d))
    assert near < 0.5, near
    code = next(t for t in _cells() if "first_wrong = None" in t)
    assert 'ax.plot(*pair_tris[0][:2].T, color=COLORS["split"]' in code
    assert 'label="the shared edge"' in code


def test_r466_s1_s2_wording():
    ns = lesson("02_half_planes")
    in_zoom, total = int((ns.sample_only & ns.zoomed).sum()), int(ns.sample_only.sum())
    assert 2 * in_zoom < total  # not "where those pixels gather"
    player = next(t for t in _cells() if t.startswith("## 6. Step through it"))
    assert "gather" not in player and "where some of them lie" in player
    table = next(t for t in _cells() if t.startswith("**What the standards ask.**"))
    assert "front face (default)" not in table and "| front face |" in table
