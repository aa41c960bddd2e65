"""Every widget in an offline page (``teachraster html``): its picture, live where it can be.

The list of widget classes comes from the package itself (every module of
``teachraster.widgets``), and each needs an example in ``tests/widget_examples.py``: a new
widget cannot be forgotten. Positions are cut to a few here (the page keeps up to 32).
"""

from __future__ import annotations

import base64
import inspect
import json
import re

import numpy as np
import pytest
from conftest import sample
from widget_examples import examples

from teachraster.widgets import offline

#: Widgets whose page steps or slides (the rest shows its picture).
LIVE = {"FillPlayer", "LinePlayer", "ZBufferStepper", "TileExplorer", "TexturedPlaneViewer",
        "FilterExplorer", "DepthPrecisionExplorer", "PlaneExplorer", "ProjectionExplorer",
        "SamplingExplorer", "SpanSubdivisionExplorer", "DivideCostExplorer", "PixelInspector", "CasePicker",
        "FrameInspector", "Predict", "HiZTileExplorer"}  # fmt: skip
#: Widgets that compute in the page (teachraster.widgets.explorable): live everywhere.
COMPUTED_IN_THE_PAGE = {"PipelineMap", "CrackExplorer", "EdgeFunctionExplorer",
                        "AttributeSurfaces", "EyeRayExplorer", "DepthValuesExplorer",
                        "FootprintExplorer", "DiamondExplorer", "PredictPixels", "PredictPoint",
                        "PredictOrder", "PredictChoice"}  # fmt: skip
LIVE |= COMPUTED_IN_THE_PAGE


def lesson_widget_classes() -> list[type]:
    """Classes a lesson displays: constructed by themselves (their own ``__init__``), not
    the parts other widgets are made of."""
    return [c for c in offline.widget_classes()
            if c.__name__ not in offline.PARTS and "__init__" in vars(c)]  # fmt: skip


@pytest.fixture
def few_positions(monkeypatch):
    monkeypatch.setattr(offline, "MOST_POSITIONS", 3)
    monkeypatch.setattr(offline, "MOST_STEPS", 3)


def test_every_widget_class_has_an_example():
    names = {c.__name__ for c in lesson_widget_classes()}
    assert names >= {"FillPlayer", "LinePlayer", "BlendingExplorer", "FrameInspector"}
    missing = names - set(examples())
    assert not missing, f"add an example of {sorted(missing)} to tests/widget_examples.py"


def _player_data(page_html: str) -> dict | None:
    match = re.search(r"mountStatic\([^,]+, (\{.*\})\);", page_html)
    return json.loads(match.group(1)) if match else None


