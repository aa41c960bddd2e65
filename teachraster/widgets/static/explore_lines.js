// Lesson 12a's diamond-exit rule, live: the diamonds a line's caption talks about, with end
// points that snap onto ties.
//
// Pixel (row i, col j) owns the open diamond |x - (j + 1/2)| + |y - (i + 1/2)| < 1/2; a line
// lights the pixels whose diamond the segment p0 -> p1 meets and goes on out of, not the one
// it ends in (GL 4.6 §14.5.1, Direct3D). GL removes ties by moving both end points by
// -(ε, ε²); here, as in teachraster.core.line_rules, that perturbation is carried exactly:
// values n0 + n1 ε + n2 ε² compared lexicographically, on the snapped grid, with y down (as
// Vulkan's Bresenham rule; GL's window has y up). The tests compare every decision with the
// engine's.

export const MISSED = 0;
export const LIT = 1;
export const ENDS_INSIDE = 2;
const SPREAD = 2;

// t = (c - a') / d for the perturbed start a' = a - ε - tie ε²: [n0, n1, n2, den], den > 0
function bound(c, a, d, tie) {
  const s = Math.sign(d);
  return [(c - a) * s, s, s * tie, Math.abs(d)];
}

// x < y for perturbed values, lexicographic in powers of ε; also whether ε decided it
function less(x, y) {
  for (let k = 0; k < 3; k++) {
    const lhs = x[k] * y[3];
    const rhs = y[k] * x[3];
    if (lhs !== rhs) return [lhs < rhs, k > 0];
  }
  return [false, true];
}

// open bounds (lo, hi) on t for |u(t) - centre| < half along one diagonal axis
function axisBounds(centre, a, d, half, tie) {
  if (d === 0) {
    const off = a - centre; // the perturbed start is inside iff -h < off <= h
    return [[-1, 0, 0, 1], [2, 0, 0, 1], off > -half && off <= half, off === half || off === -half];
  }
  const [near, far] = d > 0 ? [centre - half, centre + half] : [centre + half, centre - half];
  return [bound(near, a, d, tie), bound(far, a, d, tie), true, false];
}

// Whether the perturbed segment a -> b (units) meets the open diamond of pixel (row, col)
// and whether it ends inside: [state, tie], tie when GL's perturbation (or the half-open
// diamond) decided it. As teachraster.core.line_rules.diamond_states.
export function diamondState(a, b, unit, row, col) {
  const half = unit / 2;
  const [cx, cy] = [col * unit + half, row * unit + half];
  const [au, av, bu, bv] = [a[0] + a[1], a[0] - a[1], b[0] + b[1], b[0] - b[1]];
  const [loU, hiU, okU, tieU] = axisBounds(cx + cy, au, bu - au, half, 1);
  const [loV, hiV, okV, tieV] = axisBounds(cx - cy, av, bv - av, half, -1);
  // equal entry (exit) bounds pick the same t: a tie there decides nothing (review r63)
  const [uFirst] = less(loU, loV);
  const lo = uFirst ? loV : loU;
  const [hFirst] = less(hiU, hiV);
  const hi = hFirst ? hiU : hiV;
  const [c1, t3] = less(lo, hi);
  const [c2, t4] = less(lo, [1, 0, 0, 1]);
  const [c3, t5] = less([0, 0, 0, 1], hi);
  const meets = okU && okV && c1 && c2 && c3;
  const [du, dv] = [bu - (cx + cy), bv - (cx - cy)];
  const ends = du > -half && du <= half && dv > -half && dv <= half;
  const onEdge = Math.abs(du) + Math.abs(dv) <= 2 * half && (Math.abs(du) === half || Math.abs(dv) === half);
  // a comparison's tie decides only where the other two hold or tie too (review r71)
  const [h1, h2, h3] = [c1 || t3, c2 || t4, c3 || t5];
  const decides = (t3 && h2 && h3) || (t4 && h1 && h3) || (t5 && h1 && h2);
  const tie = tieU || tieV || (okU && okV && decides) || onEdge;
  return [meets ? (ends ? ENDS_INSIDE : LIT) : MISSED, tie];
}

