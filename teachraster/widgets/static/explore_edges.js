// Lesson 02's edge functions, live: drag the vertices of two triangles that share an edge.
//
// Triangle A is v1 v2 v3, triangle B is v3 v2 v4 (it shares A's edge v2-v3, walked the other
// way). At every pixel centre: the signs of the chosen triangle's E12, E23, E31; each
// half-plane E > 0 tinted; each edge labelled top, left, right or bottom with its bias; the
// centres exactly on the shared edge marked with the triangle that owns them. "3-D" shows
// each E as a plane over the grid, cutting z = 0 along its edge.

// E12, E23, E31 (Okabe-Ito; blue and orange are the triangles A and B)
const EDGE_HUES = ["#CC79A7", "#009E73", "#D55E00"];
const SIGN_COLOURS = { "+": "#0072B2", "−": "#D55E00", "0": "#000000" };

// The picture's numbers for vertices `xy` (four, px): both set-ups, their coverage, the
// signs at every centre and the owner of every centre on the shared edge. Pure: node checks
// it against the engine (tests/test_explorables_js.py).
export function edgeScene(xy, width, height, bits = SUBPIXEL_BITS) {
  const triA = [xy[0], xy[1], xy[2]];
  const triB = [xy[2], xy[1], xy[3]];
  const A = setupTriangle(triA, bits);
  const B = setupTriangle(triB, bits);
  const covA = coverageGrid(A, width, height);
  const covB = coverageGrid(B, width, height);
  const shared = [];
  const [p, q] = [A.given[1], A.given[2]];
  for (let r = 0; r < height; r++) {
    for (let c = 0; c < width; c++) {
      const centre = centreUnits(A, r, c);
      if (edgeValue(p, q, centre) !== 0) continue;
      const within = [0, 1].every((k) => Math.min(p[k], q[k]) <= centre[k] && centre[k] <= Math.max(p[k], q[k]));
      if (!within) continue; // on the line beyond the edge's ends
      const i = r * width + c;
      const owner = covA[i] && covB[i] ? "both" : covA[i] ? "A" : covB[i] ? "B" : "none";
      shared.push({ row: r, col: c, owner });
    }
  }
  return { A, B, covA: Array.from(covA), covB: Array.from(covB), shared };
}

// the sign glyph of an edge value
export function signOf(e) {
  return e > 0 ? "+" : e < 0 ? "−" : "0";
}

// the edges of a set-up as the labels say them: for edge k of the vertices as given
// (E12, E23, E31), its kind and bias once oriented
export function edgeLabels(setup, names) {
  return [0, 1, 2].map((k) => {
    // given edge k runs given[k] -> given[k+1]; oriented, it is the edge that joins the same
    // two vertices
    const a = k;
    const b = (k + 1) % 3;
    const j = [0, 1, 2].find((m) => {
      const i0 = setup.perm[m];
      const i1 = setup.perm[(m + 1) % 3];
      return (i0 === a && i1 === b) || (i0 === b && i1 === a);
    });
    return { name: names[k], kind: setup.kinds[j], bias: setup.topLeft[j] ? 0 : -1,
      flipped: setup.perm[j] !== a };
  });
}

const EDGES_CSS = `
.tr-edges-legend span { display: inline-block; margin-right: 12px; }
.tr-edges-table table { table-layout: fixed; width: 100%; max-width: 860px; }
.tr-edges-table td { padding: 1px 6px; vertical-align: top; text-align: left; }
.tr-edges-views { display: flex; flex-wrap: wrap; align-items: flex-start; gap: 12px; }
.tr-edges-views canvas { flex: none; }
`;

function mount(el, data, host) {
  addCss("tr-edges-css", EDGES_CSS);
  const W = data.width;
  const H = data.height;
  const state = { vertices: data.vertices, chosen: "A", planes: false, snap: 0.25, tint: "none",
    ...host.state() };
  const root = frame(el, data.title,
    "Drag a vertex (or focus the picture, press 1–4 to pick one and move it with the arrow " +
    "keys: a press moves it ¼ px with the snap on, 1/256 px with it off, 1 px with Shift). " +
    "At the pixel centres within a pixel of the chosen triangle's edges, where the " +
    "signs change, and at the centre under the pointer: the signs of E12, E23, E31, in " +
    "their edges' colours; tint a half-plane to see where its E keeps one sign (its sign " +
    "alone is then drawn at every centre, large). A centre " +
    "exactly on the shared edge v2–v3 is ringed in the colour of the triangle that owns it " +
    "(point at it, or at a vertex's centre, for its signs).");
  const m = { left: 30, top: 26 };
  // cells of 50 px on lesson 02's 16 x 14 grid (42 drew the signs about 10 px high at a
  // 1400-px page, review r291 02-2)
  const { canvas, ctx, cell, toPx, toGrid } = pixelCanvas(W, H, { minCell: 22, maxCell: 50,
    fitW: 800, fitH: 700, margin: m, pad: 12,
    label: "two triangles over the pixel grid with the edge-function signs at every centre" });
  const readout = element("div", { class: "tr-x-readout", "aria-live": "polite" });
  const table = element("div", { class: "tr-edges-table" });
  const [view3d, ctx3] = makeCanvas(760, 640, "the three edge functions as planes over the grid");
  const cam = camera3d({ centre: [W / 2, H / 2, 0], elevation: PLANES_ELEVATION, at: [380, 330] });
  cam.maxElevation = 1.2; // never top-down: there the three planes cover one another
  // moved: the pixel [col, row] of the vertex the last input moved (a drag, a key), where the
  // pointer still is: its three signs wait for the pointer to go to another pixel (review
  // r302 02-FIG2: dragged onto v2's row, v3's centre piled "+00", "v3", the B badge and two
  // rings); the readout still describes that centre
  const ui = { scene: null, hover: null, picked: 0, relabel: null, moved: null };

  function draw() {
    const scene = (ui.scene = edgeScene(state.vertices, W, H, data.bits));
    ctx.clearRect(0, 0, canvas.logical.w, canvas.logical.h);
    drawCells(ctx, scene, W, H, cell, m, data.colors);
    const chosen = state.chosen === "A" ? scene.A : scene.B;
    drawHalfPlanes(ctx, chosen, W, H, toPx, cell, state.tint);
    drawGrid(ctx, m.left, m.top, W, H, cell, data.colors.grid, true);
    // the rings and the edges first, the signs over them (a white halo keeps a "0" on its
    // edge readable: drawn under the ring and the line, "0" read as "C", review r231 02-7),
    // then the owners' badges and the vertices' dots and names
    drawRings(ctx, scene, cell, m);
    drawTriangles(ctx, state, toPx, data.colors);
    const quiet = quietCentres(scene, state.vertices);
    drawSigns(ctx, chosen, W, H, cell, m, ["E12", "E23", "E31"].indexOf(state.tint),
      ui.moved ? null : ui.hover, state.vertices.map(toPx), quiet);
    drawBadges(ctx, scene, cell, m, state.vertices.map(toPx));
    const names = vertexNames(ctx, scene, chosen, state, toPx, W, H, cell, m, quiet);
    drawVertices(ctx, state, toPx, names.map((n) => n.at));
    drawEdgeLabels(ctx, chosen, state, toPx, W, H, quiet, names.map((n) => n.box));
    if (ui.relabel) ui.relabel(chosen); // a drag can reverse the winding, and so the names
    table.innerHTML = edgeTable(scene);
    readout.innerHTML = describe(scene, ui.hover, state.chosen, W, H);
    host.picture(canvas);
  }
  const paint = painter(canvas, draw, () => state.vertices.map(toPx));
  const paint3d = painter(view3d, () => drawPlanes(ctx3, cam, ui.scene || edgeScene(
    state.vertices, W, H, data.bits), state.chosen, W, H, view3d, ui.hover));
  const both = (e) => {
    paint.request(e);
    if (state.planes) paint3d.request(e);
  };
  orbitDrag(view3d, cam, (e) => paint3d.request(e));
  const controls = edgeControls(state, host, both, view3d, ui);
  ui.relabel = controls.relabel;
  // the 3-D view beside the grid where the page is wide enough, else right under it, not
  // under the key and the table (review r302 02-FIG2: it opened 900 px below its button)
  const views = element("div", { class: "tr-edges-views" }, [canvas, view3d]);
  root.append(...controls.rows, views, element("div", { html: EDGES_KEY }), readout, table);
  vertexInput(canvas, { state, host, ui, toPx, toGrid, W, H, repaint: both });
  paint.now();
  controls.sync();
  if (state.planes) paint3d.request(); // reopened with the planes on
  return {
    setState(s) {
      Object.assign(state, s);
      controls.sync();
      both();
    },
  };
}

