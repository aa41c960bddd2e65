"""Predictions answered on a figure: the kernel's side (the page's side: test_explorables_js)."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from explorables_node import call_js  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster.plotting import plot_triangle  # noqa: E402
from teachraster.widgets import PredictChoice, PredictOrder, PredictPixels, PredictPoint  # noqa: E402

TRI = tr.Triangle([[1.5, 1.5], [9.5, 3.5], [3.5, 8.5]])


def _pixels():
    return PredictPixels("Click the pixels this triangle covers.",
                         answer=tr.rasterize(TRI, 12, 10).coverage,
                         draw=lambda ax: plot_triangle(ax, TRI, arrows=False),
                         explain="centres inside")  # fmt: skip


def test_pixels_are_judged_and_revealed_only_once_answered():
    q = _pixels()
    truth = np.argwhere(tr.rasterize(TRI, 12, 10).coverage).tolist()
    assert q._reveal["answer"] == truth and q.data["kind"] == "pixels"
    assert q.given is None and q.correct is None
    q.check()  # no answer: nothing revealed
    assert not q.revealed
    q.given = truth[:-1] + [[0, 11]]
    assert q.counts() == {"right": len(truth) - 1, "extra": 1, "missed": 1, "total": len(truth)}
    assert q.correct is False
    q.check()
    assert q.revealed and "1 too many, 1 missed" in q.verdict()
    q.given = truth  # after the reveal: the checked answer is kept (review r28)
    q.state = {**q.state, "given": truth}  # as the page would send it
    assert q.correct is False and "1 too many, 1 missed" in q.verdict() and q.revealed


def test_no_pixel_at_all_is_an_answer_where_the_question_offers_it():
    """Review r183 08-8: lesson 08's sliver question kept Check disabled until a pixel was
    marked, so a student whose honest prediction was "none" (what 1 sample draws) could not
    submit it. ``none=`` offers that choice: an explicit empty answer, judged like any other,
    in the kernel and in the page; without it an empty grid is still no answer."""
    truth = np.argwhere(tr.rasterize(TRI, 12, 10).coverage).tolist()
    plain = _pixels()
    assert "noneLabel" not in plain.data and plain.state["acted"] is False
    plain.given = []  # no choice "none" offered: an empty grid answers nothing
    assert plain.given is None and plain.correct is None
    plain.check()
    assert not plain.revealed
    q = PredictPixels("Which pixels?", answer=tr.rasterize(TRI, 12, 10).coverage,
                      none="<b>none</b>: it draws no pixel", picked="drawn")  # fmt: skip
    assert q.data["noneLabel"] == "<b>none</b>: it draws no pixel"  # HTML, as the question
    assert q.given is None and q.correct is None
    q.check()  # nothing marked, "none" not chosen: no answer, nothing revealed
    assert not q.revealed
    q.given = []  # "none"
    assert q.given == [] and q.state["acted"] is True and q.correct is False
    assert q.counts() == {"right": 0, "extra": 0, "missed": len(truth), "total": len(truth)}
    q.given = [[2, 2]]  # a marked cell answers instead: "none" no longer holds
    assert q.state["acted"] is False and q.given == [[2, 2]]
    q.state = {**q.state, "given": [], "acted": True}  # the page's "none" ticked
    q.check()
    assert q.revealed and q.given == [] and q.state["reveal"]["answer"] == truth
    assert q.verdict().startswith(f"Not quite. You marked 0 pixels: 0 right, 0 too many, "
                                  f"{len(truth)} missed.")  # fmt: skip
    # an empty answer judged right where nothing is lit
    empty = PredictPixels("Which?", answer=np.zeros((3, 4), bool), none="none")
    empty.given = []
    assert empty.correct is True and empty.counts()["total"] == 0
    # the page: "none" ticked is an answer, an empty grid alone is not; judged as the kernel
    got = call_js(("predict_figure",), [("pixelsAnswered", [[], False]),
                                        ("pixelsAnswered", [[], True]),
                                        ("pixelsAnswered", [[[1, 2]], False]),
                                        ("pixelVerdict", [truth, [], 12]),
                                        ("pixelVerdict", [[], [], 4])])  # fmt: skip
    assert got[:3] == [False, True, True]
    assert {k: got[3][k] for k in q.counts()} == q.counts() and got[3]["correct"] is False
    assert got[4]["correct"] is True
    from pathlib import Path

    js = (Path(tr.__file__).parent / "widgets" / "static" / "predict_figure.js").read_text()
    pixels = js.split("function mountPixels")[1].split("function mountPoint")[0]
    assert "checkDisabled(state.revealed, answered())" in pixels
    assert "if (!answered()) return;" in pixels and "acted: Boolean(state.acted)" in pixels


def test_check_is_pressed_once_in_the_page():
    # enabled only while an answer is given and the answer not yet shown
    cases = [(False, False), (False, True), (True, True), (True, False)]
    got = call_js(("predict_figure",), [("checkDisabled", list(c)) for c in cases])
    assert got == [True, False, True, True]
    # review r170 05b-6: the tooltip follows (it said "give your answer first" once enabled)
    from pathlib import Path

    titles = call_js(("predict_figure",), [("checkTitle", list(c)) for c in cases])
    assert titles[0] == "give your answer first" and titles[1] == "check your prediction"
    assert titles[2] == titles[3] == "checked: your prediction is kept"
    js = (Path(tr.__file__).parent / "widgets" / "static" / "predict_figure.js").read_text()
    assert js.count("check.disabled = checkDisabled(") == js.count("check.title = checkTitle(") == 4


def test_a_click_on_the_point_marker_is_no_answer():
    """Review r209 03-5: a click on lesson 03's marker, without moving it, moved it by the
    pointer's offset from its centre, enabled Check and had the start point graded. A press
    released within pointerInput's click distance of where it began keeps the answer it had
    (none: Check stays disabled); a drag gives the dragged point."""
    from pathlib import Path

    before, dragged = [11.9, 11.1], [12.0, 11.0]
    cases = [([100, 100], [102, 101], None), ([100, 100], [100, 100], before),
             ([100, 100], [103.9, 100], None), ([100, 100], [104, 100], None),
             ([100, 100], [130, 90], before)]  # fmt: skip
    got = call_js(("predict_figure",),
                  [("pressAnswer", [down, up, had, dragged]) for down, up, had in cases])  # fmt: skip
    assert got == [None, before, None, dragged, dragged]
    js = (Path(tr.__file__).parent / "widgets" / "static" / "predict_figure.js").read_text()
    point = js[js.index("function mountPoint") : js.index("function mountOrder")]
    assert "pressAnswer(press.at, p, press.before, state.given)" in point
    assert "onPress(p, _e, held)" in point
    base = (Path(tr.__file__).parent / "widgets" / "static" / "explore_base.js").read_text()
    assert "moved < CLICK_PX && onClick" in base  # one click distance for both


def test_the_picture_maps_pixels_where_the_grid_is():
    from PIL import Image

    q = _pixels()
    import base64
    import io

    img = np.asarray(Image.open(io.BytesIO(base64.b64decode(q.data["png"]))).convert("L"))
    assert list(img.shape[::-1]) == q.data["size"]
    x0, y0, sx, sy = q.data["transform"]
    assert sx == pytest.approx(sy) and sx > 20  # pixels are square, y runs down
    # the grid's lines (grey) lie where the transform puts the pixel boundaries
    for col in (2, 5, 8):
        px = round(x0 + sx * col)
        column = img[round(y0 + sy * 0.5) : round(y0 + sy * 9.5), px - 1 : px + 2]
        assert (column < 200).any(axis=1).mean() > 0.9


def test_an_order_questions_picture_has_no_empty_band_round_it():
    """Review r158 (05a): a square image in a taller figure left 110 px of white under the
    sticks; the picture is cut to what is drawn, and the transform still finds the data."""
    import base64
    import io

    from PIL import Image

    from teachraster.widgets.predict_figure import TRIM_MARGIN_PX

    def draw(ax):
        ax.imshow(np.zeros((10, 10)), cmap="gray", extent=(0, 10, 10, 0))
        ax.set(xticks=[], yticks=[], xlim=(0, 10), ylim=(10, 0))

    q = PredictOrder("Order?", ["a", "b"], answer=["a", "b"], draw=draw, figsize=(6.0, 9.0))
    img = np.asarray(Image.open(io.BytesIO(base64.b64decode(q.data["png"]))).convert("L"))
    assert list(img.shape[::-1]) == q.data["size"]
    dark_rows = np.flatnonzero((img < 128).any(axis=1))
    dark_cols = np.flatnonzero((img < 128).any(axis=0))
    h, w = img.shape
    for empty in (dark_rows[0], h - 1 - dark_rows[-1], dark_cols[0], w - 1 - dark_cols[-1]):
        assert empty <= TRIM_MARGIN_PX + 1  # the 9-inch figure held ~300 px of white
    x0, y0, sx, sy = q.data["transform"]
    # the black square fills the data box (0..10): the transform puts its corners there
    assert abs(x0 - dark_cols[0]) <= 2 and abs(x0 + 10 * sx - dark_cols[-1]) <= 2
    assert abs(y0 - dark_rows[0]) <= 2 and abs(y0 + 10 * sy - dark_rows[-1]) <= 2


def test_point_and_order_verdicts():
    p = PredictPoint("Where?", answer=(1.0, 2.0), draw=None, xlim=(0, 4), ylim=(0, 4),
                     along=((0, 0), (4, 4)), tolerance=0.25)  # fmt: skip
    assert p.data["start"] == [2.0, 2.0] and p.correct is None
    p.given = (1.5, 2.0)
    assert p.gap == pytest.approx(0.5) and p.correct is False
    p.check()
    assert p.revealed and "0.5 units" in p.verdict()
    o = PredictOrder("Order?", ["a", "b", "c"], answer=None, allow_impossible=True)
    assert o.correct is None
    o.check()
    assert not o.revealed
    o.given = ["c", "b", "a"]
    assert o.correct is False
    o.given = None  # "no order works"
    assert o.correct is True
    o.check()
    assert o.revealed and "no order works" in o.verdict()


def test_cells_are_named_and_the_keys_step_in_the_axis_units():
    from pathlib import Path

    q = PredictPixels("Tiles?", answer=np.eye(3, dtype=bool), cell="tile", picked="rejected")
    q.given = [[0, 0]]
    assert q.verdict().endswith("You marked 1 tile: 1 right, 0 too many, 2 missed. The answer: "
                                "3 tiles rejected.")  # fmt: skip
    assert "pixel" not in q.verdict() and "lit" not in q.verdict()
    # the page builds its instruction and verdict from the same two words
    js = (Path(tr.__file__).parent / "widgets" / "static" / "predict_figure.js").read_text()
    assert "Click the ${cell}s you expect ${picked}" in js and "you expect lit" not in js
    codes = dict(answer=(188, 0.5), draw=None, xlim=(-0.5, 255.5), ylim=(0, 1), tolerance=4,
                 units="codes")  # fmt: skip
    assert PredictPoint("Code?", **codes).data["keyStep"] == pytest.approx(0.01)  # the default
    p = PredictPoint("Code?", **codes, step=1)
    assert p.data["keyStep"] == 1.0  # one code per arrow key (Shift: ten, in the page)
    assert "data.keyStep * (e.shiftKey ? 10 : 1)" in js
    p.given = (186, 0.5)
    assert (
        p.verdict()
        == "Right. Your marker is 2 codes from the answer (188, 0.5); within 4 codes is right."
    )
    assert "counts" not in js[js.index("function mountPoint") : js.index("function mountOrder")]


def test_a_point_marker_can_read_out_the_code_it_sits_on():
    """Lesson 12b's sRGB code: the marker shows "code 186" while it moves (the page) and the
    verdict repeats it (both sides); without ``readout`` nothing changes."""
    codes = dict(answer=(188, 0.5), draw=None, xlim=(-0.5, 255.5), ylim=(0, 1), tolerance=4,
                 units="codes")  # fmt: skip
    p = PredictPoint("Code?", **codes, step=1, readout="code")
    assert p.data["readout"] == "code" and p.data["readoutDigits"] == 0
    assert p.readout() is None  # nothing to read before the marker moves
    p.given = (186, 0.5)
    assert p.readout() == "code 186"
    assert p.verdict().startswith("Right. You predicted code 186. Your marker is 2 codes")
    fine = PredictPoint("Where?", answer=(1, 2), draw=None, xlim=(0, 4), ylim=(0, 4), step=0.01,
                        readout="x")  # fmt: skip
    fine.given = (1.25, 2)
    assert fine.readout() == "x 1.25"
    plain = PredictPoint("Code?", **codes, step=1)
    plain.given = (186, 0.5)
    assert plain.data["readout"] is None and "predicted" not in plain.verdict()
    # r344 01-S1: "{} triangles" reads "60 triangles", not "triangles 60"
    count = PredictPoint("How many?", **codes, step=1, readout="{} triangles")
    count.given = (60, 0.5)
    assert count.readout() == "60 triangles"
    got = call_js(("predict_figure",), [("readoutText", ["code", 186.0, 0]),
                                        ("readoutText", ["x", 1.25, 2]),
                                        ("readoutText", ["{} triangles", 60.0, 0])])  # fmt: skip
    assert got == [p.readout(), fine.readout(), count.readout()]


@pytest.mark.parametrize(
    ("make", "error", "name"),
    [
        (lambda: PredictPixels("", answer=np.eye(2, dtype=bool)), TypeError, "question"),
        (lambda: PredictPixels("Q?", answer=np.eye(2)), TypeError, "answer"),
        (lambda: PredictPixels("Q?", answer=np.eye(2, dtype=bool), draw="x"), TypeError, "draw"),
        (lambda: PredictPoint("Q?", answer=(1, 2, 3), draw=None, xlim=(0, 1), ylim=(0, 1)),
         ValueError, "answer"),
        (lambda: PredictPoint("Q?", answer=(1, 2), draw=None, xlim=(0, 1), ylim=(0, 1),
                              tolerance=-1), ValueError, "tolerance"),
        (lambda: PredictPoint("Q?", answer=(1, 2), draw=None, xlim=(0, 1), ylim=(0, 1),
                              step=0), ValueError, "step"),
        (lambda: PredictPoint("Q?", answer=(1, 2), draw=None, xlim=(0, 1), ylim=(0, 1),
                              readout=""), TypeError, "readout"),
        (lambda: PredictPixels("Q?", answer=np.eye(2, dtype=bool), cell=""), TypeError, "cell"),
        (lambda: PredictPixels("Q?", answer=np.eye(2, dtype=bool), none=" "), TypeError, "none"),
        (lambda: PredictOrder("Q?", ["a", "a"], answer=None), ValueError, "items"),
        (lambda: PredictOrder("Q?", ["a", "b"], answer=None), ValueError, "allow_impossible"),
        (lambda: PredictOrder("Q?", ["a", "b"], answer=["a", "c"]), ValueError, "answer"),
        (lambda: PredictChoice("Q?", ["a"], answer="a"), ValueError, "choices"),
        (lambda: PredictChoice("Q?", ["a", "a"], answer="a"), ValueError, "choices"),
        (lambda: PredictChoice("Q?", "ab", answer="a"), TypeError, "choices"),
        (lambda: PredictChoice("Q?", ["a", "b"], answer="c"), ValueError, "answer"),
        (lambda: PredictChoice("Q?", ["a", "b"], answer="a", draw=1), TypeError, "draw"),
    ],
)  # fmt: skip
def test_bad_arguments_name_the_argument(make, error, name):
    with pytest.raises(error, match=name):
        make()


def test_the_page_judges_as_the_kernel():
    q = _pixels()
    truth = q._reveal["answer"]
    cases = [truth, truth[:-2], truth + [[0, 0]], [[9, 9]]]
    got = call_js(("predict_figure",), [("pixelVerdict", [truth, g, 12]) for g in cases]
                  + [("pointVerdict", [[1, 2], [1.1, 2.1], 0.25]),
                     ("pointVerdict", [[1, 2], [1.5, 2.0], 0.25]),
                     ("orderVerdict", [None, None]), ("orderVerdict", [["a", "b"], ["b", "a"]]),
                     ("orderVerdict", [["a", "b"], ["a", "b"]])])  # fmt: skip
    for g, js in zip(cases, got[:4], strict=True):
        q.given = g
        c = q.counts()
        assert {k: js[k] for k in c} == c and js["correct"] == q.correct
    p = PredictPoint("Q?", answer=(1, 2), draw=None, xlim=(0, 4), ylim=(0, 4), tolerance=0.25)
    for g, js in zip([(1.1, 2.1), (1.5, 2.0)], got[4:6], strict=True):
        p.given = g
        assert js["correct"] == p.correct and js["gap"] == pytest.approx(p.gap)
    assert [js["correct"] for js in got[6:]] == [True, False, True]
    assert got[7]["places"] == [False, False]


def test_a_marker_on_the_answer_is_0_away_not_float_noise():
    """Review r236 S-6: lesson 07's q_behind marker dropped on (16, 8) read "Your marker is
    1.78e-15 px from the answer": the page and the kernel both call that 0."""
    on = [16 + 1.78e-15, 8.0]
    got = call_js(("predict_figure",), [("pointVerdict", [[16, 8], on, 1.5]),
                                        ("pointVerdict", [[16, 8], [16.5, 8.0], 1.5])])  # fmt: skip
    p = PredictPoint("Q?", answer=(16, 8), draw=None, xlim=(0, 32), ylim=(32, 0), tolerance=1.5)
    p.given = on
    assert got[0]["gap"] == p.gap == 0 and got[0]["correct"] and p.correct
    assert "Your marker is 0 units from the answer" in p.verdict()
    assert got[1]["gap"] == pytest.approx(0.5)


