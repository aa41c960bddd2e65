"""Predictions answered by acting on a figure, revealed by the figure itself.

A :class:`~teachraster.widgets.Predict` takes a choice or a number. These take an action on
the lesson's own picture, where the geometry is: click the pixels you expect lit, drag a
marker to where a point lands, put items in order. Check stays disabled until an answer is
given; then the figure itself shows the answer over the student's (the true pixels outlined,
the true point beside the marker, each item's place marked), with a verdict and the
explanation.

The picture is drawn once by the kernel (matplotlib: the lesson's ``draw(ax)``); marking and
drawing the reveal happen in the page (``static/predict_figure.js``). The answer is not sent
to the page before Check (issue 31: it was in the widget's ``data``, readable with devtools
or in a saved notebook's widget state): Check sends the student's answer, and the kernel's
state then carries what the reveal shows (``state["reveal"]``). A ``teachraster html`` page,
with no kernel, carries it (``offline_html``) and judges by itself. The student's answer
reaches the kernel (``q.given``, ``q.correct``, ``q.revealed``), and a notebook saved and
reopened keeps the question, its picture and, once checked, the verdict.

API for lessons (one example each)
----------------------------------
Pixels: the answer is a (height, width) bool mask; ``draw(ax)`` adds to the pixel grid
(whose data coordinates are pixels, y down)::

    from teachraster.plotting import plot_triangle
    from teachraster.widgets import PredictPixels

    tri = tr.Triangle([[1.5, 1.5], [9.5, 3.5], [3.5, 8.5]])
    PredictPixels(
        "Click the pixels this triangle covers.",
        answer=tr.rasterize(tri, 12, 10).coverage,
        draw=lambda ax: plot_triangle(ax, tri, arrows=False),
        explain="A pixel is covered when its centre is inside (top-left rule on ties).",
    )

Point: the answer is (x, y) in the data coordinates of ``draw``'s Axes (``xlim``, ``ylim``
set by the widget); ``along`` keeps the marker on a segment; within ``tolerance`` is right::

    from teachraster.plotting.projection import Segment, plot_projection
    from teachraster.widgets import PredictPoint

    seg = Segment(x0=-1.0, z0=1.5, x1=2.0, z1=3.0)
    PredictPoint(
        "The eye ray through the middle of the screen (q = 0.5) meets the segment where? "
        "Drag the marker there.",
        answer=seg.point(seg.world_parameter(0.5))[0],
        draw=lambda ax: plot_projection(ax, seg, n_steps=1),  # the ends' rays only
        xlim=(-1.5, 2.5), ylim=(-0.2, 3.5), along=((-1.0, 1.5), (2.0, 3.0)), tolerance=0.1,
        explain="Equal steps on the screen are unequal steps on the segment: t = 1/3.",
    )

Order: ``answer`` lists the items in the right order, or is None when no order works
(``allow_impossible=True`` offers "no order works")::

    PredictOrder(
        "Order the three sticks from nearest to farthest.",
        items=["red", "green", "blue"], answer=None, allow_impossible=True,
        explain="Each stick is in front of one and behind the other: a cycle.",
    )

Choice: a multiple choice marked in the page, as these are: Check is enabled the moment an
option is picked, with no round trip to a busy kernel (review r98, 07: a :class:`Predict`'s
Check waited over a second for the kernel to hear of the pick); ``draw`` optional::

    PredictChoice(
        "How far can float32's rounding move an edge at 10⁶ px?",
        ["under a pixel", "tens of pixels", "thousands of pixels"],
        answer="thousands of pixels",
        explain="float32's numbers near 10¹² are 65,536 apart.",
    )
"""

from __future__ import annotations

import base64
import html
from collections.abc import Callable, Sequence

import numpy as np
import traitlets

from ..core.validate import as_finite, as_float
from ..plotting.frames import encode_png, frame_rgba
from .common import choices_html, font_scale, style_context
from .explorable import Explorable, esm_source, offline_html, static_pages
from .predict import HoldsAnswer


def _check_question(question, explain) -> tuple[str, str]:
    if not isinstance(question, str) or not question.strip():
        raise TypeError(f"question must be a non-empty str, got {question!r}")
    if not isinstance(explain, str):
        raise TypeError(f"explain must be a str (HTML), got {type(explain).__name__}")
    return question, explain


