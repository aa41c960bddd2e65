"""Pixel history: why a pixel is what it is, told triangle by triangle.

Graphics engineers answer "why is this pixel this colour?" with a frame debugger's *pixel
history* (RenderDoc, PIX): every draw that touched the pixel, in order, with the test that
killed each fragment and the depth before and after. ``frame.history(row, col)`` is that
for a :func:`~teachraster.pipeline.render_triangles.render` made with ``trace=True``: one
:class:`HistoryRecord` per (triangle, sample) for every triangle whose screen bounding box
(after clipping) reaches the pixel, in submission order, with the *first* test that stopped
it, in the order the history checks them:

    "culled" -> "not_covered" (which edge, how far outside) -> "hi_z" -> "failed_depth"
    -> "passed"

That is not the GPU's order of stages: hardware tests Hi-Z on whole tiles before fine
coverage (Giesen, *A trip through the Graphics Pipeline 2011*, part 7); here a missed centre
is "not_covered" even in a tile Hi-Z rejected.

A centre a triangle does not cover is refused for a reason (``HistoryRecord.reason``,
:data:`REASONS`) that names the edges as a student reads the triangle, v1, v2, v3 in the
order given (:mod:`.edge_names`): outside one of its edges E12, E23, E31 (E13, E32, E21 walked
the other way), on such an edge and refused by the top-left rule, beyond an edge that
clipping made (that part of the triangle was clipped away), across the seam between two
pieces of a clipped triangle (the neighbouring piece's side), or the triangle (piece) has
zero area; rarely, a thin piece that snapping turned over (its corners run the other way).

A fragment that passed may still be hidden by a later one (``hidden_by``; with blending
the table says "under": the later one is blended over it); the one the pixel shows at the
end (the last to pass, in the triangle-id buffer) has ``shown``. Nothing is stored per fragment for this: the
history of one pixel is computed on demand from the trace's compact arrays (the fill's
fragments, the depth test in drawing order, the in-order Hi-Z replay of
:mod:`teachraster.pipeline.hierarchical_z`) and, for coverage that failed and for MSAA
samples, from the triangles' edge functions and depth planes, with the very functions the
renderer uses. Replaying the records (:meth:`PixelHistory.replay`) gives the frame's
triangle and depth at every sample bit for bit (tests/test_frame_history.py).

The depth test is the renderer's own, decided in one place
(:func:`~teachraster.pipeline.visibility.zbuffer.passes_depth_test`; Ritschel, *Interpolation and
z-buffering*): strictly nearer passes, so of equal depths the earlier triangle stays;
without the test every fragment passes and the last one drawn shows. The one-sample history
reads the trace's answers; under MSAA the records' test is run by
:func:`~teachraster.pipeline.visibility.zbuffer.passed_on_arrival`, as the frame's.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass, replace

import numpy as np

from ...core.edges import passes, setup_edges
from ...core.multisample import offsets_in_units
from ...core.validate import as_int
from ..antialiasing.multisampling import depth_planes, pair_attributes, plane_depth
from ..blending.colour_blending import write_colour
from ..rasterization.batched_fill import weight_source
from ..rendering.stages import Visibility, fragment_values, interpolate_stage
from ..visibility.depth import quantize
from ..visibility.zbuffer import COMPARE_OFF, COMPARE_ON, passed_on_arrival
from .edge_names import CLIP_EDGE, INPUT_EDGE, SEAM, piece_edges

#: The outcomes, in the order the history checks them (the first that failed is reported).
OUTCOMES = ("culled", "not_covered", "hi_z", "failed_depth", "passed")

#: Why a centre (sample) was "not_covered". The reason is the triangle's: where several
#: edges of its pieces refuse the point, one of the triangle's own edges comes before an
#: edge clipping made, and that before a seam between pieces.
REASONS = ("zero_area", "outside_edge", "top_left", "clipped_away", "seam", "turned_over")


@dataclass(frozen=True)
class HistoryRecord:
    """One triangle (one clipped piece of it) at one sample of the pixel.

    Attributes
    ----------
    triangle : int
        Input triangle index (submission order).
    piece : int
        Index of the clipped piece it reached the pixel as (triangles after clipping).
    sample : int
        The sample (0 for the pixel centre of a single-sample frame).
    outcome : str
        The first test that stopped it, or "passed" (:data:`OUTCOMES`).
    depth : float
        The fragment's depth as the buffer stores it; NaN when there is no fragment.
    depth_before, depth_after : float
        The depth buffer at this sample before and after it (inf: still empty).
    value : tuple of float
        The attributes it wrote ("passed"), else (): a fragment Hi-Z rejected or that
        failed the depth test is never interpolated (the render shades only the fragments
        it keeps), and its outcome says why.
        With MSAA, where attributes are evaluated once per pixel and triangle, the records
        a sample shows at the end carry the frame's ``sample_attrs``; those that passed and
        were hidden later carry the same evaluation for their pair (at the centre, or the
        centroid sample); a sample of the pair that failed carries none.
    edge : str or None
        "not_covered": the edge that refused the point: "E12", "E23", "E31" (or E13, E32,
        E21) for the input triangle's own edges (v1, v2, v3 in the order given), "near",
        "far" or "guard left/right/bottom/top" for an edge a clip plane made, "seam v1–E23∩near"
        for the diagonal between two pieces of a clipped triangle; None for zero area.
    outside : float
        "not_covered": how far outside that edge the point lies, in px (0 on the edge: the
        top-left rule refused it). NaN otherwise.
    reason : str
        "not_covered": why, one of :data:`REASONS`; "" otherwise.
    across : int
        reasons "seam" and "turned_over": the piece of the same triangle that covers the
        point (-1: none does).
    shown : bool
        The sample shows this triangle at the end.
    hidden_by : int
        "passed" but later overwritten: the input triangle that passed next (-1 none).
    depth_write : bool
        The triangle's depth mask: a "passed" record without it leaves the buffer as it was.
    color : tuple of float
        With a colour buffer (RGBA attributes): the fragment's own output colour, RGBA, for
        the records that reached the buffer ("passed"), else ().
    color_before, color_after : tuple of float
        With a colour buffer: the target's colour at this sample before and after the
        record (blended, or written over without blending), else ().
    """

    triangle: int
    piece: int
    sample: int
    outcome: str
    depth: float
    depth_before: float
    depth_after: float
    value: tuple = ()
    edge: str | None = None
    outside: float = float("nan")
    reason: str = ""
    across: int = -1
    shown: bool = False
    hidden_by: int = -1
    depth_write: bool = True
    color: tuple = ()
    color_before: tuple = ()
    color_after: tuple = ()


@dataclass(frozen=True)
class PixelHistory:
    """The story of one pixel: its records in submission order (then by sample).

    ``print(h)`` is a table, ``h.plot(ax)`` a strip of fragments with the depth before and
    after each, ``h.replay()`` the frame's pixel rebuilt from the records alone.
    """

    row: int
    col: int
    records: tuple
    n_samples: int
    depth_test: bool
    shows: int  # the input triangle the frame shows at the pixel (-1 none)
    clipped_away: int = 0  # input triangles clipping removed whole (no screen position)
    blend: object = None  # the colour buffer's BlendState (None: no colour buffer)
    depth_format: str = "float64"  # the depth buffer's format (``render(depth_format=...)``)
    compare: str = COMPARE_ON  # the depth test's compare op (COMPARE_OFF with it off)

    def __len__(self) -> int:
        return len(self.records)

    def __iter__(self):
        return iter(self.records)

    def __getitem__(self, i):
        return self.records[i]

    @property
    def outcomes(self) -> list[str]:
        """The outcome of every record, in order."""
        return [r.outcome for r in self.records]

    def replay(self) -> tuple[np.ndarray, np.ndarray]:
        """Rebuild the pixel from the records: per sample (S,) the triangle shown (-1 none)
        and the depth in the buffer (NaN none). Passing records write in order (depth only
        where they write it); the depth test itself is not redone (the records say who
        passed). :meth:`replay_color` rebuilds the colour."""
        triangle = np.full(self.n_samples, -1, dtype=np.int64)
        depth = np.full(self.n_samples, np.nan)
        for r in self.records:
            if r.outcome == "passed":
                triangle[r.sample] = r.triangle
                if r.depth_write:
                    depth[r.sample] = r.depth
        return triangle, depth

    def replay_color(self) -> np.ndarray | None:
        """The colour buffer rebuilt from the records: (S, 4) per sample, from the clear
        colour through every record's fragment colour in order, by the colour stage's own
        rule (:func:`~teachraster.pipeline.blending.colour_blending.write_colour`): equal
        bit for bit to ``frame.sample_color`` (``frame.color`` for one sample). None
        without a colour buffer."""
        if self.blend is None:
            return None
        buffer = np.tile(self.blend.clear_color, (self.n_samples, 1))
        for r in self.records:
            if r.outcome == "passed":
                s = r.sample
                buffer[s] = write_colour(np.array([r.color]), buffer[s : s + 1], self.blend)[0]
        return buffer

    def __str__(self) -> str:
        return history_table(self)

    def table(self, narrow: bool = True) -> str:
        """The table in a notebook column: at most :data:`NARROW` characters a line, as the
        frame inspector shows it (``piece`` and ``smp`` only where they say something, a
        long "value / why" under its row, a triangle's samples that say the same on one
        line); ``narrow=False``: ``str(h)``, one row a line. ``records`` keeps every
        sample's record."""
        return history_table(self, narrow=narrow)

    def _repr_pretty_(self, p, cycle) -> None:  # IPython prints the table
        p.text(str(self))

    def plot(self, ax):
        """Draw the pixel's story on ``ax`` (see :func:`draw_history`); returns artists."""
        return draw_history(ax, self)


