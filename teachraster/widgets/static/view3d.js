// A small 3-D view on a 2-D canvas: an orbit camera (drag to rotate), orthographic, and
// polygons drawn far to near (the painter's algorithm, per polygon: surfaces are cut into
// small pieces so that sorting their centres is close enough for a picture).
//
// World axes: x right and y down as on the screen (pixels), z up (a value over the screen).

// the camera: `yaw` turns about z, `elevation` looks down from above the horizon (90°: the
// top view, the 2-D picture); `scale` px per world unit, `centre` the world point at `at`
export function camera3d({ yaw = -0.45, elevation = 0.6, scale = 20, centre = [0, 0, 0],
  at = [300, 250] } = {}) {
  const cam = { yaw, elevation, scale, centre, at };
  cam.project = (p) => {
    const x = p[0] - cam.centre[0];
    const y = p[1] - cam.centre[1];
    const z = p[2] - cam.centre[2];
    const ca = Math.cos(cam.yaw);
    const sa = Math.sin(cam.yaw);
    const x1 = x * ca - y * sa;
    const y1 = x * sa + y * ca;
    const se = Math.sin(cam.elevation);
    const ce = Math.cos(cam.elevation);
    return [cam.at[0] + cam.scale * x1, cam.at[1] + cam.scale * (y1 * se - z * ce),
      y1 * ce + z * se];
  };
  return cam;
}

// Draw polygons {pts: [[x, y, z], ...], fill, alpha, stroke, width} far to near. With
// `exact`, in the order of exactOrder (convex pieces only), else sorted by centre depth.
export function drawPolygons(ctx, cam, polys, exact = false) {
  const items = polys.map((poly) => {
    const s = poly.pts.map(cam.project);
    const depth = s.reduce((acc, q) => acc + q[2], 0) / s.length + (poly.bias || 0);
    return { poly, s, depth };
  });
  const order = exact ? exactOrder(cam, polys) : items.map((_, i) => i)
    .sort((a, b) => items[a].depth - items[b].depth);
  for (const { poly, s } of order.map((i) => items[i])) {
    ctx.beginPath();
    s.forEach((q, i) => (i ? ctx.lineTo(q[0], q[1]) : ctx.moveTo(q[0], q[1])));
    if (s.length > 2) ctx.closePath();
    if (poly.fill) {
      ctx.globalAlpha = poly.alpha ?? 1;
      ctx.fillStyle = poly.fill;
      ctx.fill();
      ctx.globalAlpha = 1;
    }
    if (poly.stroke) {
      ctx.strokeStyle = poly.stroke;
      ctx.lineWidth = poly.width || 1;
      ctx.stroke();
    }
  }
}

// the part of convex polygon a (2-D points) inside convex polygon b (Sutherland-Hodgman)
function clipConvex(a, b) {
  const area = b.reduce((acc, p, i) => {
    const q = b[(i + 1) % b.length];
    return acc + p[0] * q[1] - q[0] * p[1];
  }, 0);
  let out = a;
  for (let i = 0; i < b.length && out.length; i++) {
    const [p, q] = [b[i], b[(i + 1) % b.length]];
    const side = (r) => Math.sign(area) * ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
    const next = [];
    out.forEach((r, k) => {
      const t = out[(k + 1) % out.length];
      const [dr, dt] = [side(r), side(t)];
      if (dr >= 0) next.push(r);
      if ((dr > 0 && dt < 0) || (dr < 0 && dt > 0)) {
        const u = dr / (dr - dt);
        next.push([r[0] + u * (t[0] - r[0]), r[1] + u * (t[1] - r[1])]);
      }
    });
    out = next;
  }
  return out;
}

// a convex polygon's area and centre (2-D)
function areaCentre(pts) {
  let [a, cx, cy] = [0, 0, 0];
  pts.forEach((p, i) => {
    const q = pts[(i + 1) % pts.length];
    const c = p[0] * q[1] - q[0] * p[1];
    a += c;
    cx += (p[0] + q[0]) * c;
    cy += (p[1] + q[1]) * c;
  });
  return Math.abs(a) < 1e-12 ? [0, [0, 0]] : [Math.abs(a) / 2, [cx / (3 * a), cy / (3 * a)]];
}

