#!/usr/bin/env python3
"""Developer commands for teachraster. Standard library only, so it runs on a fresh machine.

    python3 dev.py lab  [jupyter lab args...]   # e.g. --no-browser
    python3 dev.py test [pytest args...]        # everything CI runs, e.g. -k packaging
    python3 dev.py test --quick [pytest args]   # the edit loop: no browser, kernel, nbgrader,
                                                # OpenGL, build or benchmark (a few minutes)

Both create ./.venv if needed and `pip install -e` the project with the right extra. The
install is skipped when pyproject.toml has not changed since the last one (a stamp file
inside .venv records its hash).
"""

import hashlib
import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent
VENV = ROOT / ".venv"
BIN = VENV / ("Scripts" if os.name == "nt" else "bin")
PYTHON = BIN / ("python.exe" if os.name == "nt" else "python")
STAMP = VENV / "teachraster-install.json"

# Which installed extras satisfy each request (dev = lab + test).
SATISFIES = {"lab": ("lab", "dev"), "dev": ("dev",)}


def run(cmd, **kwargs):
    print("+ " + " ".join(str(c) for c in cmd), flush=True)
    return subprocess.run([str(c) for c in cmd], cwd=ROOT, **kwargs).returncode


def check(cmd):
    if run(cmd) != 0:
        sys.exit(f"dev.py: command failed: {' '.join(str(c) for c in cmd)}")


def ensure_venv(extra):
    """Create .venv and install the project with `extra`, unless that is already done."""
    if sys.version_info < (3, 10):  # noqa: UP036 (dev.py may run on any python3)
        sys.exit(f"dev.py: teachraster needs Python >= 3.10, this is {sys.version.split()[0]}")
    if not PYTHON.exists():
        print(f"dev.py: creating {VENV.name}/ with {sys.executable}", flush=True)
        check([sys.executable, "-m", "venv", VENV])
        check([PYTHON, "-m", "pip", "install", "--quiet", "--upgrade", "pip"])
    digest = hashlib.sha256((ROOT / "pyproject.toml").read_bytes()).hexdigest()
    stamps = json.loads(STAMP.read_text()) if STAMP.exists() else {}
    if any(stamps.get(e) == digest for e in SATISFIES[extra]):
        print(f"dev.py: .venv is up to date with pyproject.toml ([{extra}])", flush=True)
        return
    print(f"dev.py: installing teachraster[{extra}] into .venv (takes a minute)", flush=True)
    check([PYTHON, "-m", "pip", "install", "--disable-pip-version-check", "-e", f".[{extra}]"])
    stamps[extra] = digest
    STAMP.write_text(json.dumps(stamps, indent=1))


def lab(args):
    ensure_venv("lab")
    cmd = [str(PYTHON), "-m", "jupyter", "lab", "notebooks/", *args]
    if hasattr(os, "geteuid") and os.geteuid() == 0 and "--allow-root" not in args:
        cmd.append("--allow-root")  # containers and CI machines often run as root
    print("+ " + " ".join(cmd), flush=True)
    if os.name == "nt":
        sys.exit(subprocess.call(cmd, cwd=ROOT))
    os.execv(cmd[0], cmd)  # hand the terminal (and Ctrl-C) to JupyterLab


#: The markers of the tiers the quick run leaves out (declared in pyproject.toml).
HEAVY_TIERS = ("notebook", "browser", "nbgrader", "gl", "slow", "bench")


def pytest_args(args):
    """pytest's arguments: in parallel on every core unless asked otherwise; ``--quick``
    deselects the heavy tiers and tells the tests so (fewer hypothesis examples)."""
    args = list(args)
    # One worker per core, at least two (many tests wait on a kernel or a browser). A third
    # worker on this 2-core machine was measured (fresh-clone CI, 2026-12-02): 817 s against
    # 824 s with two, for 11 % more CPU; not worth the load.
    workers = max(2, os.cpu_count() or 1)
    if "--quick" in args:
        args.remove("--quick")
        os.environ["TEACHRASTER_QUICK"] = "1"
        args = ["-m", " and ".join(f"not {t}" for t in HEAVY_TIERS), *args]
    if not any(a == "-n" or a.startswith(("-n=", "--numprocesses", "-p no:xdist")) for a in args):
        # Tests go out two at a time in collection order (heavy tiers first, conftest), so
        # the heavy tiers are shared by every worker: by default xdist hands each worker a
        # quarter of its share at once (551 consecutive tests here), which gave one worker
        # every browser, nbgrader and notebook test (740 s of them on one worker, measured).
        # What several workers need is built once per run (run_once.py, notebook_runs.py).
        args = ["-n", str(workers), "--dist", "load", "--maxschedchunk", "2", *args]
    if not any(a.startswith("--durations") for a in args):
        # the 20 slowest tests in every log: a CI run that took 36 min where the one before
        # took 12 (stop 42) left no clue which tests grew
        args = ["--durations=20", *args]
    return args


