"""Presentation style: colour-blind-safe colours and a one-call classroom look.

Every plot in :mod:`teachraster.plotting` takes its colours from :data:`COLORS`, which assigns
each *role* (triangle edge, filled pixel, bounding box, ...) one colour of the Okabe–Ito
palette, so a figure means the same in every lesson and reads for colour-blind students too.
Sizes (fonts, line widths, marker sizes) come from matplotlib's ``rcParams``, which
:func:`use_style` sets:

- ``use_style("classroom")``: large fonts, thick lines and big markers for a projector;
- ``use_style("default")``: matplotlib's own defaults again.

``use_style`` changes the style at once and also works as a context manager, which puts the
previous settings back on exit::

    with use_style("classroom"):
        fig, ax = plt.subplots()
        ...
"""

from __future__ import annotations

from collections.abc import Mapping

import matplotlib as mpl
import matplotlib.style as mstyle
from cycler import cycler

#: The Okabe–Ito palette (Okabe & Ito 2008), distinguishable with every common colour-vision
#: deficiency. Black first, so that the first line of an unstyled plot stays black.
OKABE_ITO = {
    "black": "#000000",
    "orange": "#E69F00",
    "sky_blue": "#56B4E9",
    "bluish_green": "#009E73",
    "yellow": "#F0E442",
    "blue": "#0072B2",
    "vermillion": "#D55E00",
    "reddish_purple": "#CC79A7",
}

#: The colour of each role in every teachraster plot.
COLORS = {
    "edge": OKABE_ITO["black"],  # triangle edges, arrows and vertex labels
    "fill": OKABE_ITO["sky_blue"],  # covered (filled) pixels
    "rejected": "#D9D9D9",  # pixels tested and rejected (half-planes)
    "grid": "#9A9A9A",  # pixel boundaries
    "centre": "#6E6E6E",  # pixel centres (the sample points)
    "bbox": OKABE_ITO["orange"],  # bounding box
    "split": OKABE_ITO["reddish_purple"],  # the split line at u4
    "flat_bottom": OKABE_ITO["bluish_green"],  # the upper, flat-bottom triangle
    "flat_top": OKABE_ITO["yellow"],  # the lower, flat-top triangle
    "current": OKABE_ITO["vermillion"],  # the current raster line or pixel
    "inside": OKABE_ITO["blue"],  # positive edge values / tests passed
    "outside": OKABE_ITO["vermillion"],  # negative edge values / tests failed
}

#: Sequential colour map for values (perceptually uniform and colour-blind safe).
VALUE_CMAP = "cividis"
#: Sequential colour map for errors: dark means no error, bright means large.
ERROR_CMAP = "inferno"
#: Diverging colour map for signed edge values (blue inside, red outside).
SIGNED_CMAP = "RdBu"

_CYCLE = cycler(color=[OKABE_ITO[k] for k in ("blue", "orange", "bluish_green", "vermillion",
                                               "reddish_purple", "sky_blue", "yellow", "black")])  # fmt: skip

#: Widest figure, in pixels, that fits a JupyterLab notebook column at 1400 x 900 with the file
#: browser open (about 970 px, less the output area's padding): a lesson figure is at most this
#: wide at the classroom style's dpi, so its text is shown at the style's size, never shrunk.
COLUMN_WIDTH_PX = 940

#: rcParams of each named style ("default" is matplotlib's own defaults).
STYLES: dict[str, Mapping[str, object]] = {
    "classroom": {
        "figure.figsize": (9.0, 6.0),  # fits COLUMN_WIDTH_PX at figure.dpi
        "figure.dpi": 100,
        "savefig.dpi": 150,
        "font.size": 18,
        "axes.titlesize": 20,
        "axes.titleweight": "bold",
        "axes.labelsize": 18,
        "axes.linewidth": 1.6,
        "axes.prop_cycle": _CYCLE,
        "xtick.labelsize": 15,
        "ytick.labelsize": 15,
        "xtick.major.width": 1.6,
        "ytick.major.width": 1.6,
        "xtick.major.size": 6,
        "ytick.major.size": 6,
        "legend.fontsize": 15,
        "legend.framealpha": 0.95,
        "lines.linewidth": 3.5,
        "lines.markersize": 10,
        "patch.linewidth": 2.0,
        "grid.linewidth": 1.0,
        "image.cmap": VALUE_CMAP,
        # Unhinted glyphs: at projector sizes they look the same, and matplotlib renders them
        # about 40% faster, which a step-through figure redrawn at every step needs.
        "text.hinting": "none",
    },
}


class use_style:  # noqa: N801 (a function to the user; a class only to be a context manager)
    """Switch the plotting style: ``"classroom"`` (projector) or ``"default"``.

    The change takes effect immediately and lasts until the next call. Used in a ``with``
    statement, the previous settings come back when the block ends.

    Parameters
    ----------
    name : {"classroom", "default"}
        ``"classroom"``: large fonts, thick lines, the Okabe–Ito colour cycle;
        ``"default"``: matplotlib's defaults.

    Examples
    --------
    >>> import matplotlib as mpl
    >>> with use_style("classroom"):
    ...     mpl.rcParams["font.size"]
    18.0
    """

    def __init__(self, name: str = "classroom") -> None:
        if name != "default" and name not in STYLES:
            raise ValueError(f"unknown style {name!r}; choose from {['default', *STYLES]}")
        # What rc_context saves: everything but the backend (restoring it could switch it).
        self._saved = {k: v for k, v in mpl.rcParams.items() if k != "backend"}
        self.name = name
        if name == "default":
            mstyle.use("default")  # skips backend and other non-style settings itself
        else:
            mstyle.use("default")  # start clean, so styles do not pile up
            mpl.rcParams.update(STYLES[name])

    def __enter__(self) -> use_style:
        return self

    def __exit__(self, *exc) -> None:
        # dict.update skips rcParams' validation (and its deprecation warnings): these values
        # were valid when saved.
        dict.update(mpl.rcParams, self._saved)

    def __repr__(self) -> str:
        return f"use_style({self.name!r})"