const EDGES_KEY = "Fill: <b style='color:#3a8fc4'>A</b>, <b style='color:#c98a1c'>B</b>, grey " +
  "where they overlap (drawn twice). Ring on a centre of the shared edge: " +
  "<b style='color:#0072B2'>A</b> owns it, <b style='color:#E69F00'>B</b> owns it, " +
  "<b>black (AB)</b>: both, grey (–): neither. Both or neither happens when the two " +
  "triangles lie on the same side of the edge (then it is a left or top edge for both, or a " +
  "right or bottom edge for both), and at a shared vertex, left to a third triangle. " +
  "Tint <i>all three</i>: black hatching where all three E keep the inside's sign, the " +
  "chosen triangle's inside.";

// each triangle's edges as the table names them (B = v3 v2 v4: its first edge runs v3 -> v2)
// (CONVENTIONS: named by its two vertices in walking order)
export const EDGE_NAMES = { A: ["E12", "E23", "E31"], B: ["E32", "E24", "E43"] };

// the tint buttons for the chosen triangle: [state value, label]; the value is the edge's
// place in the triangle (E12: its first edge), the label the edge's name as the figure and
// the table give it: walked backwards when `setup` (the triangle's) is counter-clockwise,
// E23 for B's E32 (review r224-02 #5: one edge, one name on the screen)
export function tintChoices(chosen, setup) {
  const names = setup && setup.area2 !== 0
    ? edgeLabels(setup, EDGE_NAMES[chosen]).map(walkedName) : EDGE_NAMES[chosen];
  return [["none", "no half-plane"], ["E12", `${names[0]}'s`], ["E23", `${names[1]}'s`],
    ["E31", `${names[2]}'s`], ["all", "all three"]];
}

// the explorer's buttons: whose signs, the 3-D planes, the snapping, the half-plane tinted
function edgeControls(state, host, repaint, view3d, ui) {
  const chosen = choiceButtons([["A", "signs of A (v1 v2 v3)"], ["B", "signs of B (v3 v2 v4)"]],
    state.chosen, (which, e) => {
      state.chosen = which;
      sync();
      host.setState({ chosen: which });
      repaint(e);
    });
  const planes = button("3-D: E as planes", (e) => {
    state.planes = !state.planes;
    sync();
    host.setState({ planes: state.planes });
    repaint(e);
    // opened, scrolled into sight (on a projector it fell below the screen's edge)
    if (state.planes && view3d.scrollIntoView) view3d.scrollIntoView({ block: "nearest" });
  }, state.planes);
  const snap = button("snap to ¼ px", () => {
    state.snap = state.snap ? 0 : 0.25;
    sync();
    host.setState({ snap: state.snap });
  }, Boolean(state.snap));
  const tints = choiceButtons(tintChoices(state.chosen), state.tint, (which, e) => {
    state.tint = which;
    host.setState({ tint: which });
    repaint(e);
  });
  // the tint buttons name the chosen triangle's own edges, as the labels and the table do
  function relabel(setup) {
    tintChoices(state.chosen, setup).forEach(([, label], k) => {
      if (tints.buttons[k].textContent !== label) tints.buttons[k].textContent = label;
    });
  }
  function sync() {
    chosen.set(state.chosen);
    relabel(ui.scene ? ui.scene[state.chosen] : null); // the last drawn scene's winding
    tints.set(state.tint);
    planes.setAttribute("aria-pressed", String(state.planes));
    snap.setAttribute("aria-pressed", String(Boolean(state.snap)));
    view3d.style.display = state.planes ? "" : "none";
  }
  const rows = [element("div", { class: "tr-x-row" }, [...chosen.buttons, planes, snap]),
    element("div", { class: "tr-x-row" }, [element("span", { text: "tint the half-plane:" }),
      ...tints.buttons])];
  return { rows, sync, relabel };
}

const pixelOf = ([x, y]) => [Math.floor(x), Math.floor(y)];

// dragging a vertex (snapped to the grid of state.snap px), or moving it with the keys
function vertexInput(canvas, v) {
  const { state, host, ui, toPx, toGrid, W, H, repaint } = v;
  const clampX = (x) => Math.max(0, Math.min(W, x));
  const clampY = (y) => Math.max(0, Math.min(H, y));
  const move = (i, x, y) => {
    state.vertices = state.vertices.map((w, k) => (k === i ? [clampX(x), clampY(y)] : w));
  };
  pointerInput(canvas, {
    handles: () => state.vertices.map(toPx),
    onDrag(i, p, e) {
      ui.picked = i;
      let [x, y] = toGrid(p);
      const s = state.snap;
      if (s) [x, y] = [Math.round(x / s) * s, Math.round(y / s) * s];
      move(i, x, y);
      ui.hover = toGrid(p);
      ui.moved = pixelOf(ui.hover);
      repaint(e);
    },
    onRelease: () => host.setState({ vertices: state.vertices }),
    onHover(p, e) {
      ui.hover = p ? toGrid(p) : null;
      const at = ui.hover && pixelOf(ui.hover);
      if (ui.moved && !(at && at[0] === ui.moved[0] && at[1] === ui.moved[1])) ui.moved = null;
      repaint(e);
    },
  });
  onKeys(canvas, (e) => {
    if (e.key.length === 1 && "1234".includes(e.key)) {
      ui.picked = Number(e.key) - 1;
      return;
    }
    const d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] }[e.key];
    if (!d) return;
    e.preventDefault();
    const step = e.shiftKey ? 1 : state.snap || 1 / 256;
    const [x, y] = state.vertices[ui.picked];
    move(ui.picked, x + d[0] * step, y + d[1] * step);
    ui.hover = state.vertices[ui.picked];
    ui.moved = pixelOf(ui.hover);
    repaint(e);
    host.setState({ vertices: state.vertices });
  });
}

