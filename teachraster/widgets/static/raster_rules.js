// teachraster's coverage rules, in the page: snapping, edge functions, the top-left rule,
// and the naive span fills lesson 01 shows failing (float crossing + ceil, float DDA).
//
// The same rules as teachraster.core.snapping / core.edges (and, for the naive fills,
// teachraster.study.hardcases.naive.naive_span_fill); tests/test_explorables_js.py runs
// these functions with node on the engine's inputs and compares every answer exactly.
//
// Exactness: positions are held in units of 1/2**(bits + 1) px (pixel centres are then
// integers too). The explorables' grids are at most 128 px, so a coordinate is below 2**17
// units, a product of two differences below 2**36 and an edge function exact in a double
// (exact below 2**53), as the engine's int64 ones are.

export const SUBPIXEL_BITS = 8;

export function unitsPerPixel(bits = SUBPIXEL_BITS) {
  return 2 ** (bits + 1);
}

// a position in px -> units on the snapped grid (round half to even, as np.rint)
export function toUnits(x, bits = SUBPIXEL_BITS) {
  return rint(x * 2 ** bits) * 2;
}

// E(a, b, p) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x): twice the signed area
export function edgeValue(a, b, p) {
  return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
}

// the directed edge a -> b (interior on its positive side, y down) is top or left
export function isTopLeft(a, b) {
  return b[1] < a[1] || (b[1] === a[1] && b[0] > a[0]);
}

// what the edge a -> b is (interior on its positive side, y down), and its bias: the
// integer test E + bias >= 0 is the top-left rule (E >= 0 on top/left edges, E > 0 else)
export function edgeKind(a, b) {
  if (b[1] < a[1]) return "left";
  if (b[1] > a[1]) return "right";
  return b[0] > a[0] ? "top" : "bottom";
}

export function edgeBias(a, b) {
  return isTopLeft(a, b) ? 0 : -1;
}

// Snap, orient, classify: the set-up of teachraster.core.edges.setup_edges. `p` holds the
// vertices (units) re-ordered so that the area is positive, perm[k] the given index of p[k];
// edge k runs p[k] -> p[(k + 1) % 3].
export function setupTriangle(xy, bits = SUBPIXEL_BITS) {
  const v = xy.map(([x, y]) => [toUnits(x, bits), toUnits(y, bits)]);
  const area2 = edgeValue(v[0], v[1], v[2]);
  const perm = area2 < 0 ? [0, 2, 1] : [0, 1, 2];
  const p = perm.map((i) => v[i]);
  const edges = [0, 1, 2].map((k) => [p[k], p[(k + 1) % 3]]);
  return {
    given: v, p, perm, area2: Math.abs(area2), originalArea2: area2,
    topLeft: edges.map(([a, b]) => isTopLeft(a, b)),
    kinds: edges.map(([a, b]) => edgeKind(a, b)),
    unit: unitsPerPixel(bits),
  };
}

// the centre of pixel (row, col) in units
export function centreUnits(setup, row, col) {
  const h = setup.unit / 2;
  return [col * setup.unit + h, row * setup.unit + h];
}

// E of the oriented edges at the centre of (row, col), in units^2
export function orientedValues(setup, row, col) {
  const c = centreUnits(setup, row, col);
  return [0, 1, 2].map((k) => edgeValue(setup.p[k], setup.p[(k + 1) % 3], c));
}

// E12, E23, E31 of the vertices as given (their signs flip with the winding), units^2
export function givenValues(setup, row, col) {
  const c = centreUnits(setup, row, col);
  const v = setup.given;
  return [0, 1, 2].map((k) => edgeValue(v[k], v[(k + 1) % 3], c));
}

// the per-centre decision: every oriented edge passes (E > 0, or E >= 0 on a top-left edge)
export function covers(setup, row, col) {
  if (setup.area2 === 0) return false; // zero area: nothing is inside
  const e = orientedValues(setup, row, col);
  return e.every((ek, k) => ek + (setup.topLeft[k] ? 0 : -1) >= 0);
}

