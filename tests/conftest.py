"""Shared helpers: an independent exact reference rasteriser and triangle generators.

The reference below is written from CONVENTIONS.md alone, not from the package code:

- snap every coordinate to 1/2**bits px with round half to even, in exact rational arithmetic
  (``fractions.Fraction``; Python's ``round`` of a Fraction rounds half to even);
- orient the triangle so that ``E(v0, v1, v2) > 0``;
- a pixel centre is covered when every edge function is > 0, or == 0 on a top-left edge
  (``b.y < a.y`` or ``b.y == a.y and b.x > a.x``).

After snapping, every coordinate times ``2**(bits + 1)`` is an integer (pixel centres too), so
the reference evaluates the Fraction-exact edge functions with Python's unbounded integers,
which is exact and fast enough to check thousands of triangles.
"""

from __future__ import annotations

import itertools
import os
import sys
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, settings
from hypothesis import strategies as st

import teachraster as tr

# Property tests run on shared 2-core machines: no per-example deadline (a busy machine is
# not a bug) and no "too slow" health check. In CI (CI=true) the examples are derandomised,
# so a submission lands or fails on its own merits; locally each run explores new examples.
settings.register_profile(
    "teachraster",
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile("ci", parent=settings.get_profile("teachraster"), derandomize=True)
# The quick tier (``dev.py test --quick``): a quarter of the examples, for the edit loop.
settings.register_profile("quick", parent=settings.get_profile("teachraster"), max_examples=25)
if os.environ.get("TEACHRASTER_QUICK"):
    settings.load_profile("quick")
else:
    settings.load_profile("ci" if os.environ.get("CI") else "teachraster")

# Exercise 11's checker makes a kernel wait after 25 failing checks of one frame (a blind search,
# review r12): the suite fails thousands on purpose, in every worker and kernel it starts, so it
# counts none (test_broken_frames sets its own number where it tests the wait).
os.environ.setdefault("TEACHRASTER_CHECK_TRIES", "0")

# -- tiers ---------------------------------------------------------------------------------------
#: ``python3 dev.py test --quick`` sets this: the edit loop, without the tiers below.
QUICK = bool(os.environ.get("TEACHRASTER_QUICK"))
#: What a test needs beyond Python and numpy, each a marker (declared in pyproject.toml) that
#: the quick tier deselects. In the quick tier a test that starts one of these anyway fails
#: at once, naming the marker it lacks (see ``_quick_tier_starts_nothing_heavy``).
TIER_PROGRAMS = {
    "notebook": ("ipykernel_launcher", "ipykernel"),
    "browser": ("chromium", "playwright", "jupyter-lab", "jupyter-notebook", "jupyter_server"),
    "nbgrader": ("nbgrader",),
    "slow": (" -m venv", " -m pip", " wheel "),
}


def pytest_configure(config):
    """One folder per test run, shared by its xdist workers (they inherit the environment):
    the notebooks executed once per run keep their results there (``notebook_runs.py``)."""
    import tempfile

    if hasattr(config, "workerinput") or os.environ.get("TEACHRASTER_RUN_CACHE"):
        return  # a worker: the controller made the folder
    folder = tempfile.mkdtemp(prefix="teachraster-run-")
    os.environ["TEACHRASTER_RUN_CACHE"] = folder
    config._teachraster_run_cache = folder


def pytest_unconfigure(config):
    import shutil

    folder = getattr(config, "_teachraster_run_cache", None)
    if folder:
        shutil.rmtree(folder, ignore_errors=True)
        os.environ.pop("TEACHRASTER_RUN_CACHE", None)


#: The tiers in the order a run starts them: the longest first, so that no worker is left with
#: a long pole (an nbgrader round trip, a wheel built) while the other has finished.
HEAVY_FIRST = ("nbgrader", "slow", "browser", "notebook", "gl")


def _tier_rank(item) -> int:
    return next(
        (k for k, tier in enumerate(HEAVY_FIRST) if item.get_closest_marker(tier)),
        len(HEAVY_FIRST),
    )


def pytest_collection_modifyitems(config, items):
    """Modules of the heavy tiers first (a module keeps its tests together and in order, so its
    fixtures are set up once per worker). Expensive fixtures several workers need are built
    once per run: ``run_once.py`` (the nbgrader course, the wheel), ``notebook_runs.py``."""
    rank: dict = {}
    for item in items:
        rank[item.path] = min(rank.get(item.path, len(HEAVY_FIRST)), _tier_rank(item))
    items.sort(key=lambda item: rank[item.path])  # stable: collection order within a rank


def pytest_collection_finish(session):
    """What collection left alive (the libraries, the test modules, the collected items) is
    moved out of the collector's reach (``gc.freeze``): every full collection of the run walked
    it again (test_plotting + test_widgets in one process: 11.5 -> 8.3 s of collections, 91.7
    -> 89.0 s of CPU). Those objects are still freed when nothing refers to them; only cycles
    among them are never collected, and these live as long as the run anyway."""
    import gc

    gc.collect()
    gc.freeze()


@pytest.hookimpl(trylast=True)  # after the fixtures' own teardown (their pages close first)
def pytest_runtest_teardown(item, nextitem):
    """After the last browser or notebook test of a worker's run of them, stop its Playwright,
    JupyterLab and Chromium (``notebook_browser.stop``): the tests after them expect a thread
    with no event loop marked running. A later browser test starts them again."""
    if nextitem is not None and (
        nextitem.get_closest_marker("browser") or nextitem.get_closest_marker("notebook")
    ):
        return
    running = sys.modules.get("notebook_browser")
    if running is not None:
        running.stop()


def examples(n: int) -> int:
    """``max_examples`` for a hypothesis test: ``n`` in the full run, a quarter in the quick tier.

    >>> examples(200) in (50, 200)
    True
    """
    return max(5, n // 4) if QUICK else n


def sample(values, keep: int = 3) -> list:
    """The parameters a test runs over: all of them in the full run; in the quick tier every
    ``keep``-th, the first included (the same ones each time), so each test still runs.

    >>> len(sample(range(9))) in (3, 9)
    True
    """
    values = list(values)
    return values[::keep] if QUICK else values


def cases(n: int) -> int:
    """How many random cases a loop runs: ``n`` in the full run, a quarter in the quick tier
    (the same seeds, so the quick tier's cases are the full run's first ones).

    >>> cases(300) in (75, 300)
    True
    """
    return max(2, n // 4) if QUICK else n


def _tier_of(argv) -> str | None:
    line = (
        " " + " ".join(str(a) for a in (argv if isinstance(argv, (list, tuple)) else [argv])) + " "
    )
    for tier, needles in TIER_PROGRAMS.items():
        if any(needle in line for needle in needles):
            return tier
    return None


@pytest.fixture(autouse=True, scope="session")
def _quick_tier_starts_nothing_heavy():
    """In the quick tier, starting a kernel, a browser, nbgrader, a venv or OpenGL is an error
    that names the missing marker, so the quick tier stays quick as tests are added."""
    if not QUICK:
        yield
        return
    import subprocess

    real_init = subprocess.Popen.__init__

    def guarded_init(self, args, *rest, **kwargs):
        tier = _tier_of(args)
        if tier is not None:
            raise RuntimeError(
                f"this test starts {args!r}, which the quick tier does not run: "
                f"mark it @pytest.mark.{tier}"
            )
        real_init(self, args, *rest, **kwargs)

    subprocess.Popen.__init__ = guarded_init
    # no OpenGL context either (llvmpipe takes every core): the benchmarks' smoke runs and
    # gl_available's doctest see "not available", as on a machine without Mesa
    from teachraster.study import opengl

    opengl._STATE["status"] = (False, "the quick tier runs without OpenGL")
    try:
        yield
    finally:
        subprocess.Popen.__init__ = real_init


PERMUTATIONS = list(itertools.permutations(range(3)))
METHODS = ("halfplane", "span")
MODES = ("perspective", "affine")


# -- exact reference --------------------------------------------------------------------------
def snap_exact(value: float, bits: int = 8) -> Fraction:
    """``value`` snapped to the 1/2**bits grid, round half to even, as an exact Fraction."""
    scale = 2**bits
    return Fraction(round(Fraction(value) * scale), scale)


def snapped_vertices(xy, bits: int = 8) -> list[tuple[Fraction, Fraction]]:
    return [(snap_exact(float(x), bits), snap_exact(float(y), bits)) for x, y in np.asarray(xy)]


def edge_exact(a, b, p):
    """E(a, b, p) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x), in the operands' type."""
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def top_left(a, b) -> bool:
    """CONVENTIONS: the directed edge a→b (interior on its positive side) is top or left."""
    return b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])


def signed_area_exact(xy, bits: int = 8) -> Fraction:
    """Signed area of the snapped triangle, px², positive when clockwise on screen."""
    v = snapped_vertices(xy, bits)
    return edge_exact(v[0], v[1], v[2]) / 2


def reference_coverage(xy, width: int, height: int, bits: int = 8) -> np.ndarray:
    """(height, width) bool coverage by the top-left rule, decided exactly on the snapped grid."""
    scale = 2 ** (bits + 1)  # snapped coordinates and pixel centres are integers in these units
    v = [(int(x * scale), int(y * scale)) for x, y in snapped_vertices(xy, bits)]
    out = np.zeros((height, width), dtype=bool)
    area2 = edge_exact(v[0], v[1], v[2])
    if area2 == 0:
        return out
    if area2 < 0:
        v = [v[0], v[2], v[1]]
    edges = [(v[k], v[(k + 1) % 3]) for k in range(3)]
    biases = [0 if top_left(a, b) else 1 for a, b in edges]  # integer E: E >= bias
    half = scale // 2
    xs, ys = [p[0] for p in v], [p[1] for p in v]
    cols = [j for j in range(width) if min(xs) <= j * scale + half <= max(xs)]
    rows = [i for i in range(height) if min(ys) <= i * scale + half <= max(ys)]
    for i in rows:
        py = i * scale + half
        for j in cols:
            p = (j * scale + half, py)
            if all(edge_exact(a, b, p) >= bias for (a, b), bias in zip(edges, biases)):
                out[i, j] = True
    return out


def exact_barycentric(xy, point, bits: int = 8) -> tuple[Fraction, Fraction, Fraction]:
    """Screen-space barycentrics of ``point`` in the snapped triangle, as exact Fractions."""
    a, b, c = snapped_vertices(xy, bits)
    p = (Fraction(point[0]), Fraction(point[1]))
    area = edge_exact(a, b, c)
    return (edge_exact(b, c, p) / area, edge_exact(c, a, p) / area, edge_exact(a, b, p) / area)


def centres(coverage: np.ndarray):
    """Rows, cols and pixel-centre coordinates (x, y) of the covered pixels."""
    rows, cols = np.nonzero(coverage)
    return rows, cols, cols + 0.5, rows + 0.5


def raster(xy, width, height, **kwargs) -> np.ndarray:
    """Coverage of ``tr.rasterize`` for bare positions."""
    return tr.rasterize(tr.Triangle(xy), width, height, **kwargs).coverage


def explain(xy, got, want) -> str:
    """Failure message that makes a coverage mismatch reproducible."""
    diff = np.argwhere(got != want)
    return f"xy={np.asarray(xy).tolist()!r}: differs at (row, col) {diff[:8].tolist()}"


# -- triangle generators ----------------------------------------------------------------------
def random_triangles(rng: np.random.Generator, kind: str, n: int, width: int, height: int):
    """``n`` triangles (n, 3, 2) of one kind, spread a little beyond a width x height image.

    kinds: ``float`` (arbitrary doubles), ``centre`` (on pixel centres), ``subpixel`` (on the
    1/256 grid), ``tie`` (small half-integer grid: many edges through centres and corners),
    ``outside`` (partly outside the image), ``huge`` (larger than the image).
    """
    lo = np.array([-2.0, -2.0])
    hi = np.array([width + 2.0, height + 2.0])
    if kind == "float":
        return rng.uniform(lo, hi, size=(n, 3, 2))
    if kind == "centre":
        return rng.integers(lo, hi, size=(n, 3, 2)) + 0.5
    if kind == "subpixel":
        return rng.integers(lo * 256, hi * 256, size=(n, 3, 2)) / 256.0
    if kind == "tie":
        return rng.integers(0, 2 * 7, size=(n, 3, 2)) / 2.0
    if kind == "outside":
        return rng.uniform(-3 * hi, 3 * hi, size=(n, 3, 2))
    if kind == "huge":
        return rng.uniform(-100 * hi, 100 * hi, size=(n, 3, 2))
    raise ValueError(kind)


KINDS = ("float", "centre", "subpixel", "tie", "outside", "huge")


def triangles(coords: st.SearchStrategy) -> st.SearchStrategy:
    """Strategy for (3, 2) float arrays whose coordinates come from ``coords``."""
    return st.lists(st.tuples(coords, coords), min_size=3, max_size=3).map(
        lambda v: np.array(v, dtype=np.float64)
    )


def float_coords(lo: float = -3.0, hi: float = 15.0) -> st.SearchStrategy:
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False)


