"""Lesson 10, review r281: C1, M1, M3, FIG1 and FIG2 (see the first test's docstring)."""

from __future__ import annotations

import pytest
from test_lessons_b import _lesson_10_run, _lesson_10_sources


def test_10_r281_items():
    """Review r281, lesson 10. C1: cell 0's "at least half of those centres lie outside" was
    false for §3's small triangles (3 of 4 covered with 2-px legs): it now says "about half"
    for a large triangle, which §3's large one measures (50 %), and names the tiny case. M1: §4
    folds a table of each standard's sub-pixel bits with its sections and int32's range,
    each range printed. M3: §5 asks q_trav (which order moves between tiles least, r292)
    and holds the table that answers it; §7's sphere is played in a HiZTileExplorer (order ×
    tile size) whose replays give the printed table. FIG1: the walk's first block is a
    ringed star, not a dot like the vertices; FIG2: the block's values take the left panel's
    colours. S6: no internal import in the cells after the first."""
    from teachraster.plotting import plot_walk_path

    ns, printed, shown = _lesson_10_run()
    cells, text, md, code = _lesson_10_sources()
    # C1
    assert "At least half of those centres" not in md
    share = f"{ns.box_outside:.0%}"
    assert 0.45 < ns.box_outside < 0.55 and f"§3 counts {share} for its large one" in md
    total = ns.half_tests
    outside = total - int(ns.big_share * 512 * 512)
    assert f"the box's centres outside the triangle: {outside:,} of {total:,} ({share})" in printed
    assert ns.covers[2] == 3 and "3 of the 4 with §3's 2-px legs" in md
    # M1: the ranges the table quotes, printed
    from teachraster.core import fixed_point

    table = next(t for t in text if "**The sub-pixel bits each standard sets**" in t)
    assert table.index("<details>") < table.index("| OpenGL 4.6 |") < table.index("</details>")
    reach = {(b, c): fixed_point.max_range(b, 32, centre_bit=c) for b in (4, 8) for c in (0, 1)}
    assert (reach[4, 0], reach[8, 0], reach[8, 1]) == (2048, 128, 64)
    for said in ("2,048 px at 4 bits, 128 px at 8", "§15.16 *Rasterizer Precision*",
                 "§3.4.1 *Coordinate Snapping*", "`subPixelPrecisionBits`", "`SUBPIXEL_BITS`",
                 "8: `FIXED_ORDER`", "| 64 px;"):  # fmt: skip
        assert said in table, said
    for line in ("GL, Vulkan at their minimum: 4 bits, int32 for differences below 2,048 px",
                 "D3D11, llvmpipe, GL and Vulkan at 8: 8 bits, int32 for differences below 128 px",
                 "teachraster's grid (the centre bit): 8 bits, int32 for differences below 64 px",
                 "llvmpipe's FIXED_ORDER: 8 sub-pixel bits"):  # fmt: skip
        assert line in printed, line
    # M3: q_trav, its figure and table held (r300 P2: asked before the figure numbers the
    # visits, serpentine's count)
    asked = next(i for i, t in enumerate(text) if "q_trav = PredictPixels(" in t)
    assert "plot_traversal(" in text[asked + 1] and text[asked + 1].startswith("q_trav.hold()")
    assert text[asked + 2].startswith("q_trav.hold()") and "plot_traversal(" not in text[asked]
    assert "answer=serp_entries," in text[asked] and ns.least == ("tiled", "morton")
    assert ns.trav_moves["scanline"] == ns.tile_changes["scanline"] == 15
    assert ns.trav_moves == ns.tile_changes and (ns.trav_moves["serpentine"], ns.trav_moves[
        "tiled"], ns.trav_moves["morton"]) == (9, 3, 3)  # fmt: skip
    assert f"{'scanline':12s}{ns.jumps['scanline']:6d}{15:12d}" in printed
    from teachraster.widgets import HiZTileExplorer

    shown_at = next(t for t in code if t.rstrip().endswith("\nhiz_explorer"))
    assert "HiZTileExplorer(" not in shown_at  # built with the table, shown after it
    built = next(t for t in code if "hiz_explorer = HiZTileExplorer(" in t)
    assert 'order="front to back", tile=8' in built and "tile_counts = {" in built
    hiz = HiZTileExplorer(ns.sphere_frames, ns.TILE_SIZES, order="front to back", tile=8,
                          backend="image")  # fmt: skip
    try:
        assert {k: r.counts for k, r in hiz.replays.items()} == ns.tile_counts
        assert hiz.counts == ns.tile_counts["front to back", 8]
        hiz.order.value, hiz.tile.value = "back to front", 16
        assert hiz.counts["hiz_rejected"] == 0 and "300 stored depths" in hiz.info.value
        assert hiz.display.draws == 3  # one picture a change
    finally:
        hiz.close()
    assert not any("replay_tiles" in t or "from teachraster.pipeline" in t for t in code[1:])
    assert "run it again" not in md
    # FIG1 and FIG2
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    start = plot_walk_path(ax, ns.fill, "scanline", level=1).start
    assert start.get_marker() == "*" and start.get_markerfacecolor() != "black"
    plt.close(fig)
    corner_fig = next(t for t in code if "plot_block_values(" in t)
    # r300 FIG1: on the left panel's colours the block was one flat blue: its own range now
    assert 'cmap="Blues", norm=block_norm' in corner_fig


@pytest.mark.gl
def test_10_r281_llvmpipe_reports_8_subpixel_bits():
    """Lesson 10's sub-pixel table: a GL context on llvmpipe reports GL_SUBPIXEL_BITS = 8."""
    from teachraster.study.opengl import gl_available, gl_context

    ok, renderer = gl_available()
    if not ok or "llvmpipe" not in renderer:
        pytest.skip(f"no llvmpipe GL context here: {renderer}")
    assert gl_context()[0].info["GL_SUBPIXEL_BITS"] == 8
