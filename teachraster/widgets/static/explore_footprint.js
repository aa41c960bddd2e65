// Lesson 09: a screen pixel and its footprint in texture space, both ways round.
//
// The kernel renders a checkerboard floor once (uv and the quad derivatives ∂uv/∂x, ∂uv/∂y
// of every pixel, teachraster.render(..., derivatives=True)); the page does the rest. Click a
// screen pixel: its footprint (the pixel square mapped by the derivatives, and the ellipse
// inscribed in it) in texture space, with λ = log2 ρ and the levels GL's filters choose.
// Click in texture space: the pixels whose footprint ellipse holds that point. λ and the
// levels are teachraster.pipeline.texturing.texture_filters' (mip_level, nearest_level,
// linear_levels), the probes teachraster.plotting.footprint's: the tests compare them.

// log2 of the length of the derivative d in texels: ½ log2((d_u W)² + (d_v H)²)
export function log2Length(d, w, h) {
  return 0.5 * Math.log2((d[0] * w) ** 2 + (d[1] * h) ** 2);
}

// GL's nearest mip level: 0 if λ <= ½, else ⌈λ + ½⌉ − 1, clamped to 0 … q
export function nearestLevel(lam, q) {
  const level = lam <= 0.5 ? 0 : Math.ceil(lam + 0.5) - 1;
  return Math.min(Math.max(level, 0), q);
}

// the two levels a linear-between-levels filter reads and its blend weight
export function linearLevels(lam, q) {
  const c = Math.min(Math.max(lam, 0), q);
  const d1 = Math.floor(c);
  return [d1, Math.min(d1 + 1, q), c - d1];
}

// Everything the picture says about one pixel's footprint (lengths in texels of level 0).
export function footprintOf(uv, ddx, ddy, w, h, q, maxAnisotropy = 16) {
  const centre = [uv[0] * w, uv[1] * h];
  const ax = [ddx[0] * w, ddx[1] * h];
  const ay = [ddy[0] * w, ddy[1] * h];
  const px = Math.hypot(ax[0], ax[1]);
  const py = Math.hypot(ay[0], ay[1]);
  const lam = Math.max(log2Length(ddx, w, h), log2Length(ddy, w, h));
  const [pmax, pmin] = [Math.max(px, py), Math.min(px, py)];
  let probes = 1;
  // ⌈P_max / P_min⌉ blind to rounding noise, as the engine's ANISOTROPY_ROUNDING (4096 ε)
  const ratio = (pmax / pmin) * (1 - 4096 * Number.EPSILON);
  if (pmax > 1) probes = Math.min(pmin > 0 ? Math.ceil(ratio) : maxAnisotropy, maxAnisotropy);
  const major = px >= py ? ax : ay;
  const probeCentres = [];
  for (let i = 1; i <= probes; i++) {
    const o = i / (probes + 1) - 0.5;
    probeCentres.push([centre[0] + o * major[0], centre[1] + o * major[1]]);
  }
  return { centre, axisX: ax, axisY: ay, rho: pmax, lam, nearest: nearestLevel(lam, q),
    linear: linearLevels(lam, q), probes, probeLam: Math.log2(pmax / probes), probeCentres };
}

// The anisotropic probes as the static figure draws them (teachraster.plotting.footprint.
// plot_footprint): a square of side P_max / N at each probe's centre, [x, y, side] with
// (x, y) its upper-left corner in texels of level 0. One probe is trilinear's own read.
export function probeSquares(fp) {
  const side = fp.rho / fp.probes;
  return fp.probeCentres.map(([x, y]) => [x - side / 2, y - side / 2, side]);
}

// whether `point` (texels) lies in the pixel's footprint ellipse: 2 (p - c) = s a + t b with
// s² + t² <= 1 (teachraster.plotting.footprint.footprint_contains)
export function ellipseHolds(uv, ddx, ddy, w, h, point) {
  const c = [uv[0] * w, uv[1] * h];
  const a = [ddx[0] * w, ddx[1] * h];
  const b = [ddy[0] * w, ddy[1] * h];
  const r = [2 * (point[0] - c[0]), 2 * (point[1] - c[1])];
  const det = a[0] * b[1] - a[1] * b[0];
  if (det === 0) return false;
  const s = (r[0] * b[1] - r[1] * b[0]) / det;
  const t = (a[0] * r[1] - a[1] * r[0]) / det;
  return s * s + t * t <= 1;
}

