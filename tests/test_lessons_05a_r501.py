"""Lesson 05a, review r501 (a fresh read after r498's cut): each test fails on the lesson before
the fix.

S-1: §4's opening said §1's triangle lies "outside the clip volume below", as if the volume lay
below; it means the clip volume and the guard band are defined further down. S-2: q_clip's
first option ("up to where it reaches the far plane, z/w = +1") made the four options wrap to a
second row in a 1300 px wide JupyterLab; it now reads as the other two planes do. S-3: the
fold's eye-plane bullet said points with w = z = 0 "get through", true of the z planes alone
(the guard band's, or GL's, x and y planes also ask x = y = 0 there); it now says so.
"""

from __future__ import annotations

import json
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK = ROOT / "notebooks" / "05a_zbuffer.ipynb"


def _cell(cell_id: str) -> str:
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    return " ".join("".join(next(c for c in cells if c["id"] == cell_id)["source"]).split())


def test_s1_clip_volume_not_said_to_lie_below():
    opening = _cell("c15")  # §4's opening
    assert "outside the clip volume below" not in opening
    assert "outside the clip volume, inside the guard band, both below)" in opening


def test_s2_q_clip_options_read_alike():
    ask = next(
        "".join(c["source"])
        for c in json.loads(NOTEBOOK.read_text())["cells"]
        if "q_clip = Predict(" in "".join(c["source"])
    )
    assert '"up to the far plane, z/w = +1"' in ask
    assert "up to where it reaches the far plane" not in ask


def test_s3_eye_plane_points_pass_the_z_planes():
    clip_volume = _cell("c15b")  # the clip volume and its fold
    assert "$w = z = 0$ get through the $z$ planes" in clip_volume
    assert "$w = z = 0$ get through," not in clip_volume
