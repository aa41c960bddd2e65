// Lesson 01's cracks and double draws: two triangles sharing an edge, filled three ways.
//
// A pair of random triangles with their vertices on pixel centres share the edge p-q:
// A = (p, q, r) and B = (q, p, s), r and s on either side. Each is filled by the float span
// fill with crossings computed as Ek writes them, divide first, + ceil (multiplied first they
// would be exact: lesson 01, 4b), by the float DDA (x += du/dv per raster line) and by
// the integer edge functions of the engine. A pixel both fill is drawn twice; a centre on the
// shared edge that the integer fill gives to one of them and that neither fills is a crack.
// Reroll draws a new pair; the tally counts over every pair drawn.

export const METHODS = [
  ["crossing", "float crossing, divide first"],
  ["dda", "float DDA: x += Δu/Δv"],
  ["integer", "integer edge functions"],
];

// A random pair: four distinct pixel centres, r and s strictly on either side of p-q.
export function randomPair(rand, W, H) {
  const pick = () => [Math.floor(rand() * W) + 0.5, Math.floor(rand() * H) + 0.5];
  for (;;) {
    const [p, q, r, s] = [pick(), pick(), pick(), pick()];
    if (p[0] === q[0] && p[1] === q[1]) continue;
    const er = edgeValue(p, q, r);
    const es = edgeValue(p, q, s);
    if (er > 0 && es < 0) return [[p, q, r], [q, p, s]];
    if (er < 0 && es > 0) return [[p, q, s], [q, p, r]];
  }
}

// A stored pair that cracks when each edge is evaluated from the end its triangle lists first
// (the float DDA leaves the centre of pixel row 4, column 0 to neither). Random pairs do so
// rarely (the test counts how rarely), so the page can load this one: it needs a 16 x 16 grid.
export const CRACKING_PAIR = [[[0.5, 4.5], [15.5, 15.5], [1.5, 11.5]],
  [[15.5, 15.5], [0.5, 4.5], [12.5, 2.5]]];
export const crackingPair = () => CRACKING_PAIR.map((t) => t.map((v) => [...v]));
export const fitsCrackingPair = (W, H) => CRACKING_PAIR.flat().every(([x, y]) => x < W && y < H);
// the grid the stored pair needs, [W, H]: the smallest from (0, 0) that holds its vertices
export const crackingBox = () => [0, 1].map((k) =>
  Math.ceil(Math.max(...CRACKING_PAIR.flat().map((v) => v[k]))));

// The grid the panels draw, [W, H]: the grid on show, or, with the stored pair on show, the
// box that holds it. On the larger grid the stored pair filled a quarter of each panel, its
// crack on the panel's border (review r239 01-FIG2): zoomed to its box, it fills the panel.
// Its fills do not change: the pair covers no pixel outside its box.
export function shownGrid(W, H, stored) {
  return stored && fitsCrackingPair(W, H) ? crackingBox() : [W, H];
}

// the line under the picture when the stored pair is drawn zoomed (none on its own grid)
export function storedNote(W, H, stored) {
  const [w, h] = shownGrid(W, H, stored);
  if (w === W && h === H) return "";
  return `<b>Show a pair that cracks:</b> the stored pair, drawn on the ${w} × ${h} corner ` +
    `of the ${W} × ${H} grid that holds it (zoomed in); a roll goes back to the whole grid.`;
}

// the pairs rolled from `seed`, `n` of them (the page's rolls, for the tests)
export function rolls(seed, n, W, H) {
  const rand = randomStream(seed);
  return Array.from({ length: n }, () => randomPair(rand, W, H));
}

// Cracks, double draws and pixels differing from the integer fill, for one method: as
// teachraster.study.naive_spans.shared_edge_faults.
export function faults(first, second, W, H, method, asListed = false) {
  const a = FILLS[method](first, W, H, asListed);
  const b = FILLS[method](second, W, H, asListed);
  const ea = edgeFunctionFill(first, W, H);
  const eb = edgeFunctionFill(second, W, H);
  const setup = setupTriangle(first);
  const [p, q] = [setup.given[0], setup.given[1]];
  const cracks = [];
  const doubles = [];
  const swapped = [];
  const wrong = [0, 0];
  for (let r = 0; r < H; r++) {
    for (let c = 0; c < W; c++) {
      const i = r * W + c;
      if (a[i] && b[i]) doubles.push([r, c]);
      const onEdge = edgeValue(p, q, centreUnits(setup, r, c)) === 0;
      if (onEdge && (ea[i] || eb[i]) && !a[i] && !b[i]) cracks.push([r, c]);
      if (onEdge && a[i] !== b[i] && a[i] !== ea[i]) swapped.push([r, c]);
      wrong[0] += a[i] !== ea[i] ? 1 : 0;
      wrong[1] += b[i] !== eb[i] ? 1 : 0;
    }
  }
  return { cracks, doubles, swapped, wrong, a: Array.from(a), b: Array.from(b) };
}

