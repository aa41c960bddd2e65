"""The pictures' bytes between the kernel and the page: packed one buffer per picture, each
named by its length, and checked by the page (``static/page.js``, ``static/frames.js``).

Lesson 02 in JupyterLab on a loaded machine once received a group message whose buffers were
the frames of another message (a kernel's ``stream`` output: its topic, ``<IDS|MSG>``, its
signature and JSON), seen in the WebSocket frame itself; decoded as PNGs they failed as "The
source image cannot be decoded." (a fresh-clone CI run failed so, in lesson 03). The kernel
sends every picture as its own buffer with its length in the message; the page checks both
and names what it got on the console (``teachraster:``), where the browser tests look.

The JavaScript half runs in node (skipped, saying why, where node is missing).
"""

from __future__ import annotations

import base64
import json
import struct
import subprocess
import tempfile
import zlib
from pathlib import Path

import numpy as np
import pytest
from explorables_node import NODE

from teachraster.plotting.frames import encode_group, encode_png, frames_js

SIGNATURE = b"\x89PNG\r\n\x1a\n"


def png_problem(data: bytes) -> str:
    """What is wrong with ``data`` as a PNG ("" when sound), as page.js's pngProblem reads it."""
    if not data.startswith(SIGNATURE):
        return "no PNG signature"
    at = 8
    while at + 12 <= len(data):
        (n,) = struct.unpack(">I", data[at : at + 4])
        kind = data[at + 4 : at + 8]
        if at + 12 + n > len(data):
            return f"chunk {kind} truncated"
        (crc,) = struct.unpack(">I", data[at + 8 + n : at + 12 + n])
        if zlib.crc32(data[at + 4 : at + 8 + n]) != crc:
            return f"chunk {kind}: wrong CRC"
        at += 12 + n
        if kind == b"IEND":
            return "" if at == len(data) else "bytes after IEND"
    return "no IEND"


def _pictures(n: int = 5) -> list[np.ndarray]:
    """n pictures 12 x 16: a square moving right, one step changing nothing."""
    out = []
    for k in range(n):
        rgba = np.full((12, 16, 4), 255, np.uint8)
        x = min(k, n - 2) * 2  # the last two the same: an empty patch
        rgba[3:7, x : x + 4, :3] = (200, 40, 40)
        out.append(rgba)
    return out


def test_a_group_is_one_sound_png_per_place_or_empty_bytes():
    places, pngs = encode_group(_pictures())
    assert len(places) == len(pngs) == 5
    assert pngs[-1] == b""  # the step that changed nothing
    for png in pngs[:-1]:
        assert png_problem(png) == "", png[:16]
    assert places[0] == [0, 0]


def test_the_group_message_names_each_pictures_length():
    from teachraster.widgets.frames import FramesWidget

    places, pngs = encode_group(_pictures())
    widget = FramesWidget(lambda g: (places, pngs))
    sent = []
    widget.send = lambda content, buffers=None: sent.append((content, buffers))
    widget._on_page_message(widget, {"type": "group", "group": 0, "gen": widget.gen}, [])
    [(content, buffers)] = sent
    assert content["places"] == places
    assert content["sizes"] == [len(p) for p in pngs] and content["sizes"][-1] == 0
    assert buffers == pngs and all(isinstance(b, bytes) for b in buffers)
    with pytest.raises(ValueError, match="pngs: 4 pictures for 5 places"):
        widget.send_group(0, places, pngs[:-1])
    widget.close()


def test_a_png_python_reads_as_sound_is_broken_by_each_kind_of_damage():
    png = encode_png(_pictures()[1])
    assert png_problem(png) == ""
    assert png_problem(png[:-5]) != ""  # truncated
    assert png_problem(png + png) == "bytes after IEND"  # two pictures run together
    flipped = bytearray(png)
    flipped[40] ^= 1
    assert "wrong CRC" in png_problem(bytes(flipped))
    assert png_problem(b"{}") == "no PNG signature"


# -- the page's side, in node ---------------------------------------------------------------

