"""Whole pictures: the student's function in a small scene, beside the package's.

As CS184 and CS248 show a student's image beside the staff reference with a difference
image, :meth:`.report.Report.compare` draws three panels: the scene rendered with the
student's function plugged in, the same scene with the package's, and the pixels that differ
(with the size of the difference where values are continuous). Each scene is small (a few
hundred calls of the student's function), runs only when it is drawn or asked for, within the
CPU time one case of the check may take, and not at all when the check stopped on a time limit
(:attr:`Scene.blocked`: an endless loop is not run a second time). The scenes themselves are
built in :mod:`.picture_scenes`:

- ``fill``: a fan of 16 triangles wound both ways, how many cover each pixel;
- ``depth_to_unorm``: two nearly coplanar triangles in a 16-bit depth buffer (z-fighting);
- ``coverage_fraction``: a fan of triangles, the covered fraction of 4 samples per pixel;
- ``resolve``: the same fan in colour, resolved over the samples;
- ``mip_level``, ``bilinear``, ``trilinear``: a textured floor receding to the horizon
  (λ per pixel; the texture filtered bilinearly; filtered trilinearly at the package's λ);
- ``classify_block``: a tile walk (blocks of 16, then 4, then pixels) over a triangle.

matplotlib is imported only when a comparison is drawn.
"""

from __future__ import annotations

import operator
import textwrap
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from . import output
from .running import CASE_SHARE, DEFAULT_BUDGET, PER_PIXEL, Outcome, budget, run_case

#: Colours of differing pixels and of the marked pixel.
DIFF_COLOUR, MARK_COLOUR = "#d7301f", "#ff9f1c"