// Is the point `c` exactly on the segment p-q (all in grid units)? On its line and between
// its ends: the centres beyond the ends lie on the line but belong to neither triangle's edge.
export function onSegment(p, q, c) {
  if (edgeValue(p, q, c) !== 0) return false;
  return [0, 1].every((k) => Math.min(p[k], q[k]) <= c[k] && c[k] <= Math.max(p[k], q[k]));
}

// the centres exactly on the shared edge of `pair` (its first triangle's first edge), as
// [row, col]: the black squares of the page
export function tieCentres(pair, W, H) {
  const setup = setupTriangle(pair[0]);
  const out = [];
  for (let r = 0; r < H; r++) {
    for (let c = 0; c < W; c++) {
      if (onSegment(setup.given[0], setup.given[1], centreUnits(setup, r, c))) out.push([r, c]);
    }
  }
  return out;
}

export function emptyTally() {
  const per = () => ({ pairs: 0, faulty: 0, triangles: 0, wrongTriangles: 0, cracks: 0,
    doubles: 0, swapped: 0, swappedPairs: 0 });
  return { crossing: per(), dda: per(), integer: per() };
}

// add one pair's faults to the running tally (pure: returns a new tally)
export function tallied(tally, pair, W, H, asListed = false) {
  const out = JSON.parse(JSON.stringify(tally));
  for (const [m] of METHODS) {
    const f = faults(pair[0], pair[1], W, H, m, asListed);
    const t = out[m];
    t.pairs += 1;
    t.triangles += 2;
    t.faulty += f.cracks.length || f.doubles.length ? 1 : 0;
    t.wrongTriangles += (f.wrong[0] ? 1 : 0) + (f.wrong[1] ? 1 : 0);
    t.cracks += f.cracks.length;
    t.doubles += f.doubles.length;
    t.swapped += f.swapped.length;
    t.swappedPairs += f.swapped.length ? 1 : 0;
  }
  return out;
}

// the tally over a list of pairs, from nothing
export function tallyOver(pairs, W, H, asListed = false) {
  return pairs.reduce((t, pair) => tallied(t, pair, W, H, asListed), emptyTally());
}

// The grid on show: the explorer's own, or its large one (`data.large`, [W, H]) when `large`.
// Random pairs on the small grid hardly ever crack, evaluated as listed (none in 3000 on
// 16 x 16: lesson 01 counts it); on 32 x 32 about two in a thousand do (review r229 01-W2).
export function gridOf(data, large) {
  return large && data.large ? [...data.large] : [data.width, data.height];
}

// "Roll until one cracks" stops after this many pairs: evaluated alike no edge ever cracks,
// and on the small grid random pairs almost never do
export const MOST_ROLLS = 3000;

// Roll pairs from `rand` until a float fill cracks the shared edge or draws a pixel twice,
// at most `most`; every pair rolled goes into the tally. Returns the last pair, the tally,
// how many pairs were rolled and whether the last one is such a pair.
export function rollUntilFault(rand, tally, W, H, asListed, most = MOST_ROLLS) {
  const bad = (t) => t.crossing.faulty + t.dda.faulty;
  let pair = null;
  for (let n = 1; n <= most; n++) {
    pair = randomPair(rand, W, H);
    const next = tallied(tally, pair, W, H, asListed);
    const found = bad(next) > bad(tally);
    tally = next;
    if (found) return { pair, tally, n, found };
  }
  return { pair, tally, n: most, found: false };
}

// the same from a seed, after the pair the page shows first (for the tests)
export function untilFault(seed, W, H, asListed, most = MOST_ROLLS) {
  const rand = randomStream(seed);
  const first = randomPair(rand, W, H);
  return rollUntilFault(rand, tallyOver([first], W, H, asListed), W, H, asListed, most);
}

// What the last "Roll until one cracks" found, for the line above the tally (`large`: on the
// larger grid, where a miss is bad luck)
export function huntNote(hunt, asListed, large = false) {
  if (!hunt) return "";
  if (hunt.found) {
    return `<b>Roll until one cracks:</b> found after ${hunt.n} pair${hunt.n === 1 ? "" : "s"} ` +
      "(each one counted in the tally); the pair on show cracks or draws a pixel twice.";
  }
  return `<b>Roll until one cracks:</b> none in ${hunt.n} pairs (all counted in the tally). ` +
    (!asListed ? "Evaluated alike, the shared edge never cracks: turn on <b>evaluate each " +
        "edge from the end its triangle lists first</b>."
      : large ? "Rare on this grid too: roll again."
        : "On this grid random pairs almost never crack: try the larger grid.");
}

const pct = (k, n) => (n ? `${((100 * k) / n).toFixed(1)} %` : "–");

export function tallyTable(tally) {
  const rows = METHODS.map(([m, name]) => {
    const t = tally[m];
    return `<tr><td>${name}</td><td>${t.faulty} of ${t.pairs} (${pct(t.faulty, t.pairs)})</td>` +
      `<td>${t.cracks} / ${t.doubles}</td>` +
      `<td>${t.swappedPairs} (${pct(t.swappedPairs, t.pairs)}), ${t.swapped} px</td>` +
      `<td>${t.wrongTriangles} of ${t.triangles} (${pct(t.wrongTriangles, t.triangles)})</td></tr>`;
  });
  return "<table><tr><th>fill</th><th>pairs cracked or drawn twice</th><th>cracked / double px</th>" +
    "<th>pairs with a tie given to the wrong triangle</th><th>triangles unlike the integer fill</th>" +
    `</tr>${rows.join("")}</table>`;
}

