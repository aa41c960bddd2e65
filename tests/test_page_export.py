"""Offline pages from the command line: ``teachraster fill -o x.html`` and ``teachraster html``."""

from __future__ import annotations

import json
import re
import time

import nbformat
import pytest

from teachraster.cli import main
from teachraster.cli.lesson_pages import count_widgets

XY = ["--xy", "2.2,1.5 13.7,5.2 5.1,12.8"]


def test_fill_page_is_one_file_with_every_step_and_no_address(tmp_path, capsys):
    out = tmp_path / "fill.html"
    assert main(["fill", *XY, "--method", "halfplane", "--size", "12x12", "-o", str(out)]) == 0
    text = out.read_text()
    data = json.loads(re.search(r"mountStatic\([^,]+, (\{.*\})\);", text).group(1))
    assert data["n"] > 50 and len(data["captions"]) == data["n"]
    assert sum(len(g["pngs"]) for g in data["groups"]) == data["n"]
    assert not re.search(r"(src|href)=['\"]?(https?:)?//", text)  # nothing fetched
    assert "steps that step and play offline" in capsys.readouterr().out


def test_huge_fill_sizes_are_refused_at_once_with_a_reason(tmp_path, capsys):
    t0 = time.perf_counter()
    with pytest.raises(SystemExit) as exc:
        main(["fill", *XY, "--size", "4096x4096", "-o", str(tmp_path / "x.gif")])
    assert exc.value.code == 2 and time.perf_counter() - t0 < 5
    assert "argument --size" in capsys.readouterr().err


def test_an_animation_estimated_too_long_is_refused(tmp_path, capsys, monkeypatch):
    from teachraster.cli import export

    monkeypatch.setattr(export, "MAX_EXPORT_SECONDS", 0.001)
    with pytest.raises(SystemExit):
        main(["fill", *XY, "--size", "16x16", "-o", str(tmp_path / "x.gif")])
    assert "--every" in capsys.readouterr().err


def test_html_export_counts_widgets_by_kind_and_drops_their_state():
    nb = nbformat.v4.new_notebook()
    view = "application/vnd.jupyter.widget-view+json"
    ours = nbformat.v4.new_code_cell("player")
    ours.outputs = [nbformat.v4.new_output("display_data", data={"text/html": "<div>page</div>"},
                    metadata={"teachraster": {"widget": "FillPlayer", "kind": "live"}})]  # fmt: skip
    other = nbformat.v4.new_code_cell("slider")
    other.outputs = [nbformat.v4.new_output("display_data", data={view: {"model_id": "y"}})]
    nb.cells = [ours, other]
    nb.metadata["widgets"] = {"application/vnd.jupyter.widget-state+json": {"state": {}}}
    assert count_widgets(nb) == {"live": 1, "pictured": 0, "missing": 1}
    assert view not in other.outputs[0]["data"] and "run the notebook" in other.outputs[0][
        "data"]["text/html"]  # fmt: skip
    assert "widgets" not in nb.metadata


def _lesson(path, source):
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_markdown_cell("Area $A = \\frac{1}{2}$."),
                nbformat.v4.new_code_cell(source)]  # fmt: skip
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3",
                                 "language": "python"}  # fmt: skip
    nbformat.write(nb, path)
    return path


@pytest.mark.notebook
@pytest.mark.filterwarnings("ignore")
def test_teachraster_html_writes_each_lesson_and_counts_its_widgets(tmp_path, capsys):
    pytest.importorskip("nbconvert")
    player = _lesson(tmp_path / "a.ipynb",
                     "import teachraster as tr\nfrom teachraster.widgets import FillPlayer\n"
                     "FillPlayer(tr.Triangle([[1, 1], [7, 2], [3, 7]]), 8, 8)")  # fmt: skip
    plain = _lesson(tmp_path / "b.ipynb", "import ipywidgets\nipywidgets.IntSlider()")
    out = tmp_path / "pages"
    assert main(["html", str(player), str(plain), "-o", str(out)]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].endswith("a.html: 1 widget(s): 1 live, 0 pictured, 0 missing; "
                             "1 formula(s) as MathML")  # fmt: skip
    assert "b.html: 1 widget(s): 0 live, 0 pictured, 1 missing" in lines[1]
    text = (out / "a.html").read_text()
    assert "mountStatic(" in text and "widget-view+json" not in text and "<math" in text
    assert "_offline" not in text  # the set-up cell is gone, and the lesson counts from 1
    assert re.findall(r"jp-InputPrompt[^>]*>In\W*\[(\d+)\]", text) == ["1"]
    assert not re.search(r"<script[^>]*\ssrc=", text)  # no script is fetched


def test_html_page_leaves_out_the_source_of_hidden_and_tagged_cells(tmp_path):
    """A Predict cell's source holds its answer: collapsed (``source_hidden``) or tagged
    ``hide-input``, the page shows its outputs only; other cells keep their source."""
    pytest.importorskip("nbconvert")
    from teachraster.cli.lesson_pages import drop_hidden_inputs, lesson_html

    nb = nbformat.v4.new_notebook()
    sources = ["answer_collapsed = 6", "answer_tagged = 7", "shown_code = 8"]
    nb.cells = [nbformat.v4.new_code_cell(s) for s in sources]
    nb.cells[0].metadata["jupyter"] = {"source_hidden": True}
    nb.cells[1].metadata["tags"] = ["hide-input"]
    for k, cell in enumerate(nb.cells):
        cell.outputs = [nbformat.v4.new_output("display_data",
                                               data={"text/html": f"<p>output {k}</p>"})]  # fmt: skip
    text = lesson_html(nb, tmp_path / "x.ipynb")
    assert "answer_collapsed" not in text and "answer_tagged" not in text
    assert "shown_code" in text  # (highlighted, so the name is whole but the "=" is not)
    assert all(f"output {k}" in text for k in range(3))  # the outputs stay
    assert drop_hidden_inputs(nbformat.v4.new_notebook()) == 0