def _check_draw(draw) -> Callable | None:
    if draw is not None and not callable(draw):
        raise TypeError(f"draw must be callable (it draws on an Axes) or None, got {draw!r}")
    return draw


def _optional_picture(draw, figsize, style) -> dict:
    """The picture over an order or a choice: ``draw(ax)`` on one Axes, or none."""
    if draw is None:
        return {}
    return figure_picture(_check_draw(draw), lambda fig: fig.add_subplot(), figsize, style,
                          trim=True)  # fmt: skip


def _plural(noun: str, n: int) -> str:
    return noun if n == 1 else noun + "s"


def grid_axes(fig, width: int, height: int, side: float):
    """Size ``fig`` for a ``width`` x ``height`` pixel grid (longer side ``side`` inches) with
    room for the row and column labels only, and add its Axes."""
    s = font_scale()
    aw, ah = (side, side * height / width) if width >= height else (side * width / height, side)
    # above: the column labels and "column j" only (0.75 * s left an empty band there)
    left, top, right, bottom = 0.75 * s, 0.42 * s + 0.1, 0.15, 0.15
    fw, fh = left + aw + right, top + ah + bottom
    fig.set_size_inches(fw, fh)
    return fig.add_axes((left / fw, bottom / fh, aw / fw, ah / fh))


#: What :func:`figure_picture` keeps round what is drawn when it trims (pixels at 96 dpi)
TRIM_MARGIN_PX = 10


