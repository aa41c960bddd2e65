"""``FramesWidget``: the page-side player of a fill's frames, as an anywidget.

The frames are made by :mod:`teachraster.plotting.frames`; the page side is its
``static/frames.js``.
"""

from __future__ import annotations

import anywidget
import traitlets

from ..plotting.frames import KEY, frames_js


class FramesWidget(anywidget.AnyWidget):
    """The page-side player: buttons, a step slider, the caption and the frames.

    ``value`` is the step on show; the page sets it when the slider is released, a button
    pressed or Play paused (not at every step), and setting it from code moves the page.
    ``interval`` is milliseconds per step when playing. ``gen`` counts the fills shown:
    the page drops groups of an older one. Groups are made by ``source(g)``, a callable
    returning ``(places, pngs)``, when the page asks. ``fill`` names the fill on show (its
    method, interpolation and samples): the page keeps the decoded frames of the last few
    fills by that name, so a toggle back shows its picture as soon as the name arrives.
    """

    _esm = frames_js()
    value = traitlets.Int(0).tag(sync=True)
    n_steps = traitlets.Int(1).tag(sync=True)
    key = traitlets.Int(KEY).tag(sync=True)
    interval = traitlets.Int(400).tag(sync=True)
    captions = traitlets.List(traitlets.Unicode()).tag(sync=True)
    infos = traitlets.List(traitlets.Unicode()).tag(sync=True)
    poster = traitlets.Bytes(b"").tag(sync=True)
    frame_width = traitlets.Int(1).tag(sync=True)
    frame_height = traitlets.Int(1).tag(sync=True)
    gen = traitlets.Int(0).tag(sync=True)
    alt = traitlets.Unicode("").tag(sync=True)
    fill = traitlets.Unicode("").tag(sync=True)

    def __init__(self, source, **kwargs) -> None:
        super().__init__(**kwargs)
        self.source = source
        self.groups_sent = 0
        self.on_msg(self._on_page_message)

    @property
    def min(self) -> int:
        """0: the first step (as an IntSlider's ``min``)."""
        return 0

    @property
    def max(self) -> int:
        """The last step (as an IntSlider's ``max``)."""
        return self.n_steps - 1

    def _on_page_message(self, _widget, content, _buffers) -> None:
        if content.get("type") != "group" or content.get("gen") != self.gen:
            return  # a request for an earlier fill
        g = int(content["group"])
        self.send_group(g, *self.source(g))

    def send_group(self, g: int, places: list, pngs: list) -> None:
        """Send group ``g`` of the fill on show (``places`` and PNG bytes) to the page.

        The message names each picture's length (``sizes``): the page checks the buffers it
        receives against them and says so on the console when they differ."""
        if len(places) != len(pngs):
            raise ValueError(f"pngs: {len(pngs)} pictures for {len(places)} places")
        self.groups_sent += 1
        self.send({"type": "group", "group": g, "gen": self.gen, "places": places,
                   "sizes": [len(p) for p in pngs]}, list(pngs))  # fmt: skip
