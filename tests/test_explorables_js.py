"""The explorables' page-side rules against the engine, exactly (node runs the JavaScript).

Every rule an explorable computes in the page exists in the engine too; these tests feed both
the same inputs and compare the answers: snapping and the top-left rule, edge values,
coverage, the owner of the centres on a shared edge, the naive span fills of lesson 01, depth
values, mip levels and footprints, and the diamond rule's pixels. Quick: one node process per
test, small grids.
"""

from __future__ import annotations

import numpy as np
from explorables_node import call_js

import teachraster as tr
from teachraster.core.edges import edge_values_at, setup_edges
from teachraster.core.snapping import to_units

RULES = ("raster_rules",)
EDGES = ("raster_rules", "view3d", "explore_edges")


def _triangles(seed: int, n: int, size: int, step: float) -> np.ndarray:
    """n random triangles on a grid of ``step`` px inside size x size (ties are frequent)."""
    rng = np.random.default_rng(seed)
    return rng.integers(0, int(size / step) + 1, (n, 3, 2)) * step


def test_snapping_rounds_half_to_even_as_the_engine():
    rng = np.random.default_rng(1)
    xs = np.concatenate([np.arange(-40, 41) / 512.0, rng.uniform(-70, 70, 200),
                         np.arange(0, 64) / 512.0 + 3.0])  # fmt: skip
    got = call_js(RULES, [("toUnits", [float(x)]) for x in xs])
    assert got == to_units(xs, 8).tolist()


def test_set_up_top_left_and_kinds_as_the_engine():
    tris = np.concatenate([_triangles(2, 60, 12, 0.5), _triangles(3, 20, 12, 1 / 256)])
    tris[0] = [[1, 1], [1, 1], [4, 4]]  # zero area
    got = call_js(RULES, [("setupTriangle", [t.tolist()]) for t in tris])
    for t, js in zip(tris, got, strict=True):
        s = setup_edges(t, 8)
        assert js["p"] == s.p.tolist()
        assert js["perm"] == s.perm.tolist()
        assert js["area2"] == int(s.area2) and js["originalArea2"] == int(s.original_area2)
        assert js["topLeft"] == s.top_left.tolist()
        for k, kind in enumerate(js["kinds"]):
            a, b = s.p[k], s.p[(k + 1) % 3]
            assert (kind in ("top", "left")) == bool(tr.is_top_left(a, b))
            want = ("left" if b[1] < a[1] else "right" if b[1] > a[1]
                    else "top" if b[0] > a[0] else "bottom")  # fmt: skip
            assert kind == want


def test_edge_values_at_centres_as_the_engine():
    tris = _triangles(4, 12, 10, 0.25)
    rows, cols = np.mgrid[0:10, 0:10]
    rows, cols = rows.ravel(), cols.ravel()
    calls = [("orientedValues", [setup, int(r), int(c)])
             for setup in call_js(RULES, [("setupTriangle", [t.tolist()]) for t in tris])
             for r, c in zip(rows, cols, strict=True)]  # fmt: skip
    got = np.array(call_js(RULES, calls)).reshape(len(tris), len(rows), 3)
    for t, js in zip(tris, got, strict=True):
        assert np.array_equal(js, edge_values_at(setup_edges(t, 8), rows, cols))


def test_coverage_as_the_engine_on_ties():
    # vertices on pixel centres, quarter pixels and the 1/256 grid: every kind of tie
    tris = np.concatenate([_triangles(5, 80, 14, 0.5) + 0.0, _triangles(6, 80, 14, 0.25),
                           _triangles(7, 40, 14, 1 / 256)])  # fmt: skip
    got = call_js(RULES, [("edgeFunctionFill", [t.tolist(), 14, 12]) for t in tris])
    for t, js in zip(tris, got, strict=True):
        want = tr.rasterize(tr.Triangle(t), 14, 12).coverage
        assert np.array_equal(np.array(js, bool).reshape(12, 14), want), t.tolist()


def test_owner_of_every_centre_on_the_shared_edge_is_the_engines():
    rng = np.random.default_rng(8)
    quads = rng.integers(0, 14, (60, 4, 2)) + 0.5  # on centres: the shared edge has ties
    quads[:, :, 1] = np.clip(quads[:, :, 1], 0.5, 11.5)
    got = call_js(EDGES, [("edgeScene", [q.tolist(), 14, 12]) for q in quads])
    checked = 0
    for q, js in zip(quads, got, strict=True):
        a = tr.rasterize(tr.Triangle(q[[0, 1, 2]]), 14, 12).coverage
        b = tr.rasterize(tr.Triangle(q[[2, 1, 3]]), 14, 12).coverage
        assert np.array_equal(np.array(js["covA"], bool).reshape(12, 14), a)
        assert np.array_equal(np.array(js["covB"], bool).reshape(12, 14), b)
        for s in js["shared"]:
            r, c = s["row"], s["col"]
            want = {(True, True): "both", (True, False): "A", (False, True): "B",
                    (False, False): "none"}[(bool(a[r, c]), bool(b[r, c]))]  # fmt: skip
            assert s["owner"] == want
            centre = np.array([c + 0.5, r + 0.5])
            assert tr.edge_function(q[1], q[2], centre) == 0  # exactly on v2-v3
            checked += 1
    assert checked > 50  # the inputs do exercise the ties


def test_edge_labels_name_the_given_edges():
    # v1 v2 v3 counter-clockwise on screen: oriented, the edges run the other way
    setup = call_js(RULES, [("setupTriangle", [[[2, 2], [2, 8], [8, 2]]])])[0]
    labels = call_js(EDGES, [("edgeLabels", [setup, ["E12", "E23", "E31"]])])[0]
    # E12 runs v1 (2,2) -> v2 (2,8): oriented v2 -> v1 goes up: a left edge, bias 0
    assert labels[0] == {"name": "E12", "kind": "left", "bias": 0, "flipped": True}
    # E31 runs v3 (8,2) -> v1 (2,2): oriented v1 -> v3 is horizontal going right: top
    assert labels[2]["kind"] == "top" and labels[2]["bias"] == 0
    assert labels[1]["kind"] == "right" and labels[1]["bias"] == -1
    # and on random triangles: bias 0 exactly where the engine's oriented edge is top-left
    tris = _triangles(9, 40, 10, 0.5)
    setups = call_js(RULES, [("setupTriangle", [t.tolist()]) for t in tris])
    got = call_js(EDGES, [("edgeLabels", [s, ["a", "b", "c"]]) for s in setups])
    for t, js in zip(tris, got, strict=True):
        s = setup_edges(t, 8)
        for k in range(3):
            pair = {k, (k + 1) % 3}
            j = next(m for m in range(3) if {int(s.perm[m]), int(s.perm[(m + 1) % 3])} == pair)
            assert (js[k]["bias"] == 0) == bool(s.top_left[j])
