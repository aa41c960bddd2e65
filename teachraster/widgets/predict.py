"""``Predict``: a "predict, then see" question that takes the student's answer first.

Students learn more from a result they predicted (and got wrong) than from one they were only
shown. A ``Predict`` asks a question at the moment where intuition fails, takes a choice or a
number, and only then reveals the answer, the explanation and the figure that shows why.

Where the answer is kept
    The choice or number is the value of an ipywidgets control, so it is saved with the
    notebook's widget state; after "Check" a plain HTML line ("Saved with the notebook: you
    predicted ...") is also written into the cell's output with a display id, which is saved
    in the ``.ipynb`` whatever the widget settings are. A lecturer can use the questions as a
    poll. The line records the prediction only: the verdict and the answer are the widget's,
    so a student reading the live notebook sees them once, not twice.

Headless runs
    Executed with nobody looking (nbclient tests, ``teachraster html`` exports, plain Python),
    the question never waits: its output holds the answer, the explanation and the figure,
    folded under "Show the answer" so that a reader of the exported page still predicts
    first. See :func:`is_headless`.

The cell that gives the answer away
    A lesson's next cell often prints or draws the answer: with Run All it would sit just
    below the question before anyone answered. That cell starts with ``q.hold()``
    (:class:`HoldsAnswer`): in JupyterLab and Notebook 7 its output stays hidden behind one
    line until ``q`` is checked, then appears in place. The output itself is the cell's, as
    ever (saved with the notebook, read by the tests); headless runs hold nothing.
"""

from __future__ import annotations

import base64
import hashlib
import html
import io
import itertools
import math
import os
import re
import struct
from collections.abc import Callable, Mapping, Sequence

import ipywidgets as widgets
import matplotlib.pyplot as plt

from .common import choices_html, display_with_fallback, standin_html, style_context

#: Environment variable that forces the headless behaviour ("1") or the interactive one ("0").
HEADLESS_ENV = "TEACHRASTER_HEADLESS"

_ids = itertools.count()


def is_headless() -> bool:
    """True when no student can answer: show the answer at once instead of asking.

    ``TEACHRASTER_HEADLESS=1`` (or ``0``) decides when set. Otherwise a run is headless when
    it exports a static page (``TEACHRASTER_STATIC_PAGES=1``, set by ``teachraster html``),
    when there is no IPython kernel (plain Python, a doctest) or when the kernel's matplotlib
    backend was forced to Agg by its environment (``MPLBACKEND=Agg``), as the test suite and
    batch exports do: a kernel a student uses draws inline or with ipympl instead.
    """
    flag = os.environ.get(HEADLESS_ENV, "").strip().lower()
    if flag in ("1", "true", "yes"):
        return True
    if flag in ("0", "false", "no"):
        return False
    if os.environ.get("TEACHRASTER_STATIC_PAGES") == "1":  # `teachraster html`: a static page
        return True
    if _kernel_shell() is None:
        return True
    return os.environ.get("MPLBACKEND", "").strip().lower() == "agg"


def _kernel_shell():
    """IPython's shell where a kernel runs this code, else None (a script, a console)."""
    try:
        from IPython import get_ipython
    except ImportError:  # pragma: no cover - ipywidgets depends on IPython
        return None
    shell = get_ipython()
    return None if shell is None or getattr(shell, "kernel", None) is None else shell


#: Hides, in JupyterLab and Notebook 7, every output of a cell after the one holding the
#: ``teachraster-held`` element of display id ``{held}``: the outputs a prediction's answer
#: cell makes after ``hold()``, until the notebook holds an element of class ``{released}``
#: (the prediction's own widget takes that class when it is revealed, and keeps it in the
#: kernel: a page reloaded on the same kernel shows the answer cell's output, although the
#: reloaded page no longer knows the display id through which the live release empties the
#: held line). The class is named after the question, so the widget of the question cell run
#: again takes it too when checked. A front end without ``:has`` shows everything at once.
#: One that strips ``<style>`` (JupyterLab on an untrusted notebook, a page exported without
#: it) shows the outputs too, and with them the line's other text, :data:`HELD_BARE_TEXT`:
#: the held line's two texts are switched by this style (which wins over the inline
#: ``display: none`` by ``!important``) and by inline styles, which sanitisers keep.
HELD_CSS = (
    "<style>.jp-Notebook:not(:has(.{released})) .jp-OutputArea-child:has(.{held}) "
    "~ .jp-OutputArea-child {{display: none}} "
    ".jp-Notebook:has(.{released}) .jp-OutputArea-child:has(.{held}) {{display: none}} "
    ".{held} .teachraster-held-live {{display: inline !important}} "
    ".{held} .teachraster-held-bare {{display: none}}</style>"
)