def test_an_order_verdict_names_the_order_given_in_the_page_as_in_the_kernel():
    """Review r167 05a-8: a wrong order's verdict was "Not quite. The answer: no order
    works.", without what the student gave (Predict and PredictChoice say "You predicted ...;
    the answer is ..."). The page's text and the kernel's are the same words."""
    cases = [(None, ["c", "b", "a"]), (None, None), (["a", "b", "c"], None),
             (["a", "b", "c"], ["b", "a", "c"]), (["a", "b", "c"], ["a", "b", "c"])]  # fmt: skip
    got = call_js(("predict_figure",),
                  [("orderVerdictText", [a, g, "no order works"]) for a, g in cases])  # fmt: skip
    for (answer, given), js in zip(cases, got, strict=True):
        q = PredictOrder("Order?", ["a", "b", "c"], answer=answer, allow_impossible=True)
        assert q.verdict() == "The answer: <b>" + js.split("the answer is <b>")[1]
        q.given = given
        word = "Right. " if given == answer else "Not quite. "
        assert q.verdict() == word + js
    assert got[0] == "You predicted <b>c → b → a</b>; the answer is <b>no order works</b>."
    assert got[2] == "You predicted <b>no order works</b>; the answer is <b>a → b → c</b>."


def test_a_choice_is_judged_in_the_page_as_in_the_kernel():
    """Review r98, 07 (q_far): an ipywidgets Predict enabled Check only after the kernel had
    heard of the pick (still disabled 1 s after it); a PredictChoice is judged in the page,
    as the figure kinds are, and says what the kernel says."""
    from pathlib import Path

    choices = ["under a pixel", "tens of pixels", "a < b & c"]
    q = PredictChoice("How far?", choices, answer="tens of pixels", explain="Far.")
    assert q.data["kind"] == "choice" and q.data["choices"] == choices and "png" not in q.data
    assert q.given is None and q.correct is None
    q.check()  # nothing picked: nothing revealed
    assert not q.revealed
    with pytest.raises(ValueError, match="choice"):
        q.given = "thousands"
    verdicts = []
    for pick in choices:
        q.given = pick
        assert q.correct is (pick == "tens of pixels")
        verdicts.append(q.verdict())
    got = call_js(("predict_figure",), [("choiceVerdict", ["tens of pixels", c]) for c in choices])
    for v, js, pick in zip(verdicts, got, choices, strict=True):
        assert v == ("Right. " if js["correct"] else "Not quite. ") + js["text"], (v, js)
        assert js["correct"] is (pick == "tens of pixels")
    assert "a &lt; b &amp; c" in verdicts[2]  # plain text, escaped alike on both sides
    q.given = "under a pixel"
    q.check()
    q.state = {**q.state, "given": "tens of pixels"}  # a later pick: the checked one is kept
    assert q.revealed and q.correct is False and q.given == "under a pixel"
    standin = q._standin()
    assert "How far?" in standin and "a &lt; b &amp; c" in standin and "Not quite." in standin
    # the page enables Check at the pick, in the page, before telling the kernel
    js = (Path(tr.__file__).parent / "widgets" / "static" / "predict_figure.js").read_text()
    pick = js.split("function mountChoice")[1].split("host.setState({ given: value })")[0]
    assert "render_();" in pick and "checkDisabled(state.revealed, state.given !== null)" in js