// the depth of projected polygon s (fanned into triangles) over the screen point p
export function depthAt(s, p) {
  let best = [-Infinity, 0];
  for (let k = 1; k + 1 < s.length; k++) {
    const [a, b, c] = [s[0], s[k], s[k + 1]];
    const det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
    if (Math.abs(det) < 1e-12) continue;
    const l1 = ((p[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (p[1] - a[1])) / det;
    const l2 = ((b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1])) / det;
    const l0 = 1 - l1 - l2;
    const inside = Math.min(l0, l1, l2);
    if (inside > best[0]) best = [inside, l0 * a[2] + l1 * b[2] + l2 * c[2]];
  }
  return best[1];
}

// The order (indices into polys) to paint convex polygons far to near so that, wherever two
// overlap on the screen, the nearer one there is drawn later (review r96 03-1: sorting the
// centres interleaved two nearly parallel sheets in a low view, facet by facet). Each pair
// whose pictures overlap is compared at the centre of the overlap; the order is a
// topological sort of those comparisons, ties (and any cycle) by centre depth.
export function exactOrder(cam, polys) {
  const items = polys.map((poly) => {
    const s = poly.pts.map(cam.project);
    const xs = s.map((q) => q[0]);
    const ys = s.map((q) => q[1]);
    return { s, bias: poly.bias || 0, box: [Math.min(...xs), Math.max(...xs), Math.min(...ys),
      Math.max(...ys)], depth: s.reduce((acc, q) => acc + q[2], 0) / s.length + (poly.bias || 0) };
  });
  const n = items.length;
  const after = items.map(() => []);
  const count = new Array(n).fill(0);
  for (let i = 0; i < n; i++) {
    const a = items[i];
    for (let j = i + 1; j < n; j++) {
      const b = items[j];
      if (a.box[1] <= b.box[0] || b.box[1] <= a.box[0] || a.box[3] <= b.box[2] ||
        b.box[3] <= a.box[2]) continue;
      const [area, c] = areaCentre(clipConvex(a.s, b.s));
      if (area < 1e-6) continue;
      const [da, db] = [depthAt(a.s, c) + a.bias, depthAt(b.s, c) + b.bias];
      if (da === db) continue;
      const [far, near] = da < db ? [i, j] : [j, i];
      after[far].push(near);
      count[near] += 1;
    }
  }
  const order = [];
  const done = new Array(n).fill(false);
  const byDepth = items.map((_, i) => i).sort((a, b) => items[a].depth - items[b].depth);
  while (order.length < n) {
    // the farthest piece that nothing still undrawn must go under; in a cycle, the farthest
    const next = byDepth.find((i) => !done[i] && count[i] === 0) ??
      byDepth.find((i) => !done[i]);
    done[next] = true;
    order.push(next);
    for (const k of after[next]) count[k] -= 1;
  }
  return order;
}

// a surface z = f(x, y) over the quadrilateral or triangle `corners` (bilinear in its
// parameters), cut into n x n pieces: polygons for drawPolygons
export function surfacePieces(corners, f, n, style) {
  const at = (s, t) => {
    if (corners.length === 3) {
      // s, t in the triangle's parameters: (1 - s) a + s ((1 - t) b + t c)
      const [a, b, c] = corners;
      const x = (1 - s) * a[0] + s * ((1 - t) * b[0] + t * c[0]);
      const y = (1 - s) * a[1] + s * ((1 - t) * b[1] + t * c[1]);
      return [x, y];
    }
    const [a, b, c, d] = corners;
    const x = (1 - t) * ((1 - s) * a[0] + s * b[0]) + t * ((1 - s) * d[0] + s * c[0]);
    const y = (1 - t) * ((1 - s) * a[1] + s * b[1]) + t * ((1 - s) * d[1] + s * c[1]);
    return [x, y];
  };
  const out = [];
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < n; j++) {
      const q = [[i, j], [i + 1, j], [i + 1, j + 1], [i, j + 1]].map(([a, b]) => {
        const [x, y] = at(a / n, b / n);
        return [x, y, f(x, y)];
      });
      out.push({ ...style, pts: q });
    }
  }
  return out;
}

