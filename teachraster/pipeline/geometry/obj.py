"""A small Wavefront OBJ reader: positions, texture coordinates and polygon faces.

Supported: ``v x y z [w]`` (w, a weight for rational curves, is accepted and ignored),
``vt u [v [w]]`` (stored as ``(u, 1 - v)``: OBJ's v points up the image, the texture
module's v down from row 0), ``f`` with ``i``, ``i/t``, ``i//n`` or ``i/t/n`` vertices (1-based, or
negative = relative to the end of the list so far), polygons fanned into triangles,
comments and blank lines. ``vn``, ``o``, ``g``, ``s``, ``usemtl``, ``mtllib`` (and the
line/point/parameter statements ``l``, ``p``, ``vp``) are accepted and ignored: normals
are not used here. Any malformed line raises :class:`ObjError` ``"line N: reason"``.

>>> mesh = read_obj('''
... v 0 0 0
... v 1 0 0
... v 1 1 0
... v 0 1 0
... f 1 2 3 4
... ''')
>>> mesh.triangles.tolist()
[[0, 1, 2], [0, 2, 3]]
"""

from __future__ import annotations

import math
import os
import re

import numpy as np

from .mesh import Mesh

IGNORED = {"vn", "o", "g", "s", "usemtl", "mtllib", "l", "p", "vp"}


class ObjError(ValueError):
    """A malformed OBJ file; ``line`` is the 1-based line number."""

    def __init__(self, line: int, reason: str):
        super().__init__(f"line {line}: {reason}")
        self.line = line
        self.reason = reason


def _text(source) -> str:
    """The OBJ text of a path, a file, a string or bytes, without a UTF-8 byte-order mark.

    Bytes are decoded as UTF-8 with undecodable bytes kept as surrogates
    (``surrogateescape``): they are harmless in a comment and reported with their line
    anywhere else (see :func:`_lines`).
    """
    if hasattr(source, "read"):
        text = source.read()
    elif (
        isinstance(source, str) and "\n" in source or isinstance(source, bytes) and b"\n" in source
    ):
        text = source  # OBJ text itself (a path has no newline)
    elif isinstance(source, str | bytes | os.PathLike):
        with open(source, "rb") as fh:
            text = fh.read()
    else:
        raise TypeError(
            f"source must be a path, a file-like object or OBJ text, got {type(source)}"
        )
    if isinstance(text, bytes | bytearray):
        text = bytes(text).decode("utf-8", errors="surrogateescape")
    if not isinstance(text, str):
        raise TypeError(f"source.read() must return str or bytes, got {type(text)}")
    return text.removeprefix("\ufeff")


#: Line breaks as Python's universal newlines see them (not str.splitlines, which also
#: breaks at form feeds and Unicode separators and would shift the line numbers).
_NEWLINE = re.compile(r"\r\n|\r|\n")
_INDEX = re.compile(r"-?[0-9]+")  # exactly: int() would also take "+1", "1_0", "١"
_NUMBER = re.compile(r"[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?")


def _lines(text: str):
    """``(line number, words)`` of each non-blank line, comments removed."""
    for n, raw in enumerate(_NEWLINE.split(text), start=1):
        line = raw.split("#", 1)[0]
        bad = _SURROGATE.search(line)
        if bad:
            byte = ord(bad.group()) - 0xDC00
            raise ObjError(n, f"byte 0x{byte:02x} is not UTF-8 text (allowed only in comments)")
        words = line.split()
        if words:
            yield n, words


_SURROGATE = re.compile("[\udc80-\udcff]")


def _numbers(n: int, words: list[str], least: int, most: int, what: str) -> list[float]:
    if not least <= len(words) <= most:
        want = f"{least}" if least == most else f"{least} to {most}"
        raise ObjError(n, f"{what} needs {want} numbers, got {len(words)}")
    out = []
    for w in words:
        try:
            x = float(w)
        except ValueError:
            raise ObjError(n, f"bad number {w!r}") from None
        if not math.isfinite(x):
            raise ObjError(n, f"bad number {w!r}: not finite")
        if not _NUMBER.fullmatch(w):  # float() also takes "1_0" and non-ASCII digits
            raise ObjError(n, f"bad number {w!r}: want ASCII digits, e.g. -1.5e3")
        out.append(x)
    return out


def _index(n: int, word: str, count: int, what: str) -> int:
    """0-based index from an OBJ index (1-based, or negative = relative to ``count``)."""
    if not _INDEX.fullmatch(word):
        raise ObjError(n, f"bad {what} index {word!r}: want an optional minus and ASCII digits")
    i = int(word)
    if i == 0:
        raise ObjError(n, f"{what} index 0: OBJ indices start at 1")
    k = i - 1 if i > 0 else count + i
    if not 0 <= k < count:
        raise ObjError(n, f"{what} index {i} out of range: {count} defined so far")
    return k


