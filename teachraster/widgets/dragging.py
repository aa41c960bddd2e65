"""Dragging in the page: a figure whose points are moved by pointer events (``static/drag.js``).

The page shows the figure as an ``<img>`` and draws the pointer feedback itself (a ring at
the pointer); the kernel hears of positions through custom messages with their own flow
control: at most two positions unanswered (one rendered, one waiting, so the kernel does
not idle for a round trip), each the latest when sent (positions that arrive meanwhile are
coalesced, never queued), and the release position always, so the drag ends exactly where
the pointer let go. Each answer is the re-rendered figure.

For the kernel to keep up, the editor redraws only what a move changes: the plans below
keep the pixel grid, tick labels, centres and legend in a cached background
(:class:`~teachraster.plotting.blitting.LayeredBlit`) and draw only the triangle's artists.
"""

from __future__ import annotations

import time
import zlib
from contextlib import contextmanager
from pathlib import Path

import anywidget
import numpy as np
import traitlets

from ..plotting.blitting import MOVING, STILL, LayeredBlit
from ..plotting.frames import changed_box, encode_png, frame_rgba, keys_js
from .common import later

#: When (``time.perf_counter()``) a figure of this kernel last heard of a point dragged in
#: the page, mid-drag (:func:`dragged_within`)
_last_move = [0.0]


def dragged_within(seconds: float) -> bool:
    """True when a point of any figure in this kernel was dragged in the page (not released)
    within the last ``seconds``: work done while the kernel idles (pictures drawn ahead,
    :mod:`~teachraster.widgets.ahead`) waits, and the drag's positions are answered at once."""
    return time.perf_counter() - _last_move[0] < seconds


def drag_js() -> str:
    """The page-side module (ESM), read from the package (``static/drag.js``)."""
    return keys_js() + (Path(__file__).parent / "static" / "drag.js").read_text(encoding="utf-8")


def fill_edit_blit(view) -> LayeredBlit:
    """A blit of a FillView whose triangle moves: only the grid and the centres stay."""
    still = [view.grid.lines, *view.ax.spines.values()]
    if view.centres is not None:
        still += [view.centres.inside, view.centres.outside]
    t, r, p, s, b = view.triangle, view.raster_line, view.pixel, view.split, view.bbox
    parts = [view.rejected, view.coverage.image, r.band, b.outline, b.cells, s.line,
             t.outline, *t.arrows, t.vertices, r.cells, p.box, r.span, p.centre, s.point,
             s.label, *t.labels, *t.edge_labels, *getattr(s, "artists", [])]  # fmt: skip
    moving = sorted({id(a): a for a in parts}.values(), key=lambda a: a.get_zorder())
    level = min(a.get_zorder() for a in still)
    below = [a for a in moving if a.get_zorder() < level]
    above = [a for a in moving if a.get_zorder() >= level]
    return LayeredBlit(view.fig, [(MOVING, below), (STILL, still), (MOVING, above)])


def comparison_edit_blit(view) -> LayeredBlit:
    """A blit of an InterpolationView whose fill changes (or a ComparisonView whose images
    change): images, outlines, colour bars, the heatmap's title and its marked maximum
    move (and an InterpolationView's profile); the grids, panel titles and "in use" notes
    stay."""
    images = [art.image for art in view.images] + [view.heatmap.image]
    # the frames too: the images are painted up to the Axes' edge, the frames drawn over them
    still = [g.lines for g in view.grids if g is not None]
    still += [s for ax in view.axes for s in ax.spines.values()]
    bars = [art.colorbar.ax for art in [*view.images, view.heatmap]
            if getattr(art, "colorbar", None) is not None]  # fmt: skip
    tris = [a for tri in getattr(view, "triangles", []) for a in tri.artists]
    profile = getattr(view, "profile", None)  # an InterpolationView's values along a row
    along = [] if profile is None else [*profile.guides, profile.title.axes]
    return LayeredBlit(view.fig, [(MOVING, images), (STILL, still),
                                  (MOVING, [*tris, view.heatmap.marker, view.heatmap.note,
                                            view.heatmap.title, *bars, *along])])  # fmt: skip


