"""The explorables' page-side rules against the engine, exactly (node runs the JavaScript).

Every rule an explorable computes in the page exists in the engine too; these tests feed both
the same inputs and compare the answers: snapping and the top-left rule, edge values,
coverage, the owner of the centres on a shared edge, the naive span fills of lesson 01, depth
values, mip levels and footprints, and the diamond rule's pixels. Quick: one node process per
test, small grids.
"""

from __future__ import annotations

import json
import re
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import pytest
from explorables_node import NODE, call_js

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


def test_canvas_text_reads_12_px_in_the_column_at_1024_px():
    """Reviews r9/r10 (02 c23, 12 c8): canvas text is shown smaller than drawn where the canvas
    is wider than JupyterLab's output column at 1024 x 768 (585 px with the file browser
    open): the edge explorer's 3-D readout (760-px canvas) read 9 px, the diamonds' numbers
    (800 px) 10. Every font the edge and diamond explorers and the grid set goes through
    readablePx, which reads at least 12 px there; the signs still fit their pixel."""
    import re

    from teachraster.widgets.explorable import esm_source

    widths = [585, 634, 684, 760, 800, 1200]
    sizes = call_js(EDGES, [("readablePx", [px, w]) for w in widths for px in (11, 13, 15)])
    for (w, px), size in zip([(w, px) for w in widths for px in (11, 13, 15)], sizes):
        assert size >= px and size * min(1.0, 585 / w) >= 12 - 1e-9, (w, px, size)
    # lesson 02's 16 x 14 grid: 42-px cells on a 714-px canvas (review r93 02-4: 37-px cells
    # on a 634-px one drew the signs 9-10 px high)
    # review r291 02-2: 50-px cells (42 drew the signs about 10 px high at a 1400-px page)
    cell = min(50, 800 // 16, 700 // 14)
    width = 30 + 16 * cell + 12
    assert cell == 50
    (size,) = call_js(EDGES, [("signSize", [cell, width])])
    assert size * 585 / width >= 12 + 1  # the signs a little above the floor
    assert size * 585 / width >= 16  # and on a projector (was 14.8 px in a 585-px column)
    assert 0.62 * size <= 0.3 * cell  # each glyph within its gap: "+−+" did not run together
    assert 2 * 0.3 * cell + 0.6 * size <= cell  # three monospace glyphs inside the pixel
    for parts in (EDGES, LINES):
        for line in esm_source(*parts).splitlines():
            if re.search(r"\.font = ", line):
                literal = re.search(r"[\"`](?:bold )?\d+px", line)
                assert not literal, f"a fixed canvas font size, not through textPx: {line}"


def test_tint_buttons_name_the_chosen_triangles_edges():
    # B = v3 v2 v4: its edges are E32, E24, E43 (CONVENTIONS: walking order), never A's E12...
    quad = [[2.5, 2.5], [9.5, 3.5], [4.5, 9.5], [11.5, 10.5]]
    scene = call_js(EDGES, [("edgeScene", [quad, 14, 12])])[0]
    a, b, table = call_js(
        EDGES, [("tintChoices", ["A"]), ("tintChoices", ["B"]), ("edgeTable", [scene])]
    )
    assert [label for _, label in a[1:4]] == ["E12's", "E23's", "E31's"]
    assert [label for _, label in b[1:4]] == ["E32's", "E24's", "E43's"]
    assert [value for value, _ in a] == [value for value, _ in b]  # the same edge slots
    for name in ("E32 (v3→v2)", "E24 (v2→v4)", "E43 (v4→v3)"):  # as the explorer's table says
        assert f">{name}</b>" in table  # the name in bold (one line: r231 02-7)


def test_a_counter_clockwise_triangle_is_labelled_by_the_edges_it_is_tested_on():
    """Review r192 02-7: B made counter-clockwise read "E32 (v3→v2) right, bias −1" while the
    pointer showed E32 negative inside: the kind and bias are those of the edge walked
    backwards, E23, and the table and labels now name that edge and say why."""
    quad = [[2.5, 2.5], [9.5, 3.5], [4.5, 9.5], [2.5, 6.5]]  # v4 over A: B = v3 v2 v4 turns CCW
    scene = call_js(EDGES, [("edgeScene", [quad, 14, 12])])[0]
    (table,) = call_js(EDGES, [("edgeTable", [scene])])
    row_b = table.split("<tr>")[2]
    assert "counter-clockwise on screen: tested backwards" in row_b
    for name in ("E23 (v2→v3)", "E42 (v4→v2)", "E34 (v3→v4)"):
        assert f">{name}</b>" in row_b
    assert "E32" not in row_b and "clockwise on screen" in table.split("<tr>")[1]
    labels = call_js(EDGES, [("edgeLabels", [scene["B"], ["E32", "E24", "E43"]])])[0]
    assert all(label["flipped"] for label in labels)
    walked = call_js(EDGES, [("walkedName", [label]) for label in labels])
    assert walked == ["E23", "E42", "E34"]
    # review r224-02 #5: the tint buttons use the same names as the labels and the table
    tints, tints_a = call_js(
        EDGES, [("tintChoices", ["B", scene["B"]]), ("tintChoices", ["A", scene["A"]])]
    )
    assert [label for _, label in tints[1:4]] == ["E23's", "E42's", "E34's"]
    assert [value for value, _ in tints[1:4]] == ["E12", "E23", "E31"]  # the same slots
    assert [label for _, label in tints_a[1:4]] == ["E12's", "E23's", "E31's"]  # A clockwise


def test_one_edge_has_its_two_names_linked_and_its_table_cell_does_not_break_its_bias():
    """Review r231 02-13: with B counter-clockwise the pointer's readout and the 3-D values
    said "E32 = ..." while the labels and the table said "E23": the readouts now link the two
    names, "E32 = −E23". 02-7: the table wrapped "right, bias / −1"; the kind and bias stay
    on one line."""
    quad = [[2.5, 2.5], [9.5, 3.5], [4.5, 9.5], [2.5, 6.5]]  # v4 over A: B turns CCW
    scene = call_js(EDGES, [("edgeScene", [quad, 14, 12])])[0]
    names_b, names_a, said, table = call_js(EDGES, [
        ("valueNames", [scene["B"], "B"]), ("valueNames", [scene["A"], "A"]),
        ("describe", [scene, [6.2, 5.7], "B", 14, 12]), ("edgeTable", [scene])])  # fmt: skip
    assert names_b == ["E32 = −E23", "E24 = −E42", "E43 = −E34"]
    assert names_a == ["E12", "E23", "E31"]  # clockwise: one name each
    assert "<b>E32 = −E23</b> = " in said and "<b>E43 = −E34</b> = " in said
    assert table.count('<span style="white-space:nowrap">') == 6
    assert '<span style="white-space:nowrap">right, bias −1</span>' in table


def test_owner_badges_stand_on_grid_corners_clear_of_the_signs():
    """Review r231 02-7: a ringed centre's owner badge stood inside its cell, over the left
    sign of "+0+"; it now stands on the cell's corner, half a pixel from every centre, and
    takes the upper corner where a vertex's dot pushes the centre's signs below it."""
    from teachraster.widgets.edge_explorer import DEFAULT_VERTICES

    scene = call_js(EDGES, [("edgeScene", [[list(v) for v in DEFAULT_VERTICES], 16, 14])])[0]
    cell, m = 42.0, {"left": 30, "top": 26}
    shared = scene["shared"]
    assert len(shared) > 5
    calls = [("badgeCentre", [scene, s["row"], s["col"], cell, m]) for s in shared]
    got = call_js(EDGES, calls)
    for s, (x, y) in zip(shared, got, strict=True):
        cx, cy = m["left"] + (s["col"] + 0.5) * cell, m["top"] + (s["row"] + 0.5) * cell
        assert abs(abs(x - cx) - cell / 2) < 1e-9 and abs(abs(y - cy) - cell / 2) < 1e-9
        assert x < cx  # a left corner
    # a vertex on a ringed centre: its badge takes the upper left corner
    s = shared[0]
    cx, cy = m["left"] + (s["col"] + 0.5) * cell, m["top"] + (s["row"] + 0.5) * cell
    ((x, y),) = call_js(EDGES, [("badgeCentre", [scene, s["row"], s["col"], cell, m, [[cx, cy]]])])
    assert y == cy - cell / 2


def test_edge_labels_stand_clear_of_the_edges_centres():
    """Review r192 02-6: a horizontal shared edge's label covered the ringed centres on it.
    The label's box keeps half a pixel (the ring and its badge) off the edge's line, on the
    side away from the triangle, whatever the edge's direction."""
    cell, half = 42.0, [70.0, 10.0]
    rng = np.random.default_rng(3)
    edges = []
    for _ in range(40):
        a, b = rng.uniform(0, 600, 2), rng.uniform(0, 600, 2)
        edges.append((a, b, (a + b) / 2 + rng.uniform(-200, 200, 2)))
    # one node process for the 40 edges (explorables_node: a test batches its inputs)
    got = call_js(EDGES, [("labelCentre", [a.tolist(), b.tolist(), centroid.tolist(), half,
                                           cell]) for a, b, centroid in edges])  # fmt: skip
    for (a, b, centroid), at in zip(edges, got, strict=True):
        d = b - a
        n = np.array([-d[1], d[0]]) / np.hypot(*d)
        side = np.sign(n @ (np.array(at) - a))
        assert side == -np.sign(n @ (centroid - a)) or abs(n @ (centroid - a)) < 1e-9
        corners = [np.array(at) + np.array([sx * half[0], sy * half[1]])
                   for sx in (-1, 1) for sy in (-1, 1)]  # fmt: skip
        assert min(abs(n @ (c - a)) for c in corners) >= 0.5 * cell + 2 - 1e-6


def test_edge_labels_stay_inside_the_canvas():
    """Review r224-02 #3: with A counter-clockwise (v1 at (13, 13)) the label of v2→v1 sat
    past the canvas's right side, "E21: right, bias −1" cut. Given the canvas's size, a label
    that would stick out goes to the triangle's side of its edge (still clear of the edge's
    centres), or is pushed inside."""
    cell, half, bounds = 40.0, [80.0, 10.0], [700.0, 600.0]
    # a steep edge 30 px from the right side, the triangle to its left: outside overflows
    a, b, centroid = [670.0, 100.0], [640.0, 400.0], [400.0, 250.0]
    rng = np.random.default_rng(5)
    edges = []  # random edges, checked below
    for _ in range(40):
        ra, rb = rng.uniform(0, 700, 2), rng.uniform(0, 600, 2)
        rc = (ra + rb) / 2 + rng.uniform(-150, 150, 2)
        edges.append([ra.tolist(), rb.tolist(), rc.tolist(), half, cell])
    # one node process for every call (explorables_node: a test batches its inputs)
    calls = [("labelCentre", [a, b, centroid, half, cell, bounds])]
    calls += [("labelCentre", args + extra) for args in edges for extra in ([], [bounds])]
    at, *placed = call_js(EDGES, calls)
    assert half[0] <= at[0] <= bounds[0] - half[0] and half[1] <= at[1] <= bounds[1] - half[1]
    d = np.subtract(b, a)
    n = np.array([-d[1], d[0]]) / np.hypot(*d)
    corners = [np.array(at) + np.array([sx * half[0], sy * half[1]])
               for sx in (-1, 1) for sy in (-1, 1)]  # fmt: skip
    assert min(abs(n @ (c - np.array(a))) for c in corners) >= 0.5 * cell + 2 - 1e-6
    # and on random edges: always inside; where the outside fits, unchanged
    assert len(placed) == 2 * len(edges)
    for free, at in zip(placed[::2], placed[1::2], strict=True):
        assert half[0] - 1e-9 <= at[0] <= bounds[0] - half[0] + 1e-9
        assert half[1] - 1e-9 <= at[1] <= bounds[1] - half[1] + 1e-9
        inside = (
            half[0] <= free[0] <= bounds[0] - half[0] and half[1] <= free[1] <= bounds[1] - half[1]
        )
        assert not inside or at == free


def test_edge_labels_and_vertex_dots_leave_the_signs_readable():
    """Review r224-02 #4: "E12: right, bias −1" stood over two centres' signs, and v1's dot on
    the centre (2.5, 1.5) hid its middle sign ("0○0"). A label takes a place that hides no
    centre's signs when there is one; a dot on a centre pushes that centre's signs below it."""
    cell, half, bounds = 40.0, [80.0, 10.0], [700.0, 600.0]
    a, b, centroid = [100.0, 100.0], [500.0, 100.0], [300.0, 300.0]  # a horizontal edge
    signs = [[300.0, 60.0], [340.0, 60.0]]  # two centres just above its middle, signs shown
    reach = [cell * 0.54, cell * 0.3]

    def hidden(p):
        return sum(abs(p[0] - q[0]) < half[0] + reach[0] and abs(p[1] - q[1]) < half[1] + reach[1]
                   for q in signs)  # fmt: skip

    free = call_js(EDGES, [("labelCentre", [a, b, centroid, half, cell, bounds])])[0]
    assert hidden(free) == 2  # the plain place: over both
    args = [a, b, centroid, half, cell, bounds, signs, reach]
    at, none = call_js(EDGES, [("placeLabel", args), ("placeLabel", args[:6] + [[], reach])])
    assert none == free  # no signs drawn (one half-plane tinted): the plain place
    assert hidden(at) == 0 and at[1] < a[1]  # still outside, above the edge
    assert a[1] - (at[1] + half[1]) >= 0.5 * cell + 2 - 1e-6  # and clear of its centres
    # a dot on the centre: the signs' ink (a sprite's top 0.3 blank) starts below the dot
    size = 19
    cy_free, cy_dot = call_js(
        EDGES, [("belowDot", [300, 305, size, cell, []]), ("belowDot", [300, 305, size, cell,
                                                                        [[300, 300]]])]
    )  # fmt: skip
    assert cy_free == 305 and cy_dot - 0.9 * size + 0.3 * size >= 300 + 6 - 1e-9


def test_planes_read_e_at_a_named_point_and_stay_in_their_box():
    from teachraster.widgets.edge_explorer import DEFAULT_VERTICES

    tri = np.array(DEFAULT_VERTICES)[:3]
    setup = call_js(EDGES, [("setupTriangle", [tri.tolist()])])[0]
    inside_pt, corner_pt = call_js(
        EDGES,
        [("planePoint", [setup, None, 16, 14]), ("planePoint", [setup, [15.9, 13.2], 16, 14])],
    )
    assert corner_pt == [15.5, 13.5]  # the centre of the pixel under the pointer
    vals = call_js(EDGES, [("planeValues", [setup, p]) for p in (inside_pt, corner_pt)])
    snapped = np.round(tri * 256) / 256
    for p, got in zip((inside_pt, corner_pt), vals, strict=True):
        want = [tr.edge_function(snapped[k], snapped[(k + 1) % 3], p) for k in range(3)]
        assert np.allclose(got, want)
    assert min(vals[0]) > 0  # without a pointer, a centre inside the triangle
    # clipped to the slab |z| <= h; a quad wholly outside vanishes
    quad = [[0, 0, -9.0], [4, 0, 3.0], [4, 4, 11.0], [0, 4, -1.0]]
    cut, gone = call_js(
        EDGES,
        [("clipToSlab", [quad, 2.0]), ("clipToSlab", [[[0, 0, 5], [1, 0, 6], [0, 1, 7]], 2.0])],
    )
    assert gone == [] and len(cut) >= 3
    assert all(abs(z) <= 2.0 + 1e-12 for _, _, z in cut)
    # the default view turns so that no plane is seen nearly edge-on (the old fixed yaw -0.45
    # saw E12's almost edge-on); the planes' gradients are E's, scaled as the view scales them
    grads = [np.subtract(snapped[(k + 1) % 3], snapped[k])[::-1] * [-1, 1] for k in range(3)]
    corners = ([0, 0], [16, 0], [16, 14], [0, 14])
    top = max(
        abs(tr.edge_function(snapped[k], snapped[(k + 1) % 3], c))
        for k in range(3)
        for c in corners
    )
    zs = 1.6 * 0.3 * 16 / top  # as drawPlanes scales E on the 16 x 14 grid
    yaw = call_js(EDGES, [("bestYaw", [[g.tolist() for g in grads], zs, 0.5])])[0]
    best, old = call_js(
        EDGES,
        [("planesFacing", [[g.tolist() for g in grads], zs, y, 0.5]) for y in (yaw, -0.45)],
    )
    assert best > 0.2 and best > 2 * old
    # the fitted box stays inside the canvas at every turn
    W, H, h, cw, ch = 16, 14, 4.8, 560, 320
    scale = call_js(EDGES, [("fitBox", [W, H, h, cw, ch])])[0]
    box = np.array([[x, y, z] for x in (0, W) for y in (0, H) for z in (-h, h)], float)
    for yaw in np.linspace(0, 2 * np.pi, 13):
        for elev in np.linspace(0.05, np.pi / 2, 7):
            x, y, z = (box - [W / 2, H / 2, 0]).T
            x1 = x * np.cos(yaw) - y * np.sin(yaw)
            y1 = x * np.sin(yaw) + y * np.cos(yaw)
            sx, sy = scale * x1, scale * (y1 * np.sin(elev) - z * np.cos(elev))
            assert (np.abs(sx) <= cw / 2).all() and (np.abs(sy) <= ch / 2).all()
    # review r99 (r93 02-8): fitted at the view's own tilt, the box still fits at every yaw,
    # and fills the height at its widest yaw (no empty band under a low view)
    elevs = np.linspace(0.05, 1.2, 9)
    scales = call_js(EDGES, [("fitBox", [W, H, h, cw, ch, 8, elev, 8]) for elev in elevs])
    for elev, scale in zip(elevs, scales, strict=True):
        tall = 0.0
        for yaw in np.linspace(0, 2 * np.pi, 73):
            x, y, z = (box - [W / 2, H / 2, 0]).T
            x1 = x * np.cos(yaw) - y * np.sin(yaw)
            y1 = x * np.sin(yaw) + y * np.cos(yaw)
            sx, sy = scale * x1, scale * (y1 * np.sin(elev) - z * np.cos(elev))
            assert (np.abs(sx) <= cw / 2).all() and (np.abs(sy) <= ch / 2).all(), (elev, yaw)
            tall = max(tall, np.abs(sy).max())
        wide = scale * np.hypot(W / 2, H / 2)
        assert tall >= ch / 2 - 8 - 0.5 or wide >= cw / 2 - 8 - 1e-9, elev  # one side is filled


def test_the_e_axis_ticks_keep_two_lines_of_text_apart_on_the_screen():
    """Review r93 02-8: turned towards the top, the 3-D view's E ticks (-50, 0, 50) ran
    together; the step is chosen in screen space: at least two text heights apart, else only
    the 0 tick."""
    span, size = 100.0, 17.0
    elevs = np.linspace(0.05, np.pi / 2, 12)
    px_pers = [3.0 * np.cos(elev) for elev in elevs]  # screen px per px² of E at this elevation
    # one node process for every call (explorables_node: a test batches its inputs)
    *steps, side_on, from_top = call_js(
        EDGES, [("eTickStep", [span, px_per, size]) for px_per in [*px_pers, 3.0, 0.0]]
    )
    for elev, px_per, step in zip(elevs, px_pers, steps, strict=True):
        assert step * px_per >= 2 * size - 1e-9 or step > span, (elev, step)
        assert step >= span / 3
    assert side_on == 50  # side on: -50, 0, 50
    assert from_top > span  # from the top: 0


def test_a_turned_view_keeps_its_e_ticks_where_they_fit():
    """Review r169 02-7: turned by a drag, the E axis kept only its 0: a step just over two
    text heights was rounded up past the box's half height. Where ±step fits the box at 1.25
    text heights apart (clear of each other), the axis keeps them."""
    size = 17.0
    # span's height on the screen (px): from 2.5 text heights, twice 1.25, up, a nice
    # step (1, 2, 2.5, 5 x 10^k, at most twice the next smaller) always fits in between
    cases = [(span, screen) for span in (60.0, 100.0, 130.0, 170.0, 240.0)
             for screen in np.linspace(2.5 * size, 4 * size, 15)]  # fmt: skip
    # one node process for all 76 calls (explorables_node: a test batches its inputs)
    calls = [("eTickStep", [span, screen / span, size]) for span, screen in cases]
    *steps, last = call_js(EDGES, [*calls, ("eTickStep", [130.0, 43.0 / 130.0, size])])
    for (span, screen), step in zip(cases, steps, strict=True):
        px_per = screen / span
        assert step <= span, (span, screen, step)  # -step, 0, +step on the axis
        assert step * px_per >= 1.25 * size - 1e-9  # and never on top of one another
    assert last <= 130.0


def test_edge_signs_are_drawn_near_the_edges_and_under_the_pointer():
    """Review r169 02-7: three signs at each of 224 centres read as a texture on a projector.
    They are drawn within a pixel of the chosen triangle's edges (where they change) and at
    the centre under the pointer; elsewhere the fill says inside or out."""
    from teachraster.widgets.edge_explorer import DEFAULT_VERTICES

    (scene,) = call_js(EDGES, [("edgeScene", [[list(v) for v in DEFAULT_VERTICES], 16, 14])])
    a = np.array(DEFAULT_VERTICES[:3])
    cells = [(r, c) for r in range(14) for c in range(16)]
    shown = call_js(EDGES, [("signsShown", [scene["A"], r, c]) for r, c in cells])

    def near(r, c):
        p = np.array([c + 0.5, r + 0.5])
        dist = []
        for k in range(3):
            e, f = a[k], a[(k + 1) % 3]
            t = np.clip(np.dot(p - e, f - e) / np.dot(f - e, f - e), 0, 1)
            dist.append(np.hypot(*(p - e - t * (f - e))))
        return min(dist) <= 1

    assert shown == [near(r, c) for r, c in cells]
    assert 30 < sum(shown) < len(cells) / 2  # a band along the edges, not the grid
    far = next(rc for rc, s in zip(cells, shown) if not s)
    hover = [far[1] + 0.3, far[0] + 0.7]
    assert call_js(EDGES, [("signsShown", [scene["A"], *far, hover])]) == [True]


def test_the_shared_edge_and_the_vertices_leave_their_signs_to_the_pointer():
    """Review r291 02-2 (r242 02-7): on the shared edge the "0" digits stood beside the
    owners' rings and letters, and "00" over the vertex dots. Those centres show their signs
    only under the pointer; the table keeps fixed columns, the winding on a line of its own."""
    from teachraster.widgets.edge_explorer import DEFAULT_VERTICES

    verts = [list(v) for v in DEFAULT_VERTICES]
    (scene,) = call_js(EDGES, [("edgeScene", [verts, 16, 14])])
    (quiet,) = call_js(EDGES, [("quietCentres", [scene, verts])])
    shared = [[s["row"], s["col"]] for s in scene["shared"]]
    assert shared and all(rc in quiet for rc in shared)
    at_vertices = [[int(y), int(x)] for x, y in verts]  # each default vertex on a centre
    assert all(rc in quiet for rc in at_vertices)
    # r343 02-FIG1: and the four centres beside v2 and v3, each on its ring's centre
    beside = [[int(y) + dr, int(x) + dc] for x, y in verts[1:3]
              for dr, dc in ((-1, 0), (1, 0), (0, -1), (0, 1))]  # fmt: skip
    assert {tuple(rc) for rc in quiet} == {tuple(rc) for rc in shared + at_vertices + beside}
    calls = [("signsShown", [scene["A"], r, c, None, quiet]) for r, c in quiet]
    calls += [("signsShown", [scene["A"], r, c, [c + 0.5, r + 0.5], quiet]) for r, c in quiet]
    shown = call_js(EDGES, calls)
    assert not any(shown[: len(quiet)]) and all(shown[len(quiet) :])
    quad = [[2.5, 2.5], [9.5, 3.5], [4.5, 9.5], [2.5, 6.5]]  # B counter-clockwise
    (ccw,) = call_js(EDGES, [("edgeScene", [quad, 14, 12])])
    (table,) = call_js(EDGES, [("edgeTable", [ccw])])
    assert table.startswith('<table><colgroup><col style="width:31%">')
    assert "<b>B</b><br><small>counter-clockwise on screen: tested backwards" in table


CRACKS = ("raster_rules", "explore_cracks")


def test_naive_span_fills_as_lesson_01s():
    from teachraster.study.naive_spans import naive_span_fill

    rng = np.random.default_rng(10)
    tris = np.concatenate([rng.integers(0, 30, (60, 3, 2)) + 0.5, rng.uniform(-2, 32, (30, 3, 2))])
    tris[0] = [[8.5, 17.5], [4.5, 1.5], [18.5, 9.5]]  # lesson 01's triangle
    tris[1] = [[0.5, 19.5], [1.5, 107.5], [84.5, 103.5]]  # and its 4b (float crossings off)
    modes = [(stepped, listed) for stepped in (False, True) for listed in (False, True)]
    calls = [("spanFill", [t.tolist(), 30, 120, *mode]) for t in tris for mode in modes]
    got = iter(call_js(RULES, calls))
    for t in tris:
        for stepped, listed in modes:
            want = naive_span_fill(t, 30, 120, stepped=stepped, as_listed=listed)
            assert np.array_equal(np.array(next(got), bool).reshape(120, 30), want)


def test_cracks_and_double_draws_as_the_reference():
    from teachraster.study.naive_spans import shared_edge_faults

    pairs = call_js(CRACKS, [("rolls", [7, 150, 16, 16])])[0]
    ways = [(m, listed) for m in ("crossing", "dda", "integer") for listed in (False, True)]
    calls = [("faults", [a, b, 16, 16, m, listed]) for a, b in pairs for m, listed in ways]
    got = iter(call_js(CRACKS, calls))
    seen = {way: 0 for way in ways}
    for a, b in pairs:
        assert tr.edge_function(a[0], a[1], a[2]) * tr.edge_function(a[0], a[1], b[2]) < 0
        for m, listed in ways:
            js, want = next(got), shared_edge_faults(a, b, 16, 16, m, as_listed=listed)
            for key in ("cracks", "doubles", "swapped"):
                assert js[key] == want[key].tolist()
            assert js["wrong"] == want["wrong"]
            seen[m, listed] += bool(js["swapped"] or any(js["wrong"]))
            if not listed:  # evaluated alike, the shared edge never cracks nor doubles
                assert not js["cracks"] and not js["doubles"]
    assert seen["integer", False] == seen["integer", True] == 0
    assert seen["dda", False] > 0  # the float DDA does fail on these


def test_stored_pair_cracks_as_the_reference_says():
    from teachraster.study.naive_spans import shared_edge_faults
    from teachraster.widgets import CrackExplorer

    size = CrackExplorer().data["width"]
    pair, fits, small = call_js(
        CRACKS,
        [("crackingPair", []), ("fitsCrackingPair", [size, size]), ("fitsCrackingPair", [12, 12])],
    )
    assert fits and not small  # offered at the explorer's default grid, not on 12 x 12
    a, b = np.array(pair[0]), np.array(pair[1])
    assert (a[:2] == b[1::-1]).all()  # they share the edge p-q
    assert tr.edge_function(a[0], a[1], a[2]) * tr.edge_function(a[0], a[1], b[2]) < 0
    listed = shared_edge_faults(a, b, size, size, "dda", as_listed=True)
    assert len(listed["cracks"]) > 0  # it does crack, evaluated as listed
    alike = shared_edge_faults(a, b, size, size, "dda")
    assert not len(alike["cracks"]) and not len(alike["doubles"])
    # its red rings lie inside the canvas and clear of the neighbouring panels (with the line)
    (g,) = call_js(CRACKS, [("panelLayout", [size, size])])
    cell, reach = g["cell"], g["radius"] + 1.5
    for row, col in listed["cracks"]:
        for x0, y0 in g["origins"]:
            cx, cy = x0 + (col + 0.5) * cell, y0 + (row + 0.5) * cell
            assert x0 - g["gap"] / 2 <= cx - reach and cx + reach <= x0 + g["panelW"] + g["gap"] / 2
            assert 0 <= cx - reach and cx + reach <= g["width"]
            assert y0 - 14 <= cy - reach and cy + reach <= min(y0 + g["panelH"] + 14, g["height"])


def test_crack_panels_fit_the_column_at_1024_px_unscaled():
    """Review r7: three across, the 16 x 16 explorer was 936 px wide and shrank to 585 px in
    JupyterLab's column at 1024 px (type of 7-8 px); two across plus the key it fits 1:1."""
    (g,) = call_js(CRACKS, [("panelLayout", [16, 16])])
    assert len(g["origins"]) == 3 and g["width"] <= 585
    boxes = [(x, y, x + g["panelW"], y + g["panelH"]) for x, y in [*g["origins"], g["key"]]]
    for i, a in enumerate(boxes):  # no two places overlap, and all lie inside the canvas
        assert 0 <= a[0] and a[2] <= g["width"] and 0 <= a[1] and a[3] <= g["height"]
        for b in boxes[i + 1 :]:
            assert a[2] <= b[0] or b[2] <= a[0] or a[3] <= b[1] or b[3] <= a[1]


def test_crack_panels_grow_with_the_column():
    """Review r65 01-4 (r57 01-1): 256-px panels of 16-px cells were small on a projector. The
    cells grow with the column the explorer is shown in (26 px in a 940-px one: 27 before the
    row numbers took their margin, review r251 01-FIG1), the canvas always within it; the
    narrow column keeps 16-px cells."""
    narrow, wide, widest = call_js(CRACKS, [("panelLayout", [16, 16, 585]),
                                            ("panelLayout", [16, 16, 940]),
                                            ("panelLayout", [16, 16, 4000])])  # fmt: skip
    assert narrow["cell"] == 16 and narrow["width"] <= 585
    assert wide["cell"] == 26 and wide["width"] <= 940
    assert widest["cell"] == 30  # at most MAX_CELL
    for g in (wide, widest):  # the places still do not overlap
        boxes = [(x, y, x + g["panelW"], y + g["panelH"]) for x, y in [*g["origins"], g["key"]]]
        for i, a in enumerate(boxes):
            assert a[2] <= g["width"] and a[3] <= g["height"]
            for b in boxes[i + 1 :]:
                assert a[2] <= b[0] or b[2] <= a[0] or a[3] <= b[1] or b[3] <= a[1]


def test_crack_note_follows_the_evaluation():
    """Review r65 01-4: the note under the tally describes the way the edges are evaluated."""
    alike, listed = call_js(CRACKS, [("crackNote", [False]), ("crackNote", [True])])
    assert "never cracks" in alike and "Turn on" in alike
    assert listed.startswith("Now each triangle evaluates") and "Show a pair that cracks" in listed


def test_crack_tally_starts_again_whatever_changes_the_evaluation():
    """Review r7 contradiction 2: "Show a pair that cracks" turned the evaluation toggle on
    but kept counting ("0 of 1001"); any change of it now starts the tally again."""
    pair = [[[0.5, 0.5], [9.5, 9.5], [9.5, 0.5]], [[9.5, 9.5], [0.5, 0.5], [0.5, 9.5]]]
    (tally,) = call_js(CRACKS, [("tallyOver", [[pair], 16, 16])])
    assert tally["integer"]["pairs"] == 1
    got = call_js(CRACKS, [
        ("listedBy", [{"asListed": False, "tally": tally}, True]),  # turned on: from nothing
        ("listedBy", [{"asListed": True, "tally": tally}, True]),  # unchanged: kept
        ("listedBy", [{"asListed": True, "tally": tally}, False]),  # turned off: from nothing
        ("listedBy", [{"asListed": False, "tally": tally}, True, True]),  # a tally restored
    ])  # fmt: skip
    assert [s["tally"]["integer"]["pairs"] for s in got] == [0, 1, 0, 1]
    assert [s["asListed"] for s in got] == [True, True, False, True]
    source = (Path(tr.__file__).parent / "widgets/static/explore_cracks.js").read_text()
    # the stored pair, the toggle and the kernel all set it through listedBy, the one place
    # that assigns it
    assert source.count("listedBy(state,") == 1 + 3 and source.count("state.asListed = ") == 1


def test_default_pair_shows_the_dda_giving_ties_to_the_wrong_triangle():
    from teachraster.study.naive_spans import shared_edge_faults
    from teachraster.widgets import CrackExplorer

    ex = CrackExplorer()
    size, seed = ex.data["width"], ex.data["seed"]
    (pair,) = call_js(CRACKS, [("rolls", [seed, 1, size, size])])[0]  # the pair on show first
    a, b = np.array(pair[0]), np.array(pair[1])
    dda = shared_edge_faults(a, b, size, size, "dda")
    assert len(dda["swapped"]) > 0 and min(dda["wrong"]) > 0  # the DDA panel shows something
    assert not len(shared_edge_faults(a, b, size, size, "integer")["swapped"])
    # both triangles of fair size, not slivers (the ties should be visible)
    areas = [abs(tr.edge_function(t[0], t[1], t[2])) / 2 for t in (a, b)]
    assert min(areas) >= 10


def test_tie_marks_only_on_the_shared_segment():
    pairs = call_js(CRACKS, [("rolls", [3, 60, 16, 16])])[0]
    got = call_js(CRACKS, [("tieCentres", [pair, 16, 16]) for pair in pairs])
    beyond = 0
    for (a, _), ties in zip(pairs, got, strict=True):
        p, q = np.array(a[0]), np.array(a[1])
        rows, cols = np.mgrid[0:16, 0:16] + 0.5
        centres = np.stack([cols.ravel(), rows.ravel()], axis=1)
        line = [c for c in centres if tr.edge_function(p, q, c) == 0]
        within = [c for c in line if ((np.minimum(p, q) <= c) & (c <= np.maximum(p, q))).all()]
        assert sorted(ties) == sorted([int(c[1]), int(c[0])] for c in within)
        beyond += len(line) - len(within)
    assert beyond > 0  # the line does run on past the ends in these pairs: the test can fail


def test_random_shared_pairs_as_the_pages():
    from teachraster.study.naive_spans import random_shared_pairs

    pairs = random_shared_pairs(np.random.default_rng(3), 200, 9, 7)
    assert len(pairs) == 200
    for a, b in pairs:
        assert (a[:2] == b[1::-1]).all() and not (a[0] == a[1]).all()  # p-q, listed both ways
        assert tr.edge_function(a[0], a[1], a[2]) > 0 > tr.edge_function(a[0], a[1], b[2])
        both = np.concatenate([a, b])
        assert ((both % 1) == 0.5).all() and (both[:, 0] < 9).all() and (both[:, 1] < 7).all()
    # the page's pairs obey the same rule (only the random stream differs)
    for a, b in call_js(CRACKS, [("rolls", [5, 100, 9, 7])])[0]:
        assert tr.edge_function(a[0], a[1], a[2]) > 0 > tr.edge_function(a[0], a[1], b[2])
    with pytest.raises(ValueError, match="n"):
        random_shared_pairs(np.random.default_rng(3), -1, 9, 7)


def test_tally_counts_every_pair_as_the_reference():
    from teachraster.study.naive_spans import shared_edge_faults

    pairs = call_js(CRACKS, [("rolls", [11, 40, 12, 12])])[0]
    js = call_js(CRACKS, [("tallyOver", [pairs, 12, 12])])[0]
    for m in ("crossing", "dda", "integer"):
        found = [shared_edge_faults(a, b, 12, 12, m) for a, b in pairs]
        assert js[m]["pairs"] == 40 and js[m]["triangles"] == 80
        assert js[m]["cracks"] == sum(len(f["cracks"]) for f in found)
        assert js[m]["doubles"] == sum(len(f["doubles"]) for f in found)
        assert js[m]["faulty"] == sum(bool(len(f["cracks"]) or len(f["doubles"])) for f in found)
        assert js[m]["swapped"] == sum(len(f["swapped"]) for f in found)
        assert js[m]["swappedPairs"] == sum(bool(len(f["swapped"])) for f in found)
        assert js[m]["wrongTriangles"] == sum((w > 0) for f in found for w in f["wrong"])


DEPTH = ("explore_depth",)


def test_stored_depth_values_and_their_neighbours_as_quantize():
    from teachraster.pipeline.visibility.depth import quantize, reversed_depth, window_depth

    rng = np.random.default_rng(12)
    calls, cases = [], []
    for near, far in [(0.1, 1000.0), (1.0, 1000.0), (0.01, 50.0)]:
        zs = np.concatenate([np.geomspace(near, far, 40), rng.uniform(near, far, 20), [near, far]])
        for fmt in ("unorm16", "unorm24", "float32", "reversed"):
            for z in zs:
                calls.append(("neighbours", [float(z), near, far, fmt]))
                cases.append((float(z), near, far, fmt))
    got = call_js(DEPTH, calls)
    for (z, near, far, fmt), js in zip(cases, got, strict=True):
        if fmt == "reversed":
            value = quantize(reversed_depth(z, near, far), "float32")
            v32 = np.float32(value)  # larger is nearer
            farther = float(np.nextafter(v32, np.float32(0)))
            nearer = float(np.nextafter(v32, np.float32(2)))
        else:
            value = quantize(window_depth(z, near, far), fmt)
            if fmt == "float32":
                v32 = np.float32(value)
                farther = float(np.nextafter(v32, np.float32(2)))
                nearer = float(np.nextafter(v32, np.float32(0)))
            else:
                scale = 2 ** (16 if fmt == "unorm16" else 24) - 1
                k = np.rint(value * scale)
                farther, nearer = (k + 1) / scale, max(k - 1, 0) / scale
        assert js["value"] == float(value), (z, near, far, fmt)
        assert (js["farther"], js["nearer"]) == (farther, nearer), (z, near, far, fmt)
        # the z each value stands for maps back onto that value (a float value within two
        # steps: the inverse mapping rounds too)
        for key, d in (("z", "value"), ("zFarther", "farther")):
            if np.isfinite(js[key]) and js[key] <= far:
                mapped = (reversed_depth(js[key], near, far) if fmt == "reversed"
                          else window_depth(js[key], near, far))  # fmt: skip
                back = quantize(mapped, "float32" if fmt == "reversed" else fmt)
                if fmt.startswith("unorm"):
                    assert back == js[d]
                else:
                    ulps = abs(int(np.float32(back).view(np.uint32))
                               - int(np.float32(js[d]).view(np.uint32)))  # fmt: skip
                    assert ulps <= 2, (z, near, far, fmt, key)


def test_depth_steps_match_depth_resolution():
    from teachraster.pipeline.visibility.depth import depth_resolution

    zs = [0.5, 2.0, 30.0, 500.0]
    calls = [("neighbours", [z, 0.1, 1000.0, fmt]) for fmt in ("unorm16", "unorm24", "reversed")
             for z in zs]  # fmt: skip
    got = iter(call_js(DEPTH, calls))
    for fmt, mapping in (("unorm16", "perspective"), ("unorm24", "perspective"),
                         ("float32", "reversed")):  # fmt: skip
        want = depth_resolution(zs, 0.1, 1000.0, fmt, mapping=mapping)
        for z, w in zip(zs, want, strict=True):
            js = next(got)
            step = js["zFarther"] - js["z"]
            assert step == pytest.approx(w, rel=0.05), (fmt, z)  # first order vs exact


def test_values_counted_and_listed_as_numpy_counts_them():
    from teachraster.pipeline.visibility.depth import window_depth

    near, far = 0.1, 1000.0
    scale = 2**16 - 1
    stored = np.arange(scale + 1) / scale
    ranges = [(0.1, 0.2), (1.0, 1.5), (200.0, 230.0), (900.0, 1000.0)]
    calls = [("countBetween", [a, b, near, far, "unorm16"]) for a, b in ranges]
    calls += [("valuesIn", [a, b, near, far, "unorm16", 10**6]) for a, b in ranges]
    got = call_js(DEPTH, calls)
    for (a, b), count, zs in zip(ranges, got[:4], got[4:], strict=True):
        da, db = window_depth([a, b], near, far)
        inside = stored[(stored >= da) & (stored < db)]
        assert abs(count - len(inside)) <= 1  # boundaries: d * scale rounds
        assert abs(len(zs) - len(inside)) <= 1
        assert np.all(np.diff(zs) > 0)
        assert a * (1 - 1e-9) <= zs[0] and zs[-1] <= b * (1 + 1e-9)  # the inverse rounds
    # float32 and reverse-Z: counts of floats by their bits
    for fmt in ("float32", "reversed"):
        (count,) = call_js(DEPTH, [("countBetween", [200.0, 230.0, near, far, fmt])])
        d = window_depth([200.0, 230.0], near, far) if fmt == "float32" else None
        if d is None:
            from teachraster.pipeline.visibility.depth import reversed_depth

            lo, hi = (
                np.float32(reversed_depth(230.0, near, far)),
                np.float32(reversed_depth(200.0, near, far)),
            )
        else:
            lo, hi = np.float32(d[0]), np.float32(d[1])
        bits = int(np.array(hi).view(np.uint32)) - int(np.array(lo).view(np.uint32))
        assert abs(count - bits) <= 1


LINES = ("raster_rules", "explore_lines")


def test_diamond_pixels_as_the_engines_on_ties():
    from teachraster.core.line_rules import diamond
    from teachraster.core.snapping import units_per_pixel

    rng = np.random.default_rng(13)
    # end points on centres, diamond corners, pixel corners and quarter pixels: ties galore
    ends = np.concatenate([rng.integers(0, 24, (150, 2, 2)) / 2.0,
                           rng.integers(0, 48, (100, 2, 2)) / 4.0,
                           rng.uniform(0, 12, (50, 2, 2))])  # fmt: skip
    ends[0] = [[0.5, 0.5], [4.5, 2.5]]  # the engine's docstring: column 1 is a tie
    ends[1:3] = [[[1.0, 0.5], [9, 0.5]], [[0.5, 1.0], [8.5, 1.0]]]  # review r71: no far ties
    calls = [("diamondSteps", [e[0].tolist(), e[1].tolist(), 12, 10]) for e in ends]
    got = call_js(LINES, calls)
    unit = units_per_pixel(8)
    ties = 0
    for e, js in zip(ends, got, strict=True):
        want = tr.rasterize_line(e[0], e[1], 12, 10).coverage
        lit = np.zeros((10, 12), bool)
        states = {}
        for s in js["steps"]:
            for c in s["cands"]:
                lit[c["row"], c["col"]] |= c["state"] == 1
                states[(s["major"], c["row"], c["col"])] = (c["state"], c["tie"])
                ties += c["tie"] and c["state"] != 0
        assert np.array_equal(lit, want), e.tolist()
        steps = diamond(tuple(js["a"]), tuple(js["b"]), unit, 12, 10)
        # the same walk, decisions and ties (the LinePlayer's captions read the engine's)
        assert [s["major"] for s in js["steps"]] == steps.major.tolist()
        engine = {(int(steps.major[s]), int(r), int(c)): (int(st), bool(t))
                  for s, r, c, st, t in zip(steps.step, steps.rows, steps.cols, steps.state,
                                            steps.tie, strict=True)}  # fmt: skip
        assert states == engine
    assert ties > 20  # the inputs do exercise GL's perturbation


def test_end_point_labels_stay_inside_the_canvas():
    """p1 in the last column: its label goes left of the point instead of past the border."""
    middle, last, top = call_js(LINES, [("labelAt", [100, 100, 60, 400]),
                                        ("labelAt", [380, 100, 60, 400]),
                                        ("labelAt", [100, 5, 60, 400])])  # fmt: skip
    assert middle == [109, 91]
    assert last[0] + 60 <= 400 and last[0] < 380
    assert top[1] > 5


def test_step_caption_says_what_the_trace_says():
    walk = call_js(LINES, [("diamondSteps", [[0.5, 0.5], [4.5, 2.5], 5, 3])])[0]
    captions = call_js(LINES, [("stepCaption", [walk, k]) for k in range(len(walk["steps"]))])
    trace = tr.rasterize_line((0.5, 0.5), (4.5, 2.5), 5, 3, trace=True).trace
    assert "tie" in captions[1].lower() and "(row 1, col 1)" in captions[1]
    assert "ends inside the diamond of (row 2, col 4)" in captions[-1]
    rows, cols = trace.ends_inside()
    assert list(zip(rows.tolist(), cols.tolist(), strict=True)) == [(2, 4)]
    # each work step of the trace names the same pixels lit as the page's caption
    first = len(trace) - trace.n_work  # after the set-up steps (snap, axis)
    assert len(captions) == trace.n_work
    for k, caption in enumerate(captions):
        lit = trace.lit_at(first + k)
        for r, c in zip(*np.nonzero(lit), strict=True):
            assert f"(row {r}, col {c})" in caption


FOOTPRINT = ("explore_footprint",)


def test_footprint_view_draws_the_wrapped_texture_beyond_the_floor():
    """Review r195 09-4: at the floor's near edge the texture view was white beyond the
    texture, under the texel grid and the level square; the wrapped copies a filter reads
    there are drawn too (paler), every copy that reaches the view and no other."""
    # a 100-px view, copies 30 px wide, the floor's first copy at (-10, 70), 2 x 2 copies
    tiles = call_js(FOOTPRINT, [("textureTiles", [-10, 70, 30, 30, 100, 2])])[0]
    xs = sorted({x for x, _, _ in tiles})
    ys = sorted({y for _, y, _ in tiles})
    assert xs == [-10, 20, 50, 80] and ys == [-20, 10, 40, 70]  # all that reach [0, 100)
    on_floor = {(x, y) for x, y, on in tiles if on}
    assert on_floor == {(-10, 70), (20, 70)}  # the floor's row 0; row 1 starts below the view
    assert len(tiles) == 16 and sum(not on for _, _, on in tiles) == 14


def test_footprint_level_and_probes_as_the_engine():
    from teachraster.pipeline.texturing.texture_filters import (
        linear_levels,
        mip_level,
        nearest_level,
    )
    from teachraster.plotting.footprint import footprint
    from teachraster.widgets.footprint_explorer import floor_scene

    data = floor_scene(32, 24, 80.0, 1)
    pixels = [i for i, uv in enumerate(data["uv"]) if uv is not None]
    calls = [("footprintOf", [data["uv"][i], data["ddx"][i], data["ddy"][i], 64, 64, data["q"]])
             for i in pixels]  # fmt: skip
    got = call_js(FOOTPRINT, calls)
    levels = set()
    for i, js in zip(pixels, got, strict=True):
        uv, dx, dy = (np.array(data[k][i]) for k in ("uv", "ddx", "ddy"))
        lam = float(mip_level(dx[None], dy[None], (64, 64))[0])
        assert js["lam"] == pytest.approx(lam, abs=1e-12)
        assert js["nearest"] == int(nearest_level(np.array([lam]), data["q"])[0])
        first, second, t = linear_levels(np.array([lam]), data["q"])
        assert js["linear"][:2] == [int(first[0]), int(second[0])]
        assert js["linear"][2] == pytest.approx(float(t[0]), abs=1e-12)
        fp = footprint(uv, dx, dy, (64, 64))
        assert js["probes"] == fp.probes and js["rho"] == pytest.approx(fp.rho, rel=1e-15)
        assert np.allclose(js["probeCentres"], fp.probe_centres, rtol=0, atol=1e-9)
        levels.add(js["nearest"])
    assert len(levels) >= 3  # near and far pixels read different levels


def test_footprint_view_draws_the_probes_as_the_static_figure():
    """Review r233 M3: the widget printed the probe count but drew no probe; it draws the
    squares of side P_max / N at the engine's probe centres, as plot_footprint does."""
    from teachraster.plotting.footprint import footprint
    from teachraster.widgets.footprint_explorer import floor_scene

    data = floor_scene(32, 24, 80.0, 1)
    pixels = [i for i, uv in enumerate(data["uv"]) if uv is not None]
    fps = call_js(FOOTPRINT, [("footprintOf", [data["uv"][i], data["ddx"][i], data["ddy"][i],
                                               64, 64, data["q"]]) for i in pixels])  # fmt: skip
    squares = call_js(FOOTPRINT, [("probeSquares", [fp]) for fp in fps])
    counts = set()
    for i, got in zip(pixels, squares, strict=True):
        fp = footprint(*(np.array(data[k][i]) for k in ("uv", "ddx", "ddy")), (64, 64))
        side = fp.rho / fp.probes
        want = [[x - side / 2, y - side / 2, side] for x, y in fp.probe_centres]
        assert np.allclose(got, want, rtol=0, atol=1e-9)
        counts.add(len(got))
    assert max(counts) >= 3 and min(counts) <= 2  # more probes far away than near


#: Draws the picked pixel's footprint and the zoom label on a context that records every
#: call with the style it was made in (node has no canvas).
RECORDING_DRIVER = """
import { readFileSync } from "node:fs";
const mod = await import(process.argv[2]);
const [uv, ddx, ddy, q] = JSON.parse(readFileSync(process.argv[3], "utf8"));
const T = 420;
const STYLE = ["strokeStyle", "fillStyle", "lineWidth", "font"];
const log = [];
let state = { strokeStyle: "#000", fillStyle: "#000", lineWidth: 1, font: "10px sans-serif",
  dash: [] };
const stack = [];
const target = {
  canvas: { width: T, height: T, logical: { w: T, h: T, dpr: 1 } },
  save() { stack.push({ ...state }); },
  restore() { state = stack.pop(); },
  setLineDash(d) { state.dash = [...d]; },
  measureText(t) { return { width: 0.55 * parseFloat(state.font) * t.length }; },
};
const ctx = new Proxy(target, {
  get(t, name) {
    if (name in t) return t[name];
    if (STYLE.includes(name)) return state[name];
    return (...args) => log.push([name, args, { ...state }]);
  },
  set(t, name, value) {
    state[name] = value;
    return true;
  },
});
const fp = mod.footprintOf(uv, ddx, ddy, 64, 64, q);
const ext = Math.max(Math.hypot(...fp.axisX), Math.hypot(...fp.axisY), fp.rho, 4);
const v = { cx: fp.centre[0], cy: fp.centre[1], half: 1.3 * ext };
const fromTex = (w, [x, y]) => [T / 2 + ((x - w.cx) / w.half) * (T / 2),
  T / 2 + ((y - w.cy) / w.half) * (T / 2)];
mod.drawPicked(ctx, fp, mod.trilinearTaps(uv, ddx, ddy, 64, 64, q), v, fromTex);
mod.drawZoomLabel(ctx, v, T);
process.stdout.write(JSON.stringify({ log, nearest: fp.nearest, linear: fp.linear }));
"""


def _recorded_footprint(pixel):
    """The drawing calls of the FootprintExplorer's texture view for ``pixel`` of lesson 09's
    floor (48 x 36, tilt 80), with the style each was made in."""
    from teachraster.widgets.explorable import esm_source
    from teachraster.widgets.footprint_explorer import floor_scene

    if NODE is None:
        pytest.skip("node is not installed (the page-side functions are checked with node)")
    data = floor_scene(48, 36, 80.0, 2)
    i = pixel[0] * 48 + pixel[1]
    with tempfile.TemporaryDirectory(prefix="tr-node-") as tmp:
        module, driver, args = Path(tmp, "m.mjs"), Path(tmp, "run.mjs"), Path(tmp, "args.json")
        module.write_text(esm_source(*FOOTPRINT), encoding="utf-8")
        driver.write_text(RECORDING_DRIVER, encoding="utf-8")
        args.write_text(json.dumps([data["uv"][i], data["ddx"][i], data["ddy"][i], data["q"]]))
        done = subprocess.run([NODE, str(driver), module.as_uri(), str(args)],
                              capture_output=True, text=True, timeout=120)  # fmt: skip
    assert done.returncode == 0, done.stderr[-3000:]
    return json.loads(done.stdout)


@pytest.mark.parametrize("pixel", [(2, 24), (35, 24)])
def test_footprint_level_grid_shows_over_the_fetched_texels_and_the_label_reads(pixel):
    """Review r246 09 FIG1. At the default pixel (row 2) GL's nearest level is 3, whose texels
    are a check wide: its grid, 35 % opaque under the fetched texels' dashed outlines, lay on
    the check borders and the level-3 outline and showed no blue at all; at row 35 it was
    faint. The grid is now opaque, in a colour neither fetched level's, drawn after the
    outlines, which sit inside their texels, off the grid lines. The zoom label the lesson
    sends students to was 12 px: 16 now, drawn last."""
    got = _recorded_footprint(pixel)
    log = got["log"]
    taps = [(k, args, st) for k, (name, args, st) in enumerate(log) if name == "strokeRect"
            and st["strokeStyle"] in ("#CC79A7", "#009E73") and st["dash"] == [7, 4]]  # fmt: skip
    assert len(taps) in (4, 8)
    grid_at = next(k for k, (name, _, st) in enumerate(log)
                   if name == "stroke" and st["strokeStyle"] == "#0072B2" and st["dash"])  # fmt: skip
    grid = log[grid_at][2]
    assert grid_at > max(k for k, _, _ in taps)  # over the fetched texels' outlines
    assert grid["strokeStyle"] not in ("#CC79A7", "#009E73") and grid["lineWidth"] >= 2
    assert "rgba" not in grid["strokeStyle"]  # opaque
    # the grid's lines: the moveTo calls of its path
    start = max(k for k, (name, _, _) in enumerate(log[:grid_at]) if name == "beginPath")
    xs = {round(a[0], 6) for name, a, _ in log[start:grid_at] if name == "moveTo"}
    ys = {round(a[1], 6) for name, a, _ in log[start:grid_at] if name == "moveTo"}
    if got["nearest"] in got["linear"][:2]:  # a fetched level's outlines run along the grid
        for _, (x, y, w, h), _ in taps:
            for edge in (x, x + w):
                assert min(abs(edge - g) for g in xs) >= 2, (edge, sorted(xs))
            for edge in (y, y + h):
                assert min(abs(edge - g) for g in ys) >= 2, (edge, sorted(ys))
    label = [(k, a, st) for k, (name, a, st) in enumerate(log) if name == "fillText"]
    ((k, (text, _, _), st),) = label
    # review r257 S4: the span as a width, "u 54.2 to 76.2: 22 texels across", not a range
    # that read as a count ("texels 54.15…76.2 across")
    m = re.fullmatch(r"u (-?[\d.]+) to (-?[\d.]+): ([\d.]+) texels across", text)
    assert m and k > grid_at, text
    lo, hi, wide = map(float, m.groups())
    assert wide == pytest.approx(hi - lo, rel=0.02, abs=0.1)
    assert int(st["font"].split("px")[0]) >= 14


def test_footprint_readout_gives_every_number_to_two_decimals():
    """r104 09-7: the readout mixed significant digits ("axes 0.976 and 1.44", "λ = 0.526"
    beside "λ = 1.7"); it gives two decimals throughout, as cells 25 and 28 print them."""
    import re

    from teachraster.widgets.footprint_explorer import floor_scene

    data = floor_scene(32, 24, 80.0, 1)
    i = 23 * 32 + 16  # the bottom row, the middle column: a near pixel of the floor
    (fp,) = call_js(FOOTPRINT, [("footprintOf", [data["uv"][i], data["ddx"][i], data["ddy"][i],
                                                 64, 64, data["q"]])])  # fmt: skip
    (text,) = call_js(FOOTPRINT, [("footprintText", [{"pixel": [23, 16]}, fp, []])])
    numbers = re.findall(r"(?<![\w.])-?\d+\.\d+", text)
    assert len(numbers) >= 5 and all(len(n.split(".")[1]) == 2 for n in numbers), numbers
    assert f"ρ = {fp['rho']:.2f}" in text and f"λ = log₂ ρ = {fp['lam']:.2f}" in text
    # r184 09-2: GL's P_x and P_y are the derivative vectors' lengths, not the ellipse's axes
    assert "extents along x and y (the derivative vectors' lengths" in text
    assert "axes are" not in text


def test_pixels_reading_a_texel_point_as_footprint_contains():
    from teachraster.plotting.footprint import footprint_contains, trilinear_reads
    from teachraster.widgets.footprint_explorer import floor_scene

    data = floor_scene(24, 18, 78.0, 2)
    covered = np.array([uv is not None for uv in data["uv"]]).reshape(18, 24)
    fill = lambda k: np.array([v if v is not None else [np.nan, np.nan] for v in data[k]])  # noqa: E731
    uv, dx, dy = fill("uv"), fill("ddx"), fill("ddy")
    rng = np.random.default_rng(14)
    points = [(float(uv[i, 0] * 64), float(uv[i, 1] * 64))
              for i in rng.choice(np.flatnonzero(covered.ravel()), 12)]  # fmt: skip
    points += rng.uniform(0, 512, (8, 2)).tolist()
    for how, reference in (("ellipse", footprint_contains), ("trilinear", trilinear_reads)):
        got = call_js(FOOTPRINT, [("pixelsReading", [data, list(p), how]) for p in points])
        for p, js in zip(points, got, strict=True):
            want = reference(uv, dx, dy, (64, 64), p).reshape(18, 24) & covered
            assert sorted(map(tuple, js)) == sorted(map(tuple, np.argwhere(want).tolist()))
        assert sum(len(js) for js in got) >= len(points) // 2
    assert any(len(js) > 1 for js in got)  # trilinear: pixels share the texels they fetch


def test_attribute_surfaces_as_the_engine():
    from teachraster.core.interpolation import perspective_weights

    xy = np.array([[2.0, 2.0], [14.0, 4.0], [5.0, 14.0]])
    rng = np.random.default_rng(15)
    lam = rng.dirichlet([1, 1, 1], 30)
    points = lam @ xy
    for w in ([1.0, 1.0, 1.0], [1.0, 2.0, 6.0]):
        f = [0.2, 1.0, 0.0]
        got = call_js(("raster_rules", "view3d", "explore_attributes"),
                      [("surfaceValues", [xy.tolist(), w, f, p.tolist()]) for p in points])  # fmt: skip
        want_lam = tr.barycentric(xy, points)
        mu = perspective_weights(want_lam, np.array(w), extrapolate=True)
        for k, js in enumerate(got):
            assert np.allclose(js["lam"], want_lam[k], rtol=0, atol=1e-13)
            assert js["correct"] == pytest.approx(float(mu[k] @ f), abs=1e-13)
            assert js["affine"] == pytest.approx(float(want_lam[k] @ f), abs=1e-13)
            assert js["inv"] == pytest.approx(float(want_lam[k] @ (1 / np.array(w))), abs=1e-13)


def test_attribute_surfaces_readout_follows_w_and_the_toggles():
    # review r78 03-1: with every w equal, f/w and 1/w are no scaled copies (1/w is flat); the
    # readout speaks of the blue sheet only while it is drawn
    xy, f = [[2.0, 2.0], [14.0, 4.0], [5.0, 14.0]], [0.2, 0.9, 0.5]
    parts = ("raster_rules", "view3d", "explore_attributes")
    flat, deep = [1.0, 1.0, 1.0], [1.0, 1.0, 4.0]
    gaps = call_js(parts, [("largestGap", [xy, w, f]) for w in (flat, deep)])
    shows = [{"correct": c, "affine": a, "fw": False, "inv": False}
             for c in (True, False) for a in (True, False)]  # fmt: skip
    calls = [("readoutText", [w, s, g]) for w, g in zip((flat, deep), gaps) for s in shows]
    got = call_js(parts, calls)
    for text in got[:4]:
        assert "scaled copies" not in text
        assert "f/w is f scaled by the same 1/w at every vertex, and 1/w is a constant" in text
    assert "drawn once, in blue" in got[0] and "drawn once, in blue" in got[1]
    assert "orange" in got[2] and "blue" not in got[2]
    assert "blue" not in got[3] and "sheet" not in got[3]
    for text in got[4:]:
        assert "Largest |affine − perspective-correct|" in text
    assert "vermillion bar" in got[4]
    assert all("Switch both f sheets on" in t for t in got[5:])


def test_attribute_surfaces_pieces_lie_on_one_side_of_the_crossing():
    # review r89 03-1: a piece straddling the crossing of the two f sheets was sorted whole,
    # a staircase; now every piece has one sheet above the other all over it, and the
    # crossing drawn is where the affine f equals v3's (only v3's w differs)
    xy, f = [[2.0, 1.0], [13.0, 5.0], [5.0, 12.0]], [0.2, 0.9, 0.5]
    parts = ("raster_rules", "view3d", "explore_attributes")
    names = ["correct", "affine"]
    got = call_js(parts, [("sheetPieces", [xy, [1.0, 1.0, w3], f, names]) for w3 in (1.5, 8.0)])
    for out in got:
        assert len(out["pieces"]) >= 256
        for piece in out["pieces"]:
            d = np.array(piece["correct"])[:, 2] - np.array(piece["affine"])[:, 2]
            assert (d >= -1e-12).all() or (d <= 1e-12).all()
            assert np.array_equal(
                np.array(piece["correct"])[:, :2], np.array(piece["affine"])[:, :2]
            )
        ends = np.array(out["crossing"]).reshape(-1, 3)
        assert len(out["crossing"]) >= 8
        lam = tr.barycentric(np.array(xy), ends[:, :2])
        inside = (lam > 1 / 16).all(axis=1) | (lam[:, 2] > 1 - 1e-12)  # off v1v2 by a cell, or v3
        assert inside.sum() >= 8
        assert np.allclose(lam[inside] @ f, f[2], atol=1e-9)  # the line where affine f is f3
        assert np.allclose(ends[inside, 2], f[2], atol=1e-9)
        # a cell that touches v1v2 (where the sheets meet too) ends it within that cell
        assert np.allclose(lam @ f, f[2], atol=0.01)
    flat = call_js(parts, [("sheetPieces", [xy, [1.0, 1.0, 1.0], f, names])])[0]
    assert flat["crossing"] == []


def test_view3d_fits_the_picture_and_spreads_the_labels():
    # review r78 03-3: the 3-D view fills its box at any turn, and labels do not overlap
    rng = np.random.default_rng(78)
    box = {"left": 8, "top": 8, "right": 632, "bottom": 440}
    calls = []
    for n in (5, 40, 200):  # points at scale 1, three of them with a label beside them
        q = rng.normal(0, rng.uniform(1, 30), (n, 2))
        items = [[x, y, 0, 0, 0] for x, y in q.tolist()]
        items[:3] = [[x, y, 150.0, 17.0, 5.0] for x, y, *_ in items[:3]]
        calls.append(("fitScale", [items, box]))
    for (_, (items, _box)), got in zip(calls, call_js(("raster_rules", "view3d"), calls)):
        x0, x1, y0, y1 = got["extent"]
        assert x0 >= 8 - 1e-6 and x1 <= 632 + 1e-6 and y0 >= 8 - 1e-6 and y1 <= 440 + 1e-6
        assert x1 - x0 > 623 or y1 - y0 > 431  # it fills the box one way: wide or high
        s, (ax, ay) = got["scale"], got["at"]
        assert min(ax + s * it[0] for it in items) == pytest.approx(x0)
        assert max(ax + s * it[0] + it[2] for it in items) == pytest.approx(x1)
        assert min(ay + s * it[1] - it[3] for it in items) == pytest.approx(y0)
    boxes = [{"x": 10.0, "y": 100.0 + 3 * k, "w": 150.0, "h": 22.0, "fixed": k == 0}
             for k in range(4)] + [{"x": 400.0, "y": 430.0, "w": 50.0, "h": 22.0, "fixed": False},
                                   {"x": 420.0, "y": 425.0, "w": 50.0, "h": 22.0, "fixed": False}]  # fmt: skip
    ys = call_js(("raster_rules", "view3d"), [("spreadLabels", [boxes, 0, 444])])[0]
    assert ys[0] == 100.0  # fixed
    for i, a in enumerate(boxes):
        assert 0 <= ys[i] and ys[i] + a["h"] <= 444
        for j, b in enumerate(boxes[:i]):
            across = a["x"] < b["x"] + b["w"] and b["x"] < a["x"] + a["w"]
            assert not across or abs(ys[i] - ys[j]) >= 22 - 1e-9, (i, j)


def test_eye_ray_t_of_q_and_the_peak_for_ratio_2():
    from teachraster.plotting.projection import Segment

    seg = Segment(x0=-1.0, z0=1.5, x1=2.0, z1=3.0)  # depth ratio 2
    qs = np.linspace(0, 1, 41)
    got = call_js(("explore_projection",), [("worldParameter", [float(q), 1.5, 3.0]) for q in qs]
                  + [("peakGap", [1.5, 3.0]), ("peakGap", [1.0, 5.0])])  # fmt: skip
    assert np.allclose(got[:41], seg.world_parameter(qs), rtol=0, atol=1e-15)
    peak = got[41]
    assert peak["gap"] == pytest.approx(3 - 2 * np.sqrt(2), abs=1e-15)
    assert peak["formula"] == pytest.approx(3 - 2 * np.sqrt(2), abs=1e-15)
    dense = np.linspace(0, 1, 200001)
    assert peak["gap"] >= (dense - Segment(0, 1.0, 1, 2.0).world_parameter(dense)).max() - 1e-12
    other = got[42]
    assert other["gap"] == pytest.approx(other["formula"], abs=1e-14)


def _text_px(text: str, px: float, bold: bool = False) -> float:
    """The width of ``text`` at ``px`` in DejaVu Sans (matplotlib's font; Chromium's sans-serif
    here, and wider than Arial, Helvetica or Segoe UI)."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextPath

    font = FontProperties(family="DejaVu Sans", weight="bold" if bold else "normal", size=px)
    return TextPath((0, 0), text, prop=font).get_extents().width


def test_pipeline_map_text_reads_16_px_and_fits_its_boxes():
    """Review r97 00-5 (r91 00-D): the stage names were 13 px bold and the caption read 12-13 px
    at 1280 px. Every text of the map is now at least 15 px where it is drawn 1:1, in any
    column as wide as the map (at most the 940-px notebook column), and 12 px in the 585-px
    column of a 1024-px screen; each name and lesson line fits its box with room to spare."""
    from teachraster.plotting.style import COLUMN_WIDTH_PX
    from teachraster.widgets.pipeline_map import tour_stages

    (m,) = call_js(("explore_pipeline",), [("mapGeometry", [])])
    assert m["name"] >= 15 and m["font"] >= 15 and m["width"] <= COLUMN_WIDTH_PX
    assert min(m["name"], m["font"]) * min(1.0, 585 / m["width"]) >= 12.0
    js = (Path(tr.__file__).parent / "widgets" / "static" / "explore_pipeline.js").read_text()
    assert not re.search(r'"font-size": \d', js)  # every size is MAP's
    names = dict(re.findall(r'^  \["(\w+)", "([^"]*)", "[^"]*"\],$', js, flags=re.M))
    lessons = tour_stages()["lessons"]
    for box in m["boxes"]:
        assert 0 <= box["x"] and box["x"] + box["w"] <= m["width"]
        assert box["y"] + box["h"] <= m["height"]
        room = box["w"] - 2 * 6  # 6 px from either border (the selected box's is 2 px)
        for line in names[box["key"]].split("|"):
            assert _text_px(line, m["name"], bold=True) <= room, line
        for line in lessons[box["key"]]:
            assert _text_px(line, m["font"]) <= room, line
    for line in m["caption"]:  # from the left edge
        assert _text_px(line, m["font"]) <= m["width"] - 4, line
    r, f = m["boxes"][6], m["boxes"][7]  # the note is centred under early-z, between them
    centre = r["x"] + r["w"] / 2 - 30 + (f["x"] - r["x"] + 60) / 2
    for line in m["note"]:
        assert _text_px(line, m["font"]) / 2 <= min(centre, m["width"] - centre) - 2, line


def test_pipeline_map_shows_the_engines_tour_triangle():
    from teachraster.pipeline.geometry.viewport import to_window
    from teachraster.widgets.pipeline_map import TOUR_XY, tour_clip, tour_stages

    data = tour_stages()
    # the clip coordinates are a projection of lesson 00's triangle: the viewport gives it back
    assert np.allclose(to_window(np.array(data["clip"]), 16, 16)[:, :2], TOUR_XY, atol=1e-12)
    assert np.allclose(data["clip"], tour_clip(TOUR_XY, [1, 2, 4], 16, 16, 0.5, 10.0))
    tour = tr.rasterize(tr.Triangle(TOUR_XY, w=[1, 2, 4], attrs={"u": [0, 1, 0]}), 16, 16)
    assert np.array_equal(np.array(data["coverage"], bool).reshape(16, 16), tour.coverage)
    assert data["fragments"] == int(tour.coverage.sum()) == data["passed"]
    u = np.array([np.nan if v is None else v for v in data["attr"]]).reshape(16, 16)
    # tr.render sets its weights up from the unsnapped vertices, tr.rasterize from the
    # snapped ones (1/256 px apart at most)
    assert np.allclose(u, tour.attrs["u"], equal_nan=True, atol=1e-3)
    # the snapped triangle's area (it differs from the unsnapped one in the 4th digit)
    assert data["area"] == setup_edges(np.array(TOUR_XY), 8).original_area2 / 512**2 / 2
    keys = ["vertex", "assembly", "clip", "divide", "viewport", "setup", "rasterize",
            "fragment", "depth", "blend"]  # fmt: skip
    got = call_js(("explore_pipeline",), [("stageHtml", [data, k]) for k in keys]
                  + [("stageImage", [data, k]) for k in keys])  # fmt: skip
    html, images = dict(zip(keys, got[:10], strict=True)), dict(zip(keys, got[10:], strict=True))
    assert all(html.values())  # every stage says something
    for k in range(3):  # the numbers each stage shows are the engine's
        assert f"{data['clip'][k][3]:g}" in html["vertex"]
        assert str(float(f"{data['window'][k][0]:.5g}")).rstrip("0").rstrip(".") in html["viewport"]
    assert f"{data['fragments']} pixel centres" in html["rasterize"]
    # the guard band render clips this image with (review r7: not the clipper's default 2**20):
    # the vertices are tested against it
    from teachraster.pipeline.geometry.clipping import INSIDE, classify
    from teachraster.pipeline.rendering.stages import guard_band

    assert data["guard"] == guard_band(16, 16, 8) == 261880.856
    assert data["inside"] == [bool(c == INSIDE) for c in classify(np.array([data["clip"]]),
                                                                     data["guard"])]  # fmt: skip
    # review r241 S7 (after r225 S4, r166 00-8, r157 00-3): a GPU's band is its own
    # fixed-point rasteriser's; the simulator's numbers are package internals in a tour (lessons
    # 05a and 10 print them): one sentence says the band is the simulator's own, no number
    assert "This simulator has a band of its own, sized in lessons 05a and 10." in html["clip"]
    assert "G ≈" not in html["clip"] and "million px" not in html["clip"]
    assert "2,097,152" not in html["clip"] and "e+" not in html["clip"]
    assert "G is set per image" not in html["clip"] and "fixed-point rasteriser" in html["clip"]
    assert "guardPx" not in data and "exactPx" not in data  # nothing the page no longer shows
    # the clip coordinates to three decimals each, z as x (r225 S4: 0.052632 beside 2.200)
    for stage in ("vertex", "clip"):
        cells = re.findall(r"<td>(-?\d+\.\d+)</td>", html[stage])[:12]  # v1 to v3, x y z w
        assert all(len(c.split(".")[1]) == 3 for c in cells), cells
        assert np.allclose([float(c) for c in cells], np.ravel(data["clip"]), atol=5.1e-4)
    assert "0.052632" not in html["vertex"]
    # r225 F1: the specification's names (object, eye, clip coordinates)
    js = (Path(tr.__file__).parent / "widgets" / "static" / "explore_pipeline.js").read_text()
    assert "object → clip coordinates" in js and "model → clip" not in js
    # review r166 00-7: the stage names the stencil test, and says what it does; its key
    # matches the picture (depth 1 is grey 200, light; white is "no fragment", not the
    # cleared buffer's 1)
    assert "stencil test" in html["depth"] and "per-pixel integer" in html["depth"]
    assert "mid grey" not in html["depth"] and "depth 1 light grey" in html["depth"]
    # review r225 S3: the cleared value, 1, is not given a second colour: the picture shows
    # the fragments' depths, white where none was written
    assert "white: no fragment written (the cleared pixels, left blank)" in html["depth"]
    assert "the buffer keeps its cleared 1 there" not in html["depth"]
    # review r225 M1: depth is interpolated affinely, with no divide (unlike the attribute)
    assert "affine on the screen: no divide by w, unlike u" in html["depth"]
    # review r241 S1: the attribute is u, as lesson 04 calls it (s is lesson 04's screen
    # coordinate), in every stage's text and the vertex table
    assert "<th>u</th>" in html["vertex"] and "lesson 04" in html["vertex"]
    assert "interpolating u/w and 1/w" in html["fragment"] and "Key: u = 0" in html["fragment"]
    assert not any(re.search(r"\bs/w\b|\battribute s\b|<th>s</th>", h) for h in html.values())
    assert "cleared to white" in html["blend"] and "dark grey" not in html["blend"]
    # early-z (test and write before the shader) only when the shader neither discards nor
    # writes depth (issue 29, r52); as lesson 05a teaches, a depth-writing shader needs the
    # late test, a discarding one may still be tested early and written late (r9)
    assert "neither discards, writes depth nor writes memory" in html["depth"]
    assert "writes its own depth needs the late test" in html["depth"]
    assert "may still test early and write the depth late" in html["depth"]
    assert "discard" in html["fragment"]
    assert sum(c != [245, 245, 245] for c in images["rasterize"]) == data["fragments"]
    # review r115 00-B: depth 1 was grey 240 beside a grey-245 "no fragment"; now depth runs
    # from grey 20 (0) to 200 (1) and no fragment is white, as the key says
    depth = [None if d is None else 20 + 180 * d for d in data["depth"]]
    assert [c[0] if d is not None else None for c, d in zip(images["depth"], depth)] == [
        None if d is None else round(d) for d in depth
    ]
    assert all(c == [255, 255, 255] for c, d in zip(images["depth"], depth) if d is None)
    assert max(d for d in depth if d is not None) <= 200  # 55 grey levels from white at least
    assert "white: no fragment" in html["depth"] and "lightest grey" not in html["depth"]
    assert images["vertex"] is None and images["blend"] == data["colour"]
    # review r157 00-12: the navy u = 0 fragments vanished on the dark-grey clear colour
    assert all(c == [255, 255, 255] for c, k in zip(images["blend"], data["coverage"]) if not k)
    lum = [0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2] for c, k in
           zip(images["blend"], data["coverage"]) if k]  # fmt: skip
    assert max(lum) < 200  # the lightest fragment (u 0.86, a dark yellow) stands off white


def test_every_explorables_module_loads_as_shipped():
    """Each explorable's whole module (its mount code too, which only the browser tests run)
    parses and runs its top level in node: a syntax slip fails here, in the quick tier."""
    from teachraster.widgets.explorable import Explorable
    from teachraster.widgets.offline import widget_classes

    shipped = {c._esm for c in widget_classes() if issubclass(c, Explorable) and "_esm" in vars(c)}
    assert len(shipped) >= 9
    with tempfile.TemporaryDirectory(prefix="tr-node-") as tmp:
        for k, source in enumerate(sorted(shipped)):
            path = Path(tmp, f"m{k}.mjs")
            path.write_text(source, encoding="utf-8")
            done = subprocess.run([NODE, "--input-type=module", "-e", f"await import({json.dumps(path.as_uri())})"],
                                  capture_output=True, text=True, timeout=120)  # fmt: skip
            assert done.returncode == 0, done.stderr[-2000:]


def test_end_point_labels_keep_clear_of_the_axis_labels():
    """Review r43 12a-8: p1 dragged to the image's top-right corner put "p1 on a pixel corner"
    over the column numbers (the canvas's top margin). A label stays right of and below the
    axis labels (the grid's left and top), here below the point, left of it."""
    width, size, grid = 120, 15, [30, 24]
    corner, free = call_js(LINES, [("labelAt", [390, 24, width, 400, [], size, grid]),
                                   ("labelAt", [100, 100, 60, 400, [], size, grid])])  # fmt: skip
    lx, ly = corner
    assert ly - size >= grid[1] and lx >= grid[0] and lx + width <= 398
    assert free == [109, 91]  # away from the margins, the first place as before


def test_end_point_labels_keep_clear_of_the_tie_marks():
    """Reviews r31/r34 12a: "p1 on a pixel centre" covered a "tie" mark. A label whose first
    place (right of and above the point) covers a mark goes to the next place that covers none."""
    mark = [105, 76, 30, 16]  # a "tie" where the label would go, right of and above (100, 100)
    free, moved, boxed_in = call_js(LINES, [("labelAt", [100, 100, 60, 400, [], 15]),
                                            ("labelAt", [100, 100, 60, 400, [mark], 15]),
                                            ("labelAt", [100, 100, 60, 400, [[0, 0, 400, 400]],
                                                         15])])  # fmt: skip
    assert free == [109, 91] and boxed_in == [109, 91]  # nowhere clear: the first place
    lx, ly = moved
    assert [lx, ly] != [109, 91]
    bx, by, bw, bh = mark
    assert lx + 60 < bx or bx + bw < lx or ly < by or by + bh < ly - 15


def test_end_point_label_is_not_read_with_a_tie_mark_beside_it():
    """Review r101 12a-D: "p0" sat a few pixels left of the "tie" mark of the next pixel, on
    its line, and read as "p0 tie". A mark on the label's line keeps a wide space from it."""
    size, width = 15, 20
    first = call_js(LINES, [("labelAt", [100, 100, width, 400, [], size])])[0]
    lx, ly = first
    mark = [lx + width + 4, ly - size, 24, size]  # 4 px right of the label, on its line
    moved = call_js(LINES, [("labelAt", [100, 100, width, 400, [mark], size])])[0]
    mx, my = moved
    assert moved != first
    bx, by, bw, bh = mark
    assert (
        mx + width + 0.8 * size < bx or bx + bw + 0.8 * size < mx or my < by or by + bh < my - size
    )


def test_readout_in_front_of_the_near_plane_says_clipped():
    # review r47 05b: near dragged from 0.1 to 2.5 left the readout at z = 0.1 with a negative
    # float32 depth; a fragment in front of the near plane is clipped and stores nothing
    clipped, at_near, beyond = call_js(DEPTH, [("depthTable", [0.1, 2.5, 1000.0]),
                                               ("depthTable", [2.5, 2.5, 1000.0]),
                                               ("depthTable", [58.5, 2.5, 1000.0])])  # fmt: skip
    assert "in front of the near plane" in clipped and "clipped" in clipped
    assert "<table>" not in clipped and "−" not in clipped and "-" not in clipped
    for table in (at_near, beyond):
        assert "<table>" in table and "clipped" not in table
        cells = [c.split("<")[0] for c in table.split("<td>")[1:]]
        values = [float(c.split()[0].replace(",", "")) for c in cells if c[:1].isdigit()]
        assert len(values) == 12 and min(values) >= 0, table  # value, step, count x 4


def test_depth_lens_ticks_are_distinct_round_and_show_300():
    # review r170 05b-8: at z = 300 ± 2.07e-5 the lens' three ticks read "299.9998 ·
    # 299.9998 · 299.9999" (7 significant digits); round ticks with the decimals their step
    # needs read apart, and 300 inside the lens shows as itself
    half = 2.07e-5
    cases = [(300.0 - 0.6 * half, half), (300.0 + 0.3 * half, half), (100.0, 22.5), (5.0, 0.004)]
    calls = [("lensTicks", [z0 - h, z0 + h]) for z0, h in cases]
    calls += [("lensCentre", [z0, 2 * h]) for z0, h in cases]
    got = call_js(DEPTH, calls)
    ticks, centres = got[: len(cases)], got[len(cases) :]
    for (z0, h), t in zip(cases, ticks, strict=True):
        labels = [x["label"] for x in t]
        assert 3 <= len(t) <= 5 and len(set(labels)) == len(labels), labels
        assert all(z0 - h <= x["z"] <= z0 + h for x in t)
        assert all(float(lab) == pytest.approx(x["z"], abs=1e-9) for lab, x in zip(labels, t))
    assert "300.00000" in [x["label"] for x in ticks[0]]
    assert "300.00000" in [x["label"] for x in ticks[1]]
    assert centres[0] != "300" and float(centres[0]) == pytest.approx(cases[0][0], abs=1e-6)
    # review r170 05b-9: the step to the smallest denormal at the near plane is flagged
    at_near, beyond = call_js(DEPTH, [("depthTable", [2.5, 2.5, 1000.0]),
                                      ("depthTable", [58.5, 2.5, 1000.0])])  # fmt: skip
    assert at_near.count(" *</td>") == 1 and " *</td>" not in beyond
    assert "smallest denormal" in at_near and "smallest denormal" not in beyond


def test_depth_lens_stays_within_near_and_far_and_says_when_it_holds_no_value():
    """Review r223 05b-2: zoomed out (zoom -2) with the near plane at 0.01, the lens at z = 500
    read "z = 500.0 ± 906000", into negative z and far past the far plane. Review r223 05b-3:
    zoomed in to ± 2.29e-8 at z = 10 (near 1), every row stayed blank."""
    wide, fine, inside = [500.0, 1.812e6, 0.01, 1000.0], [10.0, 4.58e-8, 1.0, 1000.0], [
        300.0, 0.2, 0.1, 1000.0]  # fmt: skip
    rows = [("lensRow", [*case, f]) for case in (wide, fine, inside)
            for f in ("unorm16", "unorm24", "float32", "reversed")]  # fmt: skip
    got = call_js(DEPTH, [("lensWindow", wide), ("lensTitle", wide), ("lensWindow", inside),
                          ("lensTitle", inside), ("lensTitle", fine), *rows])  # fmt: skip
    win, title, win_in, title_in, title_fine = got[:5]
    assert (win["za"], win["zb"], win["cut"]) == (0.01, 1000.0, True)
    assert title == "lens: z from 0.01 (near) to 1000 (far) (linear)" and "±" not in title
    assert not win_in["cut"] and win_in["za"] == pytest.approx(299.9) and "±" in title_in
    assert "±" in title_fine
    wide_rows, fine_rows, inside_rows = got[5:9], got[9:13], got[13:17]
    for row in wide_rows:  # the whole range: too many values in every buffer
        assert row["dense"] and row["text"].endswith("zoom in to see them one by one")
    for row in fine_rows:  # finer than every buffer's step there: said, not left blank
        assert "values" not in row and row["text"] == "no stored value within ± 2.29e-8: zoom out"
    # z = 300 ± 0.1 (near 0.1): unorm16 (step about 14) has none there, unorm24 and float32
    # (step 0.054) a few single values, reverse-Z (step 1.3e-5) too many to draw
    assert inside_rows[0]["text"] == "no stored value within ± 0.1: zoom out"
    for row in inside_rows[1:3]:
        assert 2 <= len(row["values"]) <= 5 and all(299.9 <= z <= 300.1 for z in row["values"])
    assert inside_rows[3]["dense"]


def test_diamond_explorer_outlines_only_the_pixels_the_line_crosses():
    """Review r83 12a-4: the walk outlined all 5 candidates of every column, rows 0-5 of the
    6-row grid at the start; review r88: one row either side of the line still outlined rows
    0-2 in columns 0-2. Now each walked column outlines the pixels lit, ended in or decided by
    a tie, and the missed ones whose square the segment crosses inside that column."""
    walk = call_js(LINES, [("diamondSteps", [[0.5, 0.5], [8.5, 4.5], 10, 6])])[0]
    kept = call_js(LINES, [("nearCandidates", [walk, s]) for s in walk["steps"]])
    for s, near in zip(walk["steps"], kept, strict=True):
        # the segment (slope 1/2) inside column j runs from y = (j + 1)/2 - 1/4 to + 1/4,
        # clipped to x >= 0.5 at p0, and stops at p1 (8.5, 4.5) in column 8
        j = s["major"]
        y0 = 0.5 + (max(j, 0.5) - 0.5) / 2
        y1 = 0.5 + (min(j + 1, 8.5) - 0.5) / 2
        crossed = {r for r in range(6) if r < y1 and y0 < r + 1}
        assert {c["row"] for c in near} <= crossed | {c["row"] for c in near if c["tie"]}
        assert {c["row"] for c in near if c["state"] == 0 and not c["tie"]} <= crossed
        rest = [c for c in s["cands"] if c not in near]
        assert all(c["state"] == 0 and not c["tie"] for c in rest)
        assert len(near) <= 2
    assert [sorted(c["row"] for c in n) for n in kept[:3]] == [[0], [0, 1], [1]]


def test_end_point_labels_keep_off_the_lit_squares_where_they_can():
    """Review r83 12a-3: after p1 was dragged to (9.5, 4.5), "p1 on a pixel centre" lay on the
    lit diamond (4, 8). Lit squares are avoided where a spot allows it, also a spot farther
    below the point; with none clear the label stays where it went before."""
    lit = [105, 70, 64, 64]  # a lit square under both near spots right of (100, 100)
    left = [0, 70, 100, 64]
    (plain, moved, nowhere) = call_js(LINES, [
        ("labelAt", [100, 100, 60, 400, [], 15]),
        ("labelAt", [100, 100, 60, 400, [], 15, [0, 0], None,
                     {"soft": [lit, left], "far": 32, "bottom": 300}]),
        ("labelAt", [100, 100, 60, 400, [], 15, [0, 0], None,
                     {"soft": [[0, 0, 400, 400]], "far": 32, "bottom": 300}]),
    ])  # fmt: skip
    assert plain == [109, 91] and nowhere == [109, 91]
    lx, ly = moved
    for bx, by, bw, bh in (lit, left):
        assert lx + 60 < bx or bx + bw < lx or ly < by or by + bh < ly - 15
    assert ly <= 300 - 3
    # p1 by the right border, the line running through the spots left of it: flush with the
    # border, below the point (the up-running line ended in row 0)
    (flush,) = call_js(LINES, [("labelAt", [380, 100, 60, 400, [], 15, [0, 0], None,
                                            {"soft": [[300, 80, 36, 50]], "far": 32}])])  # fmt: skip
    assert flush == [338, 122]


def _overdrawn_nearer(drawn: list[dict], n: int = 250) -> tuple[int, int]:
    """Screen points where a farther piece is drawn over a nearer one, of points covered twice.

    Each piece is tested at the grid points of its bounding box only (the points outside it
    are never inside: the same counts as testing all n * n, in a tenth of the time)."""
    s = [np.array(piece["s"]) for piece in drawn]
    allp = np.concatenate(s)
    xs = np.linspace(allp[:, 0].min(), allp[:, 0].max(), n)
    ys = np.linspace(allp[:, 1].min(), allp[:, 1].max(), n)
    last = np.full((n, n), -np.inf)  # depth of the piece drawn last over each point
    bad = np.zeros((n, n), bool)
    twice = np.zeros((n, n), bool)
    for q in s:  # in the order drawn; each piece fanned into triangles
        i0, i1 = np.searchsorted(ys, [q[:, 1].min(), q[:, 1].max()])
        j0, j1 = np.searchsorted(xs, [q[:, 0].min(), q[:, 0].max()])
        box = np.s_[i0 : i1 + 1, j0 : j1 + 1]
        px, py = np.meshgrid(xs[box[1]], ys[box[0]])
        depth = np.full(px.shape, np.nan)
        for k in range(1, len(q) - 1):
            a, b, c = q[0], q[k], q[k + 1]
            det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
            if abs(det) < 1e-12:
                continue
            l1 = ((px - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (py - a[1])) / det
            l2 = ((b[0] - a[0]) * (py - a[1]) - (px - a[0]) * (b[1] - a[1])) / det
            inside = np.minimum(np.minimum(l1, l2), 1 - l1 - l2) > 1e-6
            depth[inside] = ((1 - l1 - l2) * a[2] + l1 * b[2] + l2 * c[2])[inside]
        hit, seen = ~np.isnan(depth), last[box]
        twice[box] |= hit & np.isfinite(seen)
        bad[box] |= hit & (depth < seen - 1e-6)
        last[box] = np.where(hit, np.maximum(seen, np.nan_to_num(depth, nan=-np.inf)), seen)
    return int(bad.sum()), int(twice.sum())


def test_attribute_sheets_are_drawn_far_to_near_wherever_they_overlap():
    # review r96 03-1: dragged up (a low view), sorting the pieces' centres put orange and blue
    # facets over one another in turn, a checker pattern; now, from every view, no piece is
    # drawn over a nearer one where the two overlap on the screen
    xy, f = [[2.0, 1.0], [13.0, 5.0], [5.0, 12.0]], [0.2, 0.9, 0.5]  # lesson 03's
    parts = ("raster_rules", "view3d", "explore_attributes")
    views = [  # the opening view, r96's drag 150 px up (to the lowest elevation), turns
        {"yaw": -0.5, "elevation": 0.45},
        {"yaw": -0.5, "elevation": 0.05},
        {"yaw": 1.0, "elevation": 0.15},
        {"yaw": 2.6, "elevation": 0.05},
        {"yaw": -2.2, "elevation": 0.8},
        {"yaw": 0.3, "elevation": 1.5},
    ]
    calls = [
        ("drawnSheets", [xy, [1.0, 1.0, w3], f, ["correct", "affine"], 16, 14, view])
        for w3 in (2.0, 8.0)
        for view in views
    ]
    low = ("drawnSheets", [xy, [1.0, 1.0, 8.0], f, ["correct", "affine"], 16, 14, views[2]])
    got = call_js(parts, [*calls, (low[0], [*low[1], False])])
    for (_, args), drawn in zip(calls, got[:-1]):
        assert {piece["sheet"] for piece in drawn} == {"correct", "affine"}
        bad, twice = _overdrawn_nearer(drawn)
        assert twice > 500, args  # the sheets do overlap on the screen
        assert bad == 0, args
    # the test sees the fault: the old sort by centre depth fails in a low turned view
    assert _overdrawn_nearer(got[-1])[0] > 100


def test_value_axis_labels_only_where_they_do_not_overlap():
    # review r96 03-2: looking down, "0" and "0.5" were printed on one another
    parts = ("raster_rules", "view3d", "explore_attributes")
    calls = [("valueTicks", [30.0, e, 8.8]) for e in (0.45, 1.3, 1.5, 1.57)]
    got = call_js(parts, calls)
    for (_, (scale, e, z)), ticks in zip(calls, got):
        assert ticks == ([0, 0.5, 1] if scale * z * np.cos(e) / 2 >= 24 else [0])
    assert got[0] == [0, 0.5, 1] and got[-1] == [0]


def test_value_axis_stands_at_the_corner_leftmost_on_the_picture():
    # review r226 FIG3: at the corner (0, 0), turned to the front, the axis "1 / 0.5 / 0" ran
    # through the sheets; r288 FIG2: at the far corner its labels lay over the sheets and its
    # "0" floated mid-picture (the ground there hidden). It stands at the corner leftmost on
    # the picture now: vertical lines stay vertical, so every sheet lies right of it; the
    # vertex labels below their vertices, off the sheets that rise above them
    parts = ("raster_rules", "view3d", "explore_attributes")
    views = [(-0.5, 0.45), (1.0, 0.15), (2.6, 0.05), (-2.2, 0.8), (0.3, 1.5)]
    got = call_js(parts, [("axisCorner", [16, 14, yaw, e]) for yaw, e in views])
    corners = [[0, 0], [16, 0], [16, 14], [0, 14]]
    for (yaw, _e), corner in zip(views, got):
        # camera3d's picture x (up to its scale and shift), the same for every height
        across = [x * np.cos(yaw) - y * np.sin(yaw) for x, y in corners]
        assert corner == corners[int(np.argmin(across))]
    assert got[0] == [0, 0]  # the opening view: the left corner, by v1, on open ground
    from teachraster.widgets import explorable

    source = (explorable.STATIC / "explore_attributes.js").read_text()
    assert "...VERTEX_LABEL" in source and "[0, 0, zScale]" not in source
    assert "fixed: true, up: 17, down: 5, halo: true" in source  # the axis labels haloed


def test_gap_bar_labels_on_one_line_when_the_bar_is_short():
    # review r96 03-2: seen from above the bar shrank to a few pixels and its three labels
    # (f, affine, gap) were drawn on one another and on v3's; below GAP_LABELS_APART px they
    # are one line at the bar's middle
    parts = ("raster_rules", "view3d", "explore_attributes")
    gap = {"p": [7.17, 10.1], "gap": 0.191, "s": {"correct": 0.799, "affine": 0.608}}
    tall, short = call_js(parts, [("gapBarLabels", [gap, 8.8, px]) for px in (46.0, 12.0)])
    assert [label["text"].strip() for label in tall] == ["gap 0.191", "f 0.799", "affine 0.608"]
    assert [label["p"][2] for label in tall] == pytest.approx(
        [(0.799 + 0.608) / 2 * 8.8, 0.799 * 8.8, 0.608 * 8.8]
    )
    assert len(short) == 1
    assert short[0]["text"].strip() == "f 0.799 / affine 0.608 / gap 0.191"
    assert short[0]["p"][2] == pytest.approx((0.799 + 0.608) / 2 * 8.8)


def test_crack_explorer_finds_cracks_on_its_larger_grid():
    """Review r229 01-W2: with the toggle on, "Roll 1000 more" found no crack on the 16 x 16
    grid ("0 of 1000"), so the toggle showed cracks only through the stored pair. A button
    switches to 32 x 32, where a thousand rolls show some, and "Roll until one cracks" rolls
    (counting every pair) until a float fill cracks or draws twice; on 16 x 16, or with the
    toggle off, it gives up, as lesson 01's text says."""
    from teachraster.widgets import CrackExplorer

    ex = CrackExplorer()
    data, seed = ex.data, ex.data["seed"]
    assert data["large"] == [32, 32] and ex.state["large"] is False
    assert CrackExplorer(large=None).data["large"] is None
    with pytest.raises(ValueError, match="large"):
        CrackExplorer(large=41)
    small_grid, large_grid, most = call_js(CRACKS, [("gridOf", [data, False]),
                                                    ("gridOf", [data, True]),
                                                    ("untilFault", [seed, 4, 4, True, 0])])  # fmt: skip
    assert small_grid == [16, 16] and large_grid == [32, 32] and not most["found"]
    # the page's first 1001 pairs of each grid, evaluated as listed: none and some
    small, large = call_js(
        CRACKS, [("rolls", [seed, 1001, 16, 16]), ("rolls", [seed, 1001, 32, 32])]
    )
    t_small, t_large = call_js(CRACKS, [("tallyOver", [small, 16, 16, True]),
                                        ("tallyOver", [large, 32, 32, True])])  # fmt: skip
    assert t_small["dda"]["faulty"] == t_small["crossing"]["faulty"] == 0
    assert t_large["dda"]["faulty"] + t_large["crossing"]["faulty"] > 0
    found, none_small, none_alike = call_js(CRACKS, [
        ("untilFault", [seed, 32, 32, True]),
        ("untilFault", [seed, 16, 16, True]),
        ("untilFault", [seed, 32, 32, False, 1000]),
    ])  # fmt: skip
    assert found["found"] and found["n"] < 3000
    assert found["tally"]["integer"]["pairs"] == found["n"] + 1  # every pair counted
    a, b = (np.array(t) for t in found["pair"])
    from teachraster.study.naive_spans import shared_edge_faults

    faulty = [shared_edge_faults(a, b, 32, 32, m, as_listed=True) for m in ("crossing", "dda")]
    assert any(len(f["cracks"]) or len(f["doubles"]) for f in faulty)  # the engine agrees
    assert not none_small["found"] and none_small["n"] == 3000
    assert not none_alike["found"]
    notes = call_js(CRACKS, [("huntNote", [{"n": found["n"], "found": True}, True]),
                             ("huntNote", [{"n": 3000, "found": False}, True]),
                             ("huntNote", [{"n": 3000, "found": False}, False]),
                             ("huntNote", [{"n": 3000, "found": False}, True, True])])  # fmt: skip
    assert f"found after {found['n']} pairs" in notes[0]
    assert "try the larger grid" in notes[1] and "turn on" not in notes[1]
    assert "never cracks" in notes[2] and "roll again" in notes[3]


def test_crack_note_does_not_send_lesson_01_to_itself():
    """Review r229 01-S1: inside lesson 01 the note said "as lesson 01's loops do"."""
    notes = call_js(CRACKS, [("crackNote", [False]), ("crackNote", [True])])
    for note in notes:
        assert "lesson 01" not in note and "as the span loops above do" in note
    assert "Roll until one cracks" in notes[1]


def test_crack_explorer_zooms_the_stored_pair_on_the_larger_grid():
    """Review r239 01-FIG2: on the 32 x 32 grid "Show a pair that cracks" drew the stored
    pair, 16 x 12 px, in the top-left quarter of each panel, its crack ring on the border.
    The panels draw the 16 x 16 box that holds it (the fills unchanged: the pair covers
    nothing outside it), and a line says so."""
    pair = [[[0.5, 4.5], [15.5, 15.5], [1.5, 11.5]], [[15.5, 15.5], [0.5, 4.5], [12.5, 2.5]]]
    got = call_js(CRACKS, [
        ("crackingBox", []), ("shownGrid", [32, 32, True]), ("shownGrid", [32, 32, False]),
        ("shownGrid", [16, 16, True]), ("shownGrid", [8, 8, True]),
        ("storedNote", [32, 32, True]), ("storedNote", [16, 16, True]),
        ("storedNote", [32, 32, False]),
        ("faults", [pair[0], pair[1], 16, 16, "dda", True]),
        ("faults", [pair[0], pair[1], 32, 32, "dda", True]),
        ("panelLayout", [16, 16, 940]), ("panelLayout", [32, 32, 940]),
    ])  # fmt: skip
    box, big, plain, own, small, note, none_own, none_off, zoomed, whole, g16, g32 = got
    assert box == [16, 16] and big == [16, 16] and plain == [32, 32] and own == [16, 16]
    assert small == [8, 8]  # the pair does not fit: no stored pair on such a grid
    assert "16 × 16 corner of the 32 × 32 grid" in note and none_own == none_off == ""
    # the same cracks and doubles, zoomed or not; nothing drawn outside the box
    assert zoomed["cracks"] == whole["cracks"] == [[4, 0]]
    assert zoomed["doubles"] == whole["doubles"]
    a32 = np.array(whole["a"]).reshape(32, 32)
    b32 = np.array(whole["b"]).reshape(32, 32)
    assert not a32[16:].any() and not a32[:, 16:].any() and not b32[16:].any()
    assert not b32[:, 16:].any()
    assert np.array_equal(a32[:16, :16].ravel(), zoomed["a"])
    # zoomed, the cells are as large as on the 16 x 16 grid: the pair fills the panel
    assert g16["cell"] > g32["cell"]


def test_one_row_shared_edge_leaves_v3_its_name_and_labels_stay_inside_the_grid():
    """Review r328 02-FIG1: with v2 and v3 on one row, the centre left of v3 (on the edge's
    line, beyond its end) drew "+0−" beside v3's ring and B letter, and "v3" stood on its
    ring; a label of B's edge stood on the grid's bottom frame. That centre is quiet, the
    name takes a place clear of the rings, letters and shown signs, and a label given the
    grid's rectangle stays inside it."""
    verts = [[2.5, 1.5], [13.5, 5.5], [5.5, 5.5], [14.5, 12.5]]  # key 3, Shift+Up x 8
    cell, m, (W, H) = 50.0, {"left": 30, "top": 26}, (16, 14)
    (scene,) = call_js(EDGES, [("edgeScene", [verts, W, H])])
    (quiet,) = call_js(EDGES, [("quietCentres", [scene, verts])])
    assert [5, 4] in quiet and [5, 14] in quiet  # a pixel beyond v3 and beyond v2
    px = lambda x, y: [m["left"] + x * cell, m["top"] + y * cell]  # noqa: E731
    v3 = px(*verts[2])
    rings = [[*px(s["col"] + 0.5, s["row"] + 0.5), 0.42 * cell] for s in scene["shared"]]
    letters = call_js(EDGES, [("badgeCentre", [scene, s["row"], s["col"], cell, m,
                                               [px(*v) for v in verts]]) for s in scene["shared"]])  # fmt: skip
    boxes = [[x - 11, y - 11, x + 11, y + 11] for x, y in letters]
    grid, half = [*px(0, 0), *px(W, H)], [12.0, 9.5]
    (at,) = call_js(EDGES, [("vertexNameAt", [v3, half, cell, grid, rings, boxes])])
    box = [at[0] - half[0], at[1] - half[1], at[0] + half[0], at[1] + half[1]]
    for cx, cy, r in rings:
        near = np.hypot(max(box[0] - cx, 0, cx - box[2]), max(box[1] - cy, 0, cy - box[3]))
        assert near > r + 1.5
    assert not any(b[0] < box[2] and box[0] < b[2] and b[1] < box[3] and box[1] < b[3]
                   for b in boxes)  # fmt: skip
    # an edge along the grid's bottom row, its triangle above: the label goes inside the frame
    a, b, centroid = px(4, 13.5), px(9, 13.5), px(6, 10)
    (lab,) = call_js(EDGES, [("labelCentre", [a, b, centroid, [80.0, 10.0], cell, grid])])
    assert grid[1] + 10 <= lab[1] <= grid[3] - 10 and grid[0] + 80 <= lab[0] <= grid[2] - 80


def test_default_view_gives_v3_a_name_clear_of_its_ring_and_labels_clear_of_the_edges():
    """Review r343 02-FIG1: in the default view "v3" stood under v3's grey ring and its "−"
    letter, every place beside the ring holding a centre's signs; an edge's label could
    stand across a drawn edge. The centres beside a ringed end are quiet, and names and
    labels count a drawn edge through their box as a collision."""
    from teachraster.widgets.edge_explorer import DEFAULT_VERTICES

    verts = [list(v) for v in DEFAULT_VERTICES]
    cell, m, (W, H) = 50.0, {"left": 30, "top": 26}, (16, 14)
    (scene,) = call_js(EDGES, [("edgeScene", [verts, W, H])])
    (quiet,) = call_js(EDGES, [("quietCentres", [scene, verts])])
    px = lambda x, y: [m["left"] + x * cell, m["top"] + y * cell]  # noqa: E731
    dots = [px(*v) for v in verts]
    rings = [[*px(s["col"] + 0.5, s["row"] + 0.5), 0.42 * cell] for s in scene["shared"]]
    letters = call_js(EDGES, [("badgeCentre", [scene, s["row"], s["col"], cell, m, dots])
                              for s in scene["shared"]])  # fmt: skip
    centres = [(r, c) for r in range(H) for c in range(W)]
    shown = call_js(EDGES, [("signsShown", [scene["A"], r, c, None, quiet]) for r, c in centres])
    reach = [cell * 0.3 + cell * 0.48 / 2, cell * 0.3]
    boxes = [[x - 11, y - 11, x + 11, y + 11] for x, y in letters]
    boxes += [[x - reach[0], y - reach[1], x + reach[0], y + reach[1]]
              for (r, c), s in zip(centres, shown) if s for x, y in [px(c + 0.5, r + 0.5)]]  # fmt: skip
    (segments,) = call_js(EDGES, [("edgeSegments", [dots])])
    grid, half = [*px(0, 0), *px(W, H)], [12.0, 9.5]
    (at,) = call_js(EDGES, [("vertexNameAt", [dots[2], half, cell, grid, rings, boxes, segments])])
    box = [at[0] - half[0], at[1] - half[1], at[0] + half[0], at[1] + half[1]]
    for cx, cy, r in rings:
        assert (
            np.hypot(max(box[0] - cx, 0, cx - box[2]), max(box[1] - cy, 0, cy - box[3])) > r + 1.5
        )
    assert not any(b[0] < box[2] and box[0] < b[2] and b[1] < box[3] and box[1] < b[3]
                   for b in boxes)  # fmt: skip
    crossed = call_js(EDGES, [("segmentCrossesBox", [s, e, box]) for s, e in segments])
    assert not any(crossed)
    # the crossing test itself: through, beside, ending inside, parallel along a side
    assert call_js(EDGES, [("segmentCrossesBox", args) for args in (
        [[0, 5], [20, 5], [5, 0, 10, 10]], [[0, 20], [20, 20], [5, 0, 10, 10]],
        [[0, 0], [7, 7], [5, 0, 10, 10]], [[5, -5], [5, -1], [5, 0, 10, 10]])]) == [
        True, False, True, False]  # fmt: skip
