"""Lesson 08 (antialiasing): run it headless and check what it shows, through its variables."""

import json
from pathlib import Path

import nbformat
import pytest

pytestmark = pytest.mark.notebook
NOTEBOOK = Path(__file__).resolve().parent.parent / "notebooks" / "08_antialiasing.ipynb"

CHECKS = r"""
import json
# The tests drive the widget (the lesson no longer does it in front of the class).
inspector.pattern.value = "16 standard"
inspector.row.value, inspector.col.value = 3, 16
print(json.dumps({
    "area_sum": float(area.sum()),
    "triangle_area": float(abs(tr.Triangle(tr.snap(xy)).signed_area)),
    "sliver_1": int(sliver_1.coverage.sum()),
    "sliver_4": int(sliver_4.coverage.sum()),
    "shaded": [shaded_msaa, shaded_ssaa],
    "levels": levels,
    "twice": int((count > 1).sum()),
    "once": int((count == 1).sum()),
    "v_centre": [float(v_centre.min()), float(v_centre.max())],
    "v_centroid": [float(v_centroid.min()), float(v_centroid.max())],
    "gif": gif.stat().st_size,
    "per_sample": frames[4].plan["multisampling"].count,
    "covered": frames[4].plan["multisampling"].total,
    "errors": {f"{r['kind']}{r['samples']}": r["mean_error"] for r in rows},
    "inspected": inspector.pixel.square.axes.get_title(),
}))
"""


@pytest.fixture(scope="module")
def shown(tmp_path_factory):
    from nbclient import NotebookClient

    nb = nbformat.read(NOTEBOOK, as_version=4)
    nb.cells.append(nbformat.v4.new_code_cell(CHECKS))
    NotebookClient(nb, timeout=300, kernel_name="python3",
                   resources={"metadata": {"path": str(NOTEBOOK.parent)}}).execute()  # fmt: skip
    text = "".join(o.get("text", "") for o in nb.cells[-1].outputs)
    return json.loads(text)


def test_lesson_08_shows_what_it_says(shown):
    assert shown["area_sum"] == pytest.approx(shown["triangle_area"], abs=1e-9)
    assert shown["sliver_1"] == 0 < shown["sliver_4"]  # the sliver vanishes, then appears
    msaa, ssaa = shown["shaded"]
    assert ssaa > 2 * msaa  # supersampling shades per sample
    assert 0.75 not in shown["levels"]["ordered grid"]
    assert shown["levels"]["rotated grid (standard)"] == [0.0, 0.25, 0.5, 0.75, 1.0]
    assert shown["twice"] == 0 and shown["once"] > 100  # watertight per sample
    lo, hi = shown["v_centre"]
    assert lo < 0 or hi > 1  # extrapolated at the centres
    lo, hi = shown["v_centroid"]
    assert 0 <= lo and hi <= 1  # centroid stays inside
    assert shown["gif"] > 1000
    assert 0 < shown["per_sample"] < shown["covered"]
    err = shown["errors"]
    assert err["standard16"] < err["standard4"] < err["standard1"]
    assert "of 16 covered" in shown["inspected"]
