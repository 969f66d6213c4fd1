// The page of `ssgraph view` (docs/viewer.md): the graph diagram, a float image viewer, a
// parameter panel generated from the node descriptors, camera orbit/pan/zoom, an A/B view
// with RMSE/SSIM, and the run's per-node times. This module starts the page and wires its
// controls: they change the state (state.js), and every change of the state draws the image
// view through the one render path (render.js).
import { wireCamPanel } from './campanel.js';
import { wireCamPath } from './campath.js';
import { flipKey } from './diff.js';
import { wireEdit } from './edit.js';
import { flying, wireFly } from './fly.js';
import { refusedSet, wireHistory } from './history.js';
import { fetchFlip, fetchImage } from './image.js';
import { countUpdate, dragging, goHome, wireMouse } from './mouse.js';
import { api, errorText, LatestSender } from './net.js';
import { enlargeDiagram, fillTimes, markDiagram, panelActions, portChoices,
  refreshParamValues, showDiagram, showHeader, showNode } from './panel.js';
import { render, scheduleRender } from './render.js';
import { findNode, receive, select, setDisplay, setPorts, state, storeImages, subscribe }
  from './state.js';
import { wireTime } from './time.js';
import { $, showRequestError } from './ui.js';
import { fit, oneToOne } from './viewport.js';

// ---- the server's state -----------------------------------------------------------------
// A new state (from a poll, a set or a camera move): header, times, errors, port lists,
// diagram marks, and the images and metrics when it is a new run.
function applyState(st) {
  const newRun = receive(st);
  if (newRun && state.ports.ab) showMetrics(null, true);
  // the image first (its transfer overlaps the page's own updates below), unless the port
  // lists are still empty (the first state)
  // (and not when the port shown is gone: a node removed in the editor, edit.js)
  const imageNow = newRun && state.ports.a && st.nodes.some((n) =>
    n.outputs.some((o) => `${n.name}.${o.port}` === state.ports.a));
  if (imageNow) refreshImages(st.last_run === 'preview');
  showHeader(st);
  setPorts(portChoices(st));
  if (newRun && !imageNow) refreshImages(st.last_run === 'preview');
  fillTimes(st);
  showDiagram(st);
  if (!state.selected || !findNode(state.selected)) {
    const shown = state.ports.a.split('.')[0];
    if (findNode(shown)) pickNode(shown, false);
  } else {
    refreshParamValues();
  }
}

async function poll() {
  try {
    const resp = await api(`/api/state?since=${state.gen}`);
    if (resp.status === 200) applyState(await resp.json());
    else if (resp.status !== 204) showRequestError(`/api/state: ${await errorText(resp)}`);
  } catch (e) { /* the server stopped: keep polling quietly */ }
  setTimeout(poll, 500);
}

// The answer to a set, camera or frame request: the new state, or the error text.
async function onRunAnswer(body, resp) {
  if (resp.ok) { showRequestError(''); applyState(await resp.json()); }
  else showRequestError(await errorText(resp));
}

// A set's answer. A refused value stays in its box while the user is there to correct it,
// marked refused (the error bar quotes it), and goes back to the value the graph kept when
// the box loses focus: a panel showing -1 while the graph ran with 0.3 misleads (issue 46).
async function onSetAnswer(body, resp) {
  const [node, param] = body.slice(0, body.indexOf('=')).split('.');
  const el = document.getElementById(`param-${node}-${param}`);
  if (resp.ok) {
    if (el) { el.classList.remove('refused'); el.title = ''; }
    return onRunAnswer(body, resp);
  }
  await onRunAnswer(body, resp);
  refusedSet(node, param, body.slice(body.indexOf('=') + 1));
  if (!el) return;
  el.classList.add('refused');
  const kept = findNode(node)?.params.find((p) => p.name === param)?.value;
  el.title = `refused: the graph keeps ${kept}`;
  const restore = () => {
    if (!el.classList.contains('refused')) return;
    el.classList.remove('refused');
    el.title = '';
    refreshParamValues(true);
  };
  if (document.activeElement === el) el.addEventListener('blur', restore, { once: true });
  else restore();
}
const setSender = new LatestSender('/api/set', onSetAnswer);

