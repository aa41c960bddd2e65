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

// Bytes as a Uint8Array over exactly their own bytes: a message's buffers arrive as
// DataViews, whose .buffer is the whole ArrayBuffer they look into (a view into a larger
// buffer, from another front end than JupyterLab's, would bring its neighbours' bytes along).
export function asBytes(data) {
  if (data instanceof Uint8Array) return data;
  if (ArrayBuffer.isView(data)) return new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
  return new Uint8Array(data);
}

let crcTable = null;
function crc32(bytes) {
  if (crcTable === null) {
    crcTable = new Uint32Array(256);
    for (let n = 0; n < 256; n++) {
      let c = n;
      for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
      crcTable[n] = c >>> 0;
    }
  }
  let c = 0xffffffff;
  for (const b of bytes) c = crcTable[(c ^ b) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

const PNG_SIGNATURE = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];

// What is wrong with `data` as a PNG, or "" when it is sound: the signature, then chunks
// whose lengths and CRCs add up, IHDR first, IEND ending the bytes exactly, and no second
// signature inside (two pictures' bytes run together). Sound bytes are the kernel's own,
// byte for byte (every chunk's CRC was computed by the kernel): a decoder that rejects them
// failed by itself. Read only for the warning when a picture could not be decoded.
export function pngProblem(data) {
  const b = asBytes(data);
  if (b.byteLength === 0) return "no bytes";
  if (b.byteLength < 8 || PNG_SIGNATURE.some((v, i) => b[i] !== v)) return "no PNG signature";
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  for (let at = 8, first = true; ; first = false) {
    if (at + 12 > b.byteLength) return `no IEND: ${b.byteLength - at} bytes left at ${at}`;
    const n = dv.getUint32(at);
    const type = String.fromCharCode(...b.subarray(at + 4, at + 8));
    if (first && type !== "IHDR") return `the first chunk is ${JSON.stringify(type)}, not IHDR`;
    if (at + 12 + n > b.byteLength) {
      return `chunk ${JSON.stringify(type)} at ${at} needs ${n} bytes, ${b.byteLength - at - 12} are left`;
    }
    if (crc32(b.subarray(at + 4, at + 8 + n)) !== dv.getUint32(at + 8 + n)) {
      return `chunk ${JSON.stringify(type)} at ${at} (${n} bytes): wrong CRC`;
    }
    const again = type === "IDAT" ? secondSignature(b.subarray(at + 8, at + 8 + n)) : -1;
    if (again >= 0) return `a second PNG signature inside IDAT at ${at + 8 + again}`;
    at += 12 + n;
    if (type === "IEND") return at === b.byteLength ? "" : `${b.byteLength - at} bytes after IEND`;
  }
}

function secondSignature(b) {
  for (let i = b.indexOf(0x89); i >= 0 && i + 8 <= b.byteLength; i = b.indexOf(0x89, i + 1)) {
    if (PNG_SIGNATURE.every((v, k) => b[i + k] === v)) return i;
  }
  return -1;
}

// The picture's size from its IHDR ("w x h"), or "?".
function pngSize(b) {
  if (b.byteLength < 24) return "?";
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  return `${dv.getUint32(16)} x ${dv.getUint32(20)}`;
}

// Everything the warning says about bytes that could not be decoded: where they lie, what
// they start with, and whether they are a sound PNG (pngProblem).
export function describePng(data) {
  const b = asBytes(data);
  const head = Array.from(b.subarray(0, 8), (v) => v.toString(16).padStart(2, "0")).join(" ");
  const kind = data?.constructor?.name ?? typeof data;
  const where = ArrayBuffer.isView(data)
    ? `, a ${kind} at ${data.byteOffset} of a ${data.buffer.byteLength}-byte buffer` : "";
  const problem = pngProblem(b);
  return `${b.byteLength} bytes${where}, starting ${head}, ` +
    (problem ? `not a sound PNG: ${problem}` : `a sound PNG of ${pngSize(b)} px`);
}

// PNG bytes to an ImageBitmap, or null. Tried again after a pause, then through an <img>
// (cheap, and a decoder may fail for its own reasons). The failures once seen in loaded CI
// runs ("The source image could not be decoded.") were not the decoder's: 12,000 decodes of
// sound PNGs at load 20 in the tests' Chromium all succeeded, while a kernel exiting as it
// sent a group glued the next message's frames on as its pictures (frames.js groupMismatch
// now catches those). Bytes that fail every way give null and a console warning saying
// what they are (describePng): the caller keeps its picture and asks for a whole one.
export async function decodePng(data) {
  const blob = new Blob([asBytes(data)], { type: "image/png" });
  const failures = [];
  for (const pause of [0, 50, 250]) {
    if (pause) await new Promise((done) => setTimeout(done, pause));
    try {
      return await createImageBitmap(blob);
    } catch (error) {
      if (typeof Image === "undefined") throw error;
      failures.push(error.message);
    }
  }
  const url = URL.createObjectURL(blob);
  try {
    const img = new Image();
    img.src = url;
    await img.decode();
    return await createImageBitmap(img);
  } catch (error) {
    failures.push(`<img>: ${error.message}`);
    console.warn(`teachraster: a picture could not be decoded (${describePng(data)}): ` +
      failures.join(" / "));
    return null;
  } finally {
    URL.revokeObjectURL(url);
  }
}
