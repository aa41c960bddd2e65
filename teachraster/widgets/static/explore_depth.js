// Lesson 05b: where the representable depth values are, along the view depth z.
//
// Four depth buffers store a window depth d(z) = (1 - n/z) / (1 - n/f): unorm16, unorm24,
// float32, and float32 with reverse-Z, r(z) = (n/z - n/f) / (1 - n/f) (near -> 1, far -> 0).
// Each strip shows how many values each buffer can store in each pixel's range of z (single
// values as ticks where they are sparse, density where they are not) on a logarithmic z
// axis; the near plane is dragged along it. The lens below magnifies the z around the pointer
// linearly, where single values show. The stored values are teachraster.pipeline.visibility
// .depth's quantize(window_depth(z)) and quantize(reversed_depth(z), "float32"): the tests
// compare them exactly.

export const FORMATS = [
  ["unorm16", "unorm16"],
  ["unorm24", "unorm24"],
  ["float32", "float32"],
  ["reversed", "float32, reverse-Z"],
];

export function windowDepth(z, n, f) {
  return (1.0 - n / z) / (1.0 - n / f);
}

export function reversedDepth(z, n, f) {
  return (n / z - n / f) / (1.0 - n / f);
}

const F32 = new Float32Array(1);
const U32 = new Uint32Array(F32.buffer);

// the index of a non-negative float32 among all of them (their bits, in order)
function f32Bits(x) {
  F32[0] = x;
  return U32[0];
}

function f32FromBits(i) {
  U32[0] = i;
  return F32[0];
}

function unormScale(fmt) {
  return fmt === "unorm16" ? 65535 : 16777215;
}

// the value buffer `fmt` ("reversed": float32 of reverse-Z) stores for distance z
export function storedValue(z, n, f, fmt) {
  if (fmt === "reversed") return Math.fround(reversedDepth(z, n, f));
  const d = windowDepth(z, n, f);
  if (fmt === "float32") return Math.fround(d);
  const s = unormScale(fmt);
  return rint(Math.min(Math.max(d, 0), 1) * s) / s;
}

// the stored values on either side of the one stored for z (farther, nearer), and the z each
// stands for: one step of the buffer, in depth and in z
export function neighbours(z, n, f, fmt) {
  const v = storedValue(z, n, f, fmt);
  let up;
  let down;
  if (fmt === "float32" || fmt === "reversed") {
    const i = f32Bits(v);
    [up, down] = [f32FromBits(i + 1), i > 0 ? f32FromBits(i - 1) : 0];
  } else {
    const s = unormScale(fmt);
    const k = rint(v * s);
    [up, down] = [(k + 1) / s, Math.max(k - 1, 0) / s];
  }
  const zOf = (d) => distanceOf(d, n, f, fmt);
  // reverse-Z: a larger value is nearer, so the farther neighbour is the smaller value
  const [farther, nearer] = fmt === "reversed" ? [down, up] : [up, down];
  return { value: v, farther, nearer, z: zOf(v), zFarther: zOf(farther), zNearer: zOf(nearer) };
}

// the distance whose depth is d (the inverse of the mapping; Infinity beyond the horizon)
export function distanceOf(d, n, f, fmt) {
  const k = 1.0 - n / f;
  return fmt === "reversed" ? n / (d * k + n / f) : n / (1.0 - d * k);
}

// how many values the buffer stores for distances in [za, zb) (za < zb, both >= n)
export function countBetween(za, zb, n, f, fmt) {
  if (fmt === "reversed") {
    // stored values r in (r(zb), r(za)]: floats <= r(za) minus floats <= r(zb)
    const le = (x) => {
      const i = f32Bits(x);
      return Math.fround(x) > x ? i : i + 1;
    };
    return le(reversedDepth(za, n, f)) - le(reversedDepth(zb, n, f));
  }
  const [a, b] = [windowDepth(za, n, f), Math.min(windowDepth(zb, n, f), 1)];
  if (fmt === "float32") {
    const lt = (x) => {
      const i = f32Bits(x);
      return Math.fround(x) < x ? i + 1 : i;
    };
    return lt(b) - lt(a);
  }
  const s = unormScale(fmt);
  return Math.ceil(b * s) - Math.ceil(a * s);
}