class DragFigure(anywidget.AnyWidget):
    """A figure in the page whose ``handles`` (data coordinates) can be dragged.

    ``transform`` maps data to figure pixels from the top left: ``[x0, y0, sx, sy]`` with
    ``px = x0 + sx * x`` and ``py = y0 + sy * y``. ``poster`` is the picture a new view
    shows first; later pictures arrive as messages. ``on_move(i, x, y, final)`` is called
    for each position the page sends and must re-render (then :meth:`show` the figure).

    With ``reference`` (the slider explorers) every picture after the first goes as a patch
    against one *reference* picture the page keeps (frame ``ref_frame``): the page puts back
    the reference where the last patch was, then paints the new one. A picture then never
    depends on which came before it, so the page may also show pictures drawn ahead
    (:meth:`send_ahead`, :class:`~teachraster.widgets.ahead.FramesAhead`) in any order,
    without asking the kernel. ``caption`` is an HTML line the page shows above the picture
    (each picture drawn ahead brings its own).
    """

    _esm = drag_js()
    poster = traitlets.Bytes(b"").tag(sync=True)
    handles = traitlets.List().tag(sync=True)
    transform = traitlets.List([0.0, 0.0, 1.0, 1.0]).tag(sync=True)
    size = traitlets.List([1, 1]).tag(sync=True)
    alt = traitlets.Unicode("").tag(sync=True)
    #: the frame number of ``poster`` (the patches that follow it are numbered on)
    poster_frame = traitlets.Int(0).tag(sync=True)
    #: reference mode: the frame number of the reference picture (0: none yet)
    ref_frame = traitlets.Int(0).tag(sync=True)
    #: what the page's slider that drives this figure names it by (pictures drawn ahead)
    key = traitlets.Unicode("").tag(sync=True)
    caption = traitlets.Unicode("").tag(sync=True)
    #: where the caption goes: "top" (a line above the picture) or "right" (beside it)
    caption_side = traitlets.Unicode("top").tag(sync=True)

    def __init__(self, on_move=None, *, reference: bool = False, deflate: bool = False,
                 **kwargs) -> None:  # fmt: skip
        super().__init__(**kwargs)
        self.on_move = on_move
        #: patches against one reference picture, finals too (see the class); the poster
        #: follows each final picture, for a view opened later
        self.reference = reference
        #: patches zlib-compressed (level 1: 1-3 ms for 0.2-1.4 MB of figure, 20-40 times
        #: smaller), inflated by the page at once (DecompressionStream, no image decoder):
        #: a whole plot's changed pixels are megabytes a frame for the server and page
        self.deflate = deflate
        self.moves = 0
        self._seq = 0
        #: per view of the page, the number of the last release handled (see _stale)
        self._released: dict = {}
        self._t0 = 0.0
        self._last = None  # the last picture sent: patches are computed against it
        self._ref = None  # reference mode: the picture patches are computed against
        self._posted = None  # the picture of the poster (reference: skip an unchanged one)
        self._poster_rgba = None  # reference mode: the final picture waiting to be posted
        self._frame = 0
        #: True while a position dragged in the page (not the release) is answered
        self.in_drag = False
        #: the caption of the picture being answered mid-drag (None: the ``caption`` trait)
        self.drag_caption: str | None = None
        #: called when the page asks for a new reference (a view opened later): pictures
        #: drawn ahead against the old one are then stale
        self.on_reference = None
        #: called when a page has the module loaded and hears messages (``ready``)
        self.on_ready = None
        self.on_msg(self._on_page_message)

    def _on_page_message(self, _widget, content, _buffers) -> None:
        kind = content.get("type")
        if kind == "ready" and self.on_ready is not None:
            self.on_ready()
        elif kind == "ref" and self.reference and self._last is not None:
            if int(content.get("ref", -1)) == self.ref_frame:
                self._send_reference()
        if kind != "move" or self.on_move is None or self._stale(content):
            return
        self.moves += 1
        self._seq = int(content.get("seq", 0))
        self._t0 = time.perf_counter()
        final = bool(content.get("final"))
        _last_move[0] = 0.0 if final else self._t0
        # mid-drag the caption travels only in the frame message (PageCaption): a trait
        # sync too was a second message and a second layout of the text per frame
        self.in_drag = not final
        try:
            self.on_move(int(content["i"]), float(content["x"]), float(content["y"]), final)
        finally:
            self.in_drag = False

    def _stale(self, content) -> bool:
        """True for a position of a drag whose release was handled already (and record a
        release). The page sends them in order, but ipykernel 7 may hand a kernel that is
        busy (a notebook still running) its messages out of order: the first position of a
        fast drag came after the release, and the figure stayed mid-drag, on the old vertex,
        while the sliders showed where it was let go (review r354 W1, 1 drag in 6)."""
        view, seq = content.get("view"), int(content.get("seq", 0))
        if content.get("final"):
            self._released[view] = max(seq, self._released.get(view, 0))
            return False
        return seq < self._released.get(view, 0)

    def show(self, fig, ax, handles, *, final: bool = True, rgba=None) -> None:
        """Send the figure's current pixels (drawn already) and where the handles are now.

        During a drag (``final`` False) only the rectangle of pixels that changed since the
        last picture sent goes to the page (a move changes the triangle's part of the
        figure), as raw RGBA bytes (``place`` = ``[x, y, width, height]``). ``final``: the whole
        picture, also kept as the poster (what a re-opened view shows); in reference mode a
        patch against the reference, the poster following it. ``rgba``: these pixels, drawn
        before (a picture kept), instead of the figure's.
        """
        t_show = time.perf_counter()
        rgba = frame_rgba(fig) if rgba is None else rgba
        h, w = rgba.shape[:2]
        last, self._last = self._last, rgba
        self._frame += 1
        # a picture answering a point dragged in the page is deflated too (issue 31: the
        # PlaneExplorer's vertex sent 0.5-0.7 MB of raw pixels a frame, which the server,
        # the browser and the page's main thread each handled: 21 fps against the editor's
        # 36; deflated, 36 kB, 1-3 ms of zlib, and the page inflates without the browser
        # process, drag.js's inflate); but the release's picture goes raw, painted at once:
        # the last picture after a drag waits on no inflate (its asynchronous steps, each a
        # turn of a busy page, put it at the editor's PNG's time under load, twice the raw one's)
        deflate = self.deflate and not (final and self._t0)
        place, png = self._patch(last, rgba, final, deflate)
        t_encoded = time.perf_counter()
        bbox = ax.get_window_extent()
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        sx, sy = bbox.width / (x1 - x0), -bbox.height / (y1 - y0)
        transform = [bbox.x0 - sx * x0, (h - bbox.y0) - sy * y0, sx, sy]
        moved = [[float(x), float(y)] for x, y in handles]
        if place is None or [w, h] != self.size or transform != self.transform:
            # the page needs the handles only to pick one at the next press: during a drag
            # they travel in the frame message, and the traits (a second message per
            # frame) follow at the release
            with self.hold_sync():
                self.size, self.transform, self.handles = [w, h], transform, moved
                if place is None:
                    self.poster, self.poster_frame = png, self._frame
                    self._posted = rgba
        elif final and moved != self.handles:
            # a final picture in reference mode is a patch too: the handles where they are
            # now, for the next press (PlaneExplorer's vertices, moved by a slider or a drag)
            self.handles = moved
        # kernel_ms: from the position's arrival to this answer (for benchmarks)
        now = time.perf_counter()
        kernel_ms = (now - self._t0) * 1e3 if self._t0 else 0.0
        timing = {"render": round((t_show - self._t0) * 1e3, 1),
                  "encode": round((t_encoded - t_show) * 1e3, 1),
                  "send": round((now - t_encoded) * 1e3, 1)} if self._t0 else None  # fmt: skip
        self._t0 = 0.0
        # a patch applies to the picture of frame n - 1 (a view that missed it waits for
        # the next whole picture); in reference mode to the reference picture
        self._send_frame(self._seq, moved, place, png, kernel_ms, timing,
                         deflate and bool(place and png))  # fmt: skip
        if final and place is not None and self.reference:
            # the poster (a PNG: 10-15 ms to encode, 100+ kB to send) a moment later: the
            # picture reaches the page first, and a second final meanwhile is posted once
            self._poster_rgba = rgba
            later(self._post_latest)

    def _patch(self, last, rgba, final: bool, deflate: bool) -> tuple:
        """``(place, bytes)`` of the picture ``rgba`` for the page that shows ``last``
        (in reference mode: the reference and one patch), a patch zlib-compressed with
        ``deflate``.

        A patch travels as raw RGBA pixels: the page paints them at once (putImageData),
        where a PNG waits for an asynchronous decode that took 5-90 ms on a loaded machine;
        a few hundred kB over the loopback cost less. ``place`` is ``[x, y, width, height]``
        (all 0 with empty bytes: nothing changed), None for a whole PNG.
        """
        if self.reference:
            if self._ref is None or self._ref.shape != rgba.shape:
                self._ref, self.ref_frame = rgba, self._frame
                return None, encode_png(rgba)
            return self._crop(self._ref, rgba, deflate)
        if last is None or last.shape != rgba.shape or final:
            return None, encode_png(rgba)
        return self._crop(last, rgba, deflate)

    def _crop(self, base, rgba, deflate: bool) -> tuple:
        """``(place, bytes)``: the rectangle of ``rgba`` that differs from ``base``
        (zlib-compressed with ``deflate``)."""
        box = changed_box(base, rgba)
        if box is None:
            return [0, 0, 0, 0], b""
        r0, r1, c0, c1 = box
        raw = rgba[r0:r1, c0:c1].tobytes()
        return [c0, r0, c1 - c0, r1 - r0], zlib.compress(raw, 1) if deflate else raw

    def send_ahead(self, batch, generation: int) -> list[tuple]:
        """Send the page pictures drawn ahead, in one message: ``batch`` holds
        ``(i, k, rgba, caption)``, the picture for position ``k`` of slider ``i`` of those
        that drive this figure and its caption (reference mode only). Returns each
        picture's patch as sent, ``(place, bytes)`` (:meth:`unpatch` gives its pixels back)."""
        entries, buffers = [], []
        for i, k, rgba, caption in batch:
            place, data = self._crop(self._ref, rgba, self.deflate)
            entries.append({"slider": int(i), "k": int(k), "place": place, "caption": caption,
                            "deflate": self.deflate and bool(data)})  # fmt: skip
            buffers.append(data)
        self.send({"type": "ahead", "generation": int(generation), "ref": self.ref_frame,
                   "entries": entries}, buffers)  # fmt: skip
        return [(e["place"], data) for e, data in zip(entries, buffers)]

    def unpatch(self, place, data) -> np.ndarray:
        """The picture that a patch ``(place, bytes)`` made by :meth:`send_ahead` shows: the
        reference with the patch painted over it, as the page paints it."""
        rgba = self._ref.copy()
        x, y, w, h = place
        if w and h:
            raw = zlib.decompress(data) if self.deflate else data
            rgba[y : y + h, x : x + w] = np.frombuffer(raw, np.uint8).reshape(h, w, 4)
        return rgba

    def shown_already(self, rgba) -> None:
        """The page shows ``rgba`` already (a final picture drawn ahead, which it painted by
        itself): it becomes the last picture (the next reference a view asks for) and, a
        moment later, the poster; nothing is sent (reference mode)."""
        self._last = rgba
        self._poster_rgba = rgba
        later(self._post_latest)

    def _send_frame(self, seq, handles, place, data, kernel_ms, timing, deflate) -> None:
        """The one "frame" message (a drag's picture, a final one, a new reference): the
        page's pump reads ``n``, ``place`` and ``ref`` the same way for all of them."""
        self.send({"type": "frame", "seq": seq, "handles": handles, "n": self._frame,
                   "place": place, "kernel_ms": kernel_ms, "timing": timing,
                   "ref": self.ref_frame if self.reference else None,
                   "caption": self.caption if self.drag_caption is None else self.drag_caption,
                   "deflate": deflate}, [data])  # fmt: skip

    def _send_reference(self) -> None:
        """The last picture becomes the reference, sent whole (a view opened later asked)."""
        self._ref = None
        self._frame += 1
        rgba = self._last
        place, png = self._patch(None, rgba, True, False)
        with self.hold_sync():
            self.poster, self.poster_frame = png, self._frame
            self._posted = rgba
        self._send_frame(0, self.handles, place, png, 0.0, None, False)
        if self.on_reference is not None:
            self.on_reference()

    def _post_latest(self) -> None:
        rgba, self._poster_rgba = self._poster_rgba, None
        if rgba is not None:
            self._post(rgba)

    def _post(self, rgba) -> None:
        """Keep ``rgba`` (sent as a patch) as the poster, a PNG (what a re-opened view shows)."""
        if self._posted is not None and np.array_equal(self._posted, rgba):
            self.poster_frame = self._frame  # the same picture: only its number moves on
        else:
            with self.hold_sync():
                self.poster, self.poster_frame = encode_png(rgba), self._frame
        self._posted = rgba


