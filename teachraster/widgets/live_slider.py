"""``LiveSlider``: a slider in the page whose values reach the kernel coalesced.

An ipywidgets slider with ``continuous_update`` sends every value it passes through; a
kernel that re-renders a figure per value falls behind and works through a queue of stale
values long after the pointer stopped. This slider (``static/slider.js``) sends values as
custom messages with their own flow control, as :class:`~teachraster.widgets.DragFigure`
does for positions: at most two unanswered, each the latest when sent, values that come
meanwhile replaced (never queued), and the value where the slider was released always.
The kernel answers each once its observers have run (the new picture is sent first).
Values sent while the pointer still holds the slider are marked as drafts
(:attr:`LiveSlider.dragging` is True while their observers run), so that a widget may show
a cheaper picture during the drag; the release is always sent, marked final, and brings the
full picture. A final value may say that the page shows a picture drawn ahead there
(``held``, :attr:`LiveSlider.held` while its observers run): where that is the full
picture, the kernel sends none (:meth:`~teachraster.widgets.ahead.FramesAhead.held`).

It keeps the ipywidgets slider's interface that the explorers and lessons use: ``value``
(observable, settable from code), ``min``, ``max``, ``step``, ``description``,
``readout_format``, ``layout``; ``base`` makes it logarithmic like ``FloatLogSlider``
(``min`` and ``max`` are then exponents).
"""

from __future__ import annotations

import time
import uuid
from pathlib import Path

import anywidget
import ipywidgets as widgets
import traitlets

from ..plotting.frames import keys_js
from .display import FigureDisplay
from .dragging import DragFigure


def slider_js() -> str:
    """The page-side module (ESM), read from the package (``static/slider.js``)."""
    return keys_js() + (Path(__file__).parent / "static" / "slider.js").read_text(encoding="utf-8")


class LiveSlider(anywidget.AnyWidget):
    """A range input in the page; ``value`` follows it, coalesced (see the module).

    Parameters
    ----------
    value, min, max, step : float
        As for ``ipywidgets.FloatSlider``; with ``base``, ``min``, ``max`` and ``step`` are
        exponents and ``value`` is ``base ** exponent``.
    description : str
        The label before the slider.
    readout_format : str
        How the value is shown beside the slider (``".0f"``, ``".2f"``, ``".3g"``).
    base : float, optional
        Logarithmic slider of this base (``FloatLogSlider``).

    Examples
    --------
    >>> s = LiveSlider(value=30.0, min=0.0, max=90.0, step=1.0, description="tilt")
    >>> s.value = 45.0
    >>> s.value, s.messages
    (45.0, 0)
    """

    _esm = slider_js()
    value = traitlets.Float(0.0).tag(sync=True)
    min = traitlets.Float(0.0).tag(sync=True)
    max = traitlets.Float(100.0).tag(sync=True)
    step = traitlets.Float(1.0).tag(sync=True)
    description = traitlets.Unicode("").tag(sync=True)
    readout_format = traitlets.Unicode(".2f").tag(sync=True)
    base = traitlets.Float(0.0).tag(sync=True)  # 0: linear
    #: the ``key`` of the figure in the page that keeps pictures drawn ahead for this
    #: slider's positions and this slider's index among its sliders, ``"key/index"``
    #: (:mod:`~teachraster.widgets.ahead`); "" for none
    link = traitlets.Unicode("").tag(sync=True)

    def __init__(self, **kwargs) -> None:
        if kwargs.get("base") is None:
            kwargs.pop("base", None)
        super().__init__(**kwargs)
        self.messages = 0
        #: True while the value comes from a pointer still dragging the slider: observers may
        #: show a cheaper draft; the release then brings the full picture (:meth:`on_release`).
        self.dragging = False
        #: while a final value's observers run: what the page says it shows there by itself
        #: (a picture drawn ahead: its position, generation, reference and the last frame the
        #: page had; :meth:`~teachraster.widgets.ahead.FramesAhead.held`), else None
        self.held = None
        self._drafted = False
        self._release: list = []
        self._touch: list = []
        self.on_msg(self._on_page_message)

    def on_release(self, callback) -> None:
        """Call ``callback()`` when a drag ends on the value last shown as a draft, or the
        page sends as final the value the kernel holds (it showed a draft there).

        When the release moves the value, the observers of ``value`` run as usual (with
        ``dragging`` False); when it does not, they would not run again, so this callback
        brings the full picture instead.
        """
        self._release.append(callback)

    def on_touch(self, callback) -> None:
        """Call ``callback()`` when the page says the slider is pressed or focused."""
        self._touch.append(callback)

    @traitlets.validate("value")
    def _clamp(self, proposal) -> float:
        # as ipywidgets' sliders: a value beyond the range is clipped to it
        lo, hi = (
            (self.base**self.min, self.base**self.max) if self.base > 0 else (self.min, self.max)
        )
        return min(max(float(proposal["value"]), lo), hi)

    def _on_page_message(self, _widget, content, _buffers) -> None:
        if content.get("type") == "touch":
            for callback in self._touch:
                callback()
        if content.get("type") != "value":
            return
        self.messages += 1
        start = time.perf_counter()
        final = bool(content.get("final", True))
        try:
            before = self.value
            self.dragging = not final
            self.held = content.get("held") if final else None
            self.value = float(content["value"])  # the observers re-render here
            if not final:
                self._drafted = self._drafted or self.value != before
            else:
                self._drafted = False
                # a final value the kernel holds already: the page showed a draft there (the
                # last draft, or a picture drawn ahead: keys 60 -> 59 -> 60 while the kernel
                # was busy left 60's draft, "(on release)", for good); the page sends such a
                # value only then, so the full picture follows
                if self.value == before:
                    for callback in self._release:
                        callback()
        finally:
            self.dragging, self.held = False, None
            # how long the kernel took, for the page (benchmarks read it there)
            ms = round((time.perf_counter() - start) * 1e3, 2)
            self.send({"type": "done", "seq": int(content.get("seq", 0)), "kernel_ms": ms})


