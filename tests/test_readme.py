"""Every Python example in README.md runs as written (after the reshaping, and after every
feature added since): the blocks run in order in one namespace, like a reader pasting them.

Block 2 uses ``clip``, ``width``, ``height`` and ``uv`` as placeholders for the reader's own
scene; a tiny prelude defines them.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
BLOCKS = re.findall(r"^```python\n(.*?)^```", README.read_text(), flags=re.S | re.M)
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
