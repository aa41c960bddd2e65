"""Pieces every widget shares: style handling, figure layout for a FillView, titles."""

from __future__ import annotations

import base64
import contextlib
import html
import threading

import ipywidgets as widgets
import matplotlib as mpl

from ..plotting import use_style


class Holdable:
    """Lets a widget set its own controls without each change redrawing.

    Observers check ``self._quiet``; inside ``with self._holding():`` it is True, so the
    widget changes several controls and then redraws once.
    """

    _quiet = False

    @contextlib.contextmanager
    def _holding(self):
        self._quiet = True
        try:
            yield
        finally:
            self._quiet = False


def style_context(style: str | None):
    """``use_style(style)`` for the duration of a block, or nothing when ``style`` is None.

    Widgets build their figures inside it, so a widget can look "classroom" without
    switching the notebook's style for every later plot.
    """
    return contextlib.nullcontext() if style is None else use_style(style)


def font_scale() -> float:
    """Current font size relative to matplotlib's default of 10 pt (margins follow it)."""
    return float(mpl.rcParams["font.size"]) / 10.0


def fill_axes(
    fig, width: int, height: int, *, side: float = 4.4, legend: bool = True, key: float = 2.1
):
    """Size ``fig`` for a FillView of a ``width`` × ``height`` grid and add its Axes.

    Fixed margins (no layout engine, which would run again at every step): room above for
    the view's header and the column labels, on the left for the row labels, on the right
    for the view's colour key. ``side`` is the longer side of the grid in inches; ``key``
    the key's column in inches at the style's font scale (its longest line decides).
    """
    s = font_scale()
    if width >= height:
        aw, ah = side, side * height / width
    else:
        aw, ah = side * width / height, side
    left, right = 0.65 * s, (key * s if legend else 0.25)
    top, bottom = 0.85 * s, 0.15
    fw, fh = left + aw + right, top + ah + bottom
    fig.set_size_inches(fw, fh)
    return fig.add_axes((left / fw, bottom / fh, aw / fw, ah / fh))


def title_html(title: str, subtitle: str = "") -> widgets.HTML:
    """A bold title line with an optional grey explanation below it."""
    sub = f"<div style='color:#555'>{subtitle}</div>" if subtitle else ""
    return widgets.HTML(f"<div style='font-size:1.25em;font-weight:bold'>{title}</div>{sub}")


def labelled(text: str, control) -> widgets.HBox:
    """``control`` with a label on its left.

    ToggleButtons put their own ``description`` on a line of its own when space is short;
    a separate Label keeps label and buttons on one line.
    """
    # the label never shrinks below its text (a crowded row cut "format" to "forma"); in a
    # row too narrow for all, the buttons wrap instead (a row that wraps keeps them on one line)
    label = widgets.Label(text, layout=widgets.Layout(width="auto", margin="0 8px 0 0",
                                                      flex="0 0 auto"))  # fmt: skip
    # in a column narrower than label and control together (a 315-px column at 150 % zoom on
    # a 1024 x 768 screen), the control goes under its label and is never wider than the
    # column, instead of running past its edge (the TileExplorer's traversal menu did)
    if not control.layout.max_width:
        control.layout.max_width = "100%"
    return widgets.HBox([label, control], layout=widgets.Layout(
        flex_flow="row wrap", align_items="center", margin="0 24px 0 0", max_width="100%"))  # fmt: skip


#: Narrowest a picture of a row of pictures gets before it wraps under its neighbour (CSS px).
READABLE_PX = 300

#: The width of a slider as wide as its column. ipywidgets puts a margin
#: (``--jp-widgets-margin``, 2 px) on each side of a widget, so ``width="100%"`` made a slider
#: 4 px wider than its box: the box scrolled sideways, cutting the widget's left edge, as soon
#: as a value was typed into the readout (the TileExplorer's block slider; review r103 10-D).
#: A figure's image wider than the column gets it as its largest width, for the same reason
#: (the PixelInspector's box scrolled by 4 px at a 1280-px window; review r194).
SLIDER_COLUMN_WIDTH = "calc(100% - 2 * var(--jp-widgets-margin, 2px))"


