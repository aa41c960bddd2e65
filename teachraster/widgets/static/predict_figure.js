// Predictions answered by acting on a figure, and revealed by the figure itself.
//
// Four kinds share this module (data.kind):
// - "pixels": click (or drag across) the cells you expect (pixels lit, tiles rejected: data.cell,
//   data.picked), or tick "none" where the question offers it (data.noneLabel: an honest
//   prediction may be no cell at all); Check draws the true cells
//   over yours: right ones ticked, missed ones outlined, extra ones crossed;
// - "point": drag the marker to where you expect the point; Check draws the true point, the
//   gap and whether it is within the tolerance;
// - "order": put the items in order (drag a chip, or focus it and use the arrow keys), or
//   say that no order works; Check marks each place and shows the right order;
// - "choice": pick one option (a multiple choice, no figure needed); Check is enabled at the
//   pick, with no round trip to a kernel that may be busy (review r98, 07: an ipywidgets
//   Predict's Check waited over a second), and marks the right option and a wrong pick
//   once the kernel has sent the answer (below).
// Check stays disabled until an answer is given. The picture behind is the kernel's
// (matplotlib, drawn once); the verdicts are teachraster.widgets.predict_figure's, and the
// tests compare the two (node).
//
// The answer is not in the page before Check (issue 31: devtools, or a saved notebook's widget
// state, read it): Check tells the kernel, which sends what the reveal shows (`reveal`: the
// answer, a point's curve) in the state; the page says "Checking…" until it is there. An
// offline page (`teachraster html`, no kernel) carries it in data.reveal and judges at once.

// -- verdicts (pure) ----------------------------------------------------------------------------
// Check is pressed once: enabled while an answer is given and the answer not yet shown (a
// prediction checked again after the reveal, with the answer copied, is none: review r28)
export function checkDisabled(revealed, answered) {
  return Boolean(revealed) || !answered;
}

// Check's tooltip, kept with its state (review r170 05b-6: it still read "give your answer
// first" once an answer was given and Check enabled)
export function checkTitle(revealed, answered) {
  if (revealed) return "checked: your prediction is kept";
  return answered ? "check your prediction" : "give your answer first";
}

// A pixels question is answered by a marked cell, or by "none" ticked where it is offered
// (acted, with no cell marked: an honest prediction may be that nothing is drawn)
export function pixelsAnswered(given, acted) {
  return given.length > 0 || Boolean(acted);
}

export function pixelVerdict(answer, given, width) {
  const key = ([r, c]) => r * width + c;
  const truth = new Set(answer.map(key));
  const mine = new Set(given.map(key));
  const right = [...mine].filter((k) => truth.has(k)).length;
  return { right, extra: mine.size - right, missed: truth.size - right, total: truth.size,
    correct: right === truth.size && mine.size === truth.size };
}

// A missed cell's fill: Okabe-Ito's reddish purple (#CC79A7), half transparent
export const MISSED_FILL = "rgba(204,121,167,0.5)";
// every cell the student marked is filled blue, right or not (the outline tells them apart): the
// key's "yours, and right" swatch is blue too (review r129 08-6: only "not among them" was)
export const GIVEN_FILL = "rgba(0,114,178,0.45)";
// ... and ringed in near-black on a white halo, which reads on any picture's colour (r484 W-1)
export const GIVEN_LINE = "#111";

// The key to the revealed answer, in the colours the figure draws it in (a legend under the
// verdict: the outlines alone do not say which is which on a projector, review r31/r34)
export function pixelLegend() {
  const box = (style) => `<span style="display:inline-block;width:14px;height:14px;` +
    `vertical-align:middle;margin:0 4px 0 10px;box-sizing:border-box;${style}"></span>`;
  return `<br>${box(`background:${GIVEN_FILL};border:3px solid ${OKABE.green}`)}yours, and right` +
    `${box(`background:${MISSED_FILL};border:4px solid ${OKABE.purple}`)}missed` +
    `${box(`background:${GIVEN_FILL};border:2px solid ${OKABE.vermillion}`)}` +
    `marked, not among them (crossed)`;
}

// The answer a press on the point marker leaves: where it was dragged, or, when the press
// was a click (released within CLICK_PX of where it began), the answer before the press. A
// click on the marker moved it by the pointer's offset from its centre, enabled Check and
// had the start point graded (review r209 03-5).
export function pressAnswer(down, up, before, dragged) {
  return Math.hypot(up[0] - down[0], up[1] - down[1]) < CLICK_PX ? before : dragged;
}

