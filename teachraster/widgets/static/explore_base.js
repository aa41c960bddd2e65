// teachraster explorables: what every page-side explorable shares (no imports, no build).
//
// An explorable's module is this file, the libraries it needs (raster_rules.js, view3d.js)
// and its own file, joined in that order by teachraster.widgets.explorable.esm_source; its
// own file defines `mount(el, data, host)`. The same module runs three ways:
// - as an anywidget (`render` below): `host` keeps the state in the model, so the kernel
//   hears of it at each release, and sends the stand-in picture;
// - in an offline page (`mountStatic`, a `teachraster html` export or a saved notebook's
//   stand-in): `host` keeps the state in the page only;
// - under node (tests): only the pure functions are called, nothing touches the DOM.

export const OKABE = {
  black: "#000000", orange: "#E69F00", sky: "#56B4E9", green: "#009E73",
  yellow: "#F0E442", blue: "#0072B2", vermillion: "#D55E00", purple: "#CC79A7",
};

// numpy's rint: round half to even (Math.round rounds half up)
export function rint(x) {
  const r = Math.round(x);
  return Math.abs(x % 1) === 0.5 && r % 2 !== 0 ? r - 1 : r;
}

// A small seeded generator (mulberry32): rerolls that a test can repeat.
export function randomStream(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

export function escapeHtml(s) {
  return String(s).replace(/[&<>"']/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;",
    '"': "&quot;", "'": "&#39;" })[c]);
}

// a number as the lessons print it: at most `digits` significant digits, no trailing zeros
export function fmt(x, digits = 4) {
  if (!Number.isFinite(x)) return String(x);
  if (x === 0) return "0";
  const s = Number(x.toPrecision(digits));
  return Math.abs(s) >= 1e6 || Math.abs(s) < 1e-4 ? s.toExponential(digits - 1) : String(s);
}

// fmt with the lessons' minus sign, U+2212 ("−8", not "-8"), for text that also shows "−" in
// names or formulas (review r328 02-10: "E32 = −E23 = -8" mixed the two)
export function fmtMinus(x, digits = 4) {
  return fmt(x, digits).replace(/-/g, "\u2212");
}

const BASE_CSS = `
.tr-x { font: 14px/1.45 var(--jp-ui-font-family, system-ui, sans-serif); color: #111;
  max-width: 100%; }
.tr-x-title { font-size: 1.2em; font-weight: bold; margin: 2px 0; }
.tr-x-sub { color: #555; margin: 0 0 6px; max-width: 62em; }
.tr-x-row { display: flex; flex-wrap: wrap; align-items: center; gap: 6px 14px; margin: 4px 0; }
.tr-x canvas { display: block; max-width: 100%; height: auto; touch-action: none;
  border-radius: 2px; }
.tr-x canvas:focus-visible { outline: 2px solid #0072B2; outline-offset: 2px; }
.tr-x button { font: inherit; padding: 3px 10px; border: 1px solid #888; border-radius: 3px;
  background: #f4f4f4; cursor: pointer; }
.tr-x button[aria-pressed=true] { background: #0072B2; color: #fff; border-color: #0072B2; }
.tr-x button:disabled { opacity: 0.5; cursor: default; }
.tr-x label { display: inline-flex; align-items: center; gap: 6px; }
.tr-x input[type=range] { width: 220px; max-width: 60vw; }
.tr-x-readout { font-variant-numeric: tabular-nums; min-height: 2.9em; margin: 4px 0; }
.tr-x-readout b { font-weight: 600; }
.tr-x-hint { display: none; }
.tr-x table { border-collapse: collapse; font-variant-numeric: tabular-nums; }
.tr-x td, .tr-x th { padding: 1px 8px; border-bottom: 1px solid #ddd; text-align: right; }
.tr-x th { font-weight: 600; }
.tr-x td:first-child, .tr-x th:first-child { text-align: left; }
`;

export function element(tag, attrs = {}, children = []) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === "text") e.textContent = v;
    else if (k === "html") e.innerHTML = v;
    else if (k === "class") e.className = v;
    else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

// installKeyGuard, onKeys: keys.js; addCss (CSS once per document, by id; every explorable
// module carries its own part): page.js. Both from teachraster/plotting/static, joined
// before this file.

