"""What a fill's set-up steps find, drawn: the snapped vertices, the winding, the raster lines
to visit, the roles.

Before the first pixel a fill snaps its vertices, finds their winding, the raster lines (span
tables) or the bounding box to work on, and, for span tables, sorts the vertices into roles
and splits at point 4. The box and the split have artists of their own
(:func:`~teachraster.plotting.plot_bbox`, :func:`~teachraster.plotting.plot_split`); the
others were captions only, over one unchanged picture (review r229 01-W1: the player's steps
1-3 were byte-identical frames; review r239 01-W1: step 0, the snap, drew nothing at all).
:func:`plot_setup_marks` draws them:

- the **snap**: each vertex tagged with its position on the sub-pixel grid, the caption's
  numbers (:attr:`~teachraster.core.trace.FillTrace.snapped`), so that even a vertex the snap
  leaves where it was shows what the step found;
- the **winding**: an arrow turning round the triangle's incentre the way v1 → v2 → v3 run
  as given, and the trace's word for it (:attr:`~teachraster.core.trace.FillTrace.turn`);
- the **raster lines** of a span-table fill: a band over the rows it steps through, a line
  along the centre of each (solid where the half-open loop fills, dotted for the bottom
  vertex's line, which it traces but does not visit:
  :attr:`~teachraster.core.trace.FillTrace.visited`);
- the **roles** the sort gives: ``top``, ``middle``, ``bottom`` beside the vertex labels
  (:data:`~teachraster.core.trace.ROLES`, in the trace's ``span.order``).

Everything is read from the trace; :meth:`SetupArtists.show` picks what a step shows.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.lines import Line2D
from matplotlib.patches import FancyArrowPatch, Rectangle
from matplotlib.text import Text

from ..core.trace import ROLES, FillTrace
from .common import Artists, annotate_near, as_trace, fs, label_box, lw
from .style import COLORS

#: The winding arrow's colour (a dark blue: no other artist of a fill's set-up uses it).
TURN_COLOR = COLORS["inside"]
#: How far round the incentre the winding arrow turns (degrees): most of a circle, open
#: enough that its head and its tail read apart.
TURN_DEGREES = 290.0


@dataclass
class SetupArtists(Artists):
    """Artists of :func:`plot_setup_marks`."""

    band: Rectangle
    lines: LineCollection
    arc: Line2D
    head: FancyArrowPatch
    turn_label: Text
    roles: list = field(default_factory=list)
    #: the snapped positions, one tag per vertex (the snap step's marks)
    coords: list = field(default_factory=list)
    #: the trace drawn, and whether each mark has something to show for it
    trace: FillTrace | None = None

    def update(self, fill, labels=()) -> None:
        """Move the marks to another fill (same artists). ``labels``: the vertex labels of
        :func:`~teachraster.plotting.plot_triangle`, already placed; each role goes just
        beyond its vertex's label, on the same side."""
        trace = as_trace(fill, "plot_setup_marks")
        self.trace = trace
        self._update_turn(trace)
        self._update_rows(trace)
        self._update_roles(trace, list(labels))
        self._update_coords(trace, list(labels))

    def _update_turn(self, trace: FillTrace) -> None:
        xy = np.asarray(trace.snapped, dtype=np.float64)
        if trace.turn is None:
            return
        sides = np.array([np.hypot(*(xy[(k + 1) % 3] - xy[(k + 2) % 3])) for k in range(3)])
        centre = sides @ xy / sides.sum()  # the incentre: farthest inside from every edge
        inradius = abs(trace.signed_area) * 2 / sides.sum()
        radius = max(0.8 * inradius, 0.6)
        # y down: the angle in data coordinates grows clockwise on screen, the sign of the
        # signed area (positive when v1 -> v2 -> v3 run clockwise on screen)
        sign = 1.0 if trace.signed_area > 0 else -1.0
        start = np.arctan2(*(xy[0] - centre)[::-1])  # from v1's side
        angles = start + sign * np.radians(np.linspace(0.0, TURN_DEGREES, 60))
        points = centre + radius * np.column_stack([np.cos(angles), np.sin(angles)])
        self.arc.set_data(points[:-1, 0], points[:-1, 1])
        self.head.set_positions(tuple(points[-4]), tuple(points[-1]))
        self.turn_label.set_position(tuple(centre))
        # "counter-clockwise" on two lines: narrow enough to stay inside the arc
        self.turn_label.set_text("v1→v2→v3\n" + trace.turn.replace("-", "-\n"))

    def _update_rows(self, trace: FillTrace) -> None:
        s = trace.span
        if s is None or not len(s.rows):
            return
        rows = np.asarray(s.rows)
        self.band.set_y(float(rows[0]))
        self.band.set_height(float(rows[-1] - rows[0] + 1))
        y = rows + 0.5
        self.lines.set_segments([((0, v), (trace.width, v)) for v in y])
        visited = trace.visited
        self.lines.set_linestyles([(0, None) if on else (0, (1.5, 2.5)) for on in visited])

    def _update_roles(self, trace: FillTrace, labels: list) -> None:
        s = trace.span
        if s is None or len(labels) != 3:
            return
        ax = self.band.axes
        ax.get_xlim()  # brings autoscaled limits up to date before transData is read
        box = ax.get_window_extent()
        scale = ax.figure.dpi / 72.0  # display pixels per point
        centre = np.asarray(trace.snapped, dtype=np.float64).mean(axis=0)
        # the edges, in points: "middle" lay over the edge into its vertex, which seemed to
        # stop short of it (review r452 01-FIG2); a role goes where it crosses none
        edges = _edges_in_points(ax, trace.snapped, scale)
        # and the split line, which the middle vertex lies on: the split step draws it
        v_mid = float(s.sorted_xy[1, 1])
        split = ax.transData.transform([(0.0, v_mid), (float(trace.width), v_mid)]) / scale
        edges.append((split[0], split[1]))
        for tag, role, vertex in zip(self.roles, ROLES, s.order):
            label = labels[vertex]
            at = ax.transData.transform(label.xy) / scale  # the vertex, in points
            tag.xy = label.xy
            tag.set_text(role)
            tag.set_position(_role_offset(label, role, at, box.extents / scale,
                                          label.xy[0] < centre[0], edges=edges,
                                          stack=True))  # fmt: skip

    def _update_coords(self, trace: FillTrace, labels: list) -> None:
        """Each vertex's snapped position beside its label, written as the snap's caption
        writes it (``:g``), placed as the roles are (they never show at the same step);
        with no labels, just above its vertex."""
        xy = np.asarray(trace.snapped, dtype=np.float64)
        texts = [f"({x:g}, {y:g})" for x, y in xy]
        if len(labels) != 3:
            for tag, text, p in zip(self.coords, texts, xy):
                tag.xy = tuple(p)
                tag.set_text(text)
                tag.set_position((0.0, 1.2 * tag.get_fontsize()))
            return
        ax = self.band.axes
        ax.get_xlim()  # brings autoscaled limits up to date before transData is read
        box = ax.get_window_extent()
        scale = ax.figure.dpi / 72.0  # display pixels per point
        centre = xy.mean(axis=0)
        # the edges, in points: a position tag is long, and beside its label it cut an edge or
        # floated columns from its vertex (review r265 01-FIG3); it goes where it crosses none
        edges = _edges_in_points(ax, xy, scale)
        # the grid's row boundaries (whole y), in points: a tag centred on one covers no pixel
        # centre when less than a pixel high (review r291 02-3: "(14.5, 6.25)" on row 6's)
        rows = (
            ax.transData.transform(
                np.column_stack([np.zeros(trace.height + 1), np.arange(trace.height + 1)])
            )[:, 1]
            / scale
        )
        for tag, label, text in zip(self.coords, labels, texts):
            at = ax.transData.transform(label.xy) / scale
            tag.xy = label.xy
            tag.set_text(text)
            tag.set_position(_role_offset(label, text, at, box.extents / scale,
                                          label.xy[0] < centre[0], italic=False,
                                          edges=edges, tag_size=tag.get_fontsize(),
                                          rows=rows))  # fmt: skip

    def show(self, kind: str | None, sorted_: bool) -> None:
        """Show what the step of ``kind`` found: the snapped positions at ``"snap"``, the
        winding at ``"winding"``, the raster lines at ``"rows"``; the roles where
        ``sorted_`` (a view: at the sort and split steps, which speak of them)."""
        trace = self.trace
        for tag in self.coords:
            tag.set_visible(kind == "snap" and trace is not None)
        turning = kind == "winding" and trace is not None and trace.turn is not None
        for artist in (self.arc, self.head, self.turn_label):
            artist.set_visible(turning)
        rows = kind == "rows" and trace is not None and trace.span is not None
        rows = rows and bool(len(trace.span.rows))
        self.band.set_visible(rows)
        self.lines.set_visible(rows)
        roles = sorted_ and trace is not None and trace.span is not None
        for tag in self.roles:
            tag.set_visible(roles)


