"""``teachraster ...``: export fills, comparisons, scenes and hard cases for slides.

Every export is a still PNG or an animation (GIF through Pillow, MP4 through ffmpeg), chosen
by the suffix of ``-o``. Exports use the projector-ready ``classroom`` style unless
``--style default`` is given. Subcommands::

    teachraster fill --xy "2.2,1.5 13.7,5.2 5.1,12.8" --method halfplane -o fill.gif
    teachraster fill --xy "2.2,1.5 13.7,5.2 5.1,12.8" --step 5 -o step5.png
    teachraster compare --xy "1,1 15,3 4,14" --w "1,4,2" --attr u=0,1,0 -o error.png
    teachraster compare --xy "1,1 15,3 4,14" --attr u=0,1,0 --sweep-w 1:8 -o sweep.gif
    teachraster scene textured_floor --compare -o floor.png
    teachraster case d3d_split_square -o split.png
    teachraster list

The same runs as ``python -m teachraster ...``. Animations are driven by the plotting
layer's in-place updates (:meth:`FillView.show_step`, :meth:`InterpolationView.update`): each
frame changes the data of the artists drawn once, then the writer grabs the canvas.

The core stays numpy-only: matplotlib is imported inside the functions that draw, so
importing this module (or ``teachraster``) does not load it.

>>> build_parser().parse_args(["fill", "--xy", "0,0 4,0 0,4", "-o", "f.png"]).size
(16, 16)
>>> parse_xy("2.2,1.5 13.7,5.2 5.1,12.8").tolist()
[[2.2, 1.5], [13.7, 5.2], [5.1, 12.8]]
"""

from __future__ import annotations

import argparse
import math
import os
import shutil
import sys
from pathlib import Path

import numpy as np

#: Output formats by suffix: still image or animation.
STILL, ANIMATED = (".png",), (".gif", ".mp4")
#: Default resolutions: PNG for slides (crisp when scaled), animations small enough to embed.
PNG_DPI, ANIMATION_DPI = 150, 80


# -- argument types (their errors become "argument --opt: ..." with exit status 2) ------------
def _floats(text: str, what: str) -> list[float]:
    try:
        values = [float(v) for v in text.replace(",", " ").split()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"{what}: not a number in {text!r}") from None
    if not all(math.isfinite(v) for v in values):
        raise argparse.ArgumentTypeError(f"{what}: values must be finite, got {text!r}")
    return values


def parse_xy(text: str) -> np.ndarray:
    """Three vertices ``"x0,y0 x1,y1 x2,y2"`` (pixels, y down) as a (3, 2) array.

    Vertices are separated by spaces or semicolons, coordinates by a comma.
    """
    groups = text.replace(";", " ").split()
    if len(groups) != 3 or any(g.count(",") != 1 for g in groups):
        raise argparse.ArgumentTypeError(
            f"expected three vertices 'x0,y0 x1,y1 x2,y2', got {text!r}"
        )
    return np.array([_floats(g, "vertex") for g in groups], dtype=np.float64)


def parse_w(text: str) -> np.ndarray:
    """Clip-space w (view depth) of the three vertices, ``"1,2,4"``; each must be > 0."""
    w = _floats(text, "w")
    if len(w) != 3:
        raise argparse.ArgumentTypeError(f"expected three depths 'w0,w1,w2', got {text!r}")
    if min(w) <= 0:
        # a vertex with w <= 0 is at or behind the eye: the 2-D fill cannot take it
        raise argparse.ArgumentTypeError(f"every w must be > 0 (in front of the eye), got {text!r}")
    return np.array(w)


def parse_attr(text: str) -> tuple[str, np.ndarray]:
    """``"u=0,1,0"`` (one value per vertex) or ``"uv=0,0 1,0 0,1"`` (a vector per vertex)."""
    name, sep, values = text.partition("=")
    name = name.strip()
    if not sep or not name.isidentifier():
        raise argparse.ArgumentTypeError(f"expected NAME=v0,v1,v2, got {text!r}")
    groups = values.replace(";", " ").split()
    if len(groups) == 1:
        arr = np.array(_floats(groups[0], name))
        if arr.shape != (3,):
            raise argparse.ArgumentTypeError(f"{name}: expected 3 values, got {values!r}")
    elif len(groups) == 3:
        rows = [_floats(g, name) for g in groups]
        if len({len(r) for r in rows}) != 1:
            raise argparse.ArgumentTypeError(f"{name}: vertices have different sizes: {values!r}")
        arr = np.array(rows)
    else:
        raise argparse.ArgumentTypeError(f"{name}: expected 3 values or 3 vectors, got {values!r}")
    return name, arr


