"""Lesson 05a, review r384: each test fails on the lesson before the fix.

FIG-1: the seven-column table of depth states ran off a 932-px cell (1227 px in JupyterLab at
1366 × 900, file browser open): two tables now, what each setting does (four columns) and its
spelling in Direct3D and Vulkan (three), llvmpipe in a note (measured 2026-12-07 with Chromium:
both 907 px in the 932-px cell; the tables' shape is tested in test_lessons_a's
test_05a_r259_depth_states_in_every_api). FIG-4: the corner labels of the clipping figure are
placed by a search, so they do not overlap with the third vertex beyond the far plane either.
S-3: the panel repeating §2's "painter wrong" is gone; the painter's wrong pixels are outlined
on the failing fragments. S-2/M-5: §4 says what GPUs do first (a band such as Intel's,
homogeneous rasterisation after Olano and Greer) and presents teachraster's band as its choice,
not highlighted as the reference.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from notebook_runs import lesson

ROOT = Path(__file__).resolve().parent.parent
NAME = "05a_zbuffer"
NOTEBOOK = ROOT / "notebooks" / f"{NAME}.ipynb"


def _text() -> list[str]:
    return ["".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"]]


def test_s2_gpus_first_then_teachraster_s_choice():
    text = _text()
    at = next(i for i, t in enumerate(text) if t.startswith("**Where $x$ and $y$ clipping"))
    flat = " ".join(text[at].split())
    gpus, ours = flat.index("**What GPUs do.**"), flat.index("**teachraster's choice**")
    assert gpus < ours
    assert "`intel_guardband.h`" in flat[gpus:ours] and "8,192 or 16,384 px" in flat[gpus:ours]
    assert "Olano and Greer" in flat[gpus:ours] and "Graphics Hardware 1997" in flat[gpus:ours]
    assert "($w < 0$)" in flat[gpus:ours]
    assert "g = 2 \\cdot 0.999\\,L/\\max(W, H) - 1" in flat[ours:]
    bars = next(t for t in text if "ax_bar.barh(" in t)
    assert 'barh(names, reach, color="0.6")' in bars and 'COLORS["outside"]]' not in bars


@pytest.mark.notebook
def test_s3_no_repeated_panel():
    ns = lesson(NAME)
    text = _text()
    failing = next(t for t in text if "outline(ax, painter_wrong" in t)
    assert "plt.subplots(figsize=" in failing and "axes[1]" not in failing
    assert int(ns.failed_px.sum()) == int(ns.painter_wrong.sum()) == 639


def test_fig4_labels_are_placed_by_a_search():
    cell = next(t for t in _text() if "def place_corner_labels():" in t)
    assert "taken.append(best[2])" in cell and ".padded(9)" in cell
    assert "place_corner_labels()\nplt.show()" in cell
    # checked by eye on 2026-12-07 at the default third vertex and at z = -0.2 and z = -12
    assert "xytext=14 * away" not in cell and "xytext=(14, -10)" not in cell