function mount(el, data, host) {
  const state = { seed: data.seed, roll: 0, tally: emptyTally(), asListed: false, stored: false,
    large: false, ...host.state() };
  let [W, H] = gridOf(data, state.large);
  const root = frame(el, data.title,
    "Two triangles with their vertices on pixel centres share the edge p–q (thick). Each " +
    "panel fills both, A in blue and B in orange. <b>■</b>: a pixel centre exactly on the " +
    "shared edge, a tie the top-left rule gives to one of the two; <b>⇄</b>: a tie drawn " +
    "by the wrong one; <b style='color:#D55E00'>2</b>: drawn twice; " +
    "<b style='color:#D55E00'>✕</b> in a red ring: drawn by neither (a crack); dashed box: " +
    "unlike the integer fill. Reroll for a new pair; the tally counts every random pair drawn " +
    "(not the stored pair that cracks) and starts again when the way the edges are " +
    "evaluated, or the grid, changes.");
  // the key at the panels' text size, not the grey subtitle's 14 px (review r344 01-FIG1)
  Object.assign(root.querySelector(".tr-x-sub").style, { fontSize: `${TEXT_PX}px`, color: "#111" });
  // the grid the panels draw: W x H, or the stored pair's box (shownGrid)
  const shown = () => shownGrid(W, H, state.stored);
  let g = panelLayout(...shown());
  const [canvas, ctx] = makeCanvas(g.width, g.height,
    "the same pair of triangles filled three ways, cracks and double draws marked");
  const readout = element("div", { class: "tr-x-readout", "aria-live": "polite" });
  const table = element("div");
  const showStored = (e) => {
    state.stored = true;
    lastHunt = null;
    listedBy(state, true);
    pair = CRACKING_PAIR;
    controls.sync();
    relayout(false);
    paint.request(e);
    host.setState({ stored: true, asListed: true, tally: state.tally });
  };
  const controls = crackControls(state, host, (n, e) => roll(n, e), (e) => paint.request(e),
    fitsCrackingPair(W, H) ? showStored : null,
    { hunt: (e) => hunt(e), grid: data.large ? [data.large, (e) => setGrid(!state.large, e)] : null });
  const hunted = element("div", { class: "tr-x-sub", "aria-live": "polite" });
  const note = element("div", { class: "tr-x-sub" });
  root.append(...controls.rows, canvas, readout, hunted, table, note);
  let lastHunt = null; // what "Roll until one cracks" found last (the page's alone)
  let rand = randomStream(state.seed);
  let pair = null;
  for (let k = 0; k <= state.roll; k++) pair = randomPair(rand, W, H); // the pair on show
  if (state.stored && fitsCrackingPair(W, H)) pair = CRACKING_PAIR;
  if (!state.roll && !state.tally.integer.pairs) {
    state.tally = tallied(state.tally, pair, W, H, state.asListed);
  }
  const ui = { hover: null };

  function roll(n, e) {
    state.stored = false;
    lastHunt = null;
    for (let k = 0; k < n; k++) {
      pair = randomPair(rand, W, H);
      state.tally = tallied(state.tally, pair, W, H, state.asListed);
    }
    state.roll += n;
    relayout(false);
    paint.request(e);
    host.setState({ roll: state.roll, stored: false, tally: state.tally });
  }

  // roll until a float fill cracks or draws twice (review r229 01-W2: the toggle's cracks were
  // seen only in the stored pair); every pair rolled is counted
  function hunt(e) {
    state.stored = false;
    const found = rollUntilFault(rand, state.tally, W, H, state.asListed);
    pair = found.pair;
    state.tally = found.tally;
    state.roll += found.n;
    lastHunt = { n: found.n, found: found.found };
    relayout(false);
    paint.request(e);
    host.setState({ roll: state.roll, stored: false, tally: state.tally });
  }

  // the small grid or the large one: the first pair of the seed on it, the tally from nothing
  function setGrid(large, e) {
    state.large = Boolean(large);
    [W, H] = gridOf(data, state.large);
    Object.assign(state, { roll: 0, stored: false, tally: emptyTally() });
    rand = randomStream(state.seed);
    pair = randomPair(rand, W, H);
    state.tally = tallied(state.tally, pair, W, H, state.asListed);
    lastHunt = null;
    relayout();
    controls.sync();
    paint.request(e);
    host.setState({ large: state.large, roll: 0, stored: false, tally: state.tally });
  }

  function draw() {
    ctx.clearRect(0, 0, canvas.logical.w, canvas.logical.h);
    const [w, h] = shown(); // the panels' grid (the stored pair's box, zoomed)
    const found = METHODS.map(([meth]) => faults(pair[0], pair[1], w, h, meth, state.asListed));
    const exact = found[2];
    const { cell } = g;
    METHODS.forEach(([, name], k) => {
      const [x0, y0] = g.origins[k];
      drawPanel(ctx, found[k], exact, pair, { x0, y0, cell, W: w, H: h });
      ctx.fillStyle = "#111";
      ctx.font = `bold ${textPx(ctx, TITLE_PX)}px sans-serif`;
      ctx.fillText(name, x0, y0 - ringReach(cell) - g.ticks - 6);
      drawNumbers(ctx, x0, y0, w, h, cell, k % 2 === 0);
    });
    drawKey(ctx, g.key, cell, g.panelW + ringReach(cell));
    table.innerHTML = tallyTable(state.tally);
    readout.innerHTML = explainPixel(pair, ui.hover, w, h, found, state.asListed);
    hunted.innerHTML = huntNote(lastHunt, state.asListed, state.large) ||
      storedNote(W, H, state.stored);
    note.innerHTML = crackNote(state.asListed);
    host.picture(canvas);
  }
  const paint = painter(canvas, draw);
  // the cells as large as the column allows, again whenever its width changes
  const fit = () => relayout(false);
  // the panels for the column and the grid on show (`always`: the grid changed)
  function relayout(always = true) {
    const avail = root.clientWidth || NARROW_COLUMN_PX;
    const next = panelLayout(...shown(), avail);
    if (!always && next.cell === g.cell && next.width === g.width && next.height === g.height) {
      return;
    }
    g = next;
    resizeCanvas(canvas, ctx, g.width, g.height);
    paint.request();
  }
  if (globalThis.ResizeObserver) new ResizeObserver(fit).observe(root);
  fit();
  const point = (p, e) => {
    ui.hover = p ? pixelUnder(p, g, ...shown()) : null;
    paint.request(e);
  };
  pointerInput(canvas, { onHover: point, onClick: point });
  onKeys(canvas, (e) => {
    if (e.key === "r" || e.key === "Enter" || e.key === " ") {
      e.preventDefault();
      roll(1, e);
    }
  });
  paint.now();
  return {
    setState(s) {
      // the pair on show again only when the kernel moved it (not at the echo of our roll)
      const moved = (s.seed !== undefined && s.seed !== state.seed)
        || (s.roll !== undefined && s.roll !== state.roll)
        || (s.stored !== undefined && s.stored !== state.stored)
        || (s.large !== undefined && Boolean(s.large) !== Boolean(state.large));
      const { asListed, ...rest } = s;
      // a tally of its own with the change (a state restored) stays; ours echoed back does not
      const theirs = s.tally !== undefined && JSON.stringify(s.tally) !== JSON.stringify(state.tally);
      if (asListed !== undefined) listedBy(state, asListed, theirs);
      Object.assign(state, rest);
      if (moved) {
        const [w, h] = gridOf(data, state.large);
        [W, H] = [w, h];
        rand = randomStream(state.seed);
        for (let k = 0; k <= state.roll; k++) pair = randomPair(rand, W, H);
        if (state.stored && fitsCrackingPair(W, H)) pair = CRACKING_PAIR;
        lastHunt = null;
        relayout(false); // a new grid, or the stored pair's box

      }
      controls.sync();
      paint.request();
    },
  };
}

