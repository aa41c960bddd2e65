"""Lesson 10, review r300: P2, FIG1, S1-S6 and S8 (see the test's docstring)."""

from __future__ import annotations

from test_lessons_b import _lesson_10_run, _lesson_10_sources


def test_10_r300_items():
    """Review r300, lesson 10. P2: q_trav ("which order moves least") followed from §5's
    definitions; it now asks serpentine's tile moves, a whole number, before the figure that
    numbers the visits, which it holds. FIG1: §1's block on its own range (it was one flat
    blue on the left panel's). S1: q_hiz's grid numbers every tile column. S2: italic v_k is
    a screen y, bold v_k the vertex. S3: front to back shades one fragment more than the
    culled sphere has: the pixel is printed and the reason said. S4: along a row the walk
    makes 9% more tests, printed. S5: no forward reference to lesson 11. S6: the renderer's
    missing clear depth is in the fold. S8: the walk's tiles are 2×2 groups of blocks."""
    ns, printed, shown = _lesson_10_run()
    cells, text, md, code = _lesson_10_sources()
    # P2: asked before the figure, from the definitions; the figure and the table held
    asked = next(i for i, t in enumerate(text) if "q_trav = PredictPixels(" in t)
    assert text[asked - 1].startswith("## 5. Traversal orders")
    assert "Predict one of them before the figure" in text[asked - 1]
    assert "plot_traversal(" in text[asked + 1] and text[asked + 2].startswith("q_trav.hold()")
    assert "answer=serp_entries," in text[asked]  # r468 P1: clicked on the grid
    assert ns.serp == ns.tile_changes["serpentine"] == 9 and ns.trav_moves["scanline"] == 15
    assert "{serp} cells = 8 + 1" in text[asked]
    # FIG1: the block's colours span its own values
    assert abs(ns.block_norm.vmax - ns.values.max()) < 1e-9 and ns.block_norm.vmin < ns.values.min()
    assert "same colours" not in "".join(code) and "darker = larger" in "".join(code)
    # S1: every tile column and row numbered
    asked = next(t for t in code if "q_hiz = PredictPixels(" in t)
    assert "cols, rows = range(hw // hiz_q.tile), range(hh // hiz_q.tile)" in asked
    assert "ax.set_xticks(np.add(cols, 0.5), labels=[str(k) for k in cols])" in asked
    assert ns.hw // 8 == 12 and ns.hh // 8 == 8
    # S2
    assert "bold $\\mathbf{v}_k$ is the vertex, italic $v_k$ its screen $y$" in md
    # S3
    f2b = ns.tile_counts["front to back", 8]["shaded"]
    extra = f2b - ns.culled_counts["fragments"]
    assert extra == len(ns.twice) == 1 and ns.tile_counts["back to front", 8]["early_z_killed"] == 1
    assert "front to back, pixels shaded twice: 1, at (row, col) (185, 134)" in printed
    assert f"Front to back shades {f2b:,} fragments, 1 more than the 15,572 of the sphere" in shown
    # S4
    assert "the walk makes 9% more tests than the half-planes" in printed
    assert "41 times fewer tests on the diagonal sliver, 9% more tests along a row" in md
    assert "2.36: 9% more tests than the half-planes (half-plane ÷ tiled = 0.92" in md
    # S5, S6, S8
    assert "as lesson 11 says" not in md
    note = shown.split("**Keeping the farthest depth current.**")[1]
    assert note.index("<details>") < note.index("teachraster's renderer takes no clear depth")
    assert "now the moves into another 2×2 group of blocks (an 8×8-pixel tile)" in md