// Where the point marker goes for a pointer or an arrow key at p (data units): onto the
// segment `along` when the question has one, to 4 decimals, and always inside the plot's data
// rectangle `box` ([[x0, x1], [y0, y1]], PredictPoint's xlim and ylim, either way round), so
// a drag past the plot's edge leaves the marker on the edge, in sight (review r215 07-3:
// dragged off the plot it vanished, the mouse could not bring it back, and Check graded the
// answer off the picture). Rounded before it is clamped: a bound stays the bound.
export function constrainPoint(p, along, box) {
  let q = p;
  if (along) {
    const [a, b] = along;
    const d = [b[0] - a[0], b[1] - a[1]];
    const t = Math.max(0, Math.min(1, ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / (d[0] ** 2 + d[1] ** 2)));
    q = [a[0] + t * d[0], a[1] + t * d[1]];
  }
  q = q.map((v) => Number(v.toFixed(4)));
  if (!box) return q;
  return q.map((v, k) => Math.min(Math.max(v, Math.min(...box[k])), Math.max(...box[k])));
}

// A point answers only inside the plot's data rectangle (no box: anywhere): a marker off the
// picture, from a saved state or code, keeps Check disabled (PredictPoint.given refuses it)
export function pointAnswered(given, box) {
  if (!given) return false;
  return !box || given.every((v, k) => v >= Math.min(...box[k]) && v <= Math.max(...box[k]));
}

export function pointVerdict(answer, given, tolerance) {
  const gap = Math.hypot(given[0] - answer[0], given[1] - answer[1]);
  // a marker on the answer but for the float noise of its screen-to-data conversion is on it:
  // "1.78e-15 px from the answer" read as noise to a student (review r236 S-6; point_gap)
  const noise = 1e-9 * Math.max(1, Math.abs(answer[0]), Math.abs(answer[1]));
  return { gap: gap <= noise ? 0 : gap, correct: gap <= tolerance };
}

// a point verdict's distance: three significant digits, no finer than a hundredth of the
// tolerance's order ("0.00101 units" at a tolerance of 0.15 read as more precise than a drag
// can be, review r342 S1); gap_text in predict_figure.py writes the same
export function gapText(gap, tolerance) {
  const shown = tolerance > 0
    ? Number(gap.toFixed(Math.max(0, 2 - Math.floor(Math.log10(tolerance))))) : gap;
  return fmt(shown, 3);
}

// the point question's instruction: the arrow keys move the marker too, once the figure has
// been clicked (review r215 07-3: nothing said so); a click only gives the figure the keys, it
// moves nothing (review r270 09: "or click the figure" read as "click to place it")
export const POINT_HINT = "Drag the orange marker to your answer (or click the figure to " +
  "select it, then use the arrow keys; Shift: ten steps). A click alone does not move it.";

// the live readout of a point marker's x ("code 186"): data.readout, data.readoutDigits; a
// label with "{}" places the number there ("{} triangles": "60 triangles", review r344 01-S1)
export function readoutText(label, x, digits) {
  const n = x.toFixed(digits);
  return label.includes("{}") ? label.replace("{}", n) : `${label} ${n}`;
}

// A dragged marker whose readout shows whole numbers (codes) lands on one, as the arrow keys
// move it (review r43 12b-5: "You predicted code 180. Your marker is 8.29 codes from the
// answer"); other markers stay where they are dropped.
export function snapDragged(p, readout, digits) {
  return readout && digits === 0 ? [Math.round(p[0]), p[1]] : p;
}

// a choice's verdict: PredictChoice.verdict is "Right." or "Not quite." and then `text`
// (the tests compare the two)
export function choiceVerdict(answer, given) {
  return { correct: given === answer,
    text: `You predicted <b>${escapeHtml(given)}</b>; the answer is <b>${escapeHtml(answer)}</b>.` };
}

// an order's verdict text: PredictOrder.verdict is "Right." or "Not quite." and then this
// (the tests compare the two); null is "no order works", as answer or as given
export function orderVerdictText(answer, given, impossibleLabel) {
  const named = (order) => (order === null ? impossibleLabel : order.join(" \u2192 "));
  return `You predicted <b>${named(given)}</b>; the answer is <b>${named(answer)}</b>.`;
}

// the order's chips beside a ticked "no order works": set aside (greyed, marked disabled)
// and not movable, so the page never shows an order and the box at once, the one graded
// (review r190 05a-5: the chips stayed active, with nothing saying the order was ignored);
// after Check nothing moves either
export function chipsState(impossibleTicked, revealed) {
  return { aside: Boolean(impossibleTicked), movable: !impossibleTicked && !revealed };
}

export function orderVerdict(answer, given) {
  // answer null: no order works; given null: the student said so
  if (answer === null || given === null) return { places: null, correct: answer === given };
  const places = given.map((item, k) => item === answer[k]);
  return { places, correct: places.every(Boolean) };
}

// the live readout's font: the size of the figure's axis labels once the canvas is shown at
// a notebook column's width (review r336 S7: at 16 px "ρ 4.65" read at about 12 px on screen,
// the smallest text in the figure, though the question asks the student to read it)
export const READOUT_FONT = "bold 21px sans-serif";