def control_row(children, **layout) -> widgets.HBox:
    """A row of controls that wraps whole controls onto the next line when the column is too
    narrow for all of them.

    An HBox that does not wrap shrinks its children, or pushes them past the column's edge:
    at 1024 x 768 with JupyterLab's file browser open (a 592-px column) and at 150 % zoom
    the browser probe of 2026-12-01 found the FrameInspector's ``samples`` and ``depth
    test`` off screen and the PlaneExplorer's sliders cut (issue 31).
    """
    return widgets.HBox(list(children), layout=widgets.Layout(
        flex_flow="row wrap", align_items="center", max_width="100%", **layout))  # fmt: skip


def control_rows(*rows) -> widgets.VBox:
    """Several :func:`control_row` s, one under another: four controls in one wrapping row took
    four lines of a 315-px column (a 1024 x 768 projector at 150 %), two rows of two take two
    lines each at most (test_browser_layout allows three)."""
    return widgets.VBox([control_row(row) for row in rows])


#: what a renewed slider takes over from the one it replaces (:func:`renew_slider`); the
#: Layout and the style are shared (closing a widget leaves them open)
_SLIDER_TRAITS = ("description", "description_allow_html", "tooltip", "step", "orientation",
                  "readout", "readout_format", "continuous_update", "disabled", "behavior",
                  "tabbable", "layout", "style")  # fmt: skip


def renew_slider(slider, box, *, min=None, max=None, value=None, wire=None):
    """A new slider like ``slider`` over a new range, put in ``box`` where ``slider`` was;
    ``slider`` is closed. Returns the new slider.

    Use it instead of changing an ipywidgets slider's ``min`` or ``max`` in place: the page
    draws ``IntSlider``/``FloatSlider`` with noUiSlider, whose ``updateOptions`` (what
    ipywidgets 8 calls on a new range) gives the pointer and the arrow keys the new range
    but leaves its Home and End keys on the range the slider was created with
    (``options.spectrum``); after 0..68 became 0..388, End stopped at 68 (issue 31, the
    TileExplorer's block slider; review r27, the LinePlayer's step). A new slider starts
    from the new range.

    Parameters
    ----------
    slider : ipywidgets slider
        The slider shown now (a child of ``box``).
    box : ipywidgets.Box
        The box that shows it.
    min, max : number, optional
        The new range (None: ``slider``'s).
    value : number, optional
        The new value (None: ``slider``'s), moved into the range as a slider does.
    wire : callable, optional
        ``wire(new)`` connects the new slider (its observers, links) before it is shown:
        observers of ``slider`` are not carried over.
    """
    if not isinstance(box, widgets.Box) or not any(c is slider for c in box.children):
        raise ValueError("box: must be the ipywidgets Box that holds slider")
    lo = slider.min if min is None else min
    hi = slider.max if max is None else max
    value = slider.value if value is None else value
    kwargs = {name: getattr(slider, name) for name in _SLIDER_TRAITS if slider.has_trait(name)}
    value = sorted((lo, value, hi))[1]  # as a slider moves its value into a new range
    new = type(slider)(value=value, min=lo, max=hi, **kwargs)
    if wire is not None:
        wire(new)
    box.children = tuple(new if c is slider else c for c in box.children)
    slider.close()
    return new


def picture_row(children) -> widgets.HBox:
    """Pictures (and their notes) side by side where the column holds them, one under the
    other where it does not.

    In a row that does not wrap, the flex layout shrinks each picture to share the width: the
    FrameInspector's frame became a 105-130 px thumbnail beside its history chart at
    1024 x 768. Wrapping keeps each at its own width, or the column's when that is less
    (the pictures scale with ``max-width: 100%``, ``height: auto``); ``min-width`` keeps a
    picture from shrinking below :data:`READABLE_PX` while its neighbour still fits beside it.
    """
    for child in children:
        if isinstance(child, widgets.DOMWidget):
            child.layout.min_width = f"min({READABLE_PX}px, 100%)"
            child.layout.max_width = "100%"
    return widgets.HBox(list(children), layout=widgets.Layout(
        flex_flow="row wrap", align_items="flex-start", max_width="100%"))  # fmt: skip


def fit_width(layout: widgets.Layout) -> widgets.Layout:
    """``layout`` (of a control with a fixed width) that never gets wider than its column."""
    layout.max_width = "100%"
    return layout


def close_tree(widget) -> None:
    """Close a widget and, depth first, every widget inside it."""
    for child in getattr(widget, "children", ()):
        close_tree(child)
    widget.close()


