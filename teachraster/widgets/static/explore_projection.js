// Lesson 04: equal steps on the screen are unequal steps in the world (Ek, §2, Figs. 6-7).
//
// The eye at the origin, the screen the line z = 1, a segment from (x0, z0) to (x1, z1)
// whose ends are dragged. The ray through screen parameter q meets the segment at world
// parameter t(q) = q z0 / ((1 - q) z1 + q z0), the perspective weight of the engine
// (teachraster.plotting.projection.Segment.world_parameter; the tests compare). Below, t(q)
// against the affine guess t = q; the largest gap q - t, at q* = sqrt(r) / (1 + sqrt(r)) for the
// depth ratio r = z1 / z0, is (sqrt(r) - 1) / (sqrt(r) + 1): 3 - 2 sqrt(2) for r = 2.

export function worldParameter(q, z0, z1) {
  // λ = (1 - q, q) made perspective-correct with depths z0, z1
  const a = (1 - q) / z0;
  const b = q / z1;
  return b / (a + b);
}

// where the affine guess is furthest off, and by how much (signed: q - t)
export function peakGap(z0, z1) {
  const r = z1 / z0;
  const q = Math.sqrt(r) / (1 + Math.sqrt(r));
  return { q, t: worldParameter(q, z0, z1), gap: q - worldParameter(q, z0, z1),
    formula: (Math.sqrt(r) - 1) / (Math.sqrt(r) + 1) };
}

const ZMAX = 4.4; // the deepest end the picture holds

function mount(el, data, host) {
  let state = { ends: data.ends, q: data.q, ...host.state() };
  const root = frame(el, data.title,
    "Drag the segment's ends (or set their depth ratio with the slider) and slide q along " +
    "the screen: the eye ray through q meets the segment at t. Below, t(q) against the " +
    "affine guess t = q, with the largest gap marked.");
  const [canvas, ctx] = makeCanvas(640, 560, "eye, screen and segment, and the curve t(q)");
  const readout = element("div", { class: "tr-x-readout", "aria-live": "polite" });
  const qSlider = slider("q", { min: 0, max: 1, step: 0.01, value: state.q,
    format: (v) => v.toFixed(2) }, (v, e) => {
    state.q = v;
    paint.request(e);
  });
  qSlider.input.addEventListener("change", () => host.setState({ q: state.q }));
  const ratio = () => state.ends[1][1] / state.ends[0][1];
  const rSlider = slider("depth ratio z1/z0", { min: 0.25, max: 8, step: 0.05,
    value: ratio(), format: (v) => v.toFixed(2) }, (v, e) => {
    // keep both screen positions (x = s z): only depths change, z1 = v z0 (z0 made smaller
    // where z1 would leave the picture)
    const [[x0, z0], [x1, z1]] = state.ends;
    const [s0, s1] = [x0 / z0, x1 / z1];
    const n0 = Math.min(z0, ZMAX / v);
    state.ends = [[s0 * n0, n0], [s1 * v * n0, v * n0]];
    paint.request(e);
  });
  rSlider.input.addEventListener("change", () => host.setState({ ends: state.ends }));
  root.append(element("div", { class: "tr-x-row" }, [qSlider, rSlider]), canvas, readout);
  // the world picture: x right, depth z up, in the top 330 px
  const world = { x0: 60, y0: 330, sx: 70, sz: 62 };
  const toPx = ([x, z]) => [world.x0 + 250 + x * world.sx, world.y0 - z * world.sz];
  const fromPx = ([px, py]) => [(px - world.x0 - 250) / world.sx, (world.y0 - py) / world.sz];
  const plot = { x0: 70, y0: 530, w: 520, h: 170 };

  function draw() {
    ctx.clearRect(0, 0, 640, 560);
    const [[x0, z0], [x1, z1]] = state.ends;
    const q = state.q;
    const t = worldParameter(q, z0, z1);
    const [s0, s1] = [x0 / z0, x1 / z1];
    const s = s0 + q * (s1 - s0);
    const p = [x0 + t * (x1 - x0), z0 + t * (z1 - z0)];
    const pa = [x0 + q * (x1 - x0), z0 + q * (z1 - z0)];
    drawWorld(ctx, toPx, { x0, z0, x1, z1, s0, s1, s, p, pa });
    drawCurve(ctx, plot, z0, z1, q, t);
    const peak = peakGap(z0, z1);
    readout.innerHTML = `q = ${q.toFixed(2)} on the screen → t = ${t.toFixed(3)} on the segment ` +
      `(affine guess ${q.toFixed(2)}). Depth ratio z1/z0 = ${fmt(z1 / z0, 3)}: the largest gap ` +
      `q − t is ${fmt(peak.gap, 4)} at q = ${fmt(peak.q, 3)}` +
      `${Math.abs(z1 / z0 - 2) < 1e-9 ? " = 3 − 2√2" : ""}.`;
    host.picture(canvas);
  }
  const paint = painter(canvas, draw, () => state.ends.map(toPx));
  pointerInput(canvas, {
    handles: () => state.ends.map(toPx),
    onDrag(i, px, e) {
      let [x, z] = fromPx(px);
      z = Math.max(0.3, Math.min(ZMAX, z));
      x = Math.max(-3.4, Math.min(3.4, x));
      state.ends = state.ends.map((end, k) => (k === i ? [Number(x.toFixed(2)), Number(z.toFixed(2))] : end));
      rSlider.set(Number(ratio().toFixed(2)));
      paint.request(e);
    },
    onRelease() {
      host.setState({ ends: state.ends });
    },
  });
  paint.now();
  return {
    setState(s) {
      state = { ...state, ...s };
      qSlider.set(state.q);
      rSlider.set(Number(ratio().toFixed(2)));
      paint.request();
    },
  };
}

