// The mouse on the canvas: drag to orbit the camera, right or shift drag to pan it, Ctrl or
// Alt + wheel to dolly it (or the plain wheel with the toolbar's "wheel: camera"); the wheel
// zooms the image about the mouse and a middle or space drag pans it (viewport.js); drag the
// A/B divider, hover for the pixel readout. The page moves its own copy of the camera
// (state.cam) and sends each pose; while the user steers, the server's answers never
// overwrite it (state.js receive), so a slow answer does not make the camera jump back.
import { orbit, pan, zoom } from './camera.js';
import { LatestSender } from './net.js';
import { framePos } from './render.js';
import { setDivider, setPointer, state, steer } from './state.js';
import { $, wireNumber as num } from './ui.js';
import { panBy, zoomAt } from './viewport.js';

let drag = null;       // the current canvas drag: {mode, x, y, moved}
let spaceDown = false; // space held: a left drag pans the image
let wheelTimer = null; // the full-size run after a wheel burst
let camSender = null;
const ups = [];        // times of the preview images drawn during a drag

export function sendCamera(preview) {
  const c = state.cam;
  const body = `position=${c.position.map(num)}&target=${c.target.map(num)}` +
    `&up=${c.up.map(num)}&fov=${num(c.fov_y)}&preview=${preview ? 1 : 0}`;
  camSender.send('camera', body);
}

// Updates per second while dragging: preview images drawn in the last second.
export function countUpdate() {
  const now = performance.now();
  ups.push(now);
  while (ups.length && now - ups[0] > 1000) ups.shift();
  $('cam-ups').textContent = `camera: ${ups.length} updates/s`;
}

const noCamera = () => { $('cam-ups').textContent = 'camera: this graph has no camera'; };

// Whether a mouse event is within 6 screen pixels of the A/B divider.
function nearDivider(ev) {
  const cv = $('view'), [fx] = framePos(ev);
  const p = state.ports;
  return p.ab && p.mode === 'split' &&
    Math.abs(fx - state.divider * cv.width) < 6 * cv.width / cv.getBoundingClientRect().width;
}

function dragMode(ev) {
  if (nearDivider(ev)) return 'divider';
  if (ev.button === 1 || spaceDown) return 'image';
  return ev.button === 2 || ev.shiftKey ? 'pan' : 'orbit';
}

function onPointerDown(ev) {
  // the image takes the keyboard: a port list or a number box kept it after use, and H, F,
  // 1, X or WASD went to the list's type-ahead (H picked port h.depth) or into the box
  // (issue 46's newcomer pass); docs/viewer.md, "Keys"
  $('view').focus({ preventScroll: true });
  const mode = dragMode(ev);
  if (mode !== 'divider' && mode !== 'image' && !state.cam) {
    noCamera();
    return;
  }
  ev.preventDefault();
  $('view').setPointerCapture(ev.pointerId);
  drag = { mode, x: ev.clientX, y: ev.clientY, moved: false };
  ups.length = 0;
  $('view').classList.add('dragging');
}

function onPointerMove(ev) {
  const cv = $('view');
  if (!drag) {
    setPointer(ev);
    cv.classList.toggle('divider', nearDivider(ev));
    return;
  }
  const dx = ev.clientX - drag.x, dy = ev.clientY - drag.y;
  drag.x = ev.clientX; drag.y = ev.clientY;
  const r = cv.getBoundingClientRect();
  if (drag.mode === 'divider') { setDivider((ev.clientX - r.left) / r.width); return; }
  if (!dx && !dy) return;
  if (drag.mode === 'image') { panBy(dx * cv.width / r.width, dy * cv.height / r.height); return; }
  const cam = structuredClone(state.cam);
  if (drag.mode === 'orbit') orbit(cam, dx, dy); else pan(cam, dx, dy, r.height);
  drag.moved = true;
  steer(cam, true);
  sendCamera(true);
}

function onPointerUp() {
  if (!drag) return;
  const d = drag;
  drag = null;
  $('view').classList.remove('dragging');
  if (d.mode === 'divider' || d.mode === 'image' || !d.moved) return;
  steer(state.cam, false);
  sendCamera(false);
}

// The wheel zooms the image about the mouse; with Ctrl or Alt (or "wheel: camera") it
// dollies the camera.
function onWheel(ev) {
  if (!(ev.ctrlKey || ev.altKey || $('wheel-mode').value === 'camera')) {
    ev.preventDefault();
    const [px, py] = framePos(ev);
    zoomAt(2 ** (-ev.deltaY / (ev.deltaMode ? 3 : 200)), px, py);
    return;
  }
  if (!state.cam) return;
  ev.preventDefault();
  const cam = structuredClone(state.cam);
  zoom(cam, ev.deltaY);
  steer(cam, true);
  sendCamera(true);
  clearTimeout(wheelTimer);
  wheelTimer = setTimeout(() => { steer(state.cam, false); sendCamera(false); }, 250);
}

// Back to the camera the graph opened with (the home button, key H): an orbit past the
// one-sided walls of a box left no way back but a restart (issue 46).
export function goHome() {
  if (!state.home) {
    noCamera();
    return;
  }
  steer(structuredClone(state.home), false);
  sendCamera(false);
}

// onRunAnswer(body, resp): what app.js does with the answer to a camera request.
export function wireMouse(onRunAnswer) {
  camSender = new LatestSender('/api/camera', onRunAnswer);
  const cv = $('view');
  cv.addEventListener('pointerdown', onPointerDown);
  cv.addEventListener('pointermove', onPointerMove);
  cv.addEventListener('pointerup', onPointerUp);
  cv.addEventListener('pointercancel', onPointerUp);
  cv.addEventListener('wheel', onWheel, { passive: false });
  cv.addEventListener('contextmenu', (ev) => ev.preventDefault());
  cv.addEventListener('mousedown', (ev) => { if (ev.button === 1) ev.preventDefault(); }); // no autoscroll
  // space held over the page (not in a text box) turns a left drag into an image pan
  const typing = (ev) => ev.target.closest && ev.target.closest('input, select, textarea');
  document.addEventListener('keydown', (ev) => {
    if (ev.key !== ' ' || typing(ev)) return;
    spaceDown = true;
    ev.preventDefault();
  });
  document.addEventListener('keyup', (ev) => { if (ev.key === ' ') spaceDown = false; });
  window.addEventListener('blur', () => { spaceDown = false; });
}

// Whether a drag (not a divider move) is on: preview images count as camera updates.
export const dragging = () => drag !== null && drag.mode !== 'divider' && drag.mode !== 'image';