@dataclass(eq=False)
class Scene:
    """A picture the package renders, and the same with the student's function.

    ``student_image()`` runs the student's function once (under the checker's time limit)
    and keeps the result; ``explain(row, col)`` says why one pixel differs.
    """

    title: str
    reference: np.ndarray  # (H, W) values or codes, or (H, W, 3) colours; NaN = nothing
    run: Callable[[], np.ndarray]  # the student's picture (calls the student's function)
    explain_at: Callable[[np.ndarray, int, int], str]  # (student picture, row, col) -> words
    categories: tuple[tuple[str, str], ...] = ()  # (name, colour) per code; () = continuous
    parts: object = field(default=None, repr=False)  # the student's values behind the picture
    #: The package's values behind the picture, (k, H, W), where a pixel's picture may agree
    #: while its values do not (a wrong depth can still lose the same depth test): compared too.
    reference_parts: np.ndarray | None = field(default=None, repr=False)
    #: CPU seconds of the check's budget: the picture may take what one of its cases may.
    seconds: float = DEFAULT_BUDGET
    #: The time-out words' question, the exercise's own (r293 HN5: coverage_fraction, called
    #: once per pixel by its signature, was asked "a Python call per pixel?").
    slow: str = PER_PIXEL
    #: Why the student's function is not run for the picture (the check stopped on a time
    #: limit: a loop is not run twice), or None.
    blocked: str | None = None
    #: ``inputs(ax) -> title``: draws what the student's function is given over the scene
    #: (the triangles, the samples, the texture), no answer; the untouched stub's comparison
    #: draws it instead of the package's picture (r64 06-4, 07: the stub showed the target
    #: picture before any try). None: the package's picture, as before.
    inputs: Callable | None = field(default=None, repr=False)
    #: What a continuous picture's values are (the colour bar's label: r64 07-6, "λ").
    value_name: str = ""
    #: The check of this picture failed (set by :meth:`.report.Report.compare`): a picture
    #: that shows no difference then says the failing cases show it (r94 D8-10).
    check_failed: bool = False
    #: ``coverage_of(picture) -> (H, W) bool``: which pixels a picture of codes fills, where a
    #: pixel's code can differ with its coverage the same (8.1's walk: a block accepted at
    #: another level, r149 E1: "320 pixels differ" for one pixel covered wrongly). Its
    #: differences are then counted apart from the rest. None: every difference counts alike.
    coverage_of: Callable[[np.ndarray], np.ndarray] | None = field(default=None, repr=False)
    _outcome: object = field(default=None, repr=False)

    def student_image(self) -> np.ndarray | None:
        """The student's picture, or None when the function failed (see :attr:`error`)."""
        if self._outcome is None:
            if self.blocked is not None:
                self._outcome = Outcome(error=self.blocked, kind="timeout")
            else:
                with budget(self.seconds, share=CASE_SHARE, slow=self.slow), output.captured():
                    self._outcome = run_case(self.run, case="the picture")
        return self._outcome.value if self._outcome.ok else None

    @property
    def error(self) -> str | None:
        """Why there is no student picture (an exception, the time limit, a stub)."""
        self.student_image()
        if self._outcome.not_implemented:
            return "not implemented yet"
        return self._outcome.error

    def differs(self) -> np.ndarray:
        """(H, W) bool: pixels where the student's picture is not the package's."""
        got = self.student_image()
        ref = self.reference
        if got is None:
            return np.ones(ref.shape[:2], dtype=bool)
        same = np.isclose(got, ref, rtol=1e-9, atol=1e-9) | (np.isnan(got) & np.isnan(ref))
        differs = ~same.reshape(*ref.shape[:2], -1).all(axis=2)
        if self.reference_parts is not None and self.parts is not None:
            differs |= ~np.isclose(self.parts, self.reference_parts, rtol=0, atol=0).all(axis=0)
        return differs

    def coverage_differs(self) -> np.ndarray | None:
        """(H, W) bool: pixels the student's picture fills and the package's does not, or the
        other way round (None without :attr:`coverage_of` or a picture of the student's)."""
        got = self.student_image()
        if self.coverage_of is None or got is None:
            return None
        return np.asarray(self.coverage_of(got)) != np.asarray(self.coverage_of(self.reference))

    def difference(self) -> np.ndarray:
        """(H, W) largest absolute difference per pixel (continuous pictures), NaN = none."""
        got = self.student_image()
        if got is None or self.categories:
            return np.full(self.reference.shape[:2], np.nan)
        with np.errstate(invalid="ignore"):
            d = np.abs(got - self.reference).reshape(*self.reference.shape[:2], -1)
        return np.where(self.differs(), np.nanmax(np.where(np.isnan(d), np.inf, d), axis=2), np.nan)

    def differing(self) -> np.ndarray:
        """(n, 2) rows and columns of the pixels that differ, in raster order."""
        return np.argwhere(self.differs())

    def draw(self, axes=None, pixel=None, connect: bool = True):
        """:func:`draw_comparison` of this scene."""
        return draw_comparison(self, axes, pixel, connect)

    def explain(self, row: int, col: int) -> str:
        """Why pixel (row, col) of the student's picture differs, in the checker's words."""
        row, col = as_pixel((row, col))
        h, w = self.reference.shape[:2]
        if not (0 <= row < h and 0 <= col < w):
            raise ValueError(f"pixel must lie in the {h} × {w} picture, got ({row}, {col})")
        got = self.student_image()
        if got is None:
            return f"no picture of yours: {self.error}"
        return self.explain_at(got, row, col)


def as_pixel(pixel) -> tuple[int, int]:
    """``pixel`` as (row, col) Python ints, or a TypeError naming it."""
    try:
        row, col = pixel
        return operator.index(row), operator.index(col)
    except (TypeError, ValueError):
        raise TypeError(f"pixel must be a pair of ints (row, col), got {pixel!r}") from None


def call(fn, convert, *args):
    """The student's ``fn(*args)`` on copies of the arguments, converted like a check does."""
    copies = [a.copy() if isinstance(a, np.ndarray) else a for a in args]
    copies = [type(a)(c.copy() for c in a) if isinstance(a, list) else a for a in copies]
    return convert(fn(*copies))


def _three_axes(axes):
    import matplotlib.pyplot as plt

    if axes is None:
        return list(plt.subplots(1, 3, figsize=(9.0, 3.4), layout="constrained")[1])
    if hasattr(axes, "get_subplotspec") and axes.get_subplotspec() is not None:
        fig, spec = axes.figure, axes.get_subplotspec().subgridspec(1, 3)
        axes.remove()
        return [fig.add_subplot(spec[0, k]) for k in range(3)]
    axes = list(np.ravel(axes))
    if len(axes) != 3:
        raise ValueError(f"axes must be three Axes (or one to split), got {len(axes)}")
    return axes


