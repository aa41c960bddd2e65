"""Packaging, notebooks and CI wiring: the things that break without touching the core."""

import re
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK_DIR = ROOT / "notebooks"
NOTEBOOKS = sorted(NOTEBOOK_DIR.glob("*.ipynb"))
NB_IDS = [nb.name for nb in NOTEBOOKS]


def test_core_import_does_not_pull_in_plotting_or_widgets():
    code = (
        "import sys, teachraster\n"
        "heavy = {'matplotlib', 'ipywidgets', 'ipympl'}\n"
        "print(sorted({m.split('.')[0] for m in sys.modules} & heavy))\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT
    )
    assert out.stdout.strip() == "[]", f"import teachraster loaded {out.stdout.strip()}"


#: The lessons: issue 4's eight (00 tour, then one per topic of the seeds), and 10 (tiles).
CURRICULUM = [f"{i:02d}_" for i in range(8)] + ["10_"]


def test_every_lesson_of_the_curriculum_is_there():
    prefixes = sorted(name[:3] for name in NB_IDS)
    assert prefixes == CURRICULUM, NB_IDS


@pytest.mark.parametrize("path", NOTEBOOKS, ids=NB_IDS)
def test_notebook_is_committed_clean(path):
    nb = nbformat.read(path, as_version=4)
    nbformat.validate(nb)
    assert nb.metadata.get("kernelspec", {}).get("name") == "python3"
    dirty = [
        i
        for i, cell in enumerate(nb.cells)
        if cell.cell_type == "code" and (cell.outputs or cell.execution_count is not None)
    ]
    assert not dirty, (
        f"{path.name}: cells {dirty} have outputs or execution counts; clear them with "
        "`.venv/bin/jupyter nbconvert --clear-output --inplace notebooks/*.ipynb`"
    )


@pytest.mark.parametrize("path", NOTEBOOKS, ids=NB_IDS)
def test_notebook_runs_headless(path, monkeypatch):
    from nbclient import NotebookClient

    monkeypatch.setenv("MPLBACKEND", "Agg")  # the kernel inherits this environment
    nb = nbformat.read(path, as_version=4)
    client = NotebookClient(
        nb,
        timeout=300,
        kernel_name="python3",
        resources={"metadata": {"path": str(NOTEBOOK_DIR)}},
    )
    client.execute()  # raises CellExecutionError, with the traceback, if any cell fails


def quick_start_commands():
    """The shell commands in the fenced blocks of README's "Quick start" section."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    match = re.search(r"^## Quick start\n(.*?)(?=^## )", text, flags=re.M | re.S)
    assert match, 'README.md has no "## Quick start" section'
    blocks = re.findall(r"^```[a-z]*\n(.*?)^```$", match.group(1), flags=re.M | re.S)
    return [line.strip() for block in blocks for line in block.splitlines() if line.strip()]


def test_readme_quick_start_is_two_commands():
    assert quick_start_commands() == ["python3 dev.py lab", "python3 dev.py test"]


@pytest.mark.skipif(shutil.which("bash") is None, reason="needs bash")
def test_ci_runs_the_readme_test_command():
    out = subprocess.run(
        ["bash", str(ROOT / ".ci" / "run"), "--print-command"],
        capture_output=True,
        text=True,
        check=True,
        cwd=ROOT,
    )
    assert out.stdout.strip() == quick_start_commands()[1]