def test_the_saved_notebook_keeps_the_question_its_picture_and_the_verdict():
    q = _pixels()
    standin = q._standin()
    assert "Click the pixels this triangle covers." in standin
    assert "data:image/png;base64," in standin and "Run All (Run ▸ Run All Cells)" in standin
    q.given = q._reveal["answer"]
    q.check()
    assert "Right." in q._standin()


def test_the_answers_label_is_never_under_the_marker():
    """Review 08-09-r5 (09 cell 14): with the marker near the answer, "the answer" was
    drawn under it ("th⊕ answer"). The label's box (about 104 × 18 px at the 18 px bold font,
    from its baseline up) stays clear of the marker's cross (14 px each way) wherever the
    marker is, and inside the canvas above."""
    truth = [200.0, 60.0]
    mines = [[x, y] for x in (150, 190, 200, 205, 230, 290) for y in (20, 45, 60, 75, 120)]
    got = call_js(("predict_figure",), [("answerLabel", [m, truth]) for m in mines]
                  + [("answerLabel", [[200, 10], [200, 12]])])  # fmt: skip
    boxes = call_js(("predict_figure",), [("labelBox", [lab]) for lab in got])
    assert all(b["x1"] - b["x0"] >= 100 for b in boxes)  # r8: the 18 px font's width
    for mine, box in zip(mines, boxes, strict=False):
        clear_x = box["x1"] < mine[0] - 14 or box["x0"] > mine[0] + 14
        clear_y = box["y1"] < mine[1] - 14 or box["y0"] > mine[1] + 14
        assert clear_x or clear_y, (mine, box)
    assert boxes[-1]["y0"] >= 0  # no room above: below the dot


