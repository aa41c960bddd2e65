"""Shared helpers: the artist containers, input coercion and pixel-space axes set-up."""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, fields

import matplotlib as mpl
import numpy as np
from matplotlib.artist import Artist
from matplotlib.collections import QuadMesh
from matplotlib.colors import ListedColormap, to_rgba
from matplotlib.text import Annotation
from matplotlib.transforms import IdentityTransform

from ..core.fill import Fill
from ..core.trace import FillTrace
from ..core.validate import as_int, as_size
from ..pipeline.rendering.render_triangles import Frame


@dataclass
class Artists:
    """Base of every plot function's result: named artists, iterable like a list.

    ``list(result)`` (or ``result.artists``) gives every matplotlib artist the function put
    on the Axes, in drawing order; fields give them by name. A colour bar, where there is
    one, lives on its own Axes and is the ``colorbar`` field, not in the list.
    """

    @property
    def artists(self) -> list[Artist]:
        out: list[Artist] = []
        for f in fields(self):
            value = getattr(self, f.name)
            if isinstance(value, Artist) and f.name != "colorbar":
                out.append(value)
            elif isinstance(value, list | tuple):
                out.extend(v for v in value if isinstance(v, Artist))
        return out

    def __iter__(self):
        return iter(self.artists)

    def __len__(self) -> int:
        return len(self.artists)

    def set_visible(self, visible: bool) -> None:
        """Show or hide all the artists at once."""
        for artist in self.artists:
            artist.set_visible(visible)


def as_trace(obj, what: str = "this plot") -> FillTrace:
    """The FillTrace of a Fill (rasterised with ``trace=True``) or a FillTrace itself."""
    if isinstance(obj, FillTrace):
        return obj
    if isinstance(obj, Fill):
        if obj.trace is None:
            raise ValueError(
                f"{what} needs the fill's trace: rasterise with tr.rasterize(..., trace=True)"
            )
        return obj.trace
    raise TypeError(f"{what} needs a Fill or a FillTrace, got {type(obj).__name__}")


def as_coverage(obj) -> np.ndarray:
    """(H, W) bool coverage from a Fill, Frame, FillTrace or bool array."""
    if isinstance(obj, Fill | Frame):
        return np.asarray(obj.coverage, dtype=bool)
    if isinstance(obj, FillTrace):
        return obj.image(obj.covered, fill=False)
    arr = np.asarray(obj)
    if arr.ndim != 2:
        raise ValueError(f"coverage must be a 2-D (height, width) array, got shape {arr.shape}")
    return arr.astype(bool)


def nice_step(n: int, most: int = 8) -> int:
    """A round tick spacing (1, 2, 4, 5, 8, 10, 16, 20, 25, 32, 50, ...) giving <= ``most``."""
    for step in (1, 2, 4, 5, 8, 10, 16, 20, 25, 32, 50, 64, 100, 128, 200, 250, 256, 500):
        if math.ceil(n / step) <= most:
            return step
    return 10 ** math.ceil(math.log10(max(n, 1) / most))


#: The tops a rounded colour range may have, times a power of ten (see :func:`round_up`):
#: close enough that the colour bar ends near the maximum the title states (review r91
#: 04-E: with 1, 1.5, 2, 2.5, 3, 4, ... a maximum of 31.7 drew a bar to 40), few enough that
#: a bar comes round again (two significant digits drew a new bar at nearly every tilt,
#: about 45 % more time per picture).
ROUND_TOPS = (1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0)