// values per pixel column of a log z axis from z0 to z1 over `cols` columns
export function columnCounts(z0, z1, cols, n, f, fmt) {
  const out = new Float64Array(cols);
  const step = Math.log(z1 / z0) / cols;
  for (let c = 0; c < cols; c++) {
    const za = Math.max(z0 * Math.exp(c * step), n);
    const zb = Math.min(z0 * Math.exp((c + 1) * step), f);
    out[c] = zb > za ? countBetween(za, zb, n, f, fmt) : 0;
  }
  return out;
}

// the z of every stored value whose distance lies in [za, zb] (null: more than `limit`)
export function valuesIn(za, zb, n, f, fmt, limit = 400) {
  const lo = Math.max(za, n);
  const hi = Math.min(zb, f);
  if (!(hi >= lo)) return [];
  const reversed = fmt === "reversed";
  // the stored values in that range of depth, as indices (float bits or unorm integers)
  const [dLo, dHi] = reversed ? [reversedDepth(hi, n, f), reversedDepth(lo, n, f)]
    : [windowDepth(lo, n, f), Math.min(windowDepth(hi, n, f), 1)];
  let first;
  let last;
  let value;
  if (fmt === "unorm16" || fmt === "unorm24") {
    const s = unormScale(fmt);
    [first, last, value] = [Math.ceil(dLo * s), Math.floor(dHi * s), (k) => k / s];
  } else {
    first = f32Bits(dLo) + (Math.fround(dLo) < dLo ? 1 : 0);
    last = f32Bits(dHi) - (Math.fround(dHi) > dHi ? 1 : 0);
    value = f32FromBits;
  }
  if (last - first + 1 > limit) return null;
  const out = [];
  for (let k = first; k <= last; k++) out.push(distanceOf(value(k), n, f, fmt));
  return reversed ? out.reverse() : out;
}

// a sequential colour for log10(count) in [0, 7] (light to dark, viridis-like end points)
function densityRgb(count) {
  const t = Math.min(Math.log10(count) / 7, 1);
  const stops = [[253, 231, 37], [94, 201, 98], [33, 145, 140], [59, 82, 139], [68, 1, 84]];
  const x = t * (stops.length - 1);
  const i = Math.min(Math.floor(x), stops.length - 2);
  const u = x - i;
  return stops[i].map((v, k) => Math.round(v + (stops[i + 1][k] - v) * u));
}

function densityColour(count) {
  const c = densityRgb(count);
  return `rgb(${c[0]},${c[1]},${c[2]})`;
}

// the four strips for one near plane, as one picture (pw x 4 rows of columns, drawn once and
// stretched: one putImageData instead of thousands of rectangles)
function stripsPicture(zmin, far, pw, near) {
  const img = new ImageData(pw, FORMATS.length);
  FORMATS.forEach(([fmtName], k) => {
    const counts = columnCounts(zmin, far, pw, near, far, fmtName);
    for (let c = 0; c < pw; c++) {
      const [r, g, b] = counts[c] ? densityRgb(counts[c]) : [255, 255, 255];
      img.data.set([r, g, b, 255], 4 * (k * pw + c));
    }
  });
  const canvas = document.createElement("canvas");
  [canvas.width, canvas.height] = [pw, FORMATS.length];
  canvas.getContext("2d").putImageData(img, 0, 0);
  return canvas;
}