def _show(ax, scene: Scene, image, scale=None):
    from matplotlib.colors import ListedColormap

    h, w = scene.reference.shape[:2]
    extent = (0, w, h, 0)
    if scene.categories:
        cmap = ListedColormap([c for _, c in scene.categories]).with_extremes(bad="white")
        n = len(scene.categories) - 1
        return ax.imshow(image, cmap=cmap, vmin=0, vmax=n, extent=extent, interpolation="nearest")
    if image.ndim == 3:
        return ax.imshow(np.clip(np.nan_to_num(image, nan=1.0), 0, 1), extent=extent, interpolation="nearest")  # fmt: skip
    lo, hi = scale if scale is not None else _scale(scene.reference)
    return ax.imshow(image, cmap="viridis", vmin=lo, vmax=hi, extent=extent, interpolation="nearest")  # fmt: skip


def _scale(*images) -> tuple[float, float]:
    """One colour scale for every image given (the student's too: r40 06-4, a fan spoke
    covered 1.75 times drew as yellow as a full pixel on the package's scale, 0 to 1)."""
    finite = np.concatenate(
        [np.ravel(i)[np.isfinite(np.ravel(i))] for i in images if i is not None]
    )
    return (float(finite.min()), float(finite.max())) if finite.size else (0.0, 1.0)


