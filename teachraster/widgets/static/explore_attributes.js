// Lessons 03/04: an attribute f over the screen triangle, in 3-D (drag to turn it).
//
// Over a flat triangle (every w equal) f is a plane: the affine interpolation Σ λ_k f_k. Over
// a perspective one, f/w and 1/w are still planes over the screen (Ek, eq. 19), and the
// perspective-correct f is their ratio, a curved sheet; the affine plane misses it. The
// w slider moves one vertex away from the eye. The values are those of
// teachraster.core.barycentrics.barycentric and core.interpolation.perspective_weights
// (the tests compare them).

// screen barycentrics λ of point p in the triangle xy (λ_k is 1 at vertex k)
export function barycentrics(xy, p) {
  const [a, b, c] = xy;
  const area = edgeValue(a, b, c);
  return [edgeValue(b, c, p) / area, edgeValue(c, a, p) / area, edgeValue(a, b, p) / area];
}

// every surface at p: λ, f/w, 1/w, their ratio (perspective-correct f) and the affine f
export function surfaceValues(xy, w, f, p) {
  const lam = barycentrics(xy, p);
  const fw = lam[0] * (f[0] / w[0]) + lam[1] * (f[1] / w[1]) + lam[2] * (f[2] / w[2]);
  const inv = lam[0] / w[0] + lam[1] / w[1] + lam[2] / w[2];
  const affine = lam[0] * f[0] + lam[1] * f[1] + lam[2] * f[2];
  return { lam, fw, inv, correct: fw / inv, affine };
}

// the largest |affine - correct| over the triangle, on an n-step barycentric grid
export function largestGap(xy, w, f, n = 48) {
  let best = { gap: 0, p: xy[0] };
  for (let i = 0; i <= n; i++) {
    for (let j = 0; i + j <= n; j++) {
      const l = [i / n, j / n, (n - i - j) / n];
      const p = [0, 1].map((k) => l[0] * xy[0][k] + l[1] * xy[1][k] + l[2] * xy[2][k]);
      const s = surfaceValues(xy, w, f, p);
      const gap = Math.abs(s.affine - s.correct);
      if (gap > best.gap) best = { gap, p, s };
    }
  }
  return best;
}

