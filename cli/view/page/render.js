// The page's one render path: render() draws the image view from the state (state.js) and
// nothing else: the canvas (tonemap.js), the A/B divider and labels, the controls that show
// the display settings, and the value under the mouse. Every change reaches it the same way:
// a mutation of the state asks for a render, and the renders asked for within one animation
// frame are one render.
import { state } from './state.js';
import { diffImage, diffRange, drawScale, flipKey, isDiff } from './diff.js';
import { channelRange, drawHistogram, fmtValue, imageStats } from './stats.js';
import { ImageView, shownChannel } from './tonemap.js';
import { $, showRequestError } from './ui.js';
import { canvasToFrame, visibleRect, zoomPercent } from './viewport.js';

let view = null, queued = false, drawn = null;

export function scheduleRender() {
  if (queued) return;
  queued = true;
  requestAnimationFrame(render);
}

// What the canvas shows, from the state; the canvas is drawn again only when this changes.
function frameOf(st) {
  const p = state.ports, [W, H] = st.size, z = state.zoom;
  const ab = p.ab ? p.mode : 'none';
  // the FLIP mode shows the server's map of A against B as its image A
  const a = (ab === 'flip' ? state.images.get(flipKey(p.a, p.b)) : state.images.get(p.a)) || null;
  const b = p.ab && ab !== 'flip' ? state.images.get(p.b) || null : null;
  const [lo, hi] = isDiff(ab) ? diffRange(ab, a, b, state.display)
    : falseColourRange(a, ab === 'split' ? b : null, state.display);
  return { W, H, a, b, ab, splitX: Math.round(state.divider * W), display: state.display,
    rangeLo: lo, rangeScale: hi > lo ? 1 / (hi - lo) : 1, zoom: z.z, u: z.u, v: z.v };
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
  // the zoom and pan (viewport.js): canvas pixels per frame pixel, the centre's u and v
  cv.dataset.view = `${f.zoom} ${f.u} ${f.v}`;
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
  $('ab-labels').hidden = !p.ab;
  const what = { diff: '|A - B|', signed: 'A - B', relative: '|A - B| / (|B| + 0.01)',
    flip: 'FLIP of A against B' }[p.mode];
  $('ab-label-a').textContent = what ? `${what}  A ${p.a}` : `A ${p.a}`;
  $('ab-label-b').textContent = `B ${p.b}`;
  $('zoom-val').textContent = `${zoomPercent()}%`;
  // the colour map's scale: the values at its two ends (exposure scales it), and its bar
  const ends = drawScale(drawn, d);
  $('range-val').textContent = ends ? `${fmtValue(ends[0])} .. ${fmtValue(ends[2])}` : '';
}

// A's per-channel minimum, mean and maximum, and the histogram of what is on show: the
// shown channel over the false colour's range, or the colour channels over their joint
// minimum to maximum (issue 46: no statistics of the view, no histogram); of the pixels in
// view once zoomed in (tev's statistics of the view).
let statsShown = null;
function showStats() {
  const f = drawn, img = f && f.a;
  const z = state.zoom, whole = z.z <= 1 && z.u === 0.5 && z.v === 0.5;
  const rect = img && !whole ? visibleRect(img.w, img.h) : null;
  const key = img && `${state.ports.a} ${img.gen} ${img.w} ${f.rangeLo} ${f.rangeScale} ` +
    `${state.display.channel} ${state.display.colormap} ${state.display.stops} ${rect} ${f.ab}`;
  if (key === statsShown) return;
  statsShown = key;
  if (!img || (rect && (rect[2] <= rect[0] || rect[3] <= rect[1]))) {
    $('stats').textContent = ''; return;
  }
  const st = imageStats(img, rect), names = img.c === 1 ? ['Y'] : ['R', 'G', 'B', 'A'];
  const label = f.ab === 'flip' ? 'FLIP' : `A ${state.ports.a}`;
  const where = rect ? `  in view x ${rect[0]}-${rect[2] - 1}, y ${rect[1]}-${rect[3] - 1}` : '';
  $('stats').textContent = `${label}  ` + st.map((s, i) => (s
    ? `${names[i]} ${fmtValue(s.min)} / ${fmtValue(s.mean)} / ${fmtValue(s.max)}`
    : `${names[i]} -`)).join('   ') + `  (min / mean / max)${where}`;
  const ch = shownChannel(img, state.display);
  const chs = ch >= 0 ? [ch] : [0, 1, 2].filter((c) => c < img.c && st[c]);
  // over what the display shows: the false colour's range, else [0, 1] over the exposure
  // (a colour image's few bright pixels, a lamp at 38, would squeeze the rest into a bin)
  const gain = 2 ** state.display.stops;
  // (a difference's range is the difference's, not A's: A's histogram is then over [0, 1])
  const ownRange = !isDiff(f.ab) || f.ab === 'flip';
  const [lo, hi] = ch >= 0 && ownRange && state.display.colormap === 'viridis'
    ? [f.rangeLo, f.rangeLo + 1 / (f.rangeScale * gain)] : [0, 1 / gain];
  drawHistogram($('hist'), img, chs, lo, hi, true, rect);
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

// The floats of img at frame point [qx, qy] (before exposure), or null outside it.
function valuesAt(img, qx, qy) {
  const cv = $('view');
  const x = Math.floor(qx * img.w / cv.width), y = Math.floor(qy * img.h / cv.height);
  if (x < 0 || y < 0 || x >= img.w || y >= img.h) return null;
  const base = (y * img.w + x) * img.c;
  return { x, y, vals: [...img.data.subarray(base, base + img.c)] };
}
const fmtVals = (vals) => vals.map((v) => v.toPrecision(5)).join(', ');

// The raw floats under the mouse, read from the image's array through the zoom (the side of
// the divider it is on; a difference: A's, B's and the difference's).
function showPixel() {
  if (!state.pointer) return;
  const [fx, fy] = framePos(state.pointer), [qx, qy] = canvasToFrame(fx, fy);
  const p = state.ports, cv = $('view'), mode = p.ab ? p.mode : 'none';
  const right = mode === 'split' && fx >= state.divider * cv.width;
  const port = mode === 'flip' ? flipKey(p.a, p.b) : right ? p.b : p.a;
  const img = state.images.get(port);
  const at = img && valuesAt(img, qx, qy);
  if (!at) { $('pixel').textContent = 'x,y: -'; return; }
  let line = `${mode === 'flip' ? 'FLIP' : port}  x,y ${at.x},${at.y}` +
    `${img.preview ? ' (preview)' : ''}: ${fmtVals(at.vals)}`;
  const other = isDiff(mode) && mode !== 'flip' && state.images.get(p.b);
  const bt = other && valuesAt(other, qx, qy);
  if (bt) line += `  B ${fmtVals(bt.vals)}  ${mode} ${fmtVals(diffImage(mode, at.vals, bt.vals))}`;
  $('pixel').textContent = line;
}