class SliderDisplay:
    """A slider explorer's figure in the page: :class:`~teachraster.widgets.DragFigure`'s
    pictures (nothing to drag), with ``FigureDisplay``'s ``refresh``/``close``.

    Each refresh sends only the rectangle of pixels that differ from the figure's reference
    picture, as RGBA (zlib level 1) that the page inflates and paints at once: an
    ``ipywidgets.Image`` would send a whole PNG, which the page then decodes asynchronously
    (5-90 ms on a loaded machine, more than the kernel's draft). Against one reference, a
    picture never depends on the one before: the page may also show pictures drawn ahead
    (:meth:`ahead`). A final picture (``drafting()`` False: a key, a release) also becomes
    the poster, the picture a re-opened or saved view shows. :attr:`caption` is the line of
    text above the picture.
    """

    mode = "page"

    def __init__(self, fig, draw, drafting, alt: str = "", *, handles=None,
                 on_move=None) -> None:  # fmt: skip
        self.fig, self.draw, self.drafting = fig, draw, drafting
        #: the points dragged in the page (data coordinates of the first Axes), as
        #: :class:`~teachraster.widgets.dragging.PageDisplay`'s: none for a slider explorer
        self.handles = handles or (lambda: [])
        self.widget = DragFigure(on_move, alt=alt, reference=True, deflate=True,
                                 key=uuid.uuid4().hex)  # fmt: skip
        self.caption = PageCaption(self.widget)
        self.draws = 0
        self.frames_ahead = None
        self.refresh()

    def refresh(self, rgba=None) -> None:
        """Draw the figure and send what changed to the page (``rgba``: send these pixels,
        a picture drawn before, instead). Where the page shows the full picture drawn ahead
        already (a release there, :meth:`FramesAhead.held
        <teachraster.widgets.ahead.FramesAhead.held>`), nothing is drawn or sent."""
        shown = None
        if rgba is None and self.frames_ahead is not None and not self.drafting():
            shown = self.frames_ahead.held()
        if shown is not None:
            self.widget.shown_already(shown)
            return
        if rgba is None:
            self.draws += 1
            (self.fig.canvas.draw if self.draw is None else self.draw)()
        self.widget.show(self.fig, self.fig.axes[0], self.handles(), final=not self.drafting(),
                         rgba=rgba)  # fmt: skip

    def ahead(self, sliders, explorer, *, full: bool = False, busy=None, order=None):
        """Draw ``explorer`` at every position of its sliders (the one moved last first, then
        the others in ``order``) while the kernel idles, for the page to show by itself
        (``full``: the full picture there, not the draft;
        :class:`~teachraster.widgets.ahead.FramesAhead`)."""
        from .ahead import FramesAhead

        self.frames_ahead = FramesAhead(self, sliders, explorer, full=full, busy=busy,
                                        order=order)  # fmt: skip
        return self.frames_ahead

    def close(self) -> None:
        if self.frames_ahead is not None:
            self.frames_ahead.close()
        self.widget.close()


class PageCaption:
    """The line of text above a :class:`SliderDisplay`'s picture, with ``ipywidgets.HTML``'s
    ``value`` (an explorer's ``info``): the page shows it with the picture it belongs to."""

    def __init__(self, page: DragFigure) -> None:
        self._page = page

    @property
    def value(self) -> str:
        page = self._page
        return page.caption if page.drag_caption is None else page.drag_caption

    @value.setter
    def value(self, html: str) -> None:
        page = self._page
        if page.in_drag:  # sent with the drag's picture; the trait follows at the release
            page.drag_caption = html
            return
        page.drag_caption = None
        page.caption = html


def slider_display(fig, mode: str, *, draw=None, drafting=lambda: False, alt: str = "",
                   handles=None, on_move=None):  # fmt: skip
    """The display of a slider explorer's figure: a :class:`SliderDisplay`, or under ipympl
    (``mode`` "ipympl") the canvas itself (``FigureDisplay``). ``handles()`` and
    ``on_move(i, x, y, final)``: points of the figure dragged in the page, as a
    :class:`~teachraster.widgets.dragging.PageDisplay`'s (the page display only)."""
    if mode == "ipympl":
        return FigureDisplay(fig, mode, draw=draw)
    return SliderDisplay(fig, draw, drafting, alt, handles=handles, on_move=on_move)


def info_line(display, side: str = "top"):
    """An explorer's text by its figure (``side``: "top" or "right"), and the widgets that
    show it: the page figure's own caption, or (ipympl) an ``ipywidgets.HTML`` to place
    beside the canvas."""
    if isinstance(display, SliderDisplay):
        display.widget.caption_side = side
        return display.caption, []
    info = widgets.HTML()
    return info, [info]