def pixel_history(frame, row, col) -> PixelHistory:
    """:meth:`Frame.history`: the :class:`PixelHistory` of pixel (``row``, ``col``)."""
    trace = getattr(frame, "trace", None)
    if trace is None or getattr(trace, "debug", None) is None:
        raise ValueError("frame: the pixel history needs a frame rendered with trace=True")
    dbg = trace.debug
    height, width = frame.triangle_id.shape
    row, col = pixel_index("row", row, height), pixel_index("col", col, width)
    if dbg.offsets is None:
        records = _single_sample(frame, dbg, row, col)
        n_samples = 1
    else:
        records = _multisampled(frame, dbg, row, col)
        n_samples = len(dbg.offsets)
    if dbg.writes is not None:  # the depth masks, per piece
        records = [replace(r, depth_write=bool(dbg.writes[r.piece])) for r in records]
    records = _replay_buffer(records, dbg.inputs.depth_test)
    if dbg.offsets is not None:  # MSAA: the value a sample shows is the frame's own
        values = frame.sample_attrs[row, col]
        hidden = _hidden_values(frame, dbg, row, col, records)
        records = [replace(r, value=tuple(float(v) for v in values[r.sample])) if r.shown
                   else replace(r, value=hidden[r.piece])
                   if r.piece in hidden and r.outcome == "passed"
                   else r for r in records]  # fmt: skip
    if dbg.blend is not None:
        records = _colours(frame, dbg, row, col, records)
    dropped = int((np.asarray(frame.trace.clip_status) == 2).sum())
    a = dbg.inputs
    compare = COMPARE_ON if a.depth_test else COMPARE_OFF
    if a.depth_test and getattr(getattr(a, "overrides", None), "depth", None) is not None:
        compare = "your rule"  # a student's depth rule replaced the package's
    return PixelHistory(row, col, tuple(records), n_samples, a.depth_test,
                        int(frame.triangle_id[row, col]), dropped, dbg.blend, a.depth_format,
                        compare)  # fmt: skip


def _setup(dbg, window):
    """The edge set-up of every triangle after clipping (snapped), once per frame."""
    if "setup" not in dbg.cache:
        dbg.cache["setup"] = setup_edges(window[:, :, :2], dbg.inputs.subpixel_bits)
    return dbg.cache["setup"]


def pixel_index(name, value, size) -> int:
    """``value`` as a pixel index (an integer, not a bool) in [0, size)."""
    i = as_int(name, value)
    if not 0 <= i < size:
        raise ValueError(f"{name} must be in [0, {size}), got {i}")
    return i


def _candidates(setup, points, extra) -> np.ndarray:
    """Pieces whose snapped bounding box contains one of ``points`` (n, 2) units, plus
    ``extra`` (pieces known to reach the pixel), ascending (drawing order)."""
    p = setup.p
    lo, hi = p.min(axis=1), p.max(axis=1)  # (M, 2): cheap beside a click
    inside = np.zeros(len(p), dtype=bool)
    for x, y in points:
        inside |= (lo[:, 0] <= x) & (x <= hi[:, 0]) & (lo[:, 1] <= y) & (y <= hi[:, 1])
    inside[extra] = True
    return np.flatnonzero(inside)


def _points(setup, units, row, col) -> np.ndarray:
    """The tested points of pixel (row, col) in internal units: (S, 2)."""
    base = np.array([col * setup.unit, row * setup.unit], dtype=setup.p.dtype)
    if units is None:
        return (base + setup.half)[None, :]
    return base + units


def _edge_test(setup, pieces, pts):
    """Coverage of ``pts`` (S, 2) by ``pieces``: covered (n, S), and per edge whether it
    refuses the point (n, S, 3) and its value E (n, S, 3) in units²."""
    p, tl = setup.p[pieces], setup.top_left[pieces]
    n, s = len(pieces), len(pts)
    refused = np.zeros((n, s, 3), dtype=bool)
    value = np.zeros((n, s, 3))
    for k in range(3):
        a, b = p[:, k, None, :], p[:, (k + 1) % 3, None, :]
        e = (b[..., 0] - a[..., 0]) * (pts[None, :, 1] - a[..., 1]) - (b[..., 1] - a[..., 1]) * (
            pts[None, :, 0] - a[..., 0]
        )
        refused[..., k] = ~passes(e, tl[:, k, None])
        value[..., k] = e
    zero = (np.asarray(setup.area2)[pieces] == 0)[:, None]  # covers nothing
    return ~refused.any(axis=2) & ~zero, refused, value