function drawWorld(ctx, toPx, g) {
  const far = 1.1 * Math.max(g.z0, g.z1, 1.5);
  // equal steps of q on the screen, their rays and where they hit the segment
  ctx.strokeStyle = "#ccc";
  ctx.lineWidth = 1;
  for (let k = 0; k <= 8; k++) {
    const q = k / 8;
    const t = worldParameter(q, g.z0, g.z1);
    const p = toPx([g.x0 + t * (g.x1 - g.x0), g.z0 + t * (g.z1 - g.z0)]);
    const o = toPx([0, 0]);
    ctx.beginPath();
    ctx.moveTo(o[0], o[1]);
    ctx.lineTo(p[0], p[1]);
    ctx.stroke();
    ctx.fillStyle = OKABE.orange;
    ctx.beginPath();
    ctx.arc(p[0], p[1], 4, 0, 2 * Math.PI);
    ctx.fill();
    const sp = toPx([g.s0 + q * (g.s1 - g.s0), 1]);
    ctx.fillStyle = OKABE.blue;
    ctx.fillRect(sp[0] - 1, sp[1] - 7, 2, 14);
  }
  const line = (a, b, colour, width, dash = []) => strokeLine(ctx, toPx(a), toPx(b), colour, width, dash);
  line([-3.5, 1], [3.5, 1], "#000", 2);
  line([0, 0], [g.s * far, far], OKABE.vermillion, 2);
  line([g.x0, g.z0], [g.x1, g.z1], "#000", 3);
  const dot = (p, colour, r, hollow = false) => {
    const [x, y] = toPx(p);
    ctx.beginPath();
    ctx.arc(x, y, r, 0, 2 * Math.PI);
    ctx.lineWidth = 2.5;
    if (hollow) {
      ctx.strokeStyle = colour;
      ctx.stroke();
    } else {
      ctx.fillStyle = colour;
      ctx.fill();
    }
  };
  dot(g.p, OKABE.vermillion, 7);
  dot(g.pa, OKABE.vermillion, 8, true);
  dot([g.s, 1], OKABE.vermillion, 5);
  for (const [k, e] of [[0, [g.x0, g.z0]], [1, [g.x1, g.z1]]]) {
    dot(e, "#000", 8);
    const [x, y] = toPx(e);
    ctx.fillStyle = "#111";
    ctx.font = "bold 14px sans-serif";
    ctx.fillText(`end ${k} (z = ${fmt(e[1], 3)})`, x + 10, y - 8);
  }
  const [ex, ey] = toPx([0, 0]);
  ctx.fillStyle = "#000";
  ctx.beginPath();
  ctx.moveTo(ex, ey - 10);
  ctx.lineTo(ex - 8, ey + 6);
  ctx.lineTo(ex + 8, ey + 6);
  ctx.closePath();
  ctx.fill();
  ctx.font = "13px sans-serif";
  ctx.fillText("eye", ex + 10, ey + 4);
  const [sx, sy] = toPx([3.5, 1]);
  ctx.fillText("screen z = 1", sx - 84, sy + 18);
  ctx.fillText("hollow: the affine guess t = q", 8, 16);
}

function drawCurve(ctx, plot, z0, z1, q, t) {
  const X = (v) => plot.x0 + v * plot.w;
  const Y = (v) => plot.y0 - v * plot.h;
  ctx.strokeStyle = "#888";
  ctx.lineWidth = 1;
  ctx.strokeRect(X(0), Y(1), plot.w, plot.h);
  ctx.setLineDash([5, 4]);
  ctx.beginPath();
  ctx.moveTo(X(0), Y(0));
  ctx.lineTo(X(1), Y(1));
  ctx.stroke();
  ctx.setLineDash([]);
  ctx.strokeStyle = "#000";
  ctx.lineWidth = 2.5;
  ctx.beginPath();
  for (let k = 0; k <= 100; k++) {
    const v = k / 100;
    const [x, y] = [X(v), Y(worldParameter(v, z0, z1))];
    if (k) ctx.lineTo(x, y);
    else ctx.moveTo(x, y);
  }
  ctx.stroke();
  const peak = peakGap(z0, z1);
  ctx.strokeStyle = OKABE.purple;
  ctx.lineWidth = 3;
  ctx.beginPath();
  ctx.moveTo(X(peak.q), Y(peak.q));
  ctx.lineTo(X(peak.q), Y(peak.t));
  ctx.stroke();
  ctx.fillStyle = OKABE.purple;
  ctx.font = "bold 13px sans-serif";
  const two = Math.abs(z1 / z0 - 2) < 1e-9;
  ctx.fillText(`largest gap ${fmt(Math.abs(peak.gap), 3)}${two ? " = 3 − 2√2" : ""}`,
    X(peak.q) + 6, Y((peak.q + peak.t) / 2));
  ctx.fillStyle = OKABE.vermillion;
  ctx.beginPath();
  ctx.arc(X(q), Y(t), 6, 0, 2 * Math.PI);
  ctx.fill();
  ctx.fillStyle = "#111";
  ctx.font = "13px sans-serif";
  ctx.fillText("q (screen) →", X(1) - 80, plot.y0 + 18);
  ctx.fillText("t (world)", X(0) - 62, Y(1) + 12);
  ctx.fillText("0", X(0) - 12, Y(0) + 4);
  ctx.fillText("1", X(0) - 12, Y(1) + 4);
  ctx.fillText("dashed: t = q (affine)", X(0) + 8, Y(1) + 16);
}
