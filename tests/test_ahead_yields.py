"""A prediction's Check is answered before the work the kernel does ahead, in a real kernel.

Review r400 W1 (lesson 09): right after Run All, the first ``PredictPixels`` Check showed
"Checking…" for 43 s (load 12; 1.2-4 s here at load 2-8). The page's mark of a pixel had
reached the kernel at once, and waited there: ipykernel 7 handles a widget message over
several turns of its event loop (the shell channel's thread forwards it, two tasks, the
dispatch), and at every turn ``FilterExplorer`` drew its next truth and its next picture
ahead, so the mark's reply came 1.7 s late; the page's widget manager holds a model's next
message (the Check) until the last one's reply is in. Now the work done ahead waits while a
widget message has reached the kernel and is not handled yet
(``teachraster.widgets.common.messages_waiting``).

The page here is this test, talking to an ipykernel as JupyterLab does (comm messages on the
shell channel; the kernel's messages read on IOPub in the order it sent them). Every slice
done ahead (a truth, a picture) is slowed to take 0.3 s more and says so on IOPub when done; the
Check is sent while they run. The measure is their order, not the clock: at most the slice
under way when the Check arrived ends before its answer, and slices follow it (the work
ahead was not over, and it goes on).
"""

from __future__ import annotations

import time

import pytest

from teachraster.widgets import common

jupyter_client = pytest.importorskip("jupyter_client")
BaseComm = pytest.importorskip("ipykernel.comm.comm").BaseComm

SETUP = """
import functools, time
import numpy as np
from teachraster.widgets import FilterExplorer, PredictPixels, ahead, filter_explorer

ex = FilterExplorer(48, 36, tilt=0, filter="nearest", samples=3, backend="image")
q = PredictPixels("Which?", answer=np.eye(3, dtype=bool))

def slowed(work):  # 0.3 s more for every slice done ahead, said on IOPub once done
    @functools.wraps(work)
    def slow(*args, **kwargs):
        time.sleep(0.3)
        done = work(*args, **kwargs)
        ex.display.widget.send({"type": "slice"})
        return done
    return slow

ahead.FramesAhead.picture_at = slowed(ahead.FramesAhead.picture_at)
filter_explorer.footprint_average = slowed(filter_explorer.footprint_average)
ex._truths.clear()
ex.update()  # the truths at the other tilts, ahead
print(ex.display.widget.model_id, q.model_id)
"""

CHECK = {"method": "update", "buffer_paths": [],
         "state": {"state": {"given": [[0, 0]], "acted": False, "revealed": True}}}  # fmt: skip


def _comm_msg(client, comm_id: str, data: dict) -> None:
    """Send the kernel a comm message, as the page's widget manager does."""
    client.shell_channel.send(client.session.msg("comm_msg", {"comm_id": comm_id, "data": data}))


def _kind(msg, explorer: str, question: str) -> str | None:
    """``"slice"`` for a slice done ahead, ``"answer"`` for the question's state carrying the
    reveal; else None."""
    if msg["msg_type"] != "comm_msg":
        return None
    content = msg["content"]
    data = content.get("data", {})
    if content.get("comm_id") == explorer and data.get("content", {}).get("type") == "slice":
        return "slice"
    state = data.get("state", {}).get("state")
    if content.get("comm_id") == question and isinstance(state, dict) and "reveal" in state:
        return "answer"
    return None


def _events(client, explorer: str, question: str) -> list[str]:
    """The events "slice", "check" and "answer" in the order they happened, until two
    slices after the answer."""
    _comm_msg(client, explorer, {"method": "custom", "content": {"type": "ready"}})
    events: list[str] = []
    deadline = time.monotonic() + 240
    while time.monotonic() < deadline:
        if "answer" in events and events[events.index("answer") :].count("slice") >= 2:
            break
        kind = _kind(client.get_iopub_msg(timeout=60), explorer, question)
        if kind is not None:
            events.append(kind)
        if events.count("slice") == 3 and "check" not in events:  # the work ahead under way
            _comm_msg(client, question, CHECK)
            events.append("check")
    return events


@pytest.mark.notebook
@pytest.mark.skipif(not hasattr(BaseComm, "_reply_subshell_for"),
                    reason="this ipykernel forwards no message from a shell channel thread")  # fmt: skip
def test_a_check_is_answered_before_the_work_done_ahead_goes_on():
    manager, client = jupyter_client.manager.start_new_kernel(kernel_name="python3")
    printed = []

    def keep(msg):
        if msg["msg_type"] == "stream" and msg["content"]["name"] == "stdout":
            printed.append(msg["content"]["text"])

    try:
        reply = client.execute_interactive(SETUP, timeout=120, output_hook=keep)
        assert reply["content"]["status"] == "ok", reply["content"]
        events = _events(client, *"".join(printed).split())
    finally:
        client.stop_channels()
        manager.shutdown_kernel(now=True)
    assert "answer" in events, events
    between = events[events.index("check") + 1 : events.index("answer")]
    assert between.count("slice") <= 1, events  # the slice under way when the Check came
    assert events[events.index("answer") :].count("slice") >= 2, events  # and it goes on


def test_a_message_that_came_holds_the_pictures_drawn_ahead_until_it_is_handled():
    """Without a kernel: ``FramesAhead._run`` called by hand (as the loop calls it) draws
    nothing while a widget message waits, and draws once it is handled."""
    from teachraster.widgets import FilterExplorer

    ex = FilterExplorer(48, 36, tilt=0, filter="nearest", samples=3, backend="image")
    ahead, steps = ex._ahead, []
    step = ahead.step
    ahead.step = lambda seconds=0.0: steps.append(seconds) or step(seconds)
    ahead._schedule = lambda delay=0.0: None  # no event loop here: _run is called by hand
    ex.display.widget._handle_msg({"content": {"data": {"method": "custom",
                                                        "content": {"type": "ready"}}},
                                   "buffers": []})  # fmt: skip
    assert ahead.listening and ahead.todo
    common.message_arrived()  # as ipykernel's shell channel thread forwards one
    try:
        assert common.messages_waiting()
        ahead._run()
        assert steps == []  # held
    finally:
        ex.filter._handle_msg({"content": {"data": {"method": "update",
                                                    "state": {"index": 1}}}})  # fmt: skip
    assert ex.filter.value == "bilinear" and not common.messages_waiting()
    ahead._run()
    assert len(steps) == 1
    ex.close()


def test_a_message_that_never_reaches_a_widget_holds_nothing_for_long(monkeypatch):
    """A message counted on its way whose widget closed meanwhile is never handled: after
    ``WAIT_MOST_S`` it holds nothing back, and the count starts again from none."""
    common.message_arrived()
    assert common.messages_waiting()
    monkeypatch.setattr(common, "WAIT_MOST_S", -1.0)  # its time is up
    assert not common.messages_waiting()
    monkeypatch.undo()
    assert not common.messages_waiting()  # forgotten, not merely out of time
    common.message_arrived()
    assert common.messages_waiting()
    common._message_handled()
    assert not common.messages_waiting()
