// teachraster's page-side frames player.
//
// A fill's steps are drawn once, by matplotlib in the kernel (or by the `teachraster fill`
// command), and arrive here as groups of KEY steps: a key frame (the whole figure) and one
// patch per later step (the rectangle of pixels that step changed, or nothing). Showing
// step k paints the key frame of its group and the patches up to k on a canvas, so the
// slider, the buttons and Play change the picture without asking the kernel; the kernel
// hears of the step only when the slider is released or Play is paused.
//
// The same code runs as an anywidget module (the default export, in JupyterLab, Notebook 7,
// VS Code, Colab) and inlined in an offline HTML page (teachraster.plotting.pages), where
// every group is in the page and nothing is fetched.

const CSS = `
.tr-frames { font-family: var(--jp-ui-font-family, sans-serif); max-width: 100%;
  container-type: inline-size; }
.tr-frames .tr-bar { display: flex; align-items: center; gap: 4px; flex-wrap: wrap;
  margin: 4px 0; }
.tr-frames button { min-width: 34px; height: 28px; padding: 0 6px; cursor: pointer;
  border: 1px solid #bbb; border-radius: 3px; background: #f5f5f5; font-size: 14px; }
.tr-frames button:focus-visible, .tr-frames input:focus-visible { outline: 2px solid #1976d2; }
.tr-frames input[type=range] { flex: 1 1 200px; min-width: 160px; max-width: 460px; }
.tr-frames .tr-info { white-space: nowrap; font-size: 13px; min-width: 9em; }
.tr-frames .tr-caption { min-height: 3.2em; padding: 2px 6px; border: 1px solid #ddd;
  font-size: 15px; margin: 2px 0 4px 0; }
.tr-frames canvas { display: block; max-width: 100%; height: auto; }
/* A step whose picture is still on its way from the kernel (a busy kernel, say one still
   running the cells below): its readout and caption are shown at once, the older picture
   dimmed under a note saying so (review r99 02-5: the handle at the last step over "0 of
   172" and step 0's picture looked like a key the player had ignored). The note lies over
   the picture: one that comes and goes must not make the player jump in height (nor push
   it past a screen, issue 31). It is the player's only note: after a minute of silence it
   turns into the advice (red) and back when the kernel answers (review r9: a second
   "Waiting for the kernel" at the picture's foot said the same thing twice). */
.tr-frames .tr-stage { position: relative; width: fit-content; max-width: 100%; }
.tr-frames .tr-wait { display: none; position: absolute; left: 8px; top: 8px;
  margin-right: 8px; padding: 2px 8px; background: rgba(255, 255, 255, 0.92);
  border: 1px solid #999; border-radius: 3px; font-size: 15px; }
.tr-frames .tr-wait.tr-silent { color: #b00020; border-color: #b00020; }
.tr-frames .tr-stage.tr-waiting canvas { opacity: 0.35; }
.tr-frames .tr-stage.tr-waiting .tr-wait { display: block; }
.tr-frames button { display: inline-flex; align-items: center; justify-content: center;
  gap: 4px; white-space: nowrap; }
.tr-frames .tr-icon { width: 12px; height: 12px; fill: currentColor; flex: none; }
.tr-frames .tr-speed { white-space: nowrap; font-size: 13px; }
.tr-frames .tr-speed select { font-size: 13px; height: 26px; margin-left: 4px; }
/* Two lines of controls in a narrow column (issue 31: 315 px at 1024x768 with the file
   browser open and 150 % zoom, where the bar took three): the buttons (Play's word hidden,
   its icon and name stay) and the slider share the first, the step and the speed the
   second. A 320-px basis for the slider put it on a line of its own up to 540 px. */
@container (max-width: 420px) {
  .tr-frames .tr-text { display: none; }
  .tr-frames input[type=range] { flex-basis: 100px; min-width: 100px; }
}
`;