#: The sample patterns the widgets offer: label -> (n, kind) of ``tr.sample_pattern``.
SAMPLE_PATTERNS = {
    "1 (centre)": (1, "standard"),
    "2 standard": (2, "standard"),
    "4 standard (rotated grid)": (4, "standard"),
    "4 ordered grid": (4, "grid"),
    "8 standard": (8, "standard"),
    "16 standard": (16, "standard"),
    "16 jittered": (16, "jittered"),
    "16 random": (16, "random"),
}


def pattern_samples(label: str):
    """``samples=`` for a chooser label: an int for the standard patterns, else offsets."""
    from ..core.sample_patterns import sample_pattern

    n, kind = SAMPLE_PATTERNS[label]
    return n if kind == "standard" else sample_pattern(n, kind)


class Shown:
    """What every figure widget shares: it shows ``self.widget`` (its box of controls and
    figure) and closes its figure display (``self.display``) with every control of the box.

    Displayed in a notebook, it leaves a stand-in before the widget (:func:`box_standin`: its
    title, text and picture), which a notebook saved and reopened without a kernel shows in
    place of "model not found"; the stand-in follows the picture once it settles
    (:data:`SETTLE_S` after the last change, so a drag sends no second copy of each frame).
    A widget with a box in ``self.widget`` but a base class of its own gets the same with
    ``_ipython_display_ = Shown._ipython_display_``.
    """

    #: how the stand-in's hint names the widget: "... to bring the <noun> back"
    noun = "explorer"

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    def _ipython_display_(self) -> None:
        import os
        import types
        import uuid

        if os.environ.get("TEACHRASTER_STATIC_PAGES") == "1":  # `teachraster html`: one output
            from IPython.display import display

            display(self._repr_mimebundle_(), raw=True)
            return
        noun = getattr(self, "noun", Shown.noun)  # also for a class that borrows this method
        standin = box_standin(self.widget, noun)
        self._standin_id = f"teachraster-standin-{uuid.uuid4().hex}"
        display_with_fallback(self._repr_mimebundle_(), standin, display_id=self._standin_id)
        follow = types.MethodType(Shown._update_standin, self)  # also where borrowed
        for w, name in _pictures(self.widget):
            w.observe(lambda _change: settle(follow), name)

    def _update_standin(self) -> None:
        from IPython.display import update_display

        noun = getattr(self, "noun", Shown.noun)
        update_display({"text/html": FALLBACK_CSS + box_standin(self.widget, noun),
                        "text/plain": STANDIN_PLAIN}, raw=True,
                       display_id=self._standin_id)  # fmt: skip

    def close(self) -> None:
        """Close the figure and every widget of the box."""
        self.display.close()
        close_tree(self.widget)


#: Shown with a widget's static fallback (JupyterLab's output classes; CSS ``:has``): while
#: the widget renders, the fallback is hidden; where its model is gone (a saved notebook
#: reopened, the kernel new), the widget's "Error displaying widget: model not found" is
#: hidden and the fallback stays. A text-only output area is the manager's message
#: ("Loading widget...", "Error ..."); a live view always holds elements.
FALLBACK_CSS = (
    "<style>"
    ".jp-OutputArea-child:has(.teachraster-static) + .jp-OutputArea-child"
    " .jp-OutputArea-output:not(:has(*)) {display: none}"
    ".jp-OutputArea-child:has(.teachraster-static)"
    ":has(+ .jp-OutputArea-child .jp-OutputArea-output *) {display: none}"
    "</style>"
)


#: An explorer's control labels, read-outs and status line at 16 px, not JupyterLab's 13:
#: read from the back of a lecture hall (review r81, 08-5 and 09-6)
PROJECTOR_CSS = (
    "<style>.tr-projector .tr-live-slider, .tr-projector .widget-label,"
    " .tr-projector .widget-toggle-button, .tr-projector select,"
    " .tr-projector .tr-drag-caption {font-size: 16px}</style>"
)


def projector_text(box: widgets.Box, title: widgets.HTML) -> widgets.Box:
    """``box`` (an explorer's widget) with its controls' text and status line at projector
    size (:data:`PROJECTOR_CSS`, carried by its ``title``, one of its children)."""
    box.add_class("tr-projector")
    title.value = PROJECTOR_CSS + title.value
    return box


