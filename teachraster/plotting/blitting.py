"""Blitting: redraw only the artists that move, over still layers drawn once.

A full Agg draw of a stepping view costs tens of milliseconds (tick labels, thousands of
pixel-centre markers, annotations), yet one step changes a few artists. Matplotlib's
blitting recipe caches the still background (``canvas.copy_from_bbox``), puts it back
(``restore_region``) and draws the moving artists on top (``draw_artist``). The moving
pixel images of a fill lie *under* still artists (the grid, the centres, the triangle), so
here the still artists above them are rendered once more, alone on a transparent canvas,
and composited back at their place in the drawing order (``renderer.draw_image``).

Moving per-pixel images (the QuadMesh / AxesImage of
:func:`~teachraster.plotting.common.show_image`) are painted by nearest-pixel lookup in
numpy from their own colour map: the same colours Agg would draw, without resampling.
"""

from __future__ import annotations

from collections.abc import Hashable, Sequence

import numpy as np
from matplotlib.artist import Artist
from matplotlib.collections import QuadMesh
from matplotlib.image import AxesImage

MOVING, STILL = "moving", "still"


class LayeredBlit:
    """Draw a figure as a cached background, still layers and moving artists.

    Parameters
    ----------
    fig : matplotlib Figure
        Its canvas must be Agg-based (Agg itself, ipympl, inline).
    plan : sequence of (kind, artists)
        In drawing order: ``("moving", [...])`` artists drawn at every :meth:`draw`, and
        ``("still", [...])`` artists drawn once into a layer composited at that place. Every
        other artist of the figure is background (under everything in the plan, outside
        the moving artists' places); the plan must list each still artist that lies above a
        moving one.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> dot, = ax.plot([0.5], [0.5], "o")
    >>> blit = LayeredBlit(fig, [("moving", [dot])])
    >>> blit.draw(), blit.draw()    # full draw once, then blitted
    (True, False)
    >>> plt.close(fig)
    """

    def __init__(self, fig, plan: Sequence[tuple[str, Sequence[Artist]]]) -> None:
        self.fig = fig
        self.plan = [(kind, list(artists)) for kind, artists in plan]
        for kind, _ in self.plan:
            if kind not in (MOVING, STILL):
                raise ValueError(f"plan kinds are 'moving' or 'still', got {kind!r}")
        self._cache: dict = {}
        self._lookups: dict = {}

    def invalidate(self) -> None:
        """Forget the cached background and layers (after changing a still artist)."""
        self._cache.clear()
        self._lookups.clear()

    def draw(self, key: Hashable = None) -> bool:
        """Render the figure into its canvas' buffer; True when this needed a full draw.

        ``key`` names the state of the still artists (e.g. which of them are visible): a
        new key renders background and layers afresh (a cache per key), as does a new
        canvas size.
        """
        canvas = self.fig.canvas
        full_key = (key, canvas.get_width_height(), self.fig.dpi)
        built = full_key not in self._cache
        if built:
            if len(self._cache) >= 8:  # e.g. many canvas sizes: keep memory bounded
                self._cache.clear()
            self._cache[full_key] = self._build()
        background, layers = self._cache[full_key]
        canvas.restore_region(background)
        renderer = canvas.get_renderer()
        gc = renderer.new_gc()
        layer = iter(layers)
        for kind, artists in self.plan:
            if kind == STILL:
                image = next(layer)
                if image is not None:
                    renderer.draw_image(gc, image[0], image[1], image[2])
                continue
            self._draw_moving([a for a in artists if a.get_visible()], renderer, gc)
        gc.restore()
        return built

    # -- caches ---------------------------------------------------------------------------
    def _render(self, visible: set[int] | None) -> np.ndarray:
        """Draw the figure with only ``visible`` artists (None: all but the planned ones)."""
        fig = self.fig
        planned = {id(a) for _, arts in self.plan for a in arts}
        saved = []

        def hide(artist):
            saved.append((artist, artist.get_visible()))
            artist.set_visible(False)

        for _, arts in self.plan:
            for a in arts:
                if visible is None or id(a) not in visible:
                    hide(a)
        if visible is not None:  # a layer: nothing else, on a transparent canvas
            hide(fig.patch)
            for child in fig.get_children():
                if child is fig.patch or id(child) in planned:
                    continue
                if child in fig.axes:
                    for grandchild in child.get_children():
                        if id(grandchild) not in planned:
                            hide(grandchild)
                else:
                    hide(child)
        try:
            renderer = fig.canvas.get_renderer()
            renderer.clear()
            fig.draw(renderer)  # not canvas.draw(): ipympl would send every layer
            return np.asarray(renderer.buffer_rgba()).copy()
        finally:
            for artist, was in reversed(saved):
                artist.set_visible(was)

    def _build(self):
        layers = []
        for kind, artists in self.plan:
            if kind == STILL:
                rgba = self._render({id(a) for a in artists if a.get_visible()})
                layers.append(_crop(rgba))
        self._render(None)
        background = self.fig.canvas.copy_from_bbox(self.fig.bbox)
        return background, layers

    # -- moving artists -------------------------------------------------------------------
    def _draw_moving(self, artists, renderer, gc) -> None:
        """Draw in order; runs of per-pixel images on one Axes are merged and painted once."""
        run: list = []
        for artist in [*artists, None]:
            data = _pixel_data(artist)
            if data is not None and (not run or _same_grid(run[-1], artist, data)):
                run.append((artist, data))
                continue
            if run:
                self._paint_pixels(run, renderer, gc)
                run = []
            if data is not None:
                run.append((artist, data))
            elif artist is not None:
                artist.draw(renderer)

    def _paint_pixels(self, run, renderer, gc) -> None:
        """Paint per-pixel images by nearest lookup (no resampling), clipped to their Axes."""
        artist, data = run[0]
        x0, y0, rows, cols = self._lookup(artist.axes, data.shape[:2])
        if rows.size == 0 or cols.size == 0:
            return
        small = artist.to_rgba(data, alpha=artist.get_alpha(), bytes=True)
        for above, values in run[1:]:
            small = _over(above.to_rgba(values, alpha=above.get_alpha(), bytes=True), small)
        # one 32-bit word per pixel: two 1-D takes are much faster than a 2-D fancy index
        words = np.ascontiguousarray(small).view(np.uint32)[..., 0]
        big = words.take(rows, axis=0).take(cols, axis=1)
        renderer.draw_image(gc, x0, y0, big.view(np.uint8).reshape(*big.shape, 4))

    def _lookup(self, ax, shape):
        """Screen pixels of ``ax`` and the data pixel each one's centre falls in."""
        key = (id(ax), shape, tuple(ax.bbox.bounds), ax.get_xlim(), ax.get_ylim())
        if key not in self._lookups:
            box = ax.bbox
            # the screen pixels whose centres lie inside the Axes (Agg's clip rounding)
            c0, c1 = int(np.floor(box.x0 + 0.5)), int(np.floor(box.x1 + 0.5))
            r0, r1 = int(np.floor(box.y0 + 0.5)), int(np.floor(box.y1 + 0.5))
            inverse = ax.transData.inverted()
            xs = inverse.transform(np.column_stack([np.arange(c0, c1) + 0.5,
                                                    np.full(c1 - c0, box.y0)]))[:, 0]  # fmt: skip
            # buffer rows run top down: screen y of row r is height - r - 0.5
            # draw_image wants the bottom row first: screen rows r0 .. r1 - 1, centres at +0.5
            ys = inverse.transform(np.column_stack([np.full(r1 - r0, box.x0),
                                                    np.arange(r0, r1) + 0.5]))[:, 1]  # fmt: skip
            cols = np.clip(np.floor(xs).astype(int), 0, shape[1] - 1)
            rows = np.clip(np.floor(ys).astype(int), 0, shape[0] - 1)
            self._lookups[key] = (c0, r0, rows, cols)
        return self._lookups[key]


