// The page of `ssgraph view` (docs/viewer.md): the graph diagram, a float image viewer, a
// parameter panel generated from the node descriptors, camera orbit/pan/zoom, an A/B split
// with RMSE/SSIM, and the run's per-node times. It talks only to the server's JSON/binary API;
// the server runs the graph one request at a time, so every sender here keeps at most one
// request in flight and sends only the latest value.
'use strict';

const TOKEN = new URLSearchParams(location.search).get('token') || '';
const $ = (id) => document.getElementById(id);

// ---- HTTP -------------------------------------------------------------------------------
// The cookie set on GET /?token=T authenticates same-origin requests; the header is sent too
// so the page still works when cookies are blocked.
function api(path, body) {
  const opts = { credentials: 'same-origin', headers: {} };
  if (TOKEN) opts.headers['X-SSG-Token'] = TOKEN;
  if (body !== undefined) {
    opts.method = 'POST';
    opts.headers['Content-Type'] = 'text/plain';
    opts.body = body;
  }
  return fetch(path, opts);
}

// The error text of a failed response: the server's {"error": "..."} or the status line.
async function errorText(resp) {
  try { const j = await resp.json(); if (j && j.error) return j.error; } catch (e) { /* */ }
  return `${resp.status} ${resp.statusText}`;
}

// A sender that keeps at most one request in flight per key and, when values arrive while
// one is in flight, sends only the latest when it returns (slider drags, camera drags).
class LatestSender {
  constructor(path, onDone) { this.path = path; this.onDone = onDone; this.busy = false;
    this.pending = new Map(); }
  send(key, body) { this.pending.set(key, body); this.pump(); }
  get idle() { return !this.busy && this.pending.size === 0; }
  async pump() {
    if (this.busy || this.pending.size === 0) return;
    const [key, body] = this.pending.entries().next().value;
    this.pending.delete(key);
    this.busy = true;
    setBusy(true);
    try { await this.onDone(body, await api(this.path, body)); }
    catch (e) { showRequestError(`${this.path}: ${e}`); }
    this.busy = false;
    setBusy(false);
    this.pump();
  }
}

// ---- page state -------------------------------------------------------------------------
const S = {
  state: null,        // the latest /api/state
  gen: -1,            // its generation
  selected: null,     // the selected node's name
  images: new Map(),  // port -> {w, h, c, gen, preview, data: Float32Array}
  cam: null,          // the camera the page is driving (a copy of state.camera)
  drag: null,         // the current canvas drag: {mode, x, y, button}
  split: 0.5,         // the A/B divider as a fraction of the width
  ups: [],            // times of camera updates during the drag (updates per second)
  svgSig: '',         // the node list the diagram was fetched for
  mouse: null,        // the last mouse event over the canvas (pixel readout)
};
let busyCount = 0;
function setBusy(on) { busyCount += on ? 1 : -1; $('busy').hidden = busyCount <= 0; }
function showRequestError(text) {
  const el = $('request-error');
  el.textContent = text || '';
  el.hidden = !text;
}
const fmt = (v, d = 1) => (typeof v === 'number' ? v.toFixed(d) : '-');
const allOutputs = (st) => st.nodes.flatMap((n) => n.outputs.map((o) => `${n.name}.${o.port}`));

