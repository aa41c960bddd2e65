// Lesson 00's map: the pipeline in the logical GL / Direct3D order, in the style of the
// WebGL state diagram. Click a stage (or Tab to it and press Enter) to see the tour
// triangle's data there. Every number is the engine's (teachraster.widgets.pipeline_map
// computes them); this file only lays them out.

// [key, name, what it does]; "|" breaks the name into lines. The names are the static
// figure's (PIPELINE_STAGES: the same ten stages, review r157 00-10), the lessons in each box
// the kernel's (data.lessons, from that table), not kept here.
export const STAGES = [
  ["vertex", "vertex|processing", "the vertex shader: object → clip coordinates"],
  ["assembly", "primitive|assembly", "vertices → triangles"],
  ["clip", "clipping|(guard band)", "near/far; x, y only beyond the guard band"],
  ["divide", "perspective|divide", "x, y, z ÷ w: clip → NDC"],
  ["viewport", "viewport", "NDC → window x, y, depth"],
  ["setup", "triangle|set-up", "edges, facing, culling, bounding box"],
  ["rasterize", "rasterisation", "the pixel centres inside become fragments"],
  ["fragment", "fragment|shading", "the fragment shader: interpolated attributes → colour"],
  ["depth", "depth test", "nearer wins (stored per pixel), and the stencil test"],
  ["blend", "blending", "colour → the colour target"],
];

const num = (x, d = 4) => (x === null || x === undefined ? "–" : fmt(x, d));
// clip coordinates, all to three decimals: 0.052632 beside 2.200 read as noise (review r225 S4)
const dec3 = (x) => x.toFixed(3);
const row = (cells, head = false) =>
  `<tr>${cells.map((c) => (head ? `<th>${c}</th>` : `<td>${c}</td>`)).join("")}</tr>`;
const vertexRows = (data, f) => data.clip.map((_, k) => row([`v${k + 1}`, ...f(k)])).join("");

