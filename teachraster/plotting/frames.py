"""A fill's steps drawn once and stepped through in the page (``static/frames.js``).

The kernel draws every step of a :class:`~teachraster.plotting.FillView` once, with the
view's own blitted redraw (so the pictures are the ones the view draws), and cuts them into
groups of :data:`KEY` steps: a key frame (the whole figure as PNG) and, for each later step,
the rectangle of pixels that step changed. The page paints a key frame and the patches up to
the step wanted, so stepping, dragging the slider and playing cost no round trip; groups are
sent on request, the one under the slider first, then ahead of it.

The page side is ``static/frames.js`` (plain ESM, no build step), used by
:class:`teachraster.widgets.FillPlayer` (as an anywidget) and by the offline pages of
:mod:`teachraster.plotting.pages`.
"""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

import numpy as np

#: Steps per group: a key frame and KEY - 1 patches. Showing any step paints at most KEY
#: images; a group of a 16 x 16 fill is about 40 KB and takes the kernel about 0.1 s (which
#: a toggle may have to wait for: groups are small for that reason).
KEY = 8


def keys_js() -> str:
    """``static/keys.js`` then ``static/page.js``: keys pressed in a widget are the widget's,
    in JupyterLab and in Notebook 7; what every module shares besides (its CSS added once per
    page). Every page-side module of the package starts with it."""
    static = Path(__file__).parent / "static"
    return "".join((static / f).read_text(encoding="utf-8") for f in ("keys.js", "page.js"))


def frames_js() -> str:
    """The page-side module (ESM), read from the package (``static/frames.js``)."""
    return keys_js() + (Path(__file__).parent / "static" / "frames.js").read_text(encoding="utf-8")


def frame_rgba(fig) -> np.ndarray:
    """A copy of the figure's Agg buffer, (H, W, 4) uint8 (after the figure was drawn)."""
    return np.array(fig.canvas.buffer_rgba(), copy=True)


def changed_box(before: np.ndarray, after: np.ndarray):
    """(row0, row1, col0, col1) of the pixels that differ, or None when none does."""
    if before.shape[-1] == 4 and before.dtype == np.uint8 and after.dtype == np.uint8:
        # one 32-bit word per pixel: a quarter of the comparisons
        before = np.ascontiguousarray(before).view(np.uint32)
        after = np.ascontiguousarray(after).view(np.uint32)
    diff = (before != after).any(axis=2)
    rows, cols = np.flatnonzero(diff.any(axis=1)), np.flatnonzero(diff.any(axis=0))
    if rows.size == 0:
        return None
    return int(rows[0]), int(rows[-1]) + 1, int(cols[0]), int(cols[-1]) + 1


def render_group(view, g: int, key: int = KEY) -> tuple[list, list]:
    """Draw steps ``g*key`` .. ``g*key + key - 1`` of ``view``'s fill; leaves the view there.

    Returns
    -------
    places : list of [x, y]
        Where each image goes on the figure (pixels from the top left); [0, 0] for the key
        frame.
    pngs : list of bytes
        The key frame's PNG, then one patch per step (``b""`` when the step changed no pixel).
    """
    k0 = g * key
    stop = min(k0 + key, view.n_steps)
    if not 0 <= k0 < stop:
        raise ValueError(f"group {g} is outside the {view.n_steps} steps")

    def pictures():
        for k in range(k0, stop):
            view.show_step(k, draw=False)
            view.redraw()
            yield frame_rgba(view.fig)

    return encode_group(pictures())


def encode_group(pictures) -> tuple[list, list]:
    """A group from its pictures ((H, W, 4) uint8 each, all one size), in order: the first
    whole, then for each later one the rectangle of pixels that differ from the one before
    (``(places, pngs)`` as :func:`render_group` returns them)."""
    places, pngs, before = [], [], None
    for after in pictures:
        if before is None:
            places.append([0, 0])
            pngs.append(encode_png(after))
        else:
            box = changed_box(before, after)
            if box is None:
                places.append([0, 0])
                pngs.append(b"")
            else:
                r0, r1, c0, c1 = box
                places.append([c0, r0])
                pngs.append(encode_png(after[r0:r1, c0:c1]))
        before = after
    return places, pngs


def all_groups(view, key: int = KEY) -> list[tuple[list, list]]:
    """Every group of the view's fill (for a page with no kernel behind it)."""
    return [render_group(view, g, key) for g in range(-(-view.n_steps // key))]


def step_info(trace, k: int) -> str:
    """What the page shows after step ``k``'s number: ``"of 0–787 (pixel)"``.

    The steps are numbered from 0, as the slider, the captions and FillView's header number
    them: "9 of 17" read as the 9th of 17 steps where there are 18 (review r249 S5).
    """
    return f"of 0–{len(trace) - 1} ({trace.phase(trace.step(k))})"


def step_texts(trace) -> tuple[list[str], list[str]]:
    """Caption and "of 0–787 (pixel)" of every step, for the page to show beside its frame."""
    captions, infos = [], []
    for k in range(len(trace)):
        captions.append(trace.step(k).caption)
        infos.append(step_info(trace, k))
    return captions, infos


def encode_png(rgba: np.ndarray) -> bytes:
    """A (H, W, 4) uint8 image as PNG bytes: filter type 0 on every row, zlib level 1.

    >>> png = encode_png(np.zeros((2, 3, 4), dtype=np.uint8))
    >>> png[:8], png[12:16]
    (b'\\x89PNG\\r\\n\\x1a\\n', b'IHDR')
    """
    rgba = np.asarray(rgba, dtype=np.uint8)
    h, w, channels = rgba.shape
    if channels != 4:
        raise ValueError(f"expected an (H, W, 4) RGBA image, got shape {rgba.shape}")
    rows = np.zeros((h, 1 + 4 * w), dtype=np.uint8)  # a leading 0 per row: no filter
    rows[:, 1:] = rgba.reshape(h, 4 * w)
    header = struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)  # 8-bit RGBA, not interlaced
    return b"".join([b"\x89PNG\r\n\x1a\n", _chunk(b"IHDR", header),
                     _chunk(b"IDAT", zlib.compress(rows, 1)), _chunk(b"IEND", b"")])  # fmt: skip


def _chunk(kind: bytes, data: bytes) -> bytes:
    crc = zlib.crc32(data, zlib.crc32(kind))
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", crc)
