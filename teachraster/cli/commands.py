"""The sub-commands: fill, compare, scene, case and list."""

from __future__ import annotations

import numpy as np

from . import course
from .arguments import parse_attr
from .export import (
    animate_from_args,
    check_export_time,
    check_fill_size,
    fill_from_args,
    format_values,
    is_animation,
    output_dpi,
    pyplot,
    say,
    triangle_from_args,
    write_fill_page,
)


# -- commands ----------------------------------------------------------------------------------
def cmd_fill(args, parser) -> int:
    """Animate a fill step by step with :class:`FillView`, or save one step as a PNG."""
    from ..plotting import FillView, use_style

    if args.step is not None and is_animation(args):
        parser.error("argument --step: a .gif/.mp4 animates every step; --step is for a .png")
    check_fill_size(args, parser)
    fill = fill_from_args(args, triangle_from_args(args))
    n = len(fill.trace)
    if args.step is not None and not -n <= args.step < n:
        parser.error(f"argument --step: this fill has steps 0..{n - 1}, got {args.step}")
    if args.output.suffix.lower() == ".html":
        steps = write_fill_page(args, fill)
        say(f"wrote {args.output}: {steps} steps that step and play offline in a browser")
        return 0
    plt = pyplot()
    with use_style(args.style):
        view = FillView(fill, step=0 if is_animation(args) else args.step)
        try:
            if is_animation(args):
                steps = list(range(0, n, args.every))
                if steps[-1] != n - 1:
                    steps.append(n - 1)  # always end on the finished fill
                check_export_time(view, steps, args, parser)
                count = animate_from_args(
                    view.fig, steps, lambda k: view.show_step(k, draw=False), args
                )
                say(f"wrote {args.output}: {len(steps)} of {n} steps, {count} frames")
            else:
                view.fig.savefig(args.output, dpi=output_dpi(args))
                say(f"wrote {args.output}: step {view.step} of {n - 1}")
        finally:
            plt.close(view.fig)
    return 0


def cmd_compare(args, parser) -> int:
    """Affine vs perspective-correct values and their error (:class:`InterpolationView`)."""
    from ..core.triangle import Triangle
    from ..plotting import InterpolationView, use_style

    tri = triangle_from_args(args, attrs_default=[parse_attr("u=0,1,0")])
    name = args.show if args.show is not None else next(iter(tri.attrs))
    if name not in tri.attrs:
        parser.error(f"argument --show: no attribute {name!r}; given: {', '.join(tri.attrs)}")
    animated = is_animation(args)
    if args.sweep_w is not None and not animated:
        parser.error("argument --sweep-w: sweeps are animations; write a .gif or .mp4")
    values = np.asarray(tri.attrs[name])
    # A fixed colour range for the values: the sweep changes w, not the vertex values, so
    # every frame's colours then mean the same numbers.
    lo, hi = float(values.min()), float(values.max())
    lo, hi = (lo, hi) if hi > lo else (lo - 0.5, hi + 0.5)
    plt = pyplot()
    with use_style(args.style):
        view = InterpolationView(fill_from_args(args, tri), name, vmin=lo, vmax=hi)
        fig = view.fig
        # the depths are what the error depends on: say them above the panels
        header = fig.text(0.5, 0.995, f"w = ({format_values(tri.w)})", ha="center", va="top")
        try:
            if animated:
                a, b = args.sweep_w or (1.0, 8.0)
                base = tri.w.copy()

                def update(w_k: float) -> None:
                    w = base.copy()
                    w[args.vertex] = w_k
                    view.update(
                        fill_from_args(args, Triangle(tri.xy, w=w, attrs=tri.attrs)), draw=False
                    )
                    header.set_text(
                        f"w = ({format_values(w)}): moving the depth of v{args.vertex + 1}"
                    )

                frames = np.linspace(a, b, args.frames)
                count = animate_from_args(fig, frames, update, args)
                say(f"wrote {args.output}: w{args.vertex + 1} from {a:g} to {b:g}, {count} frames")
            else:
                fig.savefig(args.output, dpi=output_dpi(args))
                say(f"wrote {args.output}: max |affine - perspective| = {view.maximum:.3g}")
        finally:
            plt.close(fig)
    return 0


def cmd_scene(args, parser) -> int:
    """Render a built-in scene, save its image (or the comparison) and print its plan."""
    from ..pipeline.rendering.render_scenes import render_scene
    from ..pipeline.rendering.scenes import get_scene
    from ..plotting import ComparisonView, format_plan, plot_image, use_style
    from ..plotting.common import fs

    scene = get_scene(args.name)
    width, height = args.size
    frame = render_scene(scene, width=width, height=height, interpolation=args.interpolation)
    textured = scene.shading == "texture" and scene.texture is not None
    plt = pyplot()
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
                from ..pipeline.texturing.texture import texel_error

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
            fig.savefig(args.output, dpi=output_dpi(args))
        finally:
            plt.close(fig)
    say(f"{scene.name}: {scene.description}")
    if args.compare:
        what = "texel error" if textured else "|affine - perspective|"
        say(f"max {what} = {view.maximum:.3g}")
    say(format_plan(frame))
    say(f"wrote {args.output}")
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
    from ..plotting.common import fs
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
    plt = pyplot()
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
            fig.savefig(args.output, dpi=output_dpi(args))
        finally:
            plt.close(fig)
    say(f"{case.name} ({case.kind})")
    for line in lines:
        say(line)
    say(f"wrote {args.output}")
    return 0


def cmd_list(args, parser) -> int:
    """Print the built-in scenes and hard cases, one a line with what they teach."""
    from ..pipeline.rendering.scenes import SCENES
    from ..study.hardcases import CASES

    say("scenes (teachraster scene NAME -o out.png):")
    for name, make in SCENES.items():
        say(f"  {name:<26} {make().description}")
    say("")
    say("hard cases (teachraster case NAME -o out.png):")
    for name, case in CASES.items():
        naive = ", vs naive" if case.has_naive else ""
        say(f"  {name:<32} [{case.kind}{naive}] {case.why}")
    return 0


def cmd_html(args, parser) -> int:
    """Execute lessons and write each as one self-contained HTML page; say, per lesson, how
    many widgets are live, pictured or missing in it."""
    from .lesson_pages import export_notebook_html

    notebooks = args.notebook
    for nb in notebooks:
        if not nb.is_file():
            parser.error(f"argument NOTEBOOK: no file {str(nb)!r}")
    several = len(notebooks) > 1 or args.output.is_dir()
    if several:
        if args.output.suffix.lower() == ".html":
            parser.error("argument -o/--output: several notebooks are written into a folder")
        args.output.mkdir(parents=True, exist_ok=True)
    for nb in notebooks:
        out = args.output / f"{nb.stem}.html" if several else args.output
        page = export_notebook_html(nb, out, timeout=args.timeout, quiet=args.quiet)
        if not args.quiet:
            say(page.summary())
    return 0


COMMANDS = {
    "fill": cmd_fill,
    "html": cmd_html,
    "compare": cmd_compare,
    "scene": cmd_scene,
    "case": cmd_case,
    "list": cmd_list,
    **course.COMMANDS,  # lessons, student-version, nbgrader (teachraster/cli/course.py)
}
