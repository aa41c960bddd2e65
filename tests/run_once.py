"""Build something once per test run and share it with every pytest-xdist worker.

A module fixture is set up once per worker that runs one of the module's tests; with tests
spread over the workers two at a time (``--dist load --maxschedchunk 2``, ``dev.py``), an
expensive fixture (the nbgrader round trip, a built wheel) would be built on each.
:func:`shared_folder` builds it once, in the run's shared folder (``TEACHRASTER_RUN_CACHE``,
see ``conftest.py``), under a file lock: the second worker to ask waits for the first and reads
the same folder. Outside a run (no shared folder) it builds into a fresh temporary folder.
"""

from __future__ import annotations

import fcntl
import os
import shutil
import tempfile
from pathlib import Path


def shared_folder(key: str, build) -> Path:
    """The folder ``build(folder)`` filled, built once per run under ``key``.

    A build that fails leaves nothing behind, so the next worker tries again (and fails the
    same way, in its own test) rather than reading half a folder.
    """
    root = os.environ.get("TEACHRASTER_RUN_CACHE")
    if not root:
        folder = Path(tempfile.mkdtemp(prefix=f"{key}-"))
        build(folder)
        return folder
    folder, done = Path(root) / key, Path(root) / f"{key}.done"
    with open(Path(root) / f"{key}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # a second worker waits here for the first's build
        try:
            if not done.exists():
                shutil.rmtree(folder, ignore_errors=True)
                folder.mkdir()
                try:
                    build(folder)
                except BaseException:
                    shutil.rmtree(folder, ignore_errors=True)
                    raise
                done.touch()
            return folder
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)
