"""Lesson 06, review r460: each test fails on the lesson before the fix.

C1: cell 9 argued that the miss in u (texels) grows like N², above a chart whose texel mean
falls only 2.89x from N = 32 to 16; the N² law holds on screen. The text now argues on screen,
prints the texel cuts and says why they fall below 4 (far pieces' ρ is far from 1).
C2: "a little more often than 1/N" above a printed +29 % at N = 32.
"""

from __future__ import annotations

from notebook_runs import executed, lesson, streams

NAME = "06_what_accuracy_costs"


def test_c1_the_square_law_is_said_on_screen_and_the_texel_cuts_printed():
    ns = lesson(NAME)
    text = " ".join(ns.QUAKE_TEXT.split())
    # the texel mean's cut when N halves: near 4 at small N, under 3 from 32 to 16
    assert ns.tex_cut[0] > 4 and ns.tex_cut[-1] < 3
    assert all(a > b for a, b in zip(ns.tex_cut, ns.tex_cut[1:]))
    assert "on screen the miss grows like $N^2$, the slope-2 guide" in text
    assert "and the change both grow like the piece's length: the miss grows like" not in text
    lo, hi = min(ns.tex_cut), max(ns.tex_cut)
    assert f"halving $N$ divides it by {lo:.2f} to {hi:.2f} (the lines" in text
    assert f"{ns.tex_cut[-1]:.2f} from 32 to 16" in text
    # the share quoted at the floor's steepest piece, against its near-1 approximation
    assert f"it is {ns.share_q:.2f}, not {(ns.ratio_q - 1) / 4:.2f}" in text
    assert ns.share_q < 0.6 * (ns.ratio_q - 1) / 4
    # every quoted cut is printed (cell 8)
    printed = streams(executed(NAME).notebook())
    line = "halving N cuts the mean in texels:\n  " + ", ".join(
        f"{b} -> {a} {c:.2f}x" for a, b, c in zip(ns.ns_, ns.ns_[1:], ns.tex_cut)
    )
    assert line in printed


def test_c2_the_extra_divides_are_quoted_as_printed():
    ns = lesson(NAME)
    said = " ".join(ns.PRICE_TEXT.split())
    assert "a little more often" not in said
    assert f"{ns.extra_divides[32]:+.0%} at $N = 32$" in said and ns.extra_divides[32] > 0.2
    printed = streams(executed(NAME).notebook())
    assert f"32: '{ns.extra_divides[32]:+.0%}'" in printed
