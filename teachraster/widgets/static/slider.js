// teachraster: a slider in the page whose values reach the kernel coalesced.
//
// Values go to the kernel as custom messages with their own flow control: at most
// IN_FLIGHT unanswered (one being rendered, one waiting, so the kernel never idles for a
// round trip), each the latest value when sent; values that come meanwhile replace each
// other, so the kernel never works through a queue. The value where the slider is released
// is always sent. The readout follows the pointer at once. Final values (a key, a click on
// the track, a release) obey the same limit: one that comes while IN_FLIGHT are unanswered
// waits, replacing the one waiting before it, so an arrow key held down renders the newest
// position when the kernel is free, not every step it passed.
//
// A slider linked to a figure that keeps pictures drawn ahead (drag.js: the figure's store,
// by its "key") shows a position with a picture by itself and does not ask the kernel; the
// kernel hears of the value where the slider is released (the full picture follows; where
// the picture drawn ahead is the full one, the final value says the page shows it, "held",
// and the kernel sends none).

const IN_FLIGHT = 2;

function format(v, spec) {
  const m = /^\.(\d+)([fg])$/.exec(spec || "");
  if (!m) return String(v);
  return m[2] === "f" ? v.toFixed(Number(m[1])) : String(Number(v.toPrecision(Number(m[1]))));
}

function render({ model, el }) {
  installKeyGuard(); // keys.js: the arrow keys move this slider in Notebook 7 too
  const row = document.createElement("div");
  row.className = "tr-live-slider";
  row.style.cssText = "display:flex;align-items:center;gap:8px;margin:2px 0;";
  const label = document.createElement("label");
  label.style.cssText = "min-width:5em;text-align:right;";
  const input = document.createElement("input");
  input.type = "range";
  input.style.cssText = "flex:1;min-width:120px;";
  const readout = document.createElement("span");
  readout.style.cssText = "min-width:4em;font-variant-numeric:tabular-nums;";
  const notice = document.createElement("div");
  notice.style.cssText = "color:#b00020;font-size:13px;";
  row.append(label, input, readout);
  el.append(row, notice);

  const base = () => model.get("base");
  const toValue = (p) => (base() > 0 ? Math.pow(base(), p) : p);
  const toPos = (v) => (base() > 0 ? Math.log(v) / Math.log(base()) : v);
  const s = { pending: new Set(), seq: 0, latest: null, sent: null, held: false,
    drafted: false, ahead: false, shownAhead: null, finalWaiting: false };

  // the picture drawn ahead for the slider's position, shown; false when there is none
  function showAhead() {
    const [figure, i] = (model.get("link") || "").split("/"); // the figure's key, our index
    const store = figure && globalThis.__teachrasterAhead && globalThis.__teachrasterAhead.get(figure);
    if (!store) return false;
    const k = Math.round((Number(input.value) - Number(input.min)) / Number(input.step));
    return store.show(Number(i || 0), k);
  }

  // what the page shows by itself at the slider's position, for a final value (drag.js:
  // store.holding): null when it is not a picture drawn ahead
  function heldAhead() {
    const [figure, i] = (model.get("link") || "").split("/");
    const all = globalThis.__teachrasterAhead;
    const store = figure && all && all.get(figure);
    if (!store || !store.holding) return null;
    const k = Math.round((Number(input.value) - Number(input.min)) / Number(input.step));
    return store.holding(Number(i || 0), k);
  }

  function show(v) {
    readout.textContent = format(v, model.get("readout_format"));
  }
  function sync() {
    label.textContent = model.get("description");
    input.setAttribute("aria-label", model.get("description"));
    input.min = model.get("min");
    input.max = model.get("max");
    input.step = model.get("step");
    // while values are on their way (held, unanswered, or a final one waiting) the kernel's
    // value is an older one: the handle and the readout stay where the student put them (a
    // held arrow key's readout ran backwards, 55 -> 33, as the kernel's answers came in)
    const busy = s.held || s.pending.size > 0 || s.finalWaiting;
    if (!busy) input.value = toPos(model.get("value"));
    show(busy ? toValue(Number(input.value)) : model.get("value"));
  }
  function send(value, final) {
    s.seq += 1;
    s.sent = value;
    s.pending.add(s.seq);
    const seq = s.seq;
    setTimeout(() => {
      if (s.pending.has(seq)) {
        notice.textContent =
          "The kernel does not answer (stopped or restarted?): Run All (Run \u25b8 Run All Cells) " +
          "to bring the widget back.";
      }
    }, 20000); // far beyond any render: the kernel is gone, not slow
    const held = final ? heldAhead() : null;
    model.send(held ? { type: "value", value, seq, final, held }
      : { type: "value", value, seq, final });
  }
  // a final value: sent now if fewer than IN_FLIGHT are unanswered, else when an answer
  // comes (the newest then, the ones between dropped)
  function sendFinal() {
    s.finalWaiting = s.pending.size >= IN_FLIGHT;
    if (!s.finalWaiting) send(s.latest, true);
  }
  function pump() {
    if (s.finalWaiting) return; // the final value waiting goes first, as final
    if (s.latest !== null && s.latest !== s.sent && s.latest !== s.shownAhead &&
        s.pending.size < IN_FLIGHT) {
      send(s.latest, false); // a draft: the pointer still holds the slider
      s.drafted = true;
    }
  }
  // the kernel hears that this slider is about to move (pictures drawn ahead: the
  // positions of the slider moved last; telling it at the press starts them sooner)
  function touch() {
    if (s.touched || !model.get("link")) return;
    s.touched = true;
    model.send({ type: "touch" });
  }
  input.addEventListener("focus", touch);
  input.addEventListener("blur", () => (s.touched = false));
  input.addEventListener("pointerdown", () => {
    s.held = true;
    touch();
  });
  input.addEventListener("input", () => {
    s.latest = toValue(Number(input.value));
    show(s.latest);
    // shown in the page: the kernel hears of it at the release
    if (showAhead()) [s.ahead, s.shownAhead] = [true, s.latest];
    else if (s.held) pump();
    // a key (or a click on the track) is followed by its "change" at once: sent from there
    // as final, not first as a draft
    else setTimeout(pump, 0);
  });
  input.addEventListener("change", () => {
    s.held = false;
    s.latest = toValue(Number(input.value));
    // the release, marked final: the kernel shows the full picture (also when this value
    // was sent already as a draft)
    if (s.latest !== s.sent || s.drafted || s.ahead) sendFinal();
    else s.finalWaiting = false; // back at the value sent last: nothing to wait for
    s.drafted = false;
    s.ahead = false;
    s.shownAhead = null;
  });
  // arrow keys move the slider, not JupyterLab's notebook (command-mode shortcuts)
  input.addEventListener("keydown", (e) => e.stopPropagation());
  model.on("msg:custom", (msg) => {
    if (msg.type !== "done") return;
    s.pending.delete(msg.seq);
    // the kernel's time per value, where a benchmark can read it
    (input.kernelMs = input.kernelMs || []).push(msg.kernel_ms);
    notice.textContent = "";
    // a draft answered after the slider moved on to a position with a picture drawn ahead:
    // that picture (and its caption) again, over the draft's older one, so that the picture
    // and its numbers follow the readout during a drag (review r233 09 W1)
    if (s.held && s.shownAhead !== null && s.shownAhead === s.latest) showAhead();
    if (s.finalWaiting) sendFinal();
    else pump();
  });
  for (const name of ["value", "min", "max", "step", "description", "readout_format"]) {
    model.on(`change:${name}`, sync);
  }
  sync();
}

export default { render };
