// The page's one render path: render() draws the image view from the state (state.js) and
// nothing else: the canvas (tonemap.js), the A/B divider and labels, the controls that show
// the display settings, and the value under the mouse. Every change reaches it the same way:
// a mutation of the state asks for a render, and the renders asked for within one animation
// frame are one render.
import { state } from './state.js';
import { channelRange, drawHistogram, imageStats } from './stats.js';
import { ImageView, shownChannel } from './tonemap.js';
import { $, showRequestError } from './ui.js';

let view = null, queued = false, drawn = null;

export function scheduleRender() {
  if (queued) return;
  queued = true;
  requestAnimationFrame(render);
}

// What the canvas shows, from the state; the canvas is drawn again only when this changes.
function frameOf(st) {
  const p = state.ports, [W, H] = st.size;
  const a = state.images.get(p.a) || null;
  const b = p.ab ? state.images.get(p.b) || null : null;
  const [lo, hi] = falseColourRange(a, p.ab && p.mode === 'split' ? b : null, state.display);
  return { W, H, a, b, ab: p.ab ? p.mode : 'none', splitX: Math.round(state.divider * W),
    display: state.display, rangeLo: lo, rangeScale: hi > lo ? 1 / (hi - lo) : 1 };
}

// The values false colour spreads over its scale: [0, 1], or with range auto the shown
// channel's minimum to maximum over A (and B beside it in a split, so both sides share one
// scale), 0s left out (channelRange). A depth of 3-5 units over [0, 1] was one solid colour
// (issue 46).
function falseColourRange(a, b, d) {
  if (d.range !== 'auto' || d.colormap !== 'viridis') return [0, 1];
  let lo = Infinity, hi = -Infinity;
  for (const img of [a, b]) {
    const ch = img ? shownChannel(img, d) : -1;
    if (ch < 0) continue;
    const [l, h] = channelRange(img, ch);
    lo = Math.min(lo, l); hi = Math.max(hi, h);
  }
  return lo <= hi ? [lo, hi] : [0, 1];
}

const sameFrame = (f, g) => g && Object.keys(f).every((k) => f[k] === g[k]);

function drawCanvas(f) {
  const cv = $('view');
  if (cv.width !== f.W || cv.height !== f.H) { cv.width = f.W; cv.height = f.H; drawn = null; }
  if (sameFrame(f, drawn)) return;
  // what A is, for a reader of the page (and its tests): the run and the image's size, which
  // is half the frame's for a drag's preview
  cv.dataset.shown = f.a ? `${f.a.w}x${f.a.h} run ${f.a.gen}${f.a.preview ? ' preview' : ''}` : '';
  if (!view) view = new ImageView(cv, () => { drawn = null; scheduleRender(); });
  view.draw(f);
  drawn = f;
}

export function render() {
  queued = false;
  const st = state.server;
  if (!st) return;
  try { drawCanvas(frameOf(st)); } catch (e) { showRequestError(String(e.message || e)); }
  fitCanvas();
  showControls();
  showStats();
  placeDivider();
  showPixel();
}

// The canvas as large as the stage allows at the image's aspect ratio (small frames scale up).
function fitCanvas() {
  const cv = $('view'), st = $('stage');
  const k = Math.min(st.clientWidth / cv.width, st.clientHeight / cv.height);
  cv.style.width = `${Math.floor(cv.width * k)}px`;
  cv.style.height = `${Math.floor(cv.height * k)}px`;
}

// The toolbar says what the state holds (a port list refill, the 0 EV button).
function showControls() {
  const p = state.ports, d = state.display;
  for (const [id, v] of [['port-a', p.a], ['port-b', p.b], ['port-ref', p.ref],
    ['ab-mode', p.mode], ['channel', d.channel], ['colormap', d.colormap], ['tonemap', d.curve]]) {
    if ($(id).value !== v) $(id).value = v;
  }
  $('ab-enable').checked = p.ab;
  if (+$('exposure').value !== d.stops) $('exposure').value = String(d.stops);
  $('exposure-val').textContent = d.stops.toFixed(1);
  if ($('range').value !== d.range) $('range').value = d.range;
  // the false colour's scale: the values at its two ends (exposure scales it)
  const f = drawn, g = 2 ** d.stops;
  const shows = f && f.a && d.colormap === 'viridis' && shownChannel(f.a, d) >= 0;
  $('range-val').textContent = shows
    ? `${fmtValue(f.rangeLo)} .. ${fmtValue(f.rangeLo + 1 / (f.rangeScale * g))}` : '';
  $('ab-labels').hidden = !p.ab;
  $('ab-label-a').textContent = p.mode === 'diff' ? `|A - B|  A ${p.a}` : `A ${p.a}`;
  $('ab-label-b').textContent = `B ${p.b}`;
}