// The frame of every explorable: a title, its explanation, then its parts. Keys pressed
// inside are the explorable's (installKeyGuard): Jupyter's shortcuts (arrows move between
// cells in command mode, in JupyterLab and Notebook 7) do not take them. Escape, Shift+Enter
// and Ctrl+S still do: the frame is not marked `data-lm-suppress-shortcuts`, which would
// hide every shortcut from the notebook while the focus is inside.
export function frame(el, title, subtitle) {
  addCss("tr-x-base-css", BASE_CSS);
  installKeyGuard();
  const root = element("div", { class: "tr-x" });
  if (title) root.append(element("div", { class: "tr-x-title", text: title }));
  if (subtitle) root.append(element("div", { class: "tr-x-sub", html: subtitle }));
  root.addEventListener("keydown", (e) => e.stopPropagation());
  el.append(root);
  return root;
}

// Canvas text that stays readable where the canvas is shown smaller than it is drawn: a canvas
// wider than its column shrinks with it (max-width: 100%), and its text with it. JupyterLab's
// output column at 1024 x 768 with the file browser open is about 585 px wide, where an
// 800-px canvas's 14-px numbers read 10 (reviews r9/r10: 02 c23, 12 c8). readablePx(px, w)
// is `px`, or more on a canvas `w` px wide, so that the text reads at least MIN_TEXT_PX there.
export const NARROW_COLUMN_PX = 585;
export const MIN_TEXT_PX = 12;
export function readablePx(px, canvasWidth) {
  return Math.max(px, Math.ceil(MIN_TEXT_PX * Math.max(1, canvasWidth / NARROW_COLUMN_PX)));
}
// the same for the canvas `ctx` draws on (its CSS width)
export function textPx(ctx, px) {
  const c = ctx.canvas;
  return readablePx(px, c.logical ? c.logical.w : c.width);
}

// A canvas `w` x `h` CSS pixels, drawn at the screen's resolution (up to 2x), that shrinks
// with its column (max-width) and keeps its proportions; ctx draws in CSS pixels.
export function makeCanvas(w, h, label) {
  const c = document.createElement("canvas");
  const dpr = Math.max(1, Math.min(2, globalThis.devicePixelRatio || 1));
  c.width = Math.round(w * dpr);
  c.height = Math.round(h * dpr);
  c.style.width = `${w}px`;
  c.tabIndex = 0;
  if (label) c.setAttribute("aria-label", label);
  c.setAttribute("role", "img");
  const ctx = c.getContext("2d");
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  c.logical = { w, h, dpr };
  return [c, ctx];
}

// A W x H pixel grid on a canvas: the cell size in CSS pixels (between minCell and maxCell,
// the grid fitting fitW x fitH), the margin left and top for labels and `pad` right and below;
// toPx maps grid coordinates (pixels, y down) to the canvas and toGrid back.
export function pixelCanvas(W, H, { minCell, maxCell, fitW, fitH, margin, pad, label }) {
  const cell = Math.max(minCell, Math.min(maxCell, Math.floor(Math.min(fitW / W, fitH / H))));
  const [canvas, ctx] = makeCanvas(margin.left + W * cell + pad, margin.top + H * cell + pad,
    label);
  const toPx = ([x, y]) => [margin.left + x * cell, margin.top + y * cell];
  const toGrid = ([px, py]) => [(px - margin.left) / cell, (py - margin.top) / cell];
  return { canvas, ctx, cell, toPx, toGrid };
}

// the pointer in the canvas' CSS pixels at its natural size (whatever it is scaled to)
export function pointerAt(canvas, e) {
  const r = canvas.getBoundingClientRect();
  return [((e.clientX - r.left) * canvas.logical.w) / r.width,
    ((e.clientY - r.top) * canvas.logical.h) / r.height];
}

// Draw at the next animation frame, once however often asked (pointer moves coalesce).
// Each picture painted counts on the canvas (data-frames) and says how long it took and,
// when an input asked for it, how long after that input it was painted (data-latency-ms);
// `handles()` (canvas px) go to data-handles: what the benchmarks and browser tests read.
export function painter(canvas, draw, handles) {
  let asked = false;
  let since = null;
  const paint = () => {
    asked = false;
    const t0 = performance.now();
    draw();
    const t1 = performance.now();
    canvas.dataset.frames = String(Number(canvas.dataset.frames || 0) + 1);
    canvas.dataset.paintMs = (t1 - t0).toFixed(2);
    if (since !== null) canvas.dataset.latencyMs = (t1 - since).toFixed(1);
    if (handles) canvas.dataset.handles = JSON.stringify(handles().map((h) => h.map((v) => Math.round(v * 10) / 10)));
    since = null;
  };
  return {
    request(event) {
      if (event && since === null) since = event.timeStamp || performance.now();
      if (!asked) {
        asked = true;
        requestAnimationFrame(paint);
      }
    },
    now: paint,
  };
}

