"""Lesson 10, review r305: FIG1, P1, S1, S2 and S3 (see the test's docstring)."""

from __future__ import annotations

from test_lessons_b import _lesson_10_run, _lesson_10_sources


def test_10_r305_items():
    """Review r305, lesson 10. FIG1: §1's right-hand title ran into the left panel's tick
    label "56": it now lies clear of the left panel's labels. P1: q_tile was a three-way
    choice that cell 48's "trade-off" pointed to: it asks the 16×16 count given 8×8's two
    counts, a whole number, printed only by the held table, and cell 48 no longer weighs
    the gain against the memory. S1: the Vulkan row quotes the early-fragment-tests sentence;
    the sample-counting "should" is a note under the table. S2: "in 1 quad". S3: the tile
    moves' header says "(at least 3: four tiles)"."""
    ns, printed, shown = _lesson_10_run()
    cells, text, md, code = _lesson_10_sources()
    # FIG1: drawn again, the right title's box meets neither the left Axes nor its labels
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = ns.ax_blk.figure
    renderer = FigureCanvasAgg(fig).get_renderer()  # the pickled run's figure has no canvas
    fig.draw(renderer)
    title = ns.ax_blk.title.get_window_extent(renderer)
    assert not title.overlaps(ns.ax_img.get_tightbbox(renderer))
    # P1: a number, asked from 8×8's counts; the answer printed only after the question
    at8, at16 = (ns.tile_counts["front to back", t] for t in (8, 16))
    ask = next(i for i, t in enumerate(text) if "q_tile = Predict(" in t)
    assert "whole=True," in text[ask] and "choices=" not in text[ask]
    assert "answer=q_tile_answer," in text[ask]
    assert ns.q_tile_answer == at16["hiz_rejected"] < at8["hiz_rejected"]
    # the rim-doubling estimate counts as right, "the same count" does not (the widget is not
    # kept by the run: its tolerance is read from the source)
    tolerance = float(text[ask].split("tolerance=")[1].split(",")[0])
    assert abs(ns.doubled_rim - ns.q_tile_answer) <= tolerance
    assert abs(at8["hiz_rejected"] - ns.q_tile_answer) > tolerance
    answer = f"{at16['hiz_rejected']:,}"
    before = "".join(text[:ask])
    assert answer not in before and answer not in printed.split("stored depths  Hi-Z rejected")[0]
    assert f"{ns.tile_counts['front to back', 16]['hiz_rejected']:15,}" in printed
    assert "trade-off" not in md and "what it costs is memory" not in md
    # S1: the Vulkan row's last column quotes Early Fragment Tests
    table = next(t for t in text if t.startswith("**Early-z in each standard**"))
    vulkan = next(r for r in table.splitlines() if r.startswith("| Vulkan |")).split("|")[4]
    assert (
        '"If the fragment shader specifies the EarlyFragmentTests OpExecutionMode, the '
        "per-fragment tests described in Early Fragment Test Mode are performed prior to "
        'fragment shader execution" (Vulkan 1.2, *Early Fragment Tests*)'
    ) in vulkan
    assert "sample counting" not in vulkan and '"should instead be performed after' in md
    # S2, S3
    assert "shaded in  1 quad: 75% helpers" in printed and " 1 quads" not in printed
    assert "(at least 3: four tiles)" in printed and "of 3 at least" not in printed
