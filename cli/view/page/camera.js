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

// Keyboard fly (fly.js): moves camera and target together by `step` scene units along the
// view direction (forward), its right (right) and the up axis (up), each -1, 0 or 1.
export function fly(cam, forward, right, up, step) {
  const dir = V.norm(V.sub(cam.target, cam.position));
  const r = V.norm(V.cross(dir, cam.up)), u = V.norm(cam.up);
  const move = V.mul(V.add(V.add(V.mul(dir, forward), V.mul(r, right)), V.mul(u, up)), step);
  cam.position = V.add(cam.position, move);
  cam.target = V.add(cam.target, move);
}

// Turns the view around the eye (the target moves): yaw about the up axis, pitch about the
// right axis, in radians, never over the pole.
export function look(cam, yaw, pitch) {
  const up = V.norm(cam.up);
  let off = rotate(V.sub(cam.target, cam.position), up, -yaw);
  const right = V.norm(V.cross(off, up));
  const tilted = rotate(off, right, pitch);
  if (Math.abs(V.dot(V.norm(tilted), up)) < 0.995) off = tilted;
  cam.target = V.add(cam.position, off);
}

// The distance from the eye to the target: the scale a fly moves by.
export const targetDistance = (cam) => V.len(V.sub(cam.target, cam.position));

// Why {position, target, up, fov_y} is no camera, as {part, why} naming the field at
// fault, or null when it is one (the server's checks: an eye apart from the target, an up
// not along the view, a fov in (0, 180)).
export function cameraFault(cam) {
  const dir = V.sub(cam.target, cam.position);
  // a camera from the server is float32: a box typed from it differs in the 8th digit
  if (!(V.len(dir) > 1e-6 * Math.max(1, V.len(cam.position)))) {
    return { part: 'target', why: 'the position and the target are the same point' };
  }
  if (!(V.len(cam.up) > 0) || V.len(V.cross(V.norm(dir), V.norm(cam.up))) < 1e-6) {
    return { part: 'up', why: 'up is zero or along the view direction' };
  }
  if (!(cam.fov_y > 0 && cam.fov_y < 180)) {
    return { part: 'fov', why: 'the field of view is in (0, 180) degrees' };
  }
  return null;
}
