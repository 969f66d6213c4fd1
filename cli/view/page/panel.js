// The page around the image: the header, the port lists, the last run's table, the graph
// diagram and the selected node's panel, all drawn from the state (state.js). Clicks call
// the actions app.js gives (panelActions), so this module changes no state itself.
import { api, errorText } from './net.js';
import { paramRow } from './params.js';
import { findNode, state } from './state.js';
import { $, fmt } from './ui.js';

// pick(name, showOutput): select a node; showPort(port): show it as A;
// send(node, param, text, delay_ms): a parameter change; idle(): no change on its way.
const on = {};
export function panelActions(actions) { Object.assign(on, actions); }

export function showHeader(st) {
  const base = (path) => path.split('/').pop();
  $('hdr-graph').textContent = base(st.graph);
  $('hdr-graph').title = st.graph;
  $('hdr-scene').textContent = st.scene ? base(st.scene) : '(none)';
  $('hdr-scene').title = st.scene;
  $('hdr-size').textContent = `${st.size[0]}x${st.size[1]}`;
  // the backends the nodes ran on ("cpu", "cpu + gl"), not the run's choice ("graph" meant
  // each node as the graph file says, and read as a backend named graph, issue 46)
  const backends = [...new Set(st.nodes.map((n) => n.backend).filter(Boolean))].sort();
  $('hdr-backend').textContent = backends.length ? backends.join(' + ') : st.backend;
  $('hdr-backend').title = `--backend ${st.backend}`;
  $('frame-ms').textContent = fmt(st.frame_ms);
  $('total-ms').textContent = fmt(st.total_ms);
  $('last-run').textContent = st.last_run;
  $('generation').textContent = st.generation;
  const se = $('state-error');
  se.textContent = st.error || '';
  se.hidden = !st.error;
}

// options: [{value, label}]
function fillSelect(sel, options) {
  const key = (o) => `${o.value}\t${o.label}`;
  if ([...sel.options].map((o) => `${o.value}\t${o.text}`).join() !== options.map(key).join()) {
    sel.replaceChildren(...options.map((o) => new Option(o.label, o.value)));
  }
}

// Every output of the graph in the port lists, those the last run did not make marked (an
// on-demand output nothing reads, such as compare's flip map with nothing downstream);
// returns {a, b, ref}: the ports shown so far where they still exist, else the last output
// that has an image (the tutorial's sweep.graph opened on c.flip, a black canvas and an
// error, issue 46).
export function portChoices(st) {
  const outs = st.nodes.flatMap((n) => n.outputs.map((o) => ({ value: `${n.name}.${o.port}`,
    label: `${n.name}.${o.port}${o.image === false ? ' (not computed)' : ''}`,
    image: o.image !== false })));
  const made = outs.filter((o) => o.image);
  const last = made.length ? made[made.length - 1].value : outs.length ? outs[outs.length - 1].value : '';
  // an open reference file (POST /api/reference) joins the lists, after the graph's ports
  if (st.reference_file) outs.push({ value: st.reference_file, label: st.reference_file, image: true });
  const ports = outs.map((o) => o.value);
  for (const id of ['port-a', 'port-b', 'port-ref']) fillSelect($(id), outs);
  const keep = (p) => (ports.includes(p) ? p : last);
  const p = state.ports;
  return { a: keep(p.a), b: keep(p.b), ref: keep(p.ref) };
}

export function fillTimes(st) {
  const rows = st.nodes.map((n) => {
    const tr = document.createElement('tr');
    tr.dataset.node = n.name;
    tr.className = (n.ran ? 'ran ' : '') + (n.name === state.selected ? 'selected' : '');
    // why: the library's reason it ran or was kept ("parameter changed", "input g ran")
    for (const t of [n.name, n.type, n.why || (n.ran ? 'ran' : 'kept'), fmt(n.ms, 2)]) {
      tr.insertCell().textContent = t;
    }
    tr.onclick = () => on.pick(n.name, true);
    return tr;
  });
  $('node-table').tBodies[0].replaceChildren(...rows);
  $('ran-list').textContent = st.nodes.filter((n) => n.ran).map((n) => n.name).join(' ') || '(none)';
}

// ---- diagram ----------------------------------------------------------------------------
let svgSig = ''; // the node list the diagram was fetched for

// The diagram for this state: fetched again when the node list changed, else re-marked.
export function showDiagram(st) {
  // the edges too: a rewired input (edit.js) changes the drawing, not the node list
  const sig = st.nodes.map((n) => `${n.name}<${n.inputs.map((i) => i.from).join('+')}`).join(',');
  if (sig !== svgSig) loadDiagram(sig); else markDiagram();
}

async function loadDiagram(sig) {
  svgSig = sig;
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
    g.addEventListener('click', () => { on.pick(nodeName(g), true); enlargeDiagram(false); });
  }
  markDiagram();
}

// The diagram over the main area at a readable scale (dot lays graphs out wide).
export function enlargeDiagram(wide) {
  $('diagram-box').classList.toggle('wide', wide);
}

const nodeName = (g) => (g.querySelector('title') || {}).textContent || '';

// Each node of the diagram: class ran/selected and its last time under its label.
export function markDiagram() {
  if (!state.server) return;
  const byName = new Map(state.server.nodes.map((n) => [n.name, n]));
  for (const g of $('diagram').querySelectorAll('g.node')) {
    const n = byName.get(nodeName(g));
    if (!n) continue;
    g.classList.toggle('ran', n.ran);
    g.classList.toggle('selected', n.name === state.selected);
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
    let tip = g.querySelector('title.why');
    if (!tip) {
      tip = document.createElementNS('http://www.w3.org/2000/svg', 'title');
      tip.setAttribute('class', 'why'); // after dot's own <title>, which names the node
      g.appendChild(tip);
    }
    tip.textContent = n.why || '';
  }
}

// ---- node panel -------------------------------------------------------------------------
// The selected node's summary, parameter controls and ports.
export function showNode(n) {
  $('node-name').textContent = n.name;
  $('node-type').textContent = `${n.type} \u00b7 ${n.backend}`;
  $('node-doc').textContent = n.doc || '';
  $('params').replaceChildren(...n.params.map((p) => paramRow(n, p, on.send)));
  $('ports').replaceChildren(...portList(n));
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
    b.onclick = () => on.showPort(b.dataset.port);
    d.append(b);
  }
  out.push(d);
  return out;
}

// Values changed elsewhere (a reload, a rejected set) reach controls the user is not using.
// force: also the control that has the focus, and while a change is on its way (a refused
// value's box going back to the graph's value, app.js onSetAnswer).
export function refreshParamValues(force = false) {
  const n = findNode(state.selected);
  if (!n) return;
  if (n.params.map((p) => p.name).join() !==
      [...$('params').children].map((r) => r.dataset.param).join()) {
    on.pick(n.name, false);
    return;
  }
  for (const p of n.params) {
    const id = `param-${n.name}-${p.name}`;
    const el = $(id), slider = $(`${id}-slider`);
    if (!el) continue;
    if (!force && (el === document.activeElement || slider === document.activeElement ||
                   !on.idle())) continue;
    if (el.type === 'checkbox') el.checked = p.value === 'true';
    else if (el.value !== p.value && parseFloat(el.value) !== parseFloat(p.value)) {
      el.value = p.value;
      if (slider) slider.value = String(slider.scale.from(parseFloat(p.value)));
    }
  }
}
