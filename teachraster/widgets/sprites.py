"""``CachedSprite``: an artist drawn over a blitted figure, its pixels kept per state.

A colour bar whose range has not changed looks the same as last time, yet drawing it again
(ticks, tick labels, its label) costs more than the images it explains. Drawn once over the
blit's background, its pixels are copied (``canvas.copy_from_bbox``) and put back the next
time its state comes round (``restore_region``): the very same pixels, as long as nothing
else that moves lies under them, which is checked at every draw (otherwise it is drawn).
"""

from __future__ import annotations

from collections.abc import Hashable, Sequence

from matplotlib.transforms import Bbox

#: Pixels of background kept round the artist's tight box (anti-aliased edges).
PAD = 2


class CachedSprite:
    """``artist`` drawn, or put back from a cache of its pixels, for a state ``key``.

    Parameters
    ----------
    fig : matplotlib Figure
        With an Agg-based canvas (Agg, ipympl, inline).
    artist : Artist
        Drawn last, over the figure (e.g. a colour bar's Axes), outside the blit's plan.
    limit : int
        States kept (the oldest is forgotten first).

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> text = ax.text(0.5, 0.5, "hello")
    >>> fig.canvas.draw()
    >>> sprite = CachedSprite(fig, text)
    >>> sprite.draw("hello"), sprite.draw("hello")    # drawn, then put back
    ('drawn', 'cached')
    >>> plt.close(fig)
    """

    def __init__(self, fig, artist, *, limit: int = 32) -> None:
        self.fig, self.artist, self.limit = fig, artist, limit
        self._cache: dict = {}

    def clear(self) -> None:
        """Forget every state (after the background under the artist changed)."""
        self._cache.clear()

    def has(self, key: Hashable) -> bool:
        """Whether the pixels of state ``key`` are kept (for the canvas' current size)."""
        return self._full_key(key) in self._cache

    def draw(self, key: Hashable, *, others: Sequence[Bbox] = (), new: bool = True) -> str:
        """Show the artist in state ``key``: ``"cached"``, ``"drawn"`` or ``"skipped"``.

        ``others`` are the display boxes of whatever else was drawn this time (moving
        artists): kept pixels are only put back where they do not overlap, and only pixels
        that they do not overlap are kept. With ``new`` False a state not kept is skipped
        (a draft leaves the artist out rather than pay for drawing it).
        """
        canvas = self.fig.canvas
        full = self._full_key(key)
        kept = self._cache.get(full)
        if kept is not None and not _overlaps(kept[0], others):
            canvas.restore_region(kept[1])
            self._cache[full] = self._cache.pop(full)  # the most recent last
            return "cached"
        if not new:
            return "skipped"
        renderer = canvas.get_renderer()
        self.artist.draw(renderer)
        box = drawn_box(self.artist, renderer)
        if box is not None and not _overlaps(box.padded(PAD), others):
            box = _whole_pixels(box.padded(PAD), canvas.get_width_height())
            self._cache[full] = (box, canvas.copy_from_bbox(box))
            while len(self._cache) > self.limit:
                self._cache.pop(next(iter(self._cache)))
        return "drawn"

    def _full_key(self, key: Hashable):
        return (key, self.fig.canvas.get_width_height(), self.fig.dpi)


def drawn_box(artist, renderer) -> Bbox | None:
    """Display box of what ``artist`` has just drawn.

    For an Axes (a colour bar's): its frame, spines and patches, and the extents of its tick labels, axis labels
    and offset texts, whose layouts the draw has just cached; ``get_tightbbox`` would lay
    out the ticks again, which costs half a draw. Tick marks lie between the frame and their
    labels (or within the padding).
    """
    from matplotlib.axes import Axes

    if not isinstance(artist, Axes):
        return artist.get_tightbbox(renderer)
    boxes, reach = [artist.bbox], 0.0
    # a colour bar's outline spine and extend triangles reach beyond its frame, by 5 % of
    # its length (the tip of a long bar's arrow was left out of the kept pixels)
    boxes += [s.get_window_extent(renderer) for s in artist.spines.values() if s.get_visible()]
    boxes += [p.get_window_extent(renderer) for p in artist.patches if p.get_visible()]
    for axis in (artist.xaxis, artist.yaxis):
        if not axis.get_visible():
            continue
        texts = [*axis.get_ticklabels(which="both"), axis.label, axis.offsetText]
        boxes += [t.get_window_extent(renderer) for t in texts
                  if t.get_visible() and t.get_text()]  # fmt: skip
        for ticks in (axis.majorTicks, axis.minorTicks):  # how far a tick mark reaches out
            reach = max(reach, ticks[0].get_tick_padding())
    return Bbox.union(boxes).padded(renderer.points_to_pixels(reach))


