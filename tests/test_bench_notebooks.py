"""The notebook benchmark still runs (a smoke run on the smallest notebook; no speed asserted)."""

import importlib.util
import sys
from pathlib import Path

import pytest

BENCH = Path(__file__).resolve().parents[1] / "benchmarks" / "bench_notebooks.py"


def _load():
    spec = importlib.util.spec_from_file_location("bench_notebooks", BENCH)
    module = importlib.util.module_from_spec(spec)
    sys.modules["bench_notebooks"] = module
    spec.loader.exec_module(module)
    return module


@pytest.mark.notebook
def test_notebook_benchmark_smoke_run(capsys):
    bench = _load()
    assert bench.main(["--only", "02_span_split", "--server-gib", "24"]) == 0
    out = capsys.readouterr().out
    assert "exercises/02_span_split" in out and "students" in out


def test_students_per_server_counts_whole_students():
    bench = _load()
    assert bench.students_per_server(216.0, 24, 40) == 96  # 24576 MiB // 256 MiB
    assert bench.students_per_server(900.0, 1, 0) == 1