// The texel squares (level-0 texels: [x, y, side]) a pixel's trilinear filter fetches: the
// 2 x 2 texels around u W_L - 1/2 at level ⌊λ⌋, and at ⌊λ⌋ + 1 where its weight is not 0
// (teachraster.pipeline.texturing.texel_fetch.filtered; a power-of-two texture).
export function trilinearTaps(uv, ddx, ddy, w, h, q) {
  const lam = Math.max(log2Length(ddx, w, h), log2Length(ddy, w, h));
  const [l0, l1, t] = linearLevels(Number.isNaN(lam) ? 0 : lam, q);
  const out = [];
  for (const level of t > 0 ? [l0, l1] : [l0]) {
    const size = 2 ** level;
    const x0 = Math.floor(uv[0] * (w / size) - 0.5);
    const y0 = Math.floor(uv[1] * (h / size) - 0.5);
    for (const [dx, dy] of [[0, 0], [1, 0], [0, 1], [1, 1]]) out.push([(x0 + dx) * size, (y0 + dy) * size, size, level]);
  }
  return out;
}

export function trilinearReads(uv, ddx, ddy, w, h, q, point) {
  return trilinearTaps(uv, ddx, ddy, w, h, q).some(([x, y, s]) =>
    point[0] >= x && point[0] < x + s && point[1] >= y && point[1] < y + s);
}

// the pixels (row, col) that read `point`: their trilinear filter fetches a texel holding
// it ("trilinear"), or their footprint ellipse holds it ("ellipse")
export function pixelsReading(data, point, how = "trilinear") {
  const out = [];
  for (let r = 0; r < data.height; r++) {
    for (let c = 0; c < data.width; c++) {
      const i = r * data.width + c;
      const uv = data.uv[i];
      if (!uv) continue;
      const [dx, dy] = [data.ddx[i], data.ddy[i]];
      const hit = how === "ellipse" ? ellipseHolds(uv, dx, dy, data.texW, data.texH, point)
        : trilinearReads(uv, dx, dy, data.texW, data.texH, data.q, point);
      if (hit) out.push([r, c]);
    }
  }
  return out;
}

const LEVEL_COLOURS = ["#0072B2", "#56B4E9", "#009E73", "#F0E442", "#E69F00", "#D55E00",
  "#CC79A7", "#000000"];

function textureCanvas(data) {
  const c = document.createElement("canvas");
  [c.width, c.height] = [data.texW, data.texH];
  const cx = c.getContext("2d");
  const img = cx.createImageData(data.texW, data.texH);
  data.texture.forEach((v, i) => {
    const g = Math.round(255 * v);
    img.data.set([g, g, g, 255], 4 * i);
  });
  cx.putImageData(img, 0, 0);
  return c;
}