#: What stands in for the held outputs, live and in a notebook saved before the answer: one
#: short grey line, since a lesson holds up to nine cells and nine copies of a two-line
#: explanation read as noise (review r259 S-7).
HELD_TEXT = (
    "(shown once the question above is checked; if it stays hidden after that, run this cell again)"
)


#: What each held line says when a cell holds its outputs for several questions (``hold()``
#: called on each): they show only once all are checked, and "the question above" read as
#: the first, which the student checked to find them still hidden (review r354 02-S2)
HELD_ALL_TEXT = (
    "(shown once {which} above that it waits for are checked; if it stays hidden after that, "
    "run this cell again)"
)

#: The number of questions a cell's held lines wait for, as HELD_ALL_TEXT writes it
COUNT_WORDS = {2: "two", 3: "three", 4: "four", 5: "five", 6: "six"}

#: The held lines of the cell running now: (its request's message id, [(display id, css)])
_cell_holds: list = [None, []]


def _this_cell():
    """What names the cell running now (its request's message id), None outside a kernel."""
    shell = _kernel_shell()
    if shell is None:
        return None
    header = (getattr(shell, "parent_header", None) or {}).get("header", {})
    return header.get("msg_id")


def _held_line(display_id: str, css: str, text: str) -> dict:
    """The held line's data: the style, the live text and the bare one (see HELD_CSS)."""
    # two texts: the style shows the first, and where it is stripped the inline styles
    # (which sanitisers keep) show the second
    line = (f"<div class='teachraster-held {display_id}' style='color:#555'>"
            f"<i class='teachraster-held-live' style='display: none'>{text}</i>"
            f"<i class='teachraster-held-bare'>{HELD_BARE_TEXT}</i></div>")  # fmt: skip
    return {"text/html": css + line, "text/plain": text}


#: What the held line says where its style is stripped (see :data:`HELD_CSS`): then nothing
#: hides the outputs after it, and "it stays hidden" would be untrue (review r157 00-7).
HELD_BARE_TEXT = (
    "This copy cannot hide the output below, which gives the prediction above away (it was "
    "opened without its page styles: an untrusted or exported copy). Predict first: run the "
    "notebook, answer and Check, then read on."
)


class HoldsAnswer:
    """``hold()``: keep the rest of the current cell's output hidden until this prediction is
    revealed (mixed into :class:`Predict` and the figure predictions).

    The cell runs and prints as ever; only the front end hides what it printed (see
    :data:`HELD_CSS`), so holding never changes a result, and the outputs stay in the cell
    (saved with the notebook, read by the lesson tests). Headless runs, and a prediction
    already revealed, hold nothing.
    """

    def _holds(self) -> bool:
        """Whether ``hold()`` hides anything now (a student who can still answer)."""
        headless = getattr(self, "headless", None)
        return not (is_headless() if headless is None else headless) and not self.revealed

    def hold(self) -> None:
        """Call first in the cell that shows the answer: the outputs the cell makes after it
        stay hidden behind one line until the prediction is checked, then appear in place
        (JupyterLab, Notebook 7). Call it on two predictions to wait for both.

        Returns None, so that it displays nothing as a cell's last line.
        """
        from IPython.display import publish_display_data

        if not self._holds():
            return
        held = self.__dict__.setdefault("_held_ids", [])
        display_id = f"teachraster-held-{os.getpid()}-{next(_ids)}"
        held.append(display_id)
        css = HELD_CSS.format(held=display_id, released=self._released_class())
        cell = _this_cell()
        if _cell_holds[0] != cell or cell is None:
            _cell_holds[:] = [cell, []]
        lines = _cell_holds[1]
        lines.append((display_id, css))
        n = len(lines)
        # r370: "all two" for two; and "above" alone read as every question above the cell
        which = "both questions" if n == 2 else f"all {COUNT_WORDS.get(n, n)} questions"
        text = HELD_TEXT if n == 1 else HELD_ALL_TEXT.format(which=which)
        publish_display_data(_held_line(display_id, css, text),
                             transient={"display_id": display_id})  # fmt: skip
        for earlier, earlier_css in lines[:-1]:  # the cell's other lines wait for all, too
            publish_display_data(_held_line(earlier, earlier_css, text),
                                 transient={"display_id": earlier}, update=True)  # fmt: skip

    def _released_class(self) -> str:
        """The class the prediction's widget takes once revealed (see :data:`HELD_CSS`).

        One name per question (its kind and text), not per object: a question cell run again
        makes a new prediction, whose page view replaces the old one, and with it the class
        the held cells' style waits for. Then the answer cells run under the old one stayed
        hidden after the new one was checked, until they were run again too (r104 09-8). The
        same name lets the new prediction release them; a kernel restarted too.
        """
        if "_released" not in self.__dict__:
            kind = type(self).__name__
            text = getattr(self, "question", "")
            digest = hashlib.sha1(f"{kind}\0{text}".encode()).hexdigest()[:16]
            self._released = f"teachraster-released-{digest}"
        return self._released

    def _release_widget(self):
        """The widget that takes :meth:`_released_class` when revealed (the page's view of it)."""
        return self.widget

    def _release_held(self) -> None:
        """Show what ``hold()`` hid: empty its line (the outputs after it then show), and
        mark the prediction's widget released (what a reloaded page reads, :data:`HELD_CSS`).
        Each line is emptied once; the outputs never move, so nothing is shown twice."""
        from IPython.display import publish_display_data

        held = self.__dict__.get("_held_ids", [])
        # what a page reloaded on this kernel reads (its held lines lost their ids), and what
        # releases the cells held for an earlier run of this question: taken when nothing
        # was held through this object too
        self._release_widget().add_class(self._released_class())
        while held:
            publish_display_data({"text/html": "", "text/plain": ""},
                                 transient={"display_id": held.pop(0)}, update=True)  # fmt: skip


