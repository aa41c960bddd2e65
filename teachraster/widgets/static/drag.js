// teachraster: drag the points of a kernel-drawn figure, in the page.
//
// The figure is an <img>; a canvas over it draws the pointer feedback (a ring where the
// pointer holds a point) at once. Positions go to the kernel as custom messages with their
// own flow control: at most IN_FLIGHT unanswered (one being rendered, one waiting, so the
// kernel never idles for a round trip), each the latest position when sent; positions that
// come meanwhile replace each other, so the kernel never works through a queue. The release
// is always sent, so the drag ends exactly where the pointer let go. Each answer carries
// the new picture: during a drag only the rectangle that changed (a patch of raw RGBA
// pixels, painted on a canvas over the <img>), at the release the whole figure (a PNG).

const IN_FLIGHT = 2;

// Reference mode (the slider explorers): every picture is the reference picture with one
// patch painted over it, so pictures drawn ahead (kept per figure "key", below) can be shown
// in any order: the page's slider asks the store of its figure (slider.js) and shows a
// position it has a picture for without asking the kernel. Where those pictures are the full
// ones (FilterExplorer), the slider's final value says which it shows (store.holding) and
// the kernel, when no picture of its own is on the way, sends none.
const INFLATED = 8; // pictures drawn ahead kept inflated (a slider dragged back and forth)

function stores() {
  globalThis.__teachrasterAhead = globalThis.__teachrasterAhead || new Map();
  return globalThis.__teachrasterAhead;
}

// A picture drawn ahead of slider i is good while its generation is at least the store's
// floor, or, for the slider moved last (exempt: it alone moved, its pictures stay good), the
// floor its own pictures had then (ahead.py: FramesAhead.valid_from, the same rule).
function validFrom(store, i) {
  return store.exempt && store.exempt.slider === i ? store.exempt.floor : store.floor;
}
const good = (store, e) => e.generation >= validFrom(store, e.slider);
const entryKey = (i, k) => `${i}/${k}`;

function storeFor(key) {
  const all = stores();
  if (!all.has(key)) {
    all.set(key, { entries: new Map(), floor: 0, exempt: null, views: new Set(),
      raw: new Map(), want: null, busy: false, show: null, frames: 0, current: null,
      lastN: 0 });
    const store = all.get(key);
    // show the picture drawn ahead for position k of slider i (its index among the
    // sliders linked to this figure) in every view; false when there is none
    store.show = (i, k) => {
      const e = store.entries.get(entryKey(i, k));
      if (!e || !good(store, e)) return false;
      if (![...store.views].some((v) => v.canPaint(e))) return false;
      store.want = store.current = { e, frames: store.frames };
      if (!store.busy) drain(store);
      return true;
    };
    // what a slider's final value says when the page shows position k of slider i from
    // this store (painted, or painted once inflated), no picture from the kernel having come
    // since it was asked for: its position, the picture's generation and reference, and the
    // last frame the page had from the kernel; null otherwise. The kernel sends no picture
    // when that frame is its last (ahead.py: FramesAhead.held).
    store.holding = (i, k) => {
      const c = store.current;
      if (!c || c.e.slider !== i || c.e.k !== k || !good(store, c.e) ||
          c.frames !== store.frames) return null;
      return { k, generation: c.e.generation, ref: c.e.ref, n: store.lastN, slider: i };
    };
    // another control changed the picture (keep: null), or slider keep moved: the pictures
    // of the others are stale
    store.clear = (generation, keep) => {
      const since = keep === null || keep === undefined ? null : validFrom(store, keep);
      store.floor = generation;
      store.exempt = since === null ? null : { slider: keep, floor: since };
      for (const [k, e] of store.entries) {
        if (!good(store, e)) {
          store.entries.delete(k);
          store.raw.delete(k);
        }
      }
      if (store.current && !good(store, store.current.e)) store.want = store.current = null;
      if (store.want && !good(store, store.want.e)) store.want = null;
    };
  }
  return all.get(key);
}

// paint the latest picture asked for (coalesced: pictures asked for meanwhile are skipped)
async function drain(store) {
  store.busy = true;
  try {
    while (store.want) {
      const { e, frames } = store.want;
      store.want = null;
      const key = entryKey(e.slider, e.k);
      let raw = store.raw.get(key);
      if (!raw) {
        raw = e.bytes.byteLength && e.deflate ? await inflate(e.bytes) : e.bytes;
        store.raw.set(key, raw);
        if (store.raw.size > INFLATED) store.raw.delete(store.raw.keys().next().value);
      }
      // painted only if still current after the wait (inflate): no picture from the kernel
      // came meanwhile (it shows newer controls: a filter changed, a final render) and no
      // other control dropped the pictures drawn ahead. Painted regardless, a keyed run of
      // tilts then a filter left nearest's draft over bilinear's full picture for good.
      if (frames !== store.frames || !good(store, e)) {
        for (const v of store.views) v.skippedAhead(); // counted, for tests and benchmarks
        continue;
      }
      for (const v of store.views) if (v.canPaint(e)) v.paintAhead(e, raw);
    }
  } finally {
    store.busy = false;
  }
}