// where the live readout goes (canvas pixels, y down): up and to the right of the marker,
// or to its left when the canvas ends; its box (the font's cap height and descent) is what
// the answer's label must keep clear of
export function readoutPlace(mine, textWidth, canvasWidth) {
  const right = mine[0] + 18 + textWidth > canvasWidth;
  const x = mine[0] + (right ? -18 : 18);
  const y = mine[1] - 17;
  return { x, y, align: right ? "right" : "left",
    box: { x0: right ? x - textWidth : x, x1: right ? x : x + textWidth, y0: y - 18, y1: y + 4 } };
}

// where "the answer" goes by the true point (canvas pixels, y down): above the dot, or below
// it when the marker is above or there is no room, and on the side away from the marker
// (whose cross reaches 14 px each way), so that it is never drawn under the marker. With a
// readout (its box from readoutPlace) the label also keeps clear of it: "th code 188" was the
// two printed over each other with the marker on the answer; the first of the four places
// round the dot that clears both wins. `lines` (canvas pixels, [[x0, y0], [x1, y1]] each):
// drawn lines the label's white ground should not cut, such as the segment a marker moves
// along (review r91 04-F: "the answer" lay across lesson 04's segment); a place clear of them
// is preferred, but not at the price of the marker or the readout.
export function answerLabel(mine, truth, readout = null, height = Infinity, lines = []) {
  const left = mine[0] > truth[0];
  const below = mine[1] < truth[1] - 4 || truth[1] < 30;
  const place = (l, b) => ({ x: truth[0] + (l ? -6 : 6), y: b ? truth[1] + 30 : truth[1] - 18,
    align: l ? "right" : "left" });
  const tries = [[left, below], [left, !below], [!left, below], [!left, !below]].map(([l, b]) => place(l, b));
  const overlaps = (a, b) => a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
  const cross = { x0: mine[0] - 14, x1: mine[0] + 14, y0: mine[1] - 14, y1: mine[1] + 14 };
  const clear = (p) => {
    const box = labelBox(p);
    return box.y0 >= 0 && box.y1 <= height && !overlaps(box, cross) && !(readout && overlaps(box, readout));
  };
  const crosses = (p) => {
    const box = labelBox(p);
    return lines.some(([a, b]) => Array.from({ length: 41 }, (_, k) => k / 40).some((t) => {
      const [x, y] = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
      return x > box.x0 - 3 && x < box.x1 + 3 && y > box.y0 - 2 && y < box.y1 + 3;
    }));
  };
  return tries.find((p) => clear(p) && !crosses(p)) || tries.find(clear) || tries[0];
}

// the segments (data coordinates) "the answer" should keep clear of: the marker's segment,
// PredictPoint's keep_clear and the curve the reveal draws, each of its pieces
export function labelLines(data, revealCurve = null) {
  const curve = (revealCurve || []).slice(1).map((p, k) => [revealCurve[k], p]);
  return [...(data.along ? [data.along] : []), ...(data.keepClear || []), ...curve];
}

// the box "the answer" fills at the 18 px bold font (about 104 px wide), from its baseline
// up (at 14 px the label came out at 10 px in a column at 1024 px: review r8, lesson 04 c3)
export const ANSWER_FONT = "bold 18px sans-serif";
export function labelBox(p) {
  const x0 = p.align === "right" ? p.x - 104 : p.x;
  return { x0, x1: x0 + 104, y0: p.y - 15, y1: p.y + 3 };
}

const PRED_CSS = `
.tr-predict { border-left: 4px solid #0072B2; padding: 4px 0 4px 12px; margin: 6px 0; }
.tr-predict-q { font-size: 1.05em; margin: 2px 0 6px; }
.tr-predict-box { position: relative; display: inline-block; max-width: 100%; }
.tr-predict-box img { display: block; max-width: 100%; height: auto; user-select: none; }
.tr-predict-box canvas { position: absolute; left: 0; top: 0; width: 100%; height: 100%; }
.tr-predict-verdict { margin: 6px 0; }
.tr-predict-none { display: block; margin: 6px 0; font-size: 15px; cursor: pointer; }
.tr-chips { display: flex; flex-wrap: wrap; gap: 8px; margin: 6px 0; min-height: 40px; }
.tr-chip { padding: 6px 12px; border: 2px solid #0072B2; border-radius: 18px; background: #eef6fb;
  cursor: grab; user-select: none; touch-action: none; }
.tr-chip:focus { outline: 3px solid #E69F00; }
.tr-chip.right { border-color: #009E73; background: #e3f5ee; }
.tr-chip.wrong { border-color: #D55E00; background: #fbe9e0; }
.tr-chips.aside .tr-chip { opacity: 0.35; border-style: dashed; background: #f2f2f2; cursor: not-allowed; }
.tr-choices { display: flex; flex-wrap: wrap; gap: 6px; margin: 4px 0 6px; }
.tr-choices button { font-size: 15px; padding: 4px 12px; }
.tr-predict .tr-choices button.right, .tr-predict .tr-choices button.wrong { opacity: 1;
  color: #111; outline-offset: 1px; }
.tr-predict .tr-choices button.right { outline: 3px solid #009E73; background: #e3f5ee; }
.tr-predict .tr-choices button.wrong { outline: 3px solid #D55E00; background: #fbe9e0; }
`;