def figure_picture(draw, axes_for, figsize, style, *, trim: bool = False) -> dict:
    """Draw a figure once: ``axes_for(fig)`` makes and sets up its Axes, ``draw(ax)`` adds the
    lesson's artists. Returns the PNG (base64), its size in pixels and the transform from
    data coordinates to picture pixels from the top left, ``[x0, y0, sx, sy]``.

    With ``trim`` the picture is cut to what is drawn, with a margin of
    :data:`TRIM_MARGIN_PX`: an Axes of fixed aspect (an image) leaves the rest of its figure
    empty, which stood as a white band between the picture and the widget's controls
    (review r158, 05a: 110 px under the sticks).
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    with style_context(style):
        fig = Figure(figsize=figsize, dpi=96)
        FigureCanvasAgg(fig)
        ax = axes_for(fig)  # in the style: its fonts size the margins
        if draw is not None:
            draw(ax)
        fig.canvas.draw()
        rgba = frame_rgba(fig)
        drawn = fig.get_tightbbox(fig.canvas.get_renderer()) if trim else None
    h_fig, w = rgba.shape[:2]  # the whole figure; window y counts up from its bottom
    h, left, top = h_fig, 0, 0
    if drawn is not None:  # inches -> picture rows and columns (from the top), margin kept
        m = TRIM_MARGIN_PX
        left = max(int(np.floor(drawn.x0 * fig.dpi)) - m, 0)
        right = min(int(np.ceil(drawn.x1 * fig.dpi)) + m, w)
        top = max(h_fig - int(np.ceil(drawn.y1 * fig.dpi)) - m, 0)
        bottom = min(h_fig - int(np.floor(drawn.y0 * fig.dpi)) + m, h_fig)
        rgba = rgba[top:bottom, left:right]
        h, w = rgba.shape[:2]
    bbox = ax.get_window_extent()
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    sx, sy = bbox.width / (x1 - x0), -bbox.height / (y1 - y0)
    return {"png": base64.b64encode(encode_png(rgba)).decode("ascii"), "size": [w, h],
            "transform": [bbox.x0 - sx * x0 - left, (h_fig - bbox.y0) - sy * y0 - top,
                          sx, sy]}  # fmt: skip


class FigurePrediction(HoldsAnswer, Explorable):
    """What the three kinds share: the question, Check, the verdict, the stand-in."""

    _esm = esm_source("predict_figure")
    noun = "question"
    title = "Predict first"

    def __init__(self, question: str, explain: str, data: dict, reveal: dict) -> None:
        super().__init__()
        self.question, self.explain = _check_question(question, explain)
        # what Check shows (the answer, for a point the curve through it, and the
        # explanation, which often states the answer): kept in the kernel until Check, never
        # in ``data`` (issue 31: the page held the answer before Check, readable with
        # devtools or in a saved notebook's widget state; review r132 06-4: the explanation)
        self._reveal = {**reveal, "explain": explain}
        self.data = {"question": question, **data}
        self.state = {"given": None, "revealed": False}
        self.observe(self._on_state, "state")

    @traitlets.validate("state")
    def _keep_the_checked_answer(self, proposal) -> dict:
        """The answer reaches the page only with the reveal: a revealed state carries it
        (``reveal``), any other never does, and a reveal with no answer given is refused.
        Once revealed, the answer that was checked stays: a later one (from the page or
        from code) changes neither ``given`` nor the verdict (review r28)."""
        new, old = dict(proposal["value"]), self.state
        new.pop("reveal", None)
        if old.get("revealed"):
            kept = {k: old[k] for k in ("given", "acted") if k in old}
            return {**new, **kept, "revealed": True, "reveal": self._reveal}
        if new.get("revealed") and not self._answered_in(new):
            new["revealed"] = False  # Check needs an answer, in the kernel as in the page
        if new.get("revealed"):
            new["reveal"] = self._reveal
        return new

    @staticmethod
    def _answered_in(state: dict) -> bool:
        return state.get("given") not in (None, []) or bool(state.get("acted"))

    def _on_state(self, change) -> None:
        if change["new"].get("revealed") and not change["old"].get("revealed"):
            self._update_standin()  # the verdict goes into the saved notebook
            self._release_held()  # and the answer cell's output shows (``hold()``)

    def _release_widget(self):
        return self

    def _release_held(self) -> None:
        # an anywidget's view does not take ``_dom_classes`` (seen in JupyterLab 4.6): the
        # state names the released class and the page adds it (predict_figure.js, ``mark``);
        # always: cells held for an earlier run of the question wait for it too
        self.state = {**self.state, "released": self._released_class()}
        super()._release_held()

    @property
    def given(self):
        """The student's answer (None before one is given)."""
        return self.state.get("given")

    @property
    def revealed(self) -> bool:
        """Whether Check was pressed (in the page, or :meth:`check` from code)."""
        return bool(self.state.get("revealed"))

    def check(self) -> None:
        """Reveal, as the page's Check does: only once an answer is given."""
        self.state = {**self.state, "revealed": True}  # refused without one (the validator)

    def verdict(self) -> str:
        """The verdict in words (HTML), as the page says it."""
        raise NotImplementedError

    def standin_text(self) -> str:
        text = self.question  # under the title "Predict first"
        if self.data.get("items"):  # an order question: its items, in the order shown first
            text += f"<div>{choices_html(self.data['items'])}</div>"
        if self.data.get("choices"):  # a choice: its options (plain text)
            text += f"<div>{choices_html([html.escape(c) for c in self.data['choices']])}</div>"
        if self.revealed:
            text += f"<div><i>{self.verdict()}</i></div>"
        return text

    def offline_html(self) -> str:
        """This question as an offline page (``teachraster html``): no kernel there to
        reveal the answer, so the page holds it (and the explanation) and judges by itself."""
        return offline_html(self._esm, {**self.data, "reveal": self._reveal}, self.state)

    def _fallback_html(self) -> str:
        # the notebook's own output for viewers: no answer in it (issue 31), but in a
        # ``teachraster html`` run it is the live page above
        return self.offline_html() if static_pages() else super().offline_html()

    def _standin(self) -> str:
        if not self.picture and self.data.get("png"):
            self.picture = base64.b64decode(self.data["png"])  # the question's own picture
        return super()._standin()


