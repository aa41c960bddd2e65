"""Writing course files into a directory without ever losing what is there.

The course commands (``teachraster lessons``, ``student-version``, ``nbgrader``) all write
through :func:`install`, which promises:

- nothing is written until every target has been checked: a target that is a symbolic link
  (or lies under one), that is not a regular file, or whose name would leave the directory
  stops the whole run with :class:`CourseError`, naming it;
- a missing file is added; a file equal to the shipped one is left alone; a file the student
  never edited since an earlier version shipped it (its fingerprint is still the one recorded
  in ``shipped``, :mod:`.manifest`) is refreshed to the new version; a file that differs (a
  student's work) is kept, unless ``force``: then it is replaced and the old file kept as a
  backup (``name.2026-11-26T10-00.ipynb`` beside it, or under ``backups``), never overwritten;
- every write goes to a temporary file in the target's directory, renamed into place: a full
  disk or an interrupted run leaves the old file or the new one, never a truncated one.

Standard library only.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from dataclasses import dataclass, field
from datetime import datetime
from pathlib import Path, PurePosixPath

from .manifest import fingerprint


class CourseError(ValueError):
    """A course command refused to write: the message names the file and says why."""


@dataclass
class Outcome:
    """What :func:`install` did, file by file (absolute paths)."""

    added: list[Path] = field(default_factory=list)
    unchanged: list[Path] = field(default_factory=list)
    #: files the student never edited, replaced by the new version
    refreshed: list[Path] = field(default_factory=list)
    kept: list[Path] = field(default_factory=list)
    #: (replaced file, where its old content now is)
    replaced: list[tuple[Path, Path]] = field(default_factory=list)


def _target(root: Path, name: str, *, folder: bool = False) -> Path:
    """``root / name`` after checking that writing there stays in ``root``, off symlinks.

    ``folder``: the name is a directory's (it may exist as one), not a file's.
    """
    rel = PurePosixPath(name)
    if rel.is_absolute() or not rel.parts or any(p in ("", ".", "..") for p in rel.parts):
        raise CourseError(f"{name!r} is not a file name inside {root}")
    path = root
    for part in rel.parts:
        path = path / part
        if path.is_symlink():
            raise CourseError(
                f"{path} is a symbolic link: the course commands never write through one "
                "(it could point outside the directory); remove it or choose another directory"
            )
    if path.exists() and not (path.is_dir() if folder else path.is_file()):
        kind = "a directory" if folder else "a regular file"
        raise CourseError(f"{path} is in the way: it is not {kind}")
    if path.parent.exists() and not path.parent.is_dir():
        raise CourseError(f"{path.parent} is in the way: it is not a directory")
    return path


def _root(directory: Path) -> Path:
    root = Path(os.path.abspath(directory))
    if root.exists() and not root.is_dir():
        raise CourseError(f"{directory} exists and is not a directory")
    return root.resolve() if root.exists() else root


def atomic_write(path: Path, data: bytes, before=None) -> None:
    """Write ``data`` to ``path`` through a temporary file renamed into place.

    ``before()``, if given, runs once the data is safely on disk, just before the rename (a
    backup of the old file is made then: never for a write that failed). On any failure
    (``OSError`` such as a full disk, or an interruption) the temporary file is removed and
    ``path`` is as it was.
    """
    tmp = None
    try:
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
        os.close(fd)
        # mkstemp makes the file private (0600): give it the mode a plain write would
        os.chmod(tmp, path.stat().st_mode & 0o7777 if path.exists() else _default_mode())
        with open(tmp, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        if before is not None:
            before()
        os.replace(tmp, path)
    except OSError as exc:
        _remove(tmp)
        why = exc.strerror or exc
        raise OSError(exc.errno, f"could not write {path} ({why}); it is as it was") from exc
    except BaseException:
        _remove(tmp)
        raise


def _default_mode() -> int:
    umask = os.umask(0o022)  # read the umask (it can only be read by setting it)
    os.umask(umask)
    return 0o666 & ~umask


def _remove(tmp: str | None) -> None:
    if tmp is not None and os.path.lexists(tmp):
        os.unlink(tmp)


def _backup(path: Path, backups: Path | None, root: Path, now: datetime) -> Path:
    """Keep the current ``path`` under a new, never-used name; return that name."""
    folder = path.parent
    if backups is not None:  # the same layout under backups/, checked as every target is
        rel = backups.relative_to(root) / path.parent.relative_to(root)
        folder = _target(root, rel.as_posix(), folder=True)
        folder.mkdir(parents=True, exist_ok=True)
    stamp = now.strftime("%Y-%m-%dT%H-%M")
    for n in range(1, 1000):
        name = f"{path.stem}.{stamp}{'' if n == 1 else f'-{n}'}{path.suffix}"
        backup = folder / name
        try:
            os.link(path, backup)  # fails if the name is taken: an old backup is never lost
            return backup
        except FileExistsError:
            continue
        except OSError:  # no hard links here (some file systems): copy, never over a file
            try:
                dst = open(backup, "xb")
            except FileExistsError:
                continue
            try:
                with dst, open(path, "rb") as src:
                    shutil.copyfileobj(src, dst)
            except BaseException:
                _remove(str(backup))  # ours, half written: the original is still whole
                raise
            return backup
    raise CourseError(f"no free backup name for {path} in {folder}")


def _replace(path: Path, data: bytes, backups: Path | None, root: Path, now: datetime) -> Path:
    """Replace ``path`` by ``data``, its old content kept as a backup; return the backup."""
    kept = []  # the backup is made once the new data is on disk: a failed write leaves none
    atomic_write(path, data, lambda: kept.append(_backup(path, backups, root, now)))
    return kept[0]


def install(
    directory: Path,
    files: dict[str, bytes],
    *,
    force: bool = False,
    backups: Path | None = None,
    now: datetime | None = None,
    shipped: dict[str, str] | None = None,
) -> Outcome:
    """Write ``files`` (relative POSIX name -> content) into ``directory``, losing nothing.

    Parameters
    ----------
    directory : Path
        Created if missing. It may itself be a symbolic link to a directory (the one the user
        named); nothing below it may be.
    files : dict
        What to write, by name relative to ``directory`` (``"exercises/01_coverage.ipynb"``).
    force : bool
        Replace files that differ, keeping each old one as a backup.
    backups : Path, optional
        Where backups go (the same relative layout); default: beside each file.
    now : datetime, optional
        The time in backup names (default: now, local time).
    shipped : dict, optional
        Fingerprints (:func:`.manifest.fingerprint`) of what an earlier version shipped, by
        name: a file still holding that content was never edited and is refreshed.

    Raises
    ------
    CourseError
        Before anything is written, for a target that is unsafe to write (see the module).
    OSError
        When a write fails (a full disk): files written so far are complete, the failing one
        is untouched.
    """
    root = _root(directory)
    targets = {name: _target(root, name) for name in files}
    backup_root = (
        None if backups is None else _target(root, str(PurePosixPath(backups)), folder=True)
    )
    outcome = Outcome()
    for name, path in targets.items():
        data = files[name]
        if not path.exists():
            path.parent.mkdir(parents=True, exist_ok=True)
            atomic_write(path, data)
            outcome.added.append(path)
        elif (old := path.read_bytes()) == data or fingerprint(name, old) == fingerprint(
            name, data
        ):
            outcome.unchanged.append(path)  # (outputs of a run are not an edit)
        elif shipped is not None and shipped.get(name) == fingerprint(name, old):
            atomic_write(path, data)
            outcome.refreshed.append(path)
        elif not force:
            outcome.kept.append(path)
        else:
            old = _replace(path, data, backup_root, root, now or datetime.now())
            outcome.replaced.append((path, old))
    return outcome