def _key(axes, scene: Scene, shown, got=None, marked: bool = False):
    """What the colours mean: a legend of the categories under the package's panel (r40 08-3:
    the tile walk's three blues and greens had none; r214: only those a panel shows, the
    package's or ``got``; r248 S4: and the outline of the pixel explained below, where one is
    ``marked``), or one colour bar for both pictures."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    if scene.categories:
        drawn = [np.asarray(i, dtype=float) for i in (scene.reference, got) if i is not None]
        present = set(np.unique(np.concatenate([i[np.isfinite(i)] for i in drawn])).tolist())
        handles = [Patch(facecolor=c, edgecolor="0.5", label=name)
                   for k, (name, c) in enumerate(scene.categories) if k in present]  # fmt: skip
        if marked:
            handles.append(Line2D([], [], color=MARK_COLOUR, lw=2, marker="s", mfc="none",
                                  ms=7, ls="none", label="the pixel explained below"))  # fmt: skip
        return [axes[1].legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.02),
                               ncols=2, fontsize="x-small", frameon=False)]  # fmt: skip
    if scene.reference.ndim == 3 or shown is None:
        return []
    # under a wide, low picture, not beside it: a bar as tall as the panels ran into the
    # package's title above the floor (r64 07-6); beside a square one, which it leaves large
    h, w = scene.reference.shape[:2]
    wide = w > 1.5 * h
    # (under all three panels, which then stay in line: under two, the third rose over the
    # package's title)
    bar = axes[1].figure.colorbar(shown, ax=list(axes) if wide else list(axes[:2]), pad=0.02,
                                  orientation="horizontal" if wide else "vertical",
                                  shrink=0.5 if wide else 0.8, aspect=40 if wide else 20)  # fmt: skip
    bar.ax.tick_params(labelsize="x-small")
    if scene.value_name:
        bar.set_label(scene.value_name, fontsize="x-small")
    return [bar]


def _difference_panel(ax, scene: Scene):
    h, w = scene.reference.shape[:2]
    differs = scene.differs()
    base = np.where(np.isnan(scene.reference.reshape(h, w, -1)).all(axis=2), 1.0, 0.85)
    artists = [ax.imshow(base, cmap="gray", vmin=0, vmax=1, extent=(0, w, h, 0), interpolation="nearest")]  # fmt: skip
    d = scene.difference()
    if not scene.categories and np.isfinite(d).any():
        # from 0: where every difference is the same size (a quarter of a pixel's samples)
        # the default scale drew them as its lowest, near-white shade (r64 06-3)
        red = ax.imshow(d, cmap="Reds", vmin=0, vmax=float(np.nanmax(d)),
                        extent=(0, w, h, 0), interpolation="nearest")  # fmt: skip
        # r286 FIG8: a key for the reds under the panel; the title, which ran past the
        # figure's edge with "(darkest red)", only says the largest
        # (in an inset under the panel: a colour bar taking room from the panel moved it out
        # of line with the two pictures)
        cax = ax.inset_axes((0.1, -0.1, 0.8, 0.06))
        bar = ax.figure.colorbar(red, cax=cax, orientation="horizontal")
        bar.ax.tick_params(labelsize="x-small")
        bar.set_label("|yours − package's|", fontsize="x-small")
        artists += [red, bar]
        biggest = f"\nlargest {np.nanmax(d):.3g}"
    else:
        mask = np.zeros((h, w, 4))
        mask[differs] = (0.84, 0.19, 0.12, 1.0)
        wrong = scene.coverage_differs()
        if wrong is not None:  # only the walk differs there: a lighter colour
            mask[differs & ~wrong] = (0.99, 0.68, 0.42, 1.0)
        artists.append(ax.imshow(mask, extent=(0, w, h, 0), interpolation="nearest"))
        if wrong is not None:
            artists += _ring(ax, wrong)
        biggest = ""
    n = int(differs.sum())
    title = (
        f"{n} pixel{'s' * (n != 1)} differ{'s' * (n == 1)}{biggest}" if n else "no pixel differs"
    )
    wrong = scene.coverage_differs()
    if n and wrong is not None:
        title = _coverage_title(wrong, n)
    if not n and scene.check_failed:  # r94 D8-10: the picture must not read as a pass
        title += " here;\nthe failing cases above\nshow your mistake"
    ax.set_title(title, fontsize="small")
    return artists


#: At most this many wrongly covered pixels are ringed (more would hide the picture).
MAX_RINGS = 40


def _ring(ax, wrong: np.ndarray) -> list:
    """A black ring of a fixed size on screen round each wrongly covered pixel (r173 D1: in a
    48-px picture 170 px wide one pixel is 3.5 px on screen, dark red on orange, and five of
    them, the panel's point, could barely be seen)."""
    rows, cols = np.nonzero(wrong)
    if not 0 < rows.size <= MAX_RINGS:
        return []
    return [ax.scatter(cols + 0.5, rows + 0.5, s=90, facecolors="none", edgecolors="black",
                       linewidths=1.4, zorder=4)]  # fmt: skip


def _coverage_title(wrong: np.ndarray, n: int) -> str:
    """The difference panel's title where coverage differences are counted apart (r149 E1):
    "1 pixel covered wrongly (31, 31) (red), ringed; 319 walked differently (orange)", in
    lines of :data:`TITLE_WIDTH` characters."""
    k = int(wrong.sum())
    where = " " + ", ".join(f"({r}, {c})" for r, c in np.argwhere(wrong)[:2]) if 0 < k <= 2 else ""
    ringed = ", ringed" if 0 < k <= MAX_RINGS else ""
    covered = (
        f"{k} pixel{'s' * (k != 1)} covered wrongly{where} (red){ringed}" if k else "coverage right"
    )
    rest = n - k
    # r248 S4: the unit said
    walked = f"; {rest} pixel{'s' * (rest != 1)} walked differently (orange)" if rest else ""
    # r173 D1: two lines of 31 characters ran past the figure's right edge over a narrow panel
    return textwrap.fill(covered + walked, TITLE_WIDTH)


#: The difference panel's title, in characters a line (it sits over a panel a third as wide
#: as the figure).
TITLE_WIDTH = 25


def draw_comparison(scene: Scene, axes=None, pixel=None, connect: bool = True):
    """Yours, the package's, the differing pixels; ``pixel`` marked and explained.

    ``pixel`` is (row, col), ``"first"`` (the first differing pixel, when there is one) or
    None.
    With ``connect`` a click on any panel marks and explains the clicked pixel (in place).
    Returns the artists.
    """
    axes = _three_axes(axes)
    got = scene.student_image()
    if got is None and scene._outcome.not_implemented:
        return _stub_panels(scene, axes)
    artists = []
    scale = _scale(scene.reference, got)
    if got is None:  # narrow lines: the empty panel is as wide as a picture (r64 08-6)
        artists.append(axes[0].text(0.5, 0.5, textwrap.fill(str(scene.error), 18), ha="center", va="center", transform=axes[0].transAxes, fontsize="x-small"))  # fmt: skip
    else:
        artists.append(_show(axes[0], scene, got, scale))
    theirs = _show(axes[1], scene, scene.reference, scale)
    artists.append(theirs)
    if got is None:  # r64 08-6: every pixel drawn red said nothing, with no key
        axes[2].set_title("differences", fontsize="small")
        artists.append(axes[2].text(0.5, 0.5, textwrap.fill("none to show: no picture of yours", 16), ha="center", va="center", transform=axes[2].transAxes, fontsize="x-small"))  # fmt: skip
    else:
        artists += _difference_panel(axes[2], scene)
    if isinstance(pixel, str) and pixel == "first":  # the first differing pixel, if any
        differs = scene.differs() if got is not None else np.zeros(1, dtype=bool)
        wrong = scene.coverage_differs() if got is not None else None
        if wrong is not None and wrong.any():  # r149 E1: a pixel covered wrongly first
            differs = wrong
        pixel = tuple(np.argwhere(differs)[0]) if differs.any() else None
    artists += _key(axes, scene, theirs, got, marked=pixel is not None)
    axes[0].set_title("yours", fontsize="small")
    axes[1].set_title(textwrap.fill(f"the package's: {scene.title}", 26), fontsize="small")
    for ax in axes:
        ax.set_xticks([])
        ax.set_yticks([])
    marks = _Marks(scene, axes)
    if pixel is not None:
        marks.show(*as_pixel(pixel))
    if connect:
        # a function, not the bound method: the canvas keeps only weak references to methods
        axes[0].figure.canvas.mpl_connect("button_press_event", lambda e: marks.click(e))
    return artists + marks.artists


#: The three panels of the untouched stub (r64 08-6: the package's panel showed the answer
#: picture, e.g. 8.1's verdict map, beside an empty "yours" and an all-red difference panel).
STUB_PANELS = (
    ("yours", "not implemented yet"),
    ("the package's", "shown once your function returns answers (it is the answer's picture)"),
    ("differences", "none to show yet"),
)


def _stub_panels(scene: Scene, axes):
    """Notes instead of pictures: the stub has earned neither the answer nor a difference."""
    artists = []
    for ax, (title, note) in zip(axes, STUB_PANELS):
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(title, fontsize="small")
        if title == "the package's" and scene.inputs is not None:
            # its inputs instead, where the scene gives them (06, 07: r64 06-4, 07)
            shown = scene.inputs(ax)
            # r286 FIG6: 34 characters a line ran into the neighbouring panels' titles
            ax.set_title(textwrap.fill(f"the scene's input: {shown}", 26), fontsize="small")
            continue
        artists.append(ax.text(0.5, 0.5, textwrap.fill(note, 20), ha="center", va="center",
                               transform=ax.transAxes, fontsize="small"))  # fmt: skip
    return artists


class _Marks:
    """The marked pixel in every panel and its explanation, updated in place on a click."""

    def __init__(self, scene: Scene, axes):
        self.scene, self.axes = scene, axes
        self.boxes = [ax.plot([], [], color=MARK_COLOUR, linewidth=2)[0] for ax in axes]
        # the figure's (or subfigure's) bottom label: constrained layout makes room for it
        self.text = axes[0].figure.supxlabel("", fontsize="small")
        self.artists = [*self.boxes, self.text]

    def show(self, row: int, col: int) -> str:
        words = self.scene.explain(int(row), int(col))
        x, y = [col, col + 1, col + 1, col, col], [row, row, row + 1, row + 1, row]
        for box in self.boxes:
            box.set_data(x, y)
        # whole words only: "top-left" split at its hyphen reads as two words
        line = f"pixel ({row}, {col}): {words}"
        self.text.set_text(textwrap.fill(line, self._width(), break_on_hyphens=False))
        return words

    def _width(self) -> int:
        """Characters a line of the explanation, from the figure's width and the font (r286
        FIG5: 90 characters were cut at both sides of a 9-inch figure in the classroom
        style), at about 0.55 em a character."""
        fig = self.text.figure
        inches = fig.bbox.width / fig.dpi
        return max(40, min(110, int(0.95 * inches * 72 / (0.55 * self.text.get_fontsize()))))

    def click(self, event):
        if event.inaxes in self.axes and event.xdata is not None:
            h, w = self.scene.reference.shape[:2]
            row, col = int(np.floor(event.ydata)), int(np.floor(event.xdata))
            if 0 <= row < h and 0 <= col < w:
                self.show(row, col)
                event.canvas.draw_idle()


__all__ = ["Scene", "call", "draw_comparison"]