#: A whole number written with commas between groups of three digits, "-294,912"
THOUSANDS = re.compile(r"[+-]?\d{1,3}(,\d{3})+")


def parse_number(text, *, thousands: bool = False) -> float | None:
    """A typed number, or None: ``"0,25"`` (a decimal comma), ``"3/4"``, ``"20 %"`` (the
    number 20: the question says what it counts), ``"1e-3"``, ``"−4.5"`` (a true minus sign,
    as the lessons print it); None for anything else.

    With ``thousands`` (a question whose answer is printed with thousands separators, or one
    asking for a whole number), commas between groups of three digits separate thousands: ``"-294,912"``, typed as a lesson prints it, is -294912, not
    -294.912 (review r231 02-12).

    >>> parse_number("3/4"), parse_number(" 20 % "), parse_number("0,5"), parse_number("")
    (0.75, 20.0, 0.5, None)
    >>> parse_number("−294,912"), parse_number("−294,912", thousands=True)
    (-294.912, -294912.0)
    """
    t = str(text).strip().replace("\u2212", "-")
    if thousands and THOUSANDS.fullmatch(t):
        t = t.replace(",", "")
    t = t.replace(",", ".").removesuffix("%").strip()
    try:
        if t.count("/") == 1:
            num, den = (float(p) for p in t.split("/"))
            return num / den if den != 0 else None
        value = float(t)
    except ValueError:  # empty or not a number yet
        return None
    return value if value == value and abs(value) != float("inf") else None


def _check_arguments(question, choices, answer, tolerance):
    """Validate the arguments; return the choices as a tuple (or None) and the tolerance."""
    if not isinstance(question, str) or not question.strip():
        raise TypeError(f"question must be a non-empty str, got {question!r}")
    if choices is not None:
        choices = tuple(str(c) for c in choices)
        if len(choices) < 2:
            raise ValueError(f"choices must list at least two answers, got {choices!r}")
        if str(answer) not in choices:
            raise ValueError(f"answer {answer!r} is not one of choices {choices!r}")
        return choices, 0.0
    if isinstance(answer, bool) or not isinstance(answer, int | float):
        raise TypeError(f"answer must be a number when there are no choices, got {answer!r}")
    tolerance = float(tolerance)
    if not tolerance >= 0.0:
        raise ValueError(f"tolerance must be >= 0, got {tolerance!r}")
    return None, tolerance


def _check_notes(notes, choices) -> dict:
    """Validate ``notes``: a mapping of given answers (a choice, or a number) to lines."""
    if notes is None:
        return {}
    if not isinstance(notes, Mapping):
        raise TypeError(f"notes must be a mapping of answers to lines, got {type(notes).__name__}")
    checked = {}
    for key, text in notes.items():
        if not isinstance(text, str) or not text.strip():
            raise TypeError(f"notes: the line for {key!r} must be a non-empty str, got {text!r}")
        if choices is not None and str(key) not in choices:
            raise ValueError(f"notes: {key!r} is not one of choices {choices!r}")
        if choices is None and (isinstance(key, bool) or not isinstance(key, int | float)):
            raise TypeError(f"notes: keys must be numbers when there are no choices, got {key!r}")
        checked[str(key) if choices is not None else float(key)] = text
    return checked


