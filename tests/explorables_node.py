"""Run the explorables' page-side functions with node: the JS half of the cross-checks.

:func:`call_js` builds the module exactly as the widget ships it
(:func:`teachraster.widgets.explorable.esm_source`), imports it in node and calls its
exported functions on JSON arguments; typed arrays come back as lists. One node process per
batch of calls (about 50 ms), so a test batches its inputs.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import tempfile
from pathlib import Path

import pytest

NODE = shutil.which("node")

DRIVER = """
import { readFileSync } from "node:fs";
const mod = await import(process.argv[2]);
const calls = JSON.parse(readFileSync(process.argv[3], "utf8"));
const plain = (v) => (ArrayBuffer.isView(v) ? Array.from(v) : v);
const out = calls.map(([name, args]) => {
  const r = mod[name](...args);
  return JSON.parse(JSON.stringify(r, (_k, v) => plain(v)));
});
process.stdout.write(JSON.stringify(out));
"""


def call_js(parts: tuple[str, ...], calls: list[tuple[str, list]]) -> list:
    """Call ``name(*args)`` for each of ``calls`` in the module of ``parts``; the results."""
    from teachraster.widgets.explorable import esm_source

    if NODE is None:
        pytest.skip("node is not installed (the page-side functions are checked with node)")
    with tempfile.TemporaryDirectory(prefix="tr-node-") as tmp:
        module, driver, args = Path(tmp, "m.mjs"), Path(tmp, "run.mjs"), Path(tmp, "calls.json")
        module.write_text(esm_source(*parts), encoding="utf-8")
        driver.write_text(DRIVER, encoding="utf-8")
        args.write_text(json.dumps(calls), encoding="utf-8")
        done = subprocess.run([NODE, str(driver), module.as_uri(), str(args)],
                              capture_output=True, text=True, timeout=120)  # fmt: skip
    if done.returncode:
        raise RuntimeError(f"node failed:\n{done.stderr[-3000:]}")
    return json.loads(done.stdout)