def _edges_in_points(ax, xy, scale: float) -> list:
    """The triangle ``xy``'s three edges as pairs of points on the screen, in points."""
    corners = ax.transData.transform(np.asarray(xy, dtype=np.float64)) / scale
    return [(corners[k], corners[(k + 1) % 3]) for k in range(3)]


def _clear_of(offset, inside, edges, at, half_w: float, half_h: float) -> bool:
    """A tag at ``offset`` from ``at`` lies inside the Axes and crosses no edge."""
    centre = (at[0] + offset[0], at[1] + offset[1])
    return inside(offset) and not _crosses(edges, centre, half_w + 2.0, half_h)


def _crosses(edges, centre, half_w: float, half_h: float) -> bool:
    """Whether a segment of ``edges`` (pairs of points) enters the box of half sizes
    ``half_w``, ``half_h`` around ``centre`` (all in points), sampled finely enough for a box
    of a few points."""
    t = np.linspace(0.0, 1.0, 200)[:, None]
    for a, b in edges:
        pts = np.asarray(a) + t * (np.asarray(b) - np.asarray(a))
        inside = (np.abs(pts[:, 0] - centre[0]) <= half_w) & (
            np.abs(pts[:, 1] - centre[1]) <= half_h
        )
        if inside.any():
            return True
    return False