function mount(el, data, host) {
  const W = data.width;
  const H = data.height;
  const whole = { cx: (data.repeats * data.texW) / 2, cy: (data.repeats * data.texH) / 2,
    half: (data.repeats * data.texW) / 2 + 4 };
  const state = { pixel: data.pixel, point: null, view: whole, follow: true, how: "trilinear",
    ...host.state() };
  const root = frame(el, data.title,
    "Left, the floor on the screen; right, the same floor in texture space, with every pixel " +
    "centre as a dot. Click a pixel (or move it with the arrow keys): its footprint appears " +
    "in texture space, the ellipse the filters approximate, with λ, the level chosen and the " +
    "anisotropic probes (green). " +
    "Click in texture space: the pixels whose footprint holds that point light up. Beyond " +
    "the floor's edge the texture is drawn paler: the wrapped texels a filter reads there.");
  const cell = Math.max(6, Math.min(12, Math.floor(480 / W)));
  const [screen, sctx] = makeCanvas(W * cell, H * cell, "the textured floor, pixel by pixel");
  const T = 420;
  const [tex, tctx] = makeCanvas(T, T, "the texture: footprints in texels");
  const texImage = textureCanvas(data);
  const readout = element("div", { class: "tr-x-readout", "aria-live": "polite" });
  const repaint = (e) => paint.request(e);
  const row = element("div", { class: "tr-x-row" }, [screen, tex]);
  row.style.alignItems = "flex-start";
  root.append(footprintControls(state, host, whole, repaint), row, readout);
  const small = screenPicture(data);

  const fpOf = ([r, c]) => {
    const i = r * W + c;
    return data.uv[i] ? footprintOf(data.uv[i], data.ddx[i], data.ddy[i], data.texW, data.texH,
      data.q) : null;
  };
  const view = () => {
    const fp = state.pixel && fpOf(state.pixel);
    if (!state.follow || !fp) return state.view;
    const ext = Math.max(Math.hypot(...fp.axisX), Math.hypot(...fp.axisY), fp.rho, 4);
    return { cx: fp.centre[0], cy: fp.centre[1], half: 1.3 * ext };
  };
  const toTex = (v, [x, y]) => [v.cx + ((x - T / 2) / (T / 2)) * v.half, v.cy + ((y - T / 2) / (T / 2)) * v.half];
  const fromTex = (v, [u, w]) => [T / 2 + ((u - v.cx) / v.half) * (T / 2), T / 2 + ((w - v.cy) / v.half) * (T / 2)];

  function draw() {
    const v = view();
    const reading = state.point ? pixelsReading(data, state.point, state.how) : [];
    drawScreen(sctx, small, W, H, cell, state.pixel, reading);
    drawTexture(tctx, texImage, data, v, T, fromTex);
    for (const [r, c] of reading.slice(0, 60)) drawFootprint(tctx, fpOf([r, c]), v, fromTex, false);
    const fp = state.pixel && fpOf(state.pixel);
    if (fp) {
      const i = state.pixel[0] * W + state.pixel[1];
      drawPicked(tctx, fp, trilinearTaps(data.uv[i], data.ddx[i], data.ddy[i], data.texW,
        data.texH, data.q), v, fromTex);
    }
    if (state.point) {
      const [x, y] = fromTex(v, state.point);
      tctx.fillStyle = OKABE.vermillion;
      tctx.beginPath();
      tctx.arc(x, y, 5, 0, 2 * Math.PI);
      tctx.fill();
    }
    drawZoomLabel(tctx, v, T);  // last: nothing drawn over it
    readout.innerHTML = footprintText(state, fp, reading);
    host.picture(screen, tex);
  }
  const paint = painter(screen, draw);
  footprintInput(screen, tex, { state, host, W, H, cell, view, toTex, repaint });
  paint.now();
  return {
    setState(s) {
      Object.assign(state, s);
      paint.request();
    },
  };
}

// the floor as the kernel rendered it, one canvas pixel per pixel (drawn scaled up)
function screenPicture(data) {
  const small = document.createElement("canvas");
  [small.width, small.height] = [data.width, data.height];
  const x = small.getContext("2d");
  const image = x.createImageData(data.width, data.height);
  data.image.forEach((v, i) => image.data.set([v[0], v[1], v[2], 255], 4 * i));
  x.putImageData(image, 0, 0);
  return small;
}

// the texture view's window (the whole floor, or following the footprint) and what a click
// in texture space stands for
function footprintControls(state, host, whole, repaint) {
  const wholeBtn = button("whole floor", (e) => {
    Object.assign(state, { view: whole, follow: false });
    host.setState({ view: state.view, follow: false });
    repaint(e);
  });
  const zoomBtn = button("zoom to the footprint", (e) => {
    state.follow = true;
    host.setState({ follow: true });
    repaint(e);
  });
  const hows = choiceButtons([["trilinear", "read by trilinear (its texels)"],
    ["ellipse", "in the footprint ellipse"]], state.how, (how, e) => {
    state.how = how;
    host.setState({ how });
    repaint(e);
  });
  // the choice and its label wrap as one group: at 150 % zoom the five controls took 4 lines
  const how = element("span", { class: "tr-x-row" }, [element("span", { text: "a texel point is" }),
    ...hows.buttons]);
  how.style.margin = "0";
  return element("div", { class: "tr-x-row" }, [wholeBtn, zoomBtn, how]);
}

// a screen pixel picked (click, arrow keys); a texel point picked (click in texture space)
function footprintInput(screen, tex, v) {
  const { state, host, W, H, cell, view, toTex, repaint } = v;
  pointerInput(screen, {
    onClick(p, e) {
      state.pixel = [Math.min(H - 1, Math.floor(p[1] / cell)), Math.min(W - 1, Math.floor(p[0] / cell))];
      host.setState({ pixel: state.pixel });
      repaint(e);
    },
  });
  pointerInput(tex, {
    onClick(p, e) {
      state.point = toTex(view(), p);
      state.view = view();
      state.follow = false;
      host.setState({ point: state.point, view: state.view, follow: false });
      repaint(e);
    },
  });
  onKeys(screen, (e) => {
    const d = { ArrowLeft: [0, -1], ArrowRight: [0, 1], ArrowUp: [-1, 0], ArrowDown: [1, 0] }[e.key];
    if (!d) return;
    e.preventDefault();
    const [r, c] = state.pixel || [0, 0];
    state.pixel = [Math.max(0, Math.min(H - 1, r + d[0])), Math.max(0, Math.min(W - 1, c + d[1]))];
    host.setState({ pixel: state.pixel });
    repaint(e);
  });
}