// The walk of teachraster.core.line_rules.diamond: one step per major-axis column (or row)
// the segment's diamonds can meet, each with its candidate pixels and their states.
export function diamondSteps(p0, p1, width, height, bits = SUBPIXEL_BITS) {
  const unit = unitsPerPixel(bits);
  const a = [toUnits(p0[0], bits), toUnits(p0[1], bits)];
  const b = [toUnits(p1[0], bits), toUnits(p1[1], bits)];
  const d = [b[0] - a[0], b[1] - a[1]];
  const xMajor = Math.abs(d[0]) >= Math.abs(d[1]);
  if (a[0] === b[0] && a[1] === b[1]) return { xMajor, a, b, unit, steps: [] };
  const axis = xMajor ? 0 : 1;
  const other = 1 - axis;
  const size = xMajor ? width : height;
  const limit = xMajor ? height : width;
  const [lo, hi] = [Math.min(a[axis], b[axis]), Math.max(a[axis], b[axis])];
  // diamond j spans (j, j + 1) along the major axis, the segment moved by -ε [lo - ε, hi - ε]:
  // they overlap for ceil(lo) - 1 <= j <= ceil(hi) - 1 (no column the segment never reaches)
  const first = Math.max(Math.ceil(lo / unit) - 1, 0);
  const last = Math.min(Math.ceil(hi / unit) - 1, size - 1);
  const ratio = d[other] / d[axis];
  const steps = [];
  for (let major = first; major <= last; major++) {
    const centre = major * unit + unit / 2;
    const minor = a[other] + (centre - a[axis]) * ratio;
    const base = Math.floor(minor / unit);
    const cands = [];
    for (let k = -SPREAD; k <= SPREAD; k++) {
      const m = base + k;
      if (m < 0 || m >= limit) continue;
      const [row, col] = xMajor ? [m, major] : [major, m];
      const [state, tie] = diamondState(a, b, unit, row, col);
      cands.push({ row, col, state, tie });
    }
    steps.push({ major, minor: minor / unit, cands });
  }
  return { xMajor, a, b, unit, steps };
}

// the lit pixels (row, col), in walking order
export function litPixels(p0, p1, width, height, bits = SUBPIXEL_BITS) {
  const out = [];
  for (const s of diamondSteps(p0, p1, width, height, bits).steps) {
    for (const c of s.cands) if (c.state === LIT) out.push([c.row, c.col]);
  }
  return out;
}

// Whether GL, moving the ends by -(ε, ε²) with y up, decides this walk's ties otherwise: a
// horizontal segment on a row boundary (teachraster.core.line_rules.gl_decides_otherwise)
export function glDecidesOtherwise(walk) {
  const [a, b] = [walk.a, walk.b];
  return a[1] === b[1] && a[0] !== b[0] && a[1] % walk.unit === 0;
}

// Which rule decided a tie, as teachraster.core.line_trace words it (review r160 12a-1)
function tieWords(walk) {
  const words = "A tie, decided by moving the end points by −(ε, ε²) with y down (Vulkan's " +
    "Bresenham rule)";
  if (glDecidesOtherwise(walk)) {
    return words + "; GL moves them with y up and lights the pixel below instead (the line " +
      "lies on a row boundary).";
  }
  return words + "; GL, moving them with y up, decides it the same way.";
}

// What one step decided, in the words of the LinePlayer's captions.
export function stepCaption(walk, k) {
  const s = walk.steps[k];
  if (!s) return "";
  const name = walk.xMajor ? "column" : "row";
  const lit = s.cands.filter((c) => c.state === LIT);
  const ends = s.cands.filter((c) => c.state === ENDS_INSIDE);
  const ties = s.cands.filter((c) => c.tie && c.state !== MISSED);
  const where = (c) => `(row ${c.row}, col ${c.col})`;
  // on the column's (row's) centre line, not at a pixel centre: the value there may be a row
  // boundary, the tie itself (as teachraster.core.line_trace words it)
  const [axis, other] = walk.xMajor ? ["x", "y"] : ["y", "x"];
  let text = `${name} ${s.major}: at ${axis} = ${fmt(s.major + 0.5, 6)}, the ${name}'s centre, ` +
    `the line is at ${other} = ${fmt(s.minor, 6)}. `;
  if (lit.length) text += `It meets the diamond of ${lit.map(where).join(" and ")} and goes on out of it: lit. `;
  if (ends.length) text += `It ends inside the diamond of ${ends.map(where).join(", ")}: left to the next segment. `;
  if (!lit.length && !ends.length) text += "It meets no diamond here: nothing lit. ";
  if (ties.length) text += tieWords(walk);
  return text;
}