DRIVER = r"""
import { readFileSync } from "node:fs";
const m = await import(process.argv[2]);
const { good, other } = JSON.parse(readFileSync(process.argv[3], "utf8"));
const bytes = (b64) => Uint8Array.from(Buffer.from(b64, "base64"));
const png = bytes(good);
const flipped = png.slice();
flipped[50] ^= 1; // inside IDAT's data (IHDR is bytes 8-32)
const both = new Uint8Array([...png, ...bytes(other)]);
// the same PNG as a DataView in the middle of a larger buffer, as a message might hand it
const big = new Uint8Array(png.byteLength + 100).fill(7);
big.set(png, 60);
const inside = new DataView(big.buffer, 60, png.byteLength);
const text = new TextEncoder();
const problems = {
  sound: m.pngProblem(png),
  dataView: m.pngProblem(inside),
  wholeBuffer: m.pngProblem(inside.buffer), // what `.buffer` of that view would give
  truncated: m.pngProblem(png.subarray(0, 60)),
  noEnd: m.pngProblem(png.subarray(0, png.byteLength - 12)),
  flipped: m.pngProblem(flipped),
  twoPictures: m.pngProblem(both),
  empty: m.pngProblem(new Uint8Array(0)),
  stream: m.pngProblem(text.encode("stream.stdout")),
};
const view = m.asBytes(inside);
const places = [[0, 0], [2, 3]];
const out = {
  problems,
  asBytes: [view.byteLength, view[0], view[view.byteLength - 1]],
  describe: m.describePng(inside),
  describeBad: m.describePng(text.encode("<IDS|MSG>")),
  matching: m.groupMismatch({ group: 1, places, sizes: [png.byteLength, 0] },
    [new DataView(png.buffer), new DataView(new ArrayBuffer(0))]),
  fewer: m.groupMismatch({ group: 1, places, sizes: [png.byteLength, 0] },
    [new DataView(text.encode("stream.stdout").buffer)]),
  otherSizes: m.groupMismatch({ group: 2, places, sizes: [png.byteLength, 0] },
    [new DataView(text.encode("<IDS|MSG>").buffer), new DataView(text.encode("{}").buffer)]),
};
process.stdout.write(JSON.stringify(out));
"""


@pytest.fixture(scope="module")
def page_checks() -> dict:
    """page.js's and frames.js's checks, run in node on damaged and sound bytes."""
    if NODE is None:
        pytest.skip("node is not installed (the page-side checks run in node)")
    pictures = _pictures()
    good, other = encode_png(pictures[0]), encode_png(pictures[1])
    with tempfile.TemporaryDirectory(prefix="tr-node-") as tmp:
        module, driver, data = Path(tmp, "m.mjs"), Path(tmp, "run.mjs"), Path(tmp, "in.json")
        module.write_text(frames_js(), encoding="utf-8")
        driver.write_text(DRIVER, encoding="utf-8")
        data.write_text(json.dumps({k: base64.b64encode(v).decode() for k, v in
                                    (("good", good), ("other", other))}))  # fmt: skip
        done = subprocess.run([NODE, str(driver), module.as_uri(), str(data)],
                              capture_output=True, text=True, timeout=120)  # fmt: skip
    assert done.returncode == 0, done.stderr[-3000:]
    return json.loads(done.stdout) | {"length": len(good)}


def test_the_page_reads_a_sound_png_where_it_lies_in_its_buffer(page_checks):
    p = page_checks["problems"]
    assert p["sound"] == p["dataView"] == ""
    assert p["wholeBuffer"] == "no PNG signature"  # a view's .buffer is not its bytes
    n = page_checks["length"]
    assert page_checks["asBytes"] == [n, 0x89, 0x82]  # IEND's CRC ends in 0x82
    assert page_checks["describe"] == (
        f"{n} bytes, a DataView at 60 of a {n + 100}-byte buffer, starting "
        "89 50 4e 47 0d 0a 1a 0a, a sound PNG of 16 x 12 px"
    )


def test_the_page_names_each_kind_of_damage(page_checks):
    p = page_checks["problems"]
    assert p["truncated"].startswith('chunk "IDAT" at 33 needs') and "are left" in p["truncated"]
    assert p["noEnd"] == f"no IEND: 0 bytes left at {page_checks['length'] - 12}"
    assert p["flipped"].startswith('chunk "IDAT" at 33') and p["flipped"].endswith("wrong CRC")
    assert p["twoPictures"].endswith("bytes after IEND")
    assert p["empty"] == "no bytes"
    assert p["stream"] == "no PNG signature"
    assert page_checks["describeBad"].startswith("9 bytes, a Uint8Array at 0")
    assert page_checks["describeBad"].endswith("not a sound PNG: no PNG signature")


def test_the_page_checks_a_groups_buffers_against_its_places_and_sizes(page_checks):
    assert page_checks["matching"] == ""
    assert page_checks["fewer"].startswith("group 1 came with 1 buffers of [13] bytes for 2 places")
    assert '"stream.stdou"' in page_checks["fewer"]
    assert page_checks["otherSizes"].startswith("group 2 came with 2 buffers of [9,2] bytes")
    assert '"<IDS|MSG>"' in page_checks["otherSizes"]
