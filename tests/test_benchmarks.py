"""The benchmark script still runs (a smoke run; speed itself is never asserted)."""

import importlib.util
import sys
from pathlib import Path

import pytest

BENCH = Path(__file__).resolve().parents[1] / "benchmarks" / "bench_fill.py"


@pytest.mark.bench
def test_fill_benchmark_quick_run_succeeds(capsys):
    spec = importlib.util.spec_from_file_location("bench_fill", BENCH)
    bench = importlib.util.module_from_spec(spec)
    sys.modules["bench_fill"] = bench  # dataclasses look their module up there
    spec.loader.exec_module(bench)
    assert bench.main(["--quick", "--repeat", "1"]) == 0  # non-zero means a failed check
    out = capsys.readouterr().out
    assert "same coverage" in out and "PASS" in out


def _load(name: str):
    path = BENCH.parent / f"{name}.py"
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


@pytest.mark.bench
def test_scene_benchmark_quick_run_succeeds(capsys):
    assert _load("bench_scenes").main(["--quick", "--repeat", "1"]) == 0
    out = capsys.readouterr().out
    assert "planned" in out and "UV sphere" in out


# bench_widgets' smoke run is tests/test_widgets.py::test_widget_benchmark_quick_run_succeeds


@pytest.mark.bench
def test_antialiasing_benchmark_quick_run_succeeds(capsys):
    assert _load("bench_antialiasing").main(["--quick", "--repeat", "1"]) == 0
    out = capsys.readouterr().out
    assert "exact pixel area" in out and "samples=4" in out


@pytest.mark.bench
def test_texture_benchmark_quick_run_succeeds(capsys):
    assert _load("bench_texture").main(["--quick", "--repeat", "1"]) == 0
    assert "trilinear / bilinear" in capsys.readouterr().out