// A's per-channel minimum, mean and maximum, and the histogram of what is on show: the
// shown channel over the false colour's range, or the colour channels over their joint
// minimum to maximum (issue 46: no statistics of the view, no histogram).
let statsShown = null;
function showStats() {
  const f = drawn, img = f && f.a;
  const key = img && `${state.ports.a} ${img.gen} ${img.w} ${f.rangeLo} ${f.rangeScale} ` +
    `${state.display.channel} ${state.display.colormap} ${state.display.stops}`;
  if (key === statsShown) return;
  statsShown = key;
  if (!img) { $('stats').textContent = ''; return; }
  const st = imageStats(img), names = img.c === 1 ? ['Y'] : ['R', 'G', 'B', 'A'];
  $('stats').textContent = `A ${state.ports.a}  ` + st.map((s, i) => (s
    ? `${names[i]} ${fmtValue(s.min)} / ${fmtValue(s.mean)} / ${fmtValue(s.max)}`
    : `${names[i]} -`)).join('   ') + '  (min / mean / max)';
  const ch = shownChannel(img, state.display);
  const chs = ch >= 0 ? [ch] : [0, 1, 2].filter((c) => c < img.c && st[c]);
  // over what the display shows: the false colour's range, else [0, 1] over the exposure
  // (a colour image's few bright pixels, a lamp at 38, would squeeze the rest into a bin)
  const gain = 2 ** state.display.stops;
  const [lo, hi] = ch >= 0 && state.display.colormap === 'viridis'
    ? [f.rangeLo, f.rangeLo + 1 / (f.rangeScale * gain)] : [0, 1 / gain];
  drawHistogram($('hist'), img, chs, lo, hi, true);
}

// The A/B divider: a one-pixel line over the canvas at screen resolution.
function placeDivider() {
  const cv = $('view'), div = $('ab-divider');
  div.hidden = !(state.ports.ab && state.ports.mode === 'split');
  div.style.left = `${cv.offsetLeft + Math.round(state.divider * cv.clientWidth)}px`;
  div.style.top = `${cv.offsetTop}px`;
  div.style.height = `${cv.clientHeight}px`;
}

// The canvas position of a mouse event in full-frame pixels.
export function framePos(ev) {
  const cv = $('view'), r = cv.getBoundingClientRect();
  return [(ev.clientX - r.left) * cv.width / r.width, (ev.clientY - r.top) * cv.height / r.height];
}

// The raw floats under the mouse, read from the image's array (before exposure).
function showPixel() {
  if (!state.pointer) return;
  const [fx, fy] = framePos(state.pointer);
  const p = state.ports, cv = $('view');
  const right = p.ab && p.mode === 'split' && fx >= state.divider * cv.width;
  const port = right ? p.b : p.a;
  const img = state.images.get(port);
  if (!img) return;
  const x = Math.floor(fx * img.w / cv.width), y = Math.floor(fy * img.h / cv.height);
  if (x < 0 || y < 0 || x >= img.w || y >= img.h) return;
  const base = (y * img.w + x) * img.c;
  const vals = [...img.data.subarray(base, base + img.c)].map((v) => v.toPrecision(5));
  $('pixel').textContent = `${port}  x,y ${x},${y}${img.preview ? ' (preview)' : ''}: ${vals.join(', ')}`;
}

// A value of the false colour's scale, short.
const fmtValue = (v) => (v === 0 ? '0' : Math.abs(v) >= 1e4 || Math.abs(v) < 1e-3
  ? v.toExponential(2) : String(parseFloat(v.toPrecision(4))));
