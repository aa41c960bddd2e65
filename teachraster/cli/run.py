"""``teachraster ARGS``: parse, check ffmpeg for MP4, dispatch, turn errors into messages."""

from __future__ import annotations

import os
import sys

from .commands import COMMANDS
from .export import ffmpeg_available
from .parser import build_parser


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
