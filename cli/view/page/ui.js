// Small helpers of the page's modules: elements by id, number text, and the two bars every
// module may write to (the busy mark and the request error).

export const $ = (id) => document.getElementById(id);
// A number as the page sends it to the server (a camera, a key of a path): 8 significant
// digits, no trailing zeros.
export const wireNumber = (x) => String(parseFloat(x.toPrecision(8)));
export const fmt = (v, d = 1) => (typeof v === 'number' ? v.toFixed(d) : '-');

let busyCount = 0;
// on: a request starts (true) or ends (false); the mark shows while any is on its way.
export function setBusy(on) {
  busyCount += on ? 1 : -1;
  $('busy').hidden = busyCount <= 0;
}

// The error of the last request ('' clears it).
export function showRequestError(text) {
  const el = $('request-error');
  el.textContent = text || '';
  el.hidden = !text;
}