def _overlaps(box: Bbox, others: Sequence[Bbox]) -> bool:
    return any(box.overlaps(other) for other in others)


def _whole_pixels(box: Bbox, size) -> Bbox:
    """``box`` grown to whole pixels and clipped to the canvas."""
    import math

    w, h = size
    x0, y0 = max(0, math.floor(box.x0)), max(0, math.floor(box.y0))
    x1, y1 = min(w, math.ceil(box.x1)), min(h, math.ceil(box.y1))
    return Bbox([[x0, y0], [x1, y1]])


class ColourBarSprite:
    """A colour bar drawn over a blit, kept per range; left behind by drafts.

    The colour bar's Axes stays out of the blit's background (hidden while the blit draws)
    and is drawn last by a :class:`CachedSprite` keyed by the mappable's range. A draft
    changes the mappable's range without telling the colour bar (:meth:`quietly`) and shows
    the bar only if that range was drawn before; the next full picture brings the colour
    bar up to date first, so that it is exactly the picture a full update draws.

    Parameters
    ----------
    fig : matplotlib Figure
    mappable : callable
        Returns the image the colour bar explains (views may replace the artist).
    colorbar : matplotlib Colorbar
    """

    def __init__(self, fig, mappable, colorbar) -> None:
        self.mappable, self.colorbar = mappable, colorbar
        self.sprite = CachedSprite(fig, colorbar.ax)
        self.range = self._range()  # the range the colour bar shows
        self.last = ""  # what the last draw did (for tests)
        # the colour bar follows every range change it hears of (all but a draft's)
        mappable().callbacks.connect("changed", lambda *_: self._heard())

    def _heard(self) -> None:
        self.range = self._range()

    def _range(self) -> tuple[float, float]:
        return tuple(float(v) for v in self.mappable().get_clim())

    def quietly(self):
        """A context in which range changes do not reach the colour bar (for drafts)."""
        return self.mappable().callbacks.blocked(signal="changed")

    def draw(self, blit, *, draft: bool, others=()) -> str:
        """``blit.draw()`` without the colour bar, then the colour bar (see the class)."""
        ax = self.colorbar.ax
        ax.set_visible(False)  # not in the blit's background: it is drawn over it
        try:
            if blit.draw():
                self.sprite.clear()  # a new background
        finally:
            ax.set_visible(True)
        key = self._range()
        if not draft and self.range != key:  # drafts left the colour bar behind
            self.colorbar.update_normal(self.mappable())
            self.range = key
        self.last = self.sprite.draw(key, others=others, new=not draft)
        return self.last


def text_boxes(texts, pad: float = 8.0) -> list[Bbox]:
    """Display boxes of the visible ``texts`` (an annotation: its text and its point)."""
    from matplotlib.text import Annotation, Text

    boxes = []
    for text in texts:
        if text is None or not text.get_visible():
            continue
        renderer = text.figure.canvas.get_renderer()
        # Text's own box: an annotation's would lay out its arrow, which is slow
        boxes.append(Text.get_window_extent(text, renderer).padded(pad))
        if isinstance(text, Annotation):  # its line runs from the point to the text
            x, y = text.axes.transData.transform(text.xy)
            boxes.append(Bbox.from_extents(x - pad, y - pad, x + pad, y + pad))
    return boxes
