"""Every figure of every notebook fits the notebook column, and every kernel is light enough.

A figure wider than :data:`teachraster.plotting.style.COLUMN_WIDTH_PX` is shrunk to the column
by the browser, and its text with it: the classroom style's large fonts end up small. The size
that counts is the one the figure is drawn at (inches × dpi, measured when it is drawn: inline
output, widget redraws and saved GIFs alike). The kernel-side probe of
``benchmarks/bench_notebooks.py`` records it, with the kernel's peak memory after every cell.

The lessons are executed through ``tests/test_lessons.py``'s cached ``lesson()``, with the probe
switched on by environment variables, so the suite runs each lesson once for both files (this
module sorts first). Exercise notebooks run here, in their own folder.
"""

from __future__ import annotations

import functools
import importlib.util
import os
import sys
import tempfile
from pathlib import Path

import pytest

from teachraster.plotting.style import COLUMN_WIDTH_PX

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOKS = ROOT / "notebooks"
#: Ceiling on a kernel's peak resident memory: generous (the goal is 256 MiB, see the benchmark).
MEMORY_CEILING_MIB = 400


def _load(name: str, path: Path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


bench = _load("bench_notebooks", ROOT / "benchmarks" / "bench_notebooks.py")
LESSONS = [p.stem for p in sorted(NOTEBOOKS.glob("*.ipynb"))]
EXERCISES = [f"exercises/{p.stem}" for p in sorted((NOTEBOOKS / "exercises").glob("*.ipynb"))]

#: Notebooks whose figures are being narrowed on another branch: their width test is an
#: expected failure until it is merged (a name whose figures already fit is reported as XPASS).
PENDING_ELSEWHERE: set[str] = set()


@functools.cache
def probed(name: str) -> dict:
    """Execute notebook ``name`` (relative to notebooks/, no suffix) once with the probe on."""
    if name.startswith("exercises/"):
        return bench.run_notebook(NOTEBOOKS / f"{name}.ipynb")
    lessons_module = sys.modules.get("test_lessons") or _load(
        "test_lessons", ROOT / "tests" / "test_lessons.py"
    )
    with tempfile.TemporaryDirectory() as tmp:
        log = Path(tmp) / "probe.json"
        env = bench.probe_environment(Path(tmp) / "ipython", log)
        saved = {k: os.environ.get(k) for k in env}
        os.environ.update(env)
        try:
            lessons_module.lesson(name)  # cached: test_lessons.py reuses this execution
            if not log.exists():  # it ran earlier in this process, without the probe
                lessons_module.lesson.__wrapped__(name)
        finally:
            for key, value in saved.items():
                if value is None:
                    os.environ.pop(key, None)
                else:
                    os.environ[key] = value
        record = bench.read_probe(log)
    # lesson() appends a cell that pickles the globals: its memory is the test's, not the class's
    return {"figures": record["figures"], "peak_mib": max(record["rss_mib"][:-1] or [0.0])}


#: Widget figures being narrowed on another branch, by the titles of their panels: their
#: width is reported, not failed, until it is merged.
PENDING_WIDGETS: dict[tuple[str, ...], str] = {}


def _pending(figure: dict) -> bool:
    return any(tuple(figure["titles"][: len(t)]) == t for t in PENDING_WIDGETS)


def _marks(name: str):
    if name in PENDING_ELSEWHERE:
        return [pytest.mark.xfail(reason="figures being narrowed on another branch", strict=False)]
    return []


@pytest.mark.parametrize(
    "name", [pytest.param(n, marks=_marks(n)) for n in LESSONS + EXERCISES]
)  # fmt: skip
def test_every_figure_fits_the_notebook_column(name):
    figures = probed(name)["figures"]
    too_wide = [f for f in figures if round(f["width"]) > COLUMN_WIDTH_PX and not _pending(f)]
    assert not too_wide, f"{name}: " + "; ".join(
        f"cell {f['cell']} {f['width']:.0f}x{f['height']:.0f} px {f['titles'][:2]}"
        for f in too_wide
    )


@pytest.mark.parametrize("name", LESSONS + EXERCISES)
def test_every_kernel_stays_under_the_memory_ceiling(name):
    peak = probed(name)["peak_mib"]
    assert 0 < peak <= MEMORY_CEILING_MIB, f"{name}: peak {peak:.0f} MiB"


def test_the_probe_sees_a_figure_drawn_at_its_dpi(tmp_path):
    # A tiny notebook: one figure 5 in x 100 dpi wide, one 12 in x 50 dpi (a saved GIF's size).
    import nbformat

    nb = nbformat.v4.new_notebook()
    nb.cells = [
        nbformat.v4.new_code_cell(
            "%matplotlib inline\nimport matplotlib.pyplot as plt\n"
            "fig, ax = plt.subplots(figsize=(5, 2), dpi=100)\nax.set_title('five')\nplt.show()"
        ),
        nbformat.v4.new_code_cell(
            "fig = plt.figure(figsize=(12, 2))\nfig.savefig('x.png', dpi=50)\nplt.close(fig)"
        ),
    ]
    path = tmp_path / "probe_check.ipynb"
    nbformat.write(nb, path)
    r = bench.run_notebook(path)
    widths = sorted(round(f["width"]) for f in r["figures"])
    assert widths == [500, 600] and r["peak_mib"] > 20
    assert any(f["titles"] == ["five"] for f in r["figures"])
