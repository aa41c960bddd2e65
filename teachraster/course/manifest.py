"""What ``teachraster lessons`` shipped into a directory, so that an upgrade knows what the
student never touched.

``DIR/.teachraster-course.json`` records, for each file the course wrote, a fingerprint of the
content shipped: for a notebook, its cells' types and sources (outputs, execution counts and
cell metadata do not count: running a notebook is not editing it); for another file, its
bytes. On the next ``teachraster lessons DIR`` (a new version of the package), a notebook whose
fingerprint is still the one recorded was never edited and is refreshed to the new version; one
that differs is the student's work and is kept (:mod:`.install`). A directory without the
file (a course copied by an older version) keeps every notebook that differs.

Standard library only.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

#: The manifest's name, in the course directory.
NAME = ".teachraster-course.json"


def fingerprint(name: str, data: bytes) -> str:
    """A fingerprint of a file's content: a notebook's cell types and sources, else its bytes.

    >>> cell = {"cell_type": "code", "source": "x = 1", "outputs": [], "metadata": {}}
    >>> run = dict(cell, outputs=[{"output_type": "stream", "text": "1"}], execution_count=3)
    >>> a, b = ({"cells": [c], "metadata": {}, "nbformat": 4} for c in (cell, run))
    >>> fingerprint("a.ipynb", json.dumps(a).encode()) == fingerprint("a.ipynb", json.dumps(b).encode())
    True
    """
    if name.endswith(".ipynb"):
        try:
            cells = json.loads(data.decode("utf-8"))["cells"]
            content = [
                (
                    c.get("cell_type"),
                    "".join(c["source"]) if isinstance(c.get("source"), list) else c.get("source"),
                )  # fmt: skip
                for c in cells
            ]
            data = json.dumps(content, ensure_ascii=False).encode("utf-8")
        except (UnicodeDecodeError, ValueError, KeyError, TypeError, AttributeError):
            pass  # not a notebook after all: its bytes are its content
    return hashlib.sha256(data).hexdigest()


def read(root: Path) -> dict[str, str]:
    """The fingerprints recorded in ``root`` (empty when there is no readable manifest)."""
    try:
        recorded = json.loads((Path(root) / NAME).read_text(encoding="utf-8"))
        files = recorded["files"]
    except (OSError, ValueError, KeyError, TypeError):
        return {}
    if not isinstance(files, dict):
        return {}
    return {k: v for k, v in files.items() if isinstance(k, str) and isinstance(v, str)}


def text(files: dict[str, str], version: str) -> bytes:
    """The manifest's content for ``files`` (name -> fingerprint)."""
    data = {"about": "what teachraster lessons shipped here (do not edit)", "version": version,
            "files": dict(sorted(files.items()))}  # fmt: skip
    return (json.dumps(data, indent=1, ensure_ascii=False) + "\n").encode("utf-8")