// Rotate the camera by dragging on the canvas; onChange() after each move.
export function orbitDrag(canvas, cam, onChange) {
  let last = null;
  canvas.addEventListener("pointerdown", (e) => {
    if (e.button !== 0) return;
    last = [e.clientX, e.clientY];
    cam.dragging = true; // a view may draw faster, less exactly, while it turns (r96 03-1)
    capture(canvas, e);
    e.preventDefault();
    canvas.focus({ preventScroll: true });
  });
  canvas.addEventListener("pointermove", (e) => {
    if (!last) return;
    cam.yaw += (e.clientX - last[0]) * 0.01;
    cam.elevation = tilt(cam, (e.clientY - last[1]) * 0.01);
    cam.turned = true;
    last = [e.clientX, e.clientY];
    onChange(e);
  });
  const up = (e) => {
    if (!last) return;
    last = null;
    cam.dragging = false;
    onChange(e); // the picture at rest, drawn exactly
  };
  canvas.addEventListener("pointerup", up);
  canvas.addEventListener("pointercancel", up);
  onKeys(canvas, (e) => {
    const turn = { ArrowLeft: [-0.08, 0], ArrowRight: [0.08, 0], ArrowUp: [0, 0.06],
      ArrowDown: [0, -0.06] }[e.key];
    if (!turn) return;
    e.preventDefault();
    cam.yaw += turn[0];
    cam.elevation = tilt(cam, turn[1]);
    cam.turned = true;
    onChange(e);
  });
}

// the elevation after a turn by `d`: above the horizon, at most `cam.maxElevation` (a view can
// keep off the top view, where surfaces over the screen overlap one another)
const tilt = (cam, d) => Math.max(0.05, Math.min(cam.maxElevation ?? Math.PI / 2, cam.elevation + d));

// the unit vector from the scene towards the camera (the projection's depth axis)
export function towardsCamera(yaw, elevation) {
  const ce = Math.cos(elevation);
  return [Math.sin(yaw) * ce, Math.cos(yaw) * ce, Math.sin(elevation)];
}

// a line in 3-D, drawn on top (labels, axes)
export function line3d(ctx, cam, a, b, stroke, width = 1, dash = []) {
  strokeLine(ctx, cam.project(a), cam.project(b), stroke, width, dash);
}

// halo: a white outline under the letters, for a label drawn over coloured surfaces
export function label3d(ctx, cam, p, text, color = "#111", font = "13px sans-serif", halo = false) {
  const q = cam.project(p);
  label2d(ctx, q[0], q[1], text, color, font, halo);
}

// a label at (x, y) on the canvas (y its baseline), haloed or not as label3d
export function label2d(ctx, x, y, text, color = "#111", font = "13px sans-serif", halo = false) {
  ctx.fillStyle = color;
  ctx.font = font;
  if (halo) {
    ctx.save();
    ctx.strokeStyle = "#fff";
    ctx.lineWidth = 5;
    ctx.lineJoin = "round";
    ctx.strokeText(text, x, y);
    ctx.restore();
  }
  ctx.fillText(text, x, y);
}

// Set cam.scale and cam.at so that `points` ([x, y, z]) and `labels` ({p: [x, y, z], w, up,
// down}: text from the projected p rightwards w px, up px above and down px below it) fill
// `box` ({left, top, right, bottom}, canvas px) at the camera's present turn (review r78 03-3:
// a fixed scale left 40 % of the canvas empty).
export function fitView(cam, points, labels, box) {
  Object.assign(cam, { scale: 1, at: [0, 0] });
  const items = [
    ...points.map((p) => [...cam.project(p).slice(0, 2), 0, 0, 0]),
    ...labels.map((l) => [...cam.project(l.p).slice(0, 2), l.w, l.up, l.down]),
  ];
  return Object.assign(cam, fitScale(items, box));
}

// The largest scale s and the offset `at` that put every item [x, y, w, up, down] (a point
// at scale 1 around the origin, with a box of text beside it) inside `box`; `extent`: the
// canvas box they then take. Orthographic: the extent is convex in s, so bisection finds it.
export function fitScale(items, box) {
  const extent = (s) => {
    const e = [Infinity, -Infinity, Infinity, -Infinity];
    for (const [x, y, w, up, down] of items) {
      e[0] = Math.min(e[0], s * x);
      e[1] = Math.max(e[1], s * x + w);
      e[2] = Math.min(e[2], s * y - up);
      e[3] = Math.max(e[3], s * y + down);
    }
    return e;
  };
  const fits = (s) => {
    const e = extent(s);
    return e[1] - e[0] <= box.right - box.left && e[3] - e[2] <= box.bottom - box.top;
  };
  let [lo, hi] = [0, 1];
  while (fits(hi) && hi < 1e9) [lo, hi] = [hi, 2 * hi];
  for (let k = 0; k < 40; k++) {
    const mid = (lo + hi) / 2;
    if (fits(mid)) lo = mid;
    else hi = mid;
  }
  const e = extent(lo);
  const at = [(box.left + box.right - e[0] - e[1]) / 2, (box.top + box.bottom - e[2] - e[3]) / 2];
  return { scale: lo, at, extent: [e[0] + at[0], e[1] + at[0], e[2] + at[1], e[3] + at[1]] };
}