function mount(el, data, host) {
  const state = { near: data.near, z0: data.z0, zoom: 0, ...host.state() };
  const far = data.far;
  const zmin = data.zmin;
  const root = frame(el, data.title,
    "Each strip shows where a depth buffer's values fall along the view depth z (log " +
    "scale): dark where a pixel's range of z holds many, single ticks where they are few. " +
    "Drag the near plane (the orange handle); point at a depth to magnify it in the lens " +
    "below, where single values show (+ and − zoom the lens).");
  const g = { left: 150, right: 20, top: 66, strip: 40, gap: 8, lensTop: 0, lensRow: 26 };
  const W = 900;
  g.width = W;
  const pw = W - g.left - g.right;
  g.lensTop = g.top + 4 * (g.strip + g.gap) + 50;
  const Hc = g.lensTop + 4 * (g.lensRow + 4) + 46;
  const [canvas, ctx] = makeCanvas(W, Hc, "depth buffer values along the view depth");
  const readout = element("div", { class: "tr-x-readout", "aria-live": "polite" });
  const zoomIn = button("+ zoom the lens", (e) => zoom(1, e));
  const zoomOut = button("− zoom out", (e) => zoom(-1, e));
  root.append(element("div", { class: "tr-x-row" }, [zoomIn, zoomOut]), canvas, readout);
  const lz = (z) => Math.log(z);
  const xOf = (z) => g.left + ((lz(z) - lz(zmin)) / (lz(far) - lz(zmin))) * pw;
  const zOf = (x) => Math.exp(lz(zmin) + ((x - g.left) / pw) * (lz(far) - lz(zmin)));
  const ui = { hover: null };

  // the lens' width: 30 steps of unorm16 at z0, divided by 10 per zoom step
  function lensWidth() {
    const nb = neighbours(state.z0, state.near, far, "unorm16");
    const step = Math.max(nb.zFarther - nb.z, 1e-12);
    return (30 * step) / 10 ** state.zoom;
  }
  function zoom(k, e) {
    state.zoom = Math.max(-2, Math.min(6, state.zoom + k));
    host.setState({ zoom: state.zoom });
    paint.request(e);
  }

  let strips = { near: null };
  function draw() {
    ctx.clearRect(0, 0, W, Hc);
    const n = state.near;
    if (strips.near !== n) strips = { near: n, picture: stripsPicture(zmin, far, pw, n) };
    ctx.imageSmoothingEnabled = false;
    FORMATS.forEach(([, name], k) => {
      const y = g.top + k * (g.strip + g.gap);
      ctx.drawImage(strips.picture, 0, k, pw, 1, g.left, y, pw, g.strip);
      ctx.strokeStyle = "#999";
      ctx.strokeRect(g.left + 0.5, y + 0.5, pw, g.strip);
      ctx.fillStyle = "#111";
      ctx.font = "bold 14px sans-serif";
      ctx.fillText(name, 8, y + g.strip / 2 + 5);
    });
    drawLogAxis(ctx, g, zmin, far, xOf, g.top + 4 * (g.strip + g.gap));
    drawNear(ctx, g, xOf(n), n, 4 * (g.strip + g.gap));
    drawLegend(ctx, g, W);
    if (ui.hover !== null) {
      const x = xOf(ui.hover) + 0.5;
      strokeLine(ctx, [x, g.top - 6], [x, g.top + 4 * (g.strip + g.gap)], "#000", 1, [4, 3]);
    }
    drawLens(ctx, g, W, state.z0, lensWidth(), n, far);
    readout.innerHTML = depthTable(ui.hover ?? state.z0, n, far);
    host.picture(canvas);
  }
  const paint = painter(canvas, draw, () => [[xOf(state.near), g.top - 12]]);
  nearInput(canvas, { state, host, ui, g, pw, xOf, zOf, zmin, far, paint, zoom });
  paint.now();
  return {
    setState(s) {
      Object.assign(state, s);
      paint.request();
    },
  };
}