// The tour triangle at stage `key`, as HTML: what the stage receives and what it makes.
export function stageHtml(data, key) {
  const V = (k) => data.window[k];
  switch (key) {
    case "vertex":
      return "<p>The vertex shader outputs clip coordinates (x, y, z, w) per vertex. The tour " +
        `triangle's are those of GL's perspective projection (near ${num(data.near)}, far ` +
        `${num(data.far)}; w is the depth along the viewing axis in front of the eye) and carry ` +
        "the attribute u (a texture coordinate, as lesson 04 names it).</p><table>" +
        row(["", "x", "y", "z", "w", "u"], true) +
        vertexRows(data, (k) => [...data.clip[k].map(dec3), num(data.u[k])]) + "</table>";
    case "assembly":
      return "<p>Primitive assembly groups the vertices three by three, in the order given: " +
        "one triangle, v1 → v2 → v3. Nothing is known yet of where it lands on the screen.</p>";
    case "clip":
      return "<p>A vertex is inside the view volume when −w ≤ x, y, z ≤ w (OpenGL's " +
        "default, GL 4.6 §13.7; Direct3D and Vulkan clip 0 ≤ z ≤ w, D3D11.3 §15.4). GPUs " +
        // depth clamp drops the near and far planes only: "not even those" read as if it
        // dropped w > 0 too (review r307 S3; D3D11 DepthClipEnable: "0 < w" still clipped)
        "clip only against the near and far planes and w &gt; 0; with depth clamp on (GL's " +
        "GL_DEPTH_CLAMP; Direct3D's DepthClipEnable = FALSE) only against w &gt; 0, and " +
        "depth is clamped to the depth range instead. x and y are clipped only far outside ±w, " +
        "beyond a guard band that keeps every vertex within the range of the GPU's " +
        "fixed-point rasteriser, each GPU its own; the rasteriser's bounding box does the " +
        "rest (lesson 05a). " +
        // one sentence on the simulator's own band (review r241 S7: its numbers were package
        // internals in a tour; lessons 05a and 10 print them)
        "This simulator has a band of its own, sized in lessons 05a and 10. " +
        "The test, on the clip coordinates (before any divide):</p><table>" +
        row(["", "x", "y", "z", "w", "−w ≤ x, y, z ≤ w?"], true) +
        vertexRows(data, (k) => {
          const c = data.clip[k], w = c[3];
          return [...c.map(dec3),
            c.slice(0, 3).every((v) => v >= -w && v <= w) ? "yes" : "no"];
        }) + `</table><p>${data.inside[0] ? "No plane cuts the triangle: it goes on whole." :
        "A plane cuts it: it is clipped into a polygon."}</p>`;
    case "divide":
      return "<p>Dividing by w gives normalised device coordinates, each in [−1, 1] inside " +
        "the view volume. This is where perspective happens: far vertices (large w) move " +
        "towards the centre.</p><table>" + row(["", "x_ndc", "y_ndc", "z_ndc"], true) +
        vertexRows(data, (k) => data.ndc[k].map(dec3)) + "</table>";
    case "viewport":
      return `<p>The viewport maps NDC to the ${data.width} × ${data.height} window: ` +
        "x = (x_ndc + 1) W/2, y = (1 − y_ndc) H/2 (y down), depth z = z_ndc/2 + 1/2.</p><table>" +
        row(["", "x (px)", "y (px)", "depth"], true) +
        vertexRows(data, (k) => V(k).map((v) => num(v, 5))) + "</table>";
    case "setup":
      return setupHtml(data);
    case "rasterize":
      return `<p>${data.fragments} pixel centres are inside (the top-left rule decides the ` +
        "ties): each becomes a fragment with its barycentric weights. Outlined: the pixels " +
        "whose centres the rasteriser tests, the bounding box of the vertices widened to " +
        "whole pixels (the set-up's rows and columns).</p>";
    case "fragment":
      return "<p>The fragment shader runs once per fragment on the interpolated attributes: " +
        "here u, perspective-correct (interpolating u/w and 1/w), mapped to a colour. It " +
        "could write its own depth (<code>gl_FragDepth</code>) or discard the fragment, " +
        "which is why the depth test and the depth write logically come <i>after</i> it.</p>" +
        "<p>Key: u = 0 dark blue, 0.5 grey, 1 yellow (cividis, the colour map every lesson " +
        "uses for values); light grey: no fragment.</p>";
    case "depth":
      return `<p>Each fragment's depth, the window depth interpolated with the plain screen ` +
        "weights (it is affine on the screen: no divide by w, unlike u), is compared with the " +
        `stored one (cleared to 1): nearer wins. ${data.passed} of ${data.fragments} ` +
        "fragments pass (nothing was drawn before). <b>Early-z</b> (dashed; GL 4.6 §14.9) runs this test " +
        "and the depth write before the shader, to skip hidden fragments: a conditional " +
        "bypass, legal only when the shader neither discards, writes depth nor writes memory " +
        "(image or buffer stores, atomics: side effects a culled fragment must not lose). A shader that " +
        "writes its own depth needs the late test (unless it declares conservative depth); " +
        "with one that may discard, a GPU may still test early and write the depth late, " +
        "once the shader has kept the fragment (lessons 05a, 10).</p><p>The <b>stencil " +
        "test</b>, off here, runs just before the depth test (GL 4.6 §17.3): it compares a " +
        "per-pixel integer, the stencil value, with a reference, and whether a fragment " +
        "fails it, fails the depth test or passes both may update that value (masks, " +
        "shadow volumes, and the counting of lesson 11).</p><p>Key: the fragments' depths, " +
        "the darker the grey, the nearer (depth 0 would be near black, depth 1 light grey); " +
        "white: no fragment written (the cleared pixels, left blank).</p>";
    case "blend":
      return "<p>Blending is off: each surviving fragment's colour replaces the pixel's (the " +
        "colour target was cleared to white). That is the final image.</p>";
    default:
      return "";
  }
}

function setupHtml(data) {
  const names = ["E12", "E23", "E31"];
  const snapped = data.snapped.map((p, k) => `v${k + 1} = (${num(p[0], 6)}, ${num(p[1], 6)})`);
  const [r0, r1, c0, c1] = data.bbox;
  return "<p>Once per triangle: the vertices snapped to the 1/256 px grid " +
    `(${snapped.join(", ")}); the signed area ${num(data.area, 5)} px², ` +
    `${data.area > 0 ? "clockwise on screen: back-facing" : "counter-clockwise: front-facing"} ` +
    `in GL's default; culling is off, so it is ${data.culled ? "culled" : "kept"}. ` +
    `The three edge functions and the top-left rule: ${names.map((n, k) =>
      `${n} ${data.topLeft[k] ? "top/left (owns its centres)" : "not top-left"}`).join(", ")} ` +
    `(oriented order v${data.oriented.map((k) => k + 1).join(" v")}). Bounding box: rows ` +
    `${r0}–${r1 - 1}, columns ${c0}–${c1 - 1}.</p>`;
}

