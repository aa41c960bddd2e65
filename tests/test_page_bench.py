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
    assert "| interaction | median | max | / rt | target |" in out  # the Markdown table
    for line in ("do-nothing IntSlider", "plain figure", "next step", "method toggle",
                 "interpolation toggle", "samples toggle", "first frame of a drag",
                 "step slider dragged", "play at 20 ms/step", "vertex dragged", "tilt dragged",
                 "tilt, one key", "height of the whole player",
                 "TriangleEditor: last picture after a drag"):  # fmt: skip
        assert line in out, line
    # the other slider explorers: a key, a drag, the last picture after it
    for name in ("FilterExplorer: tilt", "PlaneExplorer: v1 x", "DepthPrecisionExplorer: near"):
        for what in ("one key", "one key, full picture", "dragged", "last picture after a drag"):
            assert f"{name}{', ' if what != 'dragged' else ' '}{what}" in out, (name, what)
    assert "FilterExplorer: filter toggle" in out
    assert "PlaneExplorer: f2, its first drag" in out
    # the figures whose vertices are dragged in the page (drag.js): the TriangleEditor's and
    # the PlaneExplorer's, each with its first frame, its rate and its last picture
    for name in ("TriangleEditor", "PlaneExplorer"):
        for what in (": first frame of a drag", ": vertex dragged (fills/s)",
                     ": last picture after a drag"):  # fmt: skip
            assert f"| {name}{what} |" in out, (name, what)
    # the explorables computed in the page (issue 31): a drag's first picture, its rate and
    # its last picture; a click to its picture
    for name in ("EdgeFunctionExplorer: vertex", "AttributeSurfaces: rotate",
                 "EyeRayExplorer: segment end", "DepthValuesExplorer: near plane",
                 "DiamondExplorer: end point"):  # fmt: skip
        for what in (", first picture of a drag", " dragged", ", last picture after a drag"):
            assert f"| {name}{what} |" in out, (name, what)
    for line in ("EyeRayExplorer: q slider dragged", "EyeRayExplorer: depth ratio z1/z0 slider "
                 "dragged", "PipelineMap: click a stage", "CrackExplorer: reroll",
                 "FootprintExplorer: click a pixel", "FootprintExplorer: click the texture",
                 # the controls that go through the kernel
                 "DivideCostExplorer: error toggle", "CasePicker: naive-rule toggle",
                 "CasePicker: case menu", "SamplingExplorer: kernel toggle",
                 "SamplingExplorer: samples, one key", "TileExplorer: level, one key",
                 "TileExplorer: level slider dragged", "TileExplorer: traversal menu",
                 "ProjectionExplorer: q, one key", "ProjectionExplorer: q slider dragged",
                 "ProjectionExplorer: q slider, last picture after a drag"):  # fmt: skip
        assert f"| {line}" in out, line
    # every row measured something (a selector that found nothing leaves an empty row)
    assert "no picture found" not in out
    assert "rows miss their target" in out