function verdictHtml(right, text) {
  const colour = right ? "#009E73" : "#D55E00";
  return `<span style="color:${colour};font-weight:bold">${right ? "Right." : "Not quite."}` +
    `</span> ${text}`;
}

function mount(el, data, host) {
  addCss("tr-predict-css", PRED_CSS);
  const root = frame(el, "", "");
  root.classList.add("tr-predict");
  root.append(element("div", { class: "tr-predict-q", html: `<b>Predict first.</b> ${data.question}` }));
  const kinds = { pixels: mountPixels, point: mountPoint, order: mountOrder,
    choice: mountChoice };
  const view = kinds[data.kind](root, data, host);
  // the held answer cells (q.hold()) show once the notebook holds the class the kernel names
  // in the state when revealed: also a page reloaded on the same kernel (review r95, 09)
  const mark = (s) => { if (s && s.released) el.classList.add(s.released); };
  mark(host.state());
  return { ...view, setState(s) { mark(s); if (view.setState) view.setState(s); } };
}

// the picture (the kernel's PNG) with a canvas over it, in the picture's own pixels
function pictureBox(root, data) {
  const box = element("div", { class: "tr-predict-box" });
  const img = element("img", { alt: data.alt || "the figure of the question", draggable: "false" });
  img.src = `data:image/png;base64,${data.png}`;
  const [w, h] = data.size;
  img.width = w;
  const canvas = document.createElement("canvas");
  canvas.width = w;
  canvas.height = h;
  canvas.logical = { w, h, dpr: 1 };
  canvas.tabIndex = 0;
  canvas.setAttribute("aria-label", data.alt || "the figure: answer on it");
  box.append(img, canvas);
  root.append(box);
  const [x0, y0, sx, sy] = data.transform;
  const toPx = ([x, y]) => [x0 + sx * x, y0 + sy * y];
  const toData = ([px, py]) => [(px - x0) / sx, (py - y0) / sy];
  return { canvas, ctx: canvas.getContext("2d"), toPx, toData };
}

// the picture and the marks over it, as one canvas (what the saved notebook keeps)
function overlaid(canvas) {
  const img = canvas.parentElement.querySelector("img");
  const out = document.createElement("canvas");
  [out.width, out.height] = [canvas.width, canvas.height];
  out.logical = { w: canvas.width, h: canvas.height, dpr: 1 };
  const ctx = out.getContext("2d");
  if (img.complete) ctx.drawImage(img, 0, 0, canvas.width, canvas.height);
  ctx.drawImage(canvas, 0, 0);
  return out;
}

// what the reveal shows (the answer, ...): the kernel's, once Check is pressed, or the
// offline page's own; null while the kernel has not sent it
export function revealed(data, state) {
  return state.reveal || data.reveal || null;
}

// Check (disabled until an answer is given) and, once pressed, the verdict and the
// explanation: show(correct, text, known), the explanation coming with the answer (known:
// review r132 06-4, it often states the answer); waiting(live) while the kernel has not sent it
function checkRow(root, data, onCheck) {
  const check = button("Check", onCheck);
  check.disabled = true;
  check.title = "give your answer first";
  const verdict = element("div", { class: "tr-predict-verdict", "aria-live": "polite" });
  const explain = element("div");
  root.append(element("div", { class: "tr-x-row" }, [check]), verdict, explain);
  const show = (correct, text, known) => {
    check.disabled = true;
    check.title = "checked: your prediction is kept";
    verdict.innerHTML = verdictHtml(correct, text);
    explain.innerHTML = (known && known.explain) || "";
  };
  const waiting = (live) => {
    check.disabled = true;
    verdict.textContent = live ? "Checking\u2026"
      : "Checking needs the notebook running: Run All (Run \u25b8 Run All Cells).";
  };
  return { check, show, waiting };
}

// Check pressed (byClick) or a revealed state come in: the kernel told of a Check pressed
// here; then the answer, once known (else "Checking…"). Returns it, or null.
function revealStart(host, data, state, byClick, sent, waiting) {
  state.revealed = true;
  if (byClick) host.setState(sent);
  const known = revealed(data, state);
  if (!known) waiting(host.live);
  return known;
}

// the figure shows the answer: repainted, and the picture kept for the saved notebook. A
// picture drawn without the question's own marks (data.pngAnswered: rings round the cells
// asked about) replaces the question's first, so that the figure shows only what the key
// names (review r291 02-1: rings left on cells rightly unmarked read as "missed")
function revealOnFigure(host, canvas, paint, data = {}) {
  paint.request();
  const img = canvas.parentElement.querySelector("img");
  const answered = data.pngAnswered && `data:image/png;base64,${data.pngAnswered}`;
  if (!answered || img.src === answered) return host.picture(overlaid(canvas));
  img.addEventListener("load", () => host.picture(overlaid(canvas)), { once: true });
  img.src = answered;
}