function drawCells(ctx, scene, W, H, cell, m, colors) {
  for (let r = 0; r < H; r++) {
    for (let c = 0; c < W; c++) {
      const i = r * W + c;
      const a = scene.covA[i];
      const b = scene.covB[i];
      if (!a && !b) continue;
      ctx.fillStyle = a && b ? "#b0b0b0" : a ? "#9fd3f3" : "#f3d79c";
      ctx.fillRect(m.left + c * cell, m.top + r * cell, cell, cell);
    }
  }
}

// each edge's half-plane on the triangle's side (E > 0 for a clockwise triangle, E < 0 for a
// counter-clockwise one), tinted in its colour and clipped to the grid
function drawHalfPlanes(ctx, setup, W, H, toPx, cell, which) {
  if (setup.area2 === 0 || which === "none") return;
  const u = setup.unit;
  const far = 4 * (W + H);
  ctx.save();
  const [x0, y0] = toPx([0, 0]);
  ctx.beginPath();
  ctx.rect(x0, y0, W * cell, H * cell);
  ctx.clip();
  const given = setup.given;
  const all = which === "all";
  for (let k = 0; k < 3; k++) {
    if (!all && which !== ["E12", "E23", "E31"][k]) continue;
    const a = given[k].map((t) => t / u);
    const b = given[(k + 1) % 3].map((t) => t / u);
    const d = [b[0] - a[0], b[1] - a[1]];
    const len = Math.hypot(d[0], d[1]) || 1;
    // E > 0 lies to the left of a -> b walking with y down: normal (-dy, dx)
    const n = [(-d[1] / len) * far, (d[0] / len) * far];
    const s = Math.sign(setup.originalArea2) || 1; // the inside's side (orientation)
    const ext = [d[0] / len * far, d[1] / len * far];
    const pts = [[a[0] - ext[0], a[1] - ext[1]], [a[0] + ext[0], a[1] + ext[1]],
      [a[0] + ext[0] + s * n[0], a[1] + ext[1] + s * n[1]],
      [a[0] - ext[0] + s * n[0], a[1] - ext[1] + s * n[1]]].map(toPx);
    ctx.beginPath();
    pts.forEach((p, i) => (i ? ctx.lineTo(p[0], p[1]) : ctx.moveTo(p[0], p[1])));
    ctx.closePath();
    if (all) {
      ctx.clip(); // all three: the half-planes' intersection, hatched below
      continue;
    }
    ctx.globalAlpha = 0.22;
    ctx.fillStyle = EDGE_HUES[k];
    ctx.fill();
  }
  if (all) {
    // where all three keep the inside's sign, hatched in black: the fills keep their colours
    // (three translucent tints blended into the grey of "drawn twice", review r93 02-8b)
    ctx.globalAlpha = 0.6;
    ctx.fillStyle = hatch(ctx, "#000");
    ctx.fillRect(x0, y0, W * cell, H * cell);
  }
  ctx.restore();
}


// a repeating "/" hatch in `colour` (one tile per colour)
const HATCHES = new Map();
function hatch(ctx, colour) {
  const key = colour;
  if (!HATCHES.has(key)) {
    const n = 12;
    const tile = document.createElement("canvas");
    tile.width = tile.height = n;
    const t = tile.getContext("2d");
    t.strokeStyle = colour;
    t.lineWidth = 1.5;
    t.beginPath();
    const lines = [[0, n], [n, 0], [-2, 2], [2, -2], [n - 2, n + 2], [n + 2, n - 2]];
    for (let i = 0; i < lines.length; i += 2) {
      t.moveTo(...lines[i]);
      t.lineTo(...lines[i + 1]);
    }
    t.stroke();
    HATCHES.set(key, ctx.createPattern(tile, "repeat"));
  }
  return HATCHES.get(key);
}

// A glyph drawn once as a small picture (drawImage is many times cheaper than fillText, and a
// grid shows hundreds of them at every frame of a drag)
const SPRITES = new Map();
function sprite(text, colour, size, dpr) {
  const key = `${text}|${colour}|${size}|${dpr}`;
  if (!SPRITES.has(key)) {
    const c = document.createElement("canvas");
    [c.width, c.height] = [Math.ceil(size * dpr), Math.ceil(size * 1.3 * dpr)];
    const x = c.getContext("2d");
    x.scale(dpr, dpr);
    x.font = `bold ${size}px monospace`;
    x.textAlign = "center";
    x.textBaseline = "middle";
    // a white halo: the glyph is drawn over the edges' lines and the rings
    x.lineWidth = Math.max(2, size * SIGN_HALO);
    x.lineJoin = "round";
    x.strokeStyle = "#fff";
    x.strokeText(text, size / 2, size * 0.65);
    x.fillStyle = colour;
    x.fillText(text, size / 2, size * 0.65);
    SPRITES.set(key, c);
  }
  return SPRITES.get(key);
}

// The sign glyphs' size (px) in cells of `cell` px on a canvas `width` px wide: 0.42 of a
// cell, and never less than reads 12 px in the column at 1024 px (review r7 02-4: 0.32 of a
// cell read 11 px; r9 02-5: the glyphs still looked small at 0.38; r93 02-4: 0.42 of a 37-px
// cell drew "+" 9-10 px high, small on a projector: 0.48 of a 42-px cell, as large as three
// glyphs SIGN_GAP of a cell apart allow without touching). Three of them stay inside their
// pixel; with one half-plane tinted its sign alone is drawn, ONE_SIGN_SCALE of a cell.
export const ONE_SIGN_SCALE = 0.75;
// the white halo round each glyph, a share of its size
export const SIGN_HALO = 0.16;
export const SIGN_SCALE = 0.48;
export const SIGN_GAP = 0.3;
export function signSize(cell, width) {
  return Math.max(readablePx(12, width), Math.round(cell * SIGN_SCALE));
}

// How far from the chosen triangle's edges (px) the three signs are drawn: 224 centres of
// three glyphs each read as a texture on a projector (review r169 02-7); near the edges,
// where the signs change from one centre to the next, they are information.
export const SIGNS_NEAR = 1;

// the distance (px) from the point `p` (px) to the segment a -> b (px)
function segmentDistance(a, b, p) {
  const d = [b[0] - a[0], b[1] - a[1]];
  const len2 = d[0] * d[0] + d[1] * d[1];
  const t = len2 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / len2)) : 0;
  return Math.hypot(p[0] - a[0] - t * d[0], p[1] - a[1] - t * d[1]);
}

// Are the three signs drawn at the centre of (row, col)? Within SIGNS_NEAR px of an edge of
// `setup` (the chosen triangle), or the centre under the pointer `hover` (px, or null).
export function signsShown(setup, row, col, hover = null, quiet = []) {
  if (hover && Math.floor(hover[0]) === col && Math.floor(hover[1]) === row) return true;
  if (quiet.some(([r, c]) => r === row && c === col)) return false;
  const u = setup.unit;
  const v = setup.given.map((q) => q.map((t) => t / u));
  const p = [col + 0.5, row + 0.5];
  return [0, 1, 2].some((k) => segmentDistance(v[k], v[(k + 1) % 3], p) <= SIGNS_NEAR);
}

