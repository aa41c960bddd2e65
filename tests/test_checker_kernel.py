"""In a real Jupyter kernel, a cell checking an endless loop returns after its case's limit of
CPU time (2 s), the picture of exercises 05–08 included (the loop is not run again for it).

The limits count CPU time: on a loaded machine the wall-clock time is longer (a case is cut at
20 times its limit on the wall in any case), so the cells report the kernel's CPU time too.
"""

from __future__ import annotations

import inspect
import json

import nbformat
import pytest
from endless_loops import forever

pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")

SETUP = "import time\nfrom teachraster import exercises as ex"

LOOP = (
    inspect.getsource(forever)
    + """
start, cpu = time.perf_counter(), time.process_time()
report = ex.check("depth_test", forever)  # the default budget
took, cpu = time.perf_counter() - start, time.process_time() - cpu
print(json.dumps({"took": took, "cpu": cpu, "kind": report.failures[0].kind, "text": str(report)}))
"""
)

LOOP_WITH_PICTURE = (
    inspect.getsource(forever)
    + """
start, cpu = time.perf_counter(), time.process_time()
report = ex.check("bilinear", forever, budget=1.0)  # stopped at 0.2 s, then the picture
words = report.explain_pixel(15, 20)
took, cpu = time.perf_counter() - start, time.process_time() - cpu
print(json.dumps({"took": took, "cpu": cpu, "words": words}))
"""
)

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
    cells = (LOOP, SLEEP_AND_EXIT, LOOP_WITH_PICTURE, "print('alive')")
    nb.cells += [nbformat.v4.new_code_cell(src) for src in cells]
    # a cell that hangs fails here: each may take its budget + 2 s, plus a loaded machine's slack
    NotebookClient(
        nb, timeout=60, kernel_name="python3", resources={"metadata": {"path": tmp_path}}
    ).execute()
    loop, sleep, picture = (json.loads(nb.cells[k].outputs[0]["text"]) for k in (1, 2, 3))
    assert loop["kind"] == "timeout" and loop["cpu"] < 2 + 1.5 and loop["took"] < 40
    assert "did not finish within 2 s of CPU on case 1 of 30: an endless loop" in loop["text"]
    assert sleep["kind"] == "timeout" and sleep["took"] < 3 + 2
    assert picture["cpu"] < 2 + 1.5 and picture["took"] < 40 and "not run" in picture["words"]
    assert nb.cells[4].outputs[0]["text"] == "alive\n"  # the kernel carries on
