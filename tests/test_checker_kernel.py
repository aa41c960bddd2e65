"""In a real Jupyter kernel, a cell checking an endless loop returns within the budget + 2 s."""

from __future__ import annotations

import json

import nbformat
import pytest

pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")

SETUP = "import time\nfrom teachraster import exercises as ex"

LOOP = """\
def depth_test(incoming, stored):
    while True:  # the student's endless loop, swallowing every exception
        try:
            while True:
                pass
        except BaseException:
            pass

start = time.perf_counter()
report = ex.check("depth_test", depth_test)  # the default budget
took = time.perf_counter() - start
print(json.dumps({"took": took, "kind": report.failures[0].kind, "text": str(report)}))
"""

SLEEP_AND_EXIT = """\
def depth_test(incoming, stored):
    try:
        time.sleep(1000)
    except Exception:
        pass
    exit()

start = time.perf_counter()
report = ex.check("depth_test", depth_test, budget=3.0)
took = time.perf_counter() - start
print(json.dumps({"took": took, "kind": report.failures[0].kind, "text": str(report)}))
"""


@pytest.mark.notebook
def test_a_cell_checking_an_endless_loop_returns_within_the_budget_in_a_kernel(tmp_path):
    from nbclient import NotebookClient

    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(SETUP + "\nimport json")]
    nb.cells += [nbformat.v4.new_code_cell(src) for src in (LOOP, SLEEP_AND_EXIT, "print('alive')")]
    # a cell that hangs fails here: each may take its budget + 2 s, plus a loaded machine's slack
    NotebookClient(
        nb, timeout=10 + 2 + 5, kernel_name="python3", resources={"metadata": {"path": tmp_path}}
    ).execute()
    loop, sleep = (json.loads(nb.cells[k].outputs[0]["text"]) for k in (1, 2))
    assert loop["kind"] == "timeout" and loop["took"] < 10 + 2
    assert "did not return within 2 s on case 1 of 30: an endless loop?" in loop["text"]
    assert sleep["kind"] == "timeout" and sleep["took"] < 3 + 2
    assert nb.cells[3].outputs[0]["text"] == "alive\n"  # the kernel carries on