// coverage of a width x height image, row-major (1 = covered)
export function coverageGrid(setup, width, height) {
  const out = new Uint8Array(width * height);
  for (let r = 0; r < height; r++) {
    for (let c = 0; c < width; c++) out[r * width + c] = covers(setup, r, c) ? 1 : 0;
  }
  return out;
}

// -- lesson 01's naive span fills (pixel units, float64, no snapping) ---------------------------
function sortedByHeight(xy) {
  // by v (top to bottom), then by u: np.lexsort((u, v))
  return [...xy].map((p, i) => [p, i]).sort((a, b) => a[0][1] - b[0][1] || a[0][0] - b[0][0]
    || a[1] - b[1]).map(([p]) => p);
}

// u where the raster line at height v meets the edge a-b (the u4 formula, v_mid -> v)
export function crossing(a, b, v) {
  return ((v - a[1]) / (b[1] - a[1])) * (b[0] - a[0]) + a[0];
}

// an edge's ends in the order the triangle lists them (a before b when b follows a)
function listed(xy, a, b) {
  const ia = xy.indexOf(a);
  const ib = xy.indexOf(b);
  return (ia + 1) % 3 === ib ? [a, b] : [b, a];
}

// The spans of lesson 01's float span fill: [row, x_left, x_right] for each raster line
// v_top <= v < v_bot, each crossing computed with the u4 formula or, `stepped`, walked by
// du/dv per raster line (a float DDA). Each edge is evaluated from its upper end, or with
// `asListed` from the end the triangle lists first (then two triangles sharing an edge
// evaluate it from opposite ends). As teachraster.study.naive_spans.naive_span_fill.
export function spanRows(xy, height, stepped = false, asListed = false) {
  const [TOP, MID, BOT] = sortedByHeight(xy);
  const edge = (a, b) => (asListed ? listed(xy, a, b) : [a, b]);
  const rows = [];
  for (let i = 0; i < height; i++) if (TOP[1] <= i + 0.5 && i + 0.5 < BOT[1]) rows.push(i);
  if (!rows.length) return [];
  const walker = (a, b, v) => {
    const step = (b[0] - a[0]) / (b[1] - a[1]);
    return [a[0] + (v - a[1]) * step, step];
  };
  const longIsLeft = crossing(TOP, BOT, MID[1]) < MID[0];
  const long = edge(TOP, BOT);
  let [xLong, stepLong] = walker(long[0], long[1], rows[0] + 0.5);
  let [xShort, stepShort, upper] = [0, 0, null];
  const out = [];
  for (const i of rows) {
    const v = i + 0.5;
    const short = v < MID[1] ? edge(TOP, MID) : edge(MID, BOT);
    if (stepped) {
      if (upper !== (v < MID[1])) {
        upper = v < MID[1];
        [xShort, stepShort] = walker(short[0], short[1], v);
      }
    } else {
      [xLong, xShort] = [crossing(long[0], long[1], v), crossing(short[0], short[1], v)];
    }
    out.push(longIsLeft ? [i, xLong, xShort] : [i, xShort, xLong]);
    if (stepped) [xLong, xShort] = [xLong + stepLong, xShort + stepShort];
  }
  return out;
}

// the pixels of those spans: ceil(x_left - 0.5) <= j < ceil(x_right - 0.5)
export function spanFill(xy, width, height, stepped = false, asListed = false) {
  const cover = new Uint8Array(width * height);
  for (const [i, xl, xr] of spanRows(xy, height, stepped, asListed)) {
    const first = Math.ceil(xl - 0.5);
    const stop = Math.ceil(xr - 0.5);
    for (let j = Math.max(first, 0); j < Math.max(Math.min(stop, width), 0); j++) cover[i * width + j] = 1;
  }
  return cover;
}

// the integer edge functions of the engine, on the same footing as the two above
export function edgeFunctionFill(xy, width, height) {
  return coverageGrid(setupTriangle(xy), width, height);
}

export const FILLS = {
  crossing: (xy, w, h, asListed) => spanFill(xy, w, h, false, asListed),
  dda: (xy, w, h, asListed) => spanFill(xy, w, h, true, asListed),
  integer: edgeFunctionFill,
};
