"""Ek's eye–screen–segment picture: equal steps on the screen are unequal steps in the world.

Ek (*Triangles and Perspective Correct Interpolation*, §2, Figures 6 and 7) projects a 2-D world
onto a 1-D screen: the eye at the origin, the screen the line z = 1 (a point (x, z) lands at
s = x/z), a segment from (x0, z0) to (x1, z1). Stepping evenly along the screen (q = 0, 1/N,
..., 1) and following each eye ray to the segment gives world points that are *not* evenly
spaced: the far half of the segment is squeezed into less of the screen.

Where a ray meets the segment is the perspective-correct weight of the engine
(:func:`teachraster.core.interpolation.perspective_weights`, with screen weights (1 − q, q)
and depths (z0, z1)); the picture only draws it, with the eye ray through the screen point, so
a student sees that ray, screen point and world point line up.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.ticker import MaxNLocator

from ..core.interpolation import perspective_weights
from .common import fs, lw, ms, tint
from .style import COLORS, OKABE_ITO


@dataclass(frozen=True)
class Segment:
    """A world segment (x0, z0) -> (x1, z1) seen from the eye at the origin, screen at z = 1."""

    x0: float = -1.0
    z0: float = 1.5
    x1: float = 2.0
    z1: float = 6.0

    def __post_init__(self) -> None:
        for name in ("z0", "z1"):
            if not float(getattr(self, name)) > 0.0:
                raise ValueError(
                    f"{name} must be in front of the eye (> 0), got {getattr(self, name)!r}"
                )

    def screen(self, q) -> np.ndarray:
        """Screen position s of screen parameter q: s = s0 + q (s1 − s0), s_k = x_k / z_k."""
        s0, s1 = self.x0 / self.z0, self.x1 / self.z1
        return s0 + np.asarray(q, dtype=np.float64) * (s1 - s0)

    def world_parameter(self, q) -> np.ndarray:
        """World parameter t seen at screen parameter q (the engine's perspective weight)."""
        q = np.atleast_1d(np.asarray(q, dtype=np.float64))
        lam = np.column_stack([1.0 - q, q, np.zeros_like(q)])
        return perspective_weights(lam, np.array([self.z0, self.z1, 1.0]))[:, 1]

    def point(self, t) -> np.ndarray:
        """(x, z) of world parameter t on the segment, shape (n, 2)."""
        t = np.atleast_1d(np.asarray(t, dtype=np.float64))[:, None]
        return np.array([self.x0, self.z0]) * (1 - t) + np.array([self.x1, self.z1]) * t

    def with_ratio(self, ratio: float) -> Segment:
        """The far end moved along its own eye ray to depth ``ratio`` · z0: the same image on
        the screen, another depth ratio."""
        z1 = float(ratio) * self.z0
        return Segment(self.x0, self.z0, self.x1 / self.z1 * z1, z1)

    def peak(self) -> tuple[float, float]:
        """Where |t − q| is largest, and how large: (q*, |t(q*) − q*|).

        With r = z1 / z0, t = q / (r − q (r − 1)); d(t − q)/dq = 0 where r − q (r − 1) = √r,
        so q* = √r / (1 + √r) and the gap is (√r − 1)² / (r − 1) (0 at r = 1, where t = q).
        """
        root = np.sqrt(self.z1 / self.z0)
        q_star = float(root / (1.0 + root))
        return q_star, float(abs(self.world_parameter(q_star)[0] - q_star))


@dataclass
class ProjectionArtists:
    """Artists of :func:`plot_projection`; ``update(q)`` moves the highlighted ray."""

    segment: Segment
    ray: object = None
    screen_point: object = None
    world_point: object = None
    affine_point: object = None
    label: object = None
    curve_point: object = None
    steps: list = field(default_factory=list)
    top: float = 0.0  # the picture's top depth: the highlighted ray runs up to it
    shows: bool = True  # False: the screen point at q only, not its ray or what it shows
    world: str = "t"  # the name the title gives the world parameter

    def update(self, q: float) -> float:
        """Highlight screen parameter ``q``; returns its world parameter t."""
        q = float(q)
        t = float(self.segment.world_parameter(q)[0])
        (x, z) = self.segment.point(t)[0]
        s = float(self.segment.screen(q))
        far = self.top
        self.screen_point.set_data([s], [1.0])
        if not self.shows:  # a question asks where that ray lands: nothing answers it
            return t
        self.ray.set_data([0.0, s * far], [0.0, far])
        self.world_point.set_data([x], [z])
        self.affine_point.set_data(*self.segment.point(q).T)
        # two lines: over a picture at one scale in x and z (tall, narrow) one ran off it
        self.label.set_text(f"q = {q:.2f} on the screen\n→  {self.world} = {t:.2f} on the segment")
        if self.curve_point is not None:
            self.curve_point.set_data([q], [t])
        return t


def _top(segment: Segment) -> float:
    """The picture's top depth: above the segment, and at least 2 (the screen at z = 1 then
    stays in the lower half: a segment lying on it is still seen as one, not as the frame)."""
    return 1.15 * max(segment.z0, segment.z1, 2.0)


def frame_of(segments) -> tuple[float, float, float]:
    """(x from, x to, top depth) that holds every one of ``segments`` and its screen image:
    one frame for all, so that a picture of each puts the screen at the same place."""
    lo = min(min(g.screen([0.0, 1.0]).min(), g.x0, g.x1) for g in segments) - 0.25
    hi = max(max(g.screen([0.0, 1.0]).max(), g.x0, g.x1) for g in segments) + 0.25
    return float(lo), float(hi), max(_top(g) for g in segments)


def plot_projection(ax, segment: Segment = Segment(), *, n_steps: int = 8, q: float = 0.5,
                    curve_ax=None, frame=None, shows: bool = True,
                    world: str = "t") -> ProjectionArtists:  # fmt: skip
    """Draw eye, screen, segment and the rays of ``n_steps`` equal screen steps.

    Parameters
    ----------
    ax : matplotlib Axes
        The picture: x to the right, depth z upwards, the eye at the origin.
    segment : Segment
    n_steps : int
        Equal steps of q on the screen; their rays mark unequal steps on the segment.
    q : float
        The highlighted screen parameter (``update(q)`` moves it).
    curve_ax : matplotlib Axes, optional
        Also plot t against q there (with t = q dashed), the highlighted point on it, and the
        largest gap |t − q| as a bar at the q where it occurs.
    frame : (float, float, float), optional
        x from, x to and the top depth (:func:`frame_of`); default: the segment's own.
    shows : bool
        Draw the ray through the screen point at ``q`` and what it shows (the world point,
        the affine guess, the title). False draws the screen point alone, for a question on
        where its ray meets the segment (lesson 00): with ``n_steps=1`` nothing drawn answers it.
    world : str
        The world parameter's name in the key and the title: Ek's ``t`` (lesson 04), or an
        attribute that runs evenly along the segment in the world, and so equals t (lesson
        00's ``u``, review r249 S2: its question asks for u).

    Returns
    -------
    ProjectionArtists
    """
    blue, orange = OKABE_ITO["blue"], OKABE_ITO["orange"]
    qs = np.linspace(0.0, 1.0, int(n_steps) + 1)
    ts = segment.world_parameter(qs)
    pts, ss = segment.point(ts), segment.screen(qs)
    lo, hi, far = frame_of([segment]) if frame is None else frame
    out = ProjectionArtists(segment, top=far, shows=bool(shows), world=str(world))
    for x, z in pts:
        out.steps += ax.plot([0, x], [0, z], color=COLORS["grid"], lw=lw(0.3), zorder=1)
    # a wide pale band under the segment: a segment lying on the screen (z0 = z1 = 1) is
    # still seen as a line of its own
    ax.plot([lo, hi], [1, 1], color=tint(COLORS["fill"], 0.45), lw=lw(2.2), zorder=0.5,
            solid_capstyle="butt", label="screen (z = 1)")  # fmt: skip
    steps = f"{n_steps} equal steps of q" if n_steps > 1 else "the ends' images"
    ax.plot(ss, np.ones_like(ss), "|", color=blue, ms=ms(1.6), mew=lw(0.6), label=steps)
    ax.plot(*pts.T, "-", color=COLORS["edge"], lw=lw(1.0), label="segment in the world")
    # above the large dot at t: at q = 0 or 1 that dot hid the end's own (review r77 04-4)
    (hits,) = ax.plot(*pts.T, "o", color=orange, ms=ms(0.8), zorder=4,
                      label="eye rays, where they meet it")  # fmt: skip
    ax.plot([0], [0], "^", color=COLORS["edge"], ms=ms(1.3), label="eye")
    # unlabelled when not shown: the key names only what is drawn
    shown = {} if shows else {"label": "_hidden", "visible": False}
    (out.ray,) = ax.plot([], [], color=COLORS["current"], lw=lw(0.8),
                         **({"label": "the ray at q"} | shown))  # fmt: skip
    (out.screen_point,) = ax.plot([], [], "s", color=COLORS["current"], ms=ms(1.0),
                                  label="screen point q")  # fmt: skip
    (out.world_point,) = ax.plot([], [], "o", color=COLORS["current"], ms=ms(1.3),
                                 **({"label": f"what it shows: {world}"} | shown))  # fmt: skip
    (out.affine_point,) = ax.plot([], [], "o", mfc="none", mec=COLORS["current"], mew=lw(0.5),
                                  ms=ms(1.3), **({"label": f"affine guess: {world} = q"} | shown))  # fmt: skip
    # text set by update(), size fixed here; from the left edge, as the key takes the right
    out.label = ax.set_title(" ", fontsize=fs(0.9), loc="left")
    ax.set(xlim=(lo, hi), ylim=(-0.2, far), xlabel="x", ylabel="depth z")
    # one scale in x and z: the picture is an argument by similar triangles, and with unequal
    # scales the rays looked 2.7 times flatter than they are (review r234 04-FIG1)
    ax.set_aspect("equal", adjustable="box")
    # at most six x ticks: a short segment (z1 = z0 on the screen line) got nine 0.25 apart,
    # their classroom-size labels running together (review r5, 04)
    ax.xaxis.set_major_locator(MaxNLocator(nbins=5, steps=[1, 2, 2.5, 5, 10]))
    # the key beside the picture: inside, nine entries cover part of the rays whatever
    # corner they take
    # the dots keyed on a grey eye ray: "where those rays hit it" named rays the key did not
    # show (review r249 S2); one entry for both, so that the key grows no taller, and one
    # Line2D, which a key made again from legend_handles keeps whole (ProjectionExplorer)
    ray_and_hit = Line2D([], [], color=COLORS["grid"], lw=lw(0.3), marker="o", ms=ms(0.8),
                         mfc=orange, mec=orange)  # fmt: skip
    handles, labels = ax.get_legend_handles_labels()
    handles = [ray_and_hit if h is hits else h for h in handles]
    ax.legend(handles, labels, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0,
              fontsize=fs(0.7))  # fmt: skip
    if curve_ax is not None:
        qq = np.linspace(0.0, 1.0, 200)
        curve_ax.plot(qq, segment.world_parameter(qq), color=COLORS["edge"], lw=lw(0.8),
                      label="t(q)")  # fmt: skip
        curve_ax.plot(qq, qq, "--", color=COLORS["grid"], lw=lw(0.6), label="t = q (affine)")
        q_star, gap = segment.peak()
        if gap > 1e-12:  # at z1 = z0 there is no gap to mark
            curve_ax.plot([q_star, q_star], [q_star - gap, q_star], color=OKABE_ITO["reddish_purple"],
                          lw=lw(0.6), marker="_", ms=ms(1.0),
                          label="largest |t − q|")  # fmt: skip
        # not clipped, and a margin round the unit square: at q = 0 or 1 the dot sat half
        # hidden on the frame's corner (review r77 04-4)
        (out.curve_point,) = curve_ax.plot([], [], "o", color=COLORS["current"], ms=ms(1.2),
                                           clip_on=False)  # fmt: skip
        curve_ax.set(xlabel="q (screen)", ylabel="t (world)", xlim=(-0.02, 1.02),
                     ylim=(-0.02, 1.02))  # fmt: skip
        curve_ax.legend(loc="upper left", fontsize=fs(0.7))
    out.update(q)
    return out
