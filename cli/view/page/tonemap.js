// The canvas as a WebGL2 view of float images (as tev draws them): each image is uploaded
// once as a float texture, and a fragment shader applies exposure, the CLI's tone curves and
// sRGB encoding (core/io/tonemap.h: the same formulas, constants and rounding, so the canvas
// shows the bytes `ssgraph run --show ... --tonemap C --exposure E` writes to its PNGs), or
// viridis false colour, and the A/B split or difference. A change of exposure, curve,
// channel, colour map or divider is one draw of one triangle; no pixel loop runs in
// JavaScript. A browser without WebGL2 gets a named error, not a second, slower path.
import { VIRIDIS_RGBA } from './image.js';

const VERTEX = `#version 300 es
void main() { // one triangle that covers the canvas
  vec2 p = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1)) - 1.0;
  gl_Position = vec4(p, 0.0, 1.0);
}`;

const FRAGMENT = `#version 300 es
precision highp float;
precision highp int;
uniform highp sampler2D imageA, imageB; // the float images, channels in .rgba
uniform highp sampler2D viridis;        // 256x1, entry floor(255 v) for v in [0, 1]
uniform ivec2 frame;                    // the canvas in pixels (the full frame size)
uniform int channelsA, channelsB;       // channels of each image (4 at most); 0: none yet
uniform int splitX;                     // B from this column on (frame.x: A alone)
uniform bool difference;                // |A - B| over the whole frame
uniform float gain;                     // 2^stops
uniform int curve;                      // 0 clamp, 1 reinhard, 2 aces (enum ssg_tonemap)
uniform int pick;                       // -1 colour, 0..3 the one channel R, G, B, A
uniform bool falseColour;               // one-channel views through viridis, else grey
out vec4 colour;

// ssg_tonemap_scaled: capped at 1e4 so the rational curves never see inf/inf.
float tone(float v) {
  if (!(v > 0.0)) return 0.0; // negative, zero, NaN
  v = min(v, 1e4);
  float d = v;
  if (curve == 1) d = v / (1.0 + v);
  else if (curve == 2) d = (v * (2.51 * v + 0.03)) / (v * (2.43 * v + 0.59) + 0.14);
  return min(d, 1.0);
}

// ssg_srgb8_scaled: IEC 61966-2-1 encoding, rounded to the nearest of 256 codes; the code
// over 255 becomes that code again in the 8-bit canvas.
float code(float v) {
  float x = tone(v * gain);
  float s = x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
  return clamp(floor(s * 255.0 + 0.5), 0.0, 255.0) / 255.0;
}

// The texel under frame pixel p of an image of any size (a preview fills the frame).
vec4 texel(highp sampler2D t, ivec2 p) {
  ivec2 size = textureSize(t, 0);
  ivec2 q = ivec2((vec2(p) + 0.5) * vec2(size) / vec2(frame));
  return texelFetch(t, min(q, size - 1), 0);
}

vec3 shade(vec4 px, int c) {
  if (c == 0) return vec3(0.0);
  if (c > 1 && pick < 0) return vec3(code(px.r), code(px.g), code(px.b));
  float v = px[c == 1 ? 0 : pick]; // a missing channel reads 0 (R, G, B) or 1 (A)
  if (!falseColour) return vec3(code(v));
  v *= gain;
  int k = !(v > 0.0) ? 0 : v >= 1.0 ? 255 : int(v * 255.0);
  return texelFetch(viridis, ivec2(k, 0), 0).rgb;
}

void main() {
  ivec2 p = ivec2(int(gl_FragCoord.x), frame.y - 1 - int(gl_FragCoord.y)); // rows top down
  vec3 rgb;
  if (difference) rgb = shade(abs(texel(imageA, p) - texel(imageB, p)), channelsA);
  else if (p.x >= splitX) rgb = shade(texel(imageB, p), channelsB);
  else rgb = shade(texel(imageA, p), channelsA);
  colour = vec4(rgb, 1.0);
}`;

// The uniforms' values by the page's names (state.js display).
const CURVES = { clamp: 0, reinhard: 1, aces: 2 };
const PICKS = { rgb: -1, r: 0, g: 1, b: 2, a: 3 };
// Texture formats by channel count (an image of more channels shows its first four).
const FORMATS = [null, ['R32F', 'RED'], ['RG32F', 'RG'], ['RGB32F', 'RGB'], ['RGBA32F', 'RGBA']];

function compile(gl, type, text) {
  const sh = gl.createShader(type);
  gl.shaderSource(sh, text);
  gl.compileShader(sh);
  if (!gl.getShaderParameter(sh, gl.COMPILE_STATUS)) {
    throw new Error(`the display shader does not compile: ${gl.getShaderInfoLog(sh)}`);
  }
  return sh;
}

function link(gl) {
  const prog = gl.createProgram();
  gl.attachShader(prog, compile(gl, gl.VERTEX_SHADER, VERTEX));
  gl.attachShader(prog, compile(gl, gl.FRAGMENT_SHADER, FRAGMENT));
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
    this.prog = link(gl);
    this.loc = locations(gl, this.prog, ['imageA', 'imageB', 'viridis', 'frame', 'channelsA',
      'channelsB', 'splitX', 'difference', 'gain', 'curve', 'pick', 'falseColour']);
    this.maxSize = gl.getParameter(gl.MAX_TEXTURE_SIZE);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    this.textures = [0, 1, 2].map(() => gl.createTexture());
    this.shown = [null, null]; // the image each of units 0 and 1 holds
    const zero = { w: 1, h: 1, c: 1, data: new Float32Array(1) };
    this.upload(0, zero);
    this.upload(1, zero);
    this.bind(2, gl.RGBA8, 256, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(VIRIDIS_RGBA));
    this.shown = [null, null];
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

  // One frame: {W, H, a, b: images or null, splitX, difference, display: state.display}.
  draw(f) {
    const gl = this.gl, loc = this.loc, d = f.display;
    if (f.a) this.upload(0, f.a);
    if (f.b) this.upload(1, f.b);
    gl.viewport(0, 0, f.W, f.H);
    gl.useProgram(this.prog);
    for (const [name, u] of [['imageA', 0], ['imageB', 1], ['viridis', 2]]) {
      gl.activeTexture(gl.TEXTURE0 + u);
      gl.bindTexture(gl.TEXTURE_2D, this.textures[u]);
      gl.uniform1i(loc[name], u);
    }
    gl.uniform2i(loc.frame, f.W, f.H);
    gl.uniform1i(loc.channelsA, f.a ? Math.min(f.a.c, 4) : 0);
    gl.uniform1i(loc.channelsB, f.b ? Math.min(f.b.c, 4) : 0);
    gl.uniform1i(loc.splitX, f.splitX);
    gl.uniform1i(loc.difference, f.difference ? 1 : 0);
    gl.uniform1f(loc.gain, 2 ** d.stops);
    gl.uniform1i(loc.curve, CURVES[d.curve] ?? 0);
    gl.uniform1i(loc.pick, PICKS[d.channel] ?? -1);
    gl.uniform1i(loc.falseColour, d.colormap === 'viridis' ? 1 : 0);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }
}