// points a dragged end snaps to: pixel centres, diamond corners (edge midpoints), corners
export function snapTarget(x, y, reach) {
  let best = null;
  let bestD = reach;
  const [fx, fy] = [Math.floor(x), Math.floor(y)];
  for (const [ox, oy, kind] of [[0.5, 0.5, "a pixel centre"], [0.5, 0, "a diamond corner"],
    [0, 0.5, "a diamond corner"], [0, 0, "a pixel corner"], [1, 0.5, "a diamond corner"],
    [0.5, 1, "a diamond corner"], [1, 1, "a pixel corner"], [1, 0, "a pixel corner"],
    [0, 1, "a pixel corner"]]) {
    const [px, py] = [fx + ox, fy + oy];
    const dd = Math.hypot(px - x, py - y);
    if (dd < bestD) [best, bestD] = [[px, py, kind], dd];
  }
  return best;
}

function mount(el, data, host) {
  const W = data.width;
  const H = data.height;
  let state = { p0: data.p0, p1: data.p1, step: -1, ...host.state() };
  const root = frame(el, data.title,
    "Each pixel owns the open diamond around its centre. The line lights a pixel when it " +
    "meets its diamond and goes on out of it; the diamond it ends in is left to the next " +
    "segment. Drag p0 or p1: near a pixel centre, a diamond corner or a pixel corner they " +
    "snap onto it, where ties are. Step along the line with the slider (its left end is the " +
    "first step, its right end all of them) or the arrow keys.");
  // axis numbers at 17 px, for the back of a lecture hall (review r83 12a-3): room for them
  const m = { left: 36, top: 30 };
  const { canvas, ctx, cell, toPx, toGrid } = pixelCanvas(W, H, { minCell: 30, maxCell: 64,
    fitW: 760, fitH: 480, margin: m, pad: 14,
    label: "a line over the pixel grid with every pixel's diamond" });
  const caption = element("div", { class: "tr-x-readout", "aria-live": "polite" });
  let walk = diamondSteps(state.p0, state.p1, W, H, data.bits);
  // The slider runs 0 .. n - 1 (one step each) and then n, "all" (state.step -1): its left end
  // is the first column, as a student expects, not "all" (reviews r51 item 8, r63 item 6)
  const toSlider = (s) => (s < 0 ? walk.steps.length : s);
  const fromSlider = (v) => (v >= walk.steps.length ? -1 : v);
  const stepper = slider("step", { min: 0, max: walk.steps.length, step: 1,
    value: toSlider(state.step), format: (v) => (v >= walk.steps.length ? "all" : String(v)) },
  (v, e) => {
    state.step = fromSlider(v);
    paint.request(e);
    host.setState({ step: state.step });
  });
  const count = element("div");
  root.append(element("div", { class: "tr-x-row" }, [stepper, count]), canvas, caption);
  let snapped = [null, null];

  function draw() {
    walk = diamondSteps(state.p0, state.p1, W, H, data.bits);
    stepper.input.max = String(walk.steps.length);
    if (state.step > walk.steps.length - 1) state.step = walk.steps.length - 1;
    stepper.set(toSlider(state.step));
    ctx.clearRect(0, 0, canvas.logical.w, canvas.logical.h);
    drawLineGrid(ctx, W, H, cell, m, toPx);
    const shown = state.step < 0 ? walk.steps : walk.steps.slice(0, state.step + 1);
    shown.forEach((s, k) => {
      const current = state.step >= 0 && k === state.step;
      for (const c of nearCandidates(walk, s)) drawDiamond(ctx, c, toPx, cell, current);
    });
    // the "tie" marks go on top of the line, and the end points' labels keep clear of them
    // (reviews r31, r34: "p1 on a pixel centre" covered a tie, the line crossed one)
    const ties = shown.flatMap((s) => s.cands.filter((c) => c.tie && c.state !== MISSED));
    const boxes = ties.map((c) => tieBox(ctx, c, toPx, cell));
    // the lit squares: an end point's label keeps off them where it can (review r83 12a-3)
    const litBoxes = shown.flatMap((s) => s.cands.filter((c) => c.state === LIT))
      .map((c) => [...toPx([c.col, c.row]), cell, cell]);
    drawSegment(ctx, toPx(state.p0), toPx(state.p1), snapped, boxes, [m.left, m.top],
      { soft: litBoxes, far: cell / 2, bottom: m.top + H * cell + 12 });
    drawTies(ctx, boxes);
    const lit = walk.steps.reduce((n, s) => n + s.cands.filter((c) => c.state === LIT).length, 0);
    count.textContent = `${lit} pixel${lit === 1 ? "" : "s"} lit, ${walk.steps.length} ` +
      `${walk.xMajor ? "columns" : "rows"} walked (${walk.xMajor ? "x" : "y"}-major)`;
    caption.innerHTML = state.step >= 0 ? escapeHtml(stepCaption(walk, state.step))
      : "All steps (the slider's right end). Pick a step to see its diamonds and what the " +
        "rule decided there.";
    host.picture(canvas);
  }
  const paint = painter(canvas, draw, () => [toPx(state.p0), toPx(state.p1)]);

  function place(i, p) {
    let [x, y] = toGrid(p);
    x = Math.max(0, Math.min(W, x));
    y = Math.max(0, Math.min(H, y));
    const target = snapTarget(x, y, 10 / cell);
    snapped[i] = target ? target[2] : null;
    const q = target ? [target[0], target[1]] : [Math.round(x * 64) / 64, Math.round(y * 64) / 64];
    state[i ? "p1" : "p0"] = q;
  }
  pointerInput(canvas, {
    handles: () => [toPx(state.p0), toPx(state.p1)],
    onDrag(i, p, e) {
      place(i, p);
      // a dragged end makes another line: the step shown belonged to the old one, so the
      // view goes back to all steps (review 11-12-r6: "row 1" of the new line was confusing)
      if (state.step !== -1) {
        state.step = -1;
        stepper.set(toSlider(-1));
      }
      paint.request(e);
    },
    onRelease() {
      host.setState({ p0: state.p0, p1: state.p1, step: state.step });
    },
  });
  onKeys(canvas, (e) => {
    const d = { ArrowLeft: -1, ArrowRight: 1, ArrowDown: -1, ArrowUp: 1 }[e.key];
    if (!d) return;
    e.preventDefault();
    // from "all", the right arrow starts at the first step and the left one at the last
    const n = walk.steps.length;
    if (state.step < 0) state.step = d > 0 ? 0 : n - 1;
    else state.step = fromSlider(Math.max(0, Math.min(n, state.step + d)));
    stepper.set(toSlider(state.step));
    paint.request(e);
    host.setState({ step: state.step });
  });
  paint.now();
  return {
    setState(s) {
      state = { ...state, ...s };
      stepper.set(toSlider(state.step));
      paint.request();
    },
  };
}