// The buttons' icons, drawn (SVG paths in a 16 x 16 box): the symbols U+23EE/U+23ED are
// missing from the fonts of many machines, where they showed as empty boxes.
const ICONS = {
  first: "M2 2h2.5v12H2z M14 2v12L5 8z",
  prev: "M12 2v12L4 8z",
  play: "M4 2v12l10-6z",
  pause: "M3 2h3.5v12H3z M9.5 2H13v12H9.5z",
  next: "M4 2v12l8-6z",
  last: "M11.5 2H14v12h-2.5z M2 2v12l9-6z",
};
const SVG = "http://www.w3.org/2000/svg";

function icon(name) {
  const svg = document.createElementNS(SVG, "svg");
  svg.setAttribute("viewBox", "0 0 16 16");
  svg.setAttribute("class", "tr-icon");
  svg.setAttribute("aria-hidden", "true");
  svg.dataset.icon = name;
  const path = document.createElementNS(SVG, "path");
  path.setAttribute("d", ICONS[name]);
  svg.appendChild(path);
  return svg;
}

// Speeds offered when playing, in steps per second (the player's interval is 1000 / speed
// ms): a 172-step fill takes 69 s at 2.5 steps a second, 7 s at 25.
const SPEEDS = [1, 2.5, 5, 10, 25, 50];

function speedText(ms) {
  const v = 1000 / ms;
  const n = Number.isInteger(v) ? v : Number(v.toPrecision(2));
  return `${n} ${n === 1 ? "step" : "steps"}/s`;
}

// A button showing icon `name` and `text` (optional), named `label` for screen readers.
function makeButton(label, name, text = "") {
  const b = document.createElement("button");
  b.type = "button";
  setButton(b, label, name, text);
  return b;
}

function setButton(b, label, name, text = "") {
  b.replaceChildren(icon(name));
  if (text) {
    const words = document.createElement("span");
    words.className = "tr-text"; // hidden in a narrow column (CSS above)
    words.textContent = text;
    b.append(words);
  }
  b.title = label;
  b.setAttribute("aria-label", label);
}

// The speed menu: SPEEDS, and the player's own interval when it is none of them.
function speedMenu() {
  const wrap = document.createElement("label");
  wrap.className = "tr-speed";
  wrap.append("speed");
  const select = document.createElement("select");
  select.setAttribute("aria-label", "speed");
  select.title = "speed when playing";
  wrap.appendChild(select);
  function choose(ms) {
    const values = new Set(SPEEDS.map((v) => 1000 / v));
    values.add(ms);
    const sorted = [...values].sort((a, b) => b - a); // slow to fast
    select.replaceChildren(...sorted.map((v) => {
      const o = document.createElement("option");
      o.value = String(v);
      o.textContent = speedText(v);
      return o;
    }));
    select.value = String(ms);
  }
  return { wrap, select, choose };
}

function b64Bytes(b64) {
  const raw = atob(b64);
  const out = new Uint8Array(raw.length);
  for (let i = 0; i < raw.length; i++) out[i] = raw.charCodeAt(i);
  return out;
}

// Decode one group: [[x, y], ...] with PNG bytes (or empty: the step changed nothing).
// null when a picture could not be decoded (page.js warns): the group is asked for again.
async function decodeGroup(places, blobs) {
  const frames = await Promise.all(
    places.map(async ([x, y], i) => {
      const bytes = blobs[i];
      if (!bytes || bytes.byteLength === 0) return null;
      const bitmap = await decodePng(bytes);
      return bitmap === null ? undefined : { x, y, bitmap };
    }),
  );
  if (!frames.includes(undefined)) return frames;
  for (const f of frames) if (f) f.bitmap.close();
  return null;
}

// What is wrong with a group's message, or "": one buffer per place, each of the length
// the kernel names in `sizes`. A kernel that exits while it sends (shut down, restarted)
// can glue two messages together: a group then came whose buffers were the frames of the
// next message ("stream.stdout", "<IDS|MSG>", its JSON), and decoded as pictures they
// failed as "The source image cannot be decoded." (a fresh-clone CI run).
export function groupMismatch(msg, buffers) {
  const got = buffers.map((b) => b.byteLength);
  const sizes = msg.sizes ?? got;
  if (got.length === msg.places.length && got.every((n, i) => n === sizes[i])) return "";
  const head = buffers.slice(0, 3).map((b) => JSON.stringify(String.fromCharCode(
    ...asBytes(b).subarray(0, 12))));
  return `group ${msg.group} came with ${got.length} buffers of [${got}] bytes for ` +
    `${msg.places.length} places, sent as [${sizes}] bytes (starting ${head.join(", ")})`;
}