def centre_coords(lo: int = -2, hi: int = 14) -> st.SearchStrategy:
    return st.integers(lo, hi).map(lambda i: i + 0.5)


def subpixel_coords(lo: int = -2, hi: int = 14) -> st.SearchStrategy:
    return st.integers(lo * 256, hi * 256).map(lambda i: i / 256.0)


def tie_coords(n: int = 6) -> st.SearchStrategy:
    """Half-integers in [0, n]: pixel corners and centres, so edges hit centres constantly."""
    return st.integers(0, 2 * n).map(lambda i: i / 2.0)


any_triangle = st.one_of(
    triangles(float_coords()),
    triangles(centre_coords()),
    triangles(subpixel_coords()),
    triangles(tie_coords()),
)


@pytest.fixture
def rng():
    return np.random.default_rng(20240611)


@pytest.fixture(autouse=True)
def _matplotlib_backend_left_alone():
    """Importing ipympl (``pytest.importorskip("ipympl")``) makes it matplotlib's backend as
    a side effect: put the setting back after each test, so no test sees another's backend."""
    import sys

    mpl = sys.modules.get("matplotlib")
    raw = dict.__getitem__(mpl.rcParams, "backend") if mpl is not None else None
    yield
    if mpl is not None and dict.__getitem__(mpl.rcParams, "backend") != raw:
        dict.__setitem__(mpl.rcParams, "backend", raw)