// The centres whose three signs are left to the pointer (signsShown's `quiet`): those on the
// shared edge, whose ring and owner's letter say what the rule decided, and those within
// QUIET_NEAR px of a vertex (`vertices`, grid px), where the dot and its name stand. Their
// "0" digits beside the rings and badges, and "00" over the vertex dots, collided (review
// r291 02-2, r242 02-7); hovering a centre still shows its three signs.
// Also quiet: a centre on the shared edge's line a pixel beyond one of its ends, whose "0"
// stood beside the end's ring and owner's letter ("+0−" left of v3 with v2 and v3 on one row,
// review r328 02-FIG1).
// And quiet: the four centres beside an end of the shared edge that sits on a centre, its
// ring's: the name of the vertex needs a place clear of the ring, and each of those places
// held a centre's three signs ("v3" stood on its ring by the owner's letter, review r343
// 02-FIG1).
export const QUIET_NEAR = 0.75;
const SIDES = [[-1, 0], [1, 0], [0, -1], [0, 1]];
export function quietCentres(scene, vertices) {
  const quiet = scene.shared.map(({ row, col }) => [row, col]);
  const [p, q] = [vertices[1], vertices[2]];
  for (const [x, y] of [p, q]) {
    const ringed = scene.shared.some(({ row, col }) => col + 0.5 === x && row + 0.5 === y);
    if (ringed) for (const [dr, dc] of SIDES) quiet.push([Math.floor(y) + dr, Math.floor(x) + dc]);
  }
  for (const end of [p, q]) {
    for (const [dr, dc] of SIDES) {
      const [x, y] = [end[0] + dc, end[1] + dr];
      const centre = Number.isInteger(x - 0.5) && Number.isInteger(y - 0.5);
      const along = (x - p[0]) * (q[0] - p[0]) + (y - p[1]) * (q[1] - p[1]);
      const beyond = along < 0 || along > (q[0] - p[0]) ** 2 + (q[1] - p[1]) ** 2;
      if (centre && beyond && edgeValue(p, q, [x, y]) === 0) quiet.push([Math.floor(y), Math.floor(x)]);
    }
  }
  for (const [x, y] of vertices) {
    for (let r = Math.floor(y - QUIET_NEAR); r <= Math.floor(y + QUIET_NEAR); r++) {
      for (let c = Math.floor(x - QUIET_NEAR); c <= Math.floor(x + QUIET_NEAR); c++) {
        if (Math.hypot(c + 0.5 - x, r + 0.5 - y) <= QUIET_NEAR) quiet.push([r, c]);
      }
    }
  }
  return quiet;
}

// three sign glyphs per centre near the edges (signsShown): E12, E23, E31 of the chosen
// triangle, in their colours; with one half-plane tinted, its sign at every centre
function drawSigns(ctx, setup, W, H, cell, m, only = -1, hover = null, dots = [], quiet = []) {
  const logical = ctx.canvas.logical;
  const three = signSize(cell, logical ? logical.w : ctx.canvas.width);
  // one half-plane tinted: its sign alone, large (review r93 02-4: read on a projector)
  const size = only < 0 ? three : Math.round(cell * ONE_SIGN_SCALE);
  const dpr = logical ? logical.dpr : 1;
  const gap = cell * SIGN_GAP;
  for (let r = 0; r < H; r++) {
    for (let c = 0; c < W; c++) {
      if (only < 0 && !signsShown(setup, r, c, hover, quiet)) continue;
      const e = givenValues(setup, r, c);
      const cx = m.left + (c + 0.5) * cell;
      let cy = m.top + (r + 0.5) * cell + (only < 0 ? cell * 0.12 : size * 0.25);
      if (only < 0) cy = belowDot(cx, cy, size, cell, dots);
      for (let k = 0; k < 3; k++) {
        if (only >= 0 && k !== only) continue;
        const s = signOf(e[k]);
        const img = sprite(s, s === "0" ? "#000" : EDGE_HUES[k], size, dpr);
        const x = only < 0 ? cx + (k - 1) * gap : cx;
        ctx.drawImage(img, x - size / 2, cy - size * 0.9, size, size * 1.3);
      }
    }
  }
}

// Where a centre's three signs stand (their baseline `cy`, px) when a vertex's dot (radius
// 6 px, `dots` in px) sits on or next to the centre: just below the dot, whose black disc hid
// the middle sign, "0○0" at v1 = (2.5, 1.5) (review r224-02 #4); the vertex's name stands
// above right of its dot, clear of them. A sprite's top 0.3 of its size is blank.
export function belowDot(cx, cy, size, cell, dots) {
  const dot = dots.find((p) => Math.abs(p[0] - cx) < cell * 0.5 && Math.abs(p[1] - cy) < cell * 0.5);
  return dot ? Math.max(cy, dot[1] + 6 + 0.6 * size) : cy;
}

// Which left corner of the cell (row, col) the owner's letter takes: the one farther from
// the line of the shared edge v2-v3, "lower" on a tie (a horizontal edge). The letter's disc
// is centred on that corner of the grid, half a pixel from every centre beside it: inside
// the cell it stood over the centre's left sign (review r231 02-7).
export function ownerCorner(scene, row, col) {
  const u = scene.A.unit;
  const [p, q] = [scene.A.given[1], scene.A.given[2]].map((v) => v.map((t) => t / u));
  const off = (x, y) => Math.abs(edgeValue(p, q, [x, y]));
  return off(col, row + 1) >= off(col, row) ? "lower" : "upper";
}

function ownerColour(owner) {
  return owner === "A" ? OKABE.blue : owner === "B" ? OKABE.orange
    : owner === "both" ? "#000" : "#777";
}

// a ring round each centre of the shared edge, in the colour of the triangle that owns it
function drawRings(ctx, scene, cell, m) {
  for (const { row, col, owner } of scene.shared) {
    ctx.lineWidth = 3;
    ctx.strokeStyle = ownerColour(owner);
    ctx.beginPath();
    ctx.arc(m.left + (col + 0.5) * cell, m.top + (row + 0.5) * cell, cell * 0.42, 0, 2 * Math.PI);
    ctx.stroke();
  }
}

// Where the owner's letter stands (px): on the grid corner ownerCorner picks, clear of the
// centre's signs and of its neighbours' (half a pixel from each). A centre under a vertex's
// dot (`dots`, px) has its signs pushed below the dot (belowDot): its letter takes the upper
// corner, clear of them (the vertex's name stands to the right).
export function badgeCentre(scene, row, col, cell, m, dots = []) {
  const [cx, cy] = [m.left + (col + 0.5) * cell, m.top + (row + 0.5) * cell];
  const under = dots.some((p) => Math.abs(p[0] - cx) < cell * 0.5 && Math.abs(p[1] - cy) < cell * 0.5);
  const low = !under && ownerCorner(scene, row, col) === "lower";
  return [m.left + col * cell, m.top + (low ? row + 1 : row) * cell];
}

// each owner's letter: its text, font size, disc centre and radius (px)
function badges(ctx, scene, cell, m, dots) {
  const size = Math.max(textPx(ctx, 14), Math.round(cell * 0.36));
  ctx.save();
  ctx.font = `bold ${size}px sans-serif`;
  const out = scene.shared.map(({ row, col, owner }) => {
    const text = owner === "both" ? "AB" : owner === "none" ? "–" : owner;
    const r = Math.max(ctx.measureText(text).width / 2 + 2, size * 0.6);
    return { owner, text, size, at: badgeCentre(scene, row, col, cell, m, dots), r };
  });
  ctx.restore();
  return out;
}

