"""Lesson 06, review r500: each test fails on the lesson before the fix.

P1: q_quake steered: its stem carried lesson 04's cue ("misses by more the more w changes
between them") and each choice its reading ("most pixels close, a few far off"). It asks the
magnitudes bare now; lesson 04's reasoning stays in its explanation.
S1-S5 (density): cell 4 (313 words), EDGE_TEXT (281), FRONT_TEXT (271), the Summary (391) and
QUAKE_TEXT's "Texels or pixels" paragraph (a second telling of q_quake's explanation) are cut;
word budgets hold them at or below the length left.
"""

from __future__ import annotations

import json

from notebook_runs import ROOT, lesson

NAME = "06_what_accuracy_costs"

# words as the cells' sources or the held texts read (budgets at the length r500 left)
BUDGETS = {"markdown": 2900, "prices": 240, "summary": 285, "EDGE_TEXT": 200,
           "FRONT_TEXT": 245, "QUAKE_TEXT": 310}  # fmt: skip


def _cells() -> list[tuple[str, str]]:
    nb = json.loads((ROOT / "notebooks" / f"{NAME}.ipynb").read_text())
    return [(c["cell_type"], "".join(c["source"])) for c in nb["cells"]]


def _words(text: str) -> int:
    return len(text.split())


def test_p1_q_quake_asks_bare_magnitudes_before_any_hint():
    ns = lesson(NAME)
    (quake,) = [s for _, s in _cells() if "q_quake = Predict(" in s]
    stem = quake[quake.index("q_quake = Predict(") : quake.index("explain=")]
    assert "lesson 04" not in stem and "misses by more" not in stem
    assert all(":" not in c for c in ns.quake_choices)  # no reading after the magnitudes
    n16 = ns.subdivided[16]
    assert n16["mean_abs_texels"] < 1 and n16["error"] > 10  # the answer, as printed
    assert ns.quake_answer == "mean under 1 texel, worst over 10 texels"
    # lesson 04's reasoning comes after the answer, in the explanation
    assert "Lesson 04 (section 1) found that an affine guess" in quake.split("explain=")[1]


def test_s1_to_s5_word_budgets():
    ns = lesson(NAME)
    cells = _cells()
    md = [s for k, s in cells if k == "markdown"]
    summary = next(s for s in md if s.startswith("## Summary")).split("**Try it:**")[0]
    counts = {
        "markdown": sum(_words(s) for s in md),
        "prices": _words(next(s for s in md if s.startswith("**Price lists**"))),
        "summary": _words(summary),
        **{name: _words(getattr(ns, name)) for name in ("EDGE_TEXT", "FRONT_TEXT", "QUAKE_TEXT")},
    }
    over = {k: (v, BUDGETS[k]) for k, v in counts.items() if v > BUDGETS[k]}
    assert not over, counts
    assert "**Texels or pixels.**" not in ns.QUAKE_TEXT