// the near plane dragged (or moved with the arrow keys), the lens moved by pointing, zoomed
// with + and -
function nearInput(canvas, v) {
  const { state, host, ui, g, pw, xOf, zOf, zmin, far, paint, zoom } = v;
  pointerInput(canvas, {
    handles: () => [[xOf(state.near), g.top - 12]],
    radius: 16,
    onDrag(_i, p, e) {
      const z = Math.min(Math.max(zOf(p[0]), zmin), far / 4);
      state.near = Number(z.toPrecision(3));
      if (state.z0 < state.near) state.z0 = state.near;
      // the readout follows the pointer, which now drags the plane: keep it on the plane
      if (ui.hover !== null) ui.hover = Math.max(ui.hover, state.near);
      paint.request(e);
    },
    onRelease() {
      host.setState({ near: state.near, z0: state.z0 });
    },
    onHover(p, e) {
      const inside = p && p[0] >= g.left && p[0] <= g.left + pw && p[1] < g.lensTop - 30;
      ui.hover = inside ? Math.max(zOf(p[0]), state.near) : null;
      if (ui.hover !== null) state.z0 = ui.hover;
      paint.request(e);
    },
    onClick(p, e) {
      if (p[0] >= g.left && p[1] < g.lensTop - 30) {
        state.z0 = Math.max(zOf(p[0]), state.near);
        host.setState({ z0: state.z0 });
      }
      paint.request(e);
    },
  });
  onKeys(canvas, (e) => {
    const k = { "+": 1, "=": 1, "-": -1, "_": -1 }[e.key];
    if (k) {
      e.preventDefault();
      zoom(k, e);
      return;
    }
    const d = { ArrowLeft: -1, ArrowRight: 1 }[e.key];
    if (!d) return;
    e.preventDefault();
    state.near = Number(Math.min(Math.max(state.near * 10 ** (0.05 * d), zmin), far / 4).toPrecision(3));
    state.z0 = Math.max(state.z0, state.near);
    host.setState({ near: state.near, z0: state.z0 });
    paint.request(e);
  });
}

function drawLogAxis(ctx, g, zmin, far, xOf, y) {
  ctx.fillStyle = "#111";
  ctx.strokeStyle = "#555";
  ctx.font = "14px sans-serif";
  ctx.textAlign = "center";
  for (let e = Math.ceil(Math.log10(zmin)); e <= Math.floor(Math.log10(far)); e++) {
    const x = xOf(10 ** e);
    ctx.beginPath();
    ctx.moveTo(x + 0.5, y - 4);
    ctx.lineTo(x + 0.5, y + 4);
    ctx.stroke();
    ctx.fillText(fmt(10 ** e, 3), x, y + 18);
  }
  ctx.fillText("view depth z (log scale)", g.left + (xOf(far) - g.left) / 2, y + 36);
  ctx.textAlign = "left";
}

function drawNear(ctx, g, x, near, height) {
  ctx.fillStyle = "rgba(120,120,120,0.35)";
  ctx.fillRect(g.left, g.top - 2, x - g.left, height);
  ctx.strokeStyle = OKABE.orange;
  ctx.lineWidth = 3;
  ctx.beginPath();
  ctx.moveTo(x, g.top - 6);
  ctx.lineTo(x, g.top + height - 8);
  ctx.stroke();
  ctx.lineWidth = 1;
  ctx.fillStyle = OKABE.orange;
  ctx.beginPath();
  ctx.moveTo(x - 9, g.top - 22);
  ctx.lineTo(x + 9, g.top - 22);
  ctx.lineTo(x, g.top - 6);
  ctx.closePath();
  ctx.fill();
  ctx.fillStyle = "#111";
  ctx.font = "bold 14px sans-serif";
  // right of the handle, or left of it near the right end, where the label would run off
  const label = `near = ${fmt(near, 3)}`;
  const room = x + 12 + ctx.measureText(label).width < g.width - 4;
  ctx.textAlign = room ? "left" : "right";
  ctx.fillText(label, room ? x + 12 : x - 12, g.top - 10);
  ctx.textAlign = "left";
  ctx.font = "14px sans-serif";
  if (x - g.left > 70) ctx.fillText("clipped", g.left + 6, g.top + 16);
}

// the colour key in its own row at the top, above the near plane's handle and label (which
// overlapped it at near = 1 and at the right end of the drag; review r59 05b-7); 14 px text,
// 12 px or more when the 900 px canvas is shrunk to a notebook column
function drawLegend(ctx, g, W) {
  const x0 = W - g.right - 7 * 46;
  ctx.font = "14px sans-serif";
  ctx.fillStyle = "#111";
  ctx.textAlign = "right";
  ctx.fillText("values per pixel's range:", x0 - 10, 17);
  ctx.textAlign = "left";
  for (let k = 0; k <= 6; k++) {
    ctx.fillStyle = densityColour(10 ** k);
    ctx.fillRect(x0 + k * 46, 4, 44, 16);
    ctx.fillStyle = "#111";
    ctx.fillText(k ? `10${"⁰¹²³⁴⁵⁶"[k]}` : "1", x0 + k * 46 + 4, 36);
  }
}

