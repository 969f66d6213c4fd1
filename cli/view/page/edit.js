// The graph editor (docs/viewer.md, "Editing the graph"): add a node of a type from the
// registry with its inputs chosen, rewire an input of the selected node, remove it, and
// save the edited graph file as a new one beside it. Every edit is a graph statement sent
// to /api/edit (docs/viewer-api.md); the server edits the file's text and loads it, so its
// checks and file:line:column messages are the graph file's. The selects offer only the
// outputs whose type the input takes; the server's check is the authority all the same.
import { api, errorText } from './net.js';
import { findNode, state, subscribe } from './state.js';
import { $, setBusy } from './ui.js';

let types = null;      // /api/types: name -> {name, doc, inputs, outputs}
let answer = null;     // app.js's handler of a changing request's answer
let shownSig = '';     // what the selected node's input rows were built for
let addSig = '';       // what the add form's input rows were built for

// Every output of the graph as {value: 'node.port', type}, those of `except` left out.
function outputs(except) {
  return state.server.nodes.filter((n) => n.name !== except)
    .flatMap((n) => n.outputs.map((o) => ({ value: `${n.name}.${o.port}`, type: o.type })));
}

// The outputs an input that takes `accepted` types may read (an output of no known type
// yet is offered: the server decides).
const compatible = (accepted, except) =>
  outputs(except).filter((o) => !o.type || accepted.includes(o.type));

function makeSelect(values, current, none) {
  const sel = document.createElement('select');
  if (none) sel.append(new Option('(none)', ''));
  for (const v of values) sel.append(new Option(v, v));
  if (current && !values.includes(current)) sel.append(new Option(current, current));
  sel.value = current || (none ? '' : values[0] || '');
  return sel;
}

function showResult(text, ok) {
  const out = $('edit-result');
  out.textContent = text;
  out.classList.toggle('err', !ok);
}

// Sends edits (graph statements); the answer is the new state, or the refusal's messages.
async function send(edits, done) {
  setBusy(true);
  try {
    const resp = await api('/api/edit', edits);
    if (resp.ok) {
      showResult(done, true);
      shownSig = addSig = '';
      await answer(edits, resp);
    } else {
      showResult(`refused: ${await errorText(resp)}`, false);
      shownSig = ''; // a refused rewire's select goes back to what the graph reads
      showSelected();
    }
  } catch (e) { showResult(`error: ${e}`, false); }
  setBusy(false);
}

// ---- add --------------------------------------------------------------------------------
// A name for a new node of `type` no node has: type1, type2, ...
function freeName(type) {
  for (let i = 1; ; i++) if (!findNode(`${type}${i}`)) return `${type}${i}`;
}

// The chosen type's inputs, each with a select of the outputs it may read.
function showAddInputs() {
  const t = types && types.get($('edit-type').value);
  if (!t || !state.server) return;
  const sig = `${t.name}|${outputs('').map((o) => `${o.value}:${o.type}`).join()}`;
  $('edit-name').placeholder = freeName(t.name);
  if (sig === addSig) return;
  addSig = sig;
  $('edit-add-inputs').replaceChildren(...t.inputs.map((i) => {
    const row = document.createElement('label');
    row.className = 'edit-input';
    const sel = makeSelect(compatible(i.types, '').map((o) => o.value), '', i.optional);
    sel.dataset.port = i.port;
    row.append(`${i.port} (${i.types.join('|')}${i.optional ? ', optional' : ''}) `, sel);
    return row;
  }));
}

function addNode() {
  const type = $('edit-type').value;
  const name = $('edit-name').value.trim() || freeName(type);
  const args = [...$('edit-add-inputs').querySelectorAll('select')]
    .filter((s) => s.value).map((s) => `${s.dataset.port}=${s.value}`);
  $('edit-name').value = '';
  send(`${name} = ${type}(${args.join(', ')})`, `added ${name}`);
}

// ---- the selected node ------------------------------------------------------------------
// Its inputs, each with a select of the outputs it may read (changing one rewires it).
function showSelected() {
  const n = findNode(state.selected);
  $('edit-remove').disabled = !n;
  $('edit-remove').textContent = n ? `remove ${n.name}` : 'remove';
  const t = n && types && types.get(n.type);
  const sig = n ? `${n.name}|${n.inputs.map((i) => i.from).join()}|` +
    outputs(n.name).map((o) => o.value).join() : '';
  if (sig === shownSig) return;
  shownSig = sig;
  if (!t) { $('edit-inputs').replaceChildren(); return; }
  $('edit-inputs').replaceChildren(...n.inputs.map((i) => {
    const port = t.inputs.find((p) => p.port === i.port);
    const accepted = port ? port.types : [i.type];
    const row = document.createElement('label');
    row.className = 'edit-input';
    const sel = makeSelect(compatible(accepted, n.name).map((o) => o.value), i.from || '',
      !i.from);
    sel.dataset.port = i.port;
    sel.onchange = () => {
      if (sel.value) send(`set ${n.name}.${i.port} = ${sel.value}`, `${n.name}.${i.port} \u2190 ${sel.value}`);
    };
    row.append(`${i.port} \u2190 `, sel);
    return row;
  }));
}

function removeNode() {
  if (state.selected) send(`remove ${state.selected}`, `removed ${state.selected}`);
}

// ---- save and discard -------------------------------------------------------------------
async function post(path, body, done) {
  try {
    const resp = await api(path, body);
    if (!resp.ok) { showResult(`error: ${await errorText(resp)}`, false); return; }
    const j = await resp.json();
    showResult(done(j), true);
    if (j.nodes) { shownSig = addSig = ''; await answer(body, new Response(JSON.stringify(j))); }
  } catch (e) { showResult(`error: ${e}`, false); }
}

function showEditState() {
  const st = state.server;
  $('edit-state').textContent = !st || !st.edited ? '' :
    st.unsaved_edits ? `(${st.unsaved_edits} unsaved edits)` : '(edited, saved)';
  $('edit-discard').disabled = !st || !st.edited;
}

// ---- wiring -----------------------------------------------------------------------------
async function loadTypes() {
  const resp = await api('/api/types');
  if (!resp.ok) { showResult(`/api/types: ${await errorText(resp)}`, false); return; }
  const list = (await resp.json()).types;
  types = new Map(list.map((t) => [t.name, t]));
  $('edit-type').replaceChildren(...list.map((t) => {
    const o = new Option(t.name, t.name);
    o.title = t.doc;
    return o;
  }));
  refresh();
}

function refresh() {
  if (!state.server) return;
  showEditState();
  showAddInputs();
  showSelected();
}

// onAnswer(body, resp): app.js's handler of the new state (or the error) of a request.
export function wireEdit(onAnswer) {
  answer = onAnswer;
  subscribe((what) => { if (what === 'server' || what === 'select') refresh(); });
  $('edit-type').onchange = showAddInputs;
  $('edit-add').onclick = addNode;
  $('edit-remove').onclick = removeNode;
  $('edit-save').onclick = () => post('/api/edit/save', `name=${$('edit-save-name').value.trim()}`,
    (j) => { $('edit-state').textContent = '(edited, saved)'; return `wrote ${j.path}`; });
  $('edit-discard').onclick = () => post('/api/edit/discard', '', () => 'edits discarded');
  loadTypes();
}