// ---- state ------------------------------------------------------------------------------
// A new state (from a poll, a set or a camera move): header, times, errors, selects,
// diagram marks, and the images and metrics when the generation changed.
function applyState(st) {
  const newGen = st.generation !== S.gen;
  S.state = st;
  S.gen = st.generation;
  // the image first (its transfer overlaps the page's own updates below), unless the port
  // selects are still empty (the first state)
  const imageNow = newGen && $('port-a').value;
  if (imageNow) refreshImages(st.last_run === 'preview');
  if (!S.drag && !wheelTimer && st.camera) S.cam = JSON.parse(JSON.stringify(st.camera));
  const base = (path) => path.split('/').pop();
  $('hdr-graph').textContent = base(st.graph);
  $('hdr-graph').title = st.graph;
  $('hdr-scene').textContent = st.scene ? base(st.scene) : '(none)';
  $('hdr-scene').title = st.scene;
  $('hdr-size').textContent = `${st.size[0]}x${st.size[1]}`;
  $('hdr-backend').textContent = st.backend;
  $('frame-ms').textContent = fmt(st.frame_ms);
  $('total-ms').textContent = fmt(st.total_ms);
  $('last-run').textContent = st.last_run;
  $('generation').textContent = st.generation;
  const se = $('state-error');
  se.textContent = st.error || '';
  se.hidden = !st.error;
  fillPortSelects(st);
  if (newGen && !imageNow) refreshImages(st.last_run === 'preview');
  fillTimes(st);
  const sig = st.nodes.map((n) => n.name).join(',');
  if (sig !== S.svgSig) loadDiagram(sig); else markDiagram();
  if (!S.selected || !st.nodes.some((n) => n.name === S.selected)) {
    const shown = $('port-a').value.split('.')[0];
    if (findNode(shown)) selectNode(shown, false);
  } else {
    refreshParamValues();
  }
}

async function poll() {
  try {
    const resp = await api(`/api/state?since=${S.gen}`);
    if (resp.status === 200) applyState(await resp.json());
    else if (resp.status !== 204) showRequestError(`/api/state: ${await errorText(resp)}`);
  } catch (e) { /* the server stopped: keep polling quietly */ }
  setTimeout(poll, 500);
}

// The answer to a set or camera request: the new state, or the error text.
async function onRunAnswer(body, resp) {
  if (resp.ok) { showRequestError(''); applyState(await resp.json()); }
  else showRequestError(await errorText(resp));
}
const setSender = new LatestSender('/api/set', onRunAnswer);
const camSender = new LatestSender('/api/camera', onRunAnswer);

// ---- selects and tables -----------------------------------------------------------------
function fillSelect(sel, values, fallback) {
  const old = sel.value;
  if ([...sel.options].map((o) => o.value).join() !== values.join()) {
    sel.replaceChildren(...values.map((v) => new Option(v, v)));
  }
  sel.value = values.includes(old) ? old : fallback;
}

function fillPortSelects(st) {
  const ports = allOutputs(st);
  const last = ports[ports.length - 1] || '';
  fillSelect($('port-a'), ports, last);
  fillSelect($('port-b'), ports, last);
  fillSelect($('port-ref'), ports, last);
}

function fillTimes(st) {
  const rows = st.nodes.map((n) => {
    const tr = document.createElement('tr');
    tr.dataset.node = n.name;
    tr.className = (n.ran ? 'ran ' : '') + (n.name === S.selected ? 'selected' : '');
    for (const t of [n.name, n.type, n.ran ? 'yes' : 'kept', fmt(n.ms, 2)]) {
      tr.insertCell().textContent = t;
    }
    tr.onclick = () => selectNode(n.name, true);
    return tr;
  });
  $('node-table').tBodies[0].replaceChildren(...rows);
  $('ran-list').textContent = st.nodes.filter((n) => n.ran).map((n) => n.name).join(' ') || '(none)';
}

// ---- diagram ----------------------------------------------------------------------------
async function loadDiagram(sig) {
  S.svgSig = sig;
  const resp = await api('/api/graph.svg');
  if (!resp.ok) { $('diagram').textContent = await errorText(resp); return; }
  const doc = new DOMParser().parseFromString(await resp.text(), 'image/svg+xml');
  const svg = doc.documentElement;
  if (svg.nodeName !== 'svg') { $('diagram').textContent = 'graph.svg: not an SVG'; return; }
  // dot sizes the drawing in points; keep that size unless the column is narrower
  svg.style.maxWidth = '100%';
  svg.style.height = 'auto';
  $('diagram').replaceChildren(document.importNode(svg, true));
  for (const g of $('diagram').querySelectorAll('g.node')) {
    g.addEventListener('click', () => { selectNode(nodeName(g), true); enlargeDiagram(false); });
  }
  markDiagram();
}