// A canvas of makeCanvas set to `w` x `h` CSS pixels (its drawing cleared)
function resizeCanvas(canvas, ctx, w, h) {
  const { dpr } = canvas.logical;
  canvas.width = Math.round(w * dpr);
  canvas.height = Math.round(h * dpr);
  canvas.style.width = `${w}px`;
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  canvas.logical = { w, h, dpr };
}

// The note under the tally, for the way the edges are evaluated now (review r65 01-4: it
// described the upper-end walk while the toggle showed the other way)
export function crackNote(asListed) {
  return asListed
    ? "Now each triangle evaluates the shared edge from the end it lists first. When the two " +
      "list it in opposite orders they round differently, and then, rarely, the edge cracks " +
      "or a pixel is drawn twice: <b>Roll until one cracks</b> finds one (on the larger grid; " +
      "on the small one hardly ever), <b>Show a pair that cracks</b> loads a stored one. " +
      "Turned off, both walk it from its upper end, as the span loops above do, and it never " +
      "cracks."
    : "Both triangles walk the shared edge from its upper end, as the span loops above do: " +
      "they round alike, so a tie goes to one of them, sometimes the wrong one, and the edge " +
      "never cracks. Turn on <b>evaluate each edge from the end its triangle lists first</b> " +
      "to see when it can.";
}

// Set how the edges are evaluated. Whatever changes it (the toggle, "Show a pair that cracks",
// the kernel), a change starts the tally again, as the caption says: its counts are of one way
// (review r7: after "Show a pair that cracks" it went on counting the other way's pairs).
// `keepTally`: a tally arrives with the change (the kernel restoring a state), keep that one.
export function listedBy(state, asListed, keepTally = false) {
  const value = Boolean(asListed);
  if (value !== Boolean(state.asListed) && !keepTally) state.tally = emptyTally();
  state.asListed = value;
  return state;
}

