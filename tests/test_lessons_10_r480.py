"""Lesson 10, review r480: S1, S2 and S3 (see the test's docstring)."""

from __future__ import annotations

from test_lessons_b import _lesson_10_run, _lesson_10_sources


def test_10_r480_items():
    """Review r480, lesson 10. S1 (density): §6's 264-word paragraph of widget instructions
    is a list, one item per control, with every rule it gave; cells 9 and 37 are two
    paragraphs each; HyperZ's compression and fast clear are folded. S2: "at most half its box's area, so ... about half outside" gave "half
    or more" (§3's large one: 50 %). S3: the summary said hidden work "disappears" front to
    back, where the sorted sphere still shades one pixel twice (sorted by triangle, not by
    pixel)."""
    ns, printed, shown = _lesson_10_run()
    cells, text, md, code = _lesson_10_sources()
    # S1: the controls as a list, every rule kept, and far fewer words than 264
    play = next(t for t in text if t.startswith("## 6. Play"))
    items = [line for line in play.splitlines() if line.startswith("- **")]
    assert [line.split("**")[1] for line in items] == ["level", "block", "traversal",
                                                       "block sizes"]  # fmt: skip
    flat = " ".join(play.split())
    for rule in ("*show level*", "moving it puts **block** back to 0", "(the caption says so)",
                 "depth first", "at the 1×1 level the solid pixels are the pixel tests",
                 "more levels shift the balance back", "**16 / 4 / 1**, the one it opens with"):  # fmt: skip
        assert rule in flat, rule
    assert len(flat.split()) < 200
    # the lesson's Markdown: 6,806 words at r480's read, 6,740 after; no growth past it
    words = sum(len(t.split()) for t, c in zip(text, cells) if c["cell_type"] == "markdown")
    assert words <= 6740, words
    for start in ("In the zoomed panel, then,", "Beside them the cell prints"):
        cell = next(t for t in text if start in t)
        assert f"\n\n{start}" in cell
    # S2: half or more of a large triangle's box lies outside it; §3's large one is 50 %
    assert "so for a large triangle half or more of those centres lie outside it" in md
    assert "about half of those centres" not in md
    assert 0.5 <= round(ns.box_outside, 2) and f"§3 counts {ns.box_outside:.0%}" in md
    # S3: front to back leaves hidden work (one pixel shaded twice, printed); the summary
    # says "nearly"
    summary = md.split("## Summary")[1]
    assert (
        "Hidden work nearly disappears when scenes are drawn front to back (sorted by "
        "triangle, not by pixel), or after a depth pre-pass." in summary
    )
    assert len(ns.twice) == 1 and "front to back, pixels shaded twice: 1," in printed
    # S1: HyperZ's compression and fast clear, reading matter, folded under "Why 8×8"
    why = next(t for t in text if t.startswith("**Why 8×8, and what else"))
    fold = why.split("<details>")[1].split("</details>")[0]
    assert "Persson's *Depth In-depth*" in fold and "**Fast clear**" in fold
    assert "**Compression**" in fold and "**The whole pyramid" not in fold