// The diagram over the main area at a readable scale (dot lays graphs out wide).
function enlargeDiagram(on) {
  $('diagram-box').classList.toggle('wide', on);
}

const nodeName = (g) => (g.querySelector('title') || {}).textContent || '';

// Each node of the diagram: class ran/selected and its last time under its label.
function markDiagram() {
  if (!S.state) return;
  const byName = new Map(S.state.nodes.map((n) => [n.name, n]));
  for (const g of $('diagram').querySelectorAll('g.node')) {
    const n = byName.get(nodeName(g));
    if (!n) continue;
    g.classList.toggle('ran', n.ran);
    g.classList.toggle('selected', n.name === S.selected);
    let t = g.querySelector('text.ms');
    if (!t) {
      // under the node's box, where no label of dot's is
      const box = g.getBBox();
      t = document.createElementNS('http://www.w3.org/2000/svg', 'text');
      t.setAttribute('class', 'ms');
      t.setAttribute('text-anchor', 'middle');
      t.setAttribute('x', String(box.x + box.width / 2));
      t.setAttribute('y', String(box.y + box.height + 10));
      g.appendChild(t);
    }
    t.textContent = n.ran ? `${fmt(n.ms, 1)} ms` : 'kept';
  }
}

// ---- node panel -------------------------------------------------------------------------
const findNode = (name) => S.state && S.state.nodes.find((n) => n.name === name);

function selectNode(name, showOutput) {
  const n = findNode(name);
  if (!n) return;
  S.selected = name;
  $('node-name').textContent = n.name;
  $('node-type').textContent = `${n.type} \u00b7 ${n.backend}`;
  $('node-doc').textContent = n.doc || '';
  $('params').replaceChildren(...n.params.map((p) => paramRow(n, p)));
  $('ports').replaceChildren(...portList(n));
  markDiagram();
  fillTimes(S.state);
  if (showOutput && n.outputs.length) {
    $('port-a').value = `${n.name}.${n.outputs[0].port}`;
    refreshImages(false);
  }
}

function portList(n) {
  const out = [];
  for (const i of n.inputs) {
    const d = document.createElement('div');
    const what = [i.type, i.optional ? 'optional' : ''].filter(Boolean).join(', ');
    d.textContent = `in  ${i.port}${what ? ` (${what})` : ''} \u2190 ${i.from || '-'}`;
    out.push(d);
  }
  const d = document.createElement('div');
  d.append('out ');
  for (const o of n.outputs) {
    const b = document.createElement('button');
    b.textContent = `${o.port} (${o.type}, ${o.channels} ch)`;
    b.dataset.port = `${n.name}.${o.port}`;
    b.onclick = () => { $('port-a').value = b.dataset.port; refreshImages(false); };
    d.append(b);
  }
  out.push(d);
  return out;
}

let debounce = null;
function sendParam(node, param, value, delay) {
  clearTimeout(debounce);
  const go = () => setSender.send(`${node}.${param}`, `${node}.${param}=${value}`);
  if (delay) debounce = setTimeout(go, delay); else go();
}

// Values changed elsewhere (a reload, a rejected set) reach controls the user is not using.
function refreshParamValues() {
  const n = findNode(S.selected);
  if (!n) return;
  if (n.params.map((p) => p.name).join() !==
      [...$('params').children].map((r) => r.dataset.param).join()) {
    selectNode(n.name, false);
    return;
  }
  for (const p of n.params) {
    const id = `param-${n.name}-${p.name}`;
    const el = $(id), slider = $(`${id}-slider`);
    if (!el || el === document.activeElement || slider === document.activeElement) continue;
    if (!setSender.idle) continue;
    if (el.type === 'checkbox') el.checked = p.value === 'true';
    else if (el.value !== p.value && parseFloat(el.value) !== parseFloat(p.value)) {
      el.value = p.value;
      if (slider) slider.value = String(slider.scale.from(parseFloat(p.value)));
    }
  }
}

