// The statistics of a shown image (tev's per-channel readout): each channel's minimum,
// maximum and mean over its finite values, the false colour's auto range, and a histogram
// of the channel on show, each counted once per image (a new image is the only time these
// loops run).

const statsOf = new WeakMap();
const histOf = new WeakMap();
const rangeOf = new WeakMap();

// [min, max] of channel ch over an image's finite values other than 0 ([0, 0] when it has
// none): 0 is the background of every G-buffer port, and a depth's 0 beside surfaces at 3-5
// units would squeeze them into half the scale. Counted once per image and channel: a new
// image is the only time this loop runs.
export function channelRange(img, ch) {
  if (!rangeOf.has(img)) rangeOf.set(img, new Map());
  const known = rangeOf.get(img);
  if (!known.has(ch)) {
    let lo = Infinity, hi = -Infinity;
    if (ch < img.c) {
      for (let i = ch; i < img.data.length; i += img.c) {
        const v = img.data[i];
        if (v === 0) continue;
        if (v < lo) lo = v;
        if (v > hi) hi = v; // NaN fails both tests
      }
    }
    known.set(ch, lo <= hi && Number.isFinite(lo) && Number.isFinite(hi) ? [lo, hi] : [0, 0]);
  }
  return known.get(ch);
}

// Each value of channel ch of the pixels in rect [x0, y0, x1, y1] (null: all) to fn.
function eachValue(img, ch, rect, fn) {
  const [x0, y0, x1, y1] = rect || [0, 0, img.w, img.h];
  for (let y = y0; y < y1; y++) {
    for (let i = (y * img.w + x0) * img.c + ch, end = (y * img.w + x1) * img.c; i < end;
      i += img.c) fn(img.data[i]);
  }
}

// A per-image cache of counts by key: the whole image's, and the last zoomed view's (a
// wheel burst asks for many rectangles, of which only the last is wanted again).
function cached(store, img, key, count) {
  if (!store.has(img)) store.set(img, new Map());
  const known = store.get(img);
  if (!known.has(key)) {
    if (!key.startsWith('all ')) for (const k of known.keys()) if (!k.startsWith('all ')) known.delete(k);
    known.set(key, count());
  }
  return known.get(key);
}

// [{min, max, mean}] per channel (up to 4) over the finite values of the pixels in rect
// ([x0, y0, x1, y1]: the zoomed view's; null: all); null where none is.
export function imageStats(img, rect = null) {
  return cached(statsOf, img, `${rect ? rect.join() : 'all'} `, () => {
    const n = Math.min(img.c, 4), out = [];
    for (let ch = 0; ch < n; ch++) {
      let lo = Infinity, hi = -Infinity, sum = 0, count = 0;
      eachValue(img, ch, rect, (v) => {
        if (!Number.isFinite(v)) return;
        if (v < lo) lo = v;
        if (v > hi) hi = v;
        sum += v; count++;
      });
      out.push(count ? { min: lo, max: hi, mean: sum / count } : null);
    }
    return out;
  });
}

// Counts of channel ch's finite values (of the pixels in rect, null: all) in `bins` equal
// bins over [lo, hi]; values outside count in the end bins (what the display clips shows
// there). skipZero: exact 0s are not counted at all, inside the range or out: a depth's
// background 0s, below an auto range of 2.4 .. 5.4, piled into the first bin, which then set
// the scale, and the surfaces' depths showed as a few dots (issue 46).
export function histogram(img, ch, lo, hi, bins, rect = null, skipZero = false) {
  const key = `${rect ? rect.join() : 'all'} ${ch} ${lo} ${hi} ${bins} ${skipZero}`;
  return cached(histOf, img, key, () => {
    const counts = new Uint32Array(bins), k = hi > lo ? bins / (hi - lo) : 0;
    eachValue(img, ch, rect, (v) => {
      if (!Number.isFinite(v) || (skipZero && v === 0)) return;
      counts[Math.max(0, Math.min(bins - 1, Math.floor((v - lo) * k)))]++;
    });
    return counts;
  });
}

// Draws the histograms of channels `chs` (their colours) over [lo, hi] into the canvas,
// each scaled to its tallest bin; 0s are left out when told (the background of G-buffer
// ports would flatten the rest).
export function drawHistogram(canvas, img, chs, lo, hi, skipZero, rect = null) {
  const g = canvas.getContext('2d'), W = canvas.width, H = canvas.height;
  g.fillStyle = '#1b1b1b';
  g.fillRect(0, 0, W, H);
  const colours = chs.length > 1 ? ['#e05050', '#50c050', '#5080f0', '#c0c0c0'] : ['#d0d0d0'];
  g.globalCompositeOperation = 'lighter';
  chs.forEach((ch, j) => {
    const counts = histogram(img, ch, lo, hi, W, rect, skipZero);
    const top = Math.max(1, ...counts);
    g.fillStyle = colours[j % colours.length];
    for (let x = 0; x < W; x++) {
      const h = Math.round(counts[x] / top * H);
      if (h) g.fillRect(x, H - h, 1, h);
    }
  });
  g.globalCompositeOperation = 'source-over';
}

// A value of a scale or a statistic, short.
export const fmtValue = (v) => (v === 0 ? '0' : Math.abs(v) >= 1e4 || Math.abs(v) < 1e-3
  ? v.toExponential(2) : String(parseFloat(v.toPrecision(4))));
