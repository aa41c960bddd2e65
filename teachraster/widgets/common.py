"""Pieces every widget shares: style handling, figure layout for a FillView, titles."""

from __future__ import annotations

import contextlib

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


def fill_axes(fig, width: int, height: int, *, side: float = 4.4, legend: bool = True):
    """Size ``fig`` for a FillView of a ``width`` × ``height`` grid and add its Axes.

    Fixed margins (no layout engine, which would run again at every step): room above for
    the view's header and the column labels, on the left for the row labels, on the right
    for the view's colour key. ``side`` is the longer side of the grid in inches.
    """
    s = font_scale()
    if width >= height:
        aw, ah = side, side * height / width
    else:
        aw, ah = side * width / height, side
    left, right = 0.65 * s, (2.1 * s if legend else 0.25)
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
    label = widgets.Label(text, layout=widgets.Layout(width="auto", margin="0 8px 0 0"))
    return widgets.HBox(
        [label, control], layout=widgets.Layout(align_items="center", margin="0 24px 0 0")
    )


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
    figure) and closes its figure display (``self.display``) with every control of the box."""

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

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


def display_with_fallback(bundle: dict, fallback_html: str) -> None:
    """Display a widget's mime ``bundle`` after an output holding ``fallback_html``.

    JupyterLab prefers the widget view of a display and shows "Error displaying widget:
    model not found" once its kernel is gone: a ``text/html`` beside it in the same output
    is never shown. In an output of its own the fallback is what a reopened notebook shows;
    :data:`FALLBACK_CSS` hides it while the live widget is on show. The bundle keeps its
    own ``text/html`` (a converter without the widgets' state shows that one, in place of
    the widget; the separate fallback is then hidden, as beside a live widget).
    """
    from IPython.display import publish_display_data

    publish_display_data({"text/html": FALLBACK_CSS + fallback_html,
                          "text/plain": "(the widget's picture: run the cell for the widget)"})  # fmt: skip
    publish_display_data(bundle[0] if isinstance(bundle, tuple) else bundle)


#: Seconds a deferred redraw waits (see :func:`later`).
LATER_S = 0.05
_later: dict = {}


def later(callback, *, idle_only: bool = False) -> None:
    """Call ``callback`` once the kernel has answered what it is doing (soon, not now).

    A toggle's new picture goes to the page first; a slower second figure (the player's
    comparison: a few hundred ms of colour bars on a loaded machine) is drawn from the
    kernel's event loop a moment later, so that a second toggle arriving meanwhile is
    answered first, and the figure drawn once for both (a callback already waiting is not
    scheduled again). Without a running event loop (plain Python, tests) it is called now,
    or not at all with ``idle_only`` (work worth doing only while a kernel idles).
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
        _later.pop(key, None)
        callback()

    _later[key] = loop.call_later(LATER_S, run)
