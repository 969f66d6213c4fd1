// The parameter controls of `ssgraph view`'s page (panel.js), generated from a node's
// parameter descriptors in /api/state (type, value, min, max, soft_min, soft_max, unit,
// choices, doc). A change calls send(node, param, text, debounce_ms), which the caller
// gives.

// How a number parameter's slider maps [0, 1000] to values: over its useful range
// (soft_min .. soft_max in /api/state: what the parameter row calls useful, inside the valid
// min .. max), linearly, or logarithmically where that range lies above 0 and spans two
// decades or more (a radius of 0.05 .. 5 scene units: each decade as long). A valid value
// outside it (typed into the box, or the graph's own) widens the span to include it, so the
// value is kept, never clamped, and the slider still moves from there: from(x) widens
// before it places the thumb (a log span that must reach 0 or below turns linear). An
// invalid value widens nothing (the server refuses it). null = no range (number box only).
function sliderScale(p) {
  let lo = p.soft_min ?? p.min, hi = p.soft_max ?? p.max;
  if (lo === null || hi === null || !(hi > lo)) return null;
  let log = lo > 0 && hi / lo >= 100;
  const valid = (x) => Number.isFinite(x) && !(p.min !== null && x < p.min) &&
    !(p.max !== null && x > p.max);
  return {
    to: (v) => (log ? Math.exp(Math.log(lo) + Math.log(hi / lo) * v / 1000)
      : lo + (hi - lo) * v / 1000),
    from(x) {
      if (valid(x) && (x < lo || x > hi)) {
        if (x <= 0) log = false;
        lo = Math.min(lo, x); hi = Math.max(hi, x);
      }
      const t = log ? Math.log(x / lo) / Math.log(hi / lo) : (x - lo) / (hi - lo);
      return Number.isFinite(t) ? Math.round(1000 * Math.min(1, Math.max(0, t))) : 0;
    },
  };
}

// A value as the graph file writes it: ints whole, floats with 6 significant digits.
function numText(p, x) {
  if (p.type === 'int') return String(Math.round(x));
  return String(parseFloat(x.toPrecision(6)));
}

// One row of the node panel: the name, its control, and the unit and doc under it.
export function paramRow(n, p, send) {
  const row = document.createElement('div');
  row.className = 'param';
  row.dataset.param = p.name;
  row.title = [p.doc, p.unit ? `unit: ${p.unit}` : '',
    p.min !== null && p.min !== undefined ? `range ${p.min} .. ${p.max}` : '',
    p.soft_min !== null && p.soft_min !== undefined ? `slider ${p.soft_min} .. ${p.soft_max}`
      : ''].filter(Boolean).join('\n');
  const label = document.createElement('label');
  label.textContent = p.name;
  row.append(label);
  const id = `param-${n.name}-${p.name}`;
  if (p.type === 'float' || p.type === 'int') numberControls(row, n, p, id, send);
  else if (p.type === 'enum' && p.choices) selectControl(row, n, p, id, send);
  else if (p.type === 'bool') boolControl(row, n, p, id, send);
  else textControl(row, n, p, id, send);
  if (p.unit || p.doc) {
    const u = document.createElement('div');
    u.className = 'unit';
    u.textContent = [p.unit, p.doc].filter(Boolean).join(' \u00b7 ');
    row.append(u);
  }
  return row;
}

function numberControls(row, n, p, id, send) {
  const box = document.createElement('input');
  box.type = 'number';
  box.id = id;
  box.value = p.value;
  box.step = p.type === 'int' ? '1' : 'any';
  const scale = sliderScale(p);
  let slider = null;
  box.addEventListener('change', () => {
    if (box.value.trim() === '') return; // an emptied box is an edit under way, not a value
    if (slider) slider.value = String(scale.from(parseFloat(box.value)));
    send(n.name, p.name, box.value, 0);
  });
  // an unbounded number has the box alone (it sent nothing before: its listener came with
  // the slider)
  if (!scale) { row.classList.add('wide'); row.append(box); return; }
  slider = document.createElement('input');
  slider.type = 'range';
  slider.id = `${id}-slider`;
  slider.min = '0'; slider.max = '1000'; slider.step = '1';
  slider.value = String(scale.from(parseFloat(p.value)));
  slider.scale = scale; // refreshParamValues moves the thumb on the same scale
  slider.addEventListener('input', () => {
    box.value = numText(p, scale.to(+slider.value));
    send(n.name, p.name, box.value, 60);
  });
  row.append(slider, box);
}

// A control that fills the row (no slider): el gets the id, and read(el) is the value sent
// when it changes.
function wideControl(row, n, p, id, send, el, read) {
  el.id = id;
  el.addEventListener('change', () => send(n.name, p.name, read(el), 0));
  row.classList.add('wide');
  row.append(el);
}

function selectControl(row, n, p, id, send) {
  const sel = document.createElement('select');
  sel.replaceChildren(...p.choices.map((c) => new Option(c, c)));
  sel.value = p.value;
  wideControl(row, n, p, id, send, sel, (el) => el.value);
}

function boolControl(row, n, p, id, send) {
  const cb = document.createElement('input');
  cb.type = 'checkbox';
  cb.checked = p.value === 'true';
  wideControl(row, n, p, id, send, cb, (el) => (el.checked ? 'true' : 'false'));
}

function textControl(row, n, p, id, send) {
  const t = document.createElement('input');
  t.type = 'text';
  t.value = p.value;
  wideControl(row, n, p, id, send, t, (el) => el.value);
}
