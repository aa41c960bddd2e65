"""``python -m teachraster.study.bench``: run the study, print the table, write CSV and plots."""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from .measure import run
from .report import format_table, plot, write_csv


# -- command line -----------------------------------------------------------------------------
def main(argv: list[str] | None = None) -> int:
    """``python -m teachraster.study.bench [--quick] [--out DIR] [--repeat N] [--cpu]``."""
    parser = argparse.ArgumentParser(
        prog="python -m teachraster.study.bench",
        description="Accuracy vs time of teachraster's cheaper and costlier variants.",
    )
    parser.add_argument("--quick", action="store_true", help="small scenes: a smoke run")
    parser.add_argument("--out", default="bench-out", help="output directory (bench-out/)")
    parser.add_argument("--repeat", type=int, default=None, help="timed runs per variant")
    parser.add_argument("--no-plots", action="store_true", help="write the CSV only")
    parser.add_argument("--cpu", action="store_true",
                        help="time this process's CPU (waiting for a core not counted), not the wall")  # fmt: skip
    args = parser.parse_args(argv)
    if args.repeat is not None and args.repeat < 1:
        parser.error("--repeat must be >= 1")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    clock = time.process_time if args.cpu else time.perf_counter
    rows = run(args.quick, repeat=args.repeat, progress=True, clock=clock)
    print(format_table(rows))
    written = [write_csv(rows, out / "bench.csv")]
    if not args.no_plots:
        written += plot(rows, out)
    print("wrote " + ", ".join(str(p) for p in written))
    return 0