// A throttle, not a debounce: a slider's first move is sent at once and then the latest value
// at most every `delay` ms while it moves (a debounce re-armed on every input event sent
// nothing until the hand paused: 4 requests in a 2.75 s drag, issue 46). The sender keeps
// one request in flight and sends only the latest value when it returns.
let throttle = null, lastSent = -Infinity, latest = null;
function sendParam(node, param, value, delay) {
  latest = () => { lastSent = performance.now(); latest = null;
    setSender.send(`${node}.${param}`, `${node}.${param}=${value}`); };
  if (!delay) { clearTimeout(throttle); throttle = null; latest(); return; }
  if (throttle) return; // the armed timer sends the latest value
  const wait = lastSent + delay - performance.now();
  if (wait <= 0) latest();
  else throttle = setTimeout(() => { throttle = null; if (latest) latest(); }, wait);
}

// ---- node and port choice ---------------------------------------------------------------
function pickNode(name, showOutput) {
  const n = findNode(name);
  if (!n) return;
  select(name);
  showNode(n);
  markDiagram();
  fillTimes(state.server);
  if (showOutput && n.outputs.length) showPort(`${n.name}.${n.outputs[0].port}`);
}

function showPort(port) {
  setPorts({ a: port });
  refreshImages(false);
}

// ---- images and metrics -----------------------------------------------------------------
let imageBusy = false, imageAgain = false;
// Fetches the shown ports (A, and B when the A/B view is on) for the latest run into the
// state. Calls while a fetch is on its way are folded into one more fetch after it.
async function refreshImages(preview) {
  if (imageBusy) { imageAgain = true; return; }
  imageBusy = true;
  try {
    const p = state.ports, got = new Map();
    for (const port of new Set(p.ab ? [p.a, p.b] : [p.a])) {
      if (port) got.set(port, await fetchImage(port, preview));
    }
    // the FLIP map of the full-size images (a drag's previews keep the last one)
    if (p.ab && p.mode === 'flip' && p.a && p.b && !preview) {
      got.set(flipKey(p.a, p.b), await fetchFlip(p.a, p.b));
    }
    storeImages(got);
    if (preview && (dragging() || flying())) countUpdate();
    if (!preview && p.ab) refreshMetrics();
  } catch (e) { showRequestError(String(e.message || e)); }
  imageBusy = false;
  if (imageAgain) {
    imageAgain = false;
    refreshImages(state.server && state.server.last_run === 'preview');
  }
}

// The A/B metrics line; stale: of an earlier run than the one shown (greyed until the new
// numbers come, so old numbers never pass for the current image's).
function showMetrics(text, stale) {
  const el = $('metrics');
  if (text !== null) el.textContent = text;
  el.classList.toggle('stale', stale);
  el.title = stale ? 'of an earlier run: the shown run\'s numbers are on their way' : '';
}

