"""The FillPlayer's notice while the kernel is slow (``static/frames.js``), in node.

Review r97 00-1: on a loaded machine (load 7 on 2 cores) the player of lesson 00 said "The
kernel does not answer (stopped or restarted?): Run All ..." under a picture that had come;
a student told so runs everything again and loses the state. The page now says "Waiting for
the kernel…" first, suggests Run All only after a minute of silence, and clears the notice
when the late answer comes. Here the player is mounted on a small stand-in DOM with a clock
the test moves, and the kernel's answer is delayed at will.
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
    classList: { add() {}, remove() {}, contains: () => false },
  };
}
globalThis.document = {
  createElement: element, createElementNS: element, getElementById: () => ({}),
};
const mod = await import(process.argv[2]);
const asked = [];
const el = element();
const player = mod.mountFrames(el, { request: (g, gen) => asked.push([g, gen]) });
// root > stage > [canvas, the "drawing step" note, notice]
const notice = el.children[0].children[2].children[2];
const out = {};
await player.reset({ width: 4, height: 4, n: 32, key: 16, step: 0, captions: [], infos: [],
                     gen: 1 });
out.askedFirst = asked.length;
await advance(2000);
out.at2 = notice.textContent;
await advance(8000);
out.at10 = notice.textContent;
await advance(60000);
out.at70 = notice.textContent;
const empty = new Array(16).fill(null);
await player.addGroup(0, empty.map(() => [0, 0]), empty, 1);  // the late answer
out.afterAnswer = notice.textContent;
await advance(8000);  // group 1 asked after group 0 came: waiting again, counted afresh
out.nextGroup = notice.textContent;
await player.reset({ width: 4, height: 4, n: 32, key: 16, step: 0, captions: [], infos: [],
                     gen: 2 });
out.afterNewFill = notice.textContent;
await advance(1500);
out.newFillSoon = notice.textContent;
out.texts = [mod.waitingNotice(0), mod.waitingNotice(mod.WAIT_MS),
             mod.waitingNotice(mod.SILENT_MS + 1000)];
out.limits = [mod.WAIT_MS, mod.SILENT_MS];
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


def test_a_slow_kernel_is_waited_for_and_a_late_answer_clears_the_notice():
    got = _run()
    assert got["askedFirst"] == 1
    assert got["at2"] == ""  # a few seconds: nothing said
    assert got["at10"].startswith("Waiting for the kernel")  # calm, no Run All
    assert "Run All" not in got["at10"] and "stopped" not in got["at10"]
    # only after a minute of silence the advice, and not as a verdict
    assert "has not answered for 70 s" in got["at70"] and "Run All" in got["at70"]
    assert "If it is still busy" in got["at70"]
    assert got["afterAnswer"] == ""  # the late answer clears it
    assert got["nextGroup"].startswith("Waiting")  # the next group's wait counted afresh
    assert got["afterNewFill"] == "" and got["newFillSoon"] == ""  # a toggle starts clean


def test_the_limits_are_generous():
    got = _run()
    wait, silent = got["limits"]
    assert wait >= 3000 and silent >= 30000  # r97: "generous (>= 15 s)" for the strong words
    assert got["texts"][0] == ""
    assert got["texts"][1].startswith("Waiting for the kernel")
