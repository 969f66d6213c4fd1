// Undo and redo of parameter changes (docs/viewer.md, "Undo and redo"): each committed
// change of a control in the node panel is one step from the value it had when the hand
// reached for it to the value it was left at, so a slider drag is one step however many
// values it sent. Undo (Ctrl+Z, the *undo* button) selects the step's node and sends its old
// value through /api/set, redo (Ctrl+Shift+Z, Ctrl+Y, *redo*) its new one; the panel shows
// the value once the graph has run with it. A new change after an undo drops the steps
// that were undone. The history is this page's: a reload of the page starts it empty, and
// a value changed on disk or by another page is not a step.
import { findNode, state, subscribe } from './state.js';
import { textEntry } from './fly.js';
import { $ } from './ui.js';

const LIMIT = 200;
const steps = []; // {node, param, from, to}
let at = 0;       // steps[0 .. at) are done; steps[at ..) undone
const starts = new Map(); // "node.param" -> the server's value when the control was reached for
let pending = null;       // {node, param, value, dir}: an undo (dir -1) or redo (+1) on its way
// send(node, param, value): a parameter change; pick(node): show the node's panel;
// refresh(): the panel's controls from the server's values, the focused one too
const on = {};

const serverValue = (node, param) =>
  findNode(node)?.params.find((p) => p.name === param)?.value;
// Two values as the same: the same text, or numbers equal once read ("0.50" and "0.5").
const same = (a, b) => a === b || (a !== '' && b !== '' && Number(a) === Number(b));

// node and param of a control of the node panel (params.js: id param-NODE-PARAM[-slider])
function controlOf(el) {
  const row = el.closest && el.closest('#params .param');
  return row && state.selected ? { node: state.selected, param: row.dataset.param } : null;
}

// The value a control holds as the panel sends it: a slider's is in its number box.
function controlValue({ node, param }) {
  const el = $(`param-${node}-${param}`);
  if (!el) return undefined;
  return el.type === 'checkbox' ? (el.checked ? 'true' : 'false') : el.value;
}

// The hand reaches for a control: remember the value the graph has now (a drag's start).
function reach(ev) {
  const c = controlOf(ev.target);
  if (!c) return;
  starts.set(`${c.node}.${c.param}`, serverValue(c.node, c.param));
}

// A committed change: one step from the start value to the control's value.
function commit(ev) {
  const c = controlOf(ev.target);
  if (!c) return;
  const key = `${c.node}.${c.param}`;
  const from = starts.has(key) ? starts.get(key) : serverValue(c.node, c.param);
  starts.delete(key);
  const to = controlValue(c);
  if (from === undefined || to === undefined || to === '' || same(from, to)) return;
  steps.splice(at, steps.length - at, { ...c, from, to });
  if (steps.length > LIMIT) steps.shift();
  at = steps.length;
  showButtons();
}

// A set the server refused (app.js): an undo or redo of it did not happen (the history
// stays where it was, the step kept); a change is no step (the newest of that value goes).
export function refusedSet(node, param, value) {
  if (pending && pending.node === node && pending.param === param && same(pending.value, value)) {
    at -= pending.dir;
    pending = null;
    showButtons();
    return;
  }
  for (let i = at - 1; i >= 0; i--) {
    const s = steps[i];
    if (s.node === node && s.param === param && same(s.to, value)) {
      steps.splice(i, 1);
      at--;
      break;
    }
  }
  showButtons();
}

function go(step, value, dir) {
  on.pick(step.node);
  pending = { node: step.node, param: step.param, value, dir };
  on.send(step.node, step.param, value);
  showButtons();
}

export function undo() {
  if (at > 0) { at--; go(steps[at], steps[at].from, -1); }
}

export function redo() {
  if (at < steps.length) { at++; go(steps[at - 1], steps[at - 1].to, 1); }
}

function label(s, v0, v1) { return `${s.node}.${s.param}: ${v0} \u2192 ${v1}`; }

function showButtons() {
  const u = $('undo-btn'), r = $('redo-btn');
  u.disabled = at === 0;
  r.disabled = at === steps.length;
  u.title = at ? `undo ${label(steps[at - 1], steps[at - 1].to, steps[at - 1].from)} (Ctrl+Z)`
    : 'nothing to undo (Ctrl+Z)';
  r.title = at < steps.length ? `redo ${label(steps[at], steps[at].from, steps[at].to)} ` +
    '(Ctrl+Shift+Z, Ctrl+Y)' : 'nothing to redo (Ctrl+Shift+Z, Ctrl+Y)';
  $('history-count').textContent = `${at} / ${steps.length}`;
}

function onKey(ev) {
  if (!(ev.ctrlKey || ev.metaKey) || ev.altKey || textEntry(ev.target)) return;
  const k = ev.key.toLowerCase();
  if (k === 'z' && !ev.shiftKey) undo();
  else if ((k === 'z' && ev.shiftKey) || k === 'y') redo();
  else return;
  ev.preventDefault();
}

export function wireHistory(actions) {
  Object.assign(on, actions);
  const params = $('params');
  params.addEventListener('pointerdown', reach, true);
  params.addEventListener('focusin', reach, true);
  params.addEventListener('change', commit, true);
  $('undo-btn').onclick = undo;
  $('redo-btn').onclick = redo;
  document.addEventListener('keydown', onKey);
  // the panel shows an undone value once the graph has run with it (after applyState)
  subscribe((what) => {
    if (what !== 'server' || !pending) return;
    if (!same(serverValue(pending.node, pending.param), pending.value)) return;
    pending = null;
    setTimeout(() => on.refresh(), 0);
  });
  showButtons();
}
