// Keyboard fly (docs/viewer.md, "Keys"), as Mogwai's and a game's: W/S forward and back, A/D
// left and right, Q/E down and up, the arrow keys turn the view (yaw and pitch about the
// eye), Shift four times faster. While keys are held the camera moves every animation
// frame and each pose is sent as a preview run (one request on its way, the latest pose:
// mouse.js sendCamera); releasing the last key sends a full run, as the end of a drag does.
// Speed scales with the scene: half the eye-to-target distance a second (which a fly keeps),
// so a fly crosses a Cornell box and a courtyard in about the same time. Keys go to the fly
// only when the focus is not in a text, number or list box, and never with Ctrl, Alt or Meta.
import { fly, look, targetDistance } from './camera.js';
import { sendCamera } from './mouse.js';
import { state, steer } from './state.js';
import { $ } from './ui.js';

// key -> [forward, right, up] or [yaw, pitch] (the arrows)
const MOVES = { w: [1, 0, 0], s: [-1, 0, 0], a: [0, -1, 0], d: [0, 1, 0], q: [0, 0, -1],
  e: [0, 0, 1] };
const TURNS = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] };
const SPEED = 0.5;              // eye-to-target distances a second
const TURN = Math.PI / 3;       // radians a second (60 degrees)
const FAST = 4;                 // with Shift

const held = new Set();
let shift = false, last = 0, frame = 0;

const keyOf = (ev) => (ev.key.length === 1 ? ev.key.toLowerCase() : ev.key);
const flyKey = (k) => k in MOVES || k in TURNS;

// Whether a key press belongs to a control: typing in a box, choosing in a list.
export function typingIn(target) {
  const el = target && target.closest && target.closest('input, select, textarea');
  return Boolean(el) && !(el.type === 'checkbox' || el.type === 'button');
}

// Whether the focus is in a box that edits text (where Ctrl+Z is the box's own undo); a
// slider, a list or a checkbox is not one.
export function textEntry(target) {
  const el = target && target.closest && target.closest('input, textarea');
  return Boolean(el) && (el.tagName === 'TEXTAREA' || ['text', 'number', 'search'].includes(el.type));
}

function step(now) {
  frame = 0;
  if (!held.size || !state.cam) return;
  const dt = Math.min(0.1, (now - last) / 1000 || 0);
  last = now;
  const cam = structuredClone(state.cam);
  const k = (shift ? FAST : 1) * dt;
  let f = 0, r = 0, u = 0, yaw = 0, pitch = 0;
  for (const key of held) {
    if (MOVES[key]) { f += MOVES[key][0]; r += MOVES[key][1]; u += MOVES[key][2]; }
    if (TURNS[key]) { yaw += TURNS[key][0]; pitch += TURNS[key][1]; }
  }
  if (yaw || pitch) look(cam, yaw * TURN * k, pitch * TURN * k);
  if (f || r || u) fly(cam, f, r, u, SPEED * targetDistance(cam) * k);
  if (dt > 0) {
    steer(cam, true);
    sendCamera(true);
  }
  frame = requestAnimationFrame(step);
}

// The last key up (or the window losing the keys): a full run of where the fly ended.
function land() {
  held.clear();
  cancelAnimationFrame(frame);
  frame = 0;
  if (!state.steering || !state.cam) return;
  steer(state.cam, false);
  sendCamera(false);
}

function onKeyDown(ev) {
  const key = keyOf(ev);
  shift = ev.shiftKey;
  if (!flyKey(key) || ev.ctrlKey || ev.altKey || ev.metaKey || typingIn(ev.target)) return;
  ev.preventDefault(); // arrows would scroll the column
  if (!state.cam) {
    $('cam-ups').textContent = 'camera: this graph has no camera';
    return;
  }
  held.add(key);
  if (!frame) {
    last = performance.now();
    frame = requestAnimationFrame(step);
  }
}

function onKeyUp(ev) {
  shift = ev.shiftKey;
  const key = keyOf(ev);
  if (!held.has(key)) return;
  held.delete(key);
  if (!held.size) land();
}

export function wireFly() {
  document.addEventListener('keydown', onKeyDown);
  document.addEventListener('keyup', onKeyUp);
  window.addEventListener('blur', () => { if (held.size) land(); });
}

// Whether a fly is on: its preview images count as camera updates (app.js).
export const flying = () => held.size > 0;