def round_up(x: float) -> float:
    """The smallest of 1, 1.2, 1.5, 2, 2.5, 3, 3.5, 4, 4.5, 5, 6, 7, 8, 9 (times a power
    of ten) at least ``x``.

    A colour range ending on such a number changes only when the data's maximum crosses
    one, so a colour bar drawn once per range can be put back from a cache (an explorer's
    error moves with every tilt), and it ends within a fifth of the maximum.

    >>> round_up(0.232), round_up(0.08), round_up(7.0), round_up(31.7), round_up(1e-3)
    (0.25, 0.08, 7.0, 35.0, 0.001)
    """
    x = float(x)
    if not (x > 0 and math.isfinite(x)):
        raise ValueError(f"x must be a positive finite number, got {x!r}")
    scale = 10.0 ** math.floor(math.log10(x))
    # a relative margin: 0.08 / 0.01 is 7.999999999999999 in binary, and is 8
    top = next(top for top in ROUND_TOPS if top * scale >= x * (1 - 1e-12))
    return round(top * scale, 12 - math.floor(math.log10(x)))


def pixel_axes(ax, width: int, height: int, *, ticks: bool = True, most: int = 8) -> None:
    """Make ``ax`` show a ``height`` × ``width`` image in pixel coordinates, y down.

    Pixel (row i, col j) is the unit square [j, j+1] × [i, i+1]; ticks sit on pixel centres
    and are labelled with column / row indices (at most ``most`` per axis, at round
    spacings), the x axis on top as in a matrix.
    """
    width, height = as_size("width", width), as_size("height", height)
    most = as_int("most", most, minimum=1) if ticks else most
    ax.set_xlim(0, width)
    ax.set_ylim(height, 0)  # y down: row 0 at the top
    ax.set_aspect("equal")
    if not ticks:
        ax.set_xticks([])
        ax.set_yticks([])
        return
    for axis, n, label in ((ax.xaxis, width, "column j"), (ax.yaxis, height, "row i")):
        idx = np.arange(0, n, nice_step(n, most))
        axis.set_ticks(idx + 0.5, labels=[str(i) for i in idx])
        axis.set_label_text(label)
    ax.xaxis.tick_top()
    ax.xaxis.set_label_position("top")


def clear_axes(ax) -> None:
    """``ax.clear()`` for a figure drawn again, keeping the axes' Tick objects.

    Matplotlib makes every tick anew after a clear (two lines, two texts and their
    transforms each, ~0.5 ms a tick): about a fifth of a FrameInspector view change. The
    ticks are kept and given the props of the fresh tick the clear made, as matplotlib
    gives them to every tick it adds after the first (``Axis._copy_tick_props``): the picture is the one a cleared Axes draws, pixel
    for pixel (tests/test_lesson_widgets.py compares walked widgets with fresh ones).
    """
    kept = [(axis, vars(axis).get("majorTicks"), vars(axis).get("minorTicks"))
            for axis in (ax.xaxis, ax.yaxis)]  # fmt: skip
    ax.clear()
    if not hasattr(ax.xaxis, "_copy_tick_props"):
        return  # a matplotlib without it (private API): the plain clear, ticks made anew
    for axis, *ticks in kept:
        for name, old in zip(("majorTicks", "minorTicks"), ticks):
            if not old or len(old) < 2:
                continue  # nothing to keep beyond the one tick the clear makes
            fresh = getattr(axis, name)[0]  # the clear made it (reset_ticks), in the new state
            for tick in old[1:]:
                axis._copy_tick_props(fresh, tick)
            setattr(axis, name, [fresh, *old[1:]])


def remove_drawn(ax) -> None:
    """Remove what was drawn on ``ax`` (artists and inset Axes) and restart its colour cycle,
    keeping its set-up: limits, aspect, ticks, labels and titles stay as they are.

    For a widget that draws every picture on the same Axes and sets that set-up again each
    time: ``ax.clear()`` would make every tick anew (CasePicker: a third of each picture's
    CPU). Where a picture may leave some of the set-up unset, use :func:`clear_axes`.
    """
    for inset in list(ax.child_axes):
        inset.remove()
    for art in [*ax.artists, *ax.collections, *ax.images, *ax.lines, *ax.patches, *ax.texts]:
        art.remove()
    if ax.get_legend() is not None:
        ax.get_legend().remove()
    ax.set_prop_cycle(None)  # as after a clear: an unstyled line takes the cycle's first colour