def _number(value: float, thousands: bool = False) -> str:
    """A number for the verdict, its sign the minus sign "−" as in the lessons' text (review
    r287 S3: "the answer is -0.74" beside the text's "−0.74"); with ``thousands`` a whole
    number has commas between groups of three digits, as the lesson prints it (review r302
    02-4: "the answer is −294912" above the explanation's "−294,912").

    >>> _number(-294912.0, thousands=True), _number(-294912.0), _number(0.5, thousands=True)
    ('−294,912', '−294912', '0.5')
    """
    whole = thousands and float(value).is_integer()
    text = f"{int(value):,}" if whole else f"{value:g}"
    return "−" + text[1:] if text.startswith("-") else text


class Predict(HoldsAnswer):
    """Ask first, reveal after: a multiple-choice or numeric prediction question.

    Parameters
    ----------
    question : str
        The question (HTML allowed).
    choices : list of str, optional
        The possible answers; without them the student types a number.
    answer : str or float
        The right choice (one of ``choices``) or the right number.
    explain : str
        Why (HTML allowed), shown with the answer.
    figure : callable, optional
        Called without arguments when the answer is revealed; returns the matplotlib Figure
        that explains the answer (or draws into the current figure and returns None).
    tolerance : float
        A number within ``tolerance`` of ``answer`` counts as right.
    headless : bool, optional
        Force the headless behaviour (answer shown at once) or the interactive one; by
        default :func:`is_headless` decides.
    style : str, optional
        Plotting style the figure is drawn in ("classroom" by default).
    notes : mapping, optional
        A line (HTML allowed) the verdict adds for one given answer, keyed by a choice or a
        number: why that answer, reached by a sound route, is not this one (review r118 06-3:
        lesson 02's closed box gives 50 bits where the half-open range gives 49).
    whole : bool
        A numeric question that asks for a whole number: Check stays disabled, its tooltip
        saying so, until the number typed is one (review r170 05b-6: "2.5" was graded wrong
        with no word about the format). Commas then separate thousands, as ``thousands``.
    thousands : bool
        A numeric question whose answer the lesson prints with thousands separators: commas
        between groups of three digits are read as such, "-294,912" as -294912, not -294.912
        (review r231 02-12); a decimal comma elsewhere ("0,5") is still one.

    Attributes
    ----------
    control : ipywidgets.ToggleButtons or ipywidgets.Text
        Where the student answers (set ``.value`` to answer from code; a number is typed
        as text, so that an empty box is not read as 0).
    check : ipywidgets.Button
        Reveals the answer (``check.click()`` from code).
    feedback : ipywidgets.HTML
        "Right" / "Not quite", the answer and the explanation, once revealed.
    output : ipywidgets.Output
        The explaining figure, once revealed.
    revealed : bool
    widget : ipywidgets.VBox

    Examples
    --------
    >>> q = Predict("Which row?", ["row 2", "row 3"], answer="row 2", headless=False)
    >>> q.control.value = "row 3"
    >>> q.check.click()
    >>> q.correct, q.revealed
    (False, True)
    """

    def __init__(
        self,
        question: str,
        choices: Sequence[str] | None = None,
        answer: str | float = None,
        explain: str = "",
        figure: Callable[[], object] | None = None,
        tolerance: float = 0.0,
        *,
        headless: bool | None = None,
        style: str | None = "classroom",
        notes: Mapping | None = None,
        whole: bool = False,
        thousands: bool = False,
    ) -> None:
        self.choices, self.tolerance = _check_arguments(question, choices, answer, tolerance)
        if whole and self.choices:
            raise ValueError("whole=True is for a numeric question, not for choices")
        self.whole = bool(whole)
        if thousands and self.choices:
            raise ValueError("thousands=True is for a numeric question, not for choices")
        self.thousands = bool(thousands) or self.whole
        self.notes = _check_notes(notes, self.choices)
        if figure is not None and not callable(figure):
            raise TypeError(f"figure must be callable or None, got {type(figure).__name__}")
        self.question, self.explain, self.figure, self.style = question, explain, figure, style
        self.answer = str(answer) if self.choices else float(answer)
        self.headless = is_headless() if headless is None else bool(headless)
        self.revealed = False
        self._kept = None  # the control's value when Check was pressed: the prediction kept
        self._display_id = f"teachraster-predict-{os.getpid()}-{next(_ids)}"
        self._build()

    def _build(self) -> None:
        """The controls: question, answer control, Check button, feedback, figure output."""
        if self.choices:
            self.control = widgets.ToggleButtons(
                options=self.choices, value=None, style={"button_width": "auto"}
            )
        else:
            self.control = widgets.Text(
                placeholder="a whole number" if self.whole else "your number",
                layout=widgets.Layout(width="12em"),
            )
        # Check waits for an answer: a prediction revealed without one is no prediction. Grey
        # until then, as the figure predictions' Check (review r57, 07-4: a disabled "primary"
        # button still looked blue, ready to press); blue once there is something to check
        self.check = widgets.Button(description="Check", button_style="", disabled=True,
                                    tooltip="give your answer first")  # fmt: skip
        self.check.on_click(lambda _: self._checked())
        self.control.observe(self._answer_changed, "value")
        self.feedback = widgets.HTML()
        self.output = widgets.Output()
        prompt = widgets.HTML(f"<b>Predict first.</b> {self.question}")
        row = widgets.HBox([self.control, self.check], layout=widgets.Layout(flex_flow="row wrap"))
        self.widget = widgets.VBox([prompt, row, self.feedback, self.output])

    def _answer_changed(self, _change=None) -> None:
        """Check is enabled exactly while a valid answer is given and nothing is revealed."""
        if self.revealed:  # locked: a changed box changes neither the verdict nor the record
            self._lock()
            return
        self.check.disabled = self.given is None
        self.check.button_style = "" if self.given is None else "primary"
        self.check.tooltip = "" if self.given is not None else self._missing()

    def _missing(self) -> str:
        """Check's tooltip while no valid answer is given."""
        typed = parse_number(self.control.value, thousands=self.thousands)
        if self.whole and not self.choices and typed is not None:
            return "type a whole number"
        return "give your answer first"

    def _checked(self) -> None:
        """The Check button: reveal, but only once an answer is given and only once (a click
        from code on the disabled button does nothing either)."""
        if self.given is not None and not self.revealed:
            self.reveal()

    def _lock(self) -> None:
        """After the reveal the prediction is final: the control and Check are disabled, and
        the box shows the answer that was checked (a prediction typed after seeing the answer
        is no prediction, review r28)."""
        self.control.disabled = self.check.disabled = True
        self.check.button_style = ""
        self.check.tooltip = "checked: your prediction is kept"
        if self._kept is not None and self.control.value != self._kept:
            self.control.value = self._kept

    @property
    def given(self):
        """The student's answer (a choice, a number), or None before a valid one is given;
        once revealed, the answer that was checked (the first one)."""
        value = self._kept if self.revealed else self.control.value
        if self.choices:
            return value
        number = parse_number(value, thousands=self.thousands)
        if number is not None and self.whole and number != round(number):
            return None
        return number

    @property
    def correct(self) -> bool | None:
        """Whether the given answer is right (None before an answer is given)."""
        given = self.given
        if given is None:
            return None
        if self.choices:
            return given == self.answer
        return abs(given - self.answer) <= self.tolerance

    def _answer_text(self) -> str:
        if self.choices:
            return html.escape(self.answer)
        if not self.tolerance:
            return _number(self.answer, self.thousands)
        # one digit finer than the tolerance, no more (r105 08-5: "1.15849 (± 0.1)")
        digits = max(0, 1 - math.floor(math.log10(self.tolerance)))
        # thousands as the lesson prints them (r339 S1: "11264 (± 500)" beside "11,264")
        return f"{_number(round(self.answer, digits), self.thousands)} (± {self.tolerance:g})"

    def _verdict(self) -> str:
        """One HTML line: what the student said against the answer."""
        if self.given is None:
            return f"The answer: <b>{self._answer_text()}</b>."
        said = html.escape(self.given) if self.choices else _number(self.given, self.thousands)
        word = "Right" if self.correct else "Not quite"
        colour = "#009E73" if self.correct else "#D55E00"  # Okabe–Ito bluish green, vermillion
        note = next((text for key, text in self.notes.items() if key == self.given), "")
        return (
            f"<span style='color:{colour};font-weight:bold'>{word}.</span> You predicted "
            f"<b>{said}</b>; the answer is <b>{self._answer_text()}</b>."
            + (f" {note}" if note else "")
        )

    def reveal(self) -> None:
        """Show the verdict, the explanation and the figure; record the answer in the cell.

        The first reveal locks the prediction (:meth:`_lock`); calling it again only repeats
        the same verdict and record.
        """
        if not self.revealed:
            self._kept = self.control.value
        verdict = self._verdict()
        self.feedback.value = f"<div>{verdict}</div><div>{self.explain}</div>"
        if not self.revealed and self.figure is not None:
            self.output.outputs = ()
            self.output.append_display_data(self._figure_png())
        self.revealed = True
        self._lock()
        if not self.headless:
            self._record()
        self._release_held()

    def _figure_png(self):
        """Call ``figure`` in the style; its Figure as a PNG image at the figure's own size.

        The PNG is made here (at the figure's dpi, so its width in pixels is inches × dpi)
        rather than left to the inline backend, so it shows in the Output widget and in
        headless runs alike; the figure is closed so the inline backend does not repeat it.
        """
        from IPython.display import Image

        with style_context(self.style):
            fig = self.figure()
            fig = plt.gcf() if fig is None else fig
            buffer = io.BytesIO()
            fig.savefig(buffer, format="png", dpi=fig.dpi)
        plt.close(fig)
        return Image(data=buffer.getvalue(), format="png")

    def record_html(self) -> str:
        """The line saved in the cell's output after "Check": the prediction, not the verdict
        (the widget shows that; repeated below it, a student read it twice)."""
        said = html.escape(self.given) if self.choices else _number(self.given, self.thousands)
        return (
            f"<div style='color:#555'><i>Saved with the notebook: you predicted {said}.</i></div>"
        )

    def _record(self) -> None:
        """Write the prediction into the cell's saved output (through the display id)."""
        from IPython import get_ipython
        from IPython.display import HTML, update_display

        if getattr(get_ipython(), "kernel", None) is None:
            return  # no notebook to write into (plain Python, a test driving the widget)
        update_display(HTML(self.record_html()), display_id=self._display_id)

    def standin_html(self) -> str:
        """What a notebook saved and reopened without a kernel shows in place of the widget:
        the question and its choices (or "a number"), and the hint that brings it back."""
        if self.choices:
            boxes = choices_html([html.escape(c) for c in self.choices])
        else:
            boxes = "<span style='color:#555'>(your answer: a number)</span>"
        return standin_html("", "question", text=f"<b>Predict first.</b> {self.question}"
                            f"<div>{boxes}</div>")  # fmt: skip

    def _ipython_display_(self) -> None:
        from IPython.display import HTML, display

        if self.headless:
            self._display_headless()
            return
        # the question in an output of its own, before the widget: what a reopened notebook
        # shows where JupyterLab would say "model not found" (hidden while the widget lives)
        standin = self.standin_html()
        display_with_fallback(self.widget._repr_mimebundle_(), standin)
        display(HTML(""), display_id=self._display_id)  # filled in by _record

    def _display_headless(self) -> None:
        """One HTML output: the question, then the answer, explanation and figure folded.

        Nothing waits for an answer. The answer sits in a ``<details>`` element, so a reader of
        an exported page still predicts first and then unfolds it; the figure is embedded as a
        PNG of its own size (inches × dpi).
        """
        from IPython.display import HTML, display

        display(HTML(self._headless_html()))
        self.revealed = True

    def _offline_page_(self):
        """``teachraster html``: the question, with its answer folded away (it still works
        there: the reader predicts, then unfolds)."""
        from .offline import OfflinePage

        self.revealed = True
        return OfflinePage(self._headless_html(), "live")

    def _headless_html(self) -> str:
        figure = ""
        if self.figure is not None:
            png = self._figure_png().data
            width = struct.unpack(">I", png[16:20])[0]  # the PNG header's width, in pixels
            figure = (f"<img style='max-width:100%' width='{width}' "
                      f"src='data:image/png;base64,{base64.b64encode(png).decode()}'>")  # fmt: skip
        return (
            f"<div><b>Predict first.</b> {self.question}</div>"
            f"<details><summary>Show the answer</summary>"
            f"<div>The answer: <b>{self._answer_text()}</b>.</div><div>{self.explain}</div>"
            f"{figure}</details>"
        )

    def close(self) -> None:
        """Close the widgets (and the comms behind them)."""
        for w in (self.control, self.check, self.feedback, self.output, self.widget):
            w.close()
