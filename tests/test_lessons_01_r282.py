"""Lesson 01, review r282: each test fails on the lesson before the fix.

C1: the package's span fill gets its ends by an integer floor division, not "no divider at
all"; P1: q_row asks rows the rule stated before it decides; FIG1: no vertex label over an
asked row; M1: rows and spans clipped to the image, said and tried; S3/S5: folds, and no
package walk to excuse.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from notebook_runs import lesson  # noqa: E402

import teachraster as tr  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK = ROOT / "notebooks" / "01_span_tables.ipynb"


def _cells() -> list[dict]:
    return json.loads(NOTEBOOK.read_text())["cells"]


def _source(cell_id: str) -> str:
    return " ".join("".join(next(c for c in _cells() if c.get("id") == cell_id)["source"]).split())


def test_c1_the_package_divides_hardware_does_not():
    """Cell 18 said the package decides coverage "with edge functions ... no divider at all";
    its span fill takes one integer floor division per edge and row (lesson 06 §4 says so)."""
    why = _source("5997d157")
    shown = re.sub(r"<details>.*?</details>", "", why)
    assert "The package, like hardware, decides coverage" not in why
    assert "one **integer floor division**" in shown
    # r344 S3: the package's internals (`edge_bounds` in `core/span_tables.py`) left out
    assert "`edge_bounds`" not in shown
    assert "Hardware uses edge functions instead (lesson 02): no divider" in shown
    code = (ROOT / "teachraster" / "core" / "span_tables.py").read_text()
    assert "def edge_bounds(" in code and "q = (K - bias) // np.abs(safe)" in code
    lesson06 = json.loads((ROOT / "notebooks" / "06_what_accuracy_costs.ipynb").read_text())
    told06 = " ".join(" ".join("".join(c["source"]) for c in lesson06["cells"]).split())
    assert "an integer multiply and divide per crossing" in told06


def test_s3_the_multiply_first_proof_is_folded():
    why = _source("5997d157")
    assert why.count("<details>") == 1 and "optional" in why.split("</summary>")[0]
    fold = why.split("<details>")[1].split("</details>")[0]
    for reason in ("**The product is exact.**", "**Off a tie, no rounding reaches a centre.**"):
        assert reason in fold


@pytest.mark.notebook
def test_p1_q_row_asks_rows_the_stated_rule_decides():
    """Rows 1 and 17 (a one-point span, the bottom vertex's row) needed the half-open rule,
    held until Check. Rows 5 (mirrored) and 9 have two distinct ends each, on a left and a
    right edge: the rule as section 4 states it decides every centre."""
    ns = lesson("01_span_tables")
    for i in ns.q_rows:
        left, right = ns.row_ends[i]
        assert left < right and ns.v_top < i + 0.5 < ns.v_bot
    # the mirror image of the worked row's pixels is not the answer: the tie moves
    mirror_image = sorted(ns.W - 1 - j for j in ns.worked_5)
    assert mirror_image != ns.cols_5.tolist()
    ask = _source("ece0fd62").split("q_row = PredictPixels(")[1].split("answer=")[0]
    assert "the two shaded rows" in ask and "through the top" not in ask
    rule = _source("c08b")
    assert rule.startswith("q_row.hold()") and "So the mirrored triangle's row" in rule
    assert "is a span of one point" in ns.RULE_TEXT and "is not visited: 0 pixels" in " ".join(
        ns.RULE_TEXT.split()
    )


@pytest.mark.notebook
def test_fig1_no_vertex_label_covers_an_asked_row():
    """v1's white box lay over row 17's cells 10-12, which the question asked to click."""
    from teachraster.plotting import plot_triangle
    from teachraster.plotting.style import COLORS
    from teachraster.widgets.predict_figure import grid_axes

    ns = lesson("01_span_tables")
    source = "".join(next(c for c in _cells() if c.get("id") == "ece0fd62")["source"])
    body = source[source.index("def asked_row_figure(") : source.index("r_top, r_mid, r_bot")]
    scope = {"plot_triangle": plot_triangle, "COLORS": COLORS, "mirror_fill": ns.mirror_fill,
             "q_rows": ns.q_rows}  # fmt: skip
    exec(body, scope)
    fig = plt.figure()
    try:
        ax = grid_axes(fig, 20, 20, 5.6)
        ax.set(xlim=(0, 20), ylim=(20, 0))
        scope["asked_row_figure"](ax)
        fig.canvas.draw()
        for label in (t for t in ax.texts if t.get_text() in ("v1", "v2", "v3")):
            box = label.get_window_extent().transformed(ax.transData.inverted())
            top, bottom = sorted([box.y0, box.y1])
            for i in ns.q_rows:
                assert bottom <= i + 0.02 or top >= i + 1 - 0.02, (label.get_text(), i)
    finally:
        plt.close(fig)


@pytest.mark.notebook
def test_m1_clipping_is_said_and_the_try_it_holds():
    ns = lesson("01_span_tables")
    assert "Rows and spans are **clipped to the image**" in " ".join(ns.TABLE_TEXT.split())
    assert "gets each span end exactly, by an integer division" in " ".join(ns.TABLE_TEXT.split())
    try_it = _source("c17-try")
    assert "off[2] = [2.5, -6.5]" in try_it
    # the Try-it, done: v3 above the image; the loops start at row 0 and match the package
    cells = _cells()
    scope: dict = {"np": np, "tr": tr, "math": __import__("math")}
    for cid in ("c09", "a52d84d7"):
        code = "".join(next(c for c in cells if c.get("id") == cid)["source"])
        code = code.split("\n\n\ncover, ends =")[0].split("\n\n\nstepped, stepped_ends")[0]
        exec(code.replace("q_row.hold()", ""), scope)
    off = np.array([[8.5, 17.5], [18.5, 9.5], [2.5, -6.5]])  # every edge du/dv dyadic
    ref = tr.rasterize(tr.Triangle(off), 20, 20, method="span").coverage
    cover, ends = scope["span_fill"](off, 20, 20)
    stepped, _ = scope["span_fill_stepped"](off, 20, 20)
    assert min(ends) == 0 and ref[0].any()
    assert np.array_equal(cover, ref) and np.array_equal(stepped, ref)


def test_s3_s5_reading_load():
    c02, c14 = _source("c02"), _source("c14")
    assert "<details>" not in c02 and "arrowhead" not in c02
    assert c14.count("<details>") == 1
    shown = re.sub(r"<details>.*?</details>", "", c14)
    assert len(shown.split()) < 110 and "- **snap**" not in shown


def test_r344_s4_the_prose_shrank():
    """Review r344 S4 (r303 S2): 5,583 Markdown words, cells of 469 (Summary), 460 (4b's
    reading), 450 (the integer DDA) and 399 (the crack explorer's guide). Cut, not grown."""
    nb = json.loads((ROOT / "notebooks" / "01_span_tables.ipynb").read_text())
    sizes = [len("".join(c["source"]).split()) for c in nb["cells"] if c["cell_type"] == "markdown"]
    assert sum(sizes) <= 5400 and max(sizes) <= 410, (sum(sizes), max(sizes))
