// The canvas as a WebGL2 view of float images (as tev draws them): each image is uploaded
// once as a float texture, and a fragment shader applies exposure, the CLI's tone curves and
// sRGB encoding (core/io/tonemap.h: the same formulas, constants and rounding, so the canvas
// shows the bytes `ssgraph run --show ... --tonemap C --exposure E` writes to its PNGs), or
// viridis false colour, the A/B split or a difference (|A - B|, A - B in a diverging map,
// the relative error, the server's FLIP map), through the image's zoom and pan
// (viewport.js). A change of exposure, of the divider or of the zoom is one draw of one
// triangle (of the curve, channel or colour map, the first time
// also a program compiled); no pixel loop runs in JavaScript. A browser without WebGL2 gets
// a named error, not a second, slower path.
import { DIVERGING_RGBA, VIRIDIS_RGBA } from './image.js';
import { GRID_ZOOM } from './viewport.js';

const VERTEX = `#version 300 es
void main() { // one triangle that covers the canvas
  vec2 p = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1)) - 1.0;
  gl_Position = vec4(p, 0.0, 1.0);
}`;

// The fragment shader is specialised (as mpv's video/out/gpu writes its passes): the curve,
// the A/B view and what each side shows are #defines and generated lines, so a pixel runs
// straight-line code (on SwiftShader, the CPU WebGL of headless Chromium, every branch not
// taken by the compiler costs its full price). A program per combination, made when first
// needed; exposure and the divider stay uniforms, so dragging them never compiles.
const HEAD = `#version 300 es
precision highp float;
precision highp int;
uniform highp sampler2D imageA, imageB; // the float images, channels in .rgba
uniform highp sampler2D viridis;        // 256x1, entry floor(255 v) for v in [0, 1]
uniform highp sampler2D diverging;      // 256x1, entry 128 + 127 v for v in [-1, 1]
uniform ivec2 frame;                    // the canvas in pixels (the full frame size)
uniform vec3 view;                      // the frame point at the canvas's centre, zoom
uniform int splitX;                     // AB_SPLIT: B from this column on
uniform float gain;                     // 2^stops
uniform vec2 range;                     // false colour shows (v - range.x) range.y
out vec4 colour;

// ssg_tonemap_scaled: capped at 1e4 so the rational curves never see inf/inf.
float tone(float v) {
  if (!(v > 0.0)) return 0.0; // negative, zero, NaN
  v = min(v, 1e4);
#if CURVE == 1
  v = v / (1.0 + v);
#elif CURVE == 2
  v = (v * (2.51 * v + 0.03)) / (v * (2.43 * v + 0.59) + 0.14);
#endif
  return min(v, 1.0);
}

// ssg_srgb8_scaled: IEC 61966-2-1 encoding, rounded to the nearest of 256 codes; the code
// over 255 becomes that code again in the 8-bit canvas.
float code(float v) {
  float x = tone(v * gain);
  float s = x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
  return clamp(floor(s * 255.0 + 0.5), 0.0, 255.0) / 255.0;
}

// The value mapped by the range (auto: the shown channel's minimum to maximum, else [0, 1])
// and scaled by the exposure, in [0, 1] through the viridis table.
vec3 falseColour(float v) {
  v = (v - range.x) * range.y * gain;
  int k = !(v > 0.0) ? 0 : v >= 1.0 ? 255 : int(v * 255.0);
  return texelFetch(viridis, ivec2(k, 0), 0).rgb;
}

// A signed value through the diverging map, range [-m, m] (range.y = 1 / 2m) at the
// exposure: -m blue, 0 grey, +m red.
vec3 diverge(float v) {
  v = 2.0 * v * range.y * gain;
  int k = v != v ? 128 : int(clamp(floor(128.0 + v * 127.0 + 0.5), 0.0, 255.0));
  return texelFetch(diverging, ivec2(k, 0), 0).rgb;
}

// The texel at frame point q (frame pixels) of an image of any size (a preview fills the
// frame): the nearest, so a zoomed pixel is a square.
vec4 texel(highp sampler2D t, vec2 q) {
  ivec2 size = textureSize(t, 0);
  ivec2 i = ivec2(q * vec2(size) / vec2(frame));
  return texelFetch(t, min(i, size - 1), 0);
}

// The pixel grid once a frame pixel is GRID_ZOOM canvas pixels wide: each pixel's top and
// left canvas row and column, darkened.
vec3 grid(vec3 c, vec2 q) {
  if (view.z < float(GRID_ZOOM)) return c;
  vec2 f = fract(q);
  return f.x * view.z < 1.0 || f.y * view.z < 1.0 ? mix(c, vec3(0.3), 0.5) : c;
}
`;

