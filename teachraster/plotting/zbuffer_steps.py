"""The z-buffer one triangle at a time, read from a render's trace.

``tr.render(..., trace=True)`` records every fragment in drawing order with its stored depth
and whether it passed the depth test when it arrived (``RenderTrace.fragment_*``). Replaying
those records up to triangle k gives the depth buffer as it was after that triangle: nothing is
rasterised or tested again here, the picture only reads the trace.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.colors import BoundaryNorm, ListedColormap
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.ticker import FormatStrFormatter, MaxNLocator

from .common import fs, image_extent
from .style import COLORS, OKABE_ITO, VALUE_CMAP

#: Classes of the fragment panel, in order: empty, written earlier, passed, failed.
FRAGMENT_CLASSES = ("empty", "written by an earlier triangle", "passed: written", "failed")
FRAGMENT_COLORS = ("#FFFFFF", COLORS["rejected"], OKABE_ITO["blue"], OKABE_ITO["vermillion"])


def _last_per_pixel(pixel: np.ndarray, values: np.ndarray, size: int) -> np.ndarray:
    """``values`` of the last record at each pixel (drawing order), NaN where there is none."""
    out = np.full(size, np.nan)
    last = len(pixel) - 1 - np.unique(pixel[::-1], return_index=True)[1]
    out[pixel[last]] = values[last]
    return out


def buffer_after(frame, k: int) -> tuple[np.ndarray, np.ndarray]:
    """Depth buffer and triangle id after triangles 0..k of ``frame`` (a traced render).

    Returns
    -------
    depth : (H, W) float64
        The stored depth, NaN where still cleared.
    triangle : (H, W) int
        The triangle whose fragment is stored, -1 where still cleared.
    """
    trace = frame.trace
    if trace is None:
        raise ValueError("frame must come from tr.render(..., trace=True)")
    height, width = frame.depth.shape[:2]
    keep = trace.fragment_passed & (trace.fragment_triangle <= k)
    pixel = (trace.fragment_row * width + trace.fragment_col)[keep]
    depth = _last_per_pixel(pixel, trace.fragment_depth[keep], width * height)
    tri = _last_per_pixel(pixel, trace.fragment_triangle[keep].astype(float), width * height)
    return depth.reshape(height, width), np.nan_to_num(tri, nan=-1).astype(int).reshape(
        height, width
    )


def fragment_classes(frame, k: int) -> np.ndarray:
    """(H, W) int: 0 empty, 1 written earlier, 2 triangle k passed, 3 triangle k failed."""
    trace = frame.trace
    height, width = frame.depth.shape[:2]
    before = buffer_after(frame, k - 1)[1] >= 0 if k > 0 else np.zeros((height, width), bool)
    classes = before.astype(int)
    mine = trace.fragment_triangle == k
    for value, which in ((2, trace.fragment_passed), (3, ~trace.fragment_passed)):
        sel = mine & which
        classes[trace.fragment_row[sel], trace.fragment_col[sel]] = value
    return classes


def fragment_counts(frame, k: int) -> tuple[int, int]:
    """(passed, failed): how many fragments of triangle ``k`` passed and failed the depth test."""
    trace = frame.trace
    mine = trace.fragment_triangle == k
    passed = int((mine & trace.fragment_passed).sum())
    return passed, int(mine.sum()) - passed


@dataclass
class ZBufferStepView:
    """Two panels: triangle k's fragments (passed / failed) and the depth buffer after it.

    ``show(k)`` updates both images and the titles in place. The depth panel's colour scale
    is fixed once, to the range of every depth written at any step, so that no step shows a
    value beyond its colour bar.
    """

    frame: object
    ax_fragments: object
    ax_depth: object

    def __post_init__(self) -> None:
        height, width = self.frame.depth.shape[:2]
        extent = image_extent(width, height)
        cmap = ListedColormap(FRAGMENT_COLORS)
        norm = BoundaryNorm(np.arange(-0.5, 4.0), cmap.N)
        self.classes = self.ax_fragments.imshow(np.zeros((height, width)), cmap=cmap, norm=norm,
                                                extent=extent, interpolation="nearest")  # fmt: skip
        # the whole scene's outline, so that the first triangles are seen in their place
        ys, xs = np.mgrid[0:height, 0:width] + 0.5
        self.outline = self.ax_fragments.contour(
            xs, ys, self.frame.coverage.astype(float), levels=[0.5], colors=COLORS["grid"],
            linewidths=1.5, linestyles="--")  # fmt: skip
        handles = [Patch(fc=c, ec=COLORS["grid"], label=t)
                   for c, t in zip(FRAGMENT_COLORS[1:], FRAGMENT_CLASSES[1:])]  # fmt: skip
        handles.append(Line2D([], [], color=COLORS["grid"], lw=1.5, ls="--",
                              label="the whole scene, when drawn"))  # fmt: skip
        # one key for the figure, two columns under both panels: a single column under the
        # left panel left the right half of that row empty (review r59 05a-5)
        self.legend = self.ax_fragments.figure.legend(
            handles=handles, loc="outside lower center", fontsize=fs(0.8), ncols=2, frameon=False
        )
        # the scale covers every depth the buffer holds at any step, that is every fragment
        # that passed (and was written): the final buffer's range alone left the back faces,
        # stored for a while and covered later, flat at its top (review r167 05a-3)
        trace = self.frame.trace
        written = trace.fragment_depth[trace.fragment_passed]
        self.depth = self.ax_depth.imshow(np.full((height, width), np.nan), cmap=VALUE_CMAP,
                                          vmin=written.min(), vmax=written.max(), extent=extent,
                                          interpolation="nearest")  # fmt: skip
        # beside the panel: below it, constrained layout left its label cut off by the
        # fragment panel's key, which sets the height of that row
        bar = self.ax_depth.figure.colorbar(self.depth, ax=self.ax_depth, location="right",
                                            shrink=0.8)  # fmt: skip
        bar.locator = MaxNLocator(4)  # at least three labelled ticks over the short range
        bar.formatter = FormatStrFormatter("%.3f")
        bar.update_ticks()
        bar.set_label(r"window depth $z_\mathrm{win}$ (dark = nearer)")  # as plot_depth names it
        self.colorbar = bar
        rows, cols = np.nonzero(self.frame.coverage)
        pad = 0.08 * max(width, height)
        for ax in (self.ax_fragments, self.ax_depth):  # zoom on the scene: it fills the panel
            ax.set(xticks=[], yticks=[], xlim=(cols.min() - pad, cols.max() + 1 + pad),
                   ylim=(rows.max() + 1 + pad, rows.min() - pad))  # fmt: skip
        self._title_size = fs(0.9)  # the style's size now, not whatever is active at show()
        self.ax_depth.set_title("depth buffer after it", fontsize=self._title_size)
        self.counts = (0, 0)

    @property
    def n_triangles(self) -> int:
        """Number of input triangles (the steps)."""
        return int(self.frame.trace.fragment_triangle.max()) + 1

    def show(self, k: int) -> tuple[int, int]:
        """Show triangle ``k``; returns (fragments passed, fragments failed)."""
        classes = fragment_classes(self.frame, k)
        self.classes.set_data(classes)
        self.depth.set_data(buffer_after(self.frame, k)[0])
        self.counts = (int((classes == 2).sum()), int((classes == 3).sum()))
        self.ax_fragments.set_title(
            f"triangle {k}: {self.counts[0]} pass, {self.counts[1]} fail", fontsize=self._title_size
        )
        return self.counts
