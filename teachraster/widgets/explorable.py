"""Explorables computed in the page: a widget whose pictures the browser draws by itself.

The slider explorers and editors before these draw in the kernel (matplotlib, then pixels to
the page: a round trip per picture). An explorable instead carries its rules to the page:
the kernel sends the data once (a triangle, a scene's derivatives, the tour triangle's
stages), and the page's module (plain JavaScript in ``static/``, no build, no CDN) computes
and draws every picture itself, at the screen's frame rate, with no kernel in the loop. The
kernel hears of the state at each release (``state``), so ``explorer.state`` says where the
student left it, and setting it from code moves the page.

Because the rules then exist twice, each page-side rule is checked against the engine: the
tests run the module's pure functions with node on the engine's inputs and compare
(``tests/test_explorables_js.py``).

One module, three places
    In a notebook the module is an anywidget's ESM. In a ``teachraster html`` page (no
    kernel) the same module is inlined in a ``<script type="module">`` and mounted on the
    data the kernel computed, so the exported page stays live. A notebook saved with its
    outputs and reopened without running keeps a stand-in (:func:`standin_html`): the title,
    the last picture the page drew (sent by the page a moment after each change) and a hint
    that works: Run All (the cell's names come from the cells above it).

Writing one
    Subclass :class:`Explorable`, set ``_esm = esm_source("lib", ..., "explore_x")`` and
    ``noun``, and fill ``data`` (JSON-ready, the page never changes it) and ``state`` (what
    the student changes) in ``__init__``. The page's file defines ``mount(el, data, host)``
    (see ``static/explore_base.js``).
"""

from __future__ import annotations

import base64
import binascii
import json
import os
import uuid
from pathlib import Path

import anywidget
import traitlets

from ..plotting.frames import keys_js
from .common import FALLBACK_CSS, standin_html

STATIC = Path(__file__).parent / "static"


def esm_source(*parts: str) -> str:
    """The page-side module of an explorable: ``keys.js`` (the package's key guard, from
    ``teachraster/plotting/static``), ``explore_base.js``, then ``parts`` in order.

    Each part is a file of ``static/`` without its ``.js``. They are joined into one module
    (anywidget loads one ESM; an offline page inlines it), so they share one scope: names
    must not repeat across parts.
    """
    names = ("explore_base", *parts)
    text = keys_js() + "\n".join(
        f"// ---- {n}.js\n" + (STATIC / f"{n}.js").read_text("utf-8") for n in names
    )
    if "</script" in text.lower():  # would end an offline page's inline script early
        raise ValueError(f"{names}: a module may not contain '</script'")
    return text


def static_pages() -> bool:
    """True while ``teachraster html`` executes a lesson (its outputs become one page)."""
    return os.environ.get("TEACHRASTER_STATIC_PAGES") == "1"


def offline_html(esm: str, data: dict, state: dict, *, css_class: str = "") -> str:
    """A ``<div>`` and the inline module that mounts the explorable in it, with no kernel."""
    element = f"tr-x-{uuid.uuid4().hex[:12]}"
    payload = json.dumps([data, state], separators=(",", ":")).replace("</", "<\\/")
    return (
        f'<div id="{element}" class="teachraster-explorable {css_class}"></div>\n'
        f'<script type="module">\n{esm}\n'
        f"const [DATA, STATE] = {payload};\n"
        f'mountStatic(document.getElementById("{element}"), DATA, STATE);\n</script>\n'
    )


def png_from_data_url(url: str) -> bytes:
    """The PNG bytes of a ``data:image/png;base64,...`` URL (empty if it is not one)."""
    prefix = "data:image/png;base64,"
    if not isinstance(url, str) or not url.startswith(prefix):
        return b""
    try:
        png = base64.b64decode(url[len(prefix) :], validate=True)
    except (binascii.Error, ValueError):
        return b""
    return png if png.startswith(b"\x89PNG\r\n\x1a\n") else b""


class Explorable(anywidget.AnyWidget):
    """Base of the explorables drawn in the page (see the module docstring).

    Attributes
    ----------
    data : dict
        What the page computes from (sent once; JSON-ready); ``title`` is added.
    state : dict
        What the student changed, as of the last release in the page (set it from code to
        move the page).
    picture : bytes
        The PNG of the last picture the page drew (empty until a page has drawn one).
    """

    data = traitlets.Dict().tag(sync=True)
    state = traitlets.Dict().tag(sync=True)
    #: how the stand-in's hint names it (:func:`~teachraster.widgets.common.standin_hint`)
    noun = "explorable"
    #: the stand-in's title
    title = "An explorable"

    @traitlets.validate("data")
    def _titled(self, proposal) -> dict:
        """The page shows the class's title: one place for it."""
        return {"title": self.title, **proposal["value"]}

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.picture = b""
        self._standin_id: str | None = None
        self.on_msg(self._on_page_message)

    def _on_page_message(self, _widget, content, _buffers) -> None:
        if content.get("type") != "picture":
            return
        png = png_from_data_url(content.get("png", ""))
        if png:
            self.picture = png
            self._update_standin()

    def standin_text(self) -> str:
        """HTML the stand-in shows above the picture (a question, a caption): none here."""
        return ""

    def offline_html(self) -> str:
        """This explorable as an offline page fragment (live with no kernel)."""
        return offline_html(self._esm, self.data, self.state)

    def _offline_page_(self):
        """``teachraster html``'s hook (:mod:`.offline`): the page computes this explorable
        itself, so it is live there, as it is in a notebook."""
        from .offline import OfflinePage

        return OfflinePage(self.offline_html(), "live")

    def _standin(self) -> str:
        return FALLBACK_CSS + standin_html(self.title, self.noun, self.picture,
                                           self.standin_text())  # fmt: skip

    def _update_standin(self) -> None:
        if self._standin_id is None:
            return
        from IPython.display import update_display

        update_display({"text/html": self._standin(), "text/plain": self.title}, raw=True,
                       display_id=self._standin_id)  # fmt: skip

    def _repr_mimebundle_(self, **kwargs):
        bundle = super()._repr_mimebundle_(**kwargs)
        data = bundle[0] if isinstance(bundle, tuple) else bundle
        # where no widget can live (an HTML export, a viewer): the page computes it alone
        data["text/html"] = self._fallback_html()
        return bundle

    def _fallback_html(self) -> str:
        """The HTML of its output where no widget lives (a viewer): :meth:`offline_html`."""
        return self.offline_html()

    def _ipython_display_(self) -> None:
        from IPython.display import publish_display_data

        bundle = self._repr_mimebundle_()
        data = bundle[0] if isinstance(bundle, tuple) else bundle
        if static_pages():  # `teachraster html`: one output, shown by its offline HTML
            publish_display_data(data)
            return
        # the stand-in in an output of its own, before the widget: what a reopened notebook
        # shows (hidden by FALLBACK_CSS while the widget is live)
        self._standin_id = f"teachraster-standin-{uuid.uuid4().hex}"
        publish_display_data({"text/html": self._standin(), "text/plain": self.title},
                             transient={"display_id": self._standin_id})  # fmt: skip
        publish_display_data(data)