function drawScreen(ctx, small, W, H, cell, pixel, reading) {
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(small, 0, 0, W * cell, H * cell);
  if (cell >= 8) drawGrid(ctx, 0, 0, W, H, cell, "rgba(120,120,120,0.35)");
  ctx.fillStyle = "rgba(213,94,0,0.75)";
  for (const [r, c] of reading) ctx.fillRect(c * cell + 1, r * cell + 1, cell - 2, cell - 2);
  if (pixel) {
    ctx.strokeStyle = OKABE.yellow;
    ctx.lineWidth = 3;
    ctx.strokeRect(pixel[1] * cell - 1, pixel[0] * cell - 1, cell + 2, cell + 2);
    ctx.strokeStyle = "#000";
    ctx.lineWidth = 1;
    ctx.strokeRect(pixel[1] * cell - 3, pixel[0] * cell - 3, cell + 6, cell + 6);
  }
}

// The copies of the texture that reach a T-px view whose copy (0, 0) starts at (x0, y0), each
// [x, y, onFloor]: the floor's own repeats × repeats copies, and around them, paler, the copies
// a filter reads beyond the floor's edge (wrap "repeat": texel (i, j) is texel (i mod H, j mod
// W)), so that the texel grid and the level squares drawn there lie over what is read (review
// r195 09-4: the view was white beyond the edge).
export function textureTiles(x0, y0, tw, th, T, repeats) {
  const tiles = [];
  const [j0, j1] = [Math.floor(-x0 / tw), Math.ceil((T - x0) / tw)];
  const [i0, i1] = [Math.floor(-y0 / th), Math.ceil((T - y0) / th)];
  for (let i = i0; i < i1; i++) {
    for (let j = j0; j < j1; j++) {
      const onFloor = i >= 0 && j >= 0 && i < repeats && j < repeats;
      tiles.push([x0 + j * tw, y0 + i * th, onFloor]);
    }
  }
  return tiles;
}

function drawTexture(ctx, texImage, data, v, T, fromTex) {
  ctx.fillStyle = "#fff";
  ctx.fillRect(0, 0, T, T);
  ctx.save();
  ctx.imageSmoothingEnabled = false;
  const [x0, y0] = fromTex(v, [0, 0]);
  const s = T / (2 * v.half);
  const [tw, th] = [data.texW * s, data.texH * s];
  for (const [x, y, onFloor] of textureTiles(x0, y0, tw, th, T, data.repeats)) {
    ctx.globalAlpha = onFloor ? 0.55 : 0.22;
    ctx.drawImage(texImage, x, y, tw, th);
  }
  ctx.globalAlpha = 1;
  // every covered pixel's centre, where it samples the texture
  ctx.fillStyle = "rgba(0,0,0,0.8)";
  const dot = Math.max(1.5, Math.min(3, s * 0.3));
  data.uv.forEach((uv) => {
    if (!uv) return;
    const [x, y] = fromTex(v, [uv[0] * data.texW, uv[1] * data.texH]);
    if (x >= -3 && y >= -3 && x <= T + 3 && y <= T + 3) ctx.fillRect(x - dot / 2, y - dot / 2, dot, dot);
  });
  ctx.restore();
}

// The texture view's span, "u … to …: … texels across", which lesson 09 sends students to read
// as they walk a pixel up the floor: 16 px on a white box in the lower left, drawn last (review
// r246 FIG1: at 12 px its glyphs were 9 px tall, against 16 for the line under the pictures).
// The width is said as a width (review r257 S4: "texels 54.15…76.2 across" read as a count).
export const ZOOM_LABEL_PX = 16;
export function drawZoomLabel(ctx, v, T) {
  const span = `u ${fmt(v.cx - v.half, 3)} to ${fmt(v.cx + v.half, 3)}`;
  const text = `${span}: ${fmt(2 * v.half, 3)} texels across`;
  const px = textPx(ctx, ZOOM_LABEL_PX);
  ctx.save();
  ctx.font = `${px}px sans-serif`;
  ctx.fillStyle = "rgba(255,255,255,0.85)";
  ctx.fillRect(2, T - px - 10, ctx.measureText(text).width + 8, px + 8);
  ctx.fillStyle = "#111";
  ctx.fillText(text, 6, T - 8);
  ctx.restore();
}

