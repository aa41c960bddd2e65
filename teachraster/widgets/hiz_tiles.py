"""``HiZTileExplorer``: one scene's Hi-Z replay in several drawing orders and tile sizes."""

from __future__ import annotations

from dataclasses import replace
from types import SimpleNamespace

import ipywidgets as widgets

from ..pipeline.visibility.hierarchical_z import replay_tiles
from ..plotting import plot_early_z_panels
from .common import Shown, control_rows, labelled, style_context, title_html
from .display import FigureDisplay, new_figure, resolve_backend


def stored_depths(width: int, height: int, tile: int) -> int:
    """How many farthest depths Hi-Z keeps for a ``width`` × ``height`` image: one a tile
    (a tile cut by the image's edge counts whole).

    >>> stored_depths(320, 240, 8)
    1200
    """
    return -(-width // tile) * -(-height // tile)


def with_tiles(frame, hiz):
    """``frame`` as :func:`~teachraster.plotting.plot_early_z_panels` reads it, with the
    replay ``hiz`` (:func:`replay_tiles` at another tile size) in place of its 8×8 one."""
    return SimpleNamespace(trace=replace(frame.trace, hiz=hiz), coverage=frame.coverage,
                           triangle_id=frame.triangle_id)  # fmt: skip


class HiZTileExplorer(Shown):
    """Two menus, the drawing order and the Hi-Z tile size, over one scene's replays: the
    stored depths, the fragments Hi-Z rejected, early-z killed and were shaded, and the
    rejected fragments drawn with the tiles (lesson 10 §7's trade-off, played).

    Parameters
    ----------
    frames : dict of str -> Frame
        One one-sample ``tr.render(..., trace=True)`` per drawing order, by its name.
    tile_sizes : tuple of int
        Hi-Z tile sides in pixels.
    order, tile : the menus' first values (default: the first of each).
    backend, style : as the other widgets.

    Attributes
    ----------
    order, tile : ToggleButtons
    replays : dict of (order, tile) -> HiZResult
        Every replay, computed once (``replays[o, t].counts`` are the table's numbers).
    counts : dict
        The counts on show.

    Examples
    --------
    >>> import numpy as np, teachraster as tr
    >>> quad = np.array([[[-1, -1, z, 1], [1, -1, z, 1], [-1, 1, z, 1]] for z in (0.0, 0.5)])
    >>> frames = {"near first": tr.render(quad, 16, 16, trace=True),
    ...           "far first": tr.render(quad[::-1], 16, 16, trace=True)}
    >>> ex = HiZTileExplorer(frames, (4, 8), backend="image")
    >>> ex.counts["hiz_rejected"] > 0
    True
    >>> ex.order.value = "far first"; ex.counts["hiz_rejected"]
    0
    >>> ex.close()
    """

    _offline_sweep_ = "tile"

    def __init__(self, frames: dict, tile_sizes=(4, 8, 16), *, order: str | None = None,
                 tile: int | None = None, backend: str = "auto", style: str | None = None):  # fmt: skip
        self.frames, self.tile_sizes = dict(frames), tuple(int(t) for t in tile_sizes)
        self.backend = resolve_backend(backend)
        self.replays = {(name, t): replay_tiles(frame.trace, t)
                        for name, frame in self.frames.items() for t in self.tile_sizes}  # fmt: skip
        auto = dict(layout=widgets.Layout(width="auto"), style={"button_width": "auto"})
        self.order = widgets.ToggleButtons(options=list(self.frames),
                                           value=order or next(iter(self.frames)), **auto)  # fmt: skip
        self.tile = widgets.ToggleButtons(
            options=[(f"{t}×{t}", t) for t in self.tile_sizes],
            value=self.tile_sizes[0] if tile is None else int(tile), **auto)  # fmt: skip
        with style_context(style):
            self.fig = new_figure((6.4, 5.6), self.backend)
            self.style = style
            self._draw()
            self.display = FigureDisplay(self.fig, self.backend)
        self.info = widgets.HTML(self._info())
        for control in (self.order, self.tile):
            control.observe(self._changed, "value")
        title = title_html("Hi-Z: drawing order × tile size",
                           "the replay of a GPU drawing in this order, with tiles of this size")  # fmt: skip
        self.widget = widgets.VBox([
            title, control_rows([labelled("order", self.order)], [labelled("tile", self.tile)]),
            self.info, self.display.widget])  # fmt: skip

    @property
    def counts(self) -> dict:
        return self.replays[self.order.value, self.tile.value].counts

    def _info(self) -> str:
        c, t = self.counts, self.tile.value
        h, w = next(iter(self.frames.values())).coverage.shape
        return (f"<b>{self.order.value}, {t}×{t} tiles</b>: {stored_depths(w, h, t):,} "
                f"stored depths; {c['hiz_rejected']:,} fragments rejected by Hi-Z, "
                f"{c['early_z_killed']:,} killed by early-z, {c['shaded']:,} shaded")  # fmt: skip

    def _draw(self) -> None:
        self.fig.clear()
        self.fig.set_layout_engine("constrained")  # the key goes outside, below the panel
        ax = self.fig.subplots()
        frame = with_tiles(self.frames[self.order.value],
                           self.replays[self.order.value, self.tile.value])  # fmt: skip
        key = plot_early_z_panels([ax], frame, ("hi_z",))
        key.remove()  # the caption above says what is counted; the key's lines below
        self.fig.legend(handles=[key.legend_handles[k] for k in (0, 2, 3)],
                        labels=["a fragment Hi-Z rejected in its tile's block",
                                "covered, nothing rejected", "the Hi-Z tiles"],
                        loc="outside lower center", ncols=1, fontsize=12)  # fmt: skip

    def _changed(self, _change) -> None:
        with style_context(self.style):
            self._draw()
        self.display.refresh()
        self.info.value = self._info()