// the owner's letter black on a white disc: orange on B's light orange fill was nearly
// invisible, and 7 px high (review r93 02-4)
function drawBadges(ctx, scene, cell, m, dots) {
  for (const { owner, text, size, at: [lx, ly], r } of badges(ctx, scene, cell, m, dots)) {
    ctx.font = `bold ${size}px sans-serif`;
    ctx.fillStyle = "#fff";
    ctx.strokeStyle = ownerColour(owner);
    ctx.beginPath();
    ctx.arc(lx, ly, r, 0, 2 * Math.PI);
    ctx.fill();
    ctx.lineWidth = 1.5;
    ctx.stroke();
    ctx.fillStyle = "#000";
    ctx.textAlign = "center";
    ctx.textBaseline = "middle";
    ctx.fillText(text, lx, ly + 1);
    ctx.textAlign = "left";
    ctx.textBaseline = "alphabetic";
  }
}

function arrowLine(ctx, p, q, colour, width) {
  strokeLine(ctx, p, q, colour, width);
  ctx.fillStyle = colour;
  const t = 0.55;
  const mid = [p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t];
  const ang = Math.atan2(q[1] - p[1], q[0] - p[0]);
  ctx.beginPath();
  ctx.moveTo(mid[0] + 9 * Math.cos(ang), mid[1] + 9 * Math.sin(ang));
  ctx.lineTo(mid[0] + 9 * Math.cos(ang + 2.5), mid[1] + 9 * Math.sin(ang + 2.5));
  ctx.lineTo(mid[0] + 9 * Math.cos(ang - 2.5), mid[1] + 9 * Math.sin(ang - 2.5));
  ctx.closePath();
  ctx.fill();
}

function drawTriangles(ctx, state, toPx, colors) {
  const v = state.vertices.map(toPx);
  const chosen = state.chosen === "A" ? [0, 1, 2] : [2, 1, 3];
  const other = state.chosen === "A" ? [2, 1, 3] : [0, 1, 2];
  ctx.setLineDash([6, 4]);
  ctx.strokeStyle = "#222";
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  other.forEach((i, k) => (k ? ctx.lineTo(v[i][0], v[i][1]) : ctx.moveTo(v[i][0], v[i][1])));
  ctx.closePath();
  ctx.stroke();
  ctx.setLineDash([]);
  for (let k = 0; k < 3; k++) arrowLine(ctx, v[chosen[k]], v[chosen[(k + 1) % 3]], EDGE_HUES[k], 3);
}

// each vertex's dot and name, over the signs, which belowDot keeps off; the names where
// `names` (centres, px) puts them
function drawVertices(ctx, state, toPx, names) {
  const v = state.vertices.map(toPx);
  ctx.font = `bold ${textPx(ctx, 17)}px sans-serif`;
  ctx.textAlign = "center";
  ctx.textBaseline = "middle";
  v.forEach((p, i) => {
    ctx.fillStyle = "#000";
    ctx.beginPath();
    ctx.arc(p[0], p[1], 6, 0, 2 * Math.PI);
    ctx.fill();
    ctx.fillStyle = "#fff";
    ctx.beginPath();
    ctx.arc(p[0], p[1], 3, 0, 2 * Math.PI);
    ctx.fill();
    ctx.fillStyle = "#000";
    ctx.fillText(`v${i + 1}`, names[i][0], names[i][1]);
  });
  ctx.textAlign = "left";
  ctx.textBaseline = "alphabetic";
}

// Does the box [x0, y0, x1, y1] touch the ring (circle [cx, cy, r], its stroke `w` wide) or
// stand inside it, where its centre is?
function boxOnRing(box, [cx, cy, r], w = 3) {
  const gap = [Math.max(box[0] - cx, 0, cx - box[2]), Math.max(box[1] - cy, 0, cy - box[3])];
  return Math.hypot(gap[0], gap[1]) <= r + w / 2;
}

const overlaps = (a, b) => a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];

// Where a vertex's name (a box of half-sizes `half`, px) stands round its dot at `p` (px):
// above right of it when that is free, else the first place, nearest first, whose box touches
// no ring (`rings`, [cx, cy, r]), no box of `boxes` (the owners' letters, the shown signs, the
// other dots and names) and stays inside `bounds` ([x0, y0, x1, y1], the grid); failing
// that, the one next to the dot touching fewest. With v2 and v3 on one row, "v3" stood on
// its ring, beside the B letter (review r328 02-FIG1). A drawn edge (`segments`, [[x, y],
// [x, y]] px) through the box counts as a ring does ("v3" on the dashed edge to v4, r343).
export function vertexNameAt(p, half, cell, bounds, rings, boxes, segments = []) {
  // above right first (where the names stood), then the other diagonals, the sides, and
  // the directions between them
  const dirs = [[1, -1], [-1, -1], [1, 1], [-1, 1], [1, 0], [-1, 0], [0, -1], [0, 1],
    [2, -1], [1, -2], [-1, -2], [-2, -1], [2, 1], [1, 2], [-1, 2], [-2, 1]]
    .map(([x, y]) => [x / Math.hypot(x, y), y / Math.hypot(x, y)]);
  let best = null;
  let fewest = Infinity;
  for (const d of [8, 0.3 * cell, 0.5 * cell, 0.7 * cell, 0.9 * cell, 1.1 * cell]) {
    for (const [ux, uy] of dirs) {
      const reach = d + Math.abs(ux) * half[0] + Math.abs(uy) * half[1];
      const at = [p[0] + ux * reach, p[1] + uy * reach];
      const box = [at[0] - half[0], at[1] - half[1], at[0] + half[0], at[1] + half[1]];
      const out = box[0] < bounds[0] || box[1] < bounds[1] || box[2] > bounds[2] ||
        box[3] > bounds[3];
      if (out) continue;
      // a ring's thin line hides less than a letter or a sign
      const hits = rings.filter((r) => boxOnRing(box, r)).length +
        3 * boxes.filter((b) => overlaps(box, b)).length +
        segments.filter(([s, e]) => segmentCrossesBox(s, e, box)).length;
      if (hits === 0) return at;
      // failing a free place, one next to the dot: a name far off reads as another's
      if (d === 8 && hits < fewest) [best, fewest] = [at, hits];
    }
  }
  return best || [p[0] + 8 + half[0], p[1] - 8 - half[1]];
}

// the centres (px) whose three signs are drawn (with one half-plane tinted, every centre
// shows one sign and no place is free: none), and how far a triplet reaches from its centre
function signCentres(setup, state, toPx, W, H, quiet) {
  const signs = [];
  if (["E12", "E23", "E31"].includes(state.tint)) return signs;
  for (let r = 0; r < H; r++) {
    for (let c = 0; c < W; c++) {
      if (signsShown(setup, r, c, null, quiet)) signs.push(toPx([c + 0.5, r + 0.5]));
    }
  }
  return signs;
}
const signReach = (cell) => [cell * SIGN_GAP + cell * SIGN_SCALE / 2, cell * 0.3];