def test_point_reveal_can_draw_the_ray_that_finds_the_answer():
    """Review r4/r5, lesson 04 c3: the reveal drew the answer dot but not the eye ray."""
    from pathlib import Path

    kw = dict(answer=(1.0, 2.0), draw=None, xlim=(0, 4), ylim=(0, 4))
    assert PredictPoint("Where?", **kw).data["rayFrom"] is None
    assert PredictPoint("Where?", **kw, ray_from=(0, 0)).data["rayFrom"] == [0.0, 0.0]
    js = (Path(tr.__file__).parent / "widgets" / "static" / "predict_figure.js").read_text()
    assert "data.rayFrom" in js  # the page draws it
    with pytest.raises(ValueError, match="ray_from"):
        PredictPoint("Where?", **kw, ray_from=(0, 0, 1))


def test_point_reveal_can_draw_the_curve_the_answer_comes_from():
    """Review r38, 05b c9: after Check only a dot marked the answer; the z² curve the
    explanation derives was never drawn."""
    from pathlib import Path

    kw = dict(answer=(1.0, 2.0), draw=None, xlim=(0, 4), ylim=(0, 4))
    assert PredictPoint("Where?", **kw)._reveal["revealCurve"] is None
    q = PredictPoint("Where?", **kw, reveal_curve=[(0, 0), (1, 2), (2, 4)])
    # the curve passes through the answer: it reaches the page with the reveal (issue 31)
    assert "revealCurve" not in q.data and "reveal" not in q.state
    q.given = (1.0, 2.0)
    q.check()
    assert q.state["reveal"]["revealCurve"] == [[0.0, 0.0], [1.0, 2.0], [2.0, 4.0]]
    js = (Path(tr.__file__).parent / "widgets" / "static" / "predict_figure.js").read_text()
    assert "known.revealCurve" in js  # the page draws it
    for bad in ([(0, 0)], [(0, 0, 1), (1, 1, 1)], [(0, 0), (1, float("nan"))]):
        with pytest.raises(ValueError, match="reveal_curve"):
            PredictPoint("Where?", **kw, reveal_curve=bad)