function mountPixels(root, data, host) {
  let state = { given: [], acted: false, revealed: false, ...host.state() };
  const { canvas, ctx, toPx, toData } = pictureBox(root, data);
  const { check, show, waiting } = checkRow(root, data, () => reveal(true));
  const answered = () => pixelsAnswered(state.given, state.acted);
  const none = data.noneLabel ? noneChoice(root, check, data.noneLabel) : null;
  const showNone = () => { if (none) none.checked = Boolean(state.acted) && !state.given.length; };
  showNone();
  if (none) {
    none.addEventListener("change", () => {
      if (state.revealed) return;
      state.acted = none.checked;
      if (state.acted) state.given = []; // "none" clears the marked cells
      host.setState({ given: state.given, acted: state.acted });
      paint.request();
    });
  }
  const cell = data.cell || "pixel";
  const picked = data.picked || "lit";
  const cells = (n) => (n === 1 ? cell : `${cell}s`);
  // html, as the verdict is: data.cell and data.picked come HTML-escaped ("E &gt; 0" showed
  // as such in lesson 07's q_flat when set as text: r474)
  const note = element("div", { html: data.one ? `Click the ${cell} you expect ${picked}.`
    : `Click the ${cell}s you expect ${picked} (drag to paint several).` });
  root.insertBefore(note, canvas.parentElement);
  const W = data.width;
  const H = data.height;
  const has = (r, c) => state.given.some(([a, b]) => a === r && b === c);
  let painting = null;

  function draw() {
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    const cell = (r, c) => {
      const [x, y] = toPx([c, r]);
      const [x1, y1] = toPx([c + 1, r + 1]);
      return [x, y, x1 - x, y1 - y];
    };
    const known = state.revealed && revealed(data, state);
    for (const [r, c] of state.given) {
      const [x, y, w, h] = cell(r, c);
      ctx.fillStyle = GIVEN_FILL;
      ctx.fillRect(x + 1, y + 1, w - 2, h - 2);
      // and ringed, a line on a white halo: the blue fill alone vanished on a picture's own
      // blue (lesson 05a's q_step draws passed fragments in it: review r484 W-1). Once
      // revealed, the line is the key's vermillion ("not among them"); a right cell's green
      // outline is drawn over it below.
      for (const [width, colour] of [[3, "white"], [1.5, known ? OKABE.vermillion : GIVEN_LINE]]) {
        ctx.lineWidth = width;
        ctx.strokeStyle = colour;
        ctx.strokeRect(x + 2.5, y + 2.5, w - 5, h - 5);
      }
    }
    if (known) {
      const truth = new Set(known.answer.map(([r, c]) => r * W + c));
      for (const [r, c] of known.answer) {
        const [x, y, w, h] = cell(r, c);
        // missed: purple, not the orange the lessons draw their diamonds and markers in;
        // filled and outlined solid and thick, so that where the answer was (the verdict's
        // point) reads on a projector (review r118 06-6: a dashed 3-px outline on a small
        // cell looked faint and dotted)
        if (!has(r, c)) {
          ctx.fillStyle = MISSED_FILL;
          ctx.fillRect(x + 1, y + 1, w - 2, h - 2);
        }
        ctx.lineWidth = has(r, c) ? 3 : 4;
        ctx.strokeStyle = has(r, c) ? OKABE.green : OKABE.purple;
        ctx.strokeRect(x + 2.5, y + 2.5, w - 5, h - 5);
      }
      ctx.lineWidth = 3;
      ctx.strokeStyle = OKABE.vermillion;
      for (const [r, c] of state.given) {
        if (truth.has(r * W + c)) continue;
        const [x, y, w, h] = cell(r, c);
        ctx.beginPath();
        ctx.moveTo(x + 5, y + 5);
        ctx.lineTo(x + w - 5, y + h - 5);
        ctx.moveTo(x + w - 5, y + 5);
        ctx.lineTo(x + 5, y + h - 5);
        ctx.stroke();
      }
    }
    check.disabled = checkDisabled(state.revealed, answered());
    check.title = checkTitle(state.revealed, answered());
  }
  const paint = painter(canvas, draw);

  function reveal(byClick) {
    if (!answered()) return;
    if (byClick && state.revealed) return; // checked once: the first answer is kept
    if (none) none.disabled = true; // the answer is kept as checked
    const sent = { revealed: true, given: state.given, acted: Boolean(state.acted) };
    const known = revealStart(host, data, state, byClick, sent, waiting);
    if (!known) return paint.request();
    const v = pixelVerdict(known.answer, state.given, W);
    show(v.correct, `You marked ${state.given.length} ${cells(state.given.length)}: ` +
      `${v.right} right, ${v.extra} too many, ${v.missed} missed. The answer: <b>${v.total}</b> ` +
      `${cells(v.total)} ${picked}.` + pixelLegend(), known);
    revealOnFigure(host, canvas, paint, data);
  }

  function cellAt(p) {
    const [x, y] = toData(p);
    const [c, r] = [Math.floor(x), Math.floor(y)];
    return r >= 0 && r < H && c >= 0 && c < W ? [r, c] : null;
  }
  function setCell(rc, on) {
    if (!rc || has(...rc) === on) return;
    state.given = on ? [...state.given, rc] : state.given.filter(([a, b]) => a !== rc[0] || b !== rc[1]);
  }
  canvas.addEventListener("pointerdown", (e) => {
    if (state.revealed) return;
    const rc = cellAt(pointerAt(canvas, e));
    if (!rc) return;
    state.acted = false; // a marked cell answers: "none" no longer holds
    showNone();
    painting = !has(...rc);
    setCell(rc, painting);
    capture(canvas, e);
    paint.request(e);
  });
  canvas.addEventListener("pointermove", (e) => {
    if (painting === null) return;
    setCell(cellAt(pointerAt(canvas, e)), painting);
    paint.request(e);
  });
  const up = () => {
    if (painting === null) return;
    painting = null;
    host.setState({ given: state.given, acted: false });
  };
  canvas.addEventListener("pointerup", up);
  canvas.addEventListener("pointercancel", up);
  paint.now();
  if (state.revealed) reveal(false);
  return {
    setState(s) {
      state = { ...state, ...s };
      showNone();
      if (state.revealed) reveal(false);
      paint.request();
    },
  };
}

