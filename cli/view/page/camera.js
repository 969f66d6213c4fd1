// Camera moves for `ssgraph view`'s page (mouse.js): orbit, pan and zoom of a camera
// {position, target, up, fov_y} in place, from mouse motion in screen pixels. No state.

const V = {
  add: (a, b) => a.map((x, i) => x + b[i]), sub: (a, b) => a.map((x, i) => x - b[i]),
  mul: (a, s) => a.map((x) => x * s), dot: (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2],
  cross: (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]],
  len: (a) => Math.hypot(a[0], a[1], a[2]),
  norm: (a) => V.mul(a, 1 / (V.len(a) || 1)),
};
// v rotated by angle t around the unit axis k (Rodrigues).
function rotate(v, k, t) {
  const c = Math.cos(t), s = Math.sin(t);
  return V.add(V.add(V.mul(v, c), V.mul(V.cross(k, v), s)), V.mul(k, V.dot(k, v) * (1 - c)));
}

// Turns the camera around its target: dx about the up axis, dy about the right axis, in
// screen pixels.
export function orbit(cam, dx, dy) {
  const up = V.norm(cam.up);
  let off = rotate(V.sub(cam.position, cam.target), up, -dx * 0.008);
  const right = V.norm(V.cross(off, up));
  const tilted = rotate(off, right, dy * 0.008);
  const cosUp = V.dot(V.norm(tilted), up);
  if (Math.abs(cosUp) < 0.995) off = tilted; // never over the pole
  cam.position = V.add(cam.target, off);
}

// Moves camera and target in the view plane; heightPx: the canvas height on screen, so the
// point under the mouse at the target's distance follows the mouse.
export function pan(cam, dx, dy, heightPx) {
  const off = V.sub(cam.position, cam.target);
  const fwd = V.norm(V.mul(off, -1));
  const right = V.norm(V.cross(fwd, cam.up)), camUp = V.cross(right, fwd);
  const k = 2 * V.len(off) * Math.tan((cam.fov_y * Math.PI) / 360) / (heightPx || 1);
  const move = V.add(V.mul(right, -dx * k), V.mul(camUp, dy * k));
  cam.position = V.add(cam.position, move);
  cam.target = V.add(cam.target, move);
}

// Scales the distance to the target by exp(wheel / 1000) (a wheel notch is about 10%).
export function zoom(cam, wheel) {
  const off = V.mul(V.sub(cam.position, cam.target), Math.exp(wheel * 0.001));
  cam.position = V.add(cam.target, off);
}