def test_the_answers_label_keeps_clear_of_the_readout():
    """Review 11-12-r6 (12 cell 41): after Check, with the marker on the answer, "the answer"
    and the live readout "code 188" were drawn at the same place ("th code 188"). Wherever the
    marker sits along the answer's row (the code ramp's case), by the left and right edges too,
    the label's box clears the readout's box and the marker's cross, inside the canvas."""
    width, height = 800, 240
    mines = [[x, 100.0] for x in (60, 100, 150, 190, 200, 210, 250, 300, 700, 740, 790)]
    truths = [[x, 100.0] for x in (30, 200, 760)]
    calls = [("readoutPlace", [m, 72, width]) for m in mines]
    places = call_js(("predict_figure",), calls)
    calls = [
        ("answerLabel", [m, t, r["box"], height]) for t in truths for m, r in zip(mines, places)
    ]
    got = call_js(("predict_figure",), calls)
    boxes = call_js(("predict_figure",), [("labelBox", [lab]) for lab in got])

    def overlap(a, b):
        return a["x0"] < b["x1"] and b["x0"] < a["x1"] and a["y0"] < b["y1"] and b["y0"] < a["y1"]

    pairs = [(m, r) for _ in truths for m, r in zip(mines, places)]
    for (mine, place), box in zip(pairs, boxes, strict=True):
        cross = {"x0": mine[0] - 14, "x1": mine[0] + 14, "y0": mine[1] - 14, "y1": mine[1] + 14}
        assert not overlap(box, place["box"]), (mine, box, place)
        assert not overlap(box, cross), (mine, box)
        assert 0 <= box["y0"] and box["y1"] <= height
    assert places[-1]["align"] == "right"  # by the right edge the readout turns left
    # review r336 S7: the readout in the axis labels' size, its box as tall as that font
    from pathlib import Path

    js = (Path(tr.__file__).parent / "widgets" / "static" / "predict_figure.js").read_text()
    size = int(js.split('READOUT_FONT = "bold ')[1].split("px")[0])
    assert size >= 20 and js.count("ctx.font = READOUT_FONT") == 2 and "bold 16px" not in js
    assert all(p["box"]["y1"] - p["box"]["y0"] >= size for p in places)