// the "none" choice of a pixels question: a checkbox above Check, its label the question's
function noneChoice(root, check, label) {
  const box = element("input", { type: "checkbox" });
  root.insertBefore(element("label", { class: "tr-predict-none" },
    [box, element("span", { html: ` ${label}` })]), check.parentElement);
  return box;
}

function mountPoint(root, data, host) {
  let state = { given: null, revealed: false, ...host.state() };
  const { canvas, ctx, toPx, toData } = pictureBox(root, data);
  const { check, show, waiting } = checkRow(root, data, () => reveal(true));
  root.insertBefore(element("div", { text: POINT_HINT }), canvas.parentElement);
  const start = data.start;
  const box = data.box || null; // the plot's data rectangle (none in a page saved before r215)
  const constrain = (p) => constrainPoint(p, data.along, box);
  const answered = () => pointAnswered(state.given, box);
  function readoutNow() {
    const g = state.given || start;
    return readoutText(data.readout, g[0], data.readoutDigits);
  }
  // the readout's box at the marker (null without one), measured in the font it is drawn in
  function readoutBox(mine) {
    if (!data.readout) return null;
    ctx.font = READOUT_FONT;
    return readoutPlace(mine, ctx.measureText(readoutNow()).width, canvas.width).box;
  }
  function draw() {
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    const mine = toPx(state.given || start);
    const known = state.revealed && revealed(data, state);
    if (known) {
      const truth = toPx(known.answer);
      if (known.revealCurve) {
        // the curve the answer comes from (PredictPoint's reveal_curve), kept out of the
        // question's picture
        ctx.strokeStyle = "#009E73";
        ctx.lineWidth = 3;
        ctx.beginPath();
        known.revealCurve.forEach((p, k) => (k ? ctx.lineTo(...toPx(p)) : ctx.moveTo(...toPx(p))));
        ctx.stroke();
      }
      if (data.rayFrom) {
        // the ray that finds the answer (PredictPoint's ray_from), on past it a little
        const from = toPx(data.rayFrom);
        const past = [truth[0] + 0.15 * (truth[0] - from[0]), truth[1] + 0.15 * (truth[1] - from[1])];
        ctx.strokeStyle = "#009E73";
        ctx.lineWidth = 3;
        ctx.beginPath();
        ctx.moveTo(...from);
        ctx.lineTo(...past);
        ctx.stroke();
      }
      ctx.lineWidth = 1.5;
      ctx.strokeStyle = "#333";
      ctx.setLineDash([4, 3]);
      ctx.beginPath();
      ctx.moveTo(...mine);
      ctx.lineTo(...truth);
      ctx.stroke();
      ctx.setLineDash([]);
      ctx.fillStyle = "#009E73";
      ctx.beginPath();
      ctx.arc(truth[0], truth[1], 9, 0, 2 * Math.PI);
      ctx.fill();
      const avoid = readoutBox(mine); // measured in the readout's font, before the label's is set
      ctx.font = ANSWER_FONT;
      // the segment the marker moves along, the figure's lines the label should not cover
      // (PredictPoint's keep_clear: lesson 03's triangle edges, review r106 03-W2) and the
      // curve the reveal draws (lesson 03's line λ1 = 0.6 ran under the label: review r330)
      const lines = labelLines(data, known.revealCurve).map((s) => s.map(toPx));
      const { x, y, align } = answerLabel(mine, truth, avoid, canvas.height, lines);
      // on a white ground: the lines through the answer (the segment, the eye ray) crossed the
      // words and read "theranswer" (review r58 04-7)
      const ground = labelBox({ x, y, align });
      ctx.fillStyle = "rgba(255, 255, 255, 0.9)";
      ctx.fillRect(ground.x0 - 3, ground.y0 - 2, ground.x1 - ground.x0 + 6, ground.y1 - ground.y0 + 5);
      ctx.textAlign = align;
      ctx.lineWidth = 4;
      ctx.strokeStyle = "white";
      ctx.strokeText("the answer", x, y);
      ctx.fillStyle = "#111";
      ctx.fillText("the answer", x, y);
      ctx.textAlign = "left";
    }
    ctx.lineWidth = 3.5;
    ctx.strokeStyle = OKABE.orange;
    ctx.beginPath();
    ctx.arc(mine[0], mine[1], 10, 0, 2 * Math.PI);
    ctx.stroke();
    ctx.beginPath();
    ctx.moveTo(mine[0] - 14, mine[1]);
    ctx.lineTo(mine[0] + 14, mine[1]);
    ctx.moveTo(mine[0], mine[1] - 14);
    ctx.lineTo(mine[0], mine[1] + 14);
    ctx.lineWidth = 1.5;
    ctx.stroke();
    if (data.readout) { // what the marker sits on, while it moves: no counting key presses
      const text = readoutNow();
      ctx.font = READOUT_FONT;
      const { x, y, align } = readoutPlace(mine, ctx.measureText(text).width, canvas.width);
      ctx.textAlign = align;
      ctx.lineWidth = 4;
      ctx.strokeStyle = "white";
      ctx.strokeText(text, x, y);
      ctx.fillStyle = "#111";
      ctx.fillText(text, x, y);
      ctx.textAlign = "left";
    }
    check.disabled = checkDisabled(state.revealed, answered());
    check.title = checkTitle(state.revealed, answered());
  }
  const paint = painter(canvas, draw);
  function reveal(byClick) {
    if (state.given === null || (byClick && !answered())) return;
    if (byClick && state.revealed) return; // checked once: the first answer is kept
    const known = revealStart(host, data, state, byClick, { revealed: true, given: state.given }, waiting);
    if (!known) return paint.request();
    const v = pointVerdict(known.answer, state.given, data.tolerance);
    const mine = data.readout
      ? `You predicted ${readoutText(data.readout, state.given[0], data.readoutDigits)}. ` : "";
    show(v.correct, `${mine}Your marker is ${gapText(v.gap, data.tolerance)} ${data.units} from the answer (green)` +
      `${data.tolerance ? `; within ${fmt(data.tolerance, 3)} ${data.units} is right` : ""}.`, known);
    revealOnFigure(host, canvas, paint);
  }
  let press = null; // where a press on the marker began, and the answer before it
  pointerInput(canvas, {
    handles: () => [toPx(state.given || start)],
    radius: 22,
    onPress(p, _e, held) {
      press = held === null ? null : { at: p, before: state.given };
    },
    onDrag(_i, p, e) {
      if (state.revealed) return;
      state.given = constrain(snapDragged(toData(p), data.readout, data.readoutDigits));
      paint.request(e);
    },
    onRelease(_i, p) {
      const answer = press ? pressAnswer(press.at, p, press.before, state.given) : state.given;
      press = null;
      if (answer !== state.given) { // a click on the marker: no answer given, nothing moved
        state.given = answer;
        paint.request();
        return;
      }
      host.setState({ given: state.given });
    },
  });
  onKeys(canvas, (e) => {
    const d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] }[e.key];
    if (!d || state.revealed) return;
    e.preventDefault();
    const g = state.given || start;
    const step = data.keyStep * (e.shiftKey ? 10 : 1); // Shift: ten steps at a time
    state.given = constrain([g[0] + d[0] * step, g[1] + d[1] * step * Math.sign(data.transform[3])]);
    paint.request(e);
    host.setState({ given: state.given });
  });
  paint.now();
  if (state.revealed) reveal(false);
  return {
    setState(s) {
      state = { ...state, ...s };
      if (state.revealed) reveal(false);
      paint.request();
    },
  };
}