class PredictPixels(FigurePrediction):
    """Click the pixels you expect lit on a pixel grid; Check outlines the true ones.

    Parameters
    ----------
    question : str
        The question (HTML).
    answer : (height, width) bool array-like
        The pixels that are lit (e.g. ``tr.rasterize(...).coverage``).
    draw : callable, optional
        ``draw(ax)`` adds the lesson's artists (a triangle, a line) to the grid's Axes,
        whose data coordinates are pixels (x right, y down).
    asked : callable, optional
        ``asked(ax)`` adds marks that belong to the question only (rings round the cells it
        asks about): shown until Check, then left out, so that the revealed figure draws only
        what its key names (right, missed, marked). A ring left on a cell rightly unmarked read
        as "missed" beside the key's swatch (review r291 02-1).
    explain : str
        Shown with the verdict (HTML).
    centres : bool
        Mark the pixel centres (where coverage is decided).
    side : float
        The grid's longer side in inches.
    style : str, optional
        The plotting style of the picture.
    cell, picked : str
        What a cell is (singular: "pixel", "tile", "level") and what the answer's cells are,
        as the question asks it ("lit", "rejected", "left as gaps", "drawn twice"): the
        widget's own lines read "Click the pixels you expect {picked}" and "The answer: 12
        pixels {picked}". Name what is asked: the default "lit" contradicts a question about
        gaps or about pixels drawn twice.
    none : str, optional
        The label (HTML) of a choice "no cell at all" beside the grid, for a question whose
        honest prediction may be none (a sliver that one sample per pixel loses): ticked, it
        is an answer, and Check is enabled with no cell marked. Marking a cell unticks it.
        Without it (the default) Check waits for a marked cell.
    one : bool
        The question asks for one cell: the widget's line reads "Click the {cell} you expect
        {picked}", not "the {cell}s ... (drag to paint several)", which contradicted "the one
        pixel" of lesson 04's q_worst (review r297 S2). Default False.

    Attributes
    ----------
    given : list of [row, col] or None
        The pixels the student marked: ``[]`` once ``none`` is chosen, None before an answer.
    correct : bool or None
        Whether they are exactly the lit ones (None before an answer).

    Examples
    --------
    >>> q = PredictPixels("Which?", answer=np.eye(3, dtype=bool))
    >>> q.correct is None
    True
    >>> q.given = [[0, 0], [1, 1], [2, 2]]
    >>> q.correct, q.counts()
    (True, {'right': 3, 'extra': 0, 'missed': 0, 'total': 3})
    """

    def __init__(self, question: str, answer, *, draw=None, asked=None, explain: str = "",
                 centres: bool = True, side: float = 5.0, style: str | None = "classroom",
                 cell: str = "pixel", picked: str = "lit",
                 none: str | None = None, one: bool = False) -> None:  # fmt: skip
        words = {"cell": cell, "picked": picked} | ({} if none is None else {"none": none})
        for name, word in words.items():
            if not isinstance(word, str) or not word.strip():
                raise TypeError(f"{name} must be a non-empty str, got {word!r}")
        mask = np.asarray(answer)
        if mask.dtype != bool or mask.ndim != 2 or not mask.size:
            raise TypeError(f"answer must be a (height, width) bool array, got {mask.dtype} "
                            f"{mask.shape}")  # fmt: skip
        height, width = mask.shape
        if width * height > 64 * 64:
            raise ValueError(f"answer: at most 64 x 64 pixels to click, got {width}x{height}")
        draw, asked = _check_draw(draw), _check_draw(asked)

        def axes_for(fig):
            from ..plotting import plot_pixel_centres, plot_pixel_grid

            ax = grid_axes(fig, width, height, side)
            plot_pixel_grid(ax, width, height)
            if centres:
                plot_pixel_centres(ax, width, height)
            return ax

        def drawn(ax, with_asked=True):
            for add in (draw, asked if with_asked else None):
                if add is not None:
                    add(ax)
            # The whole grid, whatever the drawing did to the limits (a line or a fill
            # autoscales them, and cut off the last row).
            ax.set(xlim=(0, width), ylim=(height, 0))

        picture = figure_picture(drawn, axes_for, (side, side), style)
        if asked is not None:  # the same Axes and transform, without the question's marks
            answered = figure_picture(lambda ax: drawn(ax, False), axes_for, (side, side), style)
            picture["pngAnswered"] = answered["png"]
        self.answer = mask.copy()
        # the "none" choice is HTML, as the question is (the page shows it as such)
        offered = {} if none is None else {"noneLabel": none}
        super().__init__(question, explain, {"kind": "pixels", "width": width, "height": height,
                                             **picture, "cell": html.escape(cell),
                                             "picked": html.escape(picked), "one": bool(one),
                                             **offered},
                         {"answer": np.argwhere(mask).tolist()})  # fmt: skip
        # ``acted``: the "none" choice ticked, an answer with no cell marked (the page sends it)
        self.state = {"given": [], "acted": False, "revealed": False}

    @property
    def given(self):
        """The marked pixels as [row, col] pairs: ``[]`` when "none" was chosen, None before
        an answer."""
        given = [list(map(int, rc)) for rc in self.state.get("given") or []]
        if given:
            return given
        return [] if self.state.get("acted") else None

    @given.setter
    def given(self, pixels) -> None:
        """Mark ``pixels``; ``[]`` chooses "none" where the question offers it."""
        rows = [[int(r), int(c)] for r, c in (pixels or [])]
        said_none = pixels is not None and not rows and "noneLabel" in self.data
        self.state = {**self.state, "given": rows, "acted": said_none}

    def counts(self) -> dict | None:
        """``right``, ``extra`` (marked, not lit), ``missed`` and ``total`` lit."""
        if self.given is None:
            return None
        mine = {tuple(rc) for rc in self.given}
        truth = {tuple(rc) for rc in np.argwhere(self.answer).tolist()}
        right = len(mine & truth)
        return {"right": right, "extra": len(mine) - right, "missed": len(truth) - right,
                "total": len(truth)}  # fmt: skip

    @property
    def correct(self) -> bool | None:
        c = self.counts()
        return None if c is None else c["extra"] == 0 and c["missed"] == 0

    def verdict(self) -> str:
        c = self.counts() or {"right": 0, "extra": 0, "missed": 0, "total": int(self.answer.sum())}
        word = "Right." if self.correct else "Not quite."
        cell, marked = self.data["cell"], c["right"] + c["extra"]
        return (f"{word} You marked {marked} {_plural(cell, marked)}: {c['right']} right, "
                f"{c['extra']} too many, {c['missed']} missed. The answer: {c['total']} "
                f"{_plural(cell, c['total'])} {self.data['picked']}.")  # fmt: skip