// Reroll, a thousand more, until one cracks, the tally reset, the edges evaluated as listed,
// the large grid, the stored pair
function crackControls(state, host, roll, repaint, showStored, more) {
  const listed = button("evaluate each edge from the end its triangle lists first", (e) => {
    listedBy(state, !state.asListed);
    sync();
    repaint(e);
    host.setState({ asListed: state.asListed, tally: state.tally });
  }, Boolean(state.asListed));
  const reset = button("Reset the tally", (e) => {
    state.tally = emptyTally();
    repaint(e);
    host.setState({ tally: state.tally });
  });
  const stored = showStored ? [button("Show a pair that cracks", showStored)] : [];
  const grid = more.grid
    ? button(`${more.grid[0][0]} × ${more.grid[0][1]} grid`, more.grid[1], Boolean(state.large))
    : null;
  function sync() {
    listed.setAttribute("aria-pressed", String(Boolean(state.asListed)));
    if (grid) grid.setAttribute("aria-pressed", String(Boolean(state.large)));
  }
  // two rows, each at most three lines in a 315-px column (tests/test_browser_layout.py):
  // the pairs rolled, then how they are drawn and filled
  const rolls = element("div", { class: "tr-x-row" }, [button("Reroll", (e) => roll(1, e)),
    button("Roll 1000 more", (e) => roll(1000, e)), button("Roll until one cracks", more.hunt),
    reset]);
  const ways = element("div", { class: "tr-x-row" }, [listed, ...(grid ? [grid] : []),
    ...stored]);
  return { rows: [rolls, ways], sync };
}

// The ring around a crack, as a multiple of the cell: it circles the pixel square (> 0.71).
export const RING = 0.85;

// Where the three panels go: two side by side and the third below the first, the key beside
// it. Three across, a 16 x 16 pair was 936 px wide and shrank to 585 in JupyterLab's column at
// 1024 px with the file browser open (review r7: 7-8 px type); two across it is 558 px wide and
// drawn 1:1 there. The margins and the gaps leave room for the ring around a crack in a border
// pixel, so that it is never cut off by the canvas or hidden by the next panel.
// The cells are as large as `avail` px of column allow (review r65 01-4: 16-px cells, 256-px
// panels, were small on a projector): 16 px in the narrow column, 27 in a 940-px one, at most
// MAX_CELL; the canvas is drawn 1:1 in any column at least MIN_CELL cells wide.
export function panelLayout(W, H, avail = NARROW_COLUMN_PX) {
  let cell = MIN_CELL;
  while (cell < MAX_CELL && layoutWidth(W, cell + 1) <= avail) cell += 1;
  const ring = ringReach(cell);
  const gap = Math.max(26, 2 * ring + 2);
  // the column numbers' row, at their size on this canvas (as the row numbers' margin)
  const ticks = Math.ceil(1.1 * readablePx(14, layoutWidth(W, cell))) + 4;
  const m = { left: numbersWidth(W, cell) + ring, top: TITLE + ticks + ring };
  const panelW = W * cell;
  const panelH = H * cell;
  // under a panel: its ring, its count, the next title and column numbers, their ring
  const below = ring + COUNT + TITLE + ticks + ring;
  const origins = [0, 1, 2, 3].map((k) => [m.left + (k % 2) * (panelW + gap),
    m.top + Math.floor(k / 2) * (panelH + below)]);
  return { cell, gap, m, ticks, panelW, panelH, origins: origins.slice(0, 3), key: origins[3],
    radius: RING * cell, width: m.left + 2 * panelW + gap + ring,
    height: m.top + 2 * panelH + below + ring + COUNT };
}

const [MIN_CELL, MAX_CELL] = [16, 30];

// the canvas' width for two panels of W cells of `cell` px (panelLayout's sum)
function layoutWidth(W, cell) {
  return numbersWidth(W, cell) + bareWidth(W, cell);
}

// the same without the row numbers' margin
function bareWidth(W, cell) {
  const ring = ringReach(cell);
  return ring + 2 * W * cell + Math.max(26, 2 * ring + 2) + ring;
}

// The margin of the row numbers: two digits at the size drawNumbers gives them on a canvas
// that wide (textPx: larger on a canvas a narrow column shrinks, as a 32 x 32 grid's is).
function numbersWidth(W, cell) {
  return Math.ceil(1.3 * readablePx(14, bareWidth(W, cell) + 22)) + 4;
}

// the height of a panel's title above it and of its count line below it (px)
const TITLE = 30;
const COUNT = 22;
// the type of the titles, the counts and the key, for a projector (review r251 01-FIG1: 13-
// and 14-px type)
const TITLE_PX = 18;
const TEXT_PX = 16;

// Every fourth row and column numbered, as the lesson names pixels by them (review r251
// 01-FIG1: "pixel (row 4, column 0)" could only be found by counting): the columns above
// each panel, the rows left of the left-hand panels (the right-hand one shares their rows;
// the gap between them is the rings' room). Outside the rings' reach.
function drawNumbers(ctx, x0, y0, W, H, cell, rows) {
  const ring = ringReach(cell);
  ctx.fillStyle = "#333";
  ctx.font = `${textPx(ctx, 14)}px sans-serif`;
  ctx.textAlign = "center";
  for (let c = 0; c < W; c += 4) ctx.fillText(String(c), x0 + (c + 0.5) * cell, y0 - ring - 4);
  ctx.textAlign = "right";
  for (let r = 0; rows && r < H; r += 4) {
    ctx.fillText(String(r), x0 - ring - 3, y0 + (r + 0.5) * cell + 5);
  }
  ctx.textAlign = "left";
}