// Keep the pointer's moves coming to `el` while it is pressed (a pointer that is not a real
// one, as a test's, has nothing to capture: the drag then goes on without)
export function capture(el, e) {
  try {
    el.setPointerCapture(e.pointerId);
  } catch (_err) {
    // no active pointer of that id
  }
}

// A press released less than this far from where it began (canvas px) is a click
export const CLICK_PX = 4;

// Pointer handling: press near one of `handles()` (canvas px) to drag it, else a click.
// onDrag(i, p, e) at each move, onRelease(i, p, e) once; onClick(p, e) for a press that
// moved less than CLICK_PX and held no handle; onHover(p) while nothing is pressed.
export function pointerInput(canvas, { handles = () => [], radius = 14, onDrag, onRelease,
  onClick, onHover, onPress }) {
  let held = null;
  let down = null;
  canvas.addEventListener("pointerdown", (e) => {
    if (e.button !== 0) return;
    const p = pointerAt(canvas, e);
    const scale = canvas.logical.w / canvas.getBoundingClientRect().width;
    let best = null;
    let bestD = radius * Math.max(1, scale);
    handles().forEach((h, i) => {
      const d = Math.hypot(h[0] - p[0], h[1] - p[1]);
      if (h && d <= bestD) [best, bestD] = [i, d];
    });
    down = p;
    held = best;
    capture(canvas, e);
    e.preventDefault();
    canvas.focus({ preventScroll: true });
    if (onPress) onPress(p, e, held);
    if (held !== null && onDrag) onDrag(held, p, e);
  });
  canvas.addEventListener("pointermove", (e) => {
    const p = pointerAt(canvas, e);
    if (down === null) {
      if (onHover) onHover(p, e);
      return;
    }
    if (held !== null && onDrag) onDrag(held, p, e);
  });
  const up = (e) => {
    if (down === null) return;
    const p = pointerAt(canvas, e);
    const moved = Math.hypot(p[0] - down[0], p[1] - down[1]);
    const was = held;
    down = null;
    held = null;
    if (was !== null) {
      if (onRelease) onRelease(was, p, e);
    } else if (moved < CLICK_PX && onClick && e.type === "pointerup") {
      onClick(p, e);
    }
  };
  canvas.addEventListener("pointerup", up);
  canvas.addEventListener("pointercancel", up);
  canvas.addEventListener("pointerleave", (e) => {
    if (down === null && onHover) onHover(null, e);
  });
}

// the boundaries of a W x H pixel grid of `cell` px from (x0, y0), and optionally the row and
// column numbers beside it (every second one beyond 20)
export function drawGrid(ctx, x0, y0, W, H, cell, colour, labels = false) {
  ctx.strokeStyle = colour;
  ctx.lineWidth = 1;
  ctx.beginPath();
  for (let c = 0; c <= W; c++) {
    ctx.moveTo(x0 + c * cell + 0.5, y0);
    ctx.lineTo(x0 + c * cell + 0.5, y0 + H * cell);
  }
  for (let r = 0; r <= H; r++) {
    ctx.moveTo(x0, y0 + r * cell + 0.5);
    ctx.lineTo(x0 + W * cell, y0 + r * cell + 0.5);
  }
  ctx.stroke();
  if (!labels) return;
  // at least 14 px (11 read 10 px at 1024 px, review r9 12 c8), more on a wide canvas; two
  // digits at 17 px still fit a 30-px margin on the left and 24 above. `labels` may be the
  // size itself (the diamond explorer's 17 px, darker, for a projector: review r83 12a-3)
  const big = typeof labels === "number";
  ctx.fillStyle = big ? "#333" : "#555";
  ctx.font = `${textPx(ctx, big ? labels : 14)}px sans-serif`;
  ctx.textAlign = "center";
  for (let c = 0; c < W; c += W > 20 ? 2 : 1) ctx.fillText(String(c), x0 + (c + 0.5) * cell, y0 - 8);
  ctx.textAlign = "right";
  for (let r = 0; r < H; r += H > 20 ? 2 : 1) ctx.fillText(String(r), x0 - 6, y0 + (r + 0.5) * cell + 4);
  ctx.textAlign = "left";
}