def screen_ticks(ax, width: int, height: int, *, most: int = 8) -> None:
    """Label ``ax`` (set up by :func:`pixel_axes`) in screen coordinates x, y instead.

    The ticks sit at whole coordinates, on pixel corners, so that a vertex at (2, 1) sits on
    its ticks; :func:`pixel_axes` labels pixel indices at the pixel centres instead. A
    figure about positions (vertices, planes over the screen) reads better this way.
    """
    for axis, n, label in ((ax.xaxis, width, "x"), (ax.yaxis, height, "y")):
        ticks = np.arange(0, n + 1, nice_step(n, most))
        axis.set_ticks(ticks, labels=[str(t) for t in ticks])
        axis.set_label_text(label)


def image_extent(width: int, height: int) -> tuple[float, float, float, float]:
    """imshow extent placing pixel (i, j) on [j, j+1] × [i, i+1], row 0 at the top."""
    width, height = as_size("width", width), as_size("height", height)
    return (0.0, float(width), float(height), 0.0)


def two_colour(color, background=(0, 0, 0, 0)) -> ListedColormap:
    """Colour map for 0/1 images: 0 -> ``background`` (transparent), 1 -> ``color``."""
    return ListedColormap([to_rgba(background), to_rgba(color)])


#: Images up to this many pixels along a side are drawn as a QuadMesh (one quad per pixel),
#: which Agg draws several times faster than a resampled AxesImage; larger ones as images.
MESH_LIMIT = 160


def show_image(ax, data, **kwargs):
    """Show per-pixel data in pixel coordinates, one flat colour per pixel, NaN transparent.

    Returns a QuadMesh for images up to :data:`MESH_LIMIT` pixels along a side and an
    AxesImage beyond; :func:`set_image` updates either. Keyword arguments go to
    ``pcolormesh`` / ``imshow`` (``cmap``, ``norm``, ``vmin``, ``vmax``, ``alpha``, ``zorder``).
    """
    data = np.asarray(data)
    h, w = data.shape[:2]
    cmap = kwargs.pop("cmap", None) or mpl.rcParams["image.cmap"]
    cmap = mpl.colormaps[cmap] if isinstance(cmap, str) else cmap
    # A copy with NaN transparent: NaN means "not covered", so the grid shows through.
    kwargs["cmap"] = cmap.with_extremes(bad=(0, 0, 0, 0))
    if max(h, w) <= MESH_LIMIT:
        art = ax.pcolormesh(np.arange(w + 1), np.arange(h + 1), data, shading="flat",
                            edgecolors="none", antialiased=False, **kwargs)  # fmt: skip
    else:
        art = ax.imshow(data, extent=image_extent(w, h), interpolation="nearest",
                        origin="upper", **kwargs)  # fmt: skip
    # Fresh axes become pixel axes (y down, ticks on centres); axes already set up, e.g. by
    # plot_pixel_grid, keep their limits and ticks.
    if ax.get_autoscalex_on() and ax.get_autoscaley_on():
        pixel_axes(ax, w, h)
    return art


def image_shape(art) -> tuple[int, ...]:
    """Shape of the data an image artist (QuadMesh or AxesImage) shows."""
    return np.shape(art.get_array())


def set_image(art, data):
    """Show ``data`` in ``art`` (from :func:`show_image`) and return the artist showing it.

    The same artist whenever it can be (always for an AxesImage, and for a QuadMesh of the
    same shape); a QuadMesh of another shape is replaced by a new one with the same colours,
    since a mesh cannot change its number of quads.
    """
    data = np.asarray(data)
    h, w = data.shape[:2]
    if isinstance(art, QuadMesh):
        if image_shape(art) == data.shape:
            art.set_array(data)
            return art
        new = show_image(art.axes, data, cmap=art.get_cmap(), norm=art.norm,
                         alpha=art.get_alpha(), zorder=art.get_zorder())  # fmt: skip
        new.set_visible(art.get_visible())
        art.remove()
        return new
    art.set_data(data)
    art.set_extent(image_extent(w, h))
    return art