def parse_size(text: str) -> tuple[int, int]:
    """``"WxH"`` in pixels, e.g. ``"16x16"``."""
    parts = text.lower().split("x")
    try:
        w, h = (int(p) for p in parts)
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected WIDTHxHEIGHT such as 16x16, got {text!r}"
        ) from None
    if w <= 0 or h <= 0:
        raise argparse.ArgumentTypeError(f"width and height must be positive, got {text!r}")
    if w * h > 4096 * 4096:
        raise argparse.ArgumentTypeError(f"{text} is too large for a teaching export")
    return w, h


def parse_range(text: str) -> tuple[float, float]:
    """``"A:B"``: a w sweep from A to B (both > 0)."""
    parts = text.split(":")
    if len(parts) != 2:
        raise argparse.ArgumentTypeError(f"expected START:STOP such as 1:8, got {text!r}")
    a, b = (_floats(p, "sweep")[0] if p.strip() else float("nan") for p in parts)
    if not (a > 0 and b > 0):
        raise argparse.ArgumentTypeError(f"both ends must be numbers > 0, got {text!r}")
    return a, b


def _positive(kind, *, zero: bool = False):
    """An argparse type: a ``kind`` (int or float) > 0, or >= 0 with ``zero``."""

    def parse(text: str):
        try:
            value = kind(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected a {kind.__name__}, got {text!r}") from None
        if not (math.isfinite(value) and (value >= 0 if zero else value > 0)):
            raise argparse.ArgumentTypeError(f"must be {'>=' if zero else '>'} 0, got {text!r}")
        return value

    parse.__name__ = kind.__name__  # argparse names the type in some messages
    return parse


def output_type(animated: bool):
    """The ``-o`` type: a file whose suffix picks the format (.png; .gif, .mp4 if animated)."""

    def parse_output(text: str) -> Path:
        path = Path(text)
        suffix = path.suffix.lower()
        if suffix not in (STILL + ANIMATED if animated else STILL):
            formats = ".png (still), .gif or .mp4 (animation)" if animated else ".png"
            raise argparse.ArgumentTypeError(
                f"the suffix picks the format: {formats}; got {text!r}"
            )
        if not path.parent.is_dir():
            raise argparse.ArgumentTypeError(f"folder {str(path.parent)!r} does not exist")
        return path

    return parse_output


# -- the parser --------------------------------------------------------------------------------
def _add_triangle(p: argparse.ArgumentParser, *, attr_default: str | None) -> None:
    p.add_argument(
        "--xy",
        type=parse_xy,
        required=True,
        help='three vertices in pixels, y down: "x0,y0 x1,y1 x2,y2"',
    )
    p.add_argument(
        "--w",
        type=parse_w,
        default=None,
        help='clip-space w (view depth) per vertex, "w0,w1,w2" (default 1,1,1)',
    )
    p.add_argument(
        "--attr",
        type=parse_attr,
        action="append",
        default=None,
        help="a vertex attribute NAME=v0,v1,v2 (repeatable)"
        + (f"; default {attr_default}" if attr_default else ""),
    )
    p.add_argument(
        "--size",
        type=parse_size,
        default=(16, 16),
        help="image size WIDTHxHEIGHT in pixels (default 16x16)",
    )
    p.add_argument(
        "--method",
        choices=("span", "halfplane", "tiled"),
        default="span",
        help="span tables, half-plane tests or tiles (default span)",
    )
    p.add_argument(
        "--interpolation",
        choices=("perspective", "affine"),
        default="perspective",
        help="attribute interpolation (default perspective)",
    )


def _add_output(p: argparse.ArgumentParser, *, animated: bool) -> None:
    formats = ".png, .gif or .mp4" if animated else ".png"
    p.add_argument(
        "-o",
        "--output",
        type=output_type(animated),
        required=True,
        help=f"output file; its suffix picks the format ({formats})",
    )
    p.add_argument(
        "--style",
        choices=("classroom", "default"),
        default="classroom",
        help="classroom: large fonts and thick lines for a projector (default)",
    )
    p.add_argument(
        "--dpi",
        type=_positive(int),
        default=None,
        help=f"resolution (default {PNG_DPI} for PNG, {ANIMATION_DPI} for animations)",
    )
    # the parser itself, so that checks after parsing can report "argument --opt: ..." too
    p.set_defaults(parser=p)
    if animated:
        p.add_argument(
            "--fps",
            type=_positive(float),
            default=4.0,
            help="frames per second of an animation (default 4)",
        )
        p.add_argument(
            "--hold",
            type=_positive(float, zero=True),
            default=1.5,
            help="seconds the last frame stays before the animation loops (1.5)",
        )
        p.add_argument("-q", "--quiet", action="store_true", help="no progress bar on stderr")


def build_parser() -> argparse.ArgumentParser:
    """The ``teachraster`` argument parser (subcommands fill, compare, scene, case, list)."""
    from ..pipeline.scenes import SCENES
    from ..study.hardcases import CASES  # numpy-only, like the rest of the core

    parser = argparse.ArgumentParser(
        prog="teachraster",
        description="Export triangle fills, interpolation comparisons, scenes and hard cases "
        "as PNG, GIF or MP4 for slides.",
        epilog="Run 'teachraster COMMAND -h' for the options of a command.",
    )
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    p = sub.add_parser(
        "fill",
        help="animate a fill step by step (or a still of one step)",
        description="Fill one triangle and export every step (.gif/.mp4) or "
        "one step (.png; the finished fill unless --step).",
    )
    _add_triangle(p, attr_default=None)
    p.add_argument(
        "--step",
        type=int,
        default=None,
        help="still PNG only: the step to show (negative counts from the end)",
    )
    p.add_argument(
        "--every",
        type=_positive(int),
        default=1,
        help="animate every N-th step (the last step is always shown)",
    )
    _add_output(p, animated=True)

    p = sub.add_parser(
        "compare",
        help="affine vs perspective-correct and their error",
        description="Affine vs perspective-correct interpolation of one "
        "attribute and the error heatmap |affine - perspective|. A .gif/.mp4 "
        "sweeps the w of one vertex (--sweep-w, default 1:8).",
    )
    _add_triangle(p, attr_default="u=0,1,0")
    p.add_argument(
        "--show",
        default=None,
        metavar="NAME",
        help="attribute to compare when several are given (default: the first)",
    )
    p.add_argument(
        "--sweep-w",
        type=parse_range,
        default=None,
        metavar="START:STOP",
        help="animation only: move the w of --vertex from START to STOP",
    )
    p.add_argument(
        "--vertex",
        type=int,
        choices=(0, 1, 2),
        default=2,
        help="the vertex whose w the sweep moves (default 2)",
    )
    p.add_argument(
        "--frames", type=_positive(int), default=24, help="frames of the sweep (default 24)"
    )
    _add_output(p, animated=True)

    p = sub.add_parser(
        "scene",
        help="render a built-in scene (plan printed to stdout)",
        description="Render a built-in scene with the full pipeline, save the "
        "image and print the render plan.",
    )
    p.add_argument(
        "name", choices=list(SCENES), metavar="NAME", help="a scene: " + ", ".join(SCENES)
    )
    p.add_argument(
        "--size",
        type=parse_size,
        default=(320, 240),
        help="image size WIDTHxHEIGHT (default 320x240)",
    )
    p.add_argument(
        "--interpolation",
        choices=("perspective", "affine"),
        default="perspective",
        help="attribute interpolation (default perspective)",
    )
    p.add_argument(
        "--compare", action="store_true", help="affine | perspective-correct | error, side by side"
    )
    _add_output(p, animated=False)

    p = sub.add_parser(
        "case",
        help="a hard case: ours vs the naive rasteriser",
        description="Run a hard case from the catalogue, check it, and save "
        "our coverage beside the naive one (where the case has one).",
    )
    p.add_argument(
        "name", choices=list(CASES), metavar="NAME", help="a hard case (see 'teachraster list')"
    )
    p.add_argument(
        "--method",
        choices=("span", "halfplane"),
        default=None,
        help="fill method (default: the case's first)",
    )
    _add_output(p, animated=False)

    p = sub.add_parser(
        "list",
        help="list the built-in scenes and hard cases",
        description="List the built-in scenes and hard cases.",
    )
    p.set_defaults(parser=p)
    return parser


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


def _pyplot():
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


def _animate(
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


def _triangle(args, *, attrs_default=None):
    from ..core.triangle import Triangle

    attrs = dict(args.attr) if args.attr else dict(attrs_default or {})
    return Triangle(args.xy, w=args.w, attrs=attrs)


def _rasterize(args, tri):
    from ..core.fill import rasterize

    width, height = args.size
    return rasterize(
        tri, width, height, method=args.method, interpolation=args.interpolation, trace=True
    )


def _dpi(args) -> int:
    if args.dpi is not None:
        return args.dpi
    return PNG_DPI if args.output.suffix.lower() in STILL else ANIMATION_DPI


def _is_animation(args) -> bool:
    return args.output.suffix.lower() in ANIMATED


def _fmt(values) -> str:
    return ", ".join(f"{x:.3g}" for x in values)


def _say(text: str) -> None:
    print(text, file=sys.stdout)


# -- commands ----------------------------------------------------------------------------------
def cmd_fill(args, parser) -> int:
    """Animate a fill step by step with :class:`FillView`, or save one step as a PNG."""
    from ..plotting import FillView, use_style

    if args.step is not None and _is_animation(args):
        parser.error("argument --step: a .gif/.mp4 animates every step; --step is for a .png")
    fill = _rasterize(args, _triangle(args))
    n = len(fill.trace)
    if args.step is not None and not -n <= args.step < n:
        parser.error(f"argument --step: this fill has steps 0..{n - 1}, got {args.step}")
    plt = _pyplot()
    with use_style(args.style):
        view = FillView(fill, step=0 if _is_animation(args) else args.step)
        try:
            if _is_animation(args):
                steps = list(range(0, n, args.every))
                if steps[-1] != n - 1:
                    steps.append(n - 1)  # always end on the finished fill
                count = _animate(
                    view.fig,
                    args.output,
                    steps,
                    lambda k: view.show_step(k, draw=False),
                    fps=args.fps,
                    hold=args.hold,
                    dpi=_dpi(args),
                    quiet=args.quiet,
                )
                _say(f"wrote {args.output}: {len(steps)} of {n} steps, {count} frames")
            else:
                view.fig.savefig(args.output, dpi=_dpi(args))
                _say(f"wrote {args.output}: step {view.step} of {n - 1}")
        finally:
            plt.close(view.fig)
    return 0


def cmd_compare(args, parser) -> int:
    """Affine vs perspective-correct values and their error (:class:`InterpolationView`)."""
    from ..core.triangle import Triangle
    from ..plotting import InterpolationView, use_style

    tri = _triangle(args, attrs_default=[parse_attr("u=0,1,0")])
    name = args.show if args.show is not None else next(iter(tri.attrs))
    if name not in tri.attrs:
        parser.error(f"argument --show: no attribute {name!r}; given: {', '.join(tri.attrs)}")
    animated = _is_animation(args)
    if args.sweep_w is not None and not animated:
        parser.error("argument --sweep-w: sweeps are animations; write a .gif or .mp4")
    values = np.asarray(tri.attrs[name])
    # A fixed colour range for the values: the sweep changes w, not the vertex values, so
    # every frame's colours then mean the same numbers.
    lo, hi = float(values.min()), float(values.max())
    lo, hi = (lo, hi) if hi > lo else (lo - 0.5, hi + 0.5)
    plt = _pyplot()
    with use_style(args.style):
        view = InterpolationView(_rasterize(args, tri), name, vmin=lo, vmax=hi)
        fig = view.fig
        # the depths are what the error depends on: say them above the panels
        header = fig.text(0.5, 0.995, f"w = ({_fmt(tri.w)})", ha="center", va="top")
        try:
            if animated:
                a, b = args.sweep_w or (1.0, 8.0)
                base = tri.w.copy()

                def update(w_k: float) -> None:
                    w = base.copy()
                    w[args.vertex] = w_k
                    view.update(
                        _rasterize(args, Triangle(tri.xy, w=w, attrs=tri.attrs)), draw=False
                    )
                    header.set_text(f"w = ({_fmt(w)}): moving the depth of v{args.vertex}")

                frames = np.linspace(a, b, args.frames)
                count = _animate(
                    fig,
                    args.output,
                    frames,
                    update,
                    fps=args.fps,
                    hold=args.hold,
                    dpi=_dpi(args),
                    quiet=args.quiet,
                )
                _say(f"wrote {args.output}: w{args.vertex} from {a:g} to {b:g}, {count} frames")
            else:
                fig.savefig(args.output, dpi=_dpi(args))
                _say(f"wrote {args.output}: max |affine - perspective| = {view.maximum:.3g}")
        finally:
            plt.close(fig)
    return 0


def cmd_scene(args, parser) -> int:
    """Render a built-in scene, save its image (or the comparison) and print its plan."""
    from ..pipeline.render_scenes import render_scene
    from ..pipeline.scenes import get_scene
    from ..plotting import ComparisonView, format_plan, plot_image, use_style
    from ..plotting._common import fs

    scene = get_scene(args.name)
    width, height = args.size
    frame = render_scene(scene, width=width, height=height, interpolation=args.interpolation)
    textured = scene.shading == "texture" and scene.texture is not None
    plt = _pyplot()
    with use_style(args.style):
        if args.compare:
            other = "affine" if args.interpolation == "perspective" else "perspective"
            second = render_scene(scene, width=width, height=height, interpolation=other)
            a, b = (frame, second) if other == "perspective" else (second, frame)
            view = ComparisonView(
                a.image,
                b.image,
                titles=("affine", "perspective-correct"),
                label="texel error" if textured else "|affine − perspective|",
                grid=max(width, height) <= 64,
            )
            if textured:
                # The colour difference of a two-tone texture is only stripes of 0 and 1:
                # compare where the samples land instead, in texels (as lesson 04 does).
                from ..pipeline.texture import texel_error

                texels = texel_error(a.attr("uv"), b.attr("uv"), scene.texture.shape)
                view.heatmap.update(texels, np.zeros_like(texels))
            fig = view.fig
            fig.text(
                0.5,
                0.995,
                f"{scene.name}: {scene.description}",
                ha="center",
                va="top",
                fontsize="small",
            )
        else:
            # the figure follows the image's aspect, with room for a two-line title
            fig_w = 10.0
            fig = plt.figure(figsize=(fig_w, fig_w * height / width + 1.4))
            ax = fig.add_axes((0.08, 0.06, 0.88, 0.94 - 1.3 / fig.get_figheight()))
            plot_image(ax, frame)
            ax.set_title(
                f"{scene.name} ({args.interpolation})\n{scene.description}",
                fontsize="small",
                pad=fs(3.0),
            )
        try:
            fig.savefig(args.output, dpi=_dpi(args))
        finally:
            plt.close(fig)
    _say(f"{scene.name}: {scene.description}")
    if args.compare:
        what = "texel error" if textured else "|affine - perspective|"
        _say(f"max {what} = {view.maximum:.3g}")
    _say(format_plan(frame))
    _say(f"wrote {args.output}")
    return 0


def _counts(result) -> np.ndarray | None:
    """(H, W) coverage counts of a case's result, where it has pixels."""
    from ..study.hardcases import Fills, Rendered

    if isinstance(result, Fills):
        return result.counts
    if isinstance(result, Rendered):
        return result.coverage.astype(np.int64)
    return None


def _case_text(case, result, naive) -> list[str]:
    lines = [f"why:    {case.why}", f"expect: {case.expect}"]
    try:
        case.check(result)
        lines.append("check:  passed")
    except AssertionError as exc:  # worth showing in class too, never a traceback
        lines.append(f"check:  FAILED: {exc}")
    if naive is not None:
        lines.append(f"naive:  {case.naive_does}")
        diff = case.naive_difference(result, naive)
        if diff:
            lines.append(f"        {diff}")
    return lines


def _count_panels(
    fig, panels, *, top_in: float, pw: float, ph: float, triangles, vertical: bool
) -> None:
    """Coverage-count panels, ``top_in`` inches below the figure's top, and one colour bar.

    Side by side, or stacked for wide strips (``vertical``). Laid out in inches by hand, as
    the views do, so every panel has the same size and pixels stay square.
    """
    from matplotlib.colors import BoundaryNorm, ListedColormap

    from ..plotting import plot_pixel_grid, plot_triangle
    from ..plotting._common import fs
    from ..plotting.style import COLORS, OKABE_ITO

    h, w = panels[0][0].shape
    top = max(int(max(p.max() for p, _ in panels)), 2)
    # One colour per count: none, once (right) and twice or more (overdraw: wrong).
    colours = ["#FFFFFF", COLORS["fill"], OKABE_ITO["vermillion"]]
    colours += [OKABE_ITO["reddish_purple"]] * (top - 2)
    cmap = ListedColormap(colours[: top + 1])
    norm = BoundaryNorm(np.arange(top + 2) - 0.5, top + 1)
    fw, fh = fig.get_figwidth(), fig.get_figheight()
    gap = 1.5 if vertical else 0.9  # below a stacked panel its title needs the room

    def rect(x, y, width, height):  # inches from the top-left corner -> figure fraction
        return (x / fw, (fh - y - height) / fh, width / fw, height / fh)

    axes = []
    for i in range(len(panels)):
        x, y = (1.0, top_in + i * (ph + gap)) if vertical else (1.0 + i * (pw + gap), top_in)
        axes.append(fig.add_axes(rect(x, y, pw, ph)))
    for i, (ax, (counts, title)) in enumerate(zip(axes, panels)):
        plot_pixel_grid(ax, w, h, ticks=5 if i == 0 or vertical else False)
        im = ax.pcolormesh(
            np.arange(w + 1), np.arange(h + 1), counts, cmap=cmap, norm=norm, zorder=0.4
        )
        if triangles is not None and len(triangles) <= 16:  # more would hide the pixels
            for xy in triangles:
                plot_triangle(ax, np.asarray(xy), arrows=False, labels=len(triangles) == 1)
        ax.set_xlim(0, w)
        ax.set_ylim(h, 0)
        if vertical:
            ax.set_yticks([0.5, h - 0.5], labels=["0", str(h - 1)])  # ticks on centres
            ax.set_ylabel("")
        twice = int((counts > 1).sum())
        more = f", {twice} twice or more" if twice else ""
        ax.set_title(f"{title}: {int((counts > 0).sum())} px covered{more}", pad=fs(3.0))
    if vertical:
        x, y, height = 1.0 + pw + 0.3, top_in, len(panels) * (ph + gap) - gap
    else:
        x, y, height = 1.0 + len(panels) * (pw + gap) - 0.6, top_in, ph
    cbar = fig.colorbar(im, cax=fig.add_axes(rect(x, y, 0.25, height)), ticks=np.arange(top + 1))
    cbar.set_label("times covered")


def cmd_case(args, parser) -> int:
    """Run a hard case, check it, and save our coverage counts beside the naive ones."""
    import textwrap

    from ..plotting import use_style
    from ..study.hardcases import get_case

    case = get_case(args.name)
    if args.method is not None and args.method not in case.methods:
        parser.error(f"argument --method: {case.name} runs with {', '.join(case.methods)} only")
    result = case.run(args.method)
    naive = case.naive() if case.has_naive else None
    lines = _case_text(case, result, naive)
    ours = _counts(result)
    theirs = None if naive is None or naive.counts is None else naive.counts
    if theirs is not None and (ours is None or theirs.shape != ours.shape):
        theirs = None
    # precision and depth cases have no pixels to show: their figure is the text alone
    panels = [(p, t) for p, t in ((ours, "ours"), (theirs, "naive")) if p is not None]
    plt = _pyplot()
    with use_style(args.style):
        import matplotlib as mpl

        h, w = panels[0][0].shape if panels else (1, 1)
        vertical = w > 3 * h  # wide strips (slivers) are stacked to keep their pixels visible
        if vertical:
            pw = 12.0
            ph = pw * h / w
            fig_w = pw + 2.8
            panels_h = len(panels) * (ph + 1.5)
        else:
            ph = 6.5 if h >= w else 6.5 * h / w
            pw = ph * w / h
            fig_w = max(1.0 + len(panels) * (pw + 0.9) + 0.7, 12.0)
            panels_h = ph + 1.5
        if not panels:
            fig_w, panels_h = 14.0, 0.0
        # Text size and wrap width in inches: monospace glyphs are about 0.6 em wide.
        size = mpl.font_manager.FontProperties(size="small").get_size_in_points()
        chars = int((fig_w - 0.5) * 72 / (0.6 * size))
        text = [f"hard case: {case.name} ({case.kind})", ""]
        text += [textwrap.fill(line, chars, subsequent_indent=" " * 8) for line in lines]
        text = "\n".join(text)
        text_h = (text.count("\n") + 1) * size * 1.3 / 72 + 0.3
        fig = plt.figure(figsize=(fig_w, text_h + panels_h))
        fig.text(
            0.15 / fig_w,
            1 - 0.15 / fig.get_figheight(),
            text,
            va="top",
            ha="left",
            family="monospace",
            fontsize=size,
            linespacing=1.3,
        )
        if panels:
            _count_panels(
                fig,
                panels,
                top_in=text_h + 1.2,
                pw=pw,
                ph=ph,
                triangles=case.triangles,
                vertical=vertical,
            )
        try:
            fig.savefig(args.output, dpi=_dpi(args))
        finally:
            plt.close(fig)
    _say(f"{case.name} ({case.kind})")
    for line in lines:
        _say(line)
    _say(f"wrote {args.output}")
    return 0


def cmd_list(args, parser) -> int:
    """Print the built-in scenes and hard cases, one a line with what they teach."""
    from ..pipeline.scenes import SCENES
    from ..study.hardcases import CASES

    _say("scenes (teachraster scene NAME -o out.png):")
    for name, make in SCENES.items():
        _say(f"  {name:<26} {make().description}")
    _say("")
    _say("hard cases (teachraster case NAME -o out.png):")
    for name, case in CASES.items():
        naive = ", vs naive" if case.has_naive else ""
        _say(f"  {name:<32} [{case.kind}{naive}] {case.why}")
    return 0


COMMANDS = {
    "fill": cmd_fill,
    "compare": cmd_compare,
    "scene": cmd_scene,
    "case": cmd_case,
    "list": cmd_list,
}


def main(argv: list[str] | None = None) -> int:
    """Run ``teachraster`` with ``argv`` (default ``sys.argv[1:]``); return the exit status.

    Bad arguments exit with status 2 and an argparse message naming the option; a failure
    while writing returns 1 with a one-line message, never a traceback.
    """
    parser = build_parser()
    args = parser.parse_args(argv)
    sub = args.parser
    if _needs_ffmpeg(args) and not ffmpeg_available():
        sub.error(
            "argument -o/--output: writing .mp4 needs ffmpeg, which is not on PATH; install "
            "it (Debian/Ubuntu: sudo apt-get install ffmpeg) or write a .gif instead"
        )
    try:
        return COMMANDS[args.command](args, sub)
    except ValueError as exc:  # the core's input checks (e.g. a degenerate sweep) name the input
        sub.error(str(exc))
    except BrokenPipeError:
        # stdout closed early (``teachraster list | head``): stop quietly, as Unix tools do
        sys.stdout = open(os.devnull, "w")  # flushing at exit must not fail
        return 0
    except OSError as exc:
        print(f"teachraster {args.command}: error: {exc}", file=sys.stderr)
        return 1


def _needs_ffmpeg(args) -> bool:
    out = getattr(args, "output", None)
    return out is not None and out.suffix.lower() == ".mp4"


if __name__ == "__main__":
    sys.exit(main())