function drawLens(ctx, g, W, z0, width, n, far) {
  const pw = W - g.left - g.right;
  const win = lensWindow(z0, width, n, far);
  const [za, zb] = win ? [win.za, win.zb] : [z0 - width / 2, z0 + width / 2];
  const xOf = (z) => g.left + ((z - za) / (zb - za)) * pw;
  ctx.fillStyle = "#111";
  ctx.font = "bold 14px sans-serif";
  ctx.fillText(lensTitle(z0, width, n, far), g.left, g.lensTop - 10);
  FORMATS.forEach(([f, name], k) => {
    const y = g.lensTop + k * (g.lensRow + 4);
    ctx.strokeStyle = "#999";
    ctx.strokeRect(g.left + 0.5, y + 0.5, pw, g.lensRow);
    ctx.fillStyle = "#111";
    ctx.font = "14px sans-serif";
    ctx.fillText(name, 8, y + g.lensRow / 2 + 5);
    const row = lensRow(z0, width, n, far, f);
    if (row.text) {
      ctx.fillStyle = row.dense ? densityColour(1e4) : "#fff";
      ctx.fillRect(g.left + 1, y + 1, pw - 1, g.lensRow - 1);
      ctx.fillStyle = row.dense ? "#fff" : "#555";
      ctx.fillText(row.text, g.left + 8, y + g.lensRow / 2 + 5);
      return;
    }
    const zs = row.values;
    ctx.strokeStyle = "#111";
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    for (const z of zs) {
      const x = Math.round(xOf(z)) + 0.5;
      ctx.moveTo(x, y + 3);
      ctx.lineTo(x, y + g.lensRow - 3);
    }
    ctx.stroke();
    ctx.lineWidth = 1;
  });
  const y = g.lensTop + 4 * (g.lensRow + 4) + 14;
  ctx.fillStyle = "#111";
  ctx.strokeStyle = "#555";
  ctx.font = "14px sans-serif";
  for (const t of lensTicks(za, zb)) {
    const x = Math.round(xOf(t.z)) + 0.5;
    strokeLine(ctx, [x, y - 16], [x, y - 11], "#555", 1);
    // the ends stay inside the canvas
    ctx.textAlign = x < g.left + 40 ? "left" : x > g.left + pw - 40 ? "right" : "center";
    ctx.fillText(t.label, x, y);
  }
  ctx.textAlign = "left";
}

// the lens' window of z: z0 ± width/2 cut to [near, far], where the buffers store values (review
// r223 05b-2: zoomed out with the near plane at 0.01 it read "z = 500.0 ± 906000", reaching
// into negative z and far past the far plane); null when none of it lies there
export function lensWindow(z0, width, n, far) {
  const za = Math.max(z0 - width / 2, n);
  const zb = Math.min(z0 + width / 2, far);
  if (!(zb > za)) return null;
  return { za, zb, cut: za > z0 - width / 2 || zb < z0 + width / 2 };
}

// the lens' title: its centre and half-width, or the range it is cut to
export function lensTitle(z0, width, n, far) {
  const win = lensWindow(z0, width, n, far);
  if (win === null) return `lens: z = ${fmt(z0, 4)}, outside the near and far planes`;
  if (!win.cut) return `lens: z = ${lensCentre(z0, width)} ± ${fmt(width / 2, 3)} (linear)`;
  const end = (z) => (z === n ? `${fmt(z, 4)} (near)` : z === far ? `${fmt(z, 4)} (far)` : fmt(z, 6));
  return `lens: z from ${end(win.za)} to ${end(win.zb)} (linear)`;
}

// one lens row: the z of the values stored in the lens ({values}), or a line saying why none
// are drawn ({text}; dense: too many to draw). Review r223 05b-3: zoomed in past a buffer's
// step, its row stayed blank, as a broken strip would
export function lensRow(z0, width, n, far, fmt_, limit = 600) {
  const win = lensWindow(z0, width, n, far);
  if (win === null) return { text: "no depth is stored outside the near and far planes" };
  const zs = valuesIn(win.za, win.zb, n, far, fmt_, limit);
  if (zs === null) {
    const count = countBetween(win.za, win.zb, n, far, fmt_);
    return { dense: true, text: `${count.toLocaleString("en-US")} values: zoom in to see them one by one` };
  }
  if (zs.length) return { values: zs };
  const where = win.cut ? "in the lens" : `within ± ${fmt(width / 2, 3)}`;
  return { text: `no stored value ${where}: zoom out` };
}