// The vertices' names (centres, px, and boxes) clear of the rings, the owners' letters, the
// shown signs, the dots and one another (vertexNameAt), inside the grid
function vertexNames(ctx, scene, setup, state, toPx, W, H, cell, m, quiet) {
  const v = state.vertices.map(toPx);
  const reach = signReach(cell);
  const boxes = signCentres(setup, state, toPx, W, H, quiet)
    .map(([x, y]) => [x - reach[0], y - reach[1], x + reach[0], y + reach[1]]);
  for (const { at: [x, y], r } of badges(ctx, scene, cell, m, v)) boxes.push([x - r, y - r, x + r, y + r]);
  for (const [x, y] of v) boxes.push([x - 7, y - 7, x + 7, y + 7]);
  const rings = scene.shared.map(({ row, col }) => [...toPx([col + 0.5, row + 0.5]), cell * 0.42]);
  const grid = [...toPx([0, 0]), ...toPx([W, H])];
  ctx.save();
  ctx.font = `bold ${textPx(ctx, 17)}px sans-serif`;
  const size = textPx(ctx, 17);
  const at = v.map((p, i) => {
    const half = [ctx.measureText(`v${i + 1}`).width / 2 + 2, size * 0.55];
    const c = vertexNameAt(p, half, cell, grid, rings, boxes, edgeSegments(v));
    const box = [c[0] - half[0], c[1] - half[1], c[0] + half[0], c[1] + half[1]];
    boxes.push(box);
    return { at: c, box };
  });
  ctx.restore();
  return at;
}

// each edge of the chosen triangle labelled with its kind and bias, outside the triangle
function drawEdgeLabels(ctx, setup, state, toPx, W, H, quiet = [], names = []) {
  if (setup.area2 === 0) return;
  const idx = state.chosen === "A" ? [0, 1, 2] : [2, 1, 3];
  const v = idx.map((i) => toPx(state.vertices[i]));
  const centroid = [(v[0][0] + v[1][0] + v[2][0]) / 3, (v[0][1] + v[1][1] + v[2][1]) / 3];
  const labels = edgeLabels(setup, EDGE_NAMES[state.chosen]);
  const size = textPx(ctx, 15);
  const cell = toPx([1, 0])[0] - toPx([0, 0])[0];
  const signs = signCentres(setup, state, toPx, W, H, quiet);
  const reach = signReach(cell);
  const grid = [...toPx([0, 0]), ...toPx([W, H])]; // inside the grid's frame, not on it
  const segments = edgeSegments(state.vertices.map(toPx)); // no label across a line
  ctx.save();
  ctx.font = `bold ${size}px sans-serif`;
  ctx.textAlign = "center";
  ctx.textBaseline = "middle";
  labels.forEach((e, k) => {
    const a = v[k];
    const b = v[(k + 1) % 3];
    // B's edges named too (review r93 02-5: "left, bias 0" beside A's "E12: right, bias −1")
    const text = `${walkedName(e)}: ${e.kind}, bias ${e.bias < 0 ? "−1" : "0"}`;
    const half = [ctx.measureText(text).width / 2 + 3, (size + 3) / 2];
    const at = placeLabel(a, b, centroid, half, cell, grid, signs, reach, names, segments);
    ctx.fillStyle = "rgba(255,255,255,0.85)";
    ctx.fillRect(at[0] - half[0], at[1] - half[1], 2 * half[0], 2 * half[1]);
    ctx.fillStyle = EDGE_HUES[k];
    ctx.fillText(text, at[0], at[1]);
  });
  ctx.restore();
}

// Where an edge's label goes: beside the edge's midpoint on the side away from the triangle,
// its box (half-sizes `half`, px) a whole half-pixel clear of the edge's line, so that it
// never covers the ringed centres on a shared edge or their owner badges (review r192 02-6:
// a horizontal shared edge's label hid the rings the lesson asks students to look at).
// With the canvas's size `bounds` ([w, h], px) given, a box that would stick out of it goes
// to the triangle's side of the edge instead, and failing that is pushed inside (review
// r224-02 #3: "E21: right, bias −1" lost its "−1" at the canvas's right side).
// With `covers` (a box's centre -> how many centres' signs it hides), the first place that
// fits and hides none is taken: along the edge, then farther out, then on the triangle's side;
// failing that, the one that hides fewest (review r224-02 #4: "E12: right, bias −1" stood
// over two centres' signs).
export function labelCentre(a, b, centroid, half, cell, bounds, covers = null) {
  const mid = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
  const len = Math.hypot(b[0] - a[0], b[1] - a[1]) || 1;
  let n = [(a[1] - b[1]) / len, (b[0] - a[0]) / len];
  if (n[0] * (mid[0] - centroid[0]) + n[1] * (mid[1] - centroid[1]) < 0) n = [-n[0], -n[1]];
  const reach = Math.abs(n[0]) * half[0] + Math.abs(n[1]) * half[1];
  const away = 0.5 * cell + 2 + reach;
  const outside = [mid[0] + n[0] * away, mid[1] + n[1] * away];
  if (!bounds) return outside;
  // [w, h] from the origin, or a rectangle [x0, y0, x1, y1] (the grid: review r328 02-FIG1,
  // "E34: left, bias 0" stood on its bottom frame, inside the canvas)
  const [x0, y0, x1, y1] = bounds.length === 4 ? bounds : [0, 0, ...bounds];
  const fits = (p) => p[0] - half[0] >= x0 && p[0] + half[0] <= x1 &&
    p[1] - half[1] >= y0 && p[1] + half[1] <= y1;
  if (covers) {
    let best = null;
    let fewest = Infinity;
    for (const side of [1, -1]) {
      for (const extra of [0, 0.5 * cell, cell]) {
        for (const t of [0.5, 0.4, 0.6, 0.3, 0.7]) {
          const d = side * (away + extra);
          const p = [a[0] + t * (b[0] - a[0]) + n[0] * d, a[1] + t * (b[1] - a[1]) + n[1] * d];
          const hidden = fits(p) ? covers(p) : Infinity;
          if (hidden === 0) return p;
          if (hidden < fewest) [best, fewest] = [p, hidden];
        }
      }
    }
    if (best) return best;
  }
  if (fits(outside)) return outside;
  const inside = [mid[0] - n[0] * away, mid[1] - n[1] * away];
  const at = fits(inside) ? inside : outside;
  const clamp = (x, h, lo, hi) => Math.max(lo + h, Math.min(hi - h, x));
  return [clamp(at[0], half[0], x0, x1), clamp(at[1], half[1], y0, y1)];
}

// labelCentre with the centres whose signs are drawn, `signs` (px), each reaching `reach`
// (half-sizes, px) from its centre: the label box hides as few of them as it can, of the
// boxes `boxes` ([x0, y0, x1, y1], px: the vertices' names) and of the drawn edges
// `segments` ([[x, y], [x, y]], px: a label across a line, review r343 02-FIG1)
export function placeLabel(a, b, centroid, half, cell, bounds, signs, reach, boxes = [],
  segments = []) {
  const covers = (p) => {
    const box = [p[0] - half[0], p[1] - half[1], p[0] + half[0], p[1] + half[1]];
    return signs.filter((q) => Math.abs(p[0] - q[0]) < half[0] + reach[0] &&
      Math.abs(p[1] - q[1]) < half[1] + reach[1]).length +
      boxes.filter((o) => overlaps(box, o)).length +
      segments.filter(([s, e]) => segmentCrossesBox(s, e, box)).length;
  };
  const any = signs.length || boxes.length || segments.length;
  return labelCentre(a, b, centroid, half, cell, bounds, any ? covers : null);
}

// the drawn edges of both triangles (A = v1 v2 v3, B = v3 v2 v4; v2-v3 once), from the
// vertices `v` (px)
export function edgeSegments(v) {
  return [[0, 1], [1, 2], [2, 0], [2, 3], [3, 1]].map(([i, j]) => [v[i], v[j]]);
}