def read_obj(source) -> Mesh:
    """Read a Wavefront OBJ into a :class:`Mesh`.

    Parameters
    ----------
    source : str, path-like or file-like
        A path, an open file, or the OBJ text itself (a string containing a newline).

    Returns
    -------
    Mesh
        Triangles (polygons fanned from their first vertex). If any face has texture
        coordinates, the mesh has a ``"uv"`` attribute and one vertex per distinct
        (position, texture coordinate) pair; otherwise the positions as listed.

    Raises
    ------
    ObjError
        ``"line N: reason"`` for a malformed line.
    """
    positions: list[list[float]] = []
    uvs: list[list[float]] = []
    n_normals = 0
    faces: list[tuple[int, list[tuple[int, int | None]]]] = []  # (line, [(v, vt)])
    first_form: tuple[int, bool] | None = None  # (line, has vt) of the first face
    for n, words in _lines(_text(source)):
        key, args = words[0], words[1:]
        if key == "v":
            positions.append(_numbers(n, args, 3, 4, "v")[:3])
        elif key == "vt":
            uv = _numbers(n, args, 1, 3, "vt")
            # OBJ puts v = 0 at the bottom of the image (OpenGL); teachraster.pipeline.texture puts
            # v = 0 at row 0, the top (like the image arrays), hence 1 - v.
            uvs.append([uv[0], 1.0 - (uv + [0.0])[1]])
        elif key == "vn":
            _numbers(n, args, 3, 3, "vn")
            n_normals += 1
        elif key == "f":
            if len(args) < 3:
                raise ObjError(n, f"a face needs at least 3 vertices, got {len(args)}")
            corners, forms = [], set()
            for word in args:
                parts = word.split("/")
                if len(parts) > 3 or parts[0] == "":
                    raise ObjError(n, f"bad face vertex {word!r} (want i, i/t, i//n or i/t/n)")
                v = _index(n, parts[0], len(positions), "vertex")
                t = None
                if len(parts) == 2 and parts[1] == "":
                    raise ObjError(n, f"bad face vertex {word!r}: empty texture coordinate index")
                if len(parts) > 1 and parts[1] != "":
                    t = _index(n, parts[1], len(uvs), "texture coordinate")
                if len(parts) > 2:
                    if parts[2] == "":
                        raise ObjError(n, f"bad face vertex {word!r}: empty normal index")
                    _index(n, parts[2], n_normals, "normal")
                forms.add((t is not None, len(parts) > 2))
                corners.append((v, t))
            if len(forms) > 1:
                raise ObjError(n, f"face mixes vertex forms (e.g. 1/1 with 1): {' '.join(args)}")
            has_vt = corners[0][1] is not None
            if first_form is None:
                first_form = (n, has_vt)
            elif first_form[1] != has_vt:
                had = "had" if first_form[1] else "had no"
                raise ObjError(
                    n,
                    f"faces mix vertices with and without texture coordinates "
                    f"(the face on line {first_form[0]} {had} them)",
                )
            faces.append((n, corners))
        elif key not in IGNORED:
            raise ObjError(n, f"unknown statement {key!r}")
    return _build(positions, uvs, faces, bool(first_form and first_form[1]))


def _build(positions, uvs, faces, with_uv: bool) -> Mesh:
    tris: list[tuple[int, int, int]] = []
    if with_uv:
        # One output vertex per distinct (position, uv) pair, in order of first use: a
        # texture seam needs two vertices at the same position.
        slot: dict[tuple[int, int], int] = {}
        for _, corners in faces:
            for c in corners:
                slot.setdefault(c, len(slot))
        keys = list(slot)
        pos = np.array([positions[v] for v, _ in keys], dtype=np.float64).reshape(-1, 3)
        attrs = {"uv": np.array([uvs[t] for _, t in keys], dtype=np.float64).reshape(-1, 2)}
        index = [[slot[c] for c in corners] for _, corners in faces]
    else:
        pos = np.array(positions, dtype=np.float64).reshape(-1, 3)
        attrs = {}
        index = [[v for v, _ in corners] for _, corners in faces]
    for ids in index:
        # A fan from the first vertex: exact for convex polygons, which OBJ faces should be.
        tris.extend((ids[0], ids[k], ids[k + 1]) for k in range(1, len(ids) - 1))
    return Mesh(pos, np.array(tris, dtype=np.int64).reshape(-1, 3), attrs)