// round ticks for the lens' linear axis [za, zb]: steps of 1, 2 or 5 times a power of ten,
// 3 to 5 of them, each written with the decimals its step needs, so that no two read alike
// and a round z inside the lens (300) shows as itself (review r170 05b-8: "299.9998 ·
// 299.9998 · 299.9999" at z = 300 ± 2.07e-5)
export function lensTicks(za, zb) {
  const lo = Math.max(za, 0);
  const top = Math.floor(Math.log10(zb - lo));
  for (let e = top; e >= top - 3; e--) {
    for (const m of [5, 2, 1]) {
      const step = m * 10 ** e;
      const first = Math.ceil(lo / step);
      const last = Math.floor(zb / step);
      if (last - first < 2) continue;  // fewer than 3: a finer step
      const decimals = Math.max(0, -e);
      const every = last - first > 5 ? 2 : 1;  // at most 6 labels across the lens
      const ticks = [];
      for (let k = first; k <= last; k++) {
        if (k % every === 0) ticks.push({ z: k * step, label: (k * step).toFixed(decimals) });
      }
      return ticks;
    }
  }
  return [];
}

// the lens' centre, written with as many decimals as its ticks (the title said "z = 300" for
// a lens on 299.99985)
export function lensCentre(z0, width) {
  const step = lensTicks(z0 - width / 2, z0 + width / 2);
  const decimals = step.length ? (step[0].label.split(".")[1] || "").length : 0;
  return z0.toFixed(Math.min(decimals + 1, 12));
}

// per buffer: the value stored for z, one step there (in z) and the values beyond z; nothing
// in front of the near plane, where a fragment is clipped and no buffer stores a depth (the
// mappings would give negative float depths there, and unorm would clamp them to 0)
export function depthTable(z, n, f) {
  if (z < n) {
    return `At z = ${fmt(z, 6)} (near ${fmt(n, 3)}, far ${fmt(f, 4)}): in front of the ` +
      "near plane. A fragment there is clipped: no depth buffer stores a value for it.";
  }
  let zeroStep = false;
  const rows = FORMATS.map(([fmtName, name]) => {
    const nb = neighbours(z, n, f, fmtName);
    // at the near plane float32 stores 0 and its neighbour is the smallest denormal, 2^-149:
    // a step of z too small for z + step to differ from z in a double (review r59 05b-7)
    const denormal = fmtName === "float32" && nb.value === 0;
    const step = nb.zFarther - nb.z || (denormal ? (2 ** -149 * (f - n) * z * z) / (f * n) : 0);
    // [z, far) and the value at far itself
    const beyond = countBetween(Math.max(z, n), f, n, f, fmtName) + 1;
    const all = countBetween(n, f, n, f, fmtName) + 1;
    if (denormal) zeroStep = true;
    return `<tr><td>${name}</td><td>${nb.value.toPrecision(9)}</td><td>${fmt(step, 3)}` +
      `${denormal ? " *" : ""}</td><td>${beyond.toLocaleString()} of ${all.toLocaleString()} ` +
      `(${(100 * beyond / all).toPrecision(3)} %)</td></tr>`;
  });
  // review r170 05b-9: the step to the smallest denormal is a property of an exact 0, not
  // float32's resolution at the near plane, which a student would otherwise quote
  const note = zeroStep ? "<div>* At the near plane float32 stores exactly 0, and the next " +
    "float up is the smallest denormal, 2<sup>−149</sup>: a step only an exact 0 has. Just " +
    "beyond the near plane float32's step is relative, about 2<sup>−24</sup> of the stored " +
    "value (move the pointer right to see it grow).</div>" : "";
  return `At z = ${fmt(z, 6)} (near ${fmt(n, 3)}, far ${fmt(f, 4)}):<table><tr><th>buffer</th>` +
    "<th>stored value</th><th>one step in z</th><th>values for distances beyond z</th></tr>" +
    `${rows.join("")}</table>${note}`;
}
