"""Writing the output: progress bar, pyplot on demand, GIF/MP4 writers and frame loops."""

from __future__ import annotations

import math
import shutil
import sys
from pathlib import Path

from .arguments import ANIMATED, ANIMATION_DPI, PNG_DPI, STILL


# -- output helpers ----------------------------------------------------------------------------
class Progress:
    """A text progress bar on stderr: ``[#####-----] 12/40 frames  out.gif``.

    Redrawn in place with a carriage return, and only when the bar changes, so a log file
    of a long export stays short.
    """

    def __init__(
        self, total: int, label: str, *, stream=None, width: int = 30, enabled: bool = True
    ) -> None:
        self.total, self.label, self.width = max(total, 1), label, width
        self.stream = sys.stderr if stream is None else stream
        self.enabled = enabled
        self._last = None

    def update(self, done: int) -> None:
        if not self.enabled:
            return
        filled = self.width * done // self.total
        if (filled, done == self.total) == self._last and done != self.total:
            return
        self._last = (filled, done == self.total)
        bar = "#" * filled + "-" * (self.width - filled)
        self.stream.write(f"\r[{bar}] {done}/{self.total} frames  {self.label}")
        self.stream.flush()

    def close(self) -> None:
        if self.enabled:
            self.stream.write("\n")
            self.stream.flush()


def pyplot():
    """pyplot on the Agg backend (an export never opens a window)."""
    import matplotlib

    if "matplotlib.pyplot" not in sys.modules:
        matplotlib.use("Agg")  # only before pyplot exists: do not switch a running session's
    import matplotlib.pyplot as plt

    return plt


def _writer(path: Path, fps: float):
    """The matplotlib animation writer for ``path``'s suffix."""
    from matplotlib import animation

    if path.suffix.lower() == ".gif":
        return animation.PillowWriter(fps=fps)
    # h264 in yuv420p (matplotlib's default for h264, and it pads odd frame sizes): what
    # presentation software and browsers play
    return animation.FFMpegWriter(fps=fps, codec="h264")


def ffmpeg_available() -> bool:
    """Whether matplotlib can write MP4 (ffmpeg on PATH or set in ``animation.ffmpeg_path``)."""
    import matplotlib as mpl

    return shutil.which(str(mpl.rcParams["animation.ffmpeg_path"])) is not None


def animate(
    fig, path: Path, frames, update, *, fps: float, hold: float, dpi: int, quiet: bool
) -> int:
    """Write an animation: ``update(frame)`` changes the artists in place, then grab.

    The last frame is repeated for ``hold`` seconds so the finished picture stays up before
    the animation loops; Pillow merges identical consecutive GIF frames into one longer frame.

    Returns
    -------
    int
        Number of frames grabbed (held repeats included).
    """
    frames = list(frames)
    extra = max(0, round(hold * fps))
    total = len(frames) + extra
    bar = Progress(total, str(path), enabled=not quiet)
    writer = _writer(path, fps)
    done = 0
    with writer.saving(fig, str(path), dpi):
        bar.update(0)
        for frame in frames + [frames[-1]] * extra:
            if done < len(frames):
                update(frame)
            writer.grab_frame()
            done += 1
            bar.update(done)
    bar.close()
    return total


def animate_from_args(fig, frames, update, args) -> int:
    """:func:`animate` to ``args.output`` with the command line's fps, hold, dpi and quiet."""
    return animate(
        fig,
        args.output,
        frames,
        update,
        fps=args.fps,
        hold=args.hold,
        dpi=output_dpi(args),
        quiet=args.quiet,
    )


def triangle_from_args(args, *, attrs_default=None):
    from ..core.triangle import Triangle

    attrs = dict(args.attr) if args.attr else dict(attrs_default or {})
    return Triangle(args.xy, w=args.w, attrs=attrs)


def fill_from_args(args, tri):
    from ..core.fill import rasterize

    width, height = args.size
    return rasterize(
        tri, width, height, method=args.method, interpolation=args.interpolation, trace=True
    )


def output_dpi(args) -> int:
    if args.dpi is not None:
        return args.dpi
    return PNG_DPI if args.output.suffix.lower() in STILL else ANIMATION_DPI


def is_animation(args) -> bool:
    return args.output.suffix.lower() in ANIMATED


def format_values(values) -> str:
    return ", ".join(f"{x:.3g}" for x in values)


def say(text: str) -> None:
    print(text, file=sys.stdout)


# -- pages: a fill that steps offline, a lesson exported to HTML ------------------------------
#: Pixels of the largest grid a fill export draws: every pixel has a centre marker and a cell
#: of its own, and beyond this a step takes seconds to draw and nothing in it can be read.
MAX_FILL_PIXELS = 128 * 128
#: Longest export a fill is allowed to take, by the estimate from its first frames.
MAX_EXPORT_SECONDS = 600.0


def check_fill_size(args, parser) -> None:
    """Refuse a grid too large to draw step by step, saying what would fit."""
    width, height = args.size
    if width * height > MAX_FILL_PIXELS:
        parser.error(
            f"argument --size: {width}x{height} is {width * height} pixels; a fill export draws "
            f"every pixel's cell and centre, so it is limited to {MAX_FILL_PIXELS} pixels "
            "(e.g. 128x128); teach large images with 'teachraster scene'"
        )


def estimate_seconds(draw_one, frames: int, *, probes: int = 3) -> float:
    """Seconds ``frames`` frames will take, from the time of drawing a few of them."""
    import time

    probes = max(1, min(probes, frames))
    t0 = time.perf_counter()
    for k in range(probes):
        draw_one(k)
    return (time.perf_counter() - t0) / probes * frames


def check_export_time(view, steps, args, parser) -> None:
    """Estimate an animation's drawing time from its first frames; refuse one too long.

    The estimate goes to stderr (with the progress bar) unless ``--quiet``.
    """
    seconds = estimate_seconds(lambda k: (view.show_step(steps[k], draw=False),
                                          view.fig.canvas.draw()), len(steps))  # fmt: skip
    if seconds > MAX_EXPORT_SECONDS:
        parser.error(
            f"argument --size: {len(steps)} frames would take about {seconds / 60:.0f} min to "
            f"draw (limit {MAX_EXPORT_SECONDS / 60:.0f} min); use --every "
            f"{math.ceil(seconds / MAX_EXPORT_SECONDS)} or more, or a smaller --size"
        )
    if not args.quiet:
        print(f"{len(steps)} frames, about {seconds:.0f} s to draw", file=sys.stderr)


def write_fill_page(args, fill) -> int:
    """``teachraster fill ... -o fill.html``: one file that steps and plays with no Python.

    Returns the number of steps in the page.
    """
    from ..plotting import FillView, use_style
    from ..plotting.pages import page_data, page_figure, standalone_page

    with use_style(args.style):
        fig, ax = page_figure(fill.trace.width, fill.trace.height)
        view = FillView(fill, ax=ax, step=0, caption=False, step_header=False)
        data = page_data(view, step=args.step or 0, interval=round(1000 / args.fps))
    title = f"{view.trace.method} fill of a triangle, step by step"
    args.output.write_text(standalone_page(data, title), encoding="utf-8")
    return data["n"]
