"""The lines and blending benchmark still runs (a smoke run; speed is never asserted)."""

import pytest
from test_benchmarks import _load


@pytest.mark.bench
def test_lines_benchmark_quick_run_succeeds(capsys):
    assert _load("bench_lines").main(["--quick", "--repeat", "1"]) == 0
    out = capsys.readouterr().out
    assert "rasterize_line" in out and "blend='over'" in out
