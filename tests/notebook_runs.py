"""Each notebook executed once per test run, shared by every test (and every worker) that reads it.

A lesson is read by several tests: that it runs headless (``test_packaging.py``), the numbers
it quotes (``test_lessons*.py``), its figures' widths and its kernel's memory
(``test_figure_width.py``). :func:`executed` runs the notebook once, in a fresh kernel with the
probe of ``benchmarks/bench_notebooks.py`` loaded (figure sizes, memory after every cell) and a
last cell that pickles every global that can be pickled, and keeps the result: in this process
(``functools.cache``) and on disk for the other pytest-xdist workers of the same run, under a
file lock, so the second worker to ask waits for the first instead of running it again.

The disk cache lives in the run's shared folder (``TEACHRASTER_RUN_CACHE``, made by
``conftest.py`` for one pytest run and removed after it) and is keyed by the notebook's
content, so nothing stale is ever read.
"""

from __future__ import annotations

import fcntl
import functools
import hashlib
import html
import importlib.util
import json
import os
import pickle
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from types import SimpleNamespace

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOKS = ROOT / "notebooks"
#: The environment variable naming the run's shared cache folder.
CACHE_VARIABLE = "TEACHRASTER_RUN_CACHE"

# Runs inside the kernel after the notebook: every global that pickles, each on its own, so one
# unpicklable value (a widget, a figure) does not hide the others.
_DUMP = """
import pickle as _pickle, types as _types
_kept = {}
_SKIP = (_types.ModuleType, type, _types.FunctionType, _types.BuiltinFunctionType,
         _types.MethodType)
for _name, _value in list(globals().items()):
    if _name.startswith("_") or isinstance(_value, _SKIP):
        continue
    try:
        _kept[_name] = _pickle.dumps(_value)
    except Exception:
        pass
with open(__PATH__, "wb") as _fh:
    _pickle.dump(_kept, _fh)
"""


@dataclass(frozen=True)
class NotebookRun:
    """One execution of a notebook: what it printed and drew, its globals, its probe record."""

    name: str
    #: the executed notebook (nbformat JSON text: outputs included); ``notebook()`` parses it
    text: str
    #: every global of the kernel that pickled, each pickled on its own
    blobs: dict
    #: the probe: ``figures`` (one dict per figure drawn) and ``peak_mib`` (notebook cells only)
    probe: dict
    #: the error a failing cell raised (its traceback as text), or "" when every cell ran
    error: str
    seconds: float
    #: run in JupyterLab in Chromium (``notebook_browser``), not headless under nbclient
    in_browser: bool = False
    #: the figures (``img`` elements) on the page after Run All Cells (browser runs only)
    figures_on_page: int = 0
    #: errors the page raised while the notebook ran (browser runs only)
    page_errors: tuple = ()

    def notebook(self):
        import nbformat

        return nbformat.reads(self.text, as_version=4)

    @functools.cached_property
    def globals(self) -> SimpleNamespace:
        """The picklable globals as a namespace (a value whose class the notebook defined is
        left out: it cannot be unpickled here)."""
        values = {}
        for key, blob in self.blobs.items():
            try:
                values[key] = pickle.loads(blob)
            except Exception:
                continue
        return SimpleNamespace(**values)


def _bench():
    name = "bench_notebooks"
    if name not in sys.modules:
        spec = importlib.util.spec_from_file_location(name, ROOT / "benchmarks" / f"{name}.py")
        module = importlib.util.module_from_spec(spec)
        sys.modules[name] = module
        spec.loader.exec_module(module)
    return sys.modules[name]


def _path(name: str) -> Path:
    return NOTEBOOKS / f"{name}.ipynb"


def _probe(record: dict, error: str) -> dict:
    """The probe's figures and peak memory; the last cell (the dump) is the test's, so its
    memory is left out unless a cell failed before it."""
    peak = max(record["rss_mib"][:-1] or [0.0]) if not error else max(record["rss_mib"] or [0])
    return {"figures": record["figures"], "peak_mib": peak}


def in_browser() -> bool:
    """Whether notebooks run in the browser in this test run: in the full run wherever Chromium,
    Playwright and JupyterLab are here (CI requires them), so each notebook runs once, as a
    student runs it; headless under nbclient otherwise (the quick tier never runs notebooks)."""
    import notebook_browser

    if os.environ.get("TEACHRASTER_QUICK") or os.environ.get("TEACHRASTER_HEADLESS_NOTEBOOKS"):
        return False
    return notebook_browser.unavailable() is None