def rgba_image(rgb: np.ndarray) -> np.ndarray:
    """(H, W, 3) colours in [0, 1] with NaN -> (H, W, 4) RGBA, transparent where NaN."""
    rgb = np.asarray(rgb, dtype=np.float64)
    if rgb.ndim != 3 or rgb.shape[2] not in (3, 4):
        raise ValueError(f"expected an (H, W, 3) colour image, got shape {rgb.shape}")
    out = np.empty((*rgb.shape[:2], 4))
    ok = np.isfinite(rgb[..., :3]).all(axis=-1)[..., None]
    # np.where over the whole image, not boolean indexing: a widget does this per frame
    with np.errstate(invalid="ignore"):
        np.clip(rgb[..., :3], 0.0, 1.0, out=out[..., :3])
        out[..., :3] = np.where(ok, out[..., :3], 0.0)
        alpha = 1.0 if rgb.shape[2] == 3 else np.clip(rgb[..., 3:], 0.0, 1.0)
        out[..., 3:] = np.where(ok, alpha, 0.0)
    return out


def lw(scale: float = 1.0) -> float:
    """A line width relative to the style's ``lines.linewidth`` (thick in the classroom)."""
    return scale * float(mpl.rcParams["lines.linewidth"])


def ms(scale: float = 1.0) -> float:
    """A marker size relative to the style's ``lines.markersize``."""
    return scale * float(mpl.rcParams["lines.markersize"])


def fs(scale: float = 1.0) -> float:
    """A font size relative to the style's ``font.size``."""
    return scale * float(mpl.rcParams["font.size"])


def bar_in(cax) -> dict:
    """``Figure.colorbar`` arguments for a colour bar filling ``cax`` along its longer side."""
    box = cax.get_position()
    return {"cax": cax, "orientation": "horizontal" if box.width > box.height else "vertical"}


def label_box(alpha: float = 0.85) -> dict:
    """A white rounded box behind a label, so it reads on top of coloured pixels."""
    return {"boxstyle": "round,pad=0.2", "fc": "white", "ec": "none", "alpha": alpha}


def quiet_nanmax(values) -> float:
    """``np.nanmax`` as a float; NaN (without a RuntimeWarning) when every value is NaN."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        return float(np.nanmax(values)) if np.size(values) else float("nan")


def tint(color, amount: float) -> tuple:
    """``color`` at opacity ``amount`` over white, as an opaque colour.

    Looks the same as ``alpha=amount`` on a white background but is cheaper to draw (no
    blending over a large area), which matters for artists redrawn at every step.
    """
    r, g, b, _ = to_rgba(color)
    return (1 - amount + amount * r, 1 - amount + amount * g, 1 - amount + amount * b, 1.0)


class NearAnnotation(Annotation):
    """An annotation drawn outside its Axes only while its point is near them.

    Labels of vertices and edges may sit just outside the image (``annotation_clip=False``
    behaviour), but a point far outside -- a vertex at 1e6 px -- is not drawn at all: text
    at such screen positions overflows FreeType's rasteriser, and there is nothing to see.
    The test runs at draw time, so it follows zooming and later changes of the limits.
    """

    #: How far (in points, times the font size) the point may lie outside the Axes.
    margin = 2.0

    def _check_xy(self, renderer=None):
        ax = self.axes
        if ax is None:
            return super()._check_xy(renderer)
        if renderer is None:
            renderer = self.get_figure(root=True)._get_renderer()
        x, y = self._get_position_xy(renderer)
        if not (np.isfinite(x) and np.isfinite(y)):
            return False
        pad = self.margin * self.get_fontsize() * ax.figure.dpi / 72.0
        return bool(ax.bbox.expanded(1.0, 1.0).padded(pad).contains(x, y))


def annotate_near(ax, text, xy, **kwargs) -> NearAnnotation:
    """``ax.annotate(text, xy, **kwargs)`` as a :class:`NearAnnotation`."""
    a = NearAnnotation(text, xy, **kwargs)
    a.set_transform(IdentityTransform())
    ax._add_text(a)
    return a
