"""Offline pages that step through a fill: no kernel, no network, one file.

The page carries the frames of :mod:`teachraster.plotting.frames` as base64 PNGs, the
captions, and the player's own script (``static/frames.js``, inlined): it steps and plays
in any browser, from a file, a slide or a course website. ``teachraster fill ... -o
fill.html`` writes one; every ``teachraster.widgets.FillPlayer`` carries one as the
HTML fallback of its output, so a lesson exported with ``teachraster html`` still steps
through its fills.
"""

from __future__ import annotations

import base64
import html
import itertools
import json

import numpy as np

from .frames import KEY, all_groups, encode_group, frame_rgba, frames_js, step_texts

_ids = itertools.count()


def page_data(view, *, step: int = 0, interval: int = 400, key: int = KEY) -> dict:
    """Everything the page needs, as JSON-ready data (draws every step of ``view``)."""
    trace = view.trace
    captions, infos = step_texts(trace)
    groups = [
        {"places": places, "pngs": [base64.b64encode(p).decode("ascii") for p in pngs]}
        for places, pngs in all_groups(view, key)
    ]
    height, width = frame_rgba(view.fig).shape[:2]
    return {"width": width, "height": height, "n": len(trace), "key": key,
            "step": trace.index(step), "interval": interval, "captions": captions,
            "infos": infos, "groups": groups,
            "alt": f"the {trace.method} fill of a triangle, step by step"}  # fmt: skip


def sequence_data(pictures, captions, infos, *, step: int = 0, interval: int = 400,
                  alt: str = "", key: int = KEY) -> dict:  # fmt: skip
    """:func:`page_data` for any sequence of pictures ((H, W, 4) uint8 each) with a caption
    and an info text each: a slider explorer's figure at every position of its slider, a
    player's at every step. Smaller pictures are padded with white to the largest.
    """
    pictures = [np.asarray(p, dtype=np.uint8) for p in pictures]
    if not pictures or not len(pictures) == len(captions) == len(infos):
        raise ValueError(
            f"need as many captions and infos as pictures (at least one), got "
            f"{len(pictures)}, {len(captions)}, {len(infos)}"
        )
    height = max(p.shape[0] for p in pictures)
    width = max(p.shape[1] for p in pictures)
    pictures = [np.pad(p, ((0, height - p.shape[0]), (0, width - p.shape[1]), (0, 0)),
                       constant_values=255) for p in pictures]  # fmt: skip
    groups = []
    for g in range(0, len(pictures), key):
        places, pngs = encode_group(pictures[g : g + key])
        groups.append({"places": places,
                       "pngs": [base64.b64encode(p).decode("ascii") for p in pngs]})  # fmt: skip
    return {"width": width, "height": height, "n": len(pictures), "key": key,
            "step": int(step) % len(pictures), "interval": interval,
            "captions": list(captions), "infos": list(infos), "groups": groups,
            "alt": alt}  # fmt: skip


def player_fragment(data: dict) -> str:
    """A ``<div>`` and the ``<script type="module">`` that mounts the player in it.

    Several fragments can share a page: each mounts into its own element.
    """
    element = f"teachraster-page-{next(_ids)}"
    # "</" cannot end the script early inside JSON: escape it
    payload = json.dumps(data, separators=(",", ":")).replace("</", "<\\/")
    module = frames_js()
    return (
        f'<div id="{element}" class="teachraster-page"></div>\n'
        f'<script type="module">\n{module}\n'
        f'mountStatic(document.getElementById("{element}"), {payload});\n</script>\n'
    )


def standalone_page(data: dict, title: str) -> str:
    """A whole HTML document around :func:`player_fragment`."""
    return (
        "<!DOCTYPE html>\n<html lang='en'>\n<head>\n<meta charset='utf-8'>\n"
        f"<title>{html.escape(title)}</title>\n"
        "<meta name='viewport' content='width=device-width, initial-scale=1'>\n"
        "<style>body{margin:16px;font-family:sans-serif;max-width:1000px}</style>\n"
        f"</head>\n<body>\n<h1 style='font-size:1.3em'>{html.escape(title)}</h1>\n"
        f"{player_fragment(data)}</body>\n</html>\n"
    )


def page_figure(width: int, height: int, *, dpi: float = 96):
    """A figure (Agg canvas, not in pyplot) and Axes laid out like the FillPlayer's.

    Fixed margins: above for the column labels, left for the row labels, right for the
    colour key; the longer side of the grid is 4.4 inches, as in the player.
    """
    import matplotlib as mpl
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    s = float(mpl.rcParams["font.size"]) / 10.0
    side = 4.4
    aw, ah = (side, side * height / width) if width >= height else (side * width / height, side)
    left, right, top, bottom = 0.65 * s, 2.1 * s, 0.85 * s, 0.15
    fw, fh = left + aw + right, top + ah + bottom
    fig = Figure(figsize=(fw, fh), dpi=dpi)
    FigureCanvasAgg(fig)
    return fig, fig.add_axes((left / fw, bottom / fh, aw / fw, ah / fh))