class _Misses:
    """Why the pieces reaching a pixel do not cover its points: the edge tests of every
    piece of their triangles at every point, once per history (:meth:`why` per record)."""

    def __init__(self, dbg, setup, pieces, pts):
        self.setup, self.names = setup, piece_edges(dbg, setup)
        parent = dbg.clipped.parent
        lo = np.searchsorted(parent, parent[pieces], "left")
        hi = np.searchsorted(parent, parent[pieces], "right")
        ranges = [np.arange(a, b) for a, b in zip(lo, hi)]  # the pieces of their triangles
        self.family = np.unique(np.concatenate(ranges)) if ranges else np.zeros(0, np.int64)
        self.covered, self.refused, self.value = _edge_test(setup, self.family, pts)
        # A zero-area piece has no sides. A piece snapping turned over has its interior on
        # the other side of its edges from the triangle's: for the triangle, a point is
        # outside such an edge where the piece's own test would call it inside.
        turned = self.names.turned[self.family][:, None, None]
        self.refused = np.where(turned, self.value > 0, self.refused)
        self.value = np.where(turned, -self.value, self.value)  # E on the triangle's side
        self.refused &= (np.asarray(setup.area2)[self.family] != 0)[:, None, None]
        self.ranges = dict(zip(pieces.tolist(), zip(lo.tolist(), hi.tolist())))

    def why(self, piece: int, s: int) -> dict:
        """The fields ``reason``, ``edge``, ``outside``, ``across`` of the record of
        ``piece`` at point ``s``.

        A zero-area piece covers nothing. Otherwise the reason is the triangle's, over all
        the pieces clipping made of it: of its own edges E12, E23, E31 that refuse the
        point the one it is farthest outside, else such an edge a clip plane made (that
        part was clipped away), else the point is inside the clipped triangle, on another piece's side of a
        seam (``across``: the piece that covers it, -1 if none does: snapping turned a thin
        piece over, leaving a gap), or the piece is that turned piece."""
        setup, names = self.setup, self.names
        if np.asarray(setup.area2)[piece] == 0:
            return dict(reason="zero_area")
        lo, hi = self.ranges[piece]
        rows = np.searchsorted(self.family, np.arange(lo, hi))
        refused, value = self.refused[rows, s], self.value[rows, s]  # (n, 3)
        for kind in (INPUT_EDGE, CLIP_EDGE):
            hit = np.argwhere(refused & (names.kind[lo:hi] == kind))
            if len(hit):  # the edge the point is farthest outside (robust to snapping)
                i, k = max(hit.tolist(), key=lambda ik: _outside(setup, lo + ik[0], ik[1],
                                                                   value[ik[0], ik[1]]))  # fmt: skip
                return _refusal(setup, names, lo + i, k, value[i, k], kind)
        cover = np.flatnonzero(self.covered[rows, s]) + lo
        across = int(cover[0]) if len(cover) else -1
        own = np.flatnonzero(refused[piece - lo])  # seams: the other edges let the point in
        if len(own):
            k = int(own[0])
            return _refusal(setup, names, piece, k, value[piece - lo, k], SEAM) | dict(
                across=across
            )
        if names.turned[piece]:  # on its side of every edge, yet the turned piece refused it
            return dict(reason="turned_over", across=across)
        return {}  # covered after all (never, for a record without a fragment)


def _outside(setup, piece, k, e) -> float:
    """How far (px) outside edge ``k`` of ``piece`` a point with edge value ``e`` lies."""
    a, b = setup.p[piece, k], setup.p[piece, (k + 1) % 3]
    length = float(np.hypot(float(b[0] - a[0]), float(b[1] - a[1])))
    return max(0.0, -float(e) / length / float(setup.unit)) if length else 0.0


def _refusal(setup, names, piece, k, e, kind) -> dict:
    """The record fields for edge ``k`` of ``piece`` refusing a point where its value is
    ``e`` (units²): the edge's name and how far outside it the point lies (px)."""
    outside = _outside(setup, piece, k, e)
    if kind == SEAM:
        reason = "seam"
    elif kind == CLIP_EDGE:
        reason = "clipped_away"
    else:
        reason = "top_left" if e == 0 else "outside_edge"
    return dict(reason=reason, edge=names.name(piece, k), outside=outside)


def _single_sample(frame, dbg, row, col) -> list[HistoryRecord]:
    """Records of a one-sample frame: fragments, tests and Hi-Z from the trace."""
    trace, frags = frame.trace, dbg.fragments
    at = np.flatnonzero((frags.row == row) & (frags.col == col))  # drawing order
    setup = _setup(dbg, trace.window)
    pts = _points(setup, None, row, col)
    pieces = _candidates(setup, pts, frags.tri[at])
    misses = _Misses(dbg, setup, pieces, pts)
    fragment_of = dict(zip(frags.tri[at].tolist(), at.tolist()))
    rejected = None if trace.hiz is None else trace.hiz.fragment_rejected
    # Only a fragment that passed is interpolated (the render shades the pairs it keeps): one
    # Hi-Z rejected or that failed the depth test has no value, its outcome says why.
    kept = np.asarray(trace.fragment_passed[at], dtype=bool)
    if rejected is not None:
        kept = kept & ~rejected[at]
    values = _values(frags, at[kept], dbg)
    records = []
    for piece in pieces.tolist():
        base = dict(triangle=int(dbg.clipped.parent[piece]), piece=piece, sample=0)
        f = fragment_of.get(piece)
        if trace.culled[piece]:
            records.append(HistoryRecord(**base, outcome="culled", depth=np.nan,
                                         depth_before=np.nan, depth_after=np.nan))  # fmt: skip
        elif f is None:
            why = misses.why(piece, 0)
            records.append(HistoryRecord(**base, outcome="not_covered", depth=np.nan,
                                         depth_before=np.nan, depth_after=np.nan,
                                         **why))  # fmt: skip
        else:
            if rejected is not None and rejected[f]:
                outcome = "hi_z"  # rejected before interpolation: no value
            else:
                outcome = "passed" if trace.fragment_passed[f] else "failed_depth"
            records.append(HistoryRecord(**base, outcome=outcome,
                                         depth=float(trace.fragment_depth[f]),
                                         depth_before=np.nan, depth_after=np.nan,
                                         value=values.get(f, ())))  # fmt: skip
    return records


def _values(frags, at, dbg) -> dict:
    """Attributes interpolated at fragments ``at`` (the renderer's interpolation stage)."""
    if len(at) == 0:
        return {}
    a = dbg.inputs
    visible = Visibility(np.zeros(len(at)), np.zeros(len(at), np.int64), a.depth_test,
                         np.arange(len(at)), at)  # fmt: skip
    # The render's own evaluation, with what it forced: "perspective" divides every row (a
    # value depends on its fragment alone, so forcing "attributes", which evaluates every
    # fragment of the frame, would give the same values here at the cost of the frame's).
    forced = a.forced - {"attributes"}
    values, _ = interpolate_stage(frags, visible, dbg.clipped, a.interpolation, forced,
                                  a.overrides)  # fmt: skip
    return {int(f): tuple(float(v) for v in values[i]) for i, f in enumerate(at)}


def _multisampled(frame, dbg, row, col) -> list[HistoryRecord]:
    """Records of an MSAA frame, one per (piece, sample): coverage per sample from the edge
    functions, depth per sample from the depth planes, as the renderer decides them."""
    trace, a = frame.trace, dbg.inputs
    window = trace.window
    setup = _setup(dbg, window)
    units = offsets_in_units(dbg.offsets, setup)
    pts = _points(setup, units, row, col)
    pieces = _candidates(setup, pts, np.zeros(0, np.int64))
    misses = _Misses(dbg, setup, pieces, pts)
    covered = misses.covered[np.searchsorted(misses.family, pieces)]
    if "planes" not in dbg.cache:
        dbg.cache["planes"] = depth_planes(weight_source(window[:, :, :2], setup, False), window)
    planes = dbg.cache["planes"]
    n_s = len(dbg.offsets)
    tri = np.repeat(pieces, n_s)
    x, y = (
        col + np.tile(dbg.offsets[:, 0], len(pieces)),
        row + np.tile(dbg.offsets[:, 1], len(pieces)),
    )
    # every candidate's planes at every sample, read only where it covers: a zero-area piece
    # (never covering) has infinite gradients, whose nan must not surface as numpy's warning
    with np.errstate(invalid="ignore", over="ignore"):
        depth = plane_depth(planes, 1.0, tri, x, y) if len(tri) else np.zeros(0)
        if a.depth_format != "float64":
            depth = quantize(depth, a.depth_format)
    depth = depth.reshape(len(pieces), n_s)
    records = []
    for i, piece in enumerate(pieces.tolist()):
        base = dict(triangle=int(dbg.clipped.parent[piece]), piece=piece)
        for s in range(n_s):
            if trace.culled[piece]:
                rec = HistoryRecord(**base, sample=s, outcome="culled", depth=np.nan,
                                    depth_before=np.nan, depth_after=np.nan)  # fmt: skip
            elif not covered[i, s]:
                why = misses.why(piece, s)
                rec = HistoryRecord(**base, sample=s, outcome="not_covered", depth=np.nan,
                                    depth_before=np.nan, depth_after=np.nan, **why)  # fmt: skip
            else:  # the depth test is replayed in _replay_buffer
                rec = HistoryRecord(**base, sample=s, outcome="covered", depth=float(depth[i, s]),
                                    depth_before=np.nan, depth_after=np.nan)  # fmt: skip
            records.append(rec)
    return records


