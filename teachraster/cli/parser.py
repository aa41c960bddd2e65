"""The argument parser: one sub-command per classroom export."""

from __future__ import annotations

import argparse
from pathlib import Path

from . import course
from .arguments import (
    ANIMATION_DPI,
    PNG_DPI,
    output_type,
    parse_attr,
    parse_range,
    parse_size,
    parse_w,
    parse_xy,
    positive,
)


# -- the parser --------------------------------------------------------------------------------
def _add_triangle(p: argparse.ArgumentParser, *, attr_default: str | None) -> None:
    p.add_argument(
        "--xy",
        type=parse_xy,
        required=True,
        help='three vertices v1, v2, v3 in pixels, y down: "x1,y1 x2,y2 x3,y3"',
    )
    p.add_argument(
        "--w",
        type=parse_w,
        default=None,
        help='clip-space w (view depth) per vertex, "w1,w2,w3" (default 1,1,1)',
    )
    p.add_argument(
        "--attr",
        type=parse_attr,
        action="append",
        default=None,
        help="a vertex attribute NAME=f1,f2,f3, its values at v1, v2, v3 (repeatable)"
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
    _add_interpolation(p)


def _add_interpolation(p: argparse.ArgumentParser) -> None:
    """``--interpolation``, as fill, compare and scene take it."""
    p.add_argument(
        "--interpolation",
        choices=("perspective", "affine"),
        default="perspective",
        help="attribute interpolation (default perspective)",
    )


def _add_output(p: argparse.ArgumentParser, *, animated: bool, page: bool = False) -> None:
    formats = ".png, .gif or .mp4" if animated else ".png"
    formats += ", or .html (steps and plays offline)" if page else ""
    p.add_argument(
        "-o",
        "--output",
        type=output_type(animated, page),
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
        type=positive(int),
        default=None,
        help=f"resolution (default {PNG_DPI} for PNG, {ANIMATION_DPI} for animations)",
    )
    # the parser itself, so that checks after parsing can report "argument --opt: ..." too
    p.set_defaults(parser=p)
    if animated:
        p.add_argument(
            "--fps",
            type=positive(float),
            default=4.0,
            help="frames per second of an animation (default 4)",
        )
        p.add_argument(
            "--hold",
            type=positive(float, zero=True),
            default=1.5,
            help="seconds the last frame stays before the animation loops (1.5)",
        )
        p.add_argument("-q", "--quiet", action="store_true", help="no progress bar on stderr")


def build_parser() -> argparse.ArgumentParser:
    """The ``teachraster`` argument parser (subcommands fill, compare, scene, case, list)."""
    parser = argparse.ArgumentParser(
        prog="teachraster",
        description="Export triangle fills, interpolation comparisons, scenes and hard cases "
        "as PNG, GIF or MP4 for slides.",
        epilog="Run 'teachraster COMMAND -h' for the options of a command.",
    )
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for add in SUBCOMMANDS:
        add(sub)
    course.add_parsers(sub)  # lessons, student-version, nbgrader (teachraster/cli/course.py)
    return parser


def add_fill(sub) -> None:
    """``teachraster fill``: every step of one fill, or one step."""
    p = sub.add_parser(
        "fill",
        help="animate a fill step by step (or a still of one step)",
        description="Fill one triangle and export every step (.gif/.mp4), "
        "one step (.png; the finished fill unless --step), or a self-contained page "
        "that steps and plays through the fill in any browser, offline (.html).",
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
        type=positive(int),
        default=1,
        help="animate every N-th step (the last step is always shown)",
    )
    _add_output(p, animated=True, page=True)


def add_compare(sub) -> None:
    """``teachraster compare``: affine vs perspective-correct, still or swept."""
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
        help="the vertex whose w the sweep moves, by index from 0: 0 is v1, 1 v2, 2 v3 (default 2)",
    )
    p.add_argument(
        "--frames", type=positive(int), default=24, help="frames of the sweep (default 24)"
    )
    _add_output(p, animated=True)


def add_scene(sub) -> None:
    """``teachraster scene NAME``: a built-in scene through the whole pipeline."""
    from ..pipeline.rendering.scenes import SCENES

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
    _add_interpolation(p)
    p.add_argument(
        "--compare", action="store_true", help="affine | perspective-correct | error, side by side"
    )
    _add_output(p, animated=False)


def add_case(sub) -> None:
    """``teachraster case NAME``: a hard case, ours beside the naive rasteriser."""
    from ..study.hardcases import CASES  # numpy-only, like the rest of the core

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


def add_list(sub) -> None:
    """``teachraster list``: the built-in scenes and hard cases."""
    p = sub.add_parser(
        "list",
        help="list the built-in scenes and hard cases",
        description="List the built-in scenes and hard cases.",
    )
    p.set_defaults(parser=p)


#: The sub-commands, in the order ``teachraster -h`` lists them.
def add_html(sub) -> None:
    """``teachraster html``: lessons, executed, as whole pages that work offline."""
    p = sub.add_parser(
        "html",
        help="execute notebooks and write each as one self-contained HTML page",
        description="Execute each NOTEBOOK (in its folder) and convert it to one HTML page "
        "that needs no kernel and no network: formulas are rendered to MathML, players step "
        "and play, sliders move over pictures drawn at export, other widgets show their "
        "picture. Prints, per lesson, how many widgets are live, pictured or missing.",
    )
    p.add_argument("notebook", metavar="NOTEBOOK", type=Path, nargs="+",
                   help="the .ipynb to export")  # fmt: skip
    p.add_argument("-o", "--output", type=Path, required=True,
                   help="the .html to write, or a folder (one NAME.html per notebook)")  # fmt: skip
    p.add_argument("--timeout", type=positive(int), default=600,
                   help="seconds a cell may run (default 600)")  # fmt: skip
    p.add_argument("-q", "--quiet", action="store_true", help="print nothing but errors")
    p.set_defaults(parser=p)


SUBCOMMANDS = [add_fill, add_compare, add_scene, add_case, add_list, add_html]
