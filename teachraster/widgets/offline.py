"""Widgets in an offline page: what ``teachraster html`` shows of each, with no kernel.

A lesson exported as one HTML page has no kernel behind it, so no widget can run there. Every
widget of this package is shown by :func:`offline_page` instead, which gives, best first:

1. what the widget's own hook ``_offline_page_()`` returns (:class:`OfflinePage`), for a
   widget that knows better (``FillPlayer``: every step of its fill; ``Predict``: the
   question with its answer folded away);
2. **live**, a slider over pictures drawn ahead: the widget's figure at every position of
   the slider its page draws ahead (:mod:`.ahead`), or of the control it names in the
   class attribute ``_offline_sweep_`` (a step, a triangle, a block): stepped through in the
   page by the offline frames player (:mod:`teachraster.plotting.pages`), with the caption
   of each position;
3. **pictured**: a snapshot of its widget tree as it is (titles, captions, the values of its
   controls and every picture), for a widget whose pictures cannot all be drawn ahead.

A widget is **missing** when none of these gives a picture (the page says so in words).

``teachraster html`` runs :func:`install` in the kernel first: it makes IPython display
every widget class of the package (:func:`widget_classes`) through :func:`offline_page`, as
one HTML output whose metadata says how (``{"teachraster": {"widget": ..., "kind": ...}}``),
which the command counts per lesson.
"""

from __future__ import annotations

import base64
import contextlib
import html
import importlib
import inspect
import io
import pkgutil
import re
import threading
from dataclasses import dataclass

import ipywidgets as widgets
import numpy as np

from ..plotting.frames import encode_png, frame_rgba
from .dragging import DragFigure

#: How an offline page shows a widget (the command counts them per lesson).
KINDS = ("live", "pictured", "missing")

#: Most positions a slider is shown at (a picture each, in the page): a longer range keeps
#: every second (third, ...) position, and its last. At 64 a lesson's page reached 10 MB
#: (lesson 04: two slider explorers, 46 and 51 pictures of a notebook-wide figure each).
MOST_POSITIONS = 32
#: Most positions of an integer control (a step, a triangle, a block: a player's steps,
#: whose pictures differ by a patch): 128 (lesson 10's 864 blocks then go 7 at a time).
MOST_STEPS = 128

#: Classes of the package that are parts of other widgets, or bases of them, not widgets of a
#: lesson.
PARTS = ("DragFigure", "FramesWidget", "LiveSlider", "Explorable", "FigurePrediction")

_PNG = b"\x89PNG\r\n\x1a\n"


@dataclass(frozen=True)
class OfflinePage:
    """A widget in an offline page: ``html`` (self-contained: no address is fetched) and
    ``kind``, one of :data:`KINDS`."""

    html: str
    kind: str

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"kind must be one of {KINDS}, got {self.kind!r}")


# -- the dispatcher --------------------------------------------------------------------------
def offline_page(obj) -> OfflinePage:
    """How ``obj`` (a widget of this package) looks in an offline page (see the module)."""
    name = type(obj).__name__
    try:
        hook = getattr(obj, "_offline_page_", None)
        page = hook() if callable(hook) else (ahead_page(obj) or swept_page(obj))
        page = page or snapshot_page(obj)
    except Exception as error:  # an export goes on: the page says what went wrong
        text = f"{name} could not be drawn for this page: {type(error).__name__}: {error}"
        page = OfflinePage(f"<p><i>{html.escape(text)}</i></p>", "missing")
    marker = f'<div class="teachraster-offline" data-kind="{page.kind}" data-widget="{name}">'
    return OfflinePage(f"{marker}{page.html}</div>", page.kind)


def widget_classes() -> list[type]:
    """Every class of :mod:`teachraster.widgets` that a notebook can display (it has
    ``_ipython_display_`` or ``_repr_mimebundle_``), from every module of the package."""
    import teachraster.widgets as package

    found: dict[str, type] = {}
    for info in pkgutil.iter_modules(package.__path__):
        module = importlib.import_module(f"{package.__name__}.{info.name}")
        for _, cls in inspect.getmembers(module, inspect.isclass):
            if not cls.__module__.startswith(package.__name__):
                continue
            if hasattr(cls, "_ipython_display_") or hasattr(cls, "_repr_mimebundle_"):
                found[f"{cls.__module__}.{cls.__qualname__}"] = cls
    return [found[k] for k in sorted(found)]