def _hidden_values(frame, dbg, row, col, records) -> dict:
    """MSAA: the attributes of the pieces that passed the depth test at some sample but show
    none at the end, shaded once for the pixel as the render shades every pair it keeps."""
    hidden = sorted({r.piece for r in records if r.outcome == "passed" and not r.shown})
    if not hidden:
        return {}
    n_s = len(dbg.offsets)
    covers = np.zeros((len(hidden), n_s), dtype=bool)
    for r in records:
        if r.piece in hidden and r.outcome not in ("culled", "not_covered"):
            covers[hidden.index(r.piece), r.sample] = True
    window = frame.trace.window
    setup = _setup(dbg, window)
    px = offsets_in_units(dbg.offsets, setup).astype(np.float64) / float(setup.unit)
    a = dbg.inputs
    width = frame.triangle_id.shape[1]
    tri = np.asarray(hidden, dtype=np.int64)
    pixel = np.full(len(tri), row * width + col, dtype=np.int64)
    options = (a.interpolation, a.forced, px, dbg.centroid)
    vals = pair_attributes(dbg.clipped, window, setup, options, tri, pixel, covers, width)
    return {p: tuple(float(v) for v in vals[i]) for i, p in enumerate(hidden)}


def _replay_buffer(records, depth_test) -> list[HistoryRecord]:
    """Fill in the buffer before and after every record (per sample, in order), decide the
    depth test where it is still open ("covered": MSAA) by the frame's own test
    (:func:`~teachraster.pipeline.visibility.zbuffer.passed_on_arrival`, per sample), and
    mark what each sample shows at the end and who hid the fragments that passed."""
    tested = [i for i, r in enumerate(records) if r.outcome == "covered"]
    if tested:
        rec = [records[i] for i in tested]
        passed = passed_on_arrival(np.array([r.sample for r in rec]),
                                   np.array([r.depth for r in rec]),
                                   np.array([r.depth_write for r in rec]), depth_test)  # fmt: skip
        records = list(records)
        for i, ok in zip(tested, passed.tolist()):
            records[i] = replace(records[i], outcome="passed" if ok else "failed_depth")
    buffer: dict[int, float] = {}
    out = []
    for r in records:
        before = buffer.get(r.sample, np.inf)
        if r.outcome == "passed" and r.depth_write:
            buffer[r.sample] = r.depth
        after = buffer.get(r.sample, np.inf)
        out.append(replace(r, depth_before=before, depth_after=after))
    last: dict[int, int] = {}  # per sample, the index of the last record that passed
    for i, r in enumerate(out):
        if r.outcome == "passed":
            if r.sample in last:
                j = last[r.sample]
                out[j] = replace(out[j], hidden_by=r.triangle)
            last[r.sample] = i
    for i in last.values():
        out[i] = replace(out[i], shown=True)
    return out


def _colours(frame, dbg, row, col, records) -> list[HistoryRecord]:
    """The records with the fragments' colours and the target's colour before and after
    each, replayed from the clear colour by the colour stage's rule. The fragment colours
    are the colour stage's own: with one sample the fill's fragments evaluated as the
    render evaluates them, under MSAA the value of the record's (pixel, triangle) pair."""
    state = dbg.blend
    source = {r.piece: r.value for r in records if r.value}  # MSAA: the pairs' values
    if dbg.offsets is None:  # the fragments at this pixel, by piece
        frags = dbg.fragments
        at = np.flatnonzero((frags.row == row) & (frags.col == col))
        a = dbg.inputs
        values = fragment_values(frags, at, dbg.clipped, a.interpolation, a.forced, a.overrides)
        source = {int(frags.tri[f]): _tuple(values[i]) for i, f in enumerate(at)}
    buffer: dict[int, np.ndarray] = {}
    out = []
    for r in records:
        before = buffer.get(r.sample, state.clear_color)
        if r.outcome != "passed":
            out.append(replace(r, color_before=_tuple(before), color_after=_tuple(before)))
            continue
        src = source[r.piece]
        after = write_colour(np.array([src]), before[None, :], state)[0]
        buffer[r.sample] = after
        out.append(replace(r, color=tuple(src), color_before=_tuple(before),
                           color_after=_tuple(after)))  # fmt: skip
    return out


def _tuple(c) -> tuple:
    return tuple(float(v) for v in c)