// The marks in a pixel, for a projector (review r57, 01-1: at 16-px cells the "2" and "✕" were
// 11 px and the tie squares 6): every glyph at least 14 px, "⇄" at least 16, as large as the
// pixel allows, and the tie squares half a pixel wide. Two panels across still fit 585 px.
// `k` (markScale) grows the least sizes on a canvas wider than the narrow column, which the
// column shrinks: the 32 x 32 grid's (review r265 01-FIG2: its marks and key drawn at about
// 6 px on screen), as textPx grows the type.
export const markPx = (cell, mark, k = 1) =>
  mark === "⇄" ? Math.max(Math.round(16 * k), Math.round(cell * 1.0))
    : Math.max(Math.round(14 * k), Math.round(cell * 0.85));
export const tieSize = (cell, k = 1) =>
  Math.min(Math.max(8, cell - 2), Math.max(Math.round(8 * k), Math.round(cell * 0.5)));
// how much a column of NARROW_COLUMN_PX shrinks this canvas at most (readablePx's factor)
export const markScale = (canvasWidth) => Math.max(1, canvasWidth / NARROW_COLUMN_PX);
const scaleOf = (ctx) => markScale(ctx.canvas.logical ? ctx.canvas.logical.w : ctx.canvas.width);

// how far the ring reaches beyond its pixel, its line width included
const ringReach = (cell) => Math.ceil((RING - 0.5) * cell) + 3;

function pixelUnder(p, g, W, H) {
  for (const [k, [x0, y0]] of g.origins.entries()) {
    const col = Math.floor((p[0] - x0) / g.cell);
    const row = Math.floor((p[1] - y0) / g.cell);
    if (col >= 0 && col < W && row >= 0 && row < H) return { panel: k, row, col };
  }
  return null;
}

function drawPanel(ctx, f, exact, pair, g) {
  const { x0, y0, cell, W, H } = g;
  const k = scaleOf(ctx);
  for (let r = 0; r < H; r++) {
    for (let c = 0; c < W; c++) {
      const i = r * W + c;
      const [a, b] = [f.a[i], f.b[i]];
      if (!a && !b) continue;
      ctx.fillStyle = a && b ? "#f0a27a" : a ? "#9fd3f3" : "#f3d79c";
      ctx.fillRect(x0 + c * cell, y0 + r * cell, cell, cell);
    }
  }
  drawGrid(ctx, x0, y0, W, H, cell, "#bbb");
  // the pixel centres, those exactly on the shared edge (the segment p-q, not its line)
  // larger: where the ties are
  const setup = setupTriangle(pair[0]);
  for (let r = 0; r < H; r++) {
    for (let c = 0; c < W; c++) {
      const on = onSegment(setup.given[0], setup.given[1], centreUnits(setup, r, c));
      ctx.fillStyle = on ? "#000" : "#999";
      const d = on ? tieSize(cell, k) : 4;
      ctx.fillRect(x0 + (c + 0.5) * cell - d / 2, y0 + (r + 0.5) * cell - d / 2, d, d);
    }
  }
  // pixels unlike the integer fill: dashed boxes
  ctx.setLineDash([3 * k, 2 * k]);
  ctx.strokeStyle = "#000";
  ctx.lineWidth = 1.5 * k;
  for (let i = 0; i < W * H; i++) {
    if (f.a[i] === exact.a[i] && f.b[i] === exact.b[i]) continue;
    const [r, c] = [Math.floor(i / W), i % W];
    ctx.strokeRect(x0 + c * cell + 2, y0 + r * cell + 2, cell - 4, cell - 4);
  }
  ctx.setLineDash([]);
  const px = ([x, y]) => [x0 + x * cell, y0 + y * cell];
  const [A, B] = pair.map((t) => t.map(px));
  for (const [t, colour] of [[A, "#0072B2"], [B, "#b86e00"]]) {
    ctx.strokeStyle = colour;
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    t.forEach((p, i) => (i ? ctx.lineTo(p[0], p[1]) : ctx.moveTo(p[0], p[1])));
    ctx.closePath();
    ctx.stroke();
  }
  ctx.strokeStyle = "#000";
  ctx.lineWidth = 3;
  ctx.beginPath();
  ctx.moveTo(A[0][0], A[0][1]);
  ctx.lineTo(A[1][0], A[1][1]);
  ctx.stroke();
  ctx.font = `bold ${markPx(cell, "2", k)}px sans-serif`;
  ctx.textAlign = "center";
  ctx.fillStyle = OKABE.vermillion;
  // on a white halo, as the "⇄" below: a crack sits on the tie square and the shared edge
  const haloed = (glyph, x, y) => {
    ctx.strokeStyle = "#fff";
    ctx.lineWidth = 3;
    ctx.lineJoin = "round";
    ctx.strokeText(glyph, x, y);
    ctx.fillText(glyph, x, y);
  };
  for (const [r, c] of f.doubles) haloed("2", x0 + (c + 0.5) * cell, y0 + (r + 0.82) * cell);
  for (const [r, c] of f.cracks) {
    haloed("✕", x0 + (c + 0.5) * cell, y0 + (r + 0.8) * cell);
    // a ring around the crack: a single pixel, often at the image's border, is easy to miss;
    // on a white halo, so that the border and the edges it crosses do not cut it
    for (const [colour, width] of [["#fff", 7], [OKABE.vermillion, 3]]) {
      ctx.strokeStyle = colour;
      ctx.lineWidth = width * k;
      ctx.beginPath();
      ctx.arc(x0 + (c + 0.5) * cell, y0 + (r + 0.5) * cell, cell * RING, 0, 2 * Math.PI);
      ctx.stroke();
    }
  }
  drawTags(ctx, pair, f, g);
  // the wrong-owner ties last, over the tie marker and the shared edge: large, black on a
  // white halo, so that the glyph survives on the thick black line
  ctx.font = `bold ${markPx(cell, "⇄", k)}px sans-serif`;
  ctx.lineJoin = "round";
  for (const [r, c] of f.swapped) {
    const [x, y] = [x0 + (c + 0.5) * cell, y0 + (r + 0.5) * cell + cell * 0.33];
    ctx.strokeStyle = "#fff";
    ctx.lineWidth = 4;
    ctx.strokeText("⇄", x, y);
    ctx.fillStyle = "#000";
    ctx.fillText("⇄", x, y);
  }
  ctx.textAlign = "left";
  ctx.fillStyle = "#111";
  ctx.font = `${textPx(ctx, TEXT_PX)}px sans-serif`;
  const said = `${f.swapped.length} stolen (⇄), ${f.cracks.length} cracked, ` +
    `${f.doubles.length} doubled`;
  ctx.fillText(said, x0, y0 + H * cell + ringReach(cell) + 16); // below a ring in the last row
}

