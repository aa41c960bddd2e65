"""The page-side pieces of the browser benchmark (``bench_browser.py`` and its modules): the
scripts that time an input in the page and count the pictures it brings, and the functions
that drive them."""

from __future__ import annotations

# In-page timing: t0 at the first matching input event, t1 at the first change of what is
# watched after it (a MutationObserver), both performance.now().
ARM = """([target, events, watch, attr]) => {
  const t = document.querySelector(target), el = document.querySelector(watch);
  const b = window.__bench = { t0: null, t1: null, before: attr ? el.getAttribute(attr) : el.textContent };
  const start = () => { if (b.t0 === null) b.t0 = performance.now(); };
  for (const e of events) t.addEventListener(e, start, { capture: true, once: true });
  const ob = new MutationObserver(() => {
    const now = attr ? el.getAttribute(attr) : el.textContent;
    if (b.t0 !== null && b.t1 === null && now !== b.before) { b.t1 = performance.now(); ob.disconnect(); }
  });
  ob.observe(el, { attributes: true, childList: true, subtree: true, characterData: true });
}"""
COUNT = """([watch, attr]) => {
  const el = document.querySelector(watch);
  const c = window.__count = { n: 0, t: [], k: [], rt: [], p: [], last: el.getAttribute(attr) };
  c.ob = new MutationObserver(() => {
    const now = el.getAttribute(attr);
    if (now !== c.last) {
      c.n += 1; c.t.push(performance.now()); c.last = now;
      c.k.push(Number(el.dataset.kernelMs)); c.rt.push(Number(el.dataset.roundTripMs));
      c.p.push(Number(el.dataset.paintMs));  // an explorable's canvas: ms its draw took
    }
  });
  c.ob.observe(el, { attributes: true });
}"""
#: How long each drag lasts and how long the kernel is then given to catch up, in ms. The
#: smoke run (``--quick``, CI) shortens both: it shows that every row works; its figures are
#: not the report's (CI time).
TIMES = {"drag": 1500, "settle": 2500}


def settle(page) -> None:
    """Wait while the kernel catches up after a drag: a value or two, never a queue."""
    page.wait_for_timeout(TIMES["settle"])


DRAG = """async ([sel, ms]) => {
  const r = document.querySelector(sel);
  const t0 = performance.now();
  let v = 0;
  while (performance.now() - t0 < ms) {
    await new Promise(requestAnimationFrame);
    v = (v + 1) % (Number(r.max) + 1);
    r.value = String(v);
    r.dispatchEvent(new Event("input", { bubbles: true }));
  }
  r.dispatchEvent(new Event("change", { bubbles: true }));
  window.__dragEnd = performance.now();
}"""
# A slider dragged along its track: its next position at every animation frame, through
# all its steps (min to max, then again from min), released at the end.
DRAG_SLIDER = """async ([sel, ms]) => {
  const r = document.querySelector(sel);
  const lo = Number(r.min), step = Number(r.step) || 1;
  const n = Math.floor((Number(r.max) - lo) / step + 1e-9) + 1;
  const t0 = performance.now();
  for (let k = 1; performance.now() - t0 < ms; k++) {
    await new Promise(requestAnimationFrame);
    r.value = String(lo + (k % n) * step);
    r.dispatchEvent(new Event("input", { bubbles: true }));
  }
  r.dispatchEvent(new Event("change", { bubbles: true }));
  window.__dragEnd = performance.now();
}"""
MOVES = """async ({sel, points, ms, mouse}) => {
  const el = document.querySelector(sel);
  const t0 = performance.now();
  for (let k = 1; performance.now() - t0 < ms; k++) {
    await new Promise(requestAnimationFrame);
    const [x, y] = points[k % points.length];
    // pointer events; mouse events for an ipywidgets slider (noUiSlider listens to those)
    el.dispatchEvent(mouse
      ? new MouseEvent("mousemove", { clientX: x, clientY: y, bubbles: true, buttons: 1 })
      : new PointerEvent("pointermove", { clientX: x, clientY: y, pointerId: 1,
        bubbles: true, isPrimary: true, pointerType: "mouse", buttons: 1 }));
  }
  window.__dragEnd = performance.now();
}"""
# The same, to the second change after the event: a key on a slider explorer shows the
# picture drawn ahead first (the page's own), the kernel's full picture second.
ARM_SECOND = """([target, events, watch, attr]) => {
  const t = document.querySelector(target), el = document.querySelector(watch);
  // pictures shown, plus pictures drawn ahead skipped because the kernel's came first (drag.js)
  const count = () => Number(el.getAttribute(attr) || 0) + Number(el.dataset.skipped || 0);
  const b = window.__bench = { t0: null, t1: null, n: 0, before: count() };
  const start = () => { if (b.t0 === null) b.t0 = performance.now(); };
  for (const e of events) t.addEventListener(e, start, { capture: true, once: true });
  const ob = new MutationObserver(() => {
    const now = count();
    if (b.t0 !== null && b.t1 === null && now !== b.before) {
      b.n += now - b.before;
      b.before = now;
      if (b.n >= 2) { b.t1 = performance.now(); ob.disconnect(); }
    }
  });
  ob.observe(el, { attributes: true });
}"""
# When the pointer is released (the first pointerup or mouseup anywhere): a drag's last
# picture is timed from there (Playwright's release arrives some way after the last move).
MARK_RELEASE = """() => {
  window.__upAt = null;
  const up = () => { if (window.__upAt === null) window.__upAt = performance.now(); };
  for (const e of ["pointerup", "mouseup"]) document.addEventListener(e, up, { capture: true, once: true });
}"""
RELEASED = "() => window.__upAt ?? window.__dragEnd"
DONE = "() => window.__bench.t1 !== null"
DT = "() => window.__bench.t1 - window.__bench.t0"


def latency(page, target, events, watch, attr, act, tries: int, arm=ARM,
            timeout: float | None = None) -> list[float]:  # fmt: skip
    """ms from the input event on ``target`` to the change of ``watch`` (``attr`` or text;
    with ``arm=ARM_SECOND`` to its second change).

    Without ``timeout`` a change that never comes is an error (after 30 s); with it (ms), a
    try that sees none within it counts as NaN (the report says "no picture").
    """
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    out = []
    for _ in range(tries):
        page.evaluate(arm, [target, events, watch, attr])
        act()
        try:
            page.wait_for_function(DONE, timeout=timeout or 30_000)
            out.append(page.evaluate(DT))
        except PlaywrightTimeout:
            if timeout is None:
                raise
            out.append(float("nan"))
        page.wait_for_timeout(60)
    return out