def history_table(h: PixelHistory, narrow: bool = False, like=None, fold: bool = True) -> str:
    """The readable table ``print(h)`` shows. ``narrow``: at most :data:`NARROW` characters a
    line, for a widget's column at a projector's 12 px (review r18, exercise 11: at 0.75em,
    9.75 px, two tables fitted a 592-px column side by side, too small to read): the header
    on two lines, the piece and sample columns only where they say something (a clipped
    piece, more than one sample), each colour line's "after" on a line of its own. ``like``:
    the other history of a pair (or None), whose rows set the columns too, so that the two
    tables have the same columns and wrap their rows alike (review r21 D4: the outcome
    column's width in one table decided which of its rows wrapped). ``fold`` (the default,
    so that ``print(h)``, ``h.table()`` and the frame inspector show the same table; review
    r96 11-2): a triangle's consecutive ``not_covered`` samples refused for the same reason
    on one line, with the nearest miss (review r82, 11-F: under 4× MSAA a glass sphere's
    pixel listed 40 records, most of them refused samples, each on two lines), its
    consecutive samples whose rows are otherwise identical on one (review r106 11-C2), and
    its samples' identical colour lines on one (:func:`colour_lines`); ``fold=False``: a
    line per record, as ``h.records`` holds them."""
    shows = "nothing" if h.shows < 0 else f"triangle {h.shows}"
    # off is GL's ALWAYS (every fragment passes, and writes where its mask lets it), not
    # glDisable(GL_DEPTH_TEST): said, so that the table is not read as the APIs' test-off.
    # The compare and the depth buffer's format (review r298 M1, S1: a tie that only a
    # 16-bit buffer makes, and a reversed mapping under LESS, need both to be read)
    where = (f"pixel (row {h.row}, col {h.col}), {h.n_samples} sample(s), depth test "
             f"{'on' if h.depth_test else 'off'} ({h.compare}), {h.depth_format} depth:")  # fmt: skip
    way = f"{len({r.triangle for r in h.records})} triangle(s) on the way; shows {shows}"
    if h.n_samples > 1 and h.shows >= 0:  # each sample keeps its own triangle
        way += " (most samples)"
    # the piece and the sample columns, unless narrow and they repeat the triangle or say 0
    both = [h] if like is None else [h, like]
    pieces = not narrow or any(r.piece != r.triangle for g in both for r in g.records)
    samples = not narrow or any(g.n_samples > 1 for g in both)
    lines = [f"{where}\n{way}" if narrow else f"{where} {way}"]
    rows = list(zip(h.records, _outcomes(h), map(_why, h.records)))
    rows = _folded(rows) if fold else [(r, o, w, str(r.sample)) for r, o, w in rows]
    outcomes = [o for g in both for o in _outcomes(g)]
    wide = 22 if not narrow else max([len("outcome"), *map(len, outcomes)])
    tri = 5 if not narrow else 3
    head = f"{'tri':>{tri}} " + (f"{'piece':>5} " if pieces else "") + ("smp " if samples else "")
    lines.append(f"{head} {'outcome':<{wide}} {'depth':>9} {'before':>9} {'after':>9}  "
                 "value / why")  # fmt: skip
    for r, outcome, why, smp in rows:
        head = (f"{r.triangle:>{tri}} " + (f"{r.piece:>5} " if pieces else "")
                + (f"{smp:>3} " if samples else ""))  # fmt: skip
        line = (f"{head} {outcome:<{wide}} {_num(r.depth)} {_num(r.depth_before)} "
                f"{_num(r.depth_after)}")  # fmt: skip
        if narrow and len(line) + 2 + len(why) > NARROW:  # the why under its row, wrapped
            lines += [line, *textwrap.wrap(why, NARROW, initial_indent=" " * 6,
                                           subsequent_indent=" " * 6)]  # fmt: skip
        else:
            lines.append(f"{line}  {why}".rstrip())
    if len(h.records) == 0:
        lines.append("  (no triangle's bounding box reaches this pixel)")
    if h.clipped_away:
        lines.append(f"  ({h.clipped_away} triangle(s) of the frame clipped away whole: behind "
                     "the eye or beyond the far plane, they reach no pixel)")  # fmt: skip
    if h.n_samples > 1 and any(r.shown for r in h.records):
        lines.append(f"  kept k of {h.n_samples}: the triangle holds k of the pixel's "
                     f"{h.n_samples} samples at the end")  # fmt: skip
    lines += colour_lines(h, narrow, fold)
    return "\n".join(lines)


def _folded(rows) -> list:
    """``rows`` [(record, outcome, why)] as [(record, outcome, why, sample text)], each run
    of one piece's consecutive samples that say the same as one row with their samples
    ("0-3"), where every column of the row is the same (:func:`_says_the_same`): the
    outcome, the depths (the buffer's before and after too) and, ``not_covered``, the reason,
    with the nearest miss ("4 samples, nearest outside E13 by 0.6400 px"), or else the value
    (review r106 11-C2: a fan's pixel printed two identical "passed (kept 2 of 4)" rows of
    triangle 5)."""
    out: list = []
    for r, outcome, why in rows:
        if out and out[-1][1] == outcome and _says_the_same(out[-1][0][0], r, outcome):
            out[-1][0].append(r)
            continue
        out.append(([r], outcome, why))
    folded = []
    for records, outcome, why in out:
        r = records[0]
        smp = sample_list([x.sample for x in records])
        if len(records) == 1 or outcome != "not_covered":
            folded.append((r, outcome, why, smp))
            continue
        near = min(records, key=lambda x: x.outside if np.isfinite(x.outside) else np.inf)
        folded.append((near, outcome, f"{len(records)} samples, nearest {_why(near)}", smp))
    return folded


def _says_the_same(first, r, outcome: str) -> bool:
    """Whether record ``r`` (its outcome text ``outcome``, the same as ``first``'s) says what
    ``first`` says in the table, so that one line can stand for both: the same piece, the same
    depths — the fragment's, the buffer's before and after — to the bit (NaN equal to NaN)
    and the same colours before and after; then, refused, the same reason, otherwise the
    same value. Review r159 C1: comparing only the reason of refused samples folded a sample
    whose buffer held 0.967634 (the fan, pixel (23, 31), triangle 4's sample 1) into a line
    that printed its neighbours' "empty empty", beside a depth chart drawing 0.967634."""
    if (first.triangle, first.piece) != (r.triangle, r.piece):
        return False
    depths = zip((first.depth, first.depth_before, first.depth_after),
                 (r.depth, r.depth_before, r.depth_after))  # fmt: skip
    if not all(a == b or (np.isnan(a) and np.isnan(b)) for a, b in depths):
        return False
    if (first.color_before, first.color_after) != (r.color_before, r.color_after):
        return False
    if outcome == "not_covered":
        return first.reason == r.reason
    return first.value == r.value and _why(first) == _why(r)


def _outcomes(h: PixelHistory) -> list[str]:
    """The outcome column's texts of ``h``'s records."""
    # Blending, a later fragment that passes is blended over this one, which is not hidden:
    # its colour is in the result (the colour lines say how much).
    later = "under" if h.blend is not None and h.blend.mode is not None else "hidden by"
    kept = samples_kept(h)
    return [_outcome_text(r, later, kept, h.n_samples) for r in h.records]


def samples_kept(h: PixelHistory) -> dict[int, int]:
    """{triangle: how many of the pixel's samples it holds at the end}. Under MSAA every
    sample keeps its own triangle and the resolve averages the samples, so several
    triangles can each be shown at some samples of one pixel (``shows`` names the one
    with the most)."""
    kept: dict[int, int] = {}
    for r in h.records:
        if r.shown:
            kept[r.triangle] = kept.get(r.triangle, 0) + 1
    return kept


def _outcome_text(r, later: str, kept: dict, n_samples: int) -> str:
    """A record's outcome, and for a passed one whether it is shown (under MSAA: its
    triangle keeps k of the pixel's samples) or what covers it."""
    if r.outcome != "passed":
        return r.outcome
    if not r.shown:
        return f"{r.outcome} ({later} {r.hidden_by})"
    if n_samples > 1:
        return f"{r.outcome} (kept {kept[r.triangle]} of {n_samples})"
    return f"{r.outcome} (shown)"


def _why(r) -> str:
    """A record's "value / why": the reason it missed, or the value it wrote."""
    if r.outcome == "not_covered":
        return reason_text(r)
    if r.value:
        return "(" + ", ".join(f"{v:.4g}" for v in r.value) + ")"
    if r.outcome == "passed":  # shaded, but the scene gives it nothing to write
        return "(no attributes: the scene has none)"
    return ""


#: The longest line of a narrow history table (:func:`history_table`): 592 px at 12 px in a
#: monospace font of 0.602 em a character is 81.9 characters.
NARROW = 80


