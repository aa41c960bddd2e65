"""Lesson 09 (texture filtering) says what it shows: its numbers, read from the executed
notebook's variables instead of asserts in the lesson."""

from __future__ import annotations

import json
from pathlib import Path

import nbformat
import pytest

NOTEBOOK = Path(__file__).resolve().parent.parent / "notebooks" / "09_texture_filtering.ipynb"
REPORT = """
import json as _json
print("LESSON09" + _json.dumps({
    "moire_error": moire_error,
    "rms": rms,
    "quad_ddx": [float(v) for v in quad_ddx],
    "exact_ddx": [float(v) for v in exact_ddx],
    "aniso_error": aniso_error,
    "trilinear_error": trilinear_error,
    "study": {r["filter"]: [r["error_minified"], r["texel_reads"]] for r in study},
    "gl_agreement": gl_agreement,
    "explorer_errors": explorer_errors,
    "helpers": art.n_helpers,
}))
"""


@pytest.fixture(scope="module")
def lesson(tmp_path_factory):
    from nbclient import NotebookClient

    nb = nbformat.read(NOTEBOOK, as_version=4)
    nb.cells.append(nbformat.v4.new_code_cell(REPORT))
    client = NotebookClient(nb, timeout=300, kernel_name="python3",
                            resources={"metadata": {"path": str(NOTEBOOK.parent)}})  # fmt: skip
    client.execute()
    text = "".join(o.get("text", "") for o in nb.cells[-1].outputs)
    return json.loads(text.split("LESSON09", 1)[1])


def test_mipmaps_remove_the_moire(lesson):
    rms = lesson["rms"]
    assert rms["trilinear"] < 0.6 * lesson["moire_error"]
    assert rms["trilinear"] < rms["bilinear"] < rms["nearest"]


def test_quad_differences_follow_the_exact_map(lesson):
    for q, e in zip(lesson["quad_ddx"], lesson["exact_ddx"]):
        assert q == pytest.approx(e, rel=1e-9)
    assert lesson["helpers"] > 0


def test_anisotropy_wins_on_minified_pixels_and_costs_more(lesson):
    assert lesson["aniso_error"] < lesson["trilinear_error"]
    study = lesson["study"]
    assert study["anisotropic"][0] < study["trilinear"][0] < study["nearest"][0]
    assert study["anisotropic"][1] > study["trilinear"][1] > study["nearest"][1]


def test_gpu_and_widget_agree_with_the_story(lesson):
    if lesson["gl_agreement"] is not None:
        assert lesson["gl_agreement"] >= 0.98
    errors = lesson["explorer_errors"]
    assert errors["trilinear"] < errors["nearest"] and errors["anisotropic"] < errors["nearest"]