let metricsBusy = false, metricsAgain = false;
// The A/B metrics for the chosen ports; a call while one is on its way asks once more after.
async function refreshMetrics() {
  if (metricsBusy) { metricsAgain = true; return; }
  metricsBusy = true;
  // the text names the ports asked for, which may have changed by the time it answers
  const { a: A, b: B, ref } = state.ports;
  const q = encodeURIComponent;
  try {
    const resp = await api(`/api/metrics?ref=${q(ref)}&a=${q(A)}&b=${q(B)}`);
    if (!resp.ok) { showMetrics(`metrics: ${await errorText(resp)}`, false); return; }
    const m = await resp.json();
    const one = (k, port, r) => `${k} ${port}: ` +
      (r ? `RMSE ${r.rmse.toPrecision(4)} SSIM ${r.ssim.toFixed(4)}` : '-');
    showMetrics(`${one('A', A, m.a)}  |  ${one('B', B, m.b)}  against ${ref} (run ${state.gen})`,
      false);
  } catch (e) { showMetrics(`metrics: ${e}`, false); }
  finally {
    metricsBusy = false;
    if (metricsAgain) { metricsAgain = false; refreshMetrics(); }
  }
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
// The toolbar's display controls: each sets its field of state.display.
function wireDisplay() {
  const exposure = $('exposure');
  exposure.addEventListener('input', () => setDisplay({ stops: +exposure.value }));
  $('fit-btn').onclick = () => setDisplay({ stops: 0 });
  $('channel').onchange = () => setDisplay({ channel: $('channel').value });
  $('colormap').onchange = () => setDisplay({ colormap: $('colormap').value });
  $('tonemap').onchange = () => setDisplay({ curve: $('tonemap').value });
  $('range').onchange = () => setDisplay({ range: $('range').value });
}

// The port lists and the A/B view: each sets its field of state.ports.
function wirePorts() {
  const reload = () => refreshImages(state.server && state.server.last_run === 'preview');
  $('port-a').onchange = () => { setPorts({ a: $('port-a').value }); reload(); };
  $('port-b').onchange = () => { setPorts({ b: $('port-b').value }); reload(); };
  $('ab-enable').onchange = () => {
    setPorts({ ab: $('ab-enable').checked });
    // the numbers of an A/B view that is gone must not stay on screen (issue 46)
    if (!state.ports.ab) showMetrics('metrics: -', false);
    reload();
  };
  $('ab-mode').onchange = () => { setPorts({ mode: $('ab-mode').value }); reload(); };
  $('port-ref').onchange = () => { setPorts({ ref: $('port-ref').value }); refreshMetrics(); };
  $('ab-swap').onclick = swapAB;
  $('ref-open').onclick = openReference;
  $('ref-path').addEventListener('keydown', (ev) => { if (ev.key === 'Enter') openReference(); });
}

// A and B trade places (the button, key X): the images are both at hand; the metrics and a
// FLIP map (B is its reference) are asked for again.
function swapAB() {
  const p = state.ports;
  setPorts({ a: p.b, b: p.a });
  refreshImages(state.server && state.server.last_run === 'preview');
}

// An EXR file as B and as the metrics' reference (POST /api/reference): the server reads it
// and lists it among the ports as file:PATH; a missing or bad file is the error bar's.
async function openReference() {
  const path = $('ref-path').value.trim();
  try {
    const resp = await api('/api/reference', `path=${path}`);
    if (!resp.ok) { showRequestError(`reference ${path}: ${await errorText(resp)}`); return; }
    showRequestError('');
    applyState(await resp.json());
    const file = state.server.reference_file;
    setPorts({ ab: true, b: file, ref: file });
    refreshImages(false);
  } catch (e) { showRequestError(`reference ${path}: ${e}`); }
}

// The image view's keys: F fit, 1 one to one, X swap A and B, H home.
const KEYS = { f: fit, F: fit, 1: oneToOne, x: swapAB, X: swapAB, h: goHome, H: goHome };

function wire() {
  subscribe(scheduleRender);
  panelActions({ pick: pickNode, showPort, send: sendParam, idle: () => setSender.idle });
  // the stage changes size with the window and with the error bars above it
  new ResizeObserver(scheduleRender).observe($('stage'));
  wireMouse(onRunAnswer);
  wireTime(onRunAnswer);
  wireEdit(onRunAnswer);
  wireDisplay();
  wirePorts();
  $('save-btn').onclick = saveVariant;
  $('diagram-expand').onclick = () => enlargeDiagram(true);
  $('diagram-close').onclick = () => enlargeDiagram(false);
  $('cam-home').onclick = goHome;
  $('zoom-fit').onclick = fit;
  $('zoom-one').onclick = oneToOne;
  wireCamPanel();
  wireCamPath();
  wireFly();
  wireHistory({ send: (n, p, v) => sendParam(n, p, v, 0), pick: (n) => pickNode(n, false),
    refresh: () => refreshParamValues(true) });
  document.addEventListener('keydown', (ev) => {
    if (ev.key === 'Escape') enlargeDiagram(false);
    const typing = ev.target.closest && ev.target.closest('input, select, textarea');
    if (KEYS[ev.key] && !typing && !ev.ctrlKey && !ev.metaKey && !ev.altKey) KEYS[ev.key]();
  });
  $('save-name').addEventListener('keydown', (ev) => { if (ev.key === 'Enter') saveVariant(); });
  releaseFocus();
}

// A list, checkbox, slider or button used with the mouse gives the keyboard back to the
// page: a list kept it for its type-ahead (H chose port h.depth instead of going home), and
// a focused checkbox took the space of a space + drag (A/B turned on, the camera orbited).
// Keyboard use (Tab, arrows, Enter) keeps the focus where it is.
function releaseFocus() {
  let pointed = null; // what the last mouse press was on
  document.addEventListener('pointerdown', (ev) => { pointed = ev.target; }, true);
  const used = (ev, kinds) => ev.target.matches && ev.target.matches(kinds) &&
    pointed && (pointed === ev.target || ev.target.contains(pointed));
  document.addEventListener('change', (ev) => {
    if (used(ev, 'select, input[type=checkbox], input[type=range]')) ev.target.blur();
  });
  document.addEventListener('click', (ev) => { if (used(ev, 'button')) ev.target.blur(); });
}

async function start() {
  wire();
  try {
    const resp = await api('/api/state');
    if (!resp.ok) { showRequestError(`/api/state: ${await errorText(resp)}`); return; }
    applyState(await resp.json());
  } catch (e) { showRequestError(`cannot reach the server: ${e}`); return; }
  render();
  setTimeout(poll, 500);
}
start();
