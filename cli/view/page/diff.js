// The A/B view's difference modes (as tev's): |A - B| and the relative error
// |A - B| / (|B| + 0.01) shown as A is (colour through the tone curve, or one channel in
// false colour), A - B in a diverging map (blue below 0, grey at 0, red above), and the
// FLIP map that the server computes with the compare node (GET /api/flip, B the
// reference). Here: the auto range each mode spreads over its colour map, counted once per
// pair of images, the values the pixel readout shows, and the scale bar that says what
// the colours mean.
import { DIVERGING_RGBA, VIRIDIS_RGBA } from './image.js';
import { channelRange, fmtValue } from './stats.js';
import { RELATIVE_EPS, shownChannel } from './tonemap.js';
import { $ } from './ui.js';

export const isDiff = (mode) => ['diff', 'signed', 'relative', 'flip'].includes(mode);

// The key of the FLIP map of A against B among the page's images (state.images).
export const flipKey = (a, b) => `flip:${a}|${b}`;

// One difference per channel of two pixels' values (the readout).
const ONE = {
  diff: (a, b) => Math.abs(a - b),
  signed: (a, b) => a - b,
  relative: (a, b) => Math.abs(a - b) / (Math.abs(b) + RELATIVE_EPS),
};
export const diffImage = (mode, a, b) => a.map((v, k) => ONE[mode](v, b[k] ?? 0));

// The value of a pixel's difference that the colour map shows: its channel, or (A - B of
// a colour) the mean of the colour channels, as the shader's pickA.
function shownDiff(mode, a, b, ia, ib, ch) {
  if (ch >= 0) return ONE[mode](a.data[ia + ch], ch < b.c ? b.data[ib + ch] : 0);
  let sum = 0;
  for (let k = 0; k < 3; k++) sum += a.data[ia + k] - (k < b.c ? b.data[ib + k] : 0);
  return sum / 3;
}

const ranges = new WeakMap(); // image A -> WeakMap(image B -> Map(key -> [lo, hi]))

// The largest |shown difference| over A's pixels (B's nearest pixel where a preview is of
// another size), finite values only; 0 when there is none.
function largestDiff(mode, a, b, ch) {
  if (!ranges.has(a)) ranges.set(a, new WeakMap());
  if (!ranges.get(a).has(b)) ranges.get(a).set(b, new Map());
  const known = ranges.get(a).get(b), key = `${mode} ${ch}`;
  if (!known.has(key)) {
    let top = 0;
    for (let y = 0; y < a.h; y++) {
      const yb = Math.floor(y * b.h / a.h);
      for (let x = 0; x < a.w; x++) {
        const xb = Math.floor(x * b.w / a.w);
        const v = Math.abs(shownDiff(mode, a, b, (y * a.w + x) * a.c, (yb * b.w + xb) * b.c, ch));
        if (v > top && Number.isFinite(v)) top = v;
      }
    }
    known.set(key, top);
  }
  return known.get(key);
}

// Whether the mode's picture goes through a colour map (else through the tone curve, as A).
export function mapped(mode, img, d) {
  if (mode === 'signed' || mode === 'flip') return true;
  return d.colormap === 'viridis' && shownChannel(img, d) >= 0;
}

// [lo, hi] of the values the colour map spreads over: auto, 0 to the largest difference
// (A - B: minus to plus it); else [0, 1] ([-1, 1]). The flip map's largest value is its
// channel's.
export function diffRange(mode, a, b, d) {
  if (!a || (!b && mode !== 'flip') || !mapped(mode, a, d)) return [0, 1];
  let top = 1;
  if (d.range === 'auto') {
    top = mode === 'flip' ? channelRange(a, 0)[1] : largestDiff(mode, a, b, shownChannel(a, d));
  }
  if (!(top > 0)) top = 1;
  return mode === 'signed' ? [-top, top] : [0, top];
}

// The scale bar: the colour map's ramp and the values at its ends and middle (the exposure
// scales them), shown whenever the canvas shows values through a colour map. Returns those
// three values, or null when no colour map is on show.
export function drawScale(f, d) {
  const box = $('scale'), mode = f ? f.ab : 'none';
  const shows = f && f.a && (isDiff(mode) ? mapped(mode, f.a, d)
    : d.colormap === 'viridis' && shownChannel(f.a, d) >= 0);
  box.hidden = !shows;
  if (!shows) return null;
  const span = 1 / (f.rangeScale * 2 ** d.stops), lo = mode === 'signed' ? -span / 2 : f.rangeLo;
  const ends = [lo, lo + span / 2, lo + span];
  ['scale-lo', 'scale-mid', 'scale-hi'].forEach((id, i) => { $(id).textContent = fmtValue(ends[i]); });
  const lut = mode === 'signed' ? DIVERGING_RGBA : VIRIDIS_RGBA, cv = $('scalebar');
  const key = `${mode === 'signed'}`;
  if (cv.dataset.map === key) return ends;
  cv.dataset.map = key;
  const g = cv.getContext('2d');
  for (let x = 0; x < cv.width; x++) {
    const k = Math.min(255, Math.floor(x * 256 / cv.width)) * 4;
    g.fillStyle = `rgb(${lut[k]}, ${lut[k + 1]}, ${lut[k + 2]})`;
    g.fillRect(x, 0, 1, cv.height);
  }
  return ends;
}