// ---- images -----------------------------------------------------------------------------
async function fetchImage(port, preview) {
  const resp = await api(`/api/image?port=${encodeURIComponent(port)}${preview ? '&preview=1' : ''}`);
  if (!resp.ok) throw new Error(`${port}: ${await errorText(resp)}`);
  return decodeImage(await resp.arrayBuffer(), port, preview);
}

let imageBusy = false, imageAgain = false;
// Fetches the shown ports (A, and B when split) for the latest run, then draws. Calls while
// a fetch is on its way are folded into one more fetch after it.
async function refreshImages(preview) {
  if (imageBusy) { imageAgain = true; return; }
  imageBusy = true;
  try {
    const ports = new Set([$('port-a').value]);
    if ($('ab-enable').checked) ports.add($('port-b').value);
    for (const p of ports) if (p) S.images.set(p, await fetchImage(p, preview));
    draw();
    if (preview && S.drag) countUpdate();
    if (!preview && $('ab-enable').checked) refreshMetrics();
  } catch (e) { showRequestError(String(e.message || e)); }
  imageBusy = false;
  if (imageAgain) {
    imageAgain = false;
    refreshImages(S.state && S.state.last_run === 'preview');
  }
}

const scratch = document.createElement('canvas');
// Draws port A (and B right of the divider when split) scaled to the full frame size, so a
// preview-size image fills the same canvas.
function draw() {
  const cv = $('view'), ctx = cv.getContext('2d');
  if (!S.state) return;
  const [W, H] = S.state.size;
  if (cv.width !== W || cv.height !== H) { cv.width = W; cv.height = H; fitCanvas(); }
  ctx.imageSmoothingEnabled = false;
  ctx.fillStyle = '#000';
  ctx.fillRect(0, 0, W, H);
  const split = $('ab-enable').checked;
  const view = { stops: +$('exposure').value, channel: $('channel').value,
    colormap: $('colormap').value };
  const drawPort = (port, x0, x1) => {
    const img = S.images.get(port);
    if (!img) return;
    scratch.width = img.w; scratch.height = img.h;
    scratch.getContext('2d').putImageData(toPixels(img, view), 0, 0);
    ctx.save();
    ctx.beginPath(); ctx.rect(x0, 0, x1 - x0, H); ctx.clip();
    ctx.drawImage(scratch, 0, 0, W, H);
    ctx.restore();
  };
  const xs = Math.round(S.split * W);
  drawPort($('port-a').value, 0, split ? xs : W);
  if (split) drawPort($('port-b').value, xs, W);
  placeDivider();
  $('ab-labels').hidden = !split;
  if (S.mouse) showPixel(S.mouse);
  $('ab-label-a').textContent = `A ${$('port-a').value}`;
  $('ab-label-b').textContent = `B ${$('port-b').value}`;
}

// The canvas as large as the stage allows at the image's aspect ratio (small frames scale up).
function fitCanvas() {
  const cv = $('view'), st = $('stage');
  const k = Math.min(st.clientWidth / cv.width, st.clientHeight / cv.height);
  cv.style.width = `${Math.floor(cv.width * k)}px`;
  cv.style.height = `${Math.floor(cv.height * k)}px`;
}

// The A/B divider: a one-pixel line over the canvas at screen resolution.
function placeDivider() {
  const cv = $('view'), div = $('ab-divider');
  div.hidden = !$('ab-enable').checked;
  div.style.left = `${cv.offsetLeft + Math.round(S.split * cv.clientWidth)}px`;
  div.style.top = `${cv.offsetTop}px`;
  div.style.height = `${cv.clientHeight}px`;
}

// The canvas position of a mouse event in full-frame pixels.
function framePos(ev) {
  const cv = $('view'), r = cv.getBoundingClientRect();
  return [(ev.clientX - r.left) * cv.width / r.width, (ev.clientY - r.top) * cv.height / r.height];
}

