// The float images of the page: GET /api/image's binary answer decoded, and the false-colour
// table the display shader (tonemap.js) looks values up in.
import { api, errorText } from './net.js';

// One image of GET /api/image: "SSGI", uint32 width, height, channels, generation (little
// endian), then width*height*channels float32, rows top down, channels interleaved.
export function decodeImage(buf, port, preview) {
  const dv = new DataView(buf);
  if (buf.byteLength < 20) throw new Error(`${port}: image truncated`);
  const magic = String.fromCharCode(...new Uint8Array(buf, 0, 4));
  if (magic !== 'SSGI') throw new Error(`${port}: not an SSGI image`);
  const [w, h, c, gen] = [4, 8, 12, 16].map((o) => dv.getUint32(o, true));
  if (buf.byteLength < 20 + w * h * c * 4) throw new Error(`${port}: image truncated`);
  const data = new Float32Array(buf.slice(20, 20 + w * h * c * 4));
  return { w, h, c, gen, preview, data };
}

export async function fetchImage(port, preview) {
  const resp = await api(`/api/image?port=${encodeURIComponent(port)}${preview ? '&preview=1' : ''}`);
  if (!resp.ok) throw new Error(`${port}: ${await errorText(resp)}`);
  return decodeImage(await resp.arrayBuffer(), port, preview);
}

// The FLIP map of port a against port b, the reference (GET /api/flip: one channel).
export async function fetchFlip(a, b) {
  const q = encodeURIComponent;
  const resp = await api(`/api/flip?a=${q(a)}&b=${q(b)}`);
  if (!resp.ok) throw new Error(`FLIP of ${a} against ${b}: ${await errorText(resp)}`);
  return decodeImage(await resp.arrayBuffer(), 'FLIP', false);
}

// Perceptual false colour: viridis at 11 stops (matplotlib's table), linearly interpolated
// into 256 RGBA entries; entry floor(255 v) shows the value v in [0, 1].
const VIRIDIS = [[68, 1, 84], [72, 36, 117], [65, 68, 135], [53, 95, 141], [42, 120, 142],
  [33, 145, 140], [34, 168, 132], [68, 191, 112], [122, 209, 81], [189, 223, 38], [253, 231, 37]];
export const VIRIDIS_RGBA = (() => {
  const lut = new Uint8ClampedArray(256 * 4);
  for (let i = 0; i < 256; i++) {
    const t = i / 255 * 10, k = Math.min(9, Math.floor(t)), f = t - k;
    for (let j = 0; j < 3; j++) lut[i * 4 + j] = VIRIDIS[k][j] * (1 - f) + VIRIDIS[k + 1][j] * f;
    lut[i * 4 + 3] = 255;
  }
  return lut;
})();

// A diverging map for signed values (Moreland's cool to warm endpoints, through a neutral
// grey): entry 128 + 127 v shows v in [-1, 1], entry 128 exactly the grey of 0.
const COOL = [59, 76, 192], NEUTRAL = [221, 221, 221], WARM = [180, 4, 38];
export const DIVERGING_RGBA = (() => {
  const lut = new Uint8ClampedArray(256 * 4);
  for (let i = 0; i < 256; i++) {
    const t = Math.max(-1, Math.min(1, (i - 128) / 127)), end = t < 0 ? COOL : WARM;
    for (let j = 0; j < 3; j++) lut[i * 4 + j] = NEUTRAL[j] + (end[j] - NEUTRAL[j]) * Math.abs(t);
    lut[i * 4 + 3] = 255;
  }
  return lut;
})();
