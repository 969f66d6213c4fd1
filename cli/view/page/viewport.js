// The image's zoom and pan (as tev's): a view transform from canvas pixels to frame pixels
// that the display shader applies (tonemap.js, uniform `view`), so zooming and panning draw
// one triangle and upload nothing. The canvas keeps the frame's size and aspect; state.zoom
// holds z (canvas pixels per frame pixel: fit is 1) and the frame point at the canvas's
// centre (u, v as fractions of the frame). The A/B divider stays in canvas columns, so it
// keeps its place on screen while the image moves under it.
import { setZoom, state } from './state.js';
import { $ } from './ui.js';

const ZOOM_MIN = 1 / 32, ZOOM_MAX = 512;
// From this zoom on (an image pixel 8 canvas pixels wide) the pixel grid is drawn.
export const GRID_ZOOM = 8;

const clampZoom = (z) => Math.min(ZOOM_MAX, Math.max(ZOOM_MIN, z));

// The frame point [x, y] (in frame pixels, fractional) under canvas point [px, py].
export function canvasToFrame(px, py) {
  const cv = $('view'), W = cv.width, H = cv.height, { z, u, v } = state.zoom;
  return [u * W + (px - W / 2) / z, v * H + (py - H / 2) / z];
}

// Zooms by `factor` about canvas point [px, py]: the frame point under it stays under it.
export function zoomAt(factor, px, py) {
  const cv = $('view'), W = cv.width, H = cv.height;
  const [qx, qy] = canvasToFrame(px, py), z = clampZoom(state.zoom.z * factor);
  setZoom({ z, u: (qx - (px - W / 2) / z) / W, v: (qy - (py - H / 2) / z) / H });
}

// Moves the image by [dx, dy] canvas pixels (a pan drag).
export function panBy(dx, dy) {
  const cv = $('view'), { z, u, v } = state.zoom;
  setZoom({ u: u - dx / (z * cv.width), v: v - dy / (z * cv.height) });
}

// The whole frame in the canvas (key F).
export const fit = () => setZoom({ z: 1, u: 0.5, v: 0.5 });

// One frame pixel to one device pixel of the screen (key 1), about the canvas's centre.
export function oneToOne() {
  const cv = $('view'), shown = cv.getBoundingClientRect().width || cv.width;
  setZoom({ z: clampZoom(cv.width / (shown * (window.devicePixelRatio || 1))) });
}

// The zoom as the toolbar shows it: screen pixels per frame pixel, in percent.
export function zoomPercent() {
  const cv = $('view'), shown = cv.getBoundingClientRect().width || cv.width;
  return Math.round(state.zoom.z * shown * (window.devicePixelRatio || 1) / cv.width * 100);
}

// The frame pixels the canvas shows, [x0, y0, x1, y1] cut to the frame (statistics of the
// view), in the pixels of an image of w x h.
export function visibleRect(w, h) {
  const cv = $('view');
  const [x0, y0] = canvasToFrame(0, 0), [x1, y1] = canvasToFrame(cv.width, cv.height);
  const sx = w / cv.width, sy = h / cv.height;
  return [Math.max(0, Math.floor(x0 * sx)), Math.max(0, Math.floor(y0 * sy)),
    Math.min(w, Math.ceil(x1 * sx)), Math.min(h, Math.ceil(y1 * sy))];
}
