"""``CasePicker``: browse the hard-case catalogue, ours beside the naive rasteriser.

Lesson 07's widget. Pick a screen-space case of :mod:`teachraster.study.hardcases` and a fill
method: the left panel colours every pixel by the triangle that owns it (red where a pixel is
covered twice), the right panel shows what the case's naive implementation covers, and the text
gives the case's *why*, what a correct rasteriser *must* do, whether ours passes its check, and
how the naive version differs.
"""

from __future__ import annotations

import html

import ipywidgets as widgets
import numpy as np
from matplotlib import colormaps

from ..plotting import COLORS, plot_coverage, plot_pixel_grid, plot_triangle
from ..study import hardcases
from .common import close_tree, labelled, style_context, title_html
from .display import FigureDisplay, new_figure, resolve_backend

#: Owner value of a pixel covered by no triangle, and by more than one.
NONE, SEVERAL = -1, -2


def owner_image(fills) -> np.ndarray:
    """(H, W) index of the triangle covering each pixel; NONE (-1) or SEVERAL (-2) otherwise.

    Parameters
    ----------
    fills : sequence of Fill (or of (H, W) bool arrays), one per triangle

    Examples
    --------
    >>> a = np.array([[1, 1, 0]], bool); b = np.array([[0, 1, 1]], bool)
    >>> owner_image([a, b]).tolist()
    [[0, -2, 1]]
    """
    masks = [np.asarray(getattr(f, "coverage", f), dtype=bool) for f in fills]
    owner = np.full(masks[0].shape, NONE, dtype=np.int64)
    count = np.zeros(masks[0].shape, dtype=np.int64)
    for k, m in enumerate(masks):
        owner[m] = k
        count += m
    owner[count > 1] = SEVERAL
    return owner


