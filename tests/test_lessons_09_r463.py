"""Lesson 09, review r463: each test fails on the lesson before the fix.

S2: on the grazing floor the level panel of ``anisotropic`` at the default cap is level 0
everywhere (the probes' λ' = log2(P_max / N) <= 0), trilinear's ramp at cap 1: the notes say
that stepping max aniso sinks the panel to level 0. S3: the seams lie nearer the viewer (lower
rows) at the sides than down the middle column, as the printed "column …: seams at rows …"
lines show; the text said only that they "bend towards the sides". S4: a nearest read of
levels 1 to 3 reads a coarser texel with level 0's colour, not level 0's own texel.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
from notebook_runs import lesson

ROOT = Path(__file__).resolve().parent.parent
NAME = "09_texture_filtering"
NOTEBOOK = ROOT / "notebooks" / f"{NAME}.ipynb"


def _flat() -> str:
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    return " ".join(" ".join("".join(c["source"]) for c in cells).split())


def test_s2_the_level_panel_sinks_to_level_0_as_max_aniso_grows():
    from teachraster.widgets import FilterExplorer

    flat = _flat()
    assert "step **max aniso** from 1 to 16: the level panel sinks to level 0." in flat
    grazing = FilterExplorer(tilt=89, filter="anisotropic", repeats=6, view="grazing floor",
                             backend="image")  # fmt: skip
    try:
        cov = grazing.frame.coverage
        default = grazing.levels_read
        assert np.all(default.first[cov] == 0) and np.all(default.weight[cov] == 0)
        grazing.max_anisotropy.value = 1
        one = grazing.levels_read
        assert np.nanmax(one.first[cov] + one.weight[cov]) > 3  # trilinear's ramp
    finally:
        grazing.close()


def test_s3_s4_seams_nearer_at_the_sides_and_a_coarser_texel_of_level_0s_colour():
    ns = lesson(NAME)
    flat = _flat()
    assert "the seams dip nearer at the sides" in flat and "bend towards the sides" not in flat
    middle = ns.seams_by_column[ns.W // 2]
    for col in (ns.crop_cols[0], ns.crop_cols[-1]):
        side = ns.seams_by_column[col]
        assert len(side) == len(middle)
        assert all(s >= m for s, m in zip(side, middle)) and side != middle, (col, side)
    assert "nearest read there is level 0's own texel" not in flat
    assert "a nearest read there returns level 0's texel's colour" in flat