def point_gap(answer, given) -> float:
    """How far a point question's marker ``given`` lies from its ``answer``, 0 within float
    noise (1e-9 of the answer's size): a marker dropped on the answer read "1.78e-15 px from
    the answer" (review r236 S-6); the page's ``pointVerdict`` rounds alike.

    >>> point_gap((16, 8), (16 + 1.8e-15, 8)), point_gap((1, 2), (1.3, 2.4))
    (0.0, 0.5)
    """
    answer = np.asarray(answer, dtype=float)
    gap = float(np.hypot(*(np.asarray(given, dtype=float) - answer)))
    return 0.0 if gap <= 1e-9 * max(1.0, *np.abs(answer)) else gap


def gap_text(gap: float, tolerance: float) -> str:
    """A point verdict's distance, to three significant digits but no finer than a hundredth
    of the tolerance's order: "0.00101 units" for a tolerance of 0.15 read as more precise
    than a drag can be (review r342 S1); the page's ``gapText`` writes the same.

    >>> gap_text(0.00101, 0.15), gap_text(17.888, 1.5), gap_text(2.0, 4), gap_text(0.3, 0)
    ('0.001', '17.9', '2', '0.3')
    """
    if tolerance > 0:
        gap = round(gap, 2 - int(np.floor(np.log10(tolerance))))
    return f"{gap + 0.0:.3g}"  # + 0.0: no "-0"