// What one side shows: colour (the first three channels), or one channel (a missing one
// reads 0, or 1 for A) as grey or in false colour.
const SHOW = { colour: 0, grey: 1, falseColour: 2 };
const SHADE = [
  () => 'vec3(code(px.r), code(px.g), code(px.b))',
  (ch) => `vec3(code(px.${'rgba'[ch]}))`,
  (ch) => `falseColour(px.${'rgba'[ch]})`,
];
const shadeFunction = (name, side) =>
  `vec3 ${name}(vec4 px) { return ${SHADE[side.show](side.channel)}; }\n`;
// The one value of a side that a signed difference shows: its channel, or the mean of the
// colour channels.
const pickFunction = (side) => `float pickA(vec4 px) { return ${side.show === SHOW.colour
  ? '(px.r + px.g + px.b) / 3.0' : `px.${'rgba'[side.channel]}`}; }\n`;

// The frame from the image(s), by A/B view: A alone, split at splitX (a canvas column),
// |A - B|, A - B, |A - B| / (|B| + 0.01), or the FLIP map (the server's, as image A).
export const RELATIVE_EPS = 0.01;
const AB = { none: 0, split: 1, diff: 2, signed: 3, relative: 4, flip: 5 };
const A = 'texel(imageA, q)', B = 'texel(imageB, q)';
const MAIN = [
  `shadeA(${A})`,
  `p.x < splitX ? shadeA(${A}) : shadeB(${B})`,
  `shadeA(abs(${A} - ${B}))`,
  `diverge(pickA(${A} - ${B}))`,
  `shadeA(abs(${A} - ${B}) / (abs(${B}) + ${RELATIVE_EPS.toFixed(2)}))`,
  `falseColour(${A}.r)`,
];
// Where the frame is not (zoomed out or panned past its edge): the page's grey.
const BACKGROUND = 'vec3(0.13)';

// The shader of one combination {curve, ab, a, b: {show, channel}}, and the uniforms it uses.
function fragment(v) {
  const text = HEAD.replace('\n', `\n#define CURVE ${v.curve}\n#define GRID_ZOOM ${GRID_ZOOM}\n`) +
    shadeFunction('shadeA', v.a) + shadeFunction('shadeB', v.b) + pickFunction(v.a) +
    'void main() {\n  ivec2 p = ivec2(int(gl_FragCoord.x), frame.y - 1 - int(gl_FragCoord.y));\n' +
    '  vec2 q = view.xy + (vec2(p) + 0.5 - 0.5 * vec2(frame)) / view.z;\n' +
    '  if (q.x < 0.0 || q.y < 0.0 || q.x >= float(frame.x) || q.y >= float(frame.y)) {\n' +
    `    colour = vec4(${BACKGROUND}, 1.0);\n    return;\n  }\n` +
    `  colour = vec4(grid(${MAIN[v.ab]}, q), 1.0);\n}\n`;
  const uniforms = ['imageA', 'frame', 'gain', 'view'];
  if (v.ab !== AB.none && v.ab !== AB.flip) uniforms.push('imageB');
  if (v.ab === AB.split) uniforms.push('splitX');
  if (v.ab === AB.signed) uniforms.push('diverging', 'range');
  else if (v.ab === AB.flip || v.a.show === SHOW.falseColour ||
           (v.ab === AB.split && v.b.show === SHOW.falseColour)) {
    uniforms.push('viridis', 'range');
  }
  return { text, uniforms };
}