#: The text/plain beside a stand-in (a front end without HTML).
STANDIN_PLAIN = "(the widget's last picture: Run All to bring the widget back)"


def display_with_fallback(bundle: dict, fallback_html: str, *, display_id: str | None = None
                          ) -> None:  # fmt: skip
    """Display a widget's mime ``bundle`` after an output holding ``fallback_html``.

    JupyterLab prefers the widget view of a display and shows "Error displaying widget:
    model not found" once its kernel is gone: a ``text/html`` beside it in the same output
    is never shown. In an output of its own the fallback is what a reopened notebook shows;
    :data:`FALLBACK_CSS` hides it while the live widget is on show. The widget's own
    output carries an empty ``text/html`` (:data:`VIEW_HTML`), so the stand-in stands
    once wherever that CSS is missing: an untrusted notebook (an nbconvert-executed copy)
    has its ``<style>`` removed by JupyterLab's sanitizer and renders ``text/html`` in place
    of the widget (its view is not a "safe" renderer), which showed every stand-in twice
    (review r158, 05a); a converter without the widgets' state shows that empty
    ``text/html`` too, not a second copy (``text/plain`` would show the widget's repr). With
    ``display_id`` the fallback can be replaced later (``update_display``), as the picture
    changes.
    """
    from IPython.display import publish_display_data

    transient = {"display_id": display_id} if display_id else None
    publish_display_data({"text/html": FALLBACK_CSS + fallback_html, "text/plain": STANDIN_PLAIN},
                         transient=transient)  # fmt: skip
    view = bundle[0] if isinstance(bundle, tuple) else bundle
    publish_display_data({**view, "text/html": VIEW_HTML})


#: The ``text/html`` of a widget's own output (:func:`display_with_fallback`): empty, so a
#: page that renders it in place of the widget shows the stand-in above it, once
VIEW_HTML = ""


def standin_hint(noun: str) -> str:
    """The hint of every stand-in: what brings the widget back once its kernel is gone.

    Run All, not "run this cell": in a reopened notebook the cell's names (the imports, the
    triangle) come from the cells above it, so running it alone fails with ``NameError``.
    """
    return (f"<p><i>No kernel is running this {html.escape(noun)}: Run All (Run ▸ Run All "
            f"Cells) to bring it back (this cell needs the cells above it).</i></p>")  # fmt: skip


def standin_html(title: str, noun: str, picture: bytes = b"", text: str = "",
                 pictures: tuple = ()) -> str:  # fmt: skip
    """What a saved notebook shows once the kernel is gone: the ``title``, ``text`` (HTML,
    e.g. a question), the hint (:func:`standin_hint`), then ``picture`` and ``pictures``
    (PNG bytes: the last pictures the widget showed)."""
    imgs = "".join(
        f'<img alt="the {html.escape(noun)} as it was last drawn" '
        f'src="data:image/png;base64,{base64.b64encode(png).decode("ascii")}" '
        'style="max-width:100%">'
        for png in (picture, *pictures)
        if png
    )
    head = f"<div><b>{html.escape(title)}</b></div>" if title else ""
    body = f"<div>{text}</div>" if text else ""
    return f'<div class="teachraster-static">{head}{body}{standin_hint(noun)}{imgs}</div>'


def choices_html(labels) -> str:
    """``labels`` (HTML) as a row of boxes that look like the widget's buttons: a stand-in's
    choices, which a reader of the saved notebook can still answer in their head."""
    return "".join(
        "<span style='display:inline-block;border:1px solid #999;border-radius:3px;"
        f"padding:1px 8px;margin:2px 6px 2px 0'>{label}</span>"
        for label in labels
    )


def _pictures(box) -> list:
    """``(widget, trait)`` of every picture in ``box``'s tree, depth first: an
    ``ipywidgets.Image``'s ``value``, a page figure's ``poster``, the ``value`` bytes of any
    other picture widget (the FrameInspector's clickable frame: review r90 11-5, without it
    the saved inspector showed its history chart alone)."""
    import traitlets

    found = []
    for child in getattr(box, "children", ()):
        found += _pictures(child)
    if isinstance(box, widgets.Image):
        found.append((box, "value"))
    elif hasattr(box, "has_trait") and box.has_trait("poster"):
        found.append((box, "poster"))
    elif hasattr(box, "traits") and isinstance(box.traits().get("value"), traitlets.Bytes):
        found.append((box, "value"))
    return found