class PredictPoint(FigurePrediction):
    """Drag a marker to where you expect a point; Check shows the true point beside it.

    Parameters
    ----------
    question : str
    answer : (2,) array-like
        The true point, in the data coordinates of the figure.
    draw : callable
        ``draw(ax)`` draws the figure (the widget sets ``xlim`` and ``ylim`` afterwards).
    xlim, ylim : (2,) floats
        The Axes' limits (``ylim`` may run downwards, as pixel grids do). The marker stays
        inside them (a drag past the edge leaves it on the edge), and an answer outside them
        is refused; ``answer`` and ``start`` must lie inside them.
    start : (2,) array-like, optional
        Where the marker starts (default: the middle of the Axes, or of ``along``).
    along : ((x0, y0), (x1, y1)), optional
        Keep the marker on this segment (and inside the Axes' limits).
    tolerance : float
        A marker this close to the answer (data units) is right.
    units : str
        What the distance is measured in, for the verdict ("px", "units", "codes").
    step : float, optional
        How far one arrow key moves the marker (Shift + arrow: ten steps), in data units:
        1 on an axis of integer codes. Default: a hundredth of the smaller Axes span.
    readout : str, optional
        Label a live readout of the marker's x while it moves, e.g. "code": the figure shows
        "code 186" beside the marker (to ``step``'s decimals) and the verdict repeats it. A
        label with "{}" puts the number there: "{} triangles" reads "60 triangles".
        Default: no readout (where reading the answer off the marker would give it away).
    ray_from : (2,) array-like, optional
        The reveal also draws the ray from this point through the answer (the eye ray that
        finds the point), so the answer shows where it comes from.
    reveal_curve : (N, 2) array-like, optional
        The reveal also draws this polyline (data coordinates, N >= 2): the curve the answer
        was worked out from, left out of the question's picture (review r38, 05b: the z² law
        drawn through the answer once it is checked).
    keep_clear : (N, 2, 2) array-like, optional
        Segments of the figure (data coordinates) that the label "the answer" should not cover,
        such as a triangle's edges near the answer (review r106 03-W2: it hid part of lesson
        03's edge v3v1); a place clear of them is preferred, as of ``along``.
    explain, figsize, style : as above.

    Examples
    --------
    >>> q = PredictPoint("Where?", answer=(1.0, 2.0), draw=None, xlim=(0, 4), ylim=(0, 4),
    ...                  tolerance=0.25)
    >>> q.given = (1.1, 2.1)
    >>> q.correct
    True
    """

    def __init__(self, question: str, answer, *, draw, xlim, ylim, start=None, along=None,
                 tolerance: float = 0.0, units: str = "units", explain: str = "",
                 figsize=(7.0, 5.0), style: str | None = "classroom", step=None,
                 readout: str | None = None, ray_from=None,
                 reveal_curve=None, keep_clear=None) -> None:  # fmt: skip
        answer = as_finite("answer", answer, (2,))
        xlim, ylim = as_finite("xlim", xlim, (2,)), as_finite("ylim", ylim, (2,))
        if xlim[0] == xlim[1] or ylim[0] == ylim[1]:
            raise ValueError(f"xlim and ylim must span a range, got {xlim}, {ylim}")
        tolerance = as_float("tolerance", tolerance)
        if not tolerance >= 0:
            raise ValueError(f"tolerance must be >= 0, got {tolerance}")
        if along is not None:
            along = as_finite("along", along, (2, 2))
        if start is None:
            start = along.mean(axis=0) if along is not None else [xlim.mean(), ylim.mean()]
        start = as_finite("start", start, (2,))
        draw = _check_draw(draw)
        if ray_from is not None:
            ray_from = as_finite("ray_from", ray_from, (2,)).tolist()
        if reveal_curve is not None:
            reveal_curve = as_finite("reveal_curve", reveal_curve, (None, 2))
            if len(reveal_curve) < 2:
                raise ValueError(f"reveal_curve needs at least 2 points, got {len(reveal_curve)}")
            reveal_curve = reveal_curve.tolist()
        if keep_clear is not None:
            keep_clear = as_finite("keep_clear", keep_clear, (None, 2, 2)).tolist()

        def axes_for(fig):
            ax = fig.add_subplot()
            # laid out inside a margin: constrained layout put a key beside the Axes flush
            # with the figure's edge, and the page cut off its frame (review r307 FIG2,
            # lesson 00's q_half)
            mx, my = (TRIM_MARGIN_PX / size for size in fig.bbox.size)
            fig.set_layout_engine("constrained", rect=(mx, my, 1 - 2 * mx, 1 - 2 * my))
            return ax

        def drawn(ax):
            if draw is not None:
                draw(ax)
            ax.set(xlim=tuple(xlim), ylim=tuple(ylim))

        picture = figure_picture(drawn, axes_for, figsize, style)
        self.answer, self.tolerance = answer, tolerance
        span = min(abs(xlim[1] - xlim[0]), abs(ylim[1] - ylim[0]))
        step = span / 100 if step is None else as_float("step", step)
        if not step > 0:
            raise ValueError(f"step must be > 0, got {step}")
        if readout is not None and (not isinstance(readout, str) or not readout):
            raise TypeError(f"readout must be a non-empty str or None, got {readout!r}")
        # the readout shows as many decimals as one key step needs (none for whole codes)
        digits = 0 if step >= 1 else min(6, int(np.ceil(-np.log10(step) - 1e-9)))
        self._box = (tuple(xlim.tolist()), tuple(ylim.tolist()))
        for name, point in (("answer", answer), ("start", start)):
            if not self.inside(point):  # the marker cannot reach it, or starts out of sight
                raise ValueError(f"{name} {point.tolist()} lies outside the plot, "
                                 f"xlim {xlim.tolist()}, ylim {ylim.tolist()}")  # fmt: skip
        super().__init__(question, explain, {
            "kind": "point", "start": start.tolist(), "box": [xlim.tolist(), ylim.tolist()],
            "along": None if along is None else along.tolist(), "tolerance": tolerance,
            "units": html.escape(units), "keyStep": step,
            "readout": None if readout is None else html.escape(readout),
            "readoutDigits": digits, "rayFrom": ray_from, "keepClear": keep_clear, **picture},
            {"answer": answer.tolist(), "revealCurve": reveal_curve})  # fmt: skip

    @FigurePrediction.given.setter
    def given(self, point) -> None:
        point = as_finite("point", point, (2,))
        if not self.inside(point):
            raise ValueError(f"point {point.tolist()} lies outside the plot, xlim "
                             f"{list(self._box[0])}, ylim {list(self._box[1])}")  # fmt: skip
        self.state = {**self.state, "given": point.tolist()}

    def inside(self, point) -> bool:
        """Whether ``point`` lies in the plot's data rectangle (its edges included), where
        the page keeps the marker (``constrainPoint``, ``pointAnswered`` in
        ``static/predict_figure.js``): only such a point is an answer."""
        try:
            xy = [float(v) for v in point]
        except (TypeError, ValueError):  # not two numbers: no point at all
            return False
        return len(xy) == 2 and all(min(lim) <= v <= max(lim) for v, lim in zip(xy, self._box))

    def _answered_in(self, state: dict) -> bool:
        # a point off the picture (a saved state, a page from before r215) is no answer
        given = state.get("given")
        return given is not None and self.inside(given)

    @property
    def gap(self) -> float | None:
        """Distance from the marker to the answer (None before the marker is moved)."""
        if self.given is None:
            return None
        return point_gap(self.answer, self.given)

    @property
    def correct(self) -> bool | None:
        return None if self.gap is None else self.gap <= self.tolerance

    def readout(self) -> str | None:
        """The page's live readout of the marker's x ("code 186"), None without one."""
        if self.data["readout"] is None or self.given is None:
            return None
        label, n = self.data["readout"], f"{self.given[0]:.{self.data['readoutDigits']}f}"
        # "{} triangles" places the number (review r344 01-S1: "triangles 60"), as the page does
        return label.replace("{}", n, 1) if "{}" in label else f"{label} {n}"

    def verdict(self) -> str:
        word = "Right." if self.correct else "Not quite."
        units = self.data["units"]
        within = f"; within {self.tolerance:.3g} {units} is right" if self.tolerance else ""
        if self.readout() is not None:
            word += f" You predicted {self.readout()}."
        return (f"{word} Your marker is {gap_text(self.gap, self.tolerance)} {units} from the answer "
                f"({self.answer[0]:.3g}, {self.answer[1]:.3g}){within}.")  # fmt: skip