def install(shell=None) -> int:
    """Display every widget class of the package through :func:`offline_page` in IPython
    ``shell`` (the running one by default). Returns the number of classes.

    IPython asks its ``ipython_display_formatter`` first, and there printers registered
    for a type come before the object's own ``_ipython_display_``: a widget then shows as
    one HTML output, whatever its own display does where a kernel runs.
    """
    if shell is None:
        from IPython import get_ipython

        shell = get_ipython()
    formatter = shell.display_formatter.ipython_display_formatter
    classes = widget_classes()
    for cls in classes:
        formatter.for_type(cls, _display)
    return len(classes)


def _display(obj) -> None:
    from IPython.display import publish_display_data

    page = offline_page(obj)
    name = type(obj).__name__
    publish_display_data(
        {"text/html": page.html, "text/plain": f"{name} ({page.kind} in this page)"},
        metadata={"teachraster": {"widget": name, "kind": page.kind}},
    )


# -- live: a slider over pictures ------------------------------------------------------------
def ahead_page(obj) -> OfflinePage | None:
    """A slider over the pictures a slider explorer draws ahead (:mod:`.ahead`): its figure
    at every position of that slider, as a final picture (not a draft). None when the
    widget draws nothing ahead."""
    ahead = getattr(getattr(obj, "display", None), "frames_ahead", None)
    if ahead is None or ahead.closed:
        return None
    from .ahead import draw_elsewhere

    explorer, slider = ahead.explorer, ahead.slider
    which = [ahead.which] if len(ahead.sliders) > 1 else []
    values = thin([float(v) for v in ahead.values])
    pictures, captions = [], []
    for value in values:
        rgba, caption, _ = draw_elsewhere(
            ahead.display, explorer, lambda v=value: explorer._compute_at(v, *which)
        )
        pictures.append(rgba)
        captions.append(html_text(caption))
    here = nearest(values, slider.value)
    infos = _position_infos(slider, values)
    return _player_page(obj, pictures, captions, infos, here)


def swept_page(obj) -> OfflinePage | None:
    """A slider over the widget's pictures at every position of the control named by its
    class attribute ``_offline_sweep_`` (None when it names none).

    The control is set to each position as a student would set it (in a thread of its own,
    so that redraws the widget defers to the kernel's event loop happen at once, and with
    the widgets' messages to the page held back), the pictures on show are kept with the
    texts that changed, and the control is put back.
    """
    name = getattr(type(obj), "_offline_sweep_", None)
    if not name:
        return None
    control = getattr(obj, name)
    values = control_positions(control)
    if len(values) < 2:
        return None
    tree = obj.widget
    start = control.value
    shots: list = []
    failed: list = []

    def sweep() -> None:
        try:
            for value in values:
                control.value = value
                shots.append((_pictures(tree), _texts(tree)))
            control.value = start
        except Exception as error:  # raised in the main thread below
            failed.append(error)

    with _held(tree):
        worker = threading.Thread(target=sweep, name="teachraster-offline-sweep")
        worker.start()
        worker.join()
    if failed:
        raise failed[0]
    pictures = [_stack(pics) for pics, _ in shots]
    varying = [i for i in range(len(shots[0][1])) if len({t[i] for _, t in shots}) > 1]
    captions = [" · ".join(texts[i] for i in varying) for _, texts in shots]
    here = nearest(values, start)
    return _player_page(obj, pictures, captions, _position_infos(control, values), here)


def control_positions(control) -> list:
    """Every value a slider (int, float, log or selection) or a menu can take, in order,
    thinned (:func:`thin`) to :data:`MOST_STEPS` for an integer slider, else to
    :data:`MOST_POSITIONS`."""
    if hasattr(control, "options") and not hasattr(control, "step"):
        values = [v for _, v in _labelled_options(control)]
    else:
        lo, hi, step = control.min, control.max, control.step
        n = int(np.floor((hi - lo) / step + 1e-9)) + 1
        values = list(np.round(lo + step * np.arange(n), 10))
        base = getattr(control, "base", None)
        if isinstance(control, widgets.FloatLogSlider) and base:
            values = [float(base**v) for v in values]
        elif isinstance(control, widgets.IntSlider):
            return thin([int(v) for v in values], MOST_STEPS)
        else:
            values = [float(v) for v in values]
    return thin(values)