def colour_lines(h: PixelHistory, narrow: bool = False, fold: bool = False) -> list[str]:
    """The colour part of the table: per record that reached the colour buffer, the
    target's RGBA before, the fragment's own and the target's after (none without a
    colour buffer); ``narrow``: the "after" on a line of its own where the line would
    pass :data:`NARROW` characters; ``fold``: one line for the samples of one triangle's
    draw whose three colours are the same, with their list ("s0-3", "s0,2"; reviews r90
    11-7 and r96 11-2: a glass sphere's pixel listed four identical lines, one per
    sample)."""
    if h.blend is None:
        return []
    mode = "blending off" if h.blend.mode is None else f"blend {h.blend.mode}"
    if not any(r.outcome == "passed" for r in h.records):  # a header over no line said nothing
        return [f"colour buffer ({mode}, {h.blend.color_format}): no fragment reached it here"]
    out = [f"colour buffer ({mode}, {h.blend.color_format}), RGBA: before -> fragment -> after"]
    runs: list = []  # [first record, its samples] of each line
    start = 0  # the first line of the present triangle's draw
    for r in (r for r in h.records if r.outcome == "passed"):
        if not runs or runs[-1][0].triangle != r.triangle:
            start = len(runs)
        same = [run for run in runs[start:] if _colours_of(run[0]) == _colours_of(r)]
        if fold and h.n_samples > 1 and same:
            same[0][1].append(r.sample)
        else:
            runs.append([r, [r.sample]])
    for r, samples in runs:
        smp = "" if h.n_samples == 1 else f" s{sample_list(samples)}"
        line = f"{r.triangle:>5}{smp:>4}  {_rgba(r.color_before)} -> {_rgba(r.color)}"
        after = f" -> {_rgba(r.color_after)}"
        wrap = narrow and len(line + after) > NARROW
        out += [line, " " * 9 + after] if wrap else [line + after]
    return out


def _colours_of(r) -> tuple:
    """A record's colour line: the target before, the fragment, the target after."""
    return tuple(r.color_before), tuple(r.color), tuple(r.color_after)


def sample_list(samples) -> str:
    """Sample numbers as a short list: runs of consecutive ones as "first-last".

    >>> sample_list([0, 1, 2, 3]), sample_list([1, 2]), sample_list([0, 2, 3])
    ('0-3', '1-2', '0,2-3')
    """
    parts: list[list[int]] = []
    for s in sorted(samples):
        if parts and s == parts[-1][1] + 1:
            parts[-1][1] = s
        else:
            parts.append([s, s])
    return ",".join(str(a) if a == b else f"{a}-{b}" for a, b in parts)


def _rgba(c) -> str:
    return "(" + ", ".join(f"{v:.4g}" for v in c) + ")"


def reason_text(r: HistoryRecord) -> str:
    """Why a "not_covered" record's point is not covered, in words (the table's column)."""
    if r.reason == "zero_area":
        return "zero area: its snapped corners are collinear, it covers nothing"
    if r.reason == "top_left":
        return f"on {r.edge}, which is neither a top nor a left edge (top-left rule)"
    if r.reason == "clipped_away":
        return (
            f"beyond the {r.edge} clip edge by {px_text(r.outside)} px: that part was clipped away"
        )
    covers = f"piece {r.across} of the same triangle covers it" if r.across >= 0 else ""
    if r.reason == "seam":
        covers = covers or "no piece of the triangle covers it (snapping turned a thin piece over)"
        return f"across the clipping seam {r.edge[5:]} by {px_text(r.outside)} px: {covers}"
    if r.reason == "turned_over":
        covers = covers or "no piece of the triangle covers it"
        return f"snapping turned this thin piece over (its corners run the other way): {covers}"
    return f"outside {r.edge} by {px_text(r.outside)} px"


def px_text(d: float) -> str:
    """A distance in pixels at one precision for every row of a table (4 decimals, finer
    than the 1/256 px snapping step); a distance too small for that in scientific notation.

    >>> [px_text(d) for d in (0.646, 2.73, 0.11573, 3e-6)]
    ['0.6460', '2.7300', '0.1157', '3.0e-06']
    """
    return f"{d:.4f}" if abs(d) >= 5e-5 else f"{d:.1e}"


def _num(x: float) -> str:
    if np.isnan(x):
        return f"{'-':>9}"
    if np.isinf(x):
        return f"{'empty':>9}"
    return f"{x:9.6f}"


#: Colours of the outcomes in :func:`draw_history` (matplotlib names).
OUTCOME_COLORS = {
    "culled": "0.75",
    "not_covered": "0.9",
    "hi_z": "tab:purple",
    "failed_depth": "tab:red",
    "passed": "tab:green",
}


#: The smallest depth range the strip spans: depths closer than the table prints (6 decimals)
#: are not spread apart on the axis.
MIN_DEPTH_SPAN = 2e-4


def depth_ticks(lo: float, hi: float, most: int = 4) -> tuple[list, list]:
    """Round depths in [lo, hi], a step of 1, 2 or 5 times a power of ten (at most
    ``most`` + 1 of them), and their labels, written with just the decimals that step needs
    and no offset.

    >>> depth_ticks(0.9661, 0.9692)
    ([0.967, 0.968, 0.969], ['0.967', '0.968', '0.969'])
    """
    raw = (hi - lo) / most
    power = 10.0 ** np.floor(np.log10(raw))
    step = next(m * power for m in (1, 2, 5, 10) if m * power >= raw)
    decimals = max(0, int(-np.floor(np.log10(step) + 1e-9)))
    ticks = np.arange(np.ceil(lo / step - 1e-9), np.floor(hi / step + 1e-9) + 1) * step
    ticks = [round(float(t), decimals) + 0.0 for t in ticks]  # (+ 0.0: no "-0")
    return ticks, [f"{t:.{decimals}f}" for t in ticks]


def _tick_range(bottom: float, top: float, lo: float, hi: float) -> tuple[float, float]:
    """The part of the depth axis ``bottom`` … ``top`` that takes tick labels: where depths
    ``lo`` … ``hi`` lie in [0, 1] (window depths always do), no tick outside it (review r32
    D11-3: with room made above for the legend the axis ran to ~1.4, ticked 0.5 and 1.0, as
    if a depth could be 1.4); the room stays, unlabelled."""
    return (max(bottom, 0.0) if lo >= 0 else bottom), (min(top, 1.0) if hi <= 1 else top)