def _png_sizes(page_html: str) -> list[tuple[int, int]]:
    sizes = []
    for b64 in re.findall(r'src="data:image/png;base64,([^"]+)"', page_html):
        png = base64.b64decode(b64)
        sizes.append((int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")))
    return sizes


@pytest.mark.parametrize("name", sample(sorted(examples()), keep=2))
def test_every_widget_shows_its_picture_offline(name, few_positions):
    widget = examples()[name]()
    try:
        page = offline.offline_page(widget)
    finally:
        widget.close()
    assert page.kind == ("live" if name in LIVE else "pictured"), page.html[:300]
    assert f'data-widget="{type(widget).__name__}"' in page.html
    assert not re.search(r"(src|href)=['\"]?(https?:)?//", page.html)  # nothing fetched
    data = _player_data(page.html)
    if name == "Predict":
        assert "<details>" in page.html and "The answer" in page.html
    elif name in COMPUTED_IN_THE_PAGE:  # its own module and data, inline: live with no kernel
        assert '<script type="module">' in page.html and "mountStatic(" in page.html
    elif data is not None:  # a player: as many pictures as captions, each group decodable
        assert data["n"] >= 2 and len(data["captions"]) == len(data["infos"]) == data["n"]
        assert sum(len(g["pngs"]) for g in data["groups"]) == data["n"]
        assert data["width"] > 100 and data["height"] > 100
    else:
        sizes = _png_sizes(page.html)
        assert sizes and max(w for w, _ in sizes) > 100, "no picture in the page"


def test_a_swept_page_shows_what_the_widget_shows_at_each_position(few_positions):
    from teachraster.widgets import LinePlayer

    player = LinePlayer((0.5, 0.5), (9.5, 4.5), 11, 6, backend="image")
    try:
        page = offline.swept_page(player)
        values = offline.control_positions(player.slider)
        assert values == [0, 6, 11] and player.slider.value == 11  # put back as it was
        data = _player_data(page.html)
        assert data["step"] == 2 and "of 2: step = 6" == data["infos"][1]
        assert data["captions"][1] == player.where(6)
        player.slider.value = 6
        shown = offline._rgba(bytes(player.display.widget.value))
        places, pngs = data["groups"][0]["places"], data["groups"][0]["pngs"]
        first = offline._rgba(base64.b64decode(pngs[0]))
        (x, y), patch = places[1], offline._rgba(base64.b64decode(pngs[1]))
        first[y : y + patch.shape[0], x : x + patch.shape[1]] = patch
        np.testing.assert_array_equal(first, shown)
    finally:
        player.close()


def test_pictures_drawn_ahead_become_a_slider(few_positions):
    from teachraster.widgets import TexturedPlaneViewer

    viewer = TexturedPlaneViewer(48, 36, tilt=30, backend="image")
    try:
        data = _player_data(offline.ahead_page(viewer).html)
        assert data["n"] == 3 and data["infos"][1].endswith("tilt (°) = 45")
        assert data["step"] == 1  # the position nearest the tilt on show (30)
        assert len({g for g in data["groups"][0]["pngs"][1:]}) == 2  # each tilt its picture
        assert viewer.tilt.value == 30  # the explorer as it was
    finally:
        viewer.close()


def test_the_hook_a_widget_implements_comes_first():
    class Custom:
        widget = None

        def _offline_page_(self):
            return offline.OfflinePage("<p>mine</p>", "live")

    page = offline.offline_page(Custom())
    assert page.kind == "live" and "<p>mine</p>" in page.html
    with pytest.raises(ValueError, match="kind"):
        offline.OfflinePage("", "sometimes")


def test_a_widget_that_fails_is_missing_and_says_why():
    class Broken:
        def _offline_page_(self):
            raise RuntimeError("no figure")

    page = offline.offline_page(Broken())
    assert page.kind == "missing" and "RuntimeError: no figure" in page.html


def test_install_displays_every_widget_class_as_one_offline_output(few_positions):
    from IPython.core.interactiveshell import InteractiveShell
    from IPython.utils.capture import capture_output

    from teachraster.widgets import BlendingExplorer

    shell = InteractiveShell.instance()
    try:
        assert offline.install(shell) == len(offline.widget_classes())
        explorer = BlendingExplorer(size=(16, 16), backend="image")
        with capture_output() as captured:
            shell.display_formatter.format(explorer)  # what the last expression of a cell does
        explorer.close()
        (out,) = captured.outputs
        assert out.metadata == {"teachraster": {"widget": "BlendingExplorer", "kind": "pictured"}}
        assert 'data-widget="BlendingExplorer"' in out.data["text/html"]
    finally:
        formatter = shell.display_formatter.ipython_display_formatter
        for cls in offline.widget_classes():
            formatter.type_printers.pop(cls, None)
        InteractiveShell.clear_instance()


def test_a_displayed_widget_class_without_init_is_a_base():
    bases = {c.__name__ for c in offline.widget_classes()} - {
        c.__name__ for c in lesson_widget_classes()}  # fmt: skip
    for name in bases - set(offline.PARTS):
        cls = next(c for c in offline.widget_classes() if c.__name__ == name)
        assert inspect.isclass(cls) and "__init__" not in vars(cls)


def test_positions_of_each_kind_of_control():
    import ipywidgets as w

    assert offline.control_positions(w.IntSlider(min=0, max=300)) == offline.thin(
        list(range(301)), offline.MOST_STEPS)  # fmt: skip
    assert offline.control_positions(w.FloatSlider(min=0, max=90, step=1))[:3] == [0, 3, 6]
    assert offline.control_positions(w.FloatLogSlider(base=2, min=0, max=2, step=1)) == [1, 2, 4]
    assert offline.control_positions(w.Dropdown(options=[("a", 1), ("b", 2)])) == [1, 2]
    assert offline.nearest([0.0, 3.0, 6.0], 4.0) == 1 and offline.nearest(["x", "y"], "z") == 0
