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

// PNG bytes to an ImageBitmap, or null. On a busy machine Chromium's createImageBitmap
// sometimes rejects good bytes ("The source image could not be decoded.", seen in loaded CI
// runs, the same bytes decoding on the next try), so it is tried again after a pause, then
// through an <img>. Bytes that fail all three ways give null and a console warning with what
// they were: the caller keeps its picture and asks for a whole one, never an uncaught error.
export async function decodePng(bytes) {
  const blob = new Blob([bytes], { type: "image/png" });
  for (const pause of [0, 50, 250]) {
    if (pause) await new Promise((done) => setTimeout(done, pause));
    try {
      return await createImageBitmap(blob);
    } catch (error) {
      if (typeof Image === "undefined") throw error;
    }
  }
  const url = URL.createObjectURL(blob);
  try {
    const img = new Image();
    img.src = url;
    await img.decode();
    return await createImageBitmap(img);
  } catch (error) {
    const view = new Uint8Array(bytes.buffer ?? bytes, bytes.byteOffset ?? 0, bytes.byteLength);
    const head = Array.from(view.slice(0, 8), (b) => b.toString(16).padStart(2, "0")).join(" ");
    console.warn(`teachraster: a picture could not be decoded (${bytes.byteLength} bytes, ` +
      `starting ${head}): ${error.message}`);
    return null;
  } finally {
    URL.revokeObjectURL(url);
  }
}