def _role_offset(label, role: str, at, extents, left: bool,
                 italic: bool = True, edges=None, tag_size: float | None = None,
                 rows=None, stack: bool = False) -> tuple[float, float]:  # fmt: skip
    """Where a tag (a role, a position) goes (points from its vertex): one line beyond the
    vertex label, the way the label is pushed out; where that leaves the Axes (a vertex at
    the grid's top or bottom: it ran over the tick labels or the frame), beside the label
    instead, on the side away from the triangle (``left``) if it fits there, else on the
    other. A tag stays wholly inside the Axes: overhanging by half its width, "middle" at a
    vertex near the grid's right side crossed the frame (review r239 01-W1). With ``edges``
    (the triangle's, in points), the first of these places, then of a few more near the vertex
    (beside it on its own row, above or below its label, along its angle's bisector), the
    nearest to the vertex whose box crosses no edge; ``tag_size`` is the tag's font size
    (default: the label's). With ``rows`` (the y, in points, of the grid's row boundaries),
    each place moved onto the nearest boundary is tried first: there a tag less than a pixel
    high covers none of the pixel centres. With ``stack``, also above or below the label,
    moved sideways into the Axes, a little farther each time (a role tag: short enough to
    stand over its vertex's label)."""
    dx, dy = label.get_position()  # the label's offset from its vertex, in points
    size = label.get_fontsize()
    own = size if tag_size is None else tag_size
    # half of the tag's padded box (italic letters are wider than digits)
    half_w = own * ((0.33 if italic else 0.3) * len(role) + 0.3)
    half_h = 0.75 * own
    x0, y0, x1, y1 = extents
    norm = float(np.hypot(dx, dy)) or 1.0
    out = (dx + 1.1 * size * dx / norm, dy + 1.1 * size * dy / norm)

    def inside(offset):
        x, y = at[0] + offset[0], at[1] + offset[1]
        if not (x0 + half_w <= x <= x1 - half_w and y0 + half_h <= y <= y1 - half_h):
            return False
        # clear of the vertex label's own box (two bold characters): the nearest place to the
        # vertex lay half on "v1" and hid its position's digits (review r452 01-FIG1)
        return (
            abs(offset[0] - dx) >= half_w + 0.8 * size or abs(offset[1] - dy) >= half_h + 0.7 * size
        )

    beside = 0.85 * size + half_w + 2.0  # the label's half width, the tag's, a gap
    sides = (-1.0, 1.0) if left else (1.0, -1.0)
    places = [out, *((dx + side * beside, dy) for side in sides)]
    if edges is not None:
        # beside the vertex dot on its own row, a little farther each time (into the angle
        # between its edges, where the dot leaves no room), and above or below the label
        near = [half_w + (0.6 + 0.5 * j) * size for j in range(6)]
        extra = [(side * d, 0.0) for d in near for side in sides]
        extra += [(dx, dy + side * 1.6 * size) for side in (1.0, -1.0)]
        if stack:
            # the same, moved sideways into the Axes and a little farther up or down each
            # time: at a vertex by the grid's side they overhang its frame, and the nearest
            # clear place lay six columns off, far from the vertex it names (review r472
            # 01-FIG1)
            fit = float(np.clip(at[0] + dx, x0 + half_w, max(x0 + half_w, x1 - half_w)))
            extra += [(fit - at[0], dy + side * (1.6 + 0.5 * j) * size)
                      for j in range(4) for side in (1.0, -1.0)]  # fmt: skip
        # along the bisector of the vertex's angle, outwards (away from both its edges) and
        # into the angle, where a vertex at the grid's side leaves no room outside
        ends = [b if np.allclose(a, at) else a for a, b in edges
                if np.allclose(a, at) or np.allclose(b, at)]  # fmt: skip
        units = [(np.asarray(e) - at) / (float(np.hypot(*(np.asarray(e) - at))) or 1.0)
                 for e in ends]  # fmt: skip
        halfway = sum(units) if len(units) == 2 else np.zeros(2)
        if float(np.hypot(*halfway)) > 1e-9:
            halfway = halfway / float(np.hypot(*halfway))
            # and just above or below it: the middle vertex's bisector runs along the split
            # line, which a role tag must not hide either (review r452 01-FIG2)
            extra += [tuple(sign * (half_w + 0.5 * j * size) * halfway + (0.0, lift))
                      for j in range(1, 16) for sign in (-1.0, 1.0)
                      for lift in (0.0, half_h + 2.0, -half_h - 2.0)]  # fmt: skip
        tried = places + extra
        if rows is not None and len(rows):
            rows = np.asarray(rows, dtype=np.float64)
            snapped = [(x, float(rows[np.argmin(np.abs(rows - at[1] - y))] - at[1]))
                       for x, y in tried]  # fmt: skip
            tried = [o for o in snapped if _clear_of(o, inside, edges, at, half_w, half_h)] or tried
        clear = [o for o in tried if _clear_of(o, inside, edges, at, half_w, half_h)]
        if clear:  # the nearest to its vertex: a tag read with its vertex, not columns off
            return min(clear, key=lambda offset: float(np.hypot(*offset)))
    for offset in places[:3]:
        if inside(offset):
            return offset
    # neither fits (a narrow grid): beside the label, moved sideways into the Axes
    x = float(np.clip(at[0] + dx + sides[0] * beside, x0 + half_w, max(x0 + half_w, x1 - half_w)))
    return (x - at[0], dy)


