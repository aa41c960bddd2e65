"""r141 (exercises 03 and 08, a fresh reader): a tile taken as 8 px wide passed 8.2 (D8.2-1);
two 8.2 mistakes got the rule only (D8.2-2); an epsilon added to 3.1's area was called float32
and its failure printed twice (D3-b); 8.1's llvmpipe sentence and the words "all four centres"
(D8.1-2, D8.1-7). The wrong answers are the reader's own variants, as a student writes them.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from teachraster import exercises as ex
from teachraster.exercises import hiz_tile, interpolation, tile_blocks

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks/exercises/08_tiles.ipynb"


def _hiz(size_of=lambda size: size, last=None, first=None, vertex_in_tile=False):
    """The reader's hiz_rejects (h01), with one slip: ``size_of`` the tile's size as used
    (h20: always 8), ``last`` its last column from col0 (h15: col0 + 7), ``first`` how the box's
    first column is rounded (h25: int(xmin + ½) and int(xmax − ½)), ``vertex_in_tile`` (h23)."""

    def hiz_rejects(xyz, row0, col0, size, buffer):
        size = size_of(size)
        p = np.array(xyz, dtype=np.float64)
        x, y, z = p[:, 0], p[:, 1], p[:, 2]
        end = (lambda c0: c0 + last) if last is not None else (lambda c0: c0 + size - 1)
        if first == "int":
            lo, hi = (lambda v: int(v + 0.5)), (lambda v: int(v - 0.5))
        else:
            lo, hi = (lambda v: math.ceil(v - 0.5)), (lambda v: math.floor(v - 0.5))
        clo, chi = max(col0, lo(x.min())), min(end(col0), hi(x.max()))
        rlo, rhi = max(row0, lo(y.min())), min(end(row0), hi(y.max()))
        if clo > chi or rlo > rhi:
            return True
        n = np.cross(p[1] - p[0], p[2] - p[0])
        gx, gy = -n[0] / n[2], -n[1] / n[2]
        zmin = min(z[0] + gx * (cx - x[0]) + gy * (cy - y[0])
                   for cx in (clo + 0.5, chi + 0.5) for cy in (rlo + 0.5, rhi + 0.5))  # fmt: skip
        if vertex_in_tile:
            inside = [z[k] for k in range(3)
                      if col0 <= x[k] < col0 + size and row0 <= y[k] < row0 + size]  # fmt: skip
            bound = max(zmin, min(inside)) if inside else zmin
        else:
            bound = max(zmin, z.min())
        return bool(bound >= np.max(np.asarray(buffer, dtype=np.float64)))

    return hiz_rejects


@pytest.mark.parametrize(
    ("fn", "words"),
    [(_hiz(size_of=lambda s: 8), "you took the tile as 8 × 8 pixels"),
     (_hiz(last=7), "you took the tile as 8 × 8 pixels"),
     (_hiz(vertex_in_tile=True), "you took the nearest vertex among those inside the tile"),
     (_hiz(first="int"), "int(xmin + ½) for its first column")],
    ids=["size = 8 (h20)", "col0 + 7 (h15)", "vertex in tile (h23)", "int(xmin + ½) (h25)"],
)  # fmt: skip
def test_hiz_mistakes_fail_and_are_named_on_the_first_try(fn, words):
    report = ex.check("hiz_rejects", fn)
    assert not report.passed
    assert all(words in f.explanation for f in report.failures), [
        f.explanation for f in report.failures
    ]


def test_hiz_right_answer_passes_and_the_16_px_case_decides_beyond_8():
    assert ex.check("hiz_rejects", _hiz()).passed
    wide = [(label, args) for label, args, _ in hiz_tile.hiz_cases() if args[3] == 16]
    assert len(wide) == 2  # cell 5: "two cases' tiles are 16 px wide"
    label, (xyz, row0, col0, size, buffer) = wide[1]
    # the bound at a centre past the first 8 × 8, the farthest stored depth there too
    assert hiz_tile.lower_bound(xyz, row0, col0, size) < buffer.max()
    assert hiz_tile.lower_bound(xyz, row0, col0, 8) >= buffer.max() > buffer[:8, :8].max()
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    assert "two cases' tiles are 16 px wide, not 8" in "".join(cells[5]["source"])


def _bary_eps(xy, p):
    """The reader's e9: float64, divided by area + 1e-12 (a guard against 0)."""

    def edge(a, b, q):
        return (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])

    v, p = np.asarray(xy, float), np.asarray(p, float)
    area = edge(v[0], v[1], v[2])
    return np.array([edge(v[1], v[2], p), edge(v[2], v[0], p), edge(v[0], v[1], p)]) / (
        area + 1e-12
    )


def test_an_epsilon_on_the_area_is_named_not_float32_and_each_failure_said_once():
    report = ex.check("barycentric", _bary_eps)
    assert not report.passed
    for f in report.failures:
        if f.case.startswith("zero area"):  # 3.1 since ex30b: refused with ValueError
            assert "raise ValueError" in f.explanation, f.explanation
            continue
        assert "you added a small number" in f.explanation, f.explanation
        assert "float32" not in f.explanation, f.explanation
    text = str(report)
    lines = [line for line in text.splitlines() if line.startswith("- ")]
    assert len(lines) == len(set(lines)), text
    labels = [label for label, _, _ in interpolation.barycentric_cases()]
    assert len(labels) == len(set(labels))


def test_8_1_says_what_llvmpipe_computes_and_no_four_centres_of_sixteen():
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    task = "".join(cells[2]["source"])
    for words in ("its offsets span `size` steps", "one step\npast the block's last pixel centre",
                  # r214: llvmpipe's fold is a table, the exercise's column beside llvmpipe's
                  "| offsets | exact, over the block's own pixel centres |",
                  "and to their trivial-accept corners with a second"):  # fmt: skip
        assert " ".join(words.split()) in " ".join(task.split()), words  # r214: re-wrapped
    assert "with one vector add." not in task
    # r162 C.2: "a one-pixel block has one centre, so its offsets are 0" gave size − 1 away
    assert "so its offsets are 0" not in task
    source = Path(tile_blocks.__file__).read_text()
    assert "all four centres" not in source and "(E₀ + R, with R ≥ 0)" in source
    assert "(E₀ plus the reject offset, ≥ 0) and" not in source