// Once per model: keep the pictures drawn ahead, then tell the kernel the page listens.
function initialize({ model }) {
  const key = model.get("key");
  if (!key) return;
  const store = storeFor(key);
  store.lastN = Math.max(store.lastN, model.get("poster_frame"));
  model.on("msg:custom", (msg, buffers) => {
    if (msg.type === "frame") {
      store.frames += 1; // a picture drawn ahead asked for before is stale
      store.lastN = msg.n;
      return;
    }
    if (msg.type === "ahead-clear") {
      store.clear(msg.generation, msg.keep);
    } else if (msg.type === "ahead") {
      if (buffers.length !== msg.entries.length) {
        // one patch (or empty bytes) per entry, always: a mismatch is a bug to hear of
        console.warn(`teachraster: ${buffers.length} pictures drawn ahead came for ` +
          `${msg.entries.length} positions`);
        return;
      }
      msg.entries.forEach((e, i) => {
        const entry = { ...e, slider: e.slider || 0, generation: msg.generation, ref: msg.ref,
          bytes: buffers[i] };
        // a batch sent before a clear that made it stale: dropped
        if (good(store, entry)) store.entries.set(entryKey(entry.slider, e.k), entry);
      });
    } else {
      return;
    }
    for (const v of store.views) v.showAheadCount(store.entries.size);
  });
  model.send({ type: "ready" });
}

const CSS = `
.tr-drag { position: relative; display: inline-block; max-width: 100%; touch-action: none; }
.tr-drag img { display: block; max-width: 100%; height: auto; user-select: none; }
.tr-drag canvas.tr-drag-picture { pointer-events: none; }
.tr-drag canvas { position: absolute; left: 0; top: 0; width: 100%; height: 100%;
  pointer-events: none; }
.tr-drag-notice { color: #b00020; font-size: 13px; }
.tr-drag-caption { font-size: var(--jp-widgets-font-size, 13px); line-height: 1.5;
  margin: 2px 0 6px; }
/* the text goes under the picture when the column has no room for both (1024x768 with the
   file browser open, 150 % zoom): shrunk to share the row, the picture was 148 px wide */
.tr-drag-row { display: flex; flex-wrap: wrap; align-items: flex-start; gap: 4px; }
.tr-drag-row .tr-drag { flex: 1 1 300px; min-width: min(300px, 100%); max-width: max-content; }
.tr-drag-row .tr-drag-caption { flex: 0 1 auto; max-width: 440px; }
`;