#: Run beside ruff, in two processes (half the files each), before pytest: what every pytest
#: worker would otherwise do at once on a fresh clone, each for itself, as it collects. It
#: rewrites the asserts of the test modules with pytest's own rewriter into the pyc files
#: pytest reads back (keyed by the source's hash, so a stale one is never used; pytest's
#: private API: where it differs, nothing is done and the workers rewrite as before) and
#: compiles the package and the test helpers. Measured on a fresh copy: 11.8 s of CPU once,
#: after which a collection took 6.9 s of CPU instead of 27.5 (about 30 s less a run with
#: two workers). Never fails the run.
PREWARM = r"""
import compileall, sys
from pathlib import Path
part, parts = int(sys.argv[1]), int(sys.argv[2])
try:
    from _pytest.assertion.rewrite import (
        PYC_TAIL, _rewrite_test, _write_pyc, get_cache_dir, try_makedirs)
except ImportError:
    sys.exit(0)
if sys.dont_write_bytecode:
    sys.exit(0)
class State:
    def trace(self, *args):
        pass
tests = Path("tests").resolve()
files = sorted(tests.glob("test_*.py"), key=lambda f: -f.stat().st_size)
for f in [*files, tests / "conftest.py"][part::parts]:
    try:
        source_hash, co = _rewrite_test(f, None)
        folder = get_cache_dir(f)
        if try_makedirs(folder):
            _write_pyc(State(), co, source_hash, folder / (f.name[:-3] + PYC_TAIL))
    except Exception:
        pass
if part == 0:
    compileall.compile_dir("teachraster", quiet=2)
    compileall.compile_dir("tests", quiet=2, maxlevels=0)
"""


def prewarm():
    """Start :data:`PREWARM`'s processes; returns them (waited for by :func:`test`)."""
    parts = 2
    try:
        return [
            subprocess.Popen(
                [str(PYTHON), "-c", PREWARM, str(k), str(parts)],
                cwd=ROOT,
                stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL,
            )
            for k in range(parts)
        ]
    except OSError:
        return []


def test(args):
    ensure_venv("dev")
    os.environ.setdefault("MPLBACKEND", "Agg")  # doctests and tests never open windows
    # A run starts a hundred Python processes (kernels, nbgrader, the CLI) and a pytest
    # worker per core: with PYTHONDONTWRITEBYTECODE (set on some machines, this one too)
    # each compiles teachraster again and each worker rewrites every test module's asserts
    # (16 s of CPU a worker where cached ones take 7); the caches go to __pycache__/, ignored.
    os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
    # One BLAS thread per process: the workers already use every core, and OpenBLAS's extra
    # threads spin while they wait (test_plotting: 16 % less CPU with one, measured here).
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    steps = {
        "ruff check": [PYTHON, "-m", "ruff", "check", "."],
        "ruff format": [PYTHON, "-m", "ruff", "format", "--check", "."],
        # last, so its summary closes the output
        "pytest": [PYTHON, "-m", "pytest", *pytest_args(args)],
    }
    warming = prewarm()
    failed = []
    for name, cmd in steps.items():
        if name == "pytest":
            for proc in warming:
                proc.wait()
        if run(cmd) != 0:
            failed.append(name)
    if failed:
        sys.exit(f"dev.py: FAILED: {', '.join(failed)}")


def main():
    commands = {"lab": lab, "test": test}
    if len(sys.argv) < 2 or sys.argv[1] not in commands:
        sys.exit(__doc__)
    os.chdir(ROOT)
    commands[sys.argv[1]](sys.argv[2:])


if __name__ == "__main__":
    main()
