// The camera panel (docs/viewer.md, "Camera"): the camera the page drives as numbers, one
// box per vector (position, target, up: "x, y, z") and one for the field of view. The boxes
// follow the camera as it moves (a drag, a fly, a run of the sequence), except the box the
// user is editing; Enter or leaving a changed box sends the whole camera (a full run). Text
// that is not a camera is refused in the page with the reason beside the boxes, and the
// camera stays as it was.
import { cameraFault } from './camera.js';
import { sendCamera } from './mouse.js';
import { state, steer, subscribe } from './state.js';
import { $ } from './ui.js';

const VECTORS = ['position', 'target', 'up'];
const BOXES = [...VECTORS, 'fov'];
const box = (name) => $(`cam-${name}`);
const num = (x) => String(parseFloat(x.toPrecision(6)));

// The vector in a box's text: three finite numbers apart by commas or spaces, else null.
export function parseVector(text) {
  const parts = text.trim().replace(/^\[|\]$/g, '').split(/[\s,]+/).filter(Boolean);
  if (parts.length !== 3) return null;
  const v = parts.map(Number);
  return v.every(Number.isFinite) ? v : null;
}

function showMessage(text) {
  const el = $('cam-msg');
  el.textContent = text;
  el.classList.toggle('err', Boolean(text));
}

// The boxes from state.cam; the one with the focus keeps what the user is typing.
function fill() {
  const c = state.cam;
  for (const name of BOXES) {
    const el = box(name);
    el.disabled = !c;
    if (!c || el === document.activeElement) continue;
    el.value = name === 'fov' ? num(c.fov_y) : c[name].map(num).join(', ');
    el.classList.remove('refused');
  }
}

// The camera the boxes say, or null with the reason shown and the bad box marked.
function readBoxes() {
  const cam = structuredClone(state.cam);
  for (const name of VECTORS) {
    const v = parseVector(box(name).value);
    if (!v) return refuse(name, `${name}: expected three numbers "x, y, z"`);
    cam[name] = v;
  }
  const fov = Number(box('fov').value.trim());
  if (box('fov').value.trim() === '' || !Number.isFinite(fov)) {
    return refuse('fov', 'fov: expected a number of degrees');
  }
  cam.fov_y = fov;
  const fault = cameraFault(cam);
  return fault ? refuse(fault.part, fault.why) : cam;
}

function refuse(name, why) {
  box(name).classList.add('refused');
  showMessage(`refused: ${why}; the camera stays`);
  return null;
}

// Sends the camera in the boxes when it differs from the current one.
function apply() {
  if (!state.cam) return;
  for (const name of BOXES) box(name).classList.remove('refused');
  const cam = readBoxes();
  if (!cam) return;
  showMessage('');
  if (JSON.stringify(cam) === JSON.stringify(state.cam)) return;
  steer(cam, false);
  sendCamera(false);
}

export function wireCamPanel() {
  for (const name of BOXES) {
    const el = box(name);
    el.addEventListener('change', apply);
    el.addEventListener('keydown', (ev) => { if (ev.key === 'Enter') { ev.preventDefault(); apply(); } });
    // a refused text stays while the user corrects it; leaving the box shows the camera again
    el.addEventListener('blur', () => setTimeout(() => {
      if (!BOXES.some((n) => box(n) === document.activeElement)) fill();
    }, 0));
  }
  subscribe((what) => { if (what === 'camera' || what === 'server') fill(); });
}