// a straight line from p to q (canvas px)
export function strokeLine(ctx, p, q, colour, width = 1, dash = []) {
  ctx.save();
  ctx.setLineDash(dash);
  ctx.strokeStyle = colour;
  ctx.lineWidth = width;
  ctx.beginPath();
  ctx.moveTo(p[0], p[1]);
  ctx.lineTo(q[0], q[1]);
  ctx.stroke();
  ctx.restore();
}

// buttons of which one is pressed: [value, label] options; onPick(value, event)
export function choiceButtons(options, current, onPick) {
  const buttons = options.map(([value, label]) => button(label, (e) => {
    set(value);
    onPick(value, e);
  }, value === current));
  function set(value) {
    buttons.forEach((b, k) => b.setAttribute("aria-pressed", String(options[k][0] === value)));
  }
  return { buttons, set };
}

export function button(text, onClick, pressed) {
  const b = element("button", { type: "button", text });
  if (pressed !== undefined) b.setAttribute("aria-pressed", String(Boolean(pressed)));
  b.addEventListener("click", (e) => onClick(e, b));
  return b;
}

// a labelled range input; onInput(value, event) at every change
export function slider(label, { min, max, step, value, format = (v) => String(v) }, onInput) {
  const input = element("input", { type: "range", min, max, step, "aria-label": label });
  input.value = String(value);
  const out = element("span", { class: "tr-x-value", text: format(Number(value)) });
  out.style.cssText = "min-width:4.5em;font-variant-numeric:tabular-nums";
  input.addEventListener("input", (e) => {
    out.textContent = format(Number(input.value));
    onInput(Number(input.value), e);
  });
  const box = element("label", {}, [element("span", { text: label }), input, out]);
  box.set = (v) => {
    input.value = String(v);
    out.textContent = format(Number(v));
  };
  box.input = input;
  return box;
}

// -- the host: where the state lives ------------------------------------------------------------
// In a notebook the model keeps the state (the kernel hears of it at each release); offline
// the page keeps it. `picture(...canvases)` sends the kernel the picture the stand-in keeps
// (the canvases side by side, at their CSS size): a saved notebook reopened without a kernel
// shows it.
export function composite(canvases) {
  const w = canvases.reduce((s, c) => s + c.logical.w, 0) + 8 * (canvases.length - 1);
  const h = Math.max(...canvases.map((c) => c.logical.h));
  const out = document.createElement("canvas");
  [out.width, out.height] = [w, h];
  const ctx = out.getContext("2d");
  ctx.fillStyle = "#fff";
  ctx.fillRect(0, 0, w, h);
  let x = 0;
  for (const c of canvases) {
    ctx.drawImage(c, x, 0, c.logical.w, c.logical.h);
    x += c.logical.w + 8;
  }
  return out;
}

function modelHost(model) {
  let timer = null;
  return {
    live: true,
    state: () => model.get("state"),
    setState(s) {
      model.set("state", { ...model.get("state"), ...s });
      model.save_changes();
    },
    send: (msg) => model.send(msg),
    picture(...canvases) {
      clearTimeout(timer);
      timer = setTimeout(() => {
        try {
          model.send({ type: "picture", png: composite(canvases).toDataURL("image/png") });
        } catch (_e) {
          // a canvas the page may not read back (never ours): no picture, no harm
        }
      }, 600);
    },
  };
}

function pageHost(initial) {
  let state = { ...(initial || {}) };
  return {
    live: false,
    state: () => state,
    setState(s) {
      state = { ...state, ...s };
    },
    send() {},
    picture() {},
  };
}

function render({ model, el }) {
  const view = mount(el, model.get("data"), modelHost(model));
  model.on("change:state", () => view.setState && view.setState(model.get("state")));
  model.on("change:data", () => view.setData && view.setData(model.get("data")));
  model.on("msg:custom", (msg) => view.message && view.message(msg));
  return () => view.destroy && view.destroy();
}

// An offline page: the explorable computes everything itself (no kernel).
export function mountStatic(el, data, state) {
  const hint = el.parentElement && el.parentElement.querySelector(".tr-x-hint-static");
  if (hint) hint.style.display = "none"; // the stand-in's hint to run the lesson: not needed now
  const view = mount(el, data, pageHost(state || data.state));
  if (el.dataset) el.dataset.mounted = "1";
  return view;
}

export default { render };
