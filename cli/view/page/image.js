// The float images of `ssgraph view`'s page (app.js): decoding GET /api/image's binary answer
// and turning floats into display bytes (exposure, channel, false colour, sRGB). No state.
'use strict';

// One image of GET /api/image: "SSGI", uint32 width, height, channels, generation (little
// endian), then width*height*channels float32, rows top down, channels interleaved.
function decodeImage(buf, port, preview) {
  const dv = new DataView(buf);
  if (buf.byteLength < 20) throw new Error(`${port}: image truncated`);
  const magic = String.fromCharCode(...new Uint8Array(buf, 0, 4));
  if (magic !== 'SSGI') throw new Error(`${port}: not an SSGI image`);
  const [w, h, c, gen] = [4, 8, 12, 16].map((o) => dv.getUint32(o, true));
  if (buf.byteLength < 20 + w * h * c * 4) throw new Error(`${port}: image truncated`);
  const data = new Float32Array(buf.slice(20, 20 + w * h * c * 4));
  return { w, h, c, gen, preview, data };
}

// Perceptual false colour: viridis at 11 stops (matplotlib's table), linearly interpolated.
const VIRIDIS = [[68, 1, 84], [72, 36, 117], [65, 68, 135], [53, 95, 141], [42, 120, 142],
  [33, 145, 140], [34, 168, 132], [68, 191, 112], [122, 209, 81], [189, 223, 38], [253, 231, 37]];
const VIRIDIS_LUT = (() => {
  const lut = new Uint8ClampedArray(256 * 3);
  for (let i = 0; i < 256; i++) {
    const t = i / 255 * 10, k = Math.min(9, Math.floor(t)), f = t - k;
    for (let j = 0; j < 3; j++) lut[i * 3 + j] = VIRIDIS[k][j] * (1 - f) + VIRIDIS[k + 1][j] * f;
  }
  return lut;
})();
// Linear [0, 1] -> sRGB bytes, 4096 steps.
const SRGB_LUT = (() => {
  const lut = new Uint8ClampedArray(4096);
  for (let i = 0; i < 4096; i++) {
    const x = i / 4095;
    lut[i] = 255 * (x <= 0.0031308 ? 12.92 * x : 1.055 * Math.pow(x, 1 / 2.4) - 0.055) + 0.5;
  }
  return lut;
})();
const srgb = (x) => SRGB_LUT[x <= 0 ? 0 : x >= 1 ? 4095 : (x * 4095) | 0];

// The float image as RGBA bytes: exposure in stops, then the channel choice; one channel
// (a one-channel image or R/G/B/A chosen) is grey or false colour, colour gets the sRGB curve.
// view: {stops, channel: 'rgb'|'r'|'g'|'b'|'a', colormap: 'viridis'|'none'}.
function toPixels(img, view) {
  const gain = Math.pow(2, view.stops), ch = view.channel, cmap = view.colormap;
  const out = new ImageData(img.w, img.h), px = out.data, d = img.data, c = img.c;
  const pick = { r: 0, g: 1, b: 2, a: 3 }[ch];
  const single = c === 1 || pick !== undefined;
  const src = c === 1 ? 0 : pick;
  for (let i = 0, n = img.w * img.h; i < n; i++) {
    const o = i * 4;
    if (single) {
      const v = src < c ? d[i * c + src] * gain : (src === 3 ? 1 : 0);
      if (cmap === 'viridis') {
        const k = (v <= 0 ? 0 : v >= 1 ? 255 : (v * 255) | 0) * 3;
        px[o] = VIRIDIS_LUT[k]; px[o + 1] = VIRIDIS_LUT[k + 1]; px[o + 2] = VIRIDIS_LUT[k + 2];
      } else {
        px[o] = px[o + 1] = px[o + 2] = srgb(v);
      }
    } else {
      px[o] = srgb(d[i * c] * gain);
      px[o + 1] = srgb(d[i * c + 1] * gain);
      px[o + 2] = c > 2 ? srgb(d[i * c + 2] * gain) : 0;
    }
    px[o + 3] = 255;
  }
  return out;
}