// A zlib-compressed patch (the slider explorers: megabytes of changed pixels a frame
// otherwise), inflated natively: no image decoder to wait for. Read through a Response
// over the bytes, not a Blob: a Blob goes through the browser process's blob registry
// (a round trip between processes, 250 ms of a vertex drag's first frame at load 14); in
// the renderer alone, 36 kB into 467 kB took 1.4 ms against the Blob's 2.5 (medians).
async function inflate(bytes) {
  const stream = new Response(bytes).body.pipeThrough(new DecompressionStream("deflate"));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

function render({ model, el }) {
  installKeyGuard(); // keys.js: keys on the controls beside it are theirs in Notebook 7 too
  addCss("tr-drag-css", CSS); // page.js
  const box = document.createElement("div");
  box.className = "tr-drag";
  const img = document.createElement("img");
  img.className = "teachraster-figure";
  img.draggable = false;
  const picture = document.createElement("canvas"); // the patches of a drag, over the <img>
  picture.className = "tr-drag-picture";
  const overlay = document.createElement("canvas");
  const notice = document.createElement("div");
  notice.className = "tr-drag-notice";
  const caption = document.createElement("div"); // a line of text above the picture
  caption.className = "tr-drag-caption";
  box.append(img, picture, overlay);
  if (model.get("caption_side") === "right") {
    const row = document.createElement("div"); // the picture, its text beside it
    row.className = "tr-drag-row";
    row.append(box, caption);
    el.append(row, notice);
  } else {
    el.append(caption, box, notice);
  }
  // the same text again changes nothing: no new layout (a drag's frame and the trait of its
  // release both bring the caption; a layout of a table beside the picture per frame)
  let captionShown = null;
  function setCaption(html) {
    if ((html || "") === captionShown) return;
    captionShown = html || "";
    caption.innerHTML = captionShown;
    caption.style.display = captionShown ? "" : "none";
  }
  setCaption(model.get("caption"));
  model.on("change:caption", () => setCaption(model.get("caption")));
  const ctx = overlay.getContext("2d");
  const pctx = picture.getContext("2d");
  // the number of the frame on show, and the queue that paints frames in order
  let shown = model.get("poster_frame");
  let painting = Promise.resolve();
  let missed = false; // a patch came for a frame this view does not show
  // The canvas holds a whole picture, not patches alone over the <img>. A patch is painted
  // on a whole picture only: on a clear canvas, a view scaled down to its column blended
  // each patch's edge pixels with the transparent ones beside them, and the <img> under
  // them (an older picture) showed through there: faint ghosts of the old tick labels
  // along a patch's edge (review r219 04-2, the TexturedPlaneViewer's profile).
  let whole = false;
  function sizePicture() {
    const [w, h] = model.get("size");
    if (picture.width !== w || picture.height !== h) {
      [picture.width, picture.height] = [w, h]; // which clears the canvas
      whole = false;
    }
  }
  // the picture the <img> shows, drawn on the canvas before a patch goes on it
  async function wholeFromImg() {
    if (whole) return;
    try {
      await img.decode();
    } catch {
      return; // nothing shown yet: the patch goes on a clear canvas, as before
    }
    pctx.drawImage(img, 0, 0, picture.width, picture.height);
    whole = true;
  }
  sizePicture();

  let url = null;
  function showPng(bytes) {
    const next = URL.createObjectURL(new Blob([bytes], { type: "image/png" }));
    img.src = next;
    if (url) URL.revokeObjectURL(url);
    url = next;
  }

  // figure pixels <-> data, and the pointer in figure pixels
  const toPx = ([x, y]) => {
    const [x0, y0, sx, sy] = model.get("transform");
    return [x0 + sx * x, y0 + sy * y];
  };
  const toData = ([px, py]) => {
    const [x0, y0, sx, sy] = model.get("transform");
    return [(px - x0) / sx, (py - y0) / sy];
  };
  function pointer(e) {
    const r = img.getBoundingClientRect();
    const [w, h] = model.get("size");
    return [((e.clientX - r.left) * w) / r.width, ((e.clientY - r.top) * h) / r.height];
  }

  // pending: seq -> time sent, of the positions not answered yet
  const s = { dragging: null, latest: null, sent: null, pending: new Map(), seq: 0 };
  // this view's name in its positions: the kernel numbers each view's drags apart (a
  // position that reaches it after its drag's release is dropped, dragging.py)
  const viewId = Math.random().toString(36).slice(2);
  // the first frame of a drag, timed (for benchmarks: data-first-frame on the <img>):
  // press -> position sent -> answer received -> picture decoded -> painted, in ms
  let first = null;

  function feedback(px) {
    const [w, h] = model.get("size");
    // resized only when the figure is (setting a canvas' size reallocates it: at every
    // pointer move, work the page can do without)
    if (overlay.width !== w || overlay.height !== h) [overlay.width, overlay.height] = [w, h];
    ctx.clearRect(0, 0, w, h);
    if (px) {
      ctx.lineWidth = 3;
      ctx.strokeStyle = "rgba(213, 94, 0, 0.9)";
      ctx.beginPath();
      ctx.arc(px[0], px[1], 9, 0, 2 * Math.PI);
      ctx.stroke();
    }
  }

  function send(final) {
    const [x, y] = s.latest;
    s.seq += 1;
    s.sent = s.latest;
    if (!final) {
      s.pending.set(s.seq, performance.now());
      setTimeout(() => checkAlive(s.seq), 6000);
    }
    if (first && first.seq === undefined) [first.seq, first.sent] = [s.seq, performance.now()];
    model.send({ type: "move", i: s.dragging, x, y, seq: s.seq, final, view: viewId });
  }

  function pump() {
    if (s.dragging !== null && s.latest && s.pending.size < IN_FLIGHT && s.latest !== s.sent) {
      send(false);
    }
  }

  function checkAlive(seq) {
    if (s.pending.has(seq)) {
      notice.textContent =
        "The kernel does not answer (stopped or restarted?): Run All (Run \u25b8 Run All Cells) " +
        "to bring the editor back.";
    }
  }

  img.addEventListener("pointerdown", (e) => {
    if (e.button !== 0) return;
    const p = pointer(e);
    const r = img.getBoundingClientRect();
    const scale = model.get("size")[0] / r.width; // figure pixels per CSS pixel
    let best = null;
    let bestD = 16 * scale; // within 16 CSS pixels of a point
    model.get("handles").forEach((h, i) => {
      const [hx, hy] = toPx(h);
      const d = Math.hypot(hx - p[0], hy - p[1]);
      if (d <= bestD) [best, bestD] = [i, d];
    });
    if (best === null) return;
    first = { down: performance.now() };
    e.preventDefault();
    img.setPointerCapture(e.pointerId);
    s.dragging = best;
    s.latest = toData(p);
    feedback(p);
    pump();
  });
  img.addEventListener("pointermove", (e) => {
    if (s.dragging === null) return;
    const p = pointer(e);
    s.latest = toData(p);
    feedback(p);
    pump();
  });
  function release(e) {
    if (s.dragging === null) return;
    s.latest = toData(pointer(e));
    send(true);
    s.dragging = null;
    feedback(null);
  }
  img.addEventListener("pointerup", release);
  img.addEventListener("pointercancel", release);

  // Reference mode: the reference picture (as a bitmap, to put back where the last patch
  // was), its frame number and the rectangle painted over it.
  const ref = { bitmap: null, frame: 0, dirty: null, asked: 0 };
  function askRef() {
    const frame = model.get("ref_frame");
    if (ref.asked === frame) return; // asked once for this reference
    ref.asked = frame;
    model.send({ type: "ref", ref: frame });
  }
  // rectangle a = [x, y, w, h] lies within b
  const within = (a, b) =>
    a[0] >= b[0] && a[1] >= b[1] && a[0] + a[2] <= b[0] + b[2] && a[1] + a[3] <= b[1] + b[3];
  function putPatch(place, raw) {
    const painted = raw && raw.byteLength;
    if (!whole) {
      // the reference under the first patch (the <img> shows it: the poster was the
      // reference), so that no patch lies on a clear canvas (see ``whole``)
      pctx.drawImage(ref.bitmap, 0, 0);
      whole = true;
      ref.dirty = null;
    }
    if (ref.dirty && !(painted && within(ref.dirty, place))) {
      // the reference, put back (not where the new patch paints over it all: a drag's
      // patches cover the same plot, and drawing it back first was a second full blit)
      const [x, y, w, h] = ref.dirty;
      pctx.drawImage(ref.bitmap, x, y, w, h, x, y, w, h);
    }
    ref.dirty = null;
    if (!painted) return;
    const [x, y, w, h] = place;
    const buf = raw instanceof ArrayBuffer ? raw : raw.buffer;
    pctx.putImageData(new ImageData(new Uint8ClampedArray(buf, raw.byteOffset || 0, 4 * w * h),
      w, h), x, y);
    ref.dirty = place;
  }
  function counted() {
    img.dataset.frames = String(Number(img.dataset.frames || 0) + 1);
  }
  // where a drag's first picture's time went (benchmarks), once its patch is painted
  function noteFirst(msg, bytes, decoded) {
    if (!first || first.seq !== msg.seq || first.decoded !== undefined) return;
    first.decoded = decoded;
    first.painted = performance.now();
    const t = (k) => Math.round((first[k] - first.down) * 10) / 10;
    img.dataset.firstFrame = JSON.stringify({ sent: t("sent"), reply: t("reply"),
      decoded: t("decoded"), painted: t("painted"), bytes: bytes.byteLength,
      kernel: msg.timing || null });
  }
  async function paintRef(msg, bytes) {
    if (msg.place === null) {
      sizePicture();
      const bitmap = await decodePng(bytes);
      if (bitmap === null) {
        askRef(); // not decoded (page.js warns): a new reference is asked for
        return;
      }
      pctx.clearRect(0, 0, picture.width, picture.height);
      pctx.drawImage(bitmap, 0, 0);
      whole = true;
      if (ref.bitmap) ref.bitmap.close();
      Object.assign(ref, { bitmap, frame: msg.ref, dirty: null });
      showPng(bytes);
    } else if (ref.bitmap && msg.ref === ref.frame) {
      const raw = msg.deflate ? await inflate(bytes) : bytes;
      const decoded = performance.now();
      putPatch(msg.place, raw);
      noteFirst(msg, bytes, decoded);
    } else {
      askRef(); // a view opened after the reference was sent: it asks for a new one
      return;
    }
    if (msg.caption !== undefined) setCaption(msg.caption);
    counted();
  }
  const view = {
    canPaint: (e) => ref.bitmap !== null && e.ref === ref.frame,
    // how many pictures drawn ahead the page keeps (for tests and benchmarks)
    showAheadCount: (n) => (img.dataset.ahead = String(n)),
    // after the kernel's pictures already on their way (one chain): a draft answered late,
    // for a position the slider has left, is painted first and then covered by the picture
    // of the position the slider holds now (slider.js shows it again at that answer)
    paintAhead(e, raw) {
      painting = painting.then(() => {
        putPatch(e.place, raw);
        setCaption(e.caption);
        counted();
      });
    },
    // a picture drawn ahead left unpainted (the kernel's newer one came first): a key then
    // brings one picture, not two (data-frames + data-skipped counts both ways)
    skippedAhead: () => (img.dataset.skipped = String(Number(img.dataset.skipped || 0) + 1)),
  };
  const key = model.get("key");
  if (key) storeFor(key).views.add(view);
  const poster0 = model.get("poster");
  if (model.get("ref_frame") && poster0 && poster0.byteLength) {
    if (model.get("poster_frame") === model.get("ref_frame")) {
      // the poster is the reference: kept as a bitmap to put back from
      const frame = model.get("ref_frame");
      painting = painting.then(async () => {
        const bitmap = await decodePng(poster0);
        if (bitmap === null) askRef(); // not decoded (page.js warns): ask for a reference
        else if (ref.bitmap === null) Object.assign(ref, { bitmap, frame });
        else bitmap.close();
      });
    } else {
      askRef();
    }
  }

  // A whole frame replaces the picture; a patch (the pixels a move changed) is painted at
  // its place, only on the frame it was made against (a view that missed one waits for
  // the next whole frame).
  async function paint(msg, bytes) {
    if (msg.ref !== undefined && msg.ref !== null) return paintRef(msg, bytes);
    if (msg.place === null) {
      sizePicture();
      const bitmap = await decodePng(bytes);
      if (bitmap === null) {
        missed = true; // not decoded (page.js warns): the next whole picture or poster
        return;
      }
      pctx.clearRect(0, 0, picture.width, picture.height);
      pctx.drawImage(bitmap, 0, 0);
      whole = true;
      bitmap.close();
      showPng(bytes); // the <img> under the canvas holds the last whole frame
      missed = false;
    } else if (msg.n - 1 === shown && bytes.byteLength) {
      // raw RGBA: painted at once, no decode (a PNG's waits for a thread on a busy machine)
      const [x, y, w, h] = msg.place;
      const raw = msg.deflate ? await inflate(bytes) : bytes;
      const buf = raw instanceof ArrayBuffer ? raw : raw.buffer;
      const data = new Uint8ClampedArray(buf, raw.byteOffset || 0, 4 * w * h);
      const decoded = performance.now();
      await wholeFromImg();
      pctx.putImageData(new ImageData(data, w, h), x, y);
      noteFirst(msg, bytes, decoded);
    } else if (msg.n - 1 !== shown) {
      missed = true; // a view opened meanwhile: it waits for a whole picture (or a poster)
      return;
    }
    shown = msg.n;
    img.dataset.frames = String(Number(img.dataset.frames || 0) + 1);
  }

  model.on("msg:custom", (msg, buffers) => {
    if (msg.type !== "frame") return;
    if (buffers.length !== 1) {
      console.warn(`teachraster: a picture came in ${buffers.length} buffers, not one`);
      return;
    }
    const bytes = buffers[0];
    if (first && first.seq === msg.seq && first.reply === undefined) first.reply = performance.now();
    painting = painting.then(() => paint(msg, bytes)).catch(() => {});
    notice.textContent = "";
    img.dataset.kernelMs = String(Math.round(msg.kernel_ms ?? 0)); // for benchmarks
    const sent = s.pending.get(msg.seq);
    if (sent) img.dataset.roundTripMs = String(Math.round(performance.now() - sent));
    for (const seq of [...s.pending.keys()]) if (seq <= msg.seq) s.pending.delete(seq);
    pump();
  });
  // A widget that sends its final pictures as patches too (the slider explorers) keeps
  // each as the poster after it: a view that missed a patch catches up there.
  model.on("change:poster", () => {
    painting = painting.then(() => {
      if (!missed || model.get("poster_frame") <= shown) return;
      missed = false;
      sizePicture();
      pctx.clearRect(0, 0, picture.width, picture.height);
      whole = false;
      showPng(model.get("poster"));
      shown = model.get("poster_frame");
    });
  });
  const poster = model.get("poster");
  if (poster && poster.byteLength) showPng(poster);
  img.alt = model.get("alt");
  return () => {
    if (url) URL.revokeObjectURL(url);
    if (key) storeFor(key).views.delete(view);
    if (ref.bitmap) ref.bitmap.close();
  };
}

export default { initialize, render };