// How long the kernel may be silent before the player says more than that a step's picture
// is on its way. On a loaded classroom hub a group can take seconds and more (review r97
// 00-1: "does not answer ... Run All" after 20 s, on a player whose picture then came): the
// advice to run everything again only after SILENT_MS, and even then not as a verdict.
export const SILENT_MS = 60000;

// The note over the picture while step k's picture is awaited and the kernel has been
// silent for `ms` (null: nothing asked yet): what is coming, then after SILENT_MS the advice.
export function waitingNote(k, ms) {
  if (ms === null || ms < SILENT_MS) {
    return `drawing step ${k}\u2026 (its picture comes from the kernel)`;
  }
  return `The kernel has not answered for ${Math.round(ms / 1000)} s. If it is still busy ` +
    "(its circle at the top right is filled), wait; if it was stopped or restarted, Run All " +
    "(Run \u25b8 Run All Cells) to bring the player back.";
}

// Mount a player in `el`. `opts`: width, height (pixels of a frame), n (steps), key (steps
// per group), step, interval (ms per step when playing), captions, infos (text per step),
// poster (PNG bytes of the first picture, optional), request(g) (ask for group g; absent
// in a static page), onStep(k) (the step settled: slider released, button, pause).
export function mountFrames(el, opts) {
  installKeyGuard(); // keys.js: the arrow keys move the step in Notebook 7 too
  addCss("tr-frames-css", CSS); // page.js
  const root = document.createElement("div");
  root.className = "tr-frames";
  const bar = document.createElement("div");
  bar.className = "tr-bar";
  const first = makeButton("first step", "first");
  const prev = makeButton("previous step", "prev");
  const play = makeButton("play", "play", "play");
  const next = makeButton("next step", "next");
  const last = makeButton("last step", "last");
  const speed = speedMenu();
  const slider = document.createElement("input");
  slider.type = "range";
  slider.min = "0";
  slider.setAttribute("aria-label", "step");
  slider.title = "step";
  const info = document.createElement("span");
  info.className = "tr-info";
  bar.append(first, prev, play, next, last, slider, info, speed.wrap);
  const caption = document.createElement("div");
  caption.className = "tr-caption teachraster-caption";
  caption.setAttribute("aria-live", "polite");
  const canvas = document.createElement("canvas");
  canvas.className = "teachraster-figure";
  canvas.setAttribute("role", "img");
  const ctx = canvas.getContext("2d");
  const stage = document.createElement("div"); // the picture, its notes over it
  stage.className = "tr-stage";
  const wait = document.createElement("div");
  wait.className = "tr-wait";
  wait.setAttribute("aria-live", "polite");
  stage.append(canvas, wait);
  root.append(bar, caption, stage);
  el.appendChild(root);
  // Keys pressed in the player (arrows on the slider, space on a button) are the player's:
  // JupyterLab's command-mode shortcuts must not also see them.
  root.addEventListener("keydown", (e) => e.stopPropagation());

  const s = {
    groups: new Map(), asked: new Set(), inflight: null, shown: -1, want: 0,
    timer: null, n: 0, key: 16, captions: [], infos: [], interval: 400, gen: 0,
    fill: "", cache: new Map(), waitingSince: null, watching: false, awaited: null,
  };
  // the decoded groups of the last few fills, by name (a toggle back paints at once)
  const CACHED_FILLS = 6;

  function label(k) {
    caption.textContent = s.captions[k] ?? "";
    info.textContent = `${k} ${s.infos[k] ?? ""}`;
  }

  // The step wanted has no picture yet (its group is on its way): its texts, which the page
  // holds for every step, at once, the picture on show dimmed under a note; or none waiting.
  function waiting(k) {
    s.awaited = k;
    if (k === null) {
      stage.classList.remove("tr-waiting");
      delete canvas.dataset.want;
      note();
      return;
    }
    label(k);
    note();
    stage.classList.add("tr-waiting");
    canvas.dataset.want = String(k); // for tests: the step whose picture is awaited
  }

  // The note's words for the step awaited (waitingNote), "" when none is.
  function note() {
    const k = s.awaited;
    const ms = s.waitingSince === null ? null : performance.now() - s.waitingSince;
    const text = k === null ? "" : waitingNote(k, ms);
    if (wait.textContent !== text) wait.textContent = text;
    wait.classList.toggle("tr-silent", k !== null && ms !== null && ms >= SILENT_MS);
  }

  function paint(p) {
    if (p) ctx.drawImage(p.bitmap, p.x, p.y);
  }

  // Paint step k if its group is here; else ask for the group and paint when it comes.
  function draw(k) {
    const g = Math.floor(k / s.key);
    const group = s.groups.get(g);
    if (!group) {
      need(g);
      return false;
    }
    const k0 = g * s.key;
    let from = k0 + 1;
    if (s.shown >= k0 && s.shown <= k && Math.floor(s.shown / s.key) === g) {
      from = s.shown + 1; // forward within the group: only the new patches
    } else {
      paint(group[0]);
    }
    for (let j = from; j <= k; j++) paint(group[j - k0]);
    s.shown = k;
    canvas.dataset.step = String(k);
    canvas.dataset.gen = String(s.gen); // the fill on show (tests and benchmarks wait on it)
    label(k);
    waiting(null);
    return true;
  }

  // Step k: the handle, the readout and the caption at once, the picture as soon as its
  // group is here (a key pressed before then must not look ignored: review r99 02-5).
  function show(k) {
    k = Math.max(0, Math.min(s.n - 1, k));
    s.want = k;
    slider.value = String(k);
    if (k === s.shown) waiting(null);
    else if (!draw(k)) waiting(k);
  }

  // One request at a time: the kernel renders a group at a time, and the page always asks
  // for the one it needs most (the step wanted, then ahead of it, then the rest).
  function need(g) {
    if (!opts.request || s.groups.has(g) || s.asked.has(g)) return;
    if (s.inflight === null) {
      s.inflight = g;
      s.asked.add(g);
      s.askedAt = performance.now();
      opts.request(g, s.gen);
      setTimeout(() => retry(g, s.gen), 3000);
      if (s.waitingSince === null) s.waitingSince = performance.now(); // kept over retries
      watch();
    } else {
      s.priority = g;
    }
  }

  // An answer that never came (dropped as one of an older fill while a toggle's state was
  // on its way, say): ask again rather than wait forever.
  function retry(g, gen) {
    if (gen === s.gen && s.inflight === g && !s.groups.has(g)) {
      s.inflight = null;
      s.asked.delete(g);
      need(g);
    }
  }

  // While a group is asked for and not here, the note over an awaited step's picture tells,
  // after SILENT_MS, how long the kernel has been silent (waitingNote); it is the step's note
  // again when the kernel answers, however late, and goes when the picture comes or a new
  // fill starts. One timer at a time, none while nothing is asked for.
  function watch() {
    if (s.watching) return;
    s.watching = true;
    const look = () => {
      if (s.inflight === null || s.waitingSince === null) {
        s.watching = false;
        s.waitingSince = null;
        note();
        return;
      }
      note();
      setTimeout(look, 1000);
    };
    setTimeout(look, 1000);
  }

  function nextMissing() {
    const count = Math.ceil(s.n / s.key);
    const here = Math.floor(s.want / s.key);
    if (s.priority !== undefined && !s.groups.has(s.priority)) return s.priority;
    for (let i = 0; i < count; i++) {
      const g = (here + i) % count;
      if (!s.groups.has(g) && !s.asked.has(g)) return g;
    }
    return null;
  }

  async function addGroup(g, places, blobs, gen) {
    if (gen !== s.gen) return;
    const frames = s.groups.get(g) ?? (await decodeGroup(places, blobs));
    if (gen !== s.gen) return;
    if (frames === null) {
      // not decoded: not kept, so showing one of its steps asks the kernel for it again
      if (s.inflight === g) s.inflight = null;
      return;
    }
    s.groups.set(g, frames);
    canvas.dataset.groups = String(s.groups.size); // for tests and benchmarks
    s.waitingSince = null; // the kernel answered: no advice (a late answer clears it)
    note();
    if (s.inflight === g) s.inflight = null;
    if (s.priority === g) s.priority = undefined;
    if (s.want !== s.shown) draw(s.want);
    const more = nextMissing();
    if (more !== null) need(more);
  }

  function settle() {
    if (opts.onStep) opts.onStep(s.want);
  }

  // Pause playing; the kernel hears of the step unless `quietly` (the slider moved: the
  // kernel hears of its own step when it is released, not of the one it left).
  function stop(quietly = false) {
    if (s.timer !== null) {
      clearInterval(s.timer);
      s.timer = null;
      setButton(play, "play", "play", "play");
      if (!quietly) settle();
    }
  }

  function tick() {
    if (s.want >= s.n - 1) return stop();
    // wait for a group still on its way rather than skip its steps
    if (s.shown === s.want) show(s.want + 1);
    else draw(s.want);
  }

  function start() {
    if (s.want >= s.n - 1) show(0);
    setButton(play, "pause (play is on)", "pause", "pause");
    s.timer = setInterval(tick, s.interval);
  }

  play.addEventListener("click", () => (s.timer === null ? start() : stop()));
  first.addEventListener("click", () => { stop(); show(0); settle(); });
  prev.addEventListener("click", () => { stop(); show(s.want - 1); settle(); });
  next.addEventListener("click", () => { stop(); show(s.want + 1); settle(); });
  last.addEventListener("click", () => { stop(); show(s.n - 1); settle(); });
  // every move of the range, by pointer or key, from the first: Play paused, the step shown
  slider.addEventListener("input", () => { stop(true); show(Number(slider.value)); });
  slider.addEventListener("change", settle);

  // The decoded frames of a fill no longer kept: their memory back at once (a bitmap's
  // pixels otherwise wait for the garbage collector).
  function release(groups) {
    for (const frames of groups.values()) for (const f of frames) if (f) f.bitmap.close();
  }

  // A new fill (or the first): new steps, new captions, new groups.
  async function reset(o) {
    stop();
    s.gen = o.gen ?? s.gen + 1;
    if (s.fill) {
      s.cache.delete(s.fill);
      s.cache.set(s.fill, s.groups);
      if (s.cache.size > CACHED_FILLS) {
        const oldest = s.cache.keys().next().value;
        if (oldest !== (o.fill ?? "")) {
          release(s.cache.get(oldest));
          s.cache.delete(oldest);
        }
      }
    } else if (s.groups) {
      release(s.groups);
    }
    s.fill = o.fill ?? "";
    s.groups = (s.fill && s.cache.get(s.fill)) || new Map();
    canvas.dataset.groups = String(s.groups.size);
    s.asked.clear();
    s.inflight = null;
    s.waitingSince = null; // a new fill: nothing awaited yet, no advice from the last one
    note();
    s.priority = undefined;
    s.n = o.n;
    s.key = o.key;
    s.captions = o.captions;
    s.infos = o.infos;
    s.shown = -1;
    slider.max = String(o.n - 1);
    canvas.width = o.width;
    canvas.height = o.height;
    canvas.style.width = `${o.width}px`;
    canvas.setAttribute("aria-label", o.alt ?? "the fill, step by step");
    s.want = Math.max(0, Math.min(o.n - 1, o.step));
    slider.value = String(s.want);
    if (s.groups.has(Math.floor(s.want / s.key))) {
      draw(s.want); // a fill shown before: its frames are here, decoded
    } else if (o.poster && o.poster.byteLength) {
      const step = s.want, gen = s.gen; // the poster's: a key may move s.want while it decodes
      const bitmap = await decodePng(o.poster);
      if (gen !== s.gen) {
        bitmap?.close(); // a newer fill came meanwhile
        return;
      }
      if (bitmap !== null) ctx.drawImage(bitmap, 0, 0);
      bitmap?.close();
      s.shown = step;
      canvas.dataset.step = String(step);
      canvas.dataset.gen = String(s.gen);
      label(step);
      if (s.want === step) waiting(null);
      else waiting(s.want);
    } else {
      waiting(s.want); // nothing to show until its group comes
    }
    for (const [g, group] of o.groups ?? []) {
      await addGroup(g, group.places, group.blobs, s.gen);
    }
    if (s.shown !== s.want) {
      if (!draw(s.want)) waiting(s.want);
    } else {
      need(nextMissing() ?? Math.floor(s.want / s.key)); // the rest of a fill seen in part
    }
  }

  // New texts for the same steps (the last caption's hint follows the comparison opening
  // and closing): the step on show, or the one awaited, relabelled at once.
  function recaption(captions) {
    s.captions = captions;
    const k = s.awaited ?? s.shown;
    if (k !== null && k >= 0) label(k);
  }

  function setInterval_(ms) {
    s.interval = ms;
    speed.choose(ms);
    root.dataset.interval = String(ms); // for tests and benchmarks
    if (s.timer !== null) {
      clearInterval(s.timer);
      s.timer = setInterval(tick, ms);
    }
  }

  speed.select.addEventListener("change", () => {
    const ms = Number(speed.select.value);
    setInterval_(ms);
    if (opts.onInterval) opts.onInterval(ms);
  });
  setInterval_(opts.interval ?? 400);
  return {
    root, reset, addGroup, show, stop, start, recaption, setInterval: setInterval_, state: s,
  };
}