// The candidates of a walked column (row) worth outlining: those the rule lit, ended in or
// decided by a tie, and the missed ones whose pixel the segment passes through inside that
// column (a diamond the line misses although it crosses the pixel). The others are tested
// (SPREAD) but the line never comes near them: outlining them showed more of the grid than
// the rule looks at (reviews r83 12a-4, r88: one row either side still did).
export function nearCandidates(walk, s) {
  const [ax, ot] = walk.xMajor ? [0, 1] : [1, 0];
  const { a, b, unit } = walk;
  // the part of the segment inside the column, and its extent along the minor axis
  const lo = Math.max(s.major * unit, Math.min(a[ax], b[ax]));
  const hi = Math.min((s.major + 1) * unit, Math.max(a[ax], b[ax]));
  const at = (u) => a[ot] + ((u - a[ax]) * (b[ot] - a[ot])) / (b[ax] - a[ax]);
  const [m0, m1] = [Math.min(at(lo), at(hi)), Math.max(at(lo), at(hi))];
  const crossed = (m) => (m0 === m1 ? m * unit <= m0 && m0 < (m + 1) * unit
    : m * unit < m1 && m0 < (m + 1) * unit);
  return s.cands.filter((c) => c.state !== MISSED || c.tie ||
    crossed(walk.xMajor ? c.row : c.col));
}