@contextmanager
def hidden(artists):
    """Within: ``artists`` hidden (a drag's drafts leave out labels, half a frame's cost; the
    page's ring marks the point in hand meanwhile), then shown as they were."""
    shown = [a.get_visible() for a in artists]
    for a in artists:
        a.set_visible(False)
    try:
        yield
    finally:
        for a, was in zip(artists, shown):
            a.set_visible(was)


def same_or_new(old: LayeredBlit, new: LayeredBlit) -> LayeredBlit:
    """``old`` (with its cached background) while it plans the same artists, else ``new``."""
    if [(k, list(map(id, a))) for k, a in old.plan] == [(k, list(map(id, a))) for k, a in new.plan]:
        return old
    return new


class PageDisplay:
    """A figure shown by a :class:`DragFigure`, with FigureDisplay's ``refresh``/``close``.

    ``draw`` renders the figure (a blit); ``handles()`` gives the draggable points;
    ``on_move(i, x, y, final)`` is called with positions from the page. ``final`` is False
    while a drag is under way (the picture is then not kept as the poster).
    """

    def __init__(self, fig, ax, draw, handles, *, on_move) -> None:
        self.fig, self.ax, self.draw, self.handles = fig, ax, draw, handles
        self.widget = DragFigure(on_move=on_move, alt="the triangle's fill; drag a vertex")
        self.draws = 0
        self.final = True
        self.refresh()

    def refresh(self) -> None:
        """Draw and send the figure to the page."""
        self.draws += 1
        self.draw()
        self.widget.show(self.fig, self.ax, self.handles(), final=self.final)

    def close(self) -> None:
        self.widget.close()
