"""What the page receives is what the kernel holds: no widget changes a synced trait in place.

A traitlets ``Dict`` or ``List`` is sent to the page when it is assigned, never when it is
changed in place: ``self.state["show"] = ...`` after ``self.state = {...}`` left the page on
its own default (review r250 04-W1: lesson 04's 3-D view opened with the f/w and 1/w planes
off and the affine plane on, the reverse of what its text says), while ``widget.state`` in
the kernel looked right. These tests record every message a widget sends to the page, fold
them into the state the page holds, and compare it with the kernel's.
"""

from __future__ import annotations

import json

import comm
import ipywidgets
import pytest
from comm.base_comm import BaseComm
from ipywidgets.widgets.widget import _remove_buffers
from widget_examples import examples

from teachraster.widgets import AttributeSurfaces


class RecordingComm(BaseComm):
    """A comm that keeps what the kernel sends instead of sending it."""

    def __init__(self, *args, **kwargs) -> None:
        self.sent: list[tuple[str, dict]] = []
        super().__init__(*args, **kwargs)

    def publish_msg(self, msg_type, data=None, metadata=None, buffers=None, **keys) -> None:
        # serialised now, as a kernel's comm does: a later change in place must not reach it
        self.sent.append((msg_type, json.loads(json.dumps(data or {}, default=repr))))


@pytest.fixture
def recorded(monkeypatch):
    """Widgets made in the test send to a :class:`RecordingComm`; a function that lists them
    (closed after the test)."""
    instances = ipywidgets.widgets.widget._instances
    before = set(instances)
    monkeypatch.setattr(comm, "create_comm", RecordingComm)

    def made() -> list:
        return [w for k, w in list(instances.items()) if k not in before]

    yield made
    for w in made():
        w.close()


def page_state(widget) -> dict:
    """The state the page holds: the state sent at the opening, updated by each later one."""
    state: dict = {}
    for kind, data in widget.comm.sent:
        if kind == "comm_open":
            state.update(data["state"])
        elif kind == "comm_msg" and data.get("method") in ("update", "echo_update"):
            state.update(data["state"])
    return state


def assert_page_has_kernel_state(widgets) -> None:
    assert widgets, "no widget was made"
    for widget in widgets:
        held, _paths, _buffers = _remove_buffers(widget.get_state())
        held = json.loads(json.dumps(held, default=repr))  # as sent: tuples become lists
        page = page_state(widget)
        for key, value in held.items():
            assert page.get(key) == value, (type(widget).__name__, key, page.get(key), value)


def test_attribute_surfaces_sends_the_sheets_it_opens_on(recorded):
    """Review r250 04-W1: the sheets asked for reach the page (lesson 04: f, f/w, 1/w on,
    the affine plane off)."""
    surfaces = AttributeSurfaces(w=[1.0, 2.0, 4.0], show=["correct", "fw", "inv"])
    page = page_state(surfaces)
    assert page["state"]["show"] == {"correct": True, "affine": False, "fw": True, "inv": True}
    assert page["state"]["w"] == [1.0, 2.0, 4.0]
    assert_page_has_kernel_state(recorded())


@pytest.mark.parametrize(
    "name",
    ["AttributeSurfaces", "EyeRayExplorer", "PipelineMap", "CrackExplorer",
     "EdgeFunctionExplorer", "DepthValuesExplorer", "FootprintExplorer", "DiamondExplorer",
     "PredictPoint", "PredictPixels", "PredictOrder", "PredictChoice", "Predict"],
)  # fmt: skip
def test_the_page_opens_on_the_kernels_state(name, recorded):
    """Every explorable computed in the page, and every question, as made: each synced trait
    the page received equals the kernel's."""
    examples()[name]()
    assert_page_has_kernel_state(recorded())
