"""The browser benchmark runs (``benchmarks/bench_browser.py --quick``): JupyterLab, Chromium,
every widget of its notebook driven once, every figure printed. Skipped, saying why, where
Playwright, Chromium or JupyterLab is missing."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from test_page_offline import WHY

BENCH = Path(__file__).resolve().parents[1] / "benchmarks" / "bench_browser.py"

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(
        WHY is not None or shutil.which("jupyter", path=str(Path(sys.executable).parent)) is None,
        reason=f"browser benchmark skipped: {WHY or 'JupyterLab is not installed'}",
    ),
]


def test_browser_benchmark_quick_run_reports_every_figure():
    # its own process: the benchmark drives its own Playwright, and a thread holds only one
    # (this worker's is the notebooks', tests/notebook_browser.py)
    run = subprocess.run(
        [sys.executable, str(BENCH), "--quick"], capture_output=True, text=True, timeout=900
    )
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-3000:]
    out = run.stdout
    for line in ("do-nothing IntSlider", "plain figure", "next step", "method toggle",
                 "interpolation toggle", "samples toggle", "first frame of a drag",
                 "step slider dragged", "play at 20 ms/step", "vertex dragged", "tilt dragged",
                 "tilt, one key", "height of the whole player"):  # fmt: skip
        assert line in out, line
    # the other slider explorers: a key, a drag, the last picture after it
    for name in ("FilterExplorer: tilt", "PlaneExplorer: v1 x", "DepthPrecisionExplorer: near"):
        for what in ("one key", "one key, full picture", "dragged", "last picture after a drag"):
            assert f"{name}{', ' if what != 'dragged' else ' '}{what}" in out, (name, what)
    assert "FilterExplorer: filter toggle" in out
    assert "PlaneExplorer: f2, its first drag" in out