def box_standin(box, noun: str) -> str:
    """A stand-in for any widget box: the text of its HTML widgets (the title, the info
    lines) and its pictures as they are now, with the hint."""
    texts = []

    def walk(w):
        if isinstance(w, widgets.HTML) and w.value:
            texts.append(w.value)
        for child in getattr(w, "children", ()):
            walk(child)

    walk(box)
    pngs = []
    for w, name in _pictures(box):
        value = getattr(w, name)  # an Image's value is a memoryview
        png = bytes(value) if isinstance(value, bytes | bytearray | memoryview) else b""
        if png.startswith(b"\x89PNG"):
            pngs.append(png)
    return standin_html("", noun, text="".join(texts), pictures=tuple(pngs))


#: Seconds a stand-in waits after the last change of a picture before it follows it.
SETTLE_S = 1.0
_settling: dict = {}


def settle(callback) -> None:
    """Call ``callback`` once nothing has asked for it for :data:`SETTLE_S` seconds (each
    call restarts the wait); without a running event loop (plain Python, tests), now."""
    import asyncio

    try:
        loop = asyncio.get_running_loop()
    except RuntimeError:
        callback()
        return
    key = id(getattr(callback, "__self__", callback)), getattr(callback, "__name__", "")
    waiting = _settling.pop(key, None)
    if waiting is not None:
        waiting.cancel()

    def run():
        if messages_waiting():  # a student's message first (review r400 W1)
            _settling[key] = loop.call_later(WAIT_POLL_S, run)
            return
        _settling.pop(key, None)
        with DRAWING:
            callback()

    _settling[key] = loop.call_later(SETTLE_S, run)


#: Seconds a deferred redraw waits (see :func:`later`).
LATER_S = 0.05
_later: dict = {}


def later(callback, *, idle_only: bool = False) -> None:
    """Call ``callback`` once the kernel has answered what it is doing (soon, not now).

    A toggle's new picture goes to the page first; a slower second figure (the player's
    comparison: a few hundred ms of colour bars on a loaded machine) is drawn from the
    kernel's event loop a moment later, so that a second toggle arriving meanwhile is
    answered first, and the figure drawn once for both (a callback already waiting is not
    scheduled again). It waits further while a widget message waits in the kernel
    (:func:`messages_waiting`). Without a running event loop (plain Python, tests) it is
    called now, or not at all with ``idle_only`` (work worth doing only while a kernel idles).
    """
    import asyncio

    try:
        loop = asyncio.get_running_loop()
    except RuntimeError:
        if not idle_only:
            callback()
        return
    key = id(getattr(callback, "__self__", callback)), getattr(callback, "__name__", "")
    if key in _later:
        return

    def run():
        if messages_waiting():  # a student's message first (review r400 W1)
            _later[key] = loop.call_later(WAIT_POLL_S, run)
            return
        _later.pop(key, None)
        with DRAWING:
            callback()

    _later[key] = loop.call_later(LATER_S, run)


#: Held while a widget's message is handled and while the kernel's event loop draws on its
#: own (pictures drawn ahead, a deferred redraw). ipykernel 7 handles some widget messages
#: on another thread than its event loop: a format toggled while the loop drew the pictures
#: ahead (which set the explorer to another state and put it back) had its new state
#: overwritten by the one put back, or its picture drawn from a half-changed figure
#: (review r5, lesson 05b: float32 shown under a caption saying reverse-Z, a blank picture,
#: "near 0.112" while the slider read 0.1). Re-entrant: a handler may schedule or draw.
DRAWING = threading.RLock()


def _serialize_widget_messages() -> None:
    """Every ipywidgets message (a control changed, a page's custom message) is handled
    holding :data:`DRAWING`, so that nothing the event loop draws runs in the middle of it."""
    handle = widgets.Widget._handle_msg
    if getattr(handle, "_teachraster_serialized", False):
        return

    def handle_msg(self, msg):
        try:
            with DRAWING:
                return handle(self, msg)
        finally:
            _message_handled()

    handle_msg._teachraster_serialized = True
    widgets.Widget._handle_msg = handle_msg


_serialize_widget_messages()

