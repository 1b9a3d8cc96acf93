// See index.html: a plain script's frame, the baseline for the seashells page's.
const SIDE = 400; // (SIDE − 1)² × 2: 318,402 triangles
const canvas = document.getElementById('canvas');
const dpr = window.devicePixelRatio || 1;
canvas.width = Math.round(600 * dpr);
canvas.height = Math.round(500 * dpr);
const gl = canvas.getContext('webgl2', { antialias: true });

const shader = (type, source) => {
  const s = gl.createShader(type);
  gl.shaderSource(s, source);
  gl.compileShader(s);
  if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
  return s;
};
const program = gl.createProgram();
gl.attachShader(program, shader(gl.VERTEX_SHADER, `#version 300 es
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform float turn;
out vec3 n;
void main() {
  float c = cos(turn), s = sin(turn);
  vec3 p = vec3(c * position.x + s * position.z, position.y, -s * position.x + c * position.z);
  n = vec3(c * normal.x + s * normal.z, normal.y, -s * normal.x + c * normal.z);
  gl_Position = vec4(p.xy * 0.8, p.z * 0.5 + 0.5, 1.0);
}`));
gl.attachShader(program, shader(gl.FRAGMENT_SHADER, `#version 300 es
precision mediump float;
in vec3 n;
out vec4 colour;
void main() { colour = vec4(vec3(0.2 + 0.8 * max(dot(normalize(n), normalize(vec3(0.3, 0.6, -0.7))), 0.0)), 1.0); }`));
gl.linkProgram(program);
gl.useProgram(program);
const turn = gl.getUniformLocation(program, 'turn');

// A sphere as a grid of SIDE × SIDE vertices (position and normal), two triangles a cell.
const vertices = new Float32Array(SIDE * SIDE * 6);
for (let i = 0; i < SIDE; i += 1) {
  for (let j = 0; j < SIDE; j += 1) {
    const theta = (Math.PI * i) / (SIDE - 1);
    const phi = (2 * Math.PI * j) / (SIDE - 1);
    const p = [Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi)];
    vertices.set([...p, ...p], (i * SIDE + j) * 6);
  }
}
const indices = new Uint32Array((SIDE - 1) * (SIDE - 1) * 6);
let k = 0;
for (let i = 0; i + 1 < SIDE; i += 1) {
  for (let j = 0; j + 1 < SIDE; j += 1) {
    const a = i * SIDE + j;
    indices.set([a, a + SIDE, a + 1, a + 1, a + SIDE, a + SIDE + 1], k);
    k += 6;
  }
}
const vertexBuffer = gl.createBuffer();
gl.bindBuffer(gl.ARRAY_BUFFER, vertexBuffer);
gl.bufferData(gl.ARRAY_BUFFER, vertices, gl.STATIC_DRAW);
gl.enableVertexAttribArray(0);
gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 24, 0);
gl.enableVertexAttribArray(1);
gl.vertexAttribPointer(1, 3, gl.FLOAT, false, 24, 12);
const indexBuffer = gl.createBuffer();
gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, indexBuffer);
gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);
// Where the replies' bytes go, as a growing shell's new rows would.
const replies = gl.createBuffer();
gl.bindBuffer(gl.COPY_WRITE_BUFFER, replies);
gl.bufferData(gl.COPY_WRITE_BUFFER, 1 << 20, gl.DYNAMIC_DRAW);
gl.enable(gl.DEPTH_TEST);

const worker = new Worker('floor-worker.js');
let reply = null;
worker.onmessage = (e) => { reply = new Uint8Array(e.data); };
const ask = () => { const b = new ArrayBuffer(64); worker.postMessage(b, [b]); };
ask();

const bar = document.getElementById('progress');
const text = document.getElementById('progress-text');
let frames = 0;
let written = 0;
document.body.dataset.state = 'growing';
function frame(t) {
  if (reply) {
    gl.bindBuffer(gl.COPY_WRITE_BUFFER, replies);
    gl.bufferSubData(gl.COPY_WRITE_BUFFER, written % (1 << 19), reply);
    written += reply.length;
    reply = null;
    ask();
  }
  frames += 1;
  bar.value = frames % 1000;
  text.textContent = `${frames} frames`;
  document.body.dataset.rows = String(frames);
  gl.viewport(0, 0, canvas.width, canvas.height);
  gl.clearColor(0.96, 0.94, 0.9, 1);
  gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
  gl.uniform1f(turn, t / 4000);
  gl.drawElements(gl.TRIANGLES, indices.length, gl.UNSIGNED_INT, 0);
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);