// Each uniform's value for a frame f (see ImageView.draw).
const SETTERS = {
  imageA: (gl, loc) => gl.uniform1i(loc, 0),
  imageB: (gl, loc) => gl.uniform1i(loc, 1),
  viridis: (gl, loc) => gl.uniform1i(loc, 2),
  diverging: (gl, loc) => gl.uniform1i(loc, 3),
  view: (gl, loc, f) => gl.uniform3f(loc, f.u * f.W, f.v * f.H, f.zoom),
  frame: (gl, loc, f) => gl.uniform2i(loc, f.W, f.H),
  gain: (gl, loc, f) => gl.uniform1f(loc, 2 ** f.display.stops),
  splitX: (gl, loc, f) => gl.uniform1i(loc, f.splitX),
  range: (gl, loc, f) => gl.uniform2f(loc, f.rangeLo, f.rangeScale),
};

// The page's names (state.js display) as the shader's numbers.
const CURVES = { clamp: 0, reinhard: 1, aces: 2 };
const PICKS = { rgb: -1, r: 0, g: 1, b: 2, a: 3 };
// Texture formats by channel count (an image of more channels shows its first four).
const FORMATS = [null, ['R32F', 'RED'], ['RG32F', 'RG'], ['RGB32F', 'RGB'], ['RGBA32F', 'RGBA']];

// The channel a side shows of an image: -1 its colour (the first three channels).
export function shownChannel(img, d) {
  const pick = PICKS[d.channel] ?? -1;
  if (!img || (img.c > 1 && pick < 0)) return -1;
  return img.c === 1 ? 0 : pick;
}

// What a side shows for an image (null: none yet, drawn black from the 1x1 zero texture).
function sideOf(img, d) {
  const pick = PICKS[d.channel] ?? -1;
  if (!img || (img.c > 1 && pick < 0)) return { show: SHOW.colour, channel: 0 };
  return { show: d.colormap === 'viridis' ? SHOW.falseColour : SHOW.grey,
    channel: img.c === 1 ? 0 : pick };
}

function compile(gl, type, text) {
  const sh = gl.createShader(type);
  gl.shaderSource(sh, text);
  gl.compileShader(sh);
  if (!gl.getShaderParameter(sh, gl.COMPILE_STATUS)) {
    throw new Error(`the display shader does not compile: ${gl.getShaderInfoLog(sh)}`);
  }
  return sh;
}

function link(gl, fragmentText) {
  const prog = gl.createProgram();
  gl.attachShader(prog, compile(gl, gl.VERTEX_SHADER, VERTEX));
  gl.attachShader(prog, compile(gl, gl.FRAGMENT_SHADER, fragmentText));
  gl.linkProgram(prog);
  if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) {
    throw new Error(`the display shader does not link: ${gl.getProgramInfoLog(prog)}`);
  }
  return prog;
}

// Every uniform's location by name; a name the shader lacks is an error, never a skip.
function locations(gl, prog, names) {
  const loc = {};
  for (const n of names) {
    loc[n] = gl.getUniformLocation(prog, n);
    if (loc[n] === null) throw new Error(`the display shader has no uniform '${n}'`);
  }
  return loc;
}

// The first min(c, 4) channels of an image, interleaved, as the texture takes them.
function texels(img) {
  if (img.c <= 4) return img.data;
  const n = img.w * img.h, out = new Float32Array(n * 4);
  for (let i = 0; i < n; i++) for (let k = 0; k < 4; k++) out[i * 4 + k] = img.data[i * img.c + k];
  return out;
}

