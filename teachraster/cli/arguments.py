"""Argument types of the command line: their errors become ``argument --opt: ...`` (exit 2)."""

from __future__ import annotations

import argparse
import math
import re
from pathlib import Path

import numpy as np

#: Output formats by suffix: still image, animation, or a page that steps (fill only).
STILL, ANIMATED, PAGE = (".png",), (".gif", ".mp4"), (".html",)
#: Default resolutions: PNG for slides (crisp when scaled), animations small enough to embed.
PNG_DPI, ANIMATION_DPI = 150, 80


# -- argument types (their errors become "argument --opt: ..." with exit status 2) ------------
def _floats(text: str, what: str) -> list[float]:
    try:
        values = [float(v) for v in text.replace(",", " ").split()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"{what}: not a number in {text!r}") from None
    if not all(math.isfinite(v) for v in values):
        raise argparse.ArgumentTypeError(f"{what}: values must be finite, got {text!r}")
    return values


def parse_xy(text: str) -> np.ndarray:
    """Three vertices v1, v2, v3 ``"x1,y1 x2,y2 x3,y3"`` (pixels, y down) as a (3, 2) array.

    Vertices are separated by spaces or semicolons, coordinates by a comma.
    """
    groups = text.replace(";", " ").split()
    if len(groups) != 3 or any(g.count(",") != 1 for g in groups):
        raise argparse.ArgumentTypeError(
            f"expected three vertices 'x1,y1 x2,y2 x3,y3', got {text!r}"
        )
    return np.array([_floats(g, "vertex") for g in groups], dtype=np.float64)


def parse_w(text: str) -> np.ndarray:
    """Clip-space w (view depth) of the three vertices, ``"1,2,4"``; each must be > 0."""
    w = _floats(text, "w")
    if len(w) != 3:
        raise argparse.ArgumentTypeError(f"expected three depths 'w1,w2,w3', got {text!r}")
    if min(w) <= 0:
        # a vertex with w <= 0 is at or behind the eye: the 2-D fill cannot take it
        raise argparse.ArgumentTypeError(f"every w must be > 0 (in front of the eye), got {text!r}")
    return np.array(w)


def parse_attr(text: str) -> tuple[str, np.ndarray]:
    """``"u=0,1,0"`` (one value per vertex) or ``"uv=0,0 1,0 0,1"`` (a vector per vertex)."""
    name, sep, values = text.partition("=")
    name = name.strip()
    if not sep or not name.isidentifier():
        raise argparse.ArgumentTypeError(
            f"expected NAME=f1,f2,f3 (a value per vertex), got {text!r}"
        )
    groups = values.replace(";", " ").split()
    if len(groups) == 1:
        arr = np.array(_floats(groups[0], name))
        if arr.shape != (3,):
            raise argparse.ArgumentTypeError(f"{name}: expected 3 values, got {values!r}")
    elif len(groups) == 3:
        rows = [_floats(g, name) for g in groups]
        if len({len(r) for r in rows}) != 1:
            raise argparse.ArgumentTypeError(f"{name}: vertices have different sizes: {values!r}")
        arr = np.array(rows)
    else:
        raise argparse.ArgumentTypeError(f"{name}: expected 3 values or 3 vectors, got {values!r}")
    return name, arr


def parse_size(text: str) -> tuple[int, int]:
    """``"WxH"`` in pixels, e.g. ``"16x16"``."""
    # ASCII digits only: int() would also take "1_6", "+16" and non-ASCII digits.
    match = re.fullmatch(r"\s*([0-9]+)\s*x\s*([0-9]+)\s*", text.lower())
    if match is None:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT such as 16x16, got {text!r}")
    w, h = int(match.group(1)), int(match.group(2))
    if w <= 0 or h <= 0:
        raise argparse.ArgumentTypeError(f"width and height must be positive, got {text!r}")
    if w * h > 4096 * 4096:
        raise argparse.ArgumentTypeError(f"{text} is too large for a teaching export")
    return w, h


def parse_range(text: str) -> tuple[float, float]:
    """``"A:B"``: a w sweep from A to B (both > 0)."""
    parts = text.split(":")
    if len(parts) != 2:
        raise argparse.ArgumentTypeError(f"expected START:STOP such as 1:8, got {text!r}")
    a, b = (_floats(p, "sweep")[0] if p.strip() else float("nan") for p in parts)
    if not (a > 0 and b > 0):
        raise argparse.ArgumentTypeError(f"both ends must be numbers > 0, got {text!r}")
    return a, b


def positive(kind, *, zero: bool = False):
    """An argparse type: a ``kind`` (int or float) > 0, or >= 0 with ``zero``."""

    def parse(text: str):
        try:
            value = kind(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected a {kind.__name__}, got {text!r}") from None
        if not (math.isfinite(value) and (value >= 0 if zero else value > 0)):
            raise argparse.ArgumentTypeError(f"must be {'>=' if zero else '>'} 0, got {text!r}")
        return value

    parse.__name__ = kind.__name__  # argparse names the type in some messages
    return parse


def output_type(animated: bool, page: bool = False):
    """The ``-o`` type: a file whose suffix picks the format (.png; .gif, .mp4 if animated;
    .html if ``page``)."""

    def parse_output(text: str) -> Path:
        path = Path(text)
        suffix = path.suffix.lower()
        if suffix not in (STILL + ANIMATED * animated + PAGE * page):
            formats = ".png (still), .gif or .mp4 (animation)" if animated else ".png"
            formats += ", .html (a page that steps, offline)" if page else ""
            raise argparse.ArgumentTypeError(
                f"the suffix picks the format: {formats}; got {text!r}"
            )
        if not path.parent.is_dir():
            raise argparse.ArgumentTypeError(f"folder {str(path.parent)!r} does not exist")
        return path

    return parse_output
