// ---- keys.js: keys pressed in a widget are the widget's, in JupyterLab and Notebook 7.
//
// Jupyter's command mode takes single keys: an arrow or Enter moves to another cell or edits
// it. JupyterLab dispatches its shortcuts from the keydown's bubbling phase, so a widget that
// stops the event keeps its keys; Notebook 7 dispatches them earlier (the capture phase), so
// its shortcut runs first, cancels the key (the slider does not move) and the view jumps to
// another cell. Both look the key up with Lumino, which skips any element marked
// `data-lm-suppress-shortcuts`. A listener on the window's capture phase runs before both:
// - a key inside an explorable (`.tr-x`) goes to the element's own handler (set with onKeys)
//   and no further (a native control still takes its default action);
// - a key that moves or presses a control (arrows, Home/End, Page Up/Down, space, Enter)
//   inside any widget (ours, or ipywidgets' own sliders and menus) marks its target for the
//   time of this one event, so the notebook's shortcuts skip it and the control gets it.
// Escape, Tab, Shift+Enter and the keys with Ctrl, Alt or Meta stay the notebook's.
// Every teachraster module carries this file (prepended by the package), and the first one
// on the page installs the listener.

const CONTROL_KEYS = new Set([
  "ArrowLeft", "ArrowRight", "ArrowUp", "ArrowDown", "Home", "End", "PageUp", "PageDown",
  " ", "Enter",
]);
const WIDGET = ".tr-x, .tr-frames, .tr-live-slider, .tr-drag, .jupyter-widgets, .widget-box";

export function installKeyGuard() {
  if (typeof window === "undefined" || window.__trKeyGuard) return;
  window.__trKeyGuard = true;
  window.addEventListener("keydown", (e) => {
    const t = e.target;
    if (!(t instanceof Element) || !t.closest(WIDGET)) return;
    if (e.key === "Escape" || e.key === "Tab" || (e.key === "Enter" && e.shiftKey)) return;
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    if (t.closest(".tr-x")) {
      if (t.__trKeydown) t.__trKeydown(e);
      e.stopPropagation();
      return;
    }
    if (!CONTROL_KEYS.has(e.key) || t.hasAttribute("data-lm-suppress-shortcuts")) return;
    t.setAttribute("data-lm-suppress-shortcuts", "true");
    setTimeout(() => t.removeAttribute("data-lm-suppress-shortcuts"), 0); // after this event
  }, true);
}

// `handler(event)` for the keys pressed on `el` (see installKeyGuard)
export function onKeys(el, handler) {
  installKeyGuard();
  el.__trKeydown = handler;
}