def draw_history(ax, h: PixelHistory):
    """A strip of the pixel's records: each fragment a short tile at its depth (colour =
    outcome; a record without a fragment a cross at the foot), the buffer before (○) and
    after (●) each. The depth axis spans the depths there are, so tiles mark depths, never
    lengths; its ticks are written out (no offset), and none lies outside [0, 1] where the
    depths are in it (the room above for the legend may reach past 1, unlabelled). Uses only the Axes' own methods, so the
    engine needs no plotting import. Returns the artists."""
    artists = []
    n = len(h.records)
    x = np.arange(n)
    depth = np.array([r.depth for r in h.records]) if n else np.zeros(0)
    every = [v for r in h.records for v in (r.depth, r.depth_before, r.depth_after)]
    every = [v for v in every if np.isfinite(v)]
    lo, hi = (min(every), max(every)) if every else (0.0, 1.0)
    mid, span = (lo + hi) / 2, max(hi - lo, MIN_DEPTH_SPAN)
    # Room above the depths for the legend, two rows across the top; with three rows (a
    # rejected fragment: five entries) :func:`_make_room` raises the top after measuring the
    # legend, so that it never covers a tile (a legend placed "best" sat on the Hi-Z tile,
    # and a three-row one on the rejected nearer fragment, the highest depth).
    bottom, top = mid - 0.85 * span, mid + 1.3 * span
    tile = span * 0.05
    foot = bottom + 0.12 * span  # where a record without a fragment is marked
    shown = []  # (handle, label) for the legend
    for name, color in OUTCOME_COLORS.items():
        mine = [i for i, r in enumerate(h.records) if r.outcome == name]
        if not mine:
            continue
        if name in ("culled", "not_covered"):  # no fragment, no depth
            (mark,) = ax.plot(x[mine], [foot] * len(mine), "x", mew=2, linestyle="none",
                              color="0.45" if name == "culled" else "0.6")  # fmt: skip
        else:
            mark = ax.bar(x[mine], tile, bottom=depth[mine] - tile / 2, width=0.7, color=color,
                          edgecolor="k", linewidth=0.5)  # fmt: skip
        artists.append(mark)
        # a cross has no depth: its height is only the foot of the axis (review r23 D3: a
        # cross at 0.5999 read as the depth of a triangle that did not cover the centre)
        shown.append((mark, f"{name} (no depth)" if name in ("culled", "not_covered") else name))
    ax.set_ylim(bottom, top)
    buffer = []
    for key, marker in (("depth_before", "o"), ("depth_after", ".")):
        v = np.array([getattr(r, key) for r in h.records]) if n else np.zeros(0)
        v = np.where(np.isinf(v), np.nan, v)
        buffer += ax.plot(x, v, marker, color="k", mfc="none" if marker == "o" else "k",
                          linestyle="none")  # fmt: skip
    artists += buffer
    if any(np.isfinite(line.get_ydata()).any() for line in buffer):  # (writes off: none)
        shown += [(buffer[0], "buffer before"), (buffer[1], "buffer after")]  # ○ and ●
    ax.set_yticks(*depth_ticks(*_tick_range(bottom, top, lo, hi)))
    _label_records(ax, h, x)
    ax.set_xlim(-0.6, max(n, 1) - 0.4)
    ax.set_ylabel("depth (smaller ↓)")
    ax.set_title(f"pixel (row {h.row}, col {h.col})", fontsize="small")
    colours = _draw_colours(ax, h, x, (bottom, top))
    artists += colours
    if not every:  # no depth at all: a 0-1 depth axis would claim a range there is not (r50 D4)
        ax.set_yticks([])
        ax.set_ylabel("")
        note = "no triangle reaches this pixel" if not n else "no fragment reached this pixel"
        artists.append(ax.text(0.5, 0.5, note, ha="center", va="center",
                               transform=ax.transAxes, fontsize="small"))  # fmt: skip
    if n:  # in the depth part of the Axes (the colours, if any, are above it)
        depth_part = (top - bottom) / (ax.get_ylim()[1] - bottom)
        legend = _fitted_legend(ax, shown, depth_part)
        artists.append(legend)
        highest = max(every + list(depth)) + tile / 2
        needed = _make_room(ax, legend, highest, bottom, top)
        if needed > top:  # the depths part grows upwards; the colours sit on its new top
            for artist in colours:
                artist.remove()
                artists.remove(artist)
            top = needed
            ax.set_ylim(bottom, top)
            ax.set_yticks(*depth_ticks(*_tick_range(bottom, top, lo, hi)))
            artists += _draw_colours(ax, h, x, (bottom, top))
    return artists


def _fitted_legend(ax, shown: list, depth_part: float):
    """The legend of :func:`draw_history` at the top of the depth part (the lower
    ``depth_part`` of the Axes), in the first layout that fits the Axes' width: two columns,
    two columns with the long "(no depth)" labels on two lines, one column (review r27 D2: in
    the inspector's 313-px Axes "not_covered (no depth)" made the two-column legend wider
    than the Axes; it ran off the figure and covered the top depth tick). Measured on the
    figure's renderer; without one, the first layout."""
    wrapped = [label.replace(" (", "\n(") for _, label in shown]
    layouts = [(2, [label for _, label in shown]), (2, wrapped), (1, wrapped)]
    try:
        renderer = ax.figure._get_renderer()
        room = ax.get_window_extent(renderer).width
    except AttributeError:  # (not a matplotlib figure we know how to measure)
        renderer = None
    for ncols, labels in layouts:
        # the longest labels share the first column (filled first), so that two columns
        # stay within the Axes' width
        half = (len(shown) + ncols - 1) // ncols
        ranked = sorted(range(len(shown)), key=lambda i: -len(labels[i]))
        first = sorted(ranked[:half])
        order = first + [i for i in range(len(shown)) if i not in first]
        legend = ax.legend([shown[i][0] for i in order], [labels[i] for i in order],
                           fontsize="x-small", loc="upper center", ncols=ncols,
                           bbox_to_anchor=(0, 0, 1, depth_part), framealpha=0.85,
                           columnspacing=0.8, handlelength=1.0, handletextpad=0.4,
                           borderaxespad=0.2)  # fmt: skip
        if renderer is None or legend.get_window_extent(renderer).width <= room - 2:
            break
    return legend


def _make_room(ax, legend, highest: float, bottom: float, top: float) -> float:
    """The top of the depth part at which ``legend`` (anchored to that top) lies wholly
    above ``highest`` (the highest tile or buffer marker), measured on the figure's
    renderer: its height in pixels is fixed, so the depth part's share of the Axes (the
    colours above keep their share) sets how far the top must rise. ``top`` if it already
    does, or if the figure has no renderer to measure with."""
    try:
        renderer = ax.figure._get_renderer()
    except AttributeError:  # (not a matplotlib figure we know how to measure)
        return top
    box = legend.get_window_extent(renderer)
    axes = ax.get_window_extent(renderer)
    if not axes.height:
        return top
    share = (top - bottom) / (ax.get_ylim()[1] - bottom)  # the depth part's share
    # a buffer marker's radius and a 5-pt gap, in pixels (r399 F7: 6 px, under the classroom
    # style's 10-pt markers at its resolution, left the legend's edge on the ○ at 0.042)
    size = max((line.get_markersize() for line in ax.lines), default=6.0)
    margin = (size / 2 + 5.0) * ax.figure.dpi / 72
    below = (box.y0 - axes.y0 - margin) / axes.height / share  # of the depth part
    if below <= 0.2:  # (an Axes too small to hold both: keep the two-row room)
        return top
    return max(top, bottom + (highest - bottom) / below)


def _record_labels(h: PixelHistory) -> list[str]:
    """The records' tick labels: the triangle; under MSAA the sample's number alone (one
    digit: twelve records at 4x stay apart; "s3s0s1" ran together, review r50 D3)."""
    if h.n_samples == 1:
        return [str(r.triangle) for r in h.records]
    return [str(r.sample) for r in h.records]


def _triangle_groups(h: PixelHistory) -> list[tuple[float, int]]:
    """Under MSAA, (centre x, triangle) of each run of consecutive records of one triangle:
    where :func:`_label_records` writes the triangle once, under its samples."""
    groups, start = [], 0
    for i in range(1, len(h.records) + 1):
        if i == len(h.records) or h.records[i].triangle != h.records[start].triangle:
            groups.append(((start + i - 1) / 2, h.records[start].triangle))
            start = i
    return groups


def _label_records(ax, h: PixelHistory, x: np.ndarray) -> None:
    """The x axis of :func:`draw_history`: the triangle under each record; under MSAA the
    sample number under each record and the triangle once, centred below its samples (minor
    ticks, without tick marks)."""
    ax.set_xticks(x, _record_labels(h), fontsize="small")
    if h.n_samples == 1:
        ax.set_xlabel("triangle, in drawing order")
        return
    centres, tris = zip(*_triangle_groups(h)) if h.records else ((), ())
    ax.set_xticks(list(centres), [str(t) for t in tris], minor=True, fontsize="small")
    # the triangle's line one full line below the samples' (a fixed 16-pt pad let the
    # classroom style's larger digits touch: "0 1₉2 3", review r55 #9): pad in points =
    # the major ticks' own pad and length, the samples' text height and a gap
    major = ax.xaxis.get_major_ticks()
    size = major[0].label1.get_size() if major else 10.0
    gap = ax.xaxis.get_tick_padding() if major else 3.5
    ax.tick_params(axis="x", which="minor", length=0, pad=gap + 1.5 * size)
    ax.set_xlabel("triangle (samples above)")