// The point between a and b (d(a), d(b) of opposite signs) where d changes sign, by
// bisection: d is not linear along a side (the f sheet is a ratio), a cut interpolated
// linearly would leave a sliver of the wrong sign.
function signChange(a, b, d, da) {
  let [lo, hi] = [0, 1];
  for (let k = 0; k < 40; k++) {
    const t = (lo + hi) / 2;
    const dt = d([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
    if (dt === 0) [lo, hi] = [t, t];
    else if (dt > 0 === da > 0) lo = t;
    else hi = t;
  }
  const t = (lo + hi) / 2;
  return [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
}

// Polygon [[x, y], ...] cut by the sign of the function d: the parts where d >= 0 and where
// d <= 0 (each side's sign change found by signChange), each left out when empty.
function splitBySign(pts, d) {
  const ds = pts.map(d);
  const parts = [[], []];
  pts.forEach((a, i) => {
    const j = (i + 1) % pts.length;
    const [da, db] = [ds[i], ds[j]];
    if (da >= 0) parts[0].push(a);
    if (da <= 0) parts[1].push(a);
    if ((da > 0 && db < 0) || (da < 0 && db > 0)) {
      const cut = signChange(a, pts[j], d, da);
      parts[0].push(cut);
      parts[1].push(cut);
    }
  });
  return parts.filter((q) => q.length >= 3);
}

// The drawn sheets (`names`, keys of surfaceValues) over the triangle xy as pieces for
// drawPolygons, on one barycentric mesh of n steps shared by every sheet, each cell cut
// wherever two of the sheets cross (review r89 03-1: sorted whole, a piece straddling the
// crossing put one sheet in front over all of it, a staircase). Over each piece one sheet
// lies wholly above or below another, so the painter's sort of a piece's centre is right
// between the sheets over it. Also `crossing`: segments [[x, y, value], [x, y, value]] of
// the curve where the perspective-correct and affine f meet, when both are drawn (a conic,
// Σλf/w = (Σλf)(Σλ/w); with only v3's w moved, the edge v1v2 and the line from v3 where the
// affine f equals v3's f: for w1 = w2 their difference is, up to a positive factor,
// λ3 (1 - w1/w3) (λ1 (f1 - f3) + λ2 (f2 - f3))). A side of the triangle is left out.
export function sheetPieces(xy, w, f, names, n = 16) {
  const at = (i, j) => [0, 1].map((k) => xy[0][k] + (i / n) * (xy[1][k] - xy[0][k]) +
    (j / n) * (xy[2][k] - xy[0][k]));
  const cells = [];
  for (let i = 0; i < n; i++) {
    for (let j = 0; i + j < n; j++) {
      cells.push([at(i, j), at(i + 1, j), at(i, j + 1)]);
      if (i + j + 1 < n) cells.push([at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
    }
  }
  const value = (p) => surfaceValues(xy, w, f, p);
  const pairs = [];
  names.forEach((a, k) => names.slice(k + 1).forEach((b) => pairs.push([a, b])));
  let parts = cells;
  for (const [a, b] of pairs) {
    const d = (p) => { // zero below rounding: no sliver cut off along a side where they meet
      const v = value(p);
      return Math.abs(v[a] - v[b]) < 1e-12 ? 0 : v[a] - v[b];
    };
    parts = parts.flatMap((pts) => splitBySign(pts, d));
  }
  const pieces = parts.map((pts) => {
    const values = pts.map(value);
    return Object.fromEntries(names.map((name) =>
      [name, pts.map((p, k) => [p[0], p[1], values[k][name]])]));
  });
  const crossing = [];
  const gap = (p) => {
    const v = value(p);
    return Math.abs(v.correct - v.affine) < 1e-12 ? 0 : v.correct - v.affine;
  };
  if (names.includes("correct") && names.includes("affine")) {
    for (const pts of cells) {
      // a corner on the curve (|d| below rounding) is one of the segment's ends
      const ds = pts.map(gap);
      const ends = [];
      pts.forEach((p, i) => {
        const j = (i + 1) % 3;
        if (ds[i] === 0) ends.push([p[0], p[1], value(p).affine]);
        if ((ds[i] > 0 && ds[j] < 0) || (ds[i] < 0 && ds[j] > 0)) {
          const q = signChange(p, pts[j], gap, ds[i]);
          ends.push([q[0], q[1], value(q).affine]);
        }
      });
      // not along the triangle's own side (v1v2 above: the sheets meet there, at its border)
      const lams = ends.map((q) => barycentrics(xy, q));
      const onSide = [0, 1, 2].some((k) => lams.every((l) => Math.abs(l[k]) < 1e-9));
      if (ends.length === 2 && !onSide) crossing.push(ends);
    }
  }
  return { pieces, crossing };
}

// the sentence under the picture: it speaks of a sheet only while that sheet is drawn
// (review r78 03-1: with every w equal, 1/w is a constant, f/w is f scaled by it)
export function readoutText(w, show, gap) {
  if (w.every((v) => v === w[0]) || !(gap.gap > 1e-9)) {
    let text = "Every w is equal: f/w is f scaled by the same 1/w at every vertex, and 1/w is " +
      "a constant, so their ratio is the affine plane itself.";
    if (show.correct) {
      text += " The perspective-correct and affine sheets coincide and are drawn once, in blue.";
    } else if (show.affine) {
      text += " The affine sheet (orange) is the perspective-correct one too.";
    }
    return text;
  }
  const where = `at (${fmt(gap.p[0], 3)}, ${fmt(gap.p[1], 3)})`;
  const text = `Largest |affine − perspective-correct| over the triangle: ` +
    `<b>${fmt(gap.gap, 3)}</b> ${where}, where f = ${fmt(gap.s.correct, 3)} but the affine ` +
    `plane gives ${fmt(gap.s.affine, 3)}.`;
  return show.correct && show.affine
    ? `${text} The vermillion bar marks it.`
    : `${text} Switch both f sheets on to see it as a bar.`;
}

// the sheets are drawn this opaque over the white page (their swatches show that colour)
const SHEET_ALPHA = 0.55;

// a sheet's colour as the picture shows it on white: `hex` at SHEET_ALPHA over #fff, "rgb(...)"
export function sheetTint(hex) {
  const rgb = [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16));
  return `rgb(${rgb.map((c) => Math.round(SHEET_ALPHA * c + (1 - SHEET_ALPHA) * 255)).join(", ")})`;
}

const SURFACES = [
  ["correct", "f, perspective-correct = (f/w) / (1/w)", OKABE.blue],
  ["affine", "f, affine (screen-space plane)", OKABE.orange],
  ["fw", "f/w (a plane)", OKABE.purple],
  ["inv", "1/w (a plane)", OKABE.green],
];

// The polygons of the picture for drawPolygons: the screen and the triangle (grey, under
// everything) and the sheets `names` (see sheetPieces) at a value of 1 standing zScale high.
export function scenePolys(xy, w, f, names, W, H, zScale) {
  const polys = surfacePieces([[0, 0], [W, 0], [W, H], [0, H]], () => 0, 6,
    { fill: "#eee", alpha: 1, stroke: "#ccc", bias: -1e6 });
  polys.push({ pts: xy.map(([x, y]) => [x, y, 0]), fill: "#bbb", alpha: 0.8, stroke: "#555",
    bias: -1e5 });
  const colours = Object.fromEntries(SURFACES.map(([name, , colour]) => [name, colour]));
  const { pieces, crossing } = sheetPieces(xy, w, f, names);
  for (const piece of pieces) {
    for (const name of names) {
      polys.push({ pts: piece[name].map(([x, y, v]) => [x, y, v * zScale]), sheet: name,
        fill: colours[name], alpha: SHEET_ALPHA, stroke: "rgba(255,255,255,0.25)" });
    }
  }
  return { polys, crossing };
}

// for the tests: the sheets' polygons projected for a camera turned to `view` ({yaw,
// elevation}), in the order drawn (`exact`: exactOrder; else by centre depth, as before r96)
export function drawnSheets(xy, w, f, names, W, H, view, exact = true) {
  const zScale = 0.55 * Math.max(W, H);
  const cam = camera3d({ centre: [W / 2, H / 2, zScale / 2], ...view });
  const { polys } = scenePolys(xy, w, f, names, W, H, zScale);
  const depth = (poly) => poly.pts.reduce((acc, p) => acc + cam.project(p)[2], 0) /
    poly.pts.length + (poly.bias || 0);
  const order = exact ? exactOrder(cam, polys)
    : polys.map((_, i) => i).sort((a, b) => depth(polys[a]) - depth(polys[b]));
  return order.filter((i) => polys[i].sheet)
    .map((i) => ({ sheet: polys[i].sheet, s: polys[i].pts.map(cam.project) }));
}

// below this projected length (px) the bar has no room for a label at each end and one at
// its middle (each 22 px tall): its three values go on one line
export const GAP_LABELS_APART = 30;

// the labels of the gap bar ({p, text, color, font}) when it is `barPx` long on the screen:
// f at its f end, the gap at its middle, the affine value at the other end; one line of all
// three at the bar's middle when barPx < GAP_LABELS_APART (review r96 03-2)
export function gapBarLabels(gap, zScale, barPx) {
  const [x, y] = gap.p;
  const at = (v) => [x, y, v * zScale];
  const f = ` f ${fmt(gap.s.correct, 3)}`;
  const affine = ` affine ${fmt(gap.s.affine, 3)}`;
  const size = ` gap ${fmt(gap.gap, 3)}`;
  const middle = (gap.s.correct + gap.s.affine) / 2;
  if (barPx < GAP_LABELS_APART) {
    return [{ p: at(middle), text: `${f} /${affine} /${size}`, color: OKABE.vermillion,
      font: "bold 16px sans-serif" }];
  }
  // over the sheets: haloed (r57 03-2); each end of the bar named with its value (r89 03-2)
  return [
    { p: at(middle), text: size, color: OKABE.vermillion, font: "bold 17px sans-serif" },
    { p: at(gap.s.correct), text: f, color: OKABE.blue, font: "bold 16px sans-serif" },
    { p: at(gap.s.affine), text: affine, color: "#9a5f00", font: "bold 16px sans-serif" },
  ];
}

// the value-axis ticks (of 0, ½, 1) labelled when a value of 1 stands zScale high, the view
// at `scale` px a unit and `elevation`: all three while ½ is 24 px (a label's height) up
// the screen, else 0 alone
export function valueTicks(scale, elevation, zScale) {
  return scale * zScale * Math.cos(elevation) / 2 >= 24 ? [0, 0.5, 1] : [0];
}

// The corner of the W x H screen leftmost in a view at `yaw` (`elevation` turns nothing
// sideways): the value axis stands there. The view keeps vertical lines vertical, so every
// sheet, standing over a point of the screen, lies on the picture at or right of that corner:
// the axis and its labels stay clear of them (review r226 FIG3: at the fixed corner (0, 0),
// turned to the front, it ran through them; r288 FIG2: at the far corner, behind the sheets,
// its labels lay over them and its 0 floated mid-picture, the ground there hidden).
export function axisCorner(W, H, yaw, elevation) {
  void elevation;
  const corners = [[0, 0], [W, 0], [W, H], [0, H]];
  const across = ([x, y]) => x * Math.cos(yaw) - y * Math.sin(yaw); // as camera3d's x
  return corners.reduce((left, c) => (across(c) < across(left) - 1e-9 ? c : left));
}

// Where a vertex label stands: below its vertex on the screen, where the ground is, since
// every sheet (a value f >= 0) rises above the vertex (review r226 FIG3: above it, the blue
// sheet's lower edge crossed v1's label). The text's baseline `base` px under the box's top.
export const VERTEX_LABEL = { up: -4, down: 22, base: 17 };

function mount(el, data, host) {
  let state = { w: data.w, show: { correct: true, affine: true, fw: false, inv: false },
    ...host.state() };
  const root = frame(el, data.title,
    "Height is the value. Drag the picture to turn it. With every w equal the triangle is " +
    "flat on the screen and f is one plane; move v3 away (its w) and f/w and 1/w stay " +
    "planes, but f, their ratio, becomes a curved sheet that the affine plane misses.");
  const [canvas, ctx] = makeCanvas(640, 470, "the attribute surfaces over the screen triangle");
  const readout = element("div", { class: "tr-x-readout", "aria-live": "polite" });
  const toggles = SURFACES.map(([key, name, colour]) => {
    const b = button(name, (e) => {
      state.show = { ...state.show, [key]: !state.show[key] };
      b.setAttribute("aria-pressed", String(state.show[key]));
      host.setState({ show: state.show });
      paint.request(e);
    }, state.show[key]);
    // each sheet's colour as the picture shows it, keyed on its button: a swatch framed in
    // white, seen on a pressed button's blue too (a left stripe of the perspective-correct
    // sheet's full blue vanished into it: the one sheet the text is about had no key, reviews
    // r312, r335, r342 FIG)
    const swatch = element("span", { class: "tr-x-swatch", "aria-hidden": "true" });
    swatch.style.cssText = `display:inline-block;width:0.9em;height:0.9em;margin-right:6px;` +
      `vertical-align:-0.1em;background:${sheetTint(colour)};border:2px solid #fff;` +
      "outline:1px solid #555";
    b.prepend(swatch);
    return b;
  });
  const wSlider = slider("w of v3", { min: 1, max: 8, step: 0.1, value: state.w[2],
    format: (v) => v.toFixed(1) }, (v, e) => {
    state.w = [state.w[0], state.w[1], v];
    paint.request(e);
  });
  wSlider.input.addEventListener("change", () => host.setState({ w: state.w }));
  root.append(element("div", { class: "tr-x-row" }, toggles),
    element("div", { class: "tr-x-row" }, [wSlider]), canvas, readout);
  const [W, H] = [data.width, data.height];
  const zScale = 0.55 * Math.max(W, H); // a value of 1 stands this many pixels high
  // scale and position: fitted to the picture at each draw (fitView)
  const cam = camera3d({ centre: [W / 2, H / 2, zScale / 2], yaw: -0.5, elevation: 0.45 });

  // the surfaces and the largest gap depend on w and on what is shown, not on the view:
  // computed once per change, only projected again while the picture turns
  let cached = { key: null };
  function scene() {
    const key = JSON.stringify([state.w, state.show]);
    if (cached.key === key) return cached;
    const { xy, f } = data;
    const w = state.w;
    // every w equal: the affine sheet is the perspective-correct one; drawn twice, the two
    // coplanar sheets z-fought into a speckle (review r9, lesson 03 c23): one is drawn
    const same = w.every((v) => v === w[0]) && state.show.correct;
    const names = SURFACES.map(([name]) => name)
      .filter((name) => state.show[name] && !(same && name === "affine"));
    const { polys, crossing } = scenePolys(xy, w, f, names, W, H, zScale);
    cached = { key, polys, crossing, gap: largestGap(xy, w, f) };
    return cached;
  }

  function draw() {
    ctx.clearRect(0, 0, 640, 470);
    const { xy, f } = data;
    const w = state.w;
    const { polys, crossing, gap } = scene();
    // the labels: the value axis at the far corner (0, ½, 1), each vertex, the gap. Text
    // no smaller than 15 px: the canvas is shown shrunk to the notebook's column on a small
    // screen (review r7: 10-11 px there)
    const [ax0, ay0] = axisCorner(W, H, cam.yaw, cam.elevation);
    const labels = [0, 0.5, 1].map((v) => ({ p: [ax0, ay0, v * zScale], text: ` ${v}`,
      color: "#333", font: "16px sans-serif", fixed: true, up: 17, down: 5, halo: true }));
    xy.forEach(([x, y], k) => labels.push({ p: [x, y, 0], color: "#111",
      text: ` v${k + 1}: f=${fmt(f[k], 3)}, w=${fmt(w[k], 3)}`, font: "bold 16px sans-serif",
      halo: true, ...VERTEX_LABEL }));
    const showGap = state.show.correct && state.show.affine && gap.gap > 1e-9;
    const first = labels.length;
    // the bar's labels: one at each end and one at its middle while the bar stands tall
    // enough for them, else one line (r96 03-2: seen from above, the three fell on v3's)
    const gapLabels = (barPx) => gapBarLabels(gap, zScale, barPx)
      .map((l) => ({ ...l, halo: true, up: 17, down: 5 }));
    if (showGap) labels.push(...gapLabels(Infinity));
    const measure = () => labels.forEach((l) => {
      ctx.font = l.font;
      l.w = ctx.measureText(l.text).width + 4;
    });
    measure();
    // the view fitted to what is drawn at this turn (review r78 03-3), above the key line
    const points = polys.flatMap((poly) => poly.pts).concat([[ax0, ay0, zScale]]);
    const box = { left: 8, top: 8, right: 632, bottom: 440 };
    fitView(cam, points, labels, box);
    if (showGap) {
      const [x, y] = gap.p;
      const [a, b] = [gap.s.correct, gap.s.affine].map((v) => cam.project([x, y, v * zScale]));
      const barPx = Math.hypot(a[0] - b[0], a[1] - b[1]);
      if (barPx < GAP_LABELS_APART) {
        labels.splice(first, labels.length - first, ...gapLabels(barPx));
        measure();
        fitView(cam, points, labels, box);
      }
    }
    // seen from high above the axis is short and its labels 0, ½, 1 fell on one another
    // (review r96 03-2): only those a label's height apart are kept
    const shown = valueTicks(cam.scale, cam.elevation, zScale);
    labels.splice(0, 3, ...labels.slice(0, 3).filter((l, k) => shown.includes([0, 0.5, 1][k])));
    // the ground first (its bias puts it under everything), then the value axis at the far
    // corner, which every sheet covering it on the screen stands in front of (axisCorner), then
    // each overlap of the sheets in its true order (r96 03-1) at rest; while the view turns, by
    // centre depth: the exact order costs ~130 ms a picture (node, 564 pieces), a 5-fps drag
    drawPolygons(ctx, cam, polys.filter((poly) => !poly.sheet));
    line3d(ctx, cam, [ax0, ay0, 0], [ax0, ay0, zScale], "#555", 1.5);
    for (const v of shown) { // a tick at each labelled height, where its label points
      const [tx, ty] = cam.project([ax0, ay0, v * zScale]);
      strokeLine(ctx, [tx, ty], [tx + 5, ty], "#555", 1.5);
    }
    drawPolygons(ctx, cam, polys.filter((poly) => poly.sheet), !cam.dragging);
    // where the two f sheets cross (see sheetPieces), drawn over them (r89 03-1)
    for (const [a, b] of crossing) {
      line3d(ctx, cam, [a[0], a[1], a[2] * zScale], [b[0], b[1], b[2] * zScale], "#222", 2.5);
    }
    if (showGap) {
      const [x, y] = gap.p;
      const ends = [[gap.s.correct, OKABE.blue], [gap.s.affine, OKABE.orange]];
      line3d(ctx, cam, [x, y, ends[0][0] * zScale], [x, y, ends[1][0] * zScale],
        OKABE.vermillion, 3);
      for (const [v, colour] of ends) {
        const q = cam.project([x, y, v * zScale]);
        ctx.beginPath();
        ctx.arc(q[0], q[1], 5, 0, 2 * Math.PI);
        ctx.fillStyle = colour;
        ctx.fill();
        ctx.lineWidth = 1.5;
        ctx.strokeStyle = "#222";
        ctx.stroke();
      }
    }
    xy.forEach(([x, y], k) => {
      line3d(ctx, cam, [x, y, 0], [x, y, f[k] * zScale], "#444", 1, [3, 3]);
    });
    // labels pushed apart where they would overlap, a thin leader back to a moved one
    const anchors = labels.map((l) => cam.project(l.p));
    const ys = spreadLabels(labels.map((l, i) => ({ x: anchors[i][0], y: anchors[i][1] - l.up,
      w: l.w, h: l.up + l.down, fixed: l.fixed })), 0, 444);
    labels.forEach((l, i) => {
      const [x, y] = [anchors[i][0], ys[i] + (l.base ?? l.up)]; // the text's baseline
      if (Math.abs(ys[i] + l.up - anchors[i][1]) > 3) { // moved off its place: a leader
        strokeLine(ctx, anchors[i], [x + 4, y - 5], l.color, 1);
      }
      label2d(ctx, x, y, l.text, l.color, l.font, l.halo);
    });
    ctx.fillStyle = "#333";
    ctx.font = "15px sans-serif";
    ctx.fillText(crossing.length
      ? "grey: the screen and the triangle; black: where the two f sheets cross"
      : "grey: the screen and the triangle; height: the value (axis at the left corner)", 8, 462);
    readout.innerHTML = readoutText(w, state.show, gap);
    host.picture(canvas);
  }
  const paint = painter(canvas, draw);
  orbitDrag(canvas, cam, (e) => paint.request(e));
  paint.now();
  return {
    setState(s) {
      state = { ...state, ...s };
      wSlider.set(state.w[2]);
      paint.request();
    },
  };
}