def plot_owners(ax, owner: np.ndarray, triangles=None, *, outlines: bool = True) -> list:
    """Pixels coloured by owning triangle (a qualitative palette), red where covered twice.

    Returns the artists drawn (coverage images, then triangle outlines).
    """
    h, w = owner.shape
    palette = colormaps["tab20"].colors
    artists = [plot_pixel_grid(ax, w, h, ticks=False)]
    for k in range(int(owner.max()) + 1):
        if (owner == k).any():
            artists.append(
                plot_coverage(ax, owner == k, color=palette[(2 * k) % 20 + (k // 10) % 2])
            )
    if (owner == SEVERAL).any():
        artists.append(plot_coverage(ax, owner == SEVERAL, color=COLORS["outside"]))
    if outlines and triangles is not None:
        for xy in triangles:
            artists.append(plot_triangle(ax, xy, labels=False, arrows=False))
    return artists


def screen_cases() -> list[str]:
    """Names of the catalogue's screen-space cases (one fill per triangle), in catalogue order."""
    return [name for name, case in hardcases.CASES.items()
            if case.kind in ("mesh", "triangle", "triangles") and case.triangles is not None]  # fmt: skip


class CasePicker:
    """Choose a hard case and a fill method; see who owns each pixel, and what naive code does.

    Parameters
    ----------
    case : str
        Starting case (one of :func:`screen_cases`).
    method : {"halfplane", "span"}
    backend : {"auto", "ipympl", "image"}
    style : str, optional

    Attributes
    ----------
    widget : ipywidgets.VBox
    case, method : Dropdown, ToggleButtons
    owner : (H, W) int
        :func:`owner_image` of our fill (what the left panel shows).
    naive_counts : (H, W) int or None
        The naive implementation's coverage counts (right panel), if the case has them.
    passed : bool
        Whether our result passes the case's check.
    info : ipywidgets.HTML

    Examples
    --------
    >>> picker = CasePicker("d3d_split_square", backend="image")
    >>> picker.passed, int((picker.owner == SEVERAL).sum())
    (True, 0)
    >>> picker.case.value = "fan_spokes_through_centres"
    >>> int(picker.owner.max())
    15
    >>> picker.close()
    """

    #: ``teachraster html``: the offline page steps through every hard case (:mod:`.offline`)
    _offline_sweep_ = "case"

    def __init__(self, case: str = "fan_spokes_through_centres", method: str = "halfplane", *,
                 backend: str = "auto", style: str | None = None) -> None:  # fmt: skip
        names = screen_cases()
        if case not in names:
            raise ValueError(f"case must be one of the screen-space cases {names}, got {case!r}")
        self.backend = resolve_backend(backend)
        self.case = widgets.Dropdown(options=names, value=case, description="case",
                                     layout=widgets.Layout(width="420px"))  # fmt: skip
        self.method = widgets.ToggleButtons(options=hardcases.FILL_METHODS, value=method)
        self._style = style
        with style_context(style):
            self.fig = new_figure((9.0, 4.4), self.backend)  # fits the notebook column
            self.fig.set_layout_engine("constrained")
            self.axes = self.fig.subplots(1, 2)
        self._run()
        self._draw()
        self.display = FigureDisplay(self.fig, self.backend)
        self.info = widgets.HTML(self._info_html())
        for control in (self.case, self.method):
            control.observe(lambda change: self.update(), "value")
        title = title_html(
            "Hard cases: who owns each pixel?",
            "Left: our fill, each pixel in the colour of the triangle that covers it (red: "
            "covered twice). Right: what a naive rasteriser covers (red: twice).",
        )
        controls = widgets.HBox([self.case, labelled("method", self.method)])
        self.widget = widgets.VBox([title, controls, self.info, self.display.widget])

    def _run(self) -> None:
        c = hardcases.get_case(self.case.value)
        self._case = c
        result = c.run(self.method.value)
        self.owner = owner_image(result.fills)
        try:
            c.check(result)
            self.passed, self.failure = True, ""
        except AssertionError as err:
            self.passed, self.failure = False, str(err)
        naive = c.naive() if c.has_naive else None
        self.naive_counts = None if naive is None else naive.counts
        diff = c.naive_difference(result, naive) if naive is not None else None
        self.difference = diff or ""

    def _draw(self) -> None:
        with style_context(self._style):
            for ax in self.axes:
                ax.clear()
            tris = self._case.triangles
            plot_owners(self.axes[0], self.owner, tris)
            self.axes[0].set_title(f"ours ({self.method.value}): pixel → triangle")
            ax = self.axes[1]
            if self.naive_counts is None:
                h, w = self.owner.shape
                plot_pixel_grid(ax, w, h, ticks=False)
                ax.set_title("no naive coverage for this case")
            else:
                n = self.naive_counts
                plot_pixel_grid(ax, n.shape[1], n.shape[0], ticks=False)
                plot_coverage(ax, n == 1)
                plot_coverage(ax, n >= 2, color=COLORS["outside"])
                for xy in tris:
                    plot_triangle(ax, xy, labels=False, arrows=False)
                ax.set_title(f"naive: max {int(n.max())} hit(s) per pixel")

    def update(self) -> None:
        """Run the chosen case with the chosen method and redraw."""
        self._run()
        self._draw()
        self.info.value = self._info_html()
        self.display.refresh()

    def _info_html(self) -> str:
        c = self._case
        verdict = ("<b style='color:#009E73'>passes its check</b>" if self.passed
                   else f"<b style='color:#D55E00'>FAILS</b>: {html.escape(self.failure)}")  # fmt: skip
        lines = [f"<b>why</b>: {html.escape(c.why)}", f"<b>must</b>: {html.escape(c.expect)}",
                 f"ours: {verdict}"]  # fmt: skip
        if c.naive_does:
            lines.append(f"<b>naive</b>: {html.escape(c.naive_does)}")
        if self.difference:
            lines.append(f"→ {html.escape(self.difference)}")
        return "<br>".join(lines)

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    def close(self) -> None:
        """Close every widget of the picker."""
        self.display.close()
        close_tree(self.widget)