// Does the segment s -> e (px) pass through the box [x0, y0, x1, y1]? (Liang-Barsky)
export function segmentCrossesBox(s, e, box) {
  const d = [e[0] - s[0], e[1] - s[1]];
  let [t0, t1] = [0, 1];
  const sides = [[-d[0], s[0] - box[0]], [d[0], box[2] - s[0]], [-d[1], s[1] - box[1]],
    [d[1], box[3] - s[1]]];
  for (const [p, q] of sides) {
    if (p === 0) {
      if (q < 0) return false; // parallel to this side, outside it
      continue;
    }
    const r = q / p;
    if (p < 0) t0 = Math.max(t0, r);
    else t1 = Math.min(t1, r);
    if (t0 > t1) return false;
  }
  return true;
}

// The name of the edge a triangle is tested on: a counter-clockwise triangle is walked
// backwards (its E then positive inside), and the kind and bias are that walk's edge's,
// "E32 (v3→v2)" tested as "E23 (v2→v3)" (review r192 02-7).
export function walkedName(label) {
  if (!label.flipped) return label.name;
  return label.name.replace(/E(\d)(\d)/, "E$2$1").replace(/v(\d)→v(\d)/, "v$2→v$1");
}

// the edges of both triangles: kind and bias of each
export function edgeTable(scene) {
  const rows = [["A", scene.A, ["E12 (v1→v2)", "E23 (v2→v3)", "E31 (v3→v1)"]],
    ["B", scene.B, ["E32 (v3→v2)", "E24 (v2→v4)", "E43 (v4→v3)"]]].map(([name, s, names]) => {
    if (s.area2 === 0) return `<tr><td><b>${name}</b></td><td colspan=3>zero area: covers nothing</td></tr>`;
    // the name and the kind each on one line: "right, bias / −1" wrapped (review r231 02-7)
    const cells = edgeLabels(s, names).map((e, k) =>
      `<td style="text-align:left;color:${name === "A" ? EDGE_HUES[k] : "#333"}">` +
      `<b style="white-space:nowrap">${walkedName(e)}</b> <span style="white-space:nowrap">` +
      `${e.kind}, bias ${e.bias < 0 ? "−1" : "0"}</span></td>`).join("");
    // the winding on a line of its own in a column of fixed width: the counter-clockwise
    // sentence wrapped the row and shifted its columns (review r291 02-2)
    const wind = s.originalArea2 > 0 ? "clockwise on screen"
      : "counter-clockwise on screen: tested backwards";
    return `<tr><td style="text-align:left"><b>${name}</b><br><small>${wind}</small></td>${cells}</tr>`;
  });
  const cols = `<colgroup><col style="width:31%"><col span="3" style="width:23%"></colgroup>`;
  return `<table>${cols}${rows.join("")}</table>`;
}

// An edge's value as the readouts give it: under its name as given, and for a triangle walked
// backwards (counter-clockwise on screen) also under the name the labels and the table give it,
// "E32 = −E23": one edge, its two names linked on the screen (review r231 02-13)
export function valueNames(setup, chosen) {
  const names = EDGE_NAMES[chosen];
  if (setup.area2 === 0) return names;
  return edgeLabels(setup, names).map((e) => (e.flipped ? `${e.name} = −${walkedName(e)}` : e.name));
}

// what the pointer is over: the centre's three edge values and who covers it
export function describe(scene, at, chosen, W, H) {
  if (!at) return "Point at a pixel centre for its edge values (px²).";
  const col = Math.floor(at[0]);
  const row = Math.floor(at[1]);
  if (col < 0 || row < 0 || col >= W || row >= H) return "";
  const setup = chosen === "A" ? scene.A : scene.B;
  const names = valueNames(setup, chosen);
  const px2 = setup.unit * setup.unit;
  const e = givenValues(setup, row, col).map((v) => v / px2);
  const i = row * W + col;
  const who = scene.covA[i] && scene.covB[i] ? "both A and B (they overlap)"
    : scene.covA[i] ? "A" : scene.covB[i] ? "B" : "neither";
  const vals = e.map((v, k) => `<b>${names[k]}</b> = ${v > 0 ? "+" : ""}${fmtMinus(v, 6)}`).join(", ");
  const onShared = scene.shared.find((s) => s.row === row && s.col === col);
  const tie = onShared ? ` It lies exactly on the shared edge: ${onShared.owner === "none"
    ? "neither owns it" : `${onShared.owner} owns it`} (top-left rule).` : "";
  return `Centre (${col + 0.5}, ${row + 0.5}), pixel row ${row}, column ${col}, ${chosen}: ` +
    `${vals}. Covered by ${who}.${tie}`;
}

// The point the 3-D view reads E at: the pixel centre under the pointer, else the centre
// nearest the chosen triangle's centroid (inside it, where all three E are positive).
export function planePoint(setup, hover, W, H) {
  const inGrid = hover && hover[0] >= 0 && hover[0] < W && hover[1] >= 0 && hover[1] < H;
  const u = setup.unit;
  const [x, y] = inGrid ? hover
    : [0, 1].map((k) => setup.given.reduce((acc, v) => acc + v[k] / u, 0) / 3);
  return [Math.min(W - 1, Math.max(0, Math.floor(x))) + 0.5,
    Math.min(H - 1, Math.max(0, Math.floor(y))) + 0.5];
}

// E12, E23, E31 of `setup` (as given) at the point `at` (px), in px²
export function planeValues(setup, at) {
  const u = setup.unit;
  return [0, 1, 2].map((k) => edgeValue(setup.given[k].map((t) => t / u),
    setup.given[(k + 1) % 3].map((t) => t / u), at));
}

const PLANES_ELEVATION = 0.5; // the default view: from low down, planes seen from the side

