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

// [{min, max, mean}] per channel (up to 4) over the finite values; null where none is.
export function imageStats(img) {
  if (!statsOf.has(img)) {
    const n = Math.min(img.c, 4), out = [];
    for (let ch = 0; ch < n; ch++) {
      let lo = Infinity, hi = -Infinity, sum = 0, count = 0;
      for (let i = ch; i < img.data.length; i += img.c) {
        const v = img.data[i];
        if (!Number.isFinite(v)) continue;
        if (v < lo) lo = v;
        if (v > hi) hi = v;
        sum += v; count++;
      }
      out.push(count ? { min: lo, max: hi, mean: sum / count } : null);
    }
    statsOf.set(img, out);
  }
  return statsOf.get(img);
}

// Counts of channel ch's finite values in `bins` equal bins over [lo, hi]; values outside
// count in the end bins (what the display clips shows there).
export function histogram(img, ch, lo, hi, bins) {
  const key = `${ch} ${lo} ${hi} ${bins}`;
  if (!histOf.has(img)) histOf.set(img, new Map());
  const known = histOf.get(img);
  if (!known.has(key)) {
    const counts = new Uint32Array(bins), k = hi > lo ? bins / (hi - lo) : 0;
    for (let i = ch; i < img.data.length; i += img.c) {
      const v = img.data[i];
      if (!Number.isFinite(v)) continue;
      counts[Math.max(0, Math.min(bins - 1, Math.floor((v - lo) * k)))]++;
    }
    known.set(key, counts);
  }
  return known.get(key);
}

// Draws the histograms of channels `chs` (their colours) over [lo, hi] into the canvas,
// each scaled to its tallest bin; 0s are left out when told (the background of G-buffer
// ports would flatten the rest).
export function drawHistogram(canvas, img, chs, lo, hi, skipZero) {
  const g = canvas.getContext('2d'), W = canvas.width, H = canvas.height;
  g.fillStyle = '#1b1b1b';
  g.fillRect(0, 0, W, H);
  const colours = chs.length > 1 ? ['#e05050', '#50c050', '#5080f0', '#c0c0c0'] : ['#d0d0d0'];
  g.globalCompositeOperation = 'lighter';
  chs.forEach((ch, j) => {
    const counts = histogram(img, ch, lo, hi, W).slice(); // the cached counts stay whole
    if (skipZero && lo <= 0 && hi >= 0) {
      counts[Math.min(W - 1, Math.floor(-lo * W / (hi - lo || 1)))] = 0;
    }
    const top = Math.max(1, ...counts);
    g.fillStyle = colours[j % colours.length];
    for (let x = 0; x < W; x++) {
      const h = Math.round(counts[x] / top * H);
      if (h) g.fillRect(x, H - h, 1, h);
    }
  });
  g.globalCompositeOperation = 'source-over';
}