def plot_setup_marks(ax, fill, labels=()) -> SetupArtists:
    """The winding arrow, the raster lines to visit and the vertices' roles, hidden until
    :meth:`SetupArtists.show` asks for them (see the module's text).

    Parameters
    ----------
    ax : matplotlib Axes
    fill : Fill (with trace) or FillTrace
    labels : list of Annotation, optional
        The vertex labels (``plot_triangle(...).labels``), beside which the roles go.

    Returns
    -------
    SetupArtists
        ``band`` and ``lines`` (the raster lines), ``arc``, ``head`` and ``turn_label``
        (the winding), ``roles`` and ``coords`` (three Annotations each: the sort's roles,
        the snapped positions).

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> import teachraster as tr
    >>> fill = tr.rasterize(tr.Triangle([[1, 1], [7, 2], [3, 7]]), 8, 8, method="span",
    ...                     trace=True)
    >>> fig, ax = plt.subplots()
    >>> marks = plot_setup_marks(ax, fill)
    >>> marks.show("winding", False)
    >>> marks.turn_label.get_text().split()[-1], marks.band.get_visible()
    ('clockwise', False)
    >>> marks.show("snap", False)
    >>> [tag.get_text() for tag in marks.coords]
    ['(1, 1)', '(7, 2)', '(3, 7)']
    >>> plt.close(fig)
    """
    trace = as_trace(fill, "plot_setup_marks")
    c = COLORS["current"]
    band = Rectangle((0, 0), 1, 1, fc=c, ec="none", alpha=0.08, zorder=0.6,
                     transform=ax.get_yaxis_transform())  # fmt: skip
    ax.add_patch(band)
    # under the pixel grid (zorder 1.5), as a view's blitted layers draw them too
    lines = LineCollection([], colors=c, linewidths=lw(0.45), alpha=0.8, zorder=1.4)
    ax.add_collection(lines, autolim=False)
    arc = ax.plot([], [], "-", color=TURN_COLOR, lw=lw(0.8), zorder=4.6,
                  solid_capstyle="round")[0]  # fmt: skip
    head = FancyArrowPatch((0, 0), (1, 0), arrowstyle="-|>", mutation_scale=fs(1.6),
                           color=TURN_COLOR, lw=lw(0.8), shrinkA=0, shrinkB=0, zorder=4.6)  # fmt: skip
    ax.add_patch(head)
    turn_label = ax.text(
        0,
        0,
        "",
        ha="center",
        va="center",
        fontsize=fs(0.75),
        fontweight="bold",
        color=TURN_COLOR,
        bbox=label_box(0.8),
        linespacing=1.1,
        zorder=4.55,
    )  # under the arc and its head

    # the roles under point 4 and the vertex labels and dots (zorder 5 and up), as a view's
    # blitted layers draw them
    roles = [
        annotate_near(ax, "", (0, 0), xytext=(0, 0), textcoords="offset points", ha="center",
                      va="center", fontsize=fs(0.8), fontstyle="italic", color=COLORS["split"],
                      bbox=label_box(0.85), zorder=4.85, annotation_clip=False)
        for _ in ROLES
    ]  # fmt: skip
    # the snapped positions, as the roles (they show at another step)
    coords = [
        annotate_near(ax, "", (0, 0), xytext=(0, 0), textcoords="offset points", ha="center",
                      va="center", fontsize=fs(0.75), color=COLORS["edge"],
                      bbox=label_box(0.85), zorder=4.85, annotation_clip=False)
        for _ in range(3)
    ]  # fmt: skip
    result = SetupArtists(band, lines, arc, head, turn_label, roles, coords)
    result.update(trace, labels)
    result.show(None, False)
    return result