def test_the_revealed_pixels_have_a_key_and_missed_ones_are_not_orange():
    # reviews r31/r34 12a: missed pixels were dashed orange, the hue of the lesson's diamonds;
    # now purple, and a legend under the verdict says which outline is which
    from pathlib import Path

    js = (Path(tr.__file__).parent / "widgets" / "static" / "predict_figure.js").read_text()
    assert "OKABE.orange" not in js.split("function mountPixels")[-1].split("function reveal")[0]
    (legend,) = call_js(("predict_figure",), [("pixelLegend", [])])
    for words in ("yours, and right", "missed", "marked, not among them"):
        assert words in legend
    assert "#CC79A7" in legend and "#E69F00" not in legend
    # review r118 06-6: missed cells filled and outlined solid, 4 px (a dashed 3-px outline
    # read as faint dots on a projector); the key shows the same fill
    pixels = js.split("function mountPixels")[-1].split("function reveal")[0]
    assert "ctx.fillStyle = MISSED_FILL" in pixels and "[5, 3]" not in pixels
    assert "has(r, c) ? 3 : 4" in pixels and "dashed" not in legend
    assert "rgba(204,121,167,0.5)" in legend and "4px solid #CC79A7" in legend
    # review r129 08-6: the marked cells are drawn blue whether right or not, so both swatches of
    # marked cells are blue (the right one was white inside: blue cells read "not among them")
    assert "ctx.fillStyle = GIVEN_FILL" in pixels
    right, wrong = legend.split("yours, and right")[0], legend.split("missed")[-1]
    assert right.count("rgba(0,114,178,0.45)") == 1 and "rgba(0,114,178,0.45)" in wrong


def test_a_dragged_marker_with_a_whole_number_readout_lands_on_a_whole_number():
    """Review r43 12b-5: the code marker was dropped between codes ("Your marker is 8.29 codes
    from the answer") while the arrow keys moved it by whole codes; a marker whose readout has
    no decimals snaps on drag, others do not."""
    code, z, plain = call_js(("predict_figure",), [("snapDragged", [[180.29, 0.5], "code", 0]),
                                                   ("snapDragged", [[0.1234, 0.5], "z", 3]),
                                                   ("snapDragged", [[180.29, 0.5], None, 0])])  # fmt: skip
    assert code == [180, 0.5] and z == [0.1234, 0.5] and plain == [180.29, 0.5]


def test_the_answers_label_keeps_off_the_segment_the_marker_moves_along():
    """Review r91 04-F (lesson 04 c4): "the answer" and its white ground lay across the
    segment the marker is dragged along; a place round the dot clear of it wins."""
    truth, mine = [300.0, 200.0], [420.0, 120.0]
    segment = [[100.0, 330.0], [600.0, 0.0]]  # up and to the right, through the dot
    plain, kept = call_js(("predict_figure",), [("answerLabel", [mine, truth]),
                                                ("answerLabel", [mine, truth, None, 600, [segment]])])  # fmt: skip
    boxes = call_js(("predict_figure",), [("labelBox", [lab]) for lab in (plain, kept)])
    assert _crosses(boxes[0], [segment]) and not _crosses(boxes[1], [segment])


def test_the_answers_label_keeps_off_the_curve_the_reveal_draws():
    """Review r330 FIG1 (lesson 03's q_weights): "the answer" lay across the middle of the
    line λ1 = 0.6 that the reveal draws through the dot; the reveal curve's pieces are now
    among the lines the label keeps clear of, after the marker's segment and keep_clear."""
    data = {"along": [[0, 0], [1, 0]], "keepClear": [[[2, 2], [3, 3]]]}
    got = call_js(("predict_figure",), [("labelLines", [data, [[0, 5], [1, 6], [2, 8]]]),
                                        ("labelLines", [{}, None])])  # fmt: skip
    assert got[0] == [[[0, 0], [1, 0]], [[2, 2], [3, 3]], [[0, 5], [1, 6]], [[1, 6], [2, 8]]]
    assert got[1] == []


def _crosses(box, segments) -> bool:
    """Whether a label's box (canvas pixels) lies across any of ``segments``."""
    for (ax, ay), (bx, by) in segments:
        for t in np.linspace(0, 1, 401):
            x, y = ax + t * (bx - ax), ay + t * (by - ay)
            if box["x0"] < x < box["x1"] and box["y0"] < y < box["y1"]:
                return True
    return False