// The picked pixel's footprint over the texture: the texels trilinear fetches, then the
// nearest level's texel grid over them, then the footprint itself (mapped square, side-ρ
// square, probes, ellipse).
export function drawPicked(ctx, fp, taps, v, fromTex) {
  drawTaps(ctx, taps, v, fromTex);
  drawLevelGrid(ctx, fp, v, fromTex);
  drawFootprint(ctx, fp, v, fromTex, true);
}

// the texels the trilinear filter fetches: level ⌊λ⌋ in purple, ⌊λ⌋ + 1 in green, each
// outline a little inside its texel, so that the level grid on the texel borders stays in
// view (review r246 FIG1: at the default pixel the nearest level is the fetched level 3,
// whose outlines lay on its grid lines and hid them)
const TAP_INSET = 3;
function drawTaps(ctx, taps, v, fromTex) {
  const first = Math.min(...taps.map((t) => t[3]));
  ctx.save();
  ctx.setLineDash([7, 4]);
  ctx.lineWidth = 2.5;
  for (const [x, y, s, level] of taps) {
    const [x0, y0] = fromTex(v, [x, y]);
    const [x1, y1] = fromTex(v, [x + s, y + s]);
    const inset = Math.min(TAP_INSET, 0.15 * (x1 - x0));
    ctx.strokeStyle = level === first ? OKABE.purple : OKABE.green;
    ctx.strokeRect(x0 + inset, y0 + inset, x1 - x0 - 2 * inset, y1 - y0 - 2 * inset);
  }
  ctx.restore();
}

// The texel grid of GL's nearest level around the footprint (2^level texels of level 0):
// dotted blue, opaque and over the fetched texels' outlines. Its lines fall on check borders
// whenever a texel is a check wide (level 3): at 35 % opacity under the outlines it did not
// show at all there (review r246 FIG1).
export const LEVEL_GRID = { colour: OKABE.blue, width: 3, dash: [5, 3] };
function drawLevelGrid(ctx, fp, v, fromTex) {
  const [a, b, c] = [fp.axisX, fp.axisY, fp.centre];
  const size = 2 ** fp.nearest;
  const ext = Math.max(fp.rho, Math.hypot(...a), Math.hypot(...b)) * 0.8 + size;
  ctx.save();
  ctx.strokeStyle = LEVEL_GRID.colour;
  ctx.lineWidth = LEVEL_GRID.width;
  ctx.setLineDash(LEVEL_GRID.dash);
  ctx.beginPath();
  for (let g = Math.floor((c[0] - ext) / size) * size; g <= c[0] + ext; g += size) {
    const [x0, y0] = fromTex(v, [g, c[1] - ext]);
    const [, y1] = fromTex(v, [g, c[1] + ext]);
    ctx.moveTo(x0, y0);
    ctx.lineTo(x0, y1);
  }
  for (let g = Math.floor((c[1] - ext) / size) * size; g <= c[1] + ext; g += size) {
    const [x0, y0] = fromTex(v, [c[0] - ext, g]);
    const [x1] = fromTex(v, [c[0] + ext, g]);
    ctx.moveTo(x0, y0);
    ctx.lineTo(x1, y0);
  }
  ctx.stroke();
  ctx.restore();
}

function drawFootprint(ctx, fp, v, fromTex, main) {
  if (!fp) return;
  const [a, b, c] = [fp.axisX, fp.axisY, fp.centre];
  const P = (k1, k2) => fromTex(v, [c[0] + (k1 * a[0] + k2 * b[0]) / 2, c[1] + (k1 * a[1] + k2 * b[1]) / 2]);
  if (main) {
    ctx.setLineDash([6, 4]);
    ctx.strokeStyle = "#000";
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    [P(-1, -1), P(1, -1), P(1, 1), P(-1, 1)].forEach((p, i) => (i ? ctx.lineTo(...p) : ctx.moveTo(...p)));
    ctx.closePath();
    ctx.stroke();
    ctx.setLineDash([]);
    const [sx, sy] = fromTex(v, [c[0] - fp.rho / 2, c[1] - fp.rho / 2]);
    const [ex, ey] = fromTex(v, [c[0] + fp.rho / 2, c[1] + fp.rho / 2]);
    ctx.strokeStyle = OKABE.orange;
    ctx.lineWidth = 2.5;
    ctx.strokeRect(sx, sy, ex - sx, ey - sy);
    drawProbes(ctx, fp, v, fromTex);
  }
  ctx.strokeStyle = main ? OKABE.blue : "rgba(213,94,0,0.8)";
  ctx.lineWidth = main ? 3 : 1.5;
  ctx.beginPath();
  for (let k = 0; k <= 64; k++) {
    const t = (2 * Math.PI * k) / 64;
    const p = P(Math.cos(t), Math.sin(t));
    if (k) ctx.lineTo(...p);
    else ctx.moveTo(...p);
  }
  ctx.stroke();
}