def _pixel_data(artist):
    """The data of a per-pixel image artist (QuadMesh or AxesImage), else None: values
    (H, W) for its colour map, or colours (H, W, 3 or 4) in [0, 1] or bytes."""
    if isinstance(artist, QuadMesh | AxesImage) and artist.get_array() is not None:
        data = artist.get_array()
        if data.ndim == 2:
            # masked where not a number: the colour map's "bad" colour, as Agg draws it
            # (a norm such as BoundaryNorm would give NaN a colour of the map)
            return np.ma.masked_invalid(data)
        if data.ndim == 3 and data.shape[2] in (3, 4):
            return np.asarray(data)
    return None


def _same_grid(previous, artist, data) -> bool:
    return previous[0].axes is artist.axes and previous[1].shape[:2] == data.shape[:2]


def _over(top: np.ndarray, bottom: np.ndarray) -> np.ndarray:
    """Straight-alpha RGBA ``top`` over ``bottom`` (uint8), as Agg blends them."""
    opacity = top[..., 3]
    if not ((opacity > 0) & (opacity < 255)).any():  # opaque or clear: just pick
        return np.where((opacity == 255)[..., None], top, bottom)
    ta = top[..., 3:4].astype(np.float32) / 255.0
    ba = bottom[..., 3:4].astype(np.float32) / 255.0
    alpha = ta + ba * (1.0 - ta)
    rgb = top[..., :3] * ta + bottom[..., :3] * ba * (1.0 - ta)
    rgb = np.divide(rgb, alpha, out=np.zeros_like(rgb), where=alpha > 0)
    out = np.concatenate([rgb, alpha * 255.0], axis=-1)
    return np.clip(np.rint(out), 0, 255).astype(np.uint8)


def _crop(rgba: np.ndarray):
    """(x, y, pixels) of the part of a transparent RGBA render that holds anything."""
    alpha = rgba[..., 3]
    rows = np.flatnonzero(alpha.any(axis=1))
    cols = np.flatnonzero(alpha.any(axis=0))
    if rows.size == 0:
        return None
    top, bottom, left, right = rows[0], rows[-1] + 1, cols[0], cols[-1] + 1
    # draw_image takes the lower-left corner in display pixels (y up), bottom row first
    pixels = np.ascontiguousarray(rgba[top:bottom, left:right][::-1])
    return int(left), int(rgba.shape[0] - bottom), pixels