// the depth stage's greys: depth 0 at DEPTH_BLACK, depth 1 at DEPTH_BLACK + DEPTH_GREYS
export const DEPTH_BLACK = 20;
export const DEPTH_GREYS = 180;

// the per-pixel picture of a stage (null: none)
export function stageImage(data, key) {
  const n = data.width * data.height;
  const grey = (v) => [v, v, v];
  if (key === "rasterize") return Array.from({ length: n }, (_, i) => (data.coverage[i] ? [86, 180, 233] : grey(245)));
  if (key === "fragment") return data.colour.map((c, i) => (data.coverage[i] ? c : grey(245)));
  if (key === "depth") {
    // depth 0..1 to grey 20..200, and no fragment white: depth 1 (grey 240) against a
    // grey-245 "no fragment" could not be told apart on a projector (review r115 00-B)
    return data.depth.map((d) => (d === null ? grey(255) : grey(Math.round(DEPTH_BLACK + DEPTH_GREYS * d))));
  }
  if (key === "blend") return data.colour;
  return null;
}

const PIPE_CSS = `
.tr-pipe svg { max-width: 100%; height: auto; display: block; }
.tr-pipe .stage { cursor: pointer; }
.tr-pipe .stage:focus { outline: none; }
.tr-pipe .stage:focus rect, .tr-pipe .stage:hover rect { stroke-width: 3; }
.tr-pipe-detail { display: flex; flex-wrap: wrap; gap: 14px; align-items: flex-start;
  font-size: 15px; }
.tr-pipe-detail > div { flex: 1 1 380px; max-width: 640px; }
`;

const SVG = "http://www.w3.org/2000/svg";
function svg(tag, attrs, text) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

// Two rows of five boxes; the second row continues from the first. Every text of the map is
// 16 px, the stage names bold (review r91 00-D, r97 00-5: 13-px names and a caption read
// 12-13 px on a laptop at 1280 px, not from the back of a hall): drawn 1:1 wherever the
// column is 736 px or more (JupyterLab's with the file browser open at 1280 and 1400 px,
// as test_browser_explorables measures), and shrunk with it below that, to 12.7 px in the
// 585-px column of a 1024-px screen (the figures' minimum there, 12 px). The boxes are
// 132 px wide: the widest
// names, "(guard band)" and "rasterisation", are 116 and 113 px at 16 px bold (DejaVu Sans,
// the widest of the usual sans-serifs), which leaves 8 px on either side, clear of the
// selected box's 2-px border (at 14 px in 104-px boxes they ran to 0.3 px of it: review r17).
// The lesson numbers come in lines of at most nine characters (about 75 px: review r97 00-5
// found the depth test's three lessons on one line filling its box from border to border),
// three lines at most, 18 px apart, under the name: boxes 100 px tall.
export const MAP = { width: 736, height: 462, font: 16, name: 16, nameLine: 19, line: 20, lessons: 18 };
// the lines of the caption above the map and of the note under early-z
export const CAPTION = ["The logical order of OpenGL and Direct3D; in each box, the lessons that",
  "teach the stage. Click a stage for the tour triangle there."];
// two statements, not one with an aside: "neither discards ... (discard: test early, write
// late)" read as a contradiction (review r157 00-11)
export const EARLY_Z_NOTE = ["early-z (lessons 05a, 10), optional: depth tested and written",
  "before shading, only if the shader neither discards, writes",
  "depth nor writes memory. With a shader that may discard,",
  "some GPUs still test early and write depth after it."];
// the map's sizes, texts and boxes (for the tests, which measure the texts against them)
export function mapGeometry() {
  return { ...MAP, caption: CAPTION, note: EARLY_Z_NOTE, boxes: layout() };
}