def test_the_answers_label_keeps_off_the_figures_lines_it_is_given():
    """Review r106 03-W2 (lesson 03 c3): after Check, "the answer" and its white ground lay
    on the triangle's edge v3v1, near which the answer lies. PredictPoint's ``keep_clear``
    hands the page the triangle's edges, and a place round the dot clear of them wins."""
    xy = np.array([[2.0, 1.0], [13.0, 5.0], [5.0, 12.0]])  # lesson 03's triangle
    edges = np.stack([xy, np.roll(xy, -1, axis=0)], axis=1)
    q = PredictPoint("Where?", answer=(4.0, 4.7), draw=None, xlim=(0, 16), ylim=(14, 0),
                     keep_clear=edges)  # fmt: skip
    assert q.data["keepClear"] == edges.tolist()
    with pytest.raises(ValueError, match="keep_clear"):
        PredictPoint("Where?", answer=(1, 1), draw=None, xlim=(0, 4), ylim=(0, 4),
                     keep_clear=[[0, 0, 1, 1]])  # fmt: skip

    def px(p):  # 40 canvas px a unit, y down as the figure's
        return [60.0 + 40 * p[0], 20.0 + 40 * p[1]]

    truth, mine = px((4.0, 4.7)), px((8.0, 6.0))  # the marker right of the answer
    lines = [[px(a), px(b)] for a, b in edges]
    plain, kept = call_js(("predict_figure",), [("answerLabel", [mine, truth]),
                                                ("answerLabel", [mine, truth, None, 600, lines])])  # fmt: skip
    boxes = call_js(("predict_figure",), [("labelBox", [lab]) for lab in (plain, kept)])
    assert _crosses(boxes[0], lines) and not _crosses(boxes[1], lines)


def _examples():
    """One of each kind, with the answer it must not send the page before Check."""
    why = "Because the whole order is c, a, b (secret 7)."  # an explanation states the answer
    return [
        (_pixels(), [[2, 2]]),
        (PredictPoint("Where?", answer=(1.25, 2.75), draw=None, xlim=(0, 4), ylim=(0, 4),
                      reveal_curve=[(0, 0), (1.25, 2.75)], explain=why), (3.0, 3.0)),
        (PredictOrder("Nearest?", ["a", "b", "c"], answer=["c", "a", "b"], explain=why),
         ["a", "b", "c"]),
        (PredictChoice("How far?", ["near", "far"], answer="far", explain=why), "near"),
    ]  # fmt: skip


def _synced(q) -> str:
    """Everything the kernel sends the page of ``q`` (its synced traits), as JSON, and the
    HTML its output keeps for a viewer (the saved notebook's)."""
    import json

    state = q.get_state()
    state.pop("_esm", None)  # the module's source: no answer in it
    return json.dumps(state) + q._repr_mimebundle_()[0]["text/html"]


def test_the_page_holds_no_answer_before_check():
    """Issue 31: the page had the answer before Check (``data["answer"]``), so a student read
    it with devtools, or in the widget state of a saved notebook. Before Check no synced
    trait and no output of the notebook holds it, nor the explanation, which often states
    it (review r132 06-4: lesson 06's q_price gave the whole order, q_rule the count); Check
    (the page's, sent as the state, or ``check()``) brings both in the state, and only with
    an answer given."""
    import json

    for q, given in _examples():
        answer, why = q._reveal["answer"], q._reveal["explain"]
        assert why and q.explain == why, q  # every kind has one here
        if q.data["kind"] != "choice":  # (a choice's answer is among the options shown)
            secret = json.dumps(answer).replace(" ", "")
            assert secret not in _synced(q).replace(" ", ""), q
            assert "2.75" not in _synced(q) and "1.25" not in _synced(q)  # nor the curve
        assert why not in _synced(q) and json.dumps(why) not in _synced(q), q
        assert "secret 7" not in _synced(q) and "centres inside" not in _synced(q), q
        assert "reveal" not in q.state and "answer" not in q.data and "explain" not in q.data
        q.state = {**q.state, "revealed": True}  # a page asking with no answer: refused
        assert not q.revealed and "reveal" not in q.state
        q.state = {**q.state, "given": given, "acted": True}  # an answer, not yet checked
        assert "reveal" not in q.get_state()["state"]
        q.state = {**q.state, "revealed": True}  # Check, as the page sends it
        assert q.revealed and q.get_state()["state"]["reveal"]["answer"] == answer
        assert q.get_state()["state"]["reveal"]["explain"] == why  # the explanation with it
        q.state = {k: v for k, v in q.state.items() if k != "reveal"}  # a page's later state
        assert q.state["reveal"]["answer"] == answer  # the answer stays with the reveal
        assert q.state["reveal"]["explain"] == why
    pixels = _pixels()
    pixels.given = [[2, 2]]
    pixels.check()  # from code, as the lessons' tests do
    assert pixels.state["reveal"]["answer"] == np.argwhere(pixels.answer).tolist()


def test_the_offline_page_carries_the_answer_it_judges_with():
    """A ``teachraster html`` page has no kernel to ask: it holds what the reveal shows
    (``data.reveal``), and the page judges at once, as before."""
    import json
    import os

    q = PredictChoice("How far?", ["near", "far"], answer="far", explain="skyward 9")
    page = q.offline_html()
    payload = json.loads(page.split("const [DATA, STATE] = ")[1].split(";\n")[0])
    assert payload[0]["reveal"] == {"answer": "far", "explain": "skyward 9"}  # as the answer
    os.environ["TEACHRASTER_STATIC_PAGES"] = "1"
    try:
        html = q._repr_mimebundle_()[0]["text/html"]
        assert '"reveal":{"answer":"far","explain":"skyward 9"}' in html
    finally:
        del os.environ["TEACHRASTER_STATIC_PAGES"]
    assert '"reveal"' not in q._repr_mimebundle_()[0]["text/html"]
    assert "skyward 9" not in q._repr_mimebundle_()[0]["text/html"]  # nor the explanation


