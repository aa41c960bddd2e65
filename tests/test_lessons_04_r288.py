"""Lesson 04, review r288: each test fails on the lesson before the fix.

P1: q_worst (click the pixel of largest |Δu|) was answered by the FillPlayer comparison that
section 4 told the student to open; the player now follows the question, held by it. FIG1:
the two edge curves v1 → v2 and v2 → v3 coincide, and the cell and the figure say so. S1:
which "largest" is over the pixel centres and which over the whole triangle. M1: an
orthographic camera leaves every w at 1, where affine is exact, printed. M2: one pixel's two
plane values and its divide, printed. S2, S3, S4: the words.
"""

from __future__ import annotations

import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK = ROOT / "notebooks" / "04_perspective_correct_interpolation.ipynb"


def _cells() -> dict:
    return {c["id"]: "".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"]}


def _flat(text: str) -> str:
    return " ".join(text.split())


def _section_5(capsys, w_text=None) -> tuple[dict, str]:
    """Sections 2 to 5 run again (the widgets left out), with ``w`` from the Try-it if
    given; their namespace and what they printed."""
    cells = _cells()
    made = cells["c04-surfaces"].split("surfaces = ")[0]
    if w_text:
        made = made.replace("w = np.array([1.0, 2.0, 4.0])", f"w = np.array({w_text})")
    ns: dict = {"display": lambda *a, **k: None}
    capsys.readouterr()
    for cid in "c01 c05 c07 c09 c12 q-worst ab224988 c12-held-errors c12-player".split():
        source = made if cid == "c05" else ""
        source += cells[cid].replace("%matplotlib inline", "").replace("plt.show()", "")
        source = source.split("player = FillPlayer(")[0]  # the widget left out
        exec(source, ns)
    return ns, capsys.readouterr().out


@pytest.mark.notebook
def test_p1_the_player_follows_the_question_it_would_answer():
    cells = _cells()
    ids = list(cells)
    player = next(k for k, t in cells.items() if "FillPlayer(" in t and "import" not in t)
    assert player == "c12-player" and ids.index(player) > ids.index("q-worst")
    assert cells[player].startswith("q_worst.hold()")
    # nothing before the question points at the comparison's error map
    before = " ".join(cells[k] for k in ids[: ids.index("q-worst")])
    assert "FillPlayer(tri" not in before and "its comparison shows" not in before
    # r297 S1, C1: the player is in section 5, not at its end (section 5 goes on after it),
    # and q_affine's explanation sends the student there, not to section 4; S2: the widget's
    # own line asks for one pixel, as the question does
    assert "The player in section 5, after its question, has the same toggle" in _flat(cells["c08"])
    affine = next(t for t in cells.values() if "q_affine = " in t)
    assert "comparison in section 5" in affine and "section 4" not in affine
    # r342 P1: the question asks for the one pixel of largest |Δu|, one click
    assert "Click the pixel whose centre has" in cells["q-worst"] and "one=True" in cells["q-worst"]
    assert "its comparison shows both interpolations" in _flat(cells["c12-player-text"])
    # r312 S3: the player's edge names tied once to the text's
    assert "edge $\\mathbf{v}_1\\mathbf{v}_2$ is its E12" in _flat(cells["c12-player-text"])


@pytest.mark.notebook
@pytest.mark.parametrize("w_text", [None, "[1.0, 1.0, 8.0]"])
def test_fig1_m1_m2_s1_printed(capsys, w_text):
    ns, out = _section_5(capsys, w_text)
    try:
        curves = ns["axd"]["edges"]
        labels = [ln.get_label() for ln in curves.get_lines() if not ln.get_label().startswith("_")]
        if w_text is None:
            # FIG1: both edges have w ratio 2 and a change of 1 in u: one curve
            assert ns["same_curve"] == [("v1v2", "v2v3")]
            assert np.abs(ns["edge_gap"]["v1v2"] - ns["edge_gap"]["v2v3"]).max() < 1e-12
            assert "v1v2 and v2v3: one curve (w ratio 2 and 2, u change 1 and 1)" in out
            assert labels == ["v1 → v2 = v2 → v3"]
            # S1: the pixel centres' largest, labelled so
            assert "78 covered pixels; the largest errors over their centres:" in out
            # r335 P1: the affine lines answer q_worst, so they are printed after it
            assert "the affine u over the 78 covered pixel centres, largest errors:" in out
            assert "  vs section 2's 3D truth:               0.163" in out
            assert "  vs section 3's Σ α_i u_i:              0.163" in out
            assert "  vs section 4's perspective-correct u:  0.163" in out
            assert "the 3-D view's largest gap, over the whole triangle: 0.172, on an edge" in out
            # M2: the ringed pixel's two plane values and its one divide
            assert "pixel (row 4, col 10): λ = 0.318, 0.678, 0.004" in out
            assert "  Σλu/w = 0.3392, Σλ/w = 0.6580: one divide, u = 0.516" in out
            assert "  the fill's u there 0.516; affine Σλu = 0.678, |Δu| = 0.163" in out
        else:
            assert ns["same_curve"] == [] and "one curve" not in out
            assert labels == ["v1 → v2", "v2 → v3"]
        # M1: an orthographic camera leaves w at 1; affine is then exact at every centre
        assert np.allclose(ns["ortho_clip"][3], 1.0)
        assert np.count_nonzero(~np.isnan(ns["seen"][0])) > 20 and ns["ortho_gap"] < 1e-12
        assert "orthographic camera: the vertices' clip w = [1.0, 1.0, 1.0]" in out
        assert "  largest |affine - perspective| at its pixel centres = 0.0e+00" in out
        worst = ns["worst"]
        assert np.isclose(ns["u_over_w"] / ns["one_over_w"], ns["persp"].attrs["u"][worst])
    finally:
        plt.close("all")


def test_s1_s2_s3_s4_words():
    cells = _cells()
    assert "largest gap over the whole triangle, every point of it" in _flat(
        cells["c04-surfaces-text"]
    )
    check = _flat(cells["c04-check-text"])
    # r335 P1: the affine errors at the centres (and that they are below the view's gap)
    # wait for q_worst; the held cell says what they are over
    assert "wait for section 5's question" in check and "smaller" not in check
    # r349 S1: the numbers are in the third held cell after q_worst, not the next one
    assert "the third held cell after that question prints them" in check
    assert (
        "over the\n# covered pixel centres only, not over the whole triangle"
        in cells["c12-held-errors"]
    )
    assert "deviation from linear in q: 1/z up to" in cells["c03"]
    assert "z linear in q:" not in cells["c03"]
    spans = _flat(cells["c12-spans-text"])
    assert "no divide at all" not in spans and "with no per-pixel divide" in spans
    assert "q_diagonal's answer" not in cells["c20"]
    assert "answered the drag" not in cells["85fc0147"]
    m1 = _flat(cells["c08"])
    # r312 S3: no benchmark-module import in a student's cell; S5: the long cells split
    assert "import span_divides" in cells["c01"] and "import" not in cells["c12-spans"]
    assert "ruler" not in cells["85fc0147"]
    ids = list(cells)
    assert ids[ids.index("c04-rule") : ids.index("c04-apis")] == [
        "c04-rule", "c04-history", "c04-divide", "c04"
    ]  # fmt: skip
    far = ["c15-far", "c15", "c15-horizon", "c15-aliasing"]
    assert ids[ids.index("c15-far") : ids.index("c15-far") + 4] == far
    for cid in ("c04-rule", "c04-history", "c04-divide", "c04", *far):
        assert len(cells[cid].split()) < 400, cid
    assert "leaves every vertex's $w$ at 1, so there affine interpolation is exact" in m1


def test_r342_m2_s2_s3_s4_words():
    """r342: M2, clipping's new vertices get perspective-correct attributes (clip space); S2,
    the Try-it names where FW, FH are set; S3, the floor's text no longer repeats q_diagonal's
    answer; S4, the far figure's blue sky is painted on it, not rendered."""
    cells = _cells()
    clip = _flat(cells["c04"])
    assert "OpenGL 4.6 §13.7.1 *Clipping Shader Outputs*" in clip
    assert "with the same $t$ as its position. It does so in clip space, before the divide" in clip
    assert "set `FW, FH = 64, 48` in the folded cell that prints the floor's vertex $w$" in _flat(
        cells["c20"]
    )
    assert "FW, FH = 320, 240" in cells["c14"] and "vertex w from" in cells["c14"]
    floor = _flat(cells["floor_md"])
    assert "moves the lookup" not in floor and "for the reason the answer above gives" in floor
    assert "lookup √2 times as far" in cells["q-diagonal"]  # the answer keeps it
    assert "is painted on the figure, not rendered" in _flat(cells["c15-horizon"])


def test_r349_s4_the_two_sides_added_get_their_note():
    """r349 S4: 53.4 (the two sides' errors added) got no note in q_diagonal; it now says why
    the errors add like the sides of a square."""
    import re

    text = json.loads(
        (
            Path(__file__).resolve().parents[1]
            / "notebooks"
            / "04_perspective_correct_interpolation.ipynb"
        ).read_text()
    )["cells"]
    q = next("".join(c["source"]) for c in text if "q_diagonal = Predict(" in "".join(c["source"]))
    assert re.search(r"round\(2 \* side, 1\): \"That is the two sides' errors added", q)