export class ImageView {
  // canvas: the page's <canvas>; onRestore: called after a lost context is back (redraw).
  constructor(canvas, onRestore) {
    this.canvas = canvas;
    canvas.addEventListener('webglcontextlost', (ev) => ev.preventDefault());
    canvas.addEventListener('webglcontextrestored', () => { this.setup(); onRestore(); });
    this.setup();
  }

  setup() {
    // preserveDrawingBuffer: the canvas keeps its pixels between draws, for screenshots and
    // the tests' readback; a draw is one triangle, so the copy it costs does not matter
    const gl = this.canvas.getContext('webgl2', { alpha: false, antialias: false, depth: false,
      stencil: false, preserveDrawingBuffer: true });
    if (!gl) throw new Error('this page needs WebGL2 to show images (any current browser has it)');
    this.gl = gl;
    this.programs = new Map(); // fragment(v) key -> {prog, loc}
    this.maxSize = gl.getParameter(gl.MAX_TEXTURE_SIZE);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    this.textures = [0, 1, 2, 3].map(() => gl.createTexture());
    this.zero = { w: 1, h: 1, c: 1, data: new Float32Array(1) };
    this.shown = [null, null]; // the image each of units 0 and 1 holds
    this.bind(2, gl.RGBA8, 256, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(VIRIDIS_RGBA));
    this.bind(3, gl.RGBA8, 256, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(DIVERGING_RGBA));
  }

  // The program of a combination (fragment()), linked when first asked for.
  program(v) {
    const key = JSON.stringify(v);
    if (!this.programs.has(key)) {
      const { text, uniforms } = fragment(v);
      const prog = link(this.gl, text);
      this.programs.set(key, { prog, loc: locations(this.gl, prog, uniforms) });
    }
    return this.programs.get(key);
  }

  // Texture unit u holds pixels (w x 1 or the image's size) with nearest sampling.
  bind(u, internal, w, format, type, data, h = 1) {
    const gl = this.gl;
    gl.activeTexture(gl.TEXTURE0 + u);
    gl.bindTexture(gl.TEXTURE_2D, this.textures[u]);
    gl.texImage2D(gl.TEXTURE_2D, 0, internal, w, h, 0, format, type, data);
    for (const p of [gl.TEXTURE_MIN_FILTER, gl.TEXTURE_MAG_FILTER]) {
      gl.texParameteri(gl.TEXTURE_2D, p, gl.NEAREST);
    }
  }

  // Unit u (0: A, 1: B) holds img; uploaded only when it is a new image.
  upload(u, img) {
    if (this.shown[u] === img) return;
    if (img.w > this.maxSize || img.h > this.maxSize) {
      throw new Error(`${img.w}x${img.h} is larger than this browser's WebGL2 textures ` +
                      `(${this.maxSize} pixels a side)`);
    }
    const [internal, format] = FORMATS[Math.min(img.c, 4)];
    const gl = this.gl;
    this.bind(u, gl[internal], img.w, gl[format], gl.FLOAT, texels(img), img.h);
    this.shown[u] = img;
  }

  // One frame: {W, H, a, b: images or null, ab: 'none', 'split' or a difference (AB),
  // splitX, display, rangeLo, rangeScale, zoom, u, v}.
  draw(f) {
    const gl = this.gl, d = f.display;
    this.upload(0, f.a || this.zero);
    this.upload(1, f.b || this.zero);
    const { prog, loc } = this.program({ curve: CURVES[d.curve] ?? 0, ab: AB[f.ab],
      a: sideOf(f.a, d), b: sideOf(f.b, d) });
    gl.viewport(0, 0, f.W, f.H);
    gl.useProgram(prog);
    for (let u = 0; u < 4; u++) {
      gl.activeTexture(gl.TEXTURE0 + u);
      gl.bindTexture(gl.TEXTURE_2D, this.textures[u]);
    }
    for (const name of Object.keys(loc)) SETTERS[name](gl, loc[name], f);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }
}