// the anisotropic probes (GL's formula, lesson 09 §6): green squares in two shades by turns,
// a dot at each centre, as in the lesson's static footprint figure (review r233 M3)
function drawProbes(ctx, fp, v, fromTex) {
  const shades = ["rgba(0,158,115,0.30)", "rgba(0,90,69,0.30)"];
  ctx.save();
  probeSquares(fp).forEach(([x, y, s], k) => {
    const [x0, y0] = fromTex(v, [x, y]);
    const [x1, y1] = fromTex(v, [x + s, y + s]);
    ctx.fillStyle = shades[k % 2];
    ctx.fillRect(x0, y0, x1 - x0, y1 - y0);
    if (fp.probes > 1) {
      ctx.strokeStyle = "rgba(0,90,69,0.9)";
      ctx.lineWidth = 1.2;
      ctx.strokeRect(x0, y0, x1 - x0, y1 - y0);
    }
  });
  ctx.fillStyle = "#005A45";
  for (const c of fp.probeCentres) {
    const [x, y] = fromTex(v, c);
    ctx.beginPath();
    ctx.arc(x, y, 3.5, 0, 2 * Math.PI);
    ctx.fill();
  }
  ctx.restore();
}

export function footprintText(state, fp, reading) {
  const parts = [];
  if (fp) {
    const [r, c] = state.pixel;
    const [l0, l1, t] = fp.linear;
    // two decimals throughout, as the lesson's printouts (r104 09-7: "axes 0.976 and 1.44",
    // "λ = 0.526" beside "λ = 1.7")
    const f2 = (x) => x.toFixed(2);
    // the derivative vectors' lengths (GL's P_x, P_y), not the ellipse's axes: the two
    // differ where the vectors are not perpendicular (lesson 09, §6)
    parts.push(`<b>Pixel (row ${r}, col ${c})</b>: its footprint's extents along x and y ` +
      `(the derivative vectors' lengths, GL's P<sub>x</sub> and P<sub>y</sub>) are ` +
      `${f2(Math.hypot(...fp.axisX))} and ${f2(Math.hypot(...fp.axisY))} texels ` +
      `(dashed: the pixel square, mapped; blue: the ellipse). ρ = ${f2(fp.rho)}, ` +
      `λ = log₂ ρ = ${f2(fp.lam)}: GL's nearest mip level is <b>${fp.nearest}</b> ` +
      `(its texel grid, dotted blue); trilinear blends levels ${l0} and ${l1}` +
      `${t > 0 ? ` (weight ${f2(t)} on ${l1})` : " (one level)"} over the orange square of ` +
      `side ρ, fetching 2 × 2 texels of each (dashed: <span style="color:#CC79A7">level ` +
      `${l0}</span>${t > 0 ? `, <span style="color:#009E73">level ${l1}</span>` : ""}); anisotropic (GL's formula) takes ${fp.probes} ` +
      `probe${fp.probes > 1 ? "s" : ""} at λ = ${f2(fp.probeLam)} (green squares, a dot at ` +
      `each centre).`);
  } else if (state.pixel) {
    parts.push(`Pixel (row ${state.pixel[0]}, col ${state.pixel[1]}) is not on the floor.`);
  }
  if (state.point) {
    const [u, v] = state.point;
    const how = state.how === "ellipse" ? "lies in the footprint ellipse of"
      : "is fetched by the trilinear filter of";
    parts.push(`<b>Texel point (${fmt(u, 4)}, ${fmt(v, 4)})</b> ${how} ` +
      `${reading.length} pixel${reading.length === 1 ? "" : "s"} (vermillion on the screen).`);
  }
  return parts.join("<br>") || "Click a pixel on the left, or a point of the texture on the right.";
}