// The tags p and q at the shared edge's ends and A and B in their triangles, as the key and
// the lesson name them (review r251 01-FIG1: they were named but not drawn), each on a white
// halo where it covers no edge and no crack's ring or double's mark (tagSpots).
function drawTags(ctx, pair, f, g) {
  const { x0, y0, cell, W, H } = g;
  const marks = [...f.cracks, ...f.doubles, ...f.swapped].map(([r, c]) => [c + 0.5, r + 0.5]);
  const spots = tagSpots(pair, marks, W, H);
  ctx.textAlign = "center";
  ctx.textBaseline = "middle";
  ctx.lineJoin = "round";
  for (const [text, [x, y], colour] of [["p", spots.p, "#111"], ["q", spots.q, "#111"],
    ["A", spots.A, "#0072B2"], ["B", spots.B, "#8a5200"]]) {
    ctx.font = `bold ${textPx(ctx, text === text.toUpperCase() ? 19 : 17)}px sans-serif`;
    ctx.strokeStyle = "#fff";
    ctx.lineWidth = 4;
    ctx.strokeText(text, x0 + x * cell, y0 + y * cell);
    ctx.fillStyle = colour;
    ctx.fillText(text, x0 + x * cell, y0 + y * cell);
  }
  ctx.textBaseline = "alphabetic";
  ctx.textAlign = "left";
}

// distance from point p to the segment a-b
function segmentDistance(p, a, b) {
  const d = [b[0] - a[0], b[1] - a[1]];
  const len2 = d[0] * d[0] + d[1] * d[1];
  const t = len2 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / len2)) : 0;
  return Math.hypot(p[0] - a[0] - t * d[0], p[1] - a[1] - t * d[1]);
}

// is p inside the triangle t (or on its edges)?
function insideTriangle(p, t) {
  const s = [0, 1, 2].map((k) => {
    const [a, b] = [t[k], t[(k + 1) % 3]];
    return Math.sign((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]));
  });
  return !(s.includes(1) && s.includes(-1));
}

// Where the tags go, in grid units: p and q a cell or so from their vertex, A and B at their
// triangle's centroid or near it, inside it; each spot inside the grid, at least half a cell
// from every edge of the pair and clear of the marks (a crack's ring: RING cells), the
// nearest such spot first, else the clearest.
export function tagSpots(pair, marks, W, H) {
  const edges = pair.flatMap((t) => [0, 1, 2].map((k) => [t[k], t[(k + 1) % 3]]));
  const clearance = (p) => Math.min(
    ...edges.map(([a, b]) => segmentDistance(p, a, b) / 0.5),
    ...marks.map((m) => Math.hypot(p[0] - m[0], p[1] - m[1]) / (RING + 0.75)));
  const around = (at, radii) => [0, ...radii].flatMap((d) => (d ? Array.from({ length: 16 },
    (_, k) => [at[0] + d * Math.cos((k * Math.PI) / 8), at[1] + d * Math.sin((k * Math.PI) / 8)])
    : [at]));
  const pick = (candidates, ok) => {
    let best = null;
    for (const p of candidates) {
      if (p[0] < 0.5 || p[0] > W - 0.5 || p[1] < 0.5 || p[1] > H - 0.5 || !ok(p)) continue;
      const c = clearance(p);
      if (c >= 1) return p;
      if (!best || c > best[1]) best = [p, c];
    }
    return best ? best[0] : candidates[0];
  };
  const [A, B] = pair;
  const centroid = (t) => [0, 1].map((k) => (t[0][k] + t[1][k] + t[2][k]) / 3);
  return {
    p: pick(around(A[0], [1.2, 1.6, 2.0]).slice(1), () => true),
    q: pick(around(A[1], [1.2, 1.6, 2.0]).slice(1), () => true),
    A: pick(around(centroid(A), [0.8, 1.6]), (pt) => insideTriangle(pt, A)),
    B: pick(around(centroid(B), [0.8, 1.6]), (pt) => insideTriangle(pt, B)),
  };
}