def _tree_cpu() -> float:
    """CPU seconds of this process and everything it started (kernels, JupyterLab, Chromium,
    nbgrader), the ones still running and the ones already reaped; 0 without psutil."""
    try:
        import psutil
    except ImportError:
        return 0.0
    me, total = psutil.Process(), 0.0
    for proc in [me, *me.children(recursive=True)]:
        try:
            t = proc.cpu_times()
        except psutil.Error:  # ended while we looked
            continue
        total += t.user + t.system + t.children_user + t.children_system
    return total


def pytest_terminal_summary(terminalreporter):
    """Seconds per test file and per tier, summed over set-up, call and tear-down on every
    worker: where a run's time goes. The 20 slowest tests alone (``--durations``) left CI's
    1,200 s unexplained (stop 46): most of it is in files of many short tests."""
    per_file: dict = {}
    for reports in terminalreporter.stats.values():
        for rep in reports:
            nodeid, seconds = getattr(rep, "nodeid", None), getattr(rep, "duration", None)
            if nodeid and seconds:
                name = nodeid.split("::")[0]
                per_file[name] = per_file.get(name, 0.0) + seconds
    if len(per_file) < 10:
        return  # a run of a few files: the durations say it already
    total = sum(per_file.values())
    terminalreporter.write_sep("=", f"seconds per test file ({total:.0f} s on all workers)")
    for name, seconds in sorted(per_file.items(), key=lambda kv: -kv[1])[:30]:
        terminalreporter.write_line(f"{seconds:8.1f} s  {100 * seconds / total:4.1f} %  {name}")


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):
    """With TEACHRASTER_CPU_LOG set, append each test's CPU seconds (this process, set-up and
    tear-down included; ``tree``: with the processes it started), wall seconds, start time and
    worker to that file: what a test costs on a quiet machine,
    read on a busy one (``python3 dev.py test --quick`` with it set, then sum per file)."""
    log = os.environ.get("TEACHRASTER_CPU_LOG")
    if not log:
        yield
        return
    import json
    import time

    cpu, wall, tree, start = time.process_time(), time.perf_counter(), _tree_cpu(), time.time()
    yield
    row = {
        "test": item.nodeid,
        "cpu": time.process_time() - cpu,
        "wall": time.perf_counter() - wall,
        "tree": _tree_cpu() - tree,
        "start": start,
        "worker": os.environ.get("PYTEST_XDIST_WORKER", "main"),
    }
    with open(log, "a") as fh:
        fh.write(json.dumps(row) + "\n")