def test_ticking_no_order_works_sets_the_chips_aside():
    """Review r190 05a-5: with "no order works" ticked the chips stayed fully active, so the
    page showed an order and the box at once with nothing saying which was graded. Ticked, the
    chips are greyed and do not move (nor after Check); the hint says so, only beside a box."""
    from pathlib import Path

    cases = [(False, False), (True, False), (False, True), (True, True)]
    got = call_js(("predict_figure",), [("chipsState", list(c)) for c in cases])
    assert [g["aside"] for g in got] == [False, True, False, True]
    assert [g["movable"] for g in got] == [True, False, False, False]
    js = (Path(tr.__file__).parent / "widgets" / "static" / "predict_figure.js").read_text()
    order = js.split("function mountOrder")[1].split("function mountChoice")[0]
    assert 'chips.classList.toggle("aside", aside)' in order
    assert order.count("chipsState(ticked(), state.revealed).movable") == 2  # drag and keys
    assert ".tr-chips.aside .tr-chip" in js
    box = PredictOrder("Order?", ["a", "b"], answer=None, allow_impossible=True)
    assert "Ticking the box below sets the order aside" in box.data["hint"]
    assert "no order works" not in box.data["hint"]  # the box's own words stay unique
    plain = PredictOrder("Order?", ["a", "b"], answer=["a", "b"])
    assert "Ticking" not in plain.data["hint"]


def test_the_point_marker_stays_on_the_plot_and_an_answer_off_it_is_refused():
    """Review r215 07-3: lesson 07's q_behind marker, dragged past the plot's top-left corner
    to (-5, -5), vanished; the mouse could not bring it back, and Check graded the off-image
    answer. The page now keeps the marker inside the plot's data rectangle (xlim x ylim, either
    way round) with or without ``along``, and an answer outside it (a saved state, or code)
    keeps Check disabled; the kernel refuses the same points (one rectangle, both sides)."""
    from pathlib import Path

    box = [[0, 32], [32, 0]]  # q_behind's: a pixel grid, y down
    along = [[0, 16], [40, 16]]  # a segment running past the plot's right edge
    cases = [([-5, -5], None, box), ([40.5, 33], None, box), ([3.14159, 7.5], None, box),
             ([-5, -5], None, None), ([36, 2], along, box), ([20, 2], along, box),
             ([31.99996, 1], None, box)]  # fmt: skip
    got = call_js(("predict_figure",), [("constrainPoint", list(c)) for c in cases])
    assert got == [[0, 0], [32, 32], [3.1416, 7.5], [-5, -5], [32, 16], [20, 16], [32, 1]]
    points = [[0, 0], [32, 32], [16, 8], [-5, -5], [16, 32.5], [-0.0001, 3], None]
    answered = call_js(("predict_figure",), [("pointAnswered", [p, box]) for p in points]
                       + [("pointAnswered", [[-5, -5], None])])  # fmt: skip
    assert answered == [True, True, True, False, False, False, False, True]
    # the kernel: the same rectangle, from xlim and ylim, in the page's data
    q = PredictPoint("Where does v3 land?", answer=(16, 8), draw=None, xlim=(0, 32),
                     ylim=(32, 0), start=(28.8, 28.8), tolerance=1.5, units="px")  # fmt: skip
    assert q.data["box"] == box
    assert [q.inside(p) for p in points[:-1]] == answered[:-2]
    with pytest.raises(ValueError, match="outside the plot"):
        q.given = (-5, -5)
    assert q.given is None
    q.state = {**q.state, "given": [-5, -5], "revealed": True}  # as a page before r215 sent it
    assert not q.revealed  # refused: no reveal, the answer not sent
    assert "reveal" not in q.state
    q.given = (0, 0)  # the marker at the corner it is clamped to: an answer
    q.check()
    assert q.revealed and q.correct is False and "17.9 px" in q.verdict()
    for bad in (dict(answer=(40, 8)), dict(answer=(16, 8), start=(-1, 4))):
        with pytest.raises(ValueError, match="outside the plot"):
            PredictPoint("Where?", **{"draw": None, "xlim": (0, 32), "ylim": (32, 0), **bad})
    # the page uses them: every drag and key step through constrainPoint, Check on pointAnswered
    js = (Path(tr.__file__).parent / "widgets" / "static" / "predict_figure.js").read_text()
    point = js[js.index("function mountPoint") : js.index("function mountOrder")]
    assert "constrainPoint(p, data.along, box)" in point and "const box = data.box" in point
    assert point.count("constrain(") == 2 and "toFixed" not in point  # drag and keys
    assert "checkDisabled(state.revealed, answered())" in point
    assert "POINT_HINT" in point and "arrow keys" in js.split("POINT_HINT =")[1].split(";")[0]


def test_a_point_verdict_quotes_the_gap_no_finer_than_the_tolerance():
    """Review r342 S1: lesson 04's q_point (tolerance 0.15) read "Your marker is 0.00101 units
    from the answer"; the page and the kernel now write 0.001."""
    from teachraster.widgets.predict_figure import gap_text

    cases = [(0.00101, 0.15), (17.888, 1.5), (2.0, 4.0), (0.3, 0.0), (0.0, 0.15)]
    got = call_js(("predict_figure",), [("gapText", list(case)) for case in cases])
    assert got == [gap_text(*case) for case in cases] == ["0.001", "17.9", "2", "0.3", "0"]
    p = PredictPoint("Q?", answer=(1, 2), draw=None, xlim=(0, 4), ylim=(0, 4), tolerance=0.15)
    p.given = [1.00101, 2.0]
    assert "Your marker is 0.001 units from the answer" in p.verdict()
