// The page's state (docs/viewer.md, "How the page is built"): the one object every module
// reads, and the only functions that change it. Each change tells the listeners (app.js
// subscribes the render path, render.js), so whatever changed, the canvas is drawn from
// this state by one function. Writes from outside are refused: `state` is a read-only view.

const s = {
  server: null,       // the latest /api/state
  gen: -1,            // its generation
  selected: null,     // the selected node's name
  images: new Map(),  // port -> {w, h, c, gen, preview, data: Float32Array} (image.js)
  ports: Object.freeze({ a: '', b: '', ref: '', ab: false, mode: 'split' }),
  // the image's zoom and pan (viewport.js): canvas pixels per frame pixel, and the frame
  // point at the canvas's centre as fractions of the frame (fit: 1, 0.5, 0.5)
  zoom: Object.freeze({ z: 1, u: 0.5, v: 0.5 }),
  display: Object.freeze({ stops: 0, curve: 'clamp', channel: 'rgb', colormap: 'viridis',
    range: 'auto' }),
  divider: 0.5,       // the A/B divider as a fraction of the width
  cam: null,          // the camera the page is driving (a copy of server.camera)
  home: null,         // the camera the graph opened with (the home button goes back to it)
  steering: false,    // a drag or a wheel burst moves cam: the server's camera waits
  pointer: null,      // the last {clientX, clientY} over the canvas (pixel readout)
};

const refuse = () => { throw new TypeError('the state changes only through state.js'); };
export const state = new Proxy(s, { set: refuse, deleteProperty: refuse });

// The node of the latest state by name, or undefined.
export const findNode = (name) => s.server && s.server.nodes.find((n) => n.name === name);

const listeners = [];
// fn(what) after every change; what names the mutation.
export function subscribe(fn) { listeners.push(fn); }
function changed(what) { for (const fn of listeners) fn(what); }

// A new /api/state. The server's camera replaces the page's copy unless the user is
// steering, so a slow answer never makes a drag jump back. Returns whether it is a new run.
export function receive(st) {
  const newRun = st.generation !== s.gen;
  // home: the first camera of this graph and scene (a reload of another scene starts over)
  if (st.camera && (!s.home || !s.server || s.server.scene !== st.scene ||
                    s.server.graph !== st.graph)) {
    s.home = structuredClone(st.camera);
  }
  s.server = st;
  s.gen = st.generation;
  if (!s.steering && st.camera) s.cam = structuredClone(st.camera);
  changed('server');
  return newRun;
}

// The fetched images of a run, by port (the others stay until replaced). An image of an
// older run than the one a port shows is dropped: a fetch that left before the last run
// answers after it (a drag's last preview behind the full-size run, issue 46).
export function storeImages(byPort) {
  for (const [port, img] of byPort) {
    const shown = s.images.get(port);
    if (shown && shown.gen > img.gen) continue;
    s.images.set(port, img);
  }
  changed('images');
}

// How the floats are shown: any of {stops, curve, channel, colormap, range: 'auto'|'unit'}.
export function setDisplay(patch) {
  s.display = Object.freeze({ ...s.display, ...patch });
  changed('display');
}

// Which ports are shown: any of {a, b, ref, ab: the A/B view on, mode: 'split', or a
// difference: 'diff' |A - B|, 'signed' A - B, 'relative' |A - B| / (|B| + 0.01), 'flip'}.
export function setPorts(patch) {
  s.ports = Object.freeze({ ...s.ports, ...patch });
  changed('ports');
}

// The image's zoom and pan: any of {z, u, v} (viewport.js keeps them in bounds).
export function setZoom(patch) {
  s.zoom = Object.freeze({ ...s.zoom, ...patch });
  changed('zoom');
}

export function setDivider(fraction) {
  s.divider = Math.min(1, Math.max(0, fraction));
  changed('divider');
}

export function select(name) {
  s.selected = name;
  changed('select');
}

// The camera the page drives (orbit, pan, zoom), and whether the user is steering it.
export function steer(cam, steering) {
  s.cam = cam;
  s.steering = steering;
  changed('camera');
}

export function setPointer(ev) {
  s.pointer = ev && { clientX: ev.clientX, clientY: ev.clientY };
  changed('pointer');
}