#: Longest the work done ahead waits for widget messages said to have reached the kernel: one
#: that never reaches a widget (its widget closed meanwhile) holds nothing back for longer
WAIT_MOST_S = 2.0
#: Seconds between two looks whether the widget messages that came are handled
WAIT_POLL_S = 0.01
_waiting = {"count": 0, "since": 0.0}
_waiting_lock = threading.Lock()


def messages_waiting() -> bool:
    """True while a widget message (a Check, a toggle, a slider's value) has reached the kernel
    and is not handled yet: the work done while the kernel idles (pictures drawn ahead, truths
    kept, deferred redraws, stand-ins) waits for it.

    Review r400 W1 (lesson 09): ipykernel 7 handles a message over several turns of its event
    loop (its shell channel's thread forwards it, two tasks, the dispatch), and at every turn
    ``FilterExplorer`` drew a truth and a picture ahead: a pixel marked right after Run All was
    handled 1.7 s after it came (load 2-8; 43 s at load 12), and the page's widget manager
    held the Check until then. The message is seen on arrival, on the shell channel's thread
    (:func:`_count_arrivals`); where the kernel has no such thread (ipykernel 6), never.
    """
    import time

    with _waiting_lock:
        if _waiting["count"] and time.monotonic() - _waiting["since"] > WAIT_MOST_S:
            _waiting["count"] = 0  # lost on its way: nothing to wait for
        return _waiting["count"] > 0


def message_arrived() -> None:
    """A widget message reached the kernel (called on the thread that receives it)."""
    import time

    with _waiting_lock:
        _waiting["count"] += 1
        _waiting["since"] = time.monotonic()


def _message_handled() -> None:
    import time

    with _waiting_lock:
        _waiting["count"] = max(0, _waiting["count"] - 1)
        _waiting["since"] = time.monotonic()


def _count_arrivals() -> None:
    """Count every widget message as it reaches the kernel: ipykernel 7's shell channel thread
    asks the message's comm where to route the reply (``_reply_subshell_for``), the moment it
    forwards the message to the thread that handles it. Only the messages that
    :func:`_serialize_widget_messages`'s handler will count as handled are counted: ipywidgets
    messages (their data has a ``method``) to a widget whose comm calls that handler (not
    the widgets' control comm, nor a widget made before this module was imported), so
    that no message is counted that is never counted handled."""
    try:
        from ipykernel.comm.comm import BaseComm
    except ImportError:  # pragma: no cover - ipykernel comes with ipywidgets
        return
    route = getattr(BaseComm, "_reply_subshell_for", None)
    if route is None or getattr(route, "_teachraster_counted", False):
        return

    def counted(self, data, default):
        handler = getattr(getattr(self, "_msg_callback", None), "__func__", None)
        if handler is widgets.Widget._handle_msg and isinstance(data, dict) and "method" in data:
            message_arrived()
        return route(self, data, default)

    counted._teachraster_counted = True
    BaseComm._reply_subshell_for = counted


_count_arrivals()

_cell = threading.local()


def _hold_drawing(*_args) -> None:
    DRAWING.acquire()
    _cell.held = getattr(_cell, "held", 0) + 1


def _let_go_of_drawing(*_args) -> None:
    # the cell that imported this module ends without having taken the lock: nothing to do
    if getattr(_cell, "held", 0) > 0:
        _cell.held -= 1
        DRAWING.release()


def _cells_hold_drawing(shell=None) -> None:
    """A notebook cell runs holding :data:`DRAWING`.

    With ipykernel 7 a widget's messages may be handled on a subshell's thread, and the
    pictures drawn ahead run there too (``widgets.ahead``): they set an explorer to another
    slider position and put it back. A cell reading the explorer meanwhile saw that other
    state (stop 45's CI: ``ex.values`` of a picture drawn ahead after a PlaneExplorer drag's
    release). Holding the lock for the cell makes such drawing wait for it.
    """
    if shell is None:
        try:
            from IPython import get_ipython
        except ImportError:  # pragma: no cover - IPython comes with ipywidgets
            return
        shell = get_ipython()
    if shell is None or getattr(shell, "_teachraster_cells_hold_drawing", False):
        return
    shell._teachraster_cells_hold_drawing = True
    shell.events.register("pre_run_cell", _hold_drawing)
    shell.events.register("post_run_cell", _let_go_of_drawing)


_cells_hold_drawing()
