// ---- page.js: what every page-side module of the package shares besides its keys (keys.js).
// Prepended with keys.js (plotting/frames.py: keys_js), so a module's parts share one scope.

// CSS once per document, by id: the first view of a module on the page adds its stylesheet,
// later views (and the other cells' views) find it there.
export function addCss(id, text) {
  if (typeof document === "undefined" || document.getElementById(id)) return;
  const style = document.createElement("style");
  style.id = id;
  style.textContent = text;
  document.head.appendChild(style);
}