// How squarely the camera sees the least visible of the planes z = zs E_k(x, y): the smallest
// |cos| between a plane's normal and the direction towards the camera (0: edge-on).
export function planesFacing(grads, zs, yaw, elevation) {
  const d = towardsCamera(yaw, elevation);
  return Math.min(...grads.map(([gx, gy]) => {
    const n = [zs * gx, zs * gy, -1];
    return Math.abs(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / Math.hypot(...n);
  }));
}

// the turn about z that shows all three planes most squarely (none edge-on), in 5° steps
export function bestYaw(grads, zs, elevation) {
  let best = [0, -1];
  for (let k = 0; k < 72; k++) {
    const yaw = (k * Math.PI) / 36;
    const f = planesFacing(grads, zs, yaw, elevation);
    if (f > best[1]) best = [yaw, f];
  }
  return best[0];
}

// The 3-D view's text: its 760-px canvas is shown about 0.77 times as wide in the column at
// 1024 px, where 13 px read 9-10 (review r9 02-5): 17 px read 13.
const PLANES_TEXT = 17;
// room above the box for the values and below it for the note's two lines, in canvas px
const planesTop = (size) => Math.round(size * 3.6);
const planesBottom = (size) => Math.round(size * 2.9);

// the three edge functions of the chosen triangle as planes z = E(x, y) over the grid,
// clipped to a box whose camera keeps it inside the canvas at every turn
function drawPlanes(ctx, cam, scene, chosen, W, H, canvas, hover) {
  const { w: cw, h: ch } = canvas.logical;
  ctx.clearRect(0, 0, cw, ch);
  const setup = chosen === "A" ? scene.A : scene.B;
  const u = setup.unit;
  const ends = [0, 1, 2].map((k) => [setup.given[k], setup.given[(k + 1) % 3]]
    .map((v) => v.map((t) => t / u)));
  const fns = ends.map(([a, b]) => (x, y) => edgeValue(a, b, [x, y]));
  const corners = [[0, 0], [W, 0], [W, H], [0, H]];
  let top = 1;
  for (const f of fns) for (const [x, y] of corners) top = Math.max(top, Math.abs(f(x, y)));
  const h = 0.3 * Math.max(W, H); // the box's half height, in grid units
  const zs = (1.6 * h) / top; // steep enough to see; the steepest plane leaves the box
  const size = textPx(ctx, PLANES_TEXT);
  const [above, below] = [planesTop(size), planesBottom(size)];
  // fitted at the view's tilt, for every yaw: turning keeps the size, tilting rescales it so
  // that the box fills the room at each tilt (review r99: fitted for the steepest tilt, a
  // low view left a band empty); 64 px at the sides for the E ticks ("-100"), 28 above and
  // below
  cam.scale = fitBox(W, H, h, cw, ch - above - below, 64, cam.elevation, 28);
  // E_k = gx x + gy y + c: its gradient, from the plane's values at three corners
  const grads = fns.map((f) => [f(1, 0) - f(0, 0), f(0, 1) - f(0, 0)]);
  if (!cam.turned) cam.yaw = bestYaw(grads, zs, cam.elevation); // until the reader turns it
  cam.at = [cw / 2, above + (ch - above - below) / 2];
  const polys = surfacePieces(corners, () => 0, 8, { fill: "#ddd", alpha: 0.55, stroke: "#bbb" });
  fns.forEach((f, k) => {
    for (const piece of surfacePieces(corners, (x, y) => f(x, y) * zs, 8,
      { fill: EDGE_HUES[k], alpha: 0.45 })) {
      const pts = clipToSlab(piece.pts, h);
      if (pts.length > 2) polys.push({ ...piece, pts });
    }
  });
  drawPolygons(ctx, cam, polys);
  // the box's vertical edges, thin: where the planes are cut
  for (const [x, y] of corners) line3d(ctx, cam, [x, y, -h], [x, y, h], "#999", 1, [3, 3]);
  // and its top and bottom: a box, not a few dashed verticals once turned (review r169 02-7)
  for (const z of [-h, h]) {
    corners.forEach(([x, y], k) => {
      const [x1, y1] = corners[(k + 1) % 4];
      line3d(ctx, cam, [x, y, z], [x1, y1, z], "#999", 1, [3, 3]);
    });
  }
  drawEAxis(ctx, cam, corners, h, zs);
  // each plane cuts z = 0 along its edge's line: drawn on top
  ends.forEach(([a, b], k) => line3d(ctx, cam, [a[0], a[1], 0], [b[0], b[1], 0], EDGE_HUES[k], 4));
  // the point the values are read at: a cross on the screen, a dot on each plane over it
  const at = planePoint(setup, hover, W, H);
  const vals = planeValues(setup, at);
  vals.forEach((e, k) => {
    const z = e * zs;
    if (Math.abs(z) > h) return; // outside the box: the value says it
    line3d(ctx, cam, [at[0], at[1], 0], [at[0], at[1], z], "#111", 1, [2, 2]);
    const q = cam.project([at[0], at[1], z]);
    ctx.fillStyle = EDGE_HUES[k];
    ctx.beginPath();
    ctx.arc(q[0], q[1], 4.5, 0, 2 * Math.PI);
    ctx.fill();
  });
  const c = cam.project([at[0], at[1], 0]);
  strokeLine(ctx, [c[0] - 6, c[1] - 6], [c[0] + 6, c[1] + 6], "#111", 2.5);
  strokeLine(ctx, [c[0] - 6, c[1] + 6], [c[0] + 6, c[1] - 6], "#111", 2.5);
  // the values, in 2-D above the box: always inside the canvas (the names as the readout
  // under the picture gives them)
  const names = valueNames(setup, chosen);
  ctx.fillStyle = "#111";
  ctx.font = `${size}px sans-serif`;
  ctx.fillText(`E (px²) at the centre (${at[0]}, ${at[1]}), the black ✕ (point at a pixel to ` +
    "move it):", 8, Math.round(size * 1.35));
  ctx.font = `bold ${size}px sans-serif`;
  let x = 8;
  vals.forEach((e, k) => {
    const text = `${names[k]} = ${fmtMinus(e, 4)}`;
    ctx.fillStyle = EDGE_HUES[k];
    ctx.fillText(text, x, Math.round(size * 2.9));
    x += ctx.measureText(text).width + 18;
  });
  ctx.fillStyle = "#333";
  ctx.font = `${size}px sans-serif`;
  // two lines: one ran past a 760-px canvas at this size
  ctx.fillText("grey: E = 0 (the screen); the planes are cut at the dashed box.", 8,
    ch - 8 - Math.round(size * 1.3));
  ctx.fillText("Drag to turn; arrow keys too.", 8, ch - 8);
}

// The E axis's tick step in px²: about three ticks over the box's half height `span`, but
// never closer on the screen than two lines of text (`pxPer`: screen px per px² of E, which
// shrinks as the view turns towards the top; review r93 02-8: -50, 0, 50 ran together).
// A step beyond `span` leaves the 0 tick alone.
// Turned, the view could round a step just above two text heights up past `span`, leaving
// the 0 tick alone (review r169 02-7): a step within the box at 1.25 text heights apart
// (labels one line high, still clear of each other) is taken before giving up.
export function eTickStep(span, pxPer, size) {
  const nice = (lines) => {
    const raw = Math.max(span / 3, (lines * size) / Math.max(pxPer, 1e-9));
    const mag = 10 ** Math.floor(Math.log10(raw));
    return [1, 2, 2.5, 5, 10].map((k) => k * mag).find((v) => v >= raw);
  };
  const apart = nice(2);
  if (apart <= span) return apart;
  const close = nice(1.25);
  return close <= span ? close : apart;
}

// the vertical E axis with ticks in px², at the box corner drawn leftmost on the screen
function drawEAxis(ctx, cam, corners, h, zs) {
  const [x, y] = corners.reduce((a, b) => (cam.project([...b, 0])[0] < cam.project([...a, 0])[0]
    ? b : a));
  line3d(ctx, cam, [x, y, -h], [x, y, h], "#111", 1.5);
  const span = h / zs; // the box's half height in px²
  const size = textPx(ctx, PLANES_TEXT);
  const step = eTickStep(span, cam.scale * zs * Math.cos(cam.elevation), size);
  ctx.font = `${size}px sans-serif`;
  ctx.textAlign = "right";
  for (let e = -Math.floor(span / step) * step; e <= span + 1e-9; e += step) {
    const q = cam.project([x, y, e * zs]);
    strokeLine(ctx, [q[0] - 5, q[1]], [q[0], q[1]], "#111", 1.5);
    ctx.fillStyle = "#111";
    ctx.fillText(fmtMinus(e, 4), q[0] - 7, q[1] + Math.round(size * 0.35));
  }
  const t = cam.project([x, y, h]);
  ctx.font = `bold ${textPx(ctx, PLANES_TEXT)}px sans-serif`;
  ctx.fillText("E (px²)", t[0] + 20, t[1] - 8);
  ctx.textAlign = "left";
}