export function layout() {
  const [bw, bh, gx, gy, x0, y0] = [132, 100, 18, 70, 2, 52];
  return STAGES.map(([key], k) => {
    const r = Math.floor(k / 5);
    const c = k % 5;
    return { key, x: x0 + c * (bw + gx), y: y0 + r * (bh + gy), w: bw, h: bh };
  });
}

function diagram(onPick, lessons) {
  const boxes = layout();
  const root = svg("svg", { viewBox: `0 0 ${MAP.width} ${MAP.height}`, width: MAP.width, role: "group",
    "aria-label": "the pipeline stages; pick one" });
  root.append(svg("defs", {}));
  root.firstChild.innerHTML = '<marker id="tr-arrow" viewBox="0 0 10 10" refX="9" refY="5" ' +
    'markerWidth="7" markerHeight="7" orient="auto"><path d="M0,0 L10,5 L0,10 z" fill="#333"/></marker>';
  const arrow = (d, dash) => root.append(svg("path", { d, fill: "none", stroke: "#333",
    "stroke-width": 2, "marker-end": "url(#tr-arrow)", "stroke-dasharray": dash || "" }));
  boxes.forEach((b, k) => {
    if (k === 4 || k === 9) return;
    const n = boxes[k + 1];
    arrow(`M${b.x + b.w},${b.y + b.h / 2} L${n.x - 2},${n.y + n.h / 2}`);
  });
  const [a, z] = [boxes[4], boxes[5]];
  arrow(`M${a.x + a.w / 2},${a.y + a.h} C${a.x + a.w / 2},${a.y + a.h + 40} ${z.x + z.w / 2},` +
    `${z.y - 40} ${z.x + z.w / 2},${z.y - 2}`);
  // early-z: an optional depth test on the way from rasterisation to the fragment shader,
  // dashed, not an arrow from rasterisation to the depth test around the shader (review r45,
  // 00: that read as fragments skipping the shader)
  const [r, f] = [boxes[6], boxes[7]];
  const [ex, ey, ew, eh] = [r.x + r.w / 2 - 30, r.y + r.h + 24, f.x - r.x + 60, 28];
  // a button too: it opens the depth test's stage, where early-z is explained (review r77
  // 00-8: clicking it did nothing). data-early, not data-stage: one box per stage
  const early = svg("g", { class: "stage", tabindex: 0, role: "button", "data-early": "depth",
    "aria-label": "early depth test: see the depth test" });
  early.append(svg("rect", { x: ex, y: ey, width: ew, height: eh, rx: 6, fill: "#fff",
    stroke: "#333", "stroke-width": 1.5, "stroke-dasharray": "7 5" }));
  early.append(svg("text", { x: ex + ew / 2, y: ey + 19, "text-anchor": "middle",
    "font-size": MAP.font, "font-weight": "bold", fill: "#333" }, "early depth test"));
  early.addEventListener("click", (e) => onPick("depth", e));
  onKeys(early, (e) => {
    if (e.key === "Enter" || e.key === " ") {
      e.preventDefault();
      onPick("depth", e);
    }
  });
  root.append(early);
  arrow(`M${r.x + r.w / 2},${r.y + r.h} L${r.x + r.w / 2},${ey - 2}`, "7 5");
  arrow(`M${f.x + f.w / 2},${ey} L${f.x + f.w / 2},${f.y + f.h + 2}`, "7 5");
  EARLY_Z_NOTE.forEach((line, i) => root.append(svg("text",
    { x: ex + ew / 2, y: ey + eh + 20 + MAP.line * i, "text-anchor": "middle",
      "font-size": MAP.font, fill: "#333" }, line)));
  const groups = boxes.map((b, k) => {
    const [, name] = STAGES[k];
    const g = svg("g", { class: "stage", tabindex: 0, role: "button", "aria-label": name.replaceAll("|", " "),
      "data-stage": b.key });
    const main = b.key === "rasterize";
    g.append(svg("rect", { x: b.x, y: b.y, width: b.w, height: b.h, rx: 8,
      fill: main ? "#d6ecf8" : "#f6f6f6", stroke: main ? "#0072B2" : "#777", "stroke-width": main ? 2.5 : 1.5 }));
    const lines = name.split("|");
    lines.forEach((line, i) => g.append(svg("text", { x: b.x + b.w / 2,
      y: b.y + (lines.length > 1 ? 23 : 30) + MAP.nameLine * i, "text-anchor": "middle",
      "font-size": MAP.name, "font-weight": "bold" }, line)));
    const taught = lessons[b.key];
    taught.forEach((line, i) => g.append(svg("text", { x: b.x + b.w / 2,
      y: b.y + b.h - 9 - MAP.lessons * (taught.length - 1 - i), "text-anchor": "middle",
      "font-size": MAP.font, fill: "#444" }, line)));
    g.addEventListener("click", (e) => onPick(b.key, e));
    onKeys(g, (e) => {
      if (e.key === "Enter" || e.key === " ") {
        e.preventDefault();
        onPick(b.key, e);
      }
    });
    root.append(g);
    return g;
  });
  CAPTION.forEach((line, i) => root.append(
    svg("text", { x: 2, y: 17 + MAP.line * i, "font-size": MAP.font, fill: "#333" }, line)));
  return { root, groups, early };
}