function drawLineGrid(ctx, W, H, cell, m, toPx) {
  drawGrid(ctx, m.left, m.top, W, H, cell, "#c8c8c8", 17);
  // every pixel's diamond, faint, and its centre
  ctx.strokeStyle = "#e0e0e0";
  ctx.beginPath();
  for (let r = 0; r < H; r++) {
    for (let c = 0; c < W; c++) diamondPath(ctx, toPx, r, c);
  }
  ctx.stroke();
  ctx.fillStyle = "#888";
  for (let r = 0; r < H; r++) {
    for (let c = 0; c < W; c++) {
      const [x, y] = toPx([c + 0.5, r + 0.5]);
      ctx.fillRect(x - 1.5, y - 1.5, 3, 3);
    }
  }
}

function diamondPath(ctx, toPx, r, c) {
  const pts = [[c + 0.5, r], [c + 1, r + 0.5], [c + 0.5, r + 1], [c, r + 0.5]].map(toPx);
  ctx.moveTo(pts[0][0], pts[0][1]);
  for (const p of pts.slice(1)) ctx.lineTo(p[0], p[1]);
  ctx.closePath();
}

function drawDiamond(ctx, c, toPx, cell, current) {
  const [x, y] = toPx([c.col, c.row]);
  if (c.state === LIT) {
    ctx.fillStyle = "rgba(86,180,233,0.45)";
    ctx.fillRect(x, y, cell, cell);
  }
  ctx.beginPath();
  diamondPath(ctx, toPx, c.row, c.col);
  if (c.state === LIT) {
    ctx.fillStyle = "#0072B2";
    ctx.globalAlpha = 0.55;
    ctx.fill();
    ctx.globalAlpha = 1;
  }
  ctx.lineWidth = current ? 3 : 1.5;
  ctx.strokeStyle = c.state === ENDS_INSIDE ? OKABE.orange : c.state === LIT ? "#0072B2"
    : current ? "#666" : "#aaa";
  if (c.state === ENDS_INSIDE) ctx.setLineDash([5, 3]);
  ctx.stroke();
  ctx.setLineDash([]);
  if (current) {
    ctx.strokeStyle = OKABE.vermillion;
    ctx.lineWidth = 2;
    ctx.strokeRect(x + 1.5, y + 1.5, cell - 3, cell - 3);
  }
}

// Where a tie's mark goes: the word "tie" in the top-left corner of the pixel's square, as
// [x, y, w, h] (top-left of the text, its size) and the font that draws it.
function tieBox(ctx, c, toPx, cell) {
  const [x, y] = toPx([c.col, c.row]);
  const size = Math.max(textPx(ctx, 12), Math.round(cell * 0.28));
  ctx.font = `bold ${size}px sans-serif`;
  return [x + 3, y + 2, ctx.measureText("tie").width, size, ctx.font];
}

function drawTies(ctx, boxes) {
  for (const [x, y, , h, font] of boxes) {
    ctx.font = font;
    haloText(ctx, "tie", x, y + h - 2, OKABE.vermillion);
  }
}

// Text with a white halo, readable where it crosses the line and the diamonds.
function haloText(ctx, text, x, y, colour) {
  ctx.lineWidth = 4;
  ctx.lineJoin = "round";
  ctx.strokeStyle = "rgba(255, 255, 255, 0.9)";
  ctx.strokeText(text, x, y);
  ctx.fillStyle = colour;
  ctx.fillText(text, x, y);
}

function drawSegment(ctx, p, q, snapped, avoid = [], grid = [0, 0], more = {}) {
  ctx.strokeStyle = "#000";
  ctx.lineWidth = 2.5;
  ctx.beginPath();
  ctx.moveTo(p[0], p[1]);
  ctx.lineTo(q[0], q[1]);
  ctx.stroke();
  [p, q].forEach((e, i) => {
    ctx.fillStyle = i ? OKABE.vermillion : "#000";
    ctx.beginPath();
    ctx.arc(e[0], e[1], 7, 0, 2 * Math.PI);
    ctx.fill();
    const size = textPx(ctx, 15);
    ctx.font = `bold ${size}px sans-serif`;
    const text = `p${i}${snapped[i] ? ` on ${snapped[i]}` : ""}`;
    const wide = ctx.canvas.logical ? ctx.canvas.logical.w : ctx.canvas.width;
    const [x, y] = labelAt(e[0], e[1], ctx.measureText(text).width, wide, avoid, size, grid,
      [p, q], more);
    // a label pushed off its point (onto the next pixel, review r168 12a-6: "p0" sat in
    // pixel (1, 0), a cell below its dot) is tied to it by a thin leader
    const lead = leaderLine(e, [x, y, ctx.measureText(text).width, size]);
    if (lead) {
      ctx.strokeStyle = "#111";
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.moveTo(lead[0][0], lead[0][1]);
      ctx.lineTo(lead[1][0], lead[1][1]);
      ctx.stroke();
    }
    // a white halo: the label crosses the line and the diamonds beside the end point
    haloText(ctx, text, x, y, "#111");
  });
}

