"""Lesson 10, review r292: C1, C2, F1, P1, M1 and M2 (see the test's docstring)."""

from __future__ import annotations

import numpy as np
from test_lessons_b import _lesson_10_run, _lesson_10_sources


def test_10_r292_items():
    """Review r292, lesson 10. C1: cell 32 said the outside pixels in the box "never reach
    -2^31", against its own 3,245 wrongly-in pixels: the cell now prints how many outside
    centres in the box pass -2^31 (and how many inside pass 2^31, and how far), the text
    quotes those counts, and every wrongly-in pixel lies among them, in the box's corner
    opposite the edge it fails. C2: the traversal path runs "from the star", the marker
    cell 37 draws. F1: Vulkan's 8 sub-pixel bits are Roadmap 2022's. P1: q_trav asks which
    order moves between tiles least, before the table says. M2: q_tile asks how Hi-Z's
    rejections move with the tile size before the table and the explorer, which it holds,
    with the text that states the answer. M1: a folded paragraph on loadOp/storeOp,
    glInvalidateFramebuffer and Direct3D 12's Discard."""
    from teachraster.study import precision

    ns, printed, shown = _lesson_10_run()
    cells, text, md, code = _lesson_10_sources()
    # C1: the magnitudes, printed and quoted; the wrongly-in pixels are past -2^31
    r = ns.regions
    assert "never reach $-2^{31}$" not in "".join(text)
    assert f"outside, in the box: {r.outside_past:,} of {r.outside:,} centres" in printed
    assert f"inside: {r.inside_past:,} of {r.inside:,} have one of 2^31 or more, up to " \
        f"{r.peak:.2f} x 2^31" in printed  # fmt: skip
    for said in (f"{r.outside_past:,} of the box's {r.outside:,} outside centres",
                 f"values reach {r.peak:.2f} × $2^{{31}}$",
                 f"{r.inside_past:,} of the {r.inside:,} covered centres"):  # fmt: skip
        assert said in shown, said
    assert 0.1 * r.outside < r.outside_past < 0.5 * r.outside and r.inside_past > 0.9 * r.inside
    assert 2 < r.peak < 3 and r.wrongly_in > 0
    e = precision.edge_values(ns.big.xy, ns.N, ns.N) * 256.0**2
    jj, ii = np.meshgrid(np.arange(ns.N) + 0.5, np.arange(ns.N) + 0.5)
    lo, hi = ns.big.xy.min(axis=0), ns.big.xy.max(axis=0)
    box = (jj >= lo[0]) & (jj <= hi[0]) & (ii >= lo[1]) & (ii <= hi[1])
    past = (e < -(2.0**31)).any(axis=0) & ~ns.narrow.exact & box
    assert int(past.sum()) == r.outside_past
    assert (ns.false_in & ~past).sum() == 0  # no wrongly-in pixel short of -2^31
    rows, cols = np.nonzero(past)
    # one edge (the long one, v2 to v3) is the one they fail, and they lie in the box's
    # corner opposite it, the bottom right
    assert sum(bool((e[k][past] < -(2.0**31)).any()) for k in range(3)) == 1
    assert rows.min() > 0.45 * ns.N and cols.min() > 0.5 * ns.N
    # C2
    assert "from the star to the square" in md and "filled dot" not in md
    # F1
    assert "Roadmap 2026" not in md and "8 from the Roadmap 2022 milestone on" in md
    # P1 (r300 P2): serpentine's tile moves, asked before the held figure
    asked = next(i for i, t in enumerate(text) if "q_trav = PredictPixels(" in t)
    assert "answer=serp_entries," in text[asked]  # r468 P1: the cells, clicked on the grid
    assert int(ns.serp_entries.sum()) == ns.serp == ns.trav_moves["serpentine"] == 9
    assert "the least four tiles allow" not in md  # said only in the held explanation
    # M2: q_tile before the table and the explorer, both held, and the text after them
    ask = next(i for i, t in enumerate(text) if "q_tile = Predict(" in t)
    assert "hiz_explorer = HiZTileExplorer(" in text[ask - 1] and "print(" not in text[ask]
    for k in (ask + 1, ask + 2):
        assert text[k].startswith("q_tile.hold()"), k
    assert "stored depths" in text[ask + 1] and "**Smaller tiles reject more**" in text[ask + 2]
    assert ns.q_tile_answer == ns.tile_counts["front to back", 16]["hiz_rejected"]  # r305 P1
    assert ns.f2b == [ns.tile_counts["front to back", t]["hiz_rejected"] for t in (4, 8, 16)]
    # M1: one folded paragraph, in §9
    nine = md.split("## 9.")[1]
    fold = nine.split("telling a tiler what it need not load or store")[1].split("</details>")[0]
    for said in ("`loadOp`", "`storeOp`", "`VK_ATTACHMENT_LOAD_OP_CLEAR`",
                 "`VK_ATTACHMENT_LOAD_OP_DONT_CARE`", "`VK_ATTACHMENT_STORE_OP_DONT_CARE`",
                 "`glInvalidateFramebuffer`", "`D3D12_RENDER_PASS_ENDING_ACCESS_TYPE_DISCARD`",
                 "The depth buffer is the usual case"):  # fmt: skip
        assert said in fold, said
