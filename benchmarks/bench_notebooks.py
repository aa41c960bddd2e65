"""Is the course light enough for a class? Peak kernel memory and run time of every notebook.

Run from anywhere (the repository root is put on ``sys.path``)::

    python benchmarks/bench_notebooks.py                 # every lesson and exercise notebook
    python benchmarks/bench_notebooks.py --only 09 10    # notebooks whose name contains 09 or 10
    python benchmarks/bench_notebooks.py --quick         # smoke run: one small notebook
    python benchmarks/bench_notebooks.py --server-gib 24 # the server size for the class count

Each notebook runs top to bottom in a fresh ``python3`` kernel with nbclient, as a student's
"Run all" does, with the working directory its own folder. Measured per notebook:

- **peak MiB**: the kernel process's peak resident memory (``VmHWM`` of ``/proc/self/status``
  after every cell, read by a probe the kernel loads at start-up, see :func:`probe_environment`;
  ``getrusage``'s ``ru_maxrss`` where there is no ``/proc``);
- **seconds**: the wall time of the whole run, kernel start-up included (``time.perf_counter``);
- **widest figure**: the widest figure drawn, in pixels (inches × dpi at drawing time), against
  :data:`teachraster.plotting.style.COLUMN_WIDTH_PX`.

The table ends with how many students a server holds when every student keeps the heaviest
notebook's kernel open (peak MiB, plus ``--overhead-mib`` for the notebook server and browser
session per student). Goals (informative, the exit status is non-zero only when a notebook
fails): each notebook ≤ 256 MiB and ≤ 10 s on a 2-core machine.

The probe is also how ``tests/test_figure_width.py`` measures every figure while the suite
executes the lessons: set the two variables :func:`probe_environment` returns before a kernel
starts, and read the log with :func:`read_probe`.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
for path in (ROOT, HERE):
    if str(path) not in sys.path:
        sys.path.insert(0, str(path))

NOTEBOOKS = ROOT / "notebooks"
GOAL_MIB, GOAL_S = 256, 10.0

#: Environment variable naming the JSON file the kernel-side probe writes after every cell.
PROBE_VARIABLE = "TEACHRASTER_NOTEBOOK_PROBE"

# Runs in the kernel at start-up (an IPython profile start-up file). Records the size of every
# figure when it is drawn (inline display, widget redraw, savefig: all go through Figure.draw,
# at the dpi of that output) and the process's peak memory after every cell.
PROBE_SOURCE = r"""
import functools as _functools, json as _json, os as _os, resource as _resource

def _teachraster_probe():
    log = _os.environ.get("TEACHRASTER_NOTEBOOK_PROBE")
    if not log:
        return
    import matplotlib.figure as mfigure

    state = {"figures": {}, "rss_mib": []}
    shell = get_ipython()
    original = mfigure.Figure.draw

    @_functools.wraps(original)
    def draw(self, renderer):
        width, height = (float(v) for v in self.get_size_inches() * self.dpi)
        key = str(id(self))
        old = state["figures"].get(key)
        if old is None or width > old["width"]:
            titles = [ax.get_title() for ax in self.axes if ax.get_title()]
            state["figures"][key] = {"cell": shell.execution_count, "width": width,
                                     "height": height, "titles": titles[:3],
                                     "label": self.get_label()}
        return original(self, renderer)

    mfigure.Figure.draw = draw

    def peak_kib():
        # VmHWM: this process's own peak (ru_maxrss would also count the memory of the process
        # that forked the kernel, kept across exec).
        try:
            with open("/proc/self/status") as fh:
                for line in fh:
                    if line.startswith("VmHWM:"):
                        return float(line.split()[1])
        except OSError:
            pass
        return float(_resource.getrusage(_resource.RUSAGE_SELF).ru_maxrss)

    def after_cell(result=None):
        state["rss_mib"].append(peak_kib() / 1024)
        with open(log, "w") as fh:
            _json.dump({"rss_mib": state["rss_mib"],
                        "figures": list(state["figures"].values())}, fh)

    shell.events.register("post_run_cell", after_cell)

_teachraster_probe()
del _teachraster_probe
"""


def probe_environment(directory: Path, log: Path) -> dict[str, str]:
    """Environment variables that make a new IPython kernel run the probe and write ``log``.

    Parameters
    ----------
    directory : Path
        An empty folder; it becomes the kernel's ``IPYTHONDIR`` and holds the start-up file.
    log : Path
        Where the probe writes its JSON after every cell.
    """
    startup = Path(directory) / "profile_default" / "startup"
    startup.mkdir(parents=True, exist_ok=True)
    (startup / "00-teachraster-probe.py").write_text(PROBE_SOURCE)
    return {"IPYTHONDIR": str(directory), PROBE_VARIABLE: str(log)}


def read_probe(log: Path) -> dict:
    """The probe's record: ``rss_mib`` (peak after each cell) and ``figures`` (one dict each)."""
    return json.loads(Path(log).read_text())