// The leader from an end point (its dot of radius `radius`) to its label ([x, y, w, size]:
// left end and baseline, width, height), or null when the label is close enough to read as
// the point's: its box within `near` px of the dot's edge.
export function leaderLine(point, label, radius = 7, near = 8) {
  const [x, y, w, size] = label;
  const nx = Math.max(x, Math.min(point[0], x + w));
  const ny = Math.max(y - size, Math.min(point[1], y + 3));
  const d = Math.hypot(nx - point[0], ny - point[1]);
  if (d <= radius + near) return null;
  const ux = (nx - point[0]) / d;
  const uy = (ny - point[1]) / d;
  return [[point[0] + ux * radius, point[1] + uy * radius], [nx - ux * 2, ny - uy * 2]];
}

// Where an end point's label goes (its text's left end and baseline): right of and above the
// point, else left of it (p1 in the last column), else below it (at the top border); of those
// that stay inside the canvas, right of and below the axis labels (`grid`: [left, top] of the
// pixel grid; review r43 12a-8: "p1 on a pixel corner" covered the column numbers), the first
// that covers none of the boxes `avoid` ([x, y, w, h]: the "tie" marks), or the first inside
// if every one covers a mark. A spot the segment itself (`segment`: [p, q], canvas pixels)
// runs through comes after those it does not (review r63 12a-5: "p1 on a pixel centre" was
// written across the line). `more.soft` boxes (the lit squares) are kept clear of where some
// spot allows it, also the spots `more.far` px farther above and below the point (above
// `more.bottom`); review r83 12a-3: "p1 on a pixel centre" lay on a lit diamond.
export function labelAt(x, y, textWidth, canvasWidth, avoid = [], size = 15, grid = [0, 0],
  segment = null, more = {}) {
  const { soft = [], far = 0, bottom = Infinity } = more;
  const left = Math.max(2, grid[0], x - 9 - textWidth);
  const spots = [[x + 9, y - 9], [left, y - 9], [x + 9, y + 22], [left, y + 22]];
  if (far > 0) {
    // where the spot right of the point runs past the border: flush with the border, over
    // the point, where the line does not run (an up-running line ended in row 0)
    const flush = x + 9 + textWidth > canvasWidth - 2 ?
      Math.max(grid[0], canvasWidth - 2 - textWidth) : x + 9;
    spots.push([flush, y + 22], [x + 9, y + 22 + far], [left, y + 22 + far],
      [flush, y + 22 + far], [x + 9, y - 9 - far], [left, y - 9 - far], [flush, y - 9 - far]);
  }
  const inside = spots.filter(([lx, ly]) => lx + textWidth <= canvasWidth - 2 &&
    ly - size >= grid[1] && lx >= grid[0] && ly + 3 <= bottom);
  const off = (boxes, gap = 0) => ([lx, ly]) => boxes.every(([bx, by, bw, bh]) =>
    lx + textWidth + gap < bx || bx + bw + gap < lx || ly < by || by + bh < ly - size);
  // a label beside a "tie" mark on its line keeps a wide space from it: "p0" a few px left
  // of a mark read as one phrase, "p0 tie" (review r101 12a-D)
  const clear = off(avoid, size * 0.8);
  const clearSoft = off(soft);
  const crossed = ([lx, ly]) => segment !== null && Array.from({ length: 65 }, (_, k) => k / 64)
    .some((t) => {
      const sx = segment[0][0] + t * (segment[1][0] - segment[0][0]);
      const sy = segment[0][1] + t * (segment[1][1] - segment[0][1]);
      return sx >= lx && sx <= lx + textWidth && sy >= ly - size && sy <= ly + 3;
    });
  return inside.find((s) => clear(s) && clearSoft(s) && !crossed(s)) ||
    inside.find((s) => clear(s) && !crossed(s)) || inside.find(clear) || inside[0] ||
    [left, y + 22];
}