// -- an offline page: every group is in the page as base64 PNGs ----------------------------
export async function mountStatic(el, data) {
  const player = mountFrames(el, { interval: data.interval });
  const groups = data.groups.map((g, i) => [
    i, { places: g.places, blobs: g.pngs.map((b) => (b ? b64Bytes(b) : null)) },
  ]);
  await player.reset({ ...data, groups, gen: 0 });
  return player;
}

// -- the anywidget side ---------------------------------------------------------------------
function render({ model, el }) {
  // set when the view is removed (its notebook closed, its kernel shut down): a retry timer
  // still pending must not send (the comm throws "Cannot send" into the page)
  let gone = false;
  const player = mountFrames(el, {
    interval: model.get("interval"),
    request: (g, gen) => gone || model.send({ type: "group", group: g, gen }),
    onStep: (k) => {
      if (model.get("value") !== k) {
        model.set("value", k);
        model.save_changes();
      }
    },
    onInterval: (ms) => {
      model.set("interval", ms); // the kernel's player.interval follows the menu
      model.save_changes();
    },
  });
  function fromModel() {
    const poster = model.get("poster");
    player.reset({
      width: model.get("frame_width"), height: model.get("frame_height"),
      n: model.get("n_steps"), key: model.get("key"), step: model.get("value"),
      captions: model.get("captions"), infos: model.get("infos"), gen: model.get("gen"),
      alt: model.get("alt"), fill: model.get("fill"),
      poster: poster ? asBytes(poster) : null, // page.js
    });
  }
  model.on("change:gen", fromModel);
  model.on("change:value", () => {
    const k = model.get("value");
    if (k !== player.state.want) {
      player.stop();
      player.show(k);
    }
  });
  model.on("change:interval", () => player.setInterval(model.get("interval")));
  // the same fill, new texts (a new fill comes with change:gen, which resets everything)
  model.on("change:captions", () => player.recaption(model.get("captions")));
  model.on("msg:custom", (msg, buffers) => {
    if (msg.type !== "group") return;
    const wrong = groupMismatch(msg, buffers);
    if (wrong) {
      console.warn(`teachraster: ${wrong}`); // not kept: the group is asked for again
      return;
    }
    player.addGroup(msg.group, msg.places, buffers.map(asBytes), msg.gen); // page.js
  });
  fromModel();
  return () => {
    gone = true;
    player.stop();
    player.state.waitingSince = null; // a pending look stops, saying nothing
  };
}

export default { render };