function mount(el, data, host) {
  addCss("tr-pipe-css", PIPE_CSS);
  let state = { stage: "rasterize", ...host.state() };
  const root = frame(el, data.title, "");
  root.classList.add("tr-pipe");
  const { root: map, groups, early } = diagram((key, e) => pick(key, e), data.lessons);
  const title = element("div", { class: "tr-x-title" });
  const text = element("div", { "aria-live": "polite" });
  const cell = Math.max(8, Math.min(18, Math.floor(300 / Math.max(data.width, data.height))));
  const [canvas, ctx] = makeCanvas(data.width * cell + 2, data.height * cell + 2,
    "the tour triangle's pixels at this stage");
  const detail = element("div", { class: "tr-pipe-detail" }, [element("div", {}, [title, text]), canvas]);
  root.append(map, detail);

  function draw() {
    const k = STAGES.findIndex(([key]) => key === state.stage);
    groups.forEach((g, i) => g.querySelector("rect").setAttribute("fill",
      i === k ? "#fde9c8" : STAGES[i][0] === "rasterize" ? "#d6ecf8" : "#f6f6f6"));
    // the early test is the depth test run earlier: its page is the depth stage's, and it
    // is marked with it (review r157 00-13: clicked, it opened that page unmarked)
    early.querySelector("rect").setAttribute("fill", state.stage === "depth" ? "#fde9c8" : "#fff");
    title.textContent = `${STAGES[k][1].replaceAll("|", " ")}: ${STAGES[k][2]}`;
    text.innerHTML = stageHtml(data, state.stage);
    const img = stageImage(data, state.stage);
    canvas.style.display = img ? "" : "none";
    if (img) drawPixels(ctx, data, img, cell, state.stage);
    host.picture(canvas);
  }
  const paint = painter(canvas, draw);
  function pick(key, e) {
    state.stage = key;
    paint.request(e);
    host.setState({ stage: key });
  }
  paint.now();
  return {
    setState(s) {
      state = { ...state, ...s };
      paint.request();
    },
  };
}

function drawPixels(ctx, data, img, cell, key) {
  const [W, H] = [data.width, data.height];
  img.forEach((c, i) => {
    ctx.fillStyle = `rgb(${c[0]},${c[1]},${c[2]})`;
    ctx.fillRect(1 + (i % W) * cell, 1 + Math.floor(i / W) * cell, cell, cell);
  });
  drawGrid(ctx, 0.5, 0.5, W, H, cell, "rgba(0,0,0,0.15)");
  if (key === "rasterize") {
    const [r0, r1, c0, c1] = data.bbox;
    ctx.strokeStyle = OKABE.orange;
    ctx.lineWidth = 2;
    ctx.strokeRect(1 + c0 * cell, 1 + r0 * cell, (c1 - c0) * cell, (r1 - r0) * cell);
    ctx.lineWidth = 1;
  }
  ctx.strokeStyle = "#000";
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  data.window.forEach(([x, y], k) => (k ? ctx.lineTo(1 + x * cell, 1 + y * cell) : ctx.moveTo(1 + x * cell, 1 + y * cell)));
  ctx.closePath();
  ctx.stroke();
  ctx.lineWidth = 1;
}
