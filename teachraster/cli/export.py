"""Writing the output: progress bar, pyplot on demand, GIF/MP4 writers and frame loops."""

from __future__ import annotations

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
