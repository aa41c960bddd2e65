"""Every Python example in the documentation runs as written, and every link in it resolves.

The README's first screen points to ``docs/`` and ``ARCHITECTURE.md``; the examples there run
in order in one namespace (``docs/api.md``, then ``docs/widgets.md``, then
``docs/exercises.md``), like a reader pasting them. The scene examples use ``clip``, ``width``,
``height`` and ``uv`` as placeholders for the reader's own scene; a tiny prelude defines them.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
#: The documents whose examples run, in the order a reader meets them.
DOCS = [
    README,
    ROOT / "docs" / "api.md",
    ROOT / "docs" / "widgets.md",
    ROOT / "docs" / "exercises.md",
]
BLOCKS = [
    block
    for doc in DOCS
    for block in re.findall(r"^```python\n(.*?)^```", doc.read_text(), flags=re.S | re.M)
]
#: Every Markdown document of the repository that a reader can reach from the README.
LINKED = [
    README,
    ROOT / "ARCHITECTURE.md",
    ROOT / "CONVENTIONS.md",
    *sorted((ROOT / "docs").glob("*.md")),
]
PRELUDE = """
import numpy as np
clip = np.array([[[-0.9, -0.8, 0.1, 1.0], [0.9, -0.7, 0.2, 1.0], [0.0, 0.9, 0.3, 1.0]]])
width, height = 32, 24
uv = np.array([[[0.0, 0.0], [1.0, 0.0], [0.5, 1.0]]])
"""


def test_readme_has_python_examples():
    assert len(BLOCKS) >= 3


def test_readme_examples_run(monkeypatch, tmp_path):
    pytest.importorskip("matplotlib")
    pytest.importorskip("ipywidgets")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    import matplotlib
    import matplotlib.pyplot as plt

    namespace: dict = {}
    # the README sets the classroom style globally: keep it from leaking into other tests
    with matplotlib.rc_context():
        exec(compile(PRELUDE, "prelude", "exec"), namespace)
        for i, block in enumerate(BLOCKS, 1):
            exec(compile(block, f"README.md python block {i}", "exec"), namespace)
    plt.close("all")


def _anchor(heading: str) -> str:
    """GitHub's anchor for a Markdown heading: lower case, punctuation dropped, spaces to -."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


@pytest.mark.parametrize("doc", LINKED, ids=lambda p: str(p.relative_to(ROOT)))
def test_every_relative_link_resolves(doc):
    text = doc.read_text()
    missing = []
    for target in re.findall(r"\]\(([^)\s]+)\)", text):
        if re.match(r"[a-z]+:", target):  # http:, https:, mailto:
            continue
        path, _, anchor = target.partition("#")
        file = (doc.parent / path).resolve() if path else doc
        if not file.exists():
            missing.append(target)
        elif anchor and file.suffix == ".md":
            headings = re.findall(r"^#+ (.*)$", file.read_text(), flags=re.M)
            if anchor not in {_anchor(h) for h in headings}:
                missing.append(target)
    assert not missing, f"{doc.name}: links that lead nowhere: {missing}"


def test_readme_first_screen_says_what_how_and_where_next():
    first = "\n".join(README.read_text().splitlines()[:50])
    for needed in (
        "python3 dev.py lab",
        "python3 dev.py test",
        "docs/exercises.md",
        "docs/grading.md",
        "docs/api.md",
        "ARCHITECTURE.md",
    ):
        assert needed in first, needed
    assert len(README.read_text().splitlines()) < 150  # reference material lives in docs/


def test_grading_says_a_students_cell_can_rebind_the_checker(monkeypatch):
    """r14 09-3: one line in a solution cell, ``Report.assert_passed = lambda self: None``,
    makes every later locked check cell pass under nbgrader whatever the answer (student code
    runs in the grading kernel). Not prevented: docs/grading.md says so, and what remains open."""
    from teachraster import exercises as ex
    from teachraster.exercises.report import Report

    monkeypatch.setattr(Report, "assert_passed", Report.assert_passed)  # restored afterwards
    exec(
        "from teachraster.exercises.report import Report\nReport.assert_passed = lambda self: None"
    )
    report = ex.check("depth_test", lambda incoming, stored: False)
    assert not report.passed
    report.assert_passed()  # the hole, as documented: no AssertionError
    text = " ".join((Path(__file__).parents[1] / "docs/grading.md").read_text().split())
    for needed in ("Report.assert_passed = lambda self: None", "not detected", "fresh kernel",
                   "--check-submissions` flags it where it is written plainly"):  # fmt: skip
        assert needed in text, needed