def _order_hint(allow_impossible: bool) -> str:
    """The line above the chips: how to answer, and, with the box offered, that ticking it
    sets the order aside (the page greys the chips; review r190 05a-5)."""
    hint = ("Drag the items into order (or focus one and use the arrow keys); "
            "to answer the order shown, click one of them.")  # fmt: skip
    if allow_impossible:
        # the label itself not repeated: the page finds the box by its words
        hint += " Ticking the box below sets the order aside; untick it to order them."
    return hint


class PredictOrder(FigurePrediction):
    """Put items in order (or say no order works); Check marks each place.

    Parameters
    ----------
    question : str
    items : list of str
        The items (HTML), in the order shown first.
    answer : list of str or None
        The items in the right order, or None when no order is right.
    allow_impossible : bool
        Offer "no order works" (``impossible_label``); needed when ``answer`` is None.
    draw : callable, optional
        ``draw(ax)`` draws a picture of the items above them.
    explain, figsize, style : as above.

    Examples
    --------
    >>> q = PredictOrder("Nearest first?", ["a", "b", "c"], answer=["b", "a", "c"])
    >>> q.given = ["b", "a", "c"]
    >>> q.correct
    True
    """

    def __init__(self, question: str, items: Sequence[str], answer: Sequence[str] | None, *,
                 allow_impossible: bool = False, impossible_label: str = "no order works",
                 draw=None, explain: str = "", figsize=(7.0, 3.5),
                 style: str | None = "classroom") -> None:  # fmt: skip
        items = [str(i) for i in items]
        if len(items) < 2 or len(set(items)) != len(items):
            raise ValueError(f"items must be at least two different items, got {items!r}")
        if answer is None:
            if not allow_impossible:
                raise ValueError("answer is None (no order works): set allow_impossible=True")
        elif sorted(map(str, answer)) != sorted(items):
            raise ValueError(f"answer must order the items {items!r}, got {answer!r}")
        picture = _optional_picture(draw, figsize, style)
        self.items = items
        self.answer = None if answer is None else [str(a) for a in answer]
        super().__init__(question, explain, {
            "kind": "order", "items": items,
            "allowImpossible": bool(allow_impossible), "impossibleLabel": impossible_label,
            "hint": _order_hint(allow_impossible),
            **picture}, {"answer": self.answer})  # fmt: skip
        self.state = {"given": None, "acted": False, "revealed": False}

    @FigurePrediction.given.setter
    def given(self, order) -> None:
        if order is not None:
            order = [str(i) for i in order]
            if sorted(order) != sorted(self.items):
                raise ValueError(f"order must hold the items {self.items!r}, got {order!r}")
        self.state = {**self.state, "given": order, "acted": True}

    @property
    def correct(self) -> bool | None:
        if not self.state.get("acted"):
            return None
        return self.given == self.answer

    def _named(self, order) -> str:
        """An order as the verdict names it: the items joined by arrows, or "no order works"."""
        return self.data["impossibleLabel"] if order is None else " → ".join(order)

    def verdict(self) -> str:
        """As the page's ``orderVerdictText``: the student's order beside the answer (review
        r167 05a-8: "Not quite. The answer: no order works." did not say what was given)."""
        right = self._named(self.answer)
        if not self.state.get("acted"):
            return f"The answer: <b>{right}</b>."
        word = "Right." if self.correct else "Not quite."
        return (
            f"{word} You predicted <b>{self._named(self.given)}</b>; the answer is <b>{right}</b>."
        )