// Move labels apart vertically until no two overlap (review r78 03-3: after a turn the vertex
// labels ran into one another). boxes: {x, y, w, h, fixed} (x, y the top left corner; a fixed
// box, such as an axis label, stays). The new y of each box, kept within [top, bottom]; a
// box pushed against an edge pushes the other one instead.
export function spreadLabels(boxes, top, bottom, gap = 2) {
  const ys = boxes.map((b) => b.y);
  const clamp = (i) => Math.min(Math.max(ys[i], top), bottom - boxes[i].h);
  for (let round = 0; round < 200; round++) {
    let moved = false;
    for (let i = 0; i < boxes.length; i++) {
      for (let j = i + 1; j < boxes.length; j++) {
        const [a, b] = [boxes[i], boxes[j]];
        const across = a.x < b.x + b.w && b.x < a.x + a.w;
        const overlap = Math.min(ys[i] + a.h, ys[j] + b.h) - Math.max(ys[i], ys[j]) + gap;
        if ((a.fixed && b.fixed) || !across || overlap <= 1e-9) continue;
        // the upper box goes up, the lower one down: half each, or all of it for a free one
        // beside a fixed one; near the canvas edge the other takes what the edge refuses
        const up = ys[i] < ys[j] || (ys[i] === ys[j] && i < j) ? i : j;
        const down = up === i ? j : i;
        const [du, dd] = boxes[up].fixed ? [0, overlap]
          : boxes[down].fixed ? [overlap, 0] : [overlap / 2, overlap / 2];
        ys[up] -= du;
        ys[down] += dd;
        const over = top - ys[up];
        if (over > 0 && !boxes[down].fixed) [ys[up], ys[down]] = [ys[up] + over, ys[down] + over];
        const under = ys[down] + boxes[down].h - bottom;
        if (under > 0 && !boxes[up].fixed) [ys[up], ys[down]] = [ys[up] - under, ys[down] - under];
        ys[up] = clamp(up);
        ys[down] = clamp(down);
        moved = true;
      }
    }
    if (!moved) break;
  }
  return ys;
}

// Clip a flat polygon [[x, y, z], ...] to the slab -h <= z <= h (Sutherland-Hodgman on z):
// a plane drawn over a box stays inside it. The empty list when nothing is left.
export function clipToSlab(pts, h) {
  let out = pts;
  for (const sign of [1, -1]) {
    const inside = (p) => sign * p[2] <= h;
    const cut = (a, b) => {
      const t = (sign * h - a[2]) / (b[2] - a[2]);
      return [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), sign * h];
    };
    const next = [];
    out.forEach((a, i) => {
      const b = out[(i + 1) % out.length];
      if (inside(a)) next.push(a);
      if (inside(a) !== inside(b)) next.push(cut(a, b));
    });
    out = next;
    if (!out.length) break;
  }
  return out;
}

// A camera scale that keeps the box [0, W] x [0, H] x [-h, h] inside a w x h_px area at every
// yaw: orthographic, so on screen x spans at most the box's radius in the ground plane. On y,
// with `elevation` given, the most a turn at that tilt shows, ground radius x sin + h x cos
// (tight: the box fills the area at its widest yaw, no band left empty under a low view);
// without it, at every tilt too, the radius of the whole box. `margin` is kept on x, `yMargin`
// (default the same) on y.
export function fitBox(W, H, h, w, hPx, margin = 8, elevation = null, yMargin = margin) {
  const ground = Math.hypot(W / 2, H / 2);
  const tall = elevation === null ? Math.hypot(ground, h)
    : ground * Math.abs(Math.sin(elevation)) + h * Math.abs(Math.cos(elevation));
  return Math.min((w / 2 - margin) / ground, (hPx / 2 - yMargin) / tall);
}