function mountOrder(root, data, host) {
  let state = { given: null, acted: false, revealed: false, ...host.state() };
  if (data.png) pictureBox(root, data);
  const chips = element("div", { class: "tr-chips", role: "list",
    "aria-label": "the items: drag to reorder, or focus one and use the arrow keys" });
  root.append(element("div", { text: data.hint }), chips);
  let order = state.given ? [...state.given] : [...data.items];
  let impossible = null;
  if (data.allowImpossible) {
    impossible = element("input", { type: "checkbox" });
    impossible.checked = state.given === null && state.acted;
    impossible.addEventListener("change", () => {
      act();
      render_();
    });
    root.append(element("label", {}, [impossible, element("span", { text: data.impossibleLabel })]));
  }
  const { check, show, waiting } = checkRow(root, data, () => reveal(true));
  const given = () => (impossible && impossible.checked ? null : order);
  function act() {
    state.acted = true;
    state.given = given();
    host.setState({ given: state.given, acted: true });
  }
  const ticked = () => Boolean(impossible && impossible.checked);
  function render_() {
    chips.innerHTML = "";
    const known = state.revealed && revealed(data, state);
    const v = known ? orderVerdict(known.answer, given()) : null;
    const { aside } = chipsState(ticked(), state.revealed);
    chips.classList.toggle("aside", aside);
    chips.setAttribute("aria-disabled", String(aside));
    chips.title = aside ? `set aside: "${data.impossibleLabel}" is ticked` : "";
    order.forEach((item, k) => {
      const chip = element("div", { class: "tr-chip", tabindex: aside ? -1 : 0, role: "listitem", html: item });
      if (v && v.places) chip.classList.add(v.places[k] ? "right" : "wrong");
      onKeys(chip, (e) => {
        const d = { ArrowLeft: -1, ArrowUp: -1, ArrowRight: 1, ArrowDown: 1 }[e.key];
        if (!d || !chipsState(ticked(), state.revealed).movable) return;
        e.preventDefault();
        move(k, k + d);
        chips.children[Math.max(0, Math.min(order.length - 1, k + d))].focus();
      });
      chip.addEventListener("pointerdown", (e) => startDrag(e, k));
      chips.append(chip);
    });
    check.disabled = checkDisabled(state.revealed, state.acted);
    check.title = checkTitle(state.revealed, state.acted);
  }
  function move(from, to) {
    // A touch that moves nothing (a click on a chip, a drop where it was, an arrow key at
    // the end) still answers: the order shown is an answer too (review r38 05a).
    to = Math.max(0, Math.min(order.length - 1, to));
    if (from !== to) {
      const [item] = order.splice(from, 1);
      order.splice(to, 0, item);
    }
    act();
    render_();
  }
  function startDrag(e, k) {
    if (!chipsState(ticked(), state.revealed).movable) return;
    e.preventDefault();
    const target = e.currentTarget;
    capture(target, e);
    const onUp = (ev) => {
      target.removeEventListener("pointerup", onUp);
      const rects = [...chips.children].map((c) => c.getBoundingClientRect());
      let to = rects.findIndex((r) => ev.clientX < r.left + r.width / 2 && ev.clientY < r.bottom);
      if (to === -1) to = order.length - 1;
      else if (to > k) to -= 1;
      move(k, to);
    };
    target.addEventListener("pointerup", onUp);
  }
  function reveal(byClick) {
    if (!state.acted) return;
    if (byClick && state.revealed) return; // checked once: the first answer is kept
    if (impossible) impossible.disabled = true; // the answer is kept as checked
    const known = revealStart(host, data, state, byClick, { revealed: true, given: given(), acted: true }, waiting);
    render_();
    if (!known) return;
    const v = orderVerdict(known.answer, given());
    show(v.correct, orderVerdictText(known.answer, given(), data.impossibleLabel), known);
  }
  render_();
  if (state.revealed) reveal(false);
  return {
    setState(s) {
      state = { ...state, ...s };
      if (state.given) order = [...state.given];
      if (impossible) impossible.checked = state.given === null && state.acted;
      if (state.revealed) reveal(false);
      render_();
    },
  };
}