function showPixel(ev) {
  S.mouse = ev; // read out again when the image under it changes
  if (!S.state) return;
  const [fx, fy] = framePos(ev);
  const split = $('ab-enable').checked && fx >= S.split * $('view').width;
  const port = split ? $('port-b').value : $('port-a').value;
  const img = S.images.get(port);
  if (!img) return;
  const x = Math.floor(fx * img.w / $('view').width), y = Math.floor(fy * img.h / $('view').height);
  if (x < 0 || y < 0 || x >= img.w || y >= img.h) return;
  const base = (y * img.w + x) * img.c;
  const vals = [...img.data.subarray(base, base + img.c)].map((v) => v.toPrecision(5));
  $('pixel').textContent = `${port}  x,y ${x},${y}${img.preview ? ' (preview)' : ''}: ${vals.join(', ')}`;
}

// ---- metrics ----------------------------------------------------------------------------
let metricsBusy = false, metricsAgain = false;
// The A/B metrics for the chosen ports; a call while one is on its way asks once more after.
async function refreshMetrics() {
  if (metricsBusy) { metricsAgain = true; return; }
  metricsBusy = true;
  // the text names the ports asked for, which may have changed by the time it answers
  const [A, B, ref] = ['port-a', 'port-b', 'port-ref'].map((k) => $(k).value);
  const q = encodeURIComponent;
  const el = $('metrics');
  try {
    const resp = await api(`/api/metrics?ref=${q(ref)}&a=${q(A)}&b=${q(B)}`);
    if (!resp.ok) { el.textContent = `metrics: ${await errorText(resp)}`; return; }
    const m = await resp.json();
    const one = (k, port, r) => `${k} ${port}: ` +
      (r ? `RMSE ${r.rmse.toPrecision(4)} SSIM ${r.ssim.toFixed(4)}` : '-');
    el.textContent = `${one('A', A, m.a)}  |  ${one('B', B, m.b)}  against ${ref} (run ${S.gen})`;
  } catch (e) { el.textContent = `metrics: ${e}`; }
  finally {
    metricsBusy = false;
    if (metricsAgain) { metricsAgain = false; refreshMetrics(); }
  }
}

// ---- camera -----------------------------------------------------------------------------
// The page moves its own copy of the camera (S.cam) and sends each pose; the server's answer
// never overwrites the copy while a drag is on, so a slow answer does not make it jump back.
const num = (x) => String(parseFloat(x.toPrecision(8)));
function sendCamera(preview) {
  const c = S.cam;
  const body = `position=${c.position.map(num)}&target=${c.target.map(num)}` +
    `&up=${c.up.map(num)}&fov=${num(c.fov_y)}&preview=${preview ? 1 : 0}`;
  camSender.send('camera', body);
}

// Updates per second while dragging: preview images drawn in the last second.
function countUpdate() {
  const now = performance.now();
  S.ups.push(now);
  while (S.ups.length && now - S.ups[0] > 1000) S.ups.shift();
  $('cam-ups').textContent = `camera: ${S.ups.length} updates/s`;
}

function onPointerDown(ev) {
  const cv = $('view');
  const [fx] = framePos(ev);
  const pxPerCss = cv.width / cv.getBoundingClientRect().width;
  const nearDivider = $('ab-enable').checked && Math.abs(fx - S.split * cv.width) < 6 * pxPerCss;
  let mode = nearDivider ? 'divider' : ev.button === 2 || ev.shiftKey ? 'pan' : 'orbit';
  if (mode !== 'divider' && !S.cam) {
    $('cam-ups').textContent = 'camera: this graph has no camera';
    return;
  }
  ev.preventDefault();
  cv.setPointerCapture(ev.pointerId);
  S.drag = { mode, x: ev.clientX, y: ev.clientY, moved: false };
  S.ups = [];
  cv.classList.add('dragging');
}