// The key, in the fourth place: each mark as the panels draw it, in type as large as theirs.
// Its marks at KEY_CELL px at most, so that its rows stay apart when the panels' cells grow.
const KEY_CELL = 20;
function drawKey(ctx, [x0, y0], panelCell, keyWidth) {
  const k = scaleOf(ctx);
  // at least 16 px once the column has shrunk the canvas (r265 01-FIG2), as the marks
  const cell = Math.max(Math.min(panelCell, KEY_CELL), Math.round(16 * k));
  const rows = [["A (blue) and B (orange) share", null], ["the thick edge p–q. Marks:", null],
    ["a centre on p–q: a tie", "tie"], ["a tie drawn by the wrong one", "⇄"],
    ["drawn twice", "2"], ["drawn by neither: a crack", "✕"],
    ["unlike the integer fill", "box"]];
  const pitch = Math.max(Math.round(1.5 * cell), 26); // 26 px at 16-px cells, 30 at KEY_CELL
  ctx.textAlign = "left";
  rows.forEach(([text, mark], i) => {
    const y = y0 + 12 + pitch * i;
    const x = mark ? x0 + Math.round(cell * 1.8) : x0;
    ctx.fillStyle = "#111";
    // TEXT_PX, or a little less where a line would run past its place (the panel's width)
    const px = textPx(ctx, TEXT_PX);
    ctx.font = `${px}px sans-serif`;
    const room = keyWidth - (x - x0);
    const wide = ctx.measureText(text).width;
    if (wide > room) ctx.font = `${Math.floor((px * room) / wide)}px sans-serif`;
    ctx.fillText(text, x, y + 5);
    const cx = x0 + Math.round(cell * 0.7);
    if (mark === "tie") {
      const d = tieSize(cell, k);
      ctx.fillRect(cx - d / 2, y - d / 2, d, d);
    }
    if (mark === "box") {
      ctx.setLineDash([3 * k, 2 * k]);
      ctx.lineWidth = 1.5 * k;
      ctx.strokeStyle = "#000";
      ctx.strokeRect(cx - cell / 2 + 2, y - cell / 2 + 2, cell - 4, cell - 4);
      ctx.setLineDash([]);
    }
    if (mark === "✕") {
      // the ring the panels draw around a crack (review r65 01-3: the key had the bare ✕)
      ctx.strokeStyle = OKABE.vermillion;
      ctx.lineWidth = 3 * k;
      ctx.beginPath();
      ctx.arc(cx, y, cell * RING, 0, 2 * Math.PI);
      ctx.stroke();
    }
    if (mark && mark.length === 1) {
      ctx.font = `bold ${markPx(cell, mark, k)}px sans-serif`;
      ctx.textAlign = "center";
      ctx.fillStyle = mark === "⇄" ? "#000" : OKABE.vermillion;
      ctx.fillText(mark, cx, y + cell * 0.3);
      ctx.textAlign = "left";
    }
  });
}

// every digit of a double that matters (17 significant), trailing zeros dropped
const full = (x) => x.toPrecision(17).replace(/\.?0+$/, "");

// the spans of the pixel's row, as each fill computed them
export function explainPixel(pair, at, W, H, found, asListed = false) {
  if (!at) return "Point at a pixel for its row's span ends in each fill.";
  const { panel, row, col } = at;
  const meth = METHODS[panel][0];
  const ends = (t) => {
    if (meth === "integer") return null;
    const hit = spanRows(t, H, meth === "dda", asListed).find(([i]) => i === row);
    return hit ? `${full(hit[1])} … ${full(hit[2])}` : "no span on this row";
  };
  const f = found[panel];
  const i = row * W + col;
  // "neither" is the legend's word for a crack: only a crack is called that (r196 01-8)
  const crack = f.cracks.some(([r, c]) => r === row && c === col);
  const who = f.a[i] && f.b[i] ? "both (drawn twice)" : f.a[i] ? "A" : f.b[i] ? "B"
    : crack ? "neither (a crack)" : "no triangle: outside both";
  const spans = meth === "integer" ? "decided by exact integer edge functions, no span ends"
    : `A's span x = ${ends(pair[0])}; B's span x = ${ends(pair[1])}`;
  return `<b>${METHODS[panel][1]}</b>, pixel row ${row}, column ${col} (centre x = ${col + 0.5}): ` +
    `drawn by ${who}. Row ${row}: ${spans}.`;
}