function mountChoice(root, data, host) {
  let state = { given: null, revealed: false, ...host.state() };
  if (data.png) pictureBox(root, data);
  const picks = choiceButtons(data.choices.map((c) => [c, c]), state.given, (value) => {
    if (state.revealed) return;
    state.given = value;
    render_(); // Check enabled at once: the page judges, the kernel hears of it after
    host.setState({ given: value });
  });
  const row = element("div", { class: "tr-choices", role: "group",
    "aria-label": "the answers: pick one" }, picks.buttons);
  root.append(row);
  const { check, show, waiting } = checkRow(root, data, () => reveal(true));
  function render_() {
    picks.set(state.given);
    const known = state.revealed && revealed(data, state);
    picks.buttons.forEach((b, k) => {
      const c = data.choices[k];
      b.disabled = state.revealed;
      b.classList.toggle("right", Boolean(known) && c === known.answer);
      b.classList.toggle("wrong", Boolean(known) && c === state.given && c !== known.answer);
    });
    check.disabled = checkDisabled(state.revealed, state.given !== null);
    check.title = checkTitle(state.revealed, state.given !== null);
  }
  function reveal(byClick) {
    if (state.given === null) return;
    if (byClick && state.revealed) return; // checked once: the first answer is kept
    const known = revealStart(host, data, state, byClick, { revealed: true, given: state.given }, waiting);
    render_();
    if (!known) return;
    const v = choiceVerdict(known.answer, state.given);
    show(v.correct, v.text, known);
  }
  render_();
  if (state.revealed) reveal(false);
  return {
    setState(s) {
      state = { ...state, ...s };
      if (state.revealed) reveal(false);
      render_();
    },
  };
}