def notebook_paths(only: list[str] | None = None) -> list[Path]:
    """The lessons, then the exercise notebooks; with ``only``, those whose name contains one."""
    paths = sorted(NOTEBOOKS.glob("*.ipynb")) + sorted((NOTEBOOKS / "exercises").glob("*.ipynb"))
    if only:
        paths = [p for p in paths if any(key in p.name for key in only)]
    return paths


def run_notebook(path: Path, timeout: int = 600) -> dict:
    """Execute one notebook in a fresh kernel with the probe; return its measurements.

    Returns
    -------
    dict
        ``name``, ``seconds`` (wall time, kernel start included), ``peak_mib``, ``widest_px``
        and ``figures`` (the probe's list).
    """
    import nbformat
    from nbclient import NotebookClient

    nb = nbformat.read(path, as_version=4)
    with tempfile.TemporaryDirectory() as tmp:
        log = Path(tmp) / "probe.json"
        saved = {k: os.environ.get(k) for k in ("IPYTHONDIR", PROBE_VARIABLE, "MPLBACKEND")}
        os.environ.update(probe_environment(Path(tmp) / "ipython", log), MPLBACKEND="Agg")
        try:
            start = time.perf_counter()
            NotebookClient(nb, timeout=timeout, kernel_name="python3",
                           resources={"metadata": {"path": str(path.parent)}}).execute()  # fmt: skip
            seconds = time.perf_counter() - start
        finally:
            for key, value in saved.items():
                if value is None:
                    os.environ.pop(key, None)
                else:
                    os.environ[key] = value
        record = read_probe(log)
    figures = record["figures"]
    inside = path.resolve().is_relative_to(NOTEBOOKS)
    return {
        "name": path.resolve().relative_to(NOTEBOOKS).with_suffix("").as_posix()
        if inside
        else path.stem,
        "seconds": seconds,
        "peak_mib": max(record["rss_mib"]),
        "widest_px": max((f["width"] for f in figures), default=0.0),
        "figures": figures,
    }


def students_per_server(peak_mib: float, server_gib: float, overhead_mib: float) -> int:
    """How many students' kernels fit in ``server_gib`` if each needs peak + overhead MiB."""
    return int(server_gib * 1024 // (peak_mib + overhead_mib))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", nargs="*", help="run notebooks whose name contains one of these")
    parser.add_argument("--quick", action="store_true", help="smoke run: one small notebook")
    parser.add_argument("--server-gib", type=float, default=24.0, help="server memory (GiB)")
    parser.add_argument("--overhead-mib", type=float, default=40.0,
                        help="per-student memory beside the kernel (notebook server session)")  # fmt: skip
    args = parser.parse_args(argv)

    from teachraster.plotting.style import COLUMN_WIDTH_PX

    results, failed = [], []
    print(f"{'notebook':42s} {'peak MiB':>9s} {'seconds':>8s} {'widest px':>10s}  goals")
    only = args.only or (["02_span_split"] if args.quick else None)
    for path in notebook_paths(only):
        try:
            r = run_notebook(path)
        except Exception as exc:  # a failing notebook is reported, the others still run
            failed.append(path.name)
            print(f"{path.name:42s} FAILED: {type(exc).__name__}: {str(exc)[:200]}")
            continue
        results.append(r)
        verdict = [
            "mem ok" if r["peak_mib"] <= GOAL_MIB else f"mem > {GOAL_MIB}",
            "time ok" if r["seconds"] <= GOAL_S else f"time > {GOAL_S:g} s",
            "width ok" if r["widest_px"] <= COLUMN_WIDTH_PX else f"width > {COLUMN_WIDTH_PX}",
        ]
        print(f"{r['name']:42s} {r['peak_mib']:9.0f} {r['seconds']:8.1f} {r['widest_px']:10.0f}"
              f"  {', '.join(verdict)}")  # fmt: skip
    if results:
        worst = max(results, key=lambda r: r["peak_mib"])
        total = sum(r["seconds"] for r in results)
        n = students_per_server(worst["peak_mib"], args.server_gib, args.overhead_mib)
        print(f"\nall {len(results)} notebooks: {total:.0f} s in all; heaviest kernel "
              f"{worst['name']} at {worst['peak_mib']:.0f} MiB")  # fmt: skip
        print(f"a {args.server_gib:g} GiB server holds {n} students (each: heaviest kernel + "
              f"{args.overhead_mib:g} MiB)")  # fmt: skip
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
