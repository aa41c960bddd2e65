"""Student versions of exercise notebooks: solutions replaced by stubs, as nbgrader does.

The teacher version holds each solution between ``### BEGIN SOLUTION`` and ``### END SOLUTION``
(nbgrader's markers). The student version replaces every such region by nbgrader's stub,
indented like the markers::

    # YOUR CODE HERE
    raise NotImplementedError()

and clears outputs. The check cells stay: :func:`teachraster.exercises.check` reports a stub as
"not implemented yet", so the student notebook runs top to bottom without a traceback.

Standard library only (json, re): the build (setup.py) loads this file directly to put student
versions into the wheel, before teachraster or numpy can be imported.

>>> cell = {"cell_type": "code", "source": "def f(x):\\n    ### BEGIN SOLUTION\\n    return x\\n"
...         "    ### END SOLUTION\\n", "outputs": [], "execution_count": 3, "metadata": {}}
>>> print(student_notebook({"cells": [cell]})["cells"][0]["source"])
def f(x):
    # YOUR CODE HERE
    raise NotImplementedError()
<BLANKLINE>
"""

from __future__ import annotations

import copy
import json
import re
from pathlib import Path

BEGIN, END = "BEGIN SOLUTION", "END SOLUTION"
STUB = ("# YOUR CODE HERE", "raise NotImplementedError()")
_REGION = re.compile(
    r"^(?P<indent>[ \t]*)#+ *" + BEGIN + r"[^\n]*\n.*?^[ \t]*#+ *" + END + r"[^\n]*(\n|$)",
    flags=re.M | re.S,
)


def strip_solutions(source: str) -> str:
    """``source`` with every solution region replaced by the stub."""

    def stub(match: re.Match) -> str:
        indent = match.group("indent")
        return "".join(f"{indent}{line}\n" for line in STUB)

    return _REGION.sub(stub, source)


def student_notebook(nb: dict) -> dict:
    """A copy of notebook ``nb`` (as parsed JSON) without solutions and outputs."""
    nb = copy.deepcopy(nb)
    for cell in nb.get("cells", []):
        source = cell.get("source", "")
        text = "".join(source) if isinstance(source, list) else source
        if BEGIN in text:
            if END not in text:
                raise ValueError(f"a cell has {BEGIN!r} without {END!r}: {text[:80]!r}")
            cell["source"] = strip_solutions(text)
        if cell.get("cell_type") == "code":
            cell["outputs"] = []
            cell["execution_count"] = None
    return nb


def write_student_version(src: Path, dst: Path) -> Path:
    """Write the student version of notebook ``src`` to ``dst`` (a file or a directory)."""
    src, dst = Path(src), Path(dst)
    if dst.is_dir():
        dst = dst / src.name
    nb = json.loads(src.read_text(encoding="utf-8"))
    dst.write_text(json.dumps(student_notebook(nb), indent=1, ensure_ascii=False) + "\n", "utf-8")
    return dst