def swatch_colours(h: PixelHistory, key: str) -> np.ndarray:
    """The opaque RGB that :func:`draw_history` paints for ``key`` (``"color_before"``,
    ``"color"`` or ``"color_after"``) of each passed record of ``h``, one row each.

    The target's before and after are its RGB clipped to [0, 1]; the fragment is its RGB
    over white by its alpha (see :func:`_draw_colours`: drawn over checks, white in the
    swatch's middle, so that a translucent fragment is told from an opaque result)."""
    if key not in ("color_before", "color", "color_after"):
        raise ValueError(f"key must be color_before, color or color_after, not {key!r}")
    on = [r for r in h.records if r.outcome == "passed"]
    rgba = np.array([getattr(r, key) for r in on], dtype=float).reshape(len(on), -1)
    rgb = np.clip(rgba[:, :3], 0, 1)
    if key != "color":  # the target: already composited, as the frame shows it
        return rgb
    a = np.clip(rgba[:, 3:4], 0, 1)
    return rgb * a + (1 - a)  # the fragment before its blend: over white, for the eye


def _draw_colours(ax, h: PixelHistory, x, limits):
    """With a colour buffer: above each record that reached it, three swatches, the
    target's colour before, the fragment's and the target's after; returns the artists
    (none without a colour buffer).

    The target's RGB is drawn as it is (clipped to [0, 1]): it already holds the clear
    colour and every blend so far, so it is the colour the frame shows. Only the fragment,
    whose alpha has not been applied yet, is drawn over white by its alpha (review r44 D1:
    compositing the target again by its own alpha drew (245, 179, 179) for a pixel the
    table prints as (0.95, 0.6, 0.6) = (242, 153, 153))."""
    if h.blend is None or not len(x):
        return []
    lo, hi = limits
    band = (hi - lo) * SWATCH_BAND
    ax.set_ylim(lo, hi + band * 1.75)
    on = [i for i, r in enumerate(h.records) if r.outcome == "passed"]
    if not on:
        return []
    artists = [ax.axhline(hi, color="0.6", linewidth=0.8)]  # depths below, colours above
    for key, dx in zip(("color_before", "color", "color_after"), SWATCH_OFFSETS):
        shown = swatch_colours(h, key)
        if key == "color":  # its own RGB by its alpha over checks, white in the middle
            artists += _checks(ax, x[on] + dx, hi + band * 0.15, band, h, on)
            shown = _fragment_rgba(h)
        artists.append(ax.bar(x[on] + dx, band, bottom=hi + band * 0.15, width=SWATCH_WIDTH,
                              color=shown, edgecolor="k", linewidth=0.4))  # fmt: skip
    size = _swatch_word_size(ax, SWATCH_WORDS)
    if size is not None:
        # each record's three swatches named above them, as RenderDoc names its columns: one
        # label at the left named only the first record's (review r55 #7, r62)
        for word, dx in zip(SWATCH_WORDS, SWATCH_OFFSETS):
            artists += [ax.text(x[i] + dx, hi + band * 1.2, word, fontsize=size,
                                ha="center", va="bottom") for i in on]  # fmt: skip
        return artists
    # at the Axes' left edge (x in Axes fractions), made to fit its width
    header = ax.text(0.02, hi + band * 1.2, SWATCH_HEADER, fontsize="x-small", ha="left",
                     va="bottom", transform=ax.get_yaxis_transform())  # fmt: skip
    _fit_header(ax, header)
    return artists + [header]


#: The one label over the colour swatches where each record's cannot be named
#: (:func:`_draw_colours`), and its short form where even that does not fit.
SWATCH_HEADER = "before | fragment (over checks) | after"
SWATCH_HEADER_SHORT = "before | fragment | after"


def _fit_header(ax, header) -> None:
    """Keep the swatches' one label inside the Axes (review r211 11-4: in the inspector's
    glass view it ran past the right edge): smaller, down to 9 points (12 px at 96 dpi),
    then in its short form. Measured on the figure's renderer; without one, left as it is."""
    from matplotlib.font_manager import FontProperties

    try:
        renderer = ax.figure._get_renderer()
        right = ax.get_window_extent(renderer).x1
    except AttributeError:  # (not a matplotlib figure we know how to measure)
        return
    for text in (SWATCH_HEADER, SWATCH_HEADER_SHORT):
        header.set_text(text)
        header.set_fontsize(FontProperties(size="x-small").get_size_in_points())
        while header.get_window_extent(renderer).x1 > right - 2:
            if header.get_fontsize() * 0.9 < 9:
                break
            header.set_fontsize(header.get_fontsize() * 0.9)
        else:
            return


def _fragment_rgba(h: PixelHistory) -> np.ndarray:
    """Each passed record's fragment colour as drawn: its RGB clipped to [0, 1], with its
    alpha, over :func:`_checks` (over white where a check is white: :func:`swatch_colours`)."""
    on = [r for r in h.records if r.outcome == "passed"]
    rgba = np.array([r.color for r in on], dtype=float).reshape(len(on), -1)
    return np.column_stack([np.clip(rgba[:, :3], 0, 1), np.clip(rgba[:, 3], 0, 1)])


def _checks(ax, centres, bottom, height, h: PixelHistory, on) -> list:
    """Under each translucent fragment swatch (alpha < 1), a 3 x 3 board of grey and white
    checks, white in the middle: a fragment with alpha ½ over white looked the same as the
    target after it was blended over a white target (review r90 11-6); over the checks
    its translucency shows, while its middle is still the colour over white."""
    from matplotlib.patches import Rectangle

    artists = []
    alpha = _fragment_rgba(h)[:, 3]
    for k, x0 in enumerate(centres):
        if alpha[k] >= 1:
            continue
        for i in range(3):
            for j in range(3):
                colour = "white" if (i + j) % 2 == 0 else "0.6"
                artists.append(ax.add_patch(Rectangle(
                    (x0 + (i / 3 - 0.5) * SWATCH_WIDTH, bottom + j * height / 3),
                    SWATCH_WIDTH / 3, height / 3,
                    facecolor=colour, edgecolor="none", zorder=1)))  # fmt: skip
    return artists


#: The words over a record's three colour swatches, where they fit (:func:`_draw_colours`).
SWATCH_WORDS = ("before", "fragment", "after")
#: A colour swatch's width (records) and the three's offsets from their record: 0.92 of a
#: record's room (0.26 wide, ±0.27 before: 15 px in the frame inspector; review r96 11-3).
SWATCH_WIDTH = 0.3
SWATCH_OFFSETS = (-0.31, 0.0, 0.31)
#: A swatch's height as a share of the depths' range (0.18 before: 30 px in the inspector,
#: r96 11-3); the colour band above the depths is 1.75 of it (the words over the swatches).
SWATCH_BAND = 0.36


def _swatch_word_size(ax, words) -> float | None:
    """The font size (points) in which the longest of ``words`` fits over a colour swatch
    (:data:`SWATCH_WIDTH` records wide; estimated at 0.55 em a character): the Axes' small size, else its
    x-small one, as long as that is at least 9 points (12 px at 96 dpi); else None."""
    from matplotlib.font_manager import FontProperties

    width_in = ax.get_position().width * ax.figure.get_size_inches()[0]
    span = abs(np.subtract(*ax.get_xlim())) or 1.0
    swatch_pt = SWATCH_WIDTH * width_in / span * 72
    for name in ("small", "x-small"):
        size = FontProperties(size=name).get_size_in_points()
        if size >= 9 and swatch_pt >= 0.55 * size * max(len(w) for w in words):
            return size
    return None