def _run_in_browser(name: str) -> NotebookRun:
    import notebook_browser

    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "globals.pickle"
        run = notebook_browser.run_all(name, _DUMP.replace("__PATH__", repr(str(out))))
        blobs = pickle.loads(out.read_bytes()) if out.exists() else {}
    probe = _probe(run.probe_record or {"figures": [], "rss_mib": [0.0]}, run.error)
    return NotebookRun(
        name, run.text, blobs, probe, run.error, run.seconds, True, run.figures, run.page_errors
    )


def _run(name: str) -> NotebookRun:
    if in_browser():
        return _run_in_browser(name)
    import nbformat
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError

    bench = _bench()
    path = _path(name)
    nb = nbformat.read(path, as_version=4)
    with tempfile.TemporaryDirectory() as tmp:
        out, log = Path(tmp) / "globals.pickle", Path(tmp) / "probe.json"
        nb.cells.append(nbformat.v4.new_code_cell(_DUMP.replace("__PATH__", repr(str(out)))))
        env = {**os.environ, "MPLBACKEND": "Agg"}
        env.update(bench.probe_environment(Path(tmp) / "ipython", log))
        client = NotebookClient(
            nb, timeout=600, kernel_name="python3",
            resources={"metadata": {"path": str(path.parent)}},
        )  # fmt: skip
        start, error = time.perf_counter(), ""
        try:
            client.execute(env=env)
        except CellExecutionError as exc:
            error = str(exc)
        seconds = time.perf_counter() - start
        blobs = pickle.loads(out.read_bytes()) if out.exists() else {}
        record = bench.read_probe(log) if log.exists() else {"figures": [], "rss_mib": [0.0]}
    nb.cells.pop()  # the dump cell is the test's, not the notebook's
    probe = _probe(record, error)
    return NotebookRun(name, nbformat.writes(nb), blobs, probe, error, seconds)


def _cache_dir() -> Path | None:
    folder = os.environ.get(CACHE_VARIABLE)
    return Path(folder) if folder else None


@functools.cache
def executed(name: str) -> NotebookRun:
    """Notebook ``name`` (relative to ``notebooks/``, no suffix), executed once per test run.

    A failing cell does not raise here: the run keeps its error, and each test decides
    (``executed(name).error``, or :func:`lesson`, which raises it).
    """
    folder = _cache_dir()
    if folder is None:
        return _run(name)
    digest = hashlib.sha256(_path(name).read_bytes()).hexdigest()[:16]
    stem = folder / f"{name.replace('/', '__')}-{digest}"
    with open(f"{stem}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # a second worker waits here for the first's run
        try:
            if Path(f"{stem}.pickle").exists():
                return pickle.loads(Path(f"{stem}.pickle").read_bytes())
            run = _run(name)
            Path(f"{stem}.tmp").write_bytes(pickle.dumps(run))
            os.replace(f"{stem}.tmp", f"{stem}.pickle")
            return run
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


def lesson(name: str) -> SimpleNamespace:
    """The globals of lesson ``name`` after it ran top to bottom; its error if a cell failed."""
    run = executed(name)
    if run.error:
        raise AssertionError(f"{name} failed to run:\n{run.error}")
    return run.globals


def streams(nb) -> str:
    """Everything the notebook's code cells printed."""
    return "".join(
        out.get("text", "")
        for cell in nb.cells
        if cell.cell_type == "code"
        for out in cell.outputs
        if out.get("output_type") == "stream"
    )


def printed_and_folded(nb) -> str:
    """What :func:`streams` gives, then the lines folded under ``<details>`` (lesson 06's
    ``study.bench.tables.folded``), unescaped: every line a cell prints, shown or one click
    away."""
    folded = []
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        for out in cell.outputs:
            page = out.get("data", {}).get("text/html", "")
            page = "".join(page) if isinstance(page, list) else page
            if page.startswith("<details>") and "<pre>" in page:
                body = page.split("<pre>", 1)[1].rsplit("</pre>", 1)[0]
                folded.append(html.unescape(body) + "\n")
    return streams(nb) + "".join(folded)


def summary(run: NotebookRun) -> str:
    """One line for a failing test's message."""
    return json.dumps(
        {"name": run.name, "seconds": round(run.seconds, 1), "error": run.error[:200]}
    )
