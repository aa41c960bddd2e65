"""The FillPlayer's note while the kernel is slow (``static/frames.js``), in node.

Review r97 00-1: on a loaded machine (load 7 on 2 cores) the player of lesson 00 said "The
kernel does not answer (stopped or restarted?): Run All ..." under a picture that had come;
a student told so runs everything again and loses the state. Run All is suggested only after
a minute of silence, and the advice goes when the late answer comes. Review r9: a step
awaited showed two notes for one state after 4 s ("drawing step k…" over the dimmed picture,
"Waiting for the kernel…" at its foot); now the step's note is the only one, and it is the
one that turns into the advice. Here the player is mounted on a small stand-in DOM with a
clock the test moves, and the kernel's answer is delayed at will.
"""

from __future__ import annotations

import json
import subprocess
import tempfile
from pathlib import Path

import pytest
from explorables_node import NODE

from teachraster.plotting.frames import frames_js

DRIVER = r"""
// a clock the script moves: setTimeout callbacks run when `advance` passes their time
let now = 0;
let timers = [];
globalThis.performance = { now: () => now };
globalThis.setTimeout = (f, ms) => { timers.push({ at: now + (ms ?? 0), f }); return timers.length; };
globalThis.setInterval = () => 0;
globalThis.clearInterval = () => {};
async function advance(ms) {
  const end = now + ms;
  for (;;) {
    timers.sort((a, b) => a.at - b.at);
    if (!timers.length || timers[0].at > end) break;
    const t = timers.shift();
    now = t.at;
    t.f();
    await Promise.resolve();
  }
  now = end;
}
// just enough DOM for mountFrames
function element() {
  return {
    children: [], dataset: {}, style: {}, textContent: "", value: "",
    append(...c) { this.children.push(...c); }, appendChild(c) { this.children.push(c); },
    replaceChildren(...c) { this.children = c; }, setAttribute() {}, addEventListener() {},
    getContext: () => ({ drawImage() {} }),
    classList: { add() {}, remove() {}, toggle() {}, contains: () => false },
  };
}
globalThis.document = {
  createElement: element, createElementNS: element, getElementById: () => ({}),
};
const mod = await import(process.argv[2]);
const asked = [];
const el = element();
const player = mod.mountFrames(el, { request: (g, gen) => asked.push([g, gen]) });
// root > stage > [canvas, the "drawing step" note]: the player's one note
const stage = el.children[0].children[2];
const note = stage.children[1];
const out = { notes: stage.children.length - 1 };
await player.reset({ width: 4, height: 4, n: 32, key: 16, step: 0, captions: [], infos: [],
                     gen: 1 });
out.askedFirst = asked.length;
out.at0 = note.textContent;
await advance(2000);
out.at2 = note.textContent;
await advance(8000);
out.at10 = note.textContent;
await advance(60000);
out.at70 = note.textContent;
const empty = new Array(16).fill(null);
await player.addGroup(0, empty.map(() => [0, 0]), empty, 1);  // the late answer
out.afterAnswer = note.textContent;
await advance(8000);  // group 1 asked after group 0 came, its picture not awaited yet
out.nextGroup = note.textContent;
player.show(20);  // a step of group 1: awaited now, the silence counted from group 1's ask
out.step20 = note.textContent;
await advance(55000);
out.step20At63 = note.textContent;
await player.addGroup(1, empty.map(() => [0, 0]), empty, 1);  // it comes: painted, no note
out.step20Came = note.textContent;
await player.reset({ width: 4, height: 4, n: 32, key: 16, step: 0, captions: [], infos: [],
                     gen: 2 });
out.afterNewFill = note.textContent;
await advance(1500);
out.newFillSoon = note.textContent;
out.texts = [mod.waitingNote(3, null), mod.waitingNote(3, mod.SILENT_MS - 1),
             mod.waitingNote(3, mod.SILENT_MS + 1000)];
out.limits = [mod.SILENT_MS];
process.stdout.write(JSON.stringify(out));
"""


def _run() -> dict:
    if NODE is None:
        pytest.skip("node is not installed (the player's page side runs in node)")
    with tempfile.TemporaryDirectory(prefix="tr-node-") as tmp:
        module, driver = Path(tmp, "frames.mjs"), Path(tmp, "run.mjs")
        module.write_text(frames_js(), encoding="utf-8")
        driver.write_text(DRIVER, encoding="utf-8")
        done = subprocess.run([NODE, str(driver), module.as_uri()], capture_output=True,
                              text=True, timeout=120)  # fmt: skip
    assert done.returncode == 0, done.stderr[-3000:]
    return json.loads(done.stdout)


STEP_0 = "drawing step 0\u2026 (its picture comes from the kernel)"


def test_a_slow_kernel_is_waited_for_under_one_note_and_a_late_answer_clears_it():
    got = _run()
    assert got["notes"] == 1  # r9: one note for one state, no second "Waiting" at the foot
    assert got["askedFirst"] == 1
    # the step's note at once and while the kernel is busy: calm, no Run All
    assert got["at0"] == got["at2"] == got["at10"] == STEP_0
    # only after a minute of silence the same note turns into the advice, not as a verdict
    assert "has not answered for 70 s" in got["at70"] and "Run All" in got["at70"]
    assert "If it is still busy" in got["at70"]
    assert got["afterAnswer"] == ""  # the late answer clears it (step 0's picture came)
    assert got["nextGroup"] == ""  # a group fetched ahead, no step waiting for it: no note
    # a step of the group on its way: its note, the silence counted from that group's ask
    assert got["step20"].startswith("drawing step 20")
    assert "has not answered for 63 s" in got["step20At63"]
    assert got["step20Came"] == ""
    # a toggle starts clean: the new fill's step note, no advice carried over
    assert got["afterNewFill"] == got["newFillSoon"] == STEP_0


def test_the_limit_is_generous_and_the_page_says_waiting_once():
    got = _run()
    (silent,) = got["limits"]
    assert silent >= 30000  # r97: "generous (>= 15 s)" for the strong words
    step_3 = "drawing step 3\u2026 (its picture comes from the kernel)"
    assert got["texts"][0] == got["texts"][1] == step_3
    assert got["texts"][2].startswith("The kernel has not answered for 61 s")
    assert "tr-notice" not in frames_js()  # the second note (at the picture's foot) is gone