@pytest.fixture(autouse=True)
def _matplotlib_style_stays_in_its_test():
    """A test that sets a style for good (``use_style("classroom")`` outside a block) no longer
    leaks into the tests after it in the same worker: every test ends with the rcParams it
    started with. Twice a leak failed CI at random (an 18-pt font where a test expected the
    default), depending on which worker ran which test first."""
    mpl = sys.modules.get("matplotlib")
    saved = dict(mpl.rcParams) if mpl is not None else None
    yield
    if saved is not None:
        dict.update(mpl.rcParams, saved)  # as rc_context restores: the values were valid


@pytest.fixture(autouse=True)
def _checks_give_their_full_words():
    """Every test starts with the staged hints spent: a check's first explanation is the same
    whichever tests ran before it in this process (a corpus test failed in one order only).
    The hint tests call ``tries.forget_hints`` first."""
    from teachraster.exercises import checks, tries

    tries.spend_hints(n for n in checks.names() if checks.exercise(n).hints)
    tries.spend_hints(["a_buffer"])  # the capstone's glass_sorted stages its words too (r84)
    yield


@pytest.fixture
def plt():
    """matplotlib's pyplot on the Agg backend, every figure closed afterwards (the exercises'
    picture tests; a module may define its own)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    yield plt
    plt.close("all")