function onPointerMove(ev) {
  const cv = $('view');
  if (!S.drag) {
    showPixel(ev);
    const [fx] = framePos(ev);
    const near = $('ab-enable').checked &&
      Math.abs(fx - S.split * cv.width) < 6 * cv.width / cv.getBoundingClientRect().width;
    cv.classList.toggle('divider', near);
    return;
  }
  const dx = ev.clientX - S.drag.x, dy = ev.clientY - S.drag.y;
  S.drag.x = ev.clientX; S.drag.y = ev.clientY;
  if (S.drag.mode === 'divider') {
    const r = cv.getBoundingClientRect();
    S.split = Math.min(1, Math.max(0, (ev.clientX - r.left) / r.width));
    draw();
    return;
  }
  if (!dx && !dy) return;
  if (S.drag.mode === 'orbit') orbit(S.cam, dx, dy);
  else pan(S.cam, dx, dy, cv.getBoundingClientRect().height);
  S.drag.moved = true;
  sendCamera(true);
}

function onPointerUp(ev) {
  if (!S.drag) return;
  const d = S.drag;
  S.drag = null;
  $('view').classList.remove('dragging');
  if (d.mode !== 'divider' && d.moved) sendCamera(false);
}

let wheelTimer = null;
function onWheel(ev) {
  if (!S.cam) return;
  ev.preventDefault();
  zoom(S.cam, ev.deltaY);
  sendCamera(true);
  clearTimeout(wheelTimer);
  wheelTimer = setTimeout(() => { wheelTimer = null; sendCamera(false); }, 250);
}

// ---- save -------------------------------------------------------------------------------
async function saveVariant() {
  const name = $('save-name').value.trim(), out = $('save-result');
  try {
    const resp = await api('/api/save', `name=${name}`);
    out.textContent = resp.ok ? `wrote ${(await resp.json()).path}` : `error: ${await errorText(resp)}`;
    out.classList.toggle('err', !resp.ok);
  } catch (e) { out.textContent = `error: ${e}`; }
}

// ---- wiring -----------------------------------------------------------------------------
function wire() {
  const cv = $('view');
  // the stage changes size with the window and with the error bars above it
  new ResizeObserver(() => { fitCanvas(); placeDivider(); }).observe($('stage'));
  cv.addEventListener('pointerdown', onPointerDown);
  cv.addEventListener('pointermove', onPointerMove);
  cv.addEventListener('pointerup', onPointerUp);
  cv.addEventListener('pointercancel', onPointerUp);
  cv.addEventListener('wheel', onWheel, { passive: false });
  cv.addEventListener('contextmenu', (ev) => ev.preventDefault());
  const exposure = $('exposure');
  exposure.addEventListener('input', () => {
    $('exposure-val').textContent = (+exposure.value).toFixed(1);
    draw();
  });
  $('fit-btn').onclick = () => { exposure.value = '0'; exposure.dispatchEvent(new Event('input')); };
  $('channel').onchange = draw;
  $('colormap').onchange = draw;
  const reload = () => refreshImages(S.state && S.state.last_run === 'preview');
  $('port-a').onchange = reload;
  $('port-b').onchange = reload;
  $('ab-enable').onchange = reload;
  $('port-ref').onchange = refreshMetrics;
  $('save-btn').onclick = saveVariant;
  $('diagram-expand').onclick = () => enlargeDiagram(true);
  $('diagram-close').onclick = () => enlargeDiagram(false);
  document.addEventListener('keydown', (ev) => { if (ev.key === 'Escape') enlargeDiagram(false); });
  $('save-name').addEventListener('keydown', (ev) => { if (ev.key === 'Enter') saveVariant(); });
}

async function start() {
  wire();
  try {
    const resp = await api('/api/state');
    if (!resp.ok) { showRequestError(`/api/state: ${await errorText(resp)}`); return; }
    applyState(await resp.json());
  } catch (e) { showRequestError(`cannot reach the server: ${e}`); return; }
  setTimeout(poll, 500);
}
start();