class PredictChoice(FigurePrediction):
    """A multiple choice judged in the page: Check is enabled as soon as an option is picked.

    :class:`~teachraster.widgets.Predict` (ipywidgets) enables its Check only once the
    kernel has heard of the pick, which a kernel busy with the lesson's later cells (Run
    All) delays by seconds; here, as in the figure predictions, the page enables Check at
    the pick; Check then brings the answer from the kernel (none is in the page before).

    Parameters
    ----------
    question : str
        The question (HTML).
    choices : list of str
        The options (plain text), at least two, all different.
    answer : str
        The right one, one of ``choices``.
    draw : callable, optional
        ``draw(ax)`` draws a picture above the options.
    explain, figsize, style : as above.

    Examples
    --------
    >>> q = PredictChoice("Which row?", ["row 2", "row 3"], answer="row 2")
    >>> q.correct is None
    True
    >>> q.given = "row 3"
    >>> q.correct, q.verdict()
    (False, 'Not quite. You predicted <b>row 3</b>; the answer is <b>row 2</b>.')
    """

    def __init__(self, question: str, choices: Sequence[str], answer: str, *,
                 draw=None, explain: str = "", figsize=(7.0, 3.5),
                 style: str | None = "classroom") -> None:  # fmt: skip
        if isinstance(choices, str):
            raise TypeError(f"choices must be a list of str, got the str {choices!r}")
        choices = [str(c) for c in choices]
        if len(choices) < 2 or len(set(choices)) != len(choices):
            raise ValueError(f"choices must be at least two different answers, got {choices!r}")
        if str(answer) not in choices:
            raise ValueError(f"answer {answer!r} is not one of choices {choices!r}")
        picture = _optional_picture(draw, figsize, style)
        self.choices, self.answer = choices, str(answer)
        super().__init__(question, explain, {
            "kind": "choice", "choices": choices, **picture}, {"answer": self.answer})  # fmt: skip

    @FigurePrediction.given.setter
    def given(self, choice) -> None:
        if choice is not None and str(choice) not in self.choices:
            raise ValueError(f"choice must be one of {self.choices!r}, got {choice!r}")
        self.state = {**self.state, "given": None if choice is None else str(choice)}

    @property
    def correct(self) -> bool | None:
        return None if self.given is None else self.given == self.answer

    def verdict(self) -> str:
        if self.given is None:
            return f"The answer: <b>{html.escape(self.answer)}</b>."
        word = "Right." if self.correct else "Not quite."
        return (f"{word} You predicted <b>{html.escape(self.given)}</b>; the answer is "
                f"<b>{html.escape(self.answer)}</b>.")  # fmt: skip
