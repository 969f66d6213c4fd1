// Camera path recording (docs/viewer.md, "Camera path"): *record* adds the current camera
// as a key at a time (0 for the first, then one second after the last; each time is
// editable), *record while flying* adds a key every `period` seconds of a fly or a drag, the
// list shows the keys (x removes one), and *save path* asks the server to write them as
// `camera_key` lines in NAME.scene beside the graph (POST /api/save_path, docs/viewer-api.md),
// a scene that includes the graph's own, so that `ssgraph run GRAPH --scene NAME.scene
// --frames N` flies the path. The keys live in this page only (a reload forgets them).
import { api, errorText } from './net.js';
import { state, subscribe } from './state.js';
import { $, wireNumber as num } from './ui.js';

const keys = []; // {time, cam}
let autoTimer = 0;

function say(text, bad) {
  const el = $('path-result');
  el.textContent = text;
  el.classList.toggle('err', Boolean(bad));
}

// One key at `time` (default: 0, else a second after the last) of the current camera.
export function recordKey(time) {
  if (!state.cam) { say('this graph has no camera', true); return; }
  const t = time ?? (keys.length ? keys[keys.length - 1].time + 1 : 0);
  keys.push({ time: t, cam: structuredClone(state.cam) });
  showKeys();
}

function showKeys() {
  const rows = keys.map((k, i) => {
    const tr = document.createElement('tr');
    const time = document.createElement('input');
    time.type = 'number';
    time.step = 'any';
    time.min = '0';
    time.value = num(k.time);
    time.className = 'key-time';
    time.addEventListener('change', () => {
      const t = Number(time.value);
      if (time.value.trim() !== '' && Number.isFinite(t) && t >= 0) k.time = t;
      else time.value = num(k.time);
      showCount();
    });
    const p = k.cam.position.map((x) => x.toFixed(2)).join(', ');
    const drop = document.createElement('button');
    drop.textContent = 'x';
    drop.title = 'remove this key';
    drop.onclick = () => { keys.splice(i, 1); showKeys(); };
    tr.insertCell().append(time);
    tr.insertCell().textContent = `[${p}]`;
    tr.insertCell().append(drop);
    return tr;
  });
  $('path-keys').tBodies[0].replaceChildren(...rows);
  showCount();
}

// How many keys, and how many frames `run --frames N` needs to fly the whole path: keys 1 s
// apart are 30 frames apart, and three keys run with --frames 3 gave three near-identical
// images (issue 46's newcomer pass).
function showCount() {
  const end = keys.length ? Math.max(...keys.map((k) => k.time)) : 0;
  $('path-count').textContent = `${keys.length} key${keys.length === 1 ? '' : 's'}` +
    (keys.length > 1 ? `, to ${num(end)} s: --frames ${Math.round(end * 30) + 1} at 30 fps` : '');
  $('path-count').title = 'frame f of `ssgraph run --frames N` is at f / fps seconds: 30 fps, ' +
    'or the scene\'s frame_rate';
}

// The keys as the endpoint takes them: 11 numbers a key, keys apart by ';', by time;
// null with the reason when two keys share a time.
function keysText() {
  const sorted = [...keys].sort((a, b) => a.time - b.time);
  for (let i = 1; i < sorted.length; i++) {
    if (sorted[i].time === sorted[i - 1].time) return null;
  }
  return sorted.map(({ time, cam: c }) =>
    [time, ...c.position, ...c.target, ...c.up, c.fov_y].map(num).join(',')).join(';');
}

async function savePath() {
  const name = $('path-name').value.trim();
  if (keys.length < 2) { say('a path needs two keys or more: press record', true); return; }
  const text = keysText();
  if (text === null) { say('two keys have the same time: change one', true); return; }
  try {
    const resp = await api('/api/save_path', `name=${encodeURIComponent(name)}&keys=${text}`);
    if (resp.ok) say(`wrote ${(await resp.json()).path}`, false);
    else say(`error: ${await errorText(resp)}`, true);
  } catch (e) { say(`error: ${e}`, true); }
}

// Record while flying: while the camera is being steered (a fly or a drag), a key every
// `period` seconds of the clock, each `period` after the last key (the first at 0).
function autoRecord(on) {
  clearInterval(autoTimer);
  autoTimer = 0;
  if (!on) return;
  const period = Math.max(0.05, Number($('path-period').value) || 0.5);
  autoTimer = setInterval(() => {
    if (state.steering && state.cam) recordKey(keys.length ? keys[keys.length - 1].time + period : 0);
  }, period * 1000);
}

export function wireCamPath() {
  $('path-record').onclick = () => recordKey();
  $('path-clear').onclick = () => { keys.length = 0; showKeys(); };
  $('path-save').onclick = savePath;
  $('path-name').addEventListener('keydown', (ev) => { if (ev.key === 'Enter') savePath(); });
  $('path-auto').onchange = () => autoRecord($('path-auto').checked);
  $('path-period').onchange = () => autoRecord($('path-auto').checked);
  subscribe((what) => { if (what === 'server') $('path-record').disabled = !state.cam; });
  showKeys();
}