def thin(values: list, most: int | None = None) -> list:
    """About ``most`` (:data:`MOST_POSITIONS`) of ``values``, one more at most: every k-th,
    and the last.

    >>> thin(list(range(91)))[:3], len(thin(list(range(91))))
    ([0, 3, 6], 31)
    """
    most = MOST_POSITIONS if most is None else most
    stride = max(1, -(-(len(values) - 1) // (most - 1)))
    kept = values[::stride]
    return kept if kept[-1] == values[-1] else [*kept, values[-1]]


def nearest(values: list, value) -> int:
    """The index of the position nearest ``value`` (the first of equals; 0 for an option
    that is not a number and not among them)."""
    if value in values:
        return values.index(value)
    try:
        return int(np.argmin(np.abs(np.asarray(values, dtype=float) - float(value))))
    except (TypeError, ValueError):
        return 0


def _labelled_options(control) -> list:
    options = list(control.options)
    return [o if isinstance(o, tuple) else (str(o), o) for o in options]


def _position_infos(control, values) -> list[str]:
    label = getattr(control, "description", "") or "position"
    last = len(values) - 1
    return [f"of {last}: {label} = {_fmt(v)}" for v in values]


def _fmt(value) -> str:
    return f"{value:g}" if isinstance(value, float) else str(value)


def _player_page(obj, pictures, captions, infos, step) -> OfflinePage:
    """The frames player over ``pictures``, under the widget's title (its first text)."""
    from ..plotting.pages import player_fragment, sequence_data

    title = _title(obj)
    alt = html_text(title) or f"the {type(obj).__name__}'s picture at each position"
    data = sequence_data(pictures, captions, infos, step=step, alt=alt[:200])
    kind = "live" if len(data["groups"]) and _distinct(pictures) > 1 else "pictured"
    return OfflinePage(f"{title}{player_fragment(data)}", kind)


def _distinct(pictures) -> int:
    return len(
        {(p.shape, p.tobytes()) for p in pictures[:4]}
        | {(p.shape, p.tobytes()) for p in pictures[-4:]}
    )


def _title(obj) -> str:
    """The widget's title: the first text of its tree (every widget starts with one)."""
    for child in _walk(getattr(obj, "widget", None)):
        if isinstance(child, (widgets.HTML, widgets.HTMLMath)):
            return child.value
        if hasattr(child, "children") or isinstance(child, widgets.Label):
            continue
        break
    return ""


@contextlib.contextmanager
def _held(tree):
    """Hold back every widget's state messages to the page (sent once, at the end)."""
    with contextlib.ExitStack() as stack:
        for w in _walk(tree):
            stack.enter_context(w.hold_sync())
        yield


# -- pictured: a snapshot of the widget tree -------------------------------------------------
def snapshot_page(obj) -> OfflinePage:
    """The widget's tree as it is: texts, the values of its controls, every picture."""
    tree = getattr(obj, "widget", obj if isinstance(obj, widgets.Widget) else None)
    if tree is None:
        return OfflinePage("<p><i>(this widget has nothing to show without a kernel)</i></p>",
                           "missing")  # fmt: skip
    counted: list = []
    body = snapshot_html(tree, counted)
    return OfflinePage(body, "pictured" if counted else "missing")


def snapshot_html(widget, pictures: list | None = None) -> str:
    """HTML of ``widget`` and its children as they are now; each picture shown is appended
    to ``pictures``."""
    pictures = [] if pictures is None else pictures
    picture = _picture(widget)
    if picture is not None:
        pictures.append(picture)
        return _img(picture, getattr(widget, "alt", "") or "the widget's picture")
    if isinstance(widget, (widgets.HTML, widgets.HTMLMath)):
        return f"<div>{widget.value}</div>"
    if isinstance(widget, widgets.Label):
        return f"<div>{html.escape(str(widget.value))}</div>"
    if isinstance(widget, widgets.Output):
        return "".join(_output_html(out, pictures) for out in widget.outputs)
    children = getattr(widget, "children", None)
    if children is not None:
        return _box_html(widget, children, pictures)
    return _control_html(widget)


def _box_html(widget, children, pictures) -> str:
    parts = [snapshot_html(c, pictures) for c in children]
    titles = getattr(widget, "titles", None)
    if titles:  # an Accordion or Tab: each child under its title
        parts = [f"<div><b>{html.escape(str(t or ''))}</b>{p}</div>" for t, p in zip(titles, parts)]
    row = isinstance(widget, (widgets.HBox, widgets.GridBox))
    style = ("display:flex;flex-wrap:wrap;gap:8px;align-items:flex-start" if row
             else "display:flex;flex-direction:column;gap:4px")  # fmt: skip
    return f'<div style="{style}">{"".join(p for p in parts if p)}</div>'


def _control_html(widget) -> str:
    """A control as text: its label and value (nothing for buttons and players)."""
    if not hasattr(widget, "value") or isinstance(widget, (widgets.Button, widgets.Play)):
        return ""
    label = getattr(widget, "description", "") or ""
    value = getattr(widget, "label", None) if hasattr(widget, "options") else None
    value = widget.value if value is None else value
    if isinstance(value, (bytes, bytearray, memoryview)):
        return ""
    text = f"{label}: {_fmt(value)}" if label else _fmt(value)
    return f'<div style="color:#444;font-size:90%">{html.escape(text)}</div>'


def _output_html(out: dict, pictures: list) -> str:
    data = out.get("data", {})
    if "image/png" in data:
        png = data["image/png"]
        png = base64.b64decode(png) if isinstance(png, str) else png
        pictures.append(png)
        return _img(png, "a figure")
    if "text/html" in data:
        return str(data["text/html"])
    text = data.get("text/plain", out.get("text", ""))
    return f"<pre>{html.escape(str(text))}</pre>" if text else ""


def _picture(widget):
    """The picture a figure widget shows now: PNG bytes or an RGBA array, else None."""
    last = getattr(widget, "_last", None)  # a page figure: the last picture it sent
    if isinstance(last, np.ndarray) and last.ndim == 3:
        return last
    for trait in ("value", "poster"):
        data = getattr(widget, trait, None) if widget.has_trait(trait) else None
        if isinstance(data, (bytes, bytearray, memoryview)) and bytes(data[:8]) == _PNG:
            return bytes(data)  # an Image's value comes back as a memoryview
    figure = getattr(widget, "figure", None)  # an ipympl canvas
    if figure is not None and hasattr(figure, "canvas"):
        figure.canvas.draw()
        return frame_rgba(figure)
    return None


def _img(picture, alt: str) -> str:
    png = encode_png(picture) if isinstance(picture, np.ndarray) else picture
    width = int.from_bytes(png[16:20], "big")
    src = base64.b64encode(png).decode("ascii")
    return (f'<img class="teachraster-picture" alt="{html.escape(html_text(alt), quote=True)}" '
            f'width="{width}" style="max-width:100%;height:auto" '
            f'src="data:image/png;base64,{src}">')  # fmt: skip


def _pictures(tree) -> list[np.ndarray]:
    """Every picture in the tree now, as RGBA arrays."""
    return [_rgba(p) for p in map(_picture, _walk(tree)) if p is not None]


def _texts(tree) -> list[str]:
    """The plain text of every text widget of the tree, and of every page figure's caption
    (the line above a slider explorer's picture), in order."""
    texts = []
    for w in _walk(tree):
        if isinstance(w, (widgets.HTML, widgets.HTMLMath, widgets.Label)):
            texts.append(html_text(w.value))
        elif isinstance(w, DragFigure):
            texts.append(html_text(w.caption))
    return texts


def _walk(widget):
    """The widget and, depth first, every widget inside it."""
    if widget is None:
        return
    yield widget
    for child in getattr(widget, "children", ()) or ():
        yield from _walk(child)


def _rgba(picture) -> np.ndarray:
    if isinstance(picture, np.ndarray):
        return picture
    from matplotlib.image import imread

    image = imread(io.BytesIO(picture), format="png")
    if image.shape[2] == 3:
        image = np.concatenate([image, np.ones(image.shape[:2] + (1,), image.dtype)], axis=2)
    return (image * 255 + 0.5).astype(np.uint8) if image.dtype != np.uint8 else image


def _stack(pictures: list[np.ndarray]) -> np.ndarray:
    """Several pictures one above the other (white where narrower), one as it is."""
    if len(pictures) == 1:
        return pictures[0]
    if not pictures:
        return np.full((1, 1, 4), 255, np.uint8)
    width = max(p.shape[1] for p in pictures)
    out = [np.pad(p, ((0, 0), (0, width - p.shape[1]), (0, 0)), constant_values=255)
           for p in pictures]  # fmt: skip
    return np.concatenate(out, axis=0)


def html_text(fragment: str) -> str:
    """The text of an HTML fragment: tags dropped, entities read, spaces collapsed.

    >>> html_text("<b>tilt</b> 30&deg; &middot; <i>λ</i> = 2")
    'tilt 30° · λ = 2'
    """
    text = re.sub(r"<(br|/p|/div|/tr)\b[^>]*>", " ", str(fragment), flags=re.IGNORECASE)
    text = html.unescape(re.sub(r"<[^>]+>", "", text))
    return re.sub(r"\s+", " ", text).strip()
