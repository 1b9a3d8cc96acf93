// Exports from the page: the download menu offers GLB first, then PLY, 3MF, OBJ, STL, the
// picture and the pattern, each with its size; the Oliva's GLB passes the Khronos glTF
// validator and opens in three.js's GLTFLoader, drawn beside the page's own picture of it
// (exports/oliva-page-and-three.png, in docs/exports.md); the Murex at its own resolution is
// written over many frames with a progress bar, into the file the command line writes; a mesh
// of an implicit shell still growing is of the whole shell, finished first; and what cannot be
// exported says why instead of downloading anything.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { open, session, waitForState } from './browser.mjs';
import { CLI } from './native.mjs';

const ROOT = new URL('../../', import.meta.url).pathname;
const SHOTS = new URL('./screenshots/exports/', import.meta.url).pathname;
mkdirSync(SHOTS, { recursive: true });
const validator = createRequire(import.meta.url)('gltf-validator');

let browser;
let base;
let close;
before(async () => ({ browser, base, close } = await session()));
after(() => close());

/** Clicks the download button `what` and saves the file; returns its path and bytes. */
async function download(page, what, file) {
  const [event] = await Promise.all([page.waitForEvent('download', { timeout: 300_000 }), page.click(`#download-${what}`)]);
  const path = `${SHOTS}${file ?? event.suggestedFilename()}`;
  await event.saveAs(path);
  return { name: event.suggestedFilename(), path, bytes: readFileSync(path) };
}

/** The JSON chunk of a GLB, and where its binary chunk starts. */
function glbJson(bytes) {
  const length = bytes.readUInt32LE(12);
  return { json: JSON.parse(bytes.subarray(20, 20 + length).toString()), bin: 20 + length + 8 };
}

const TYPES = { '.js': 'text/javascript', '.glb': 'model/gltf-binary', '.html': 'text/html' };

/**
 * Opens `glb` in three.js's GLTFLoader on a page of its own (three.js served from
 * node_modules, only for this test), lit by a room environment and seen as the page first
 * sees the shell (from the front, `pitch` radians above, the same field of view), on a canvas
 * of `width × height`. Returns what the loader found and the picture as PNG bytes.
 */
async function openInThree(glb, width, height, pitch) {
  const page = await browser.newPage({ viewport: { width, height } });
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  const html = `<!doctype html><html><body style="margin:0;background:#f4f1ea">
<canvas id="c" width="${width}" height="${height}"></canvas>
<script type="importmap">{"imports":{"three":"./three/build/three.module.js","three/addons/":"./three/examples/jsm/"}}</script>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { RoomEnvironment } from 'three/addons/environments/RoomEnvironment.js';
try {
  const renderer = new THREE.WebGLRenderer({ canvas: document.getElementById('c'), antialias: true, preserveDrawingBuffer: true });
  renderer.setClearColor(0xf4f1ea);
  const scene = new THREE.Scene();
  renderer.toneMapping = THREE.NeutralToneMapping;
  scene.environment = new THREE.PMREMGenerator(renderer).fromScene(new RoomEnvironment(), 0.04).texture;
  scene.environmentIntensity = 0.55;
  const key = new THREE.DirectionalLight(0xfff7ee, 1.2);
  key.position.set(-0.45, 0.75, 0.55);
  scene.add(key);
  const gltf = await new GLTFLoader().loadAsync('./shell.glb');
  scene.add(gltf.scene);
  const box = new THREE.Box3().setFromObject(gltf.scene);
  const centre = box.getCenter(new THREE.Vector3());
  const size = box.getSize(new THREE.Vector3());
  const fov = 0.6;
  const distance = size.length() / 2 / Math.sin(fov / 2);
  const camera = new THREE.PerspectiveCamera(fov * 180 / Math.PI, ${width} / ${height}, distance / 100, distance * 3);
  camera.position.set(centre.x, centre.y + distance * Math.sin(${pitch}), centre.z + distance * Math.cos(${pitch}));
  camera.lookAt(centre);
  renderer.render(scene, camera);
  const meshes = [];
  gltf.scene.traverse((o) => { if (o.isMesh) meshes.push({ name: o.material.name, textured: Boolean(o.material.map), triangles: o.geometry.index.count / 3, uv: Boolean(o.geometry.attributes.uv) }); });
  window.loaded = { meshes, size: size.toArray() };
} catch (e) {
  window.loaded = { error: String(e) };
}
</script></body></html>`;
  await page.route('**/three-viewer/**', (route) => {
    const path = new URL(route.request().url()).pathname.replace(/^\/three-viewer\//, '');
    const ext = path.slice(path.lastIndexOf('.'));
    if (path === 'index.html') return route.fulfill({ body: html, contentType: TYPES['.html'] });
    if (path === 'shell.glb') return route.fulfill({ body: glb, contentType: TYPES['.glb'] });
    if (path.startsWith('three/')) {
      return route.fulfill({ body: readFileSync(`${ROOT}node_modules/${path}`), contentType: TYPES[ext] ?? 'application/octet-stream' });
    }
    return route.fulfill({ status: 404, body: 'not found' });
  });
  try {
    await page.goto(`${base}three-viewer/index.html`);
    await page.waitForFunction(() => window.loaded, null, { timeout: 60_000 });
    const loaded = await page.evaluate(() => window.loaded);
    const picture = await page.locator('#c').screenshot();
    return { loaded, picture, errors };
  } finally {
    await page.close();
  }
}

/** Two PNGs side by side on the page's background, as PNG bytes (made in `page`). */
async function sideBySide(page, left, right) {
  const png = await page.evaluate(async ([a, b]) => {
    const bitmaps = await Promise.all([a, b].map((bytes) => createImageBitmap(new Blob([new Uint8Array(bytes)], { type: 'image/png' }))));
    const gap = 16;
    const canvas = new OffscreenCanvas(bitmaps[0].width + gap + bitmaps[1].width, Math.max(bitmaps[0].height, bitmaps[1].height));
    const g = canvas.getContext('2d');
    g.fillStyle = '#f4f1ea';
    g.fillRect(0, 0, canvas.width, canvas.height);
    g.drawImage(bitmaps[0], 0, 0);
    g.drawImage(bitmaps[1], bitmaps[0].width + gap, 0);
    const blob = await canvas.convertToBlob({ type: 'image/png' });
    return Array.from(new Uint8Array(await blob.arrayBuffer()));
  }, [[...left], [...right]]);
  return Buffer.from(png);
}

/** The share of pixels of a PNG that differ from its corner's colour (by more than 24). */
async function covered(page, png) {
  return page.evaluate(async (bytes) => {
    const bitmap = await createImageBitmap(new Blob([new Uint8Array(bytes)], { type: 'image/png' }));
    const c = new OffscreenCanvas(bitmap.width, bitmap.height);
    const g = c.getContext('2d');
    g.drawImage(bitmap, 0, 0);
    const { data } = g.getImageData(0, 0, bitmap.width, bitmap.height);
    let n = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (Math.abs(data[i] - data[0]) + Math.abs(data[i + 1] - data[1]) + Math.abs(data[i + 2] - data[2]) > 24) n += 1;
    }
    return n / (data.length / 4);
  }, [...png]);
}

test("the menu offers every file with its size, and the Oliva's GLB passes the validator and opens in three.js", async () => {
  const { page, errors } = await open(browser, `${base}#v=1&preset=oliva-porphyria&growth.speed=200`, { width: 1200, height: 760 });
  try {
    await waitForState(page, ['grown']);
    const buttons = await page.$$eval('.downloads button', (bs) => bs.map((b) => ({ id: b.id, size: b.querySelector('.size').textContent })));
    assert.deepEqual(buttons.map((b) => b.id), ['glb', 'ply', '3mf', 'obj', 'stl', 'picture', 'pattern'].map((w) => `download-${w}`));
    for (const { id, size } of buttons) assert.match(size, /^≈ [\d.]+ MB$|^\d+ × \d+$/, `${id} shows "${size}"`);
    assert.equal(buttons.at(-1).size, '400 × 2900');
    await page.locator('.downloads').screenshot({ path: `${SHOTS}menu.png` });
    const shot = await page.locator('#shell').screenshot({ path: `${SHOTS}oliva-page.png` });
    const box = await page.locator('#shell').boundingBox();

    const glb = await download(page, 'glb');
    assert.equal(glb.name, 'oliva-porphyria.glb');
    assert.equal(glb.bytes.subarray(0, 4).toString(), 'glTF');
    assert.equal(await page.textContent('#size-glb'), `${(glb.bytes.length / 1e6).toFixed(1)} MB`, 'the exact size once made');
    assert.equal(await page.evaluate(() => document.body.dataset.download), 'offered');
    const report = await validator.validateBytes(new Uint8Array(glb.bytes));
    const problems = report.issues.messages.filter((m) => m.severity === 0);
    console.log(`# oliva-porphyria.glb from the page: ${glb.bytes.length} bytes, validator ${report.issues.numErrors} errors, ${report.issues.numWarnings} warnings`);
    assert.equal(report.issues.numErrors, 0, JSON.stringify(problems));
    assert.equal(report.info.hasTextures, true);

    const three = await openInThree(glb.bytes, Math.round(box.width), Math.round(box.height), 0.2);
    assert.deepEqual(three.errors, []);
    assert.equal(three.loaded.error, undefined, three.loaded.error);
    const shell = three.loaded.meshes.find((m) => m.name === 'shell');
    assert.ok(shell && shell.textured && shell.uv, JSON.stringify(three.loaded.meshes));
    assert.ok(three.loaded.meshes.some((m) => m.name === 'interior'));
    assert.ok(Math.abs(three.loaded.size[1] - 0.08) < 1e-6, `stands ${three.loaded.size[1]} m tall`);
    const share = await covered(page, three.picture);
    assert.ok(share > 0.1, `three.js drew the shell on only ${share} of its canvas`);
    const both = await sideBySide(page, shot, three.picture);
    writeFileSync(`${SHOTS}oliva-page-and-three.png`, both);
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('the Murex at its own resolution is written over many frames with a progress bar, as the command line writes it', async () => {
  const link = 'v=1&preset=murex-cabritii';
  const { page, errors } = await open(browser, `${base}#${link}`);
  try {
    await waitForState(page, ['growing', 'grown']);
    await page.keyboard.press('e');
    await waitForState(page, ['grown'], 300_000);
    await page.evaluate(() => {
      window.seen = { frames: 0, progress: [] };
      const bar = document.getElementById('download-progress');
      const frame = () => {
        if (document.body.dataset.download === 'writing') {
          window.seen.frames += 1;
          if (!bar.hidden) window.seen.progress.push(bar.value);
        }
        requestAnimationFrame(frame);
      };
      document.querySelector('.downloads').scrollIntoView();
      requestAnimationFrame(frame);
    });
    const started = Date.now();
    const writing = download(page, 'glb');
    await page.waitForFunction(() => document.getElementById('download-progress').value > 0.3, null, { timeout: 120_000 });
    await page.locator('.downloads').screenshot({ path: `${SHOTS}murex-writing.png` });
    const glb = await writing;
    const seconds = (Date.now() - started) / 1000;
    const seen = await page.evaluate(() => window.seen);
    console.log(`# murex-cabritii.glb: ${glb.bytes.length} bytes, written in ${seconds.toFixed(1)} s over ${seen.frames} frames`);
    assert.ok(seen.frames >= 10, `written in ${seen.frames} frames`);
    assert.ok(seen.progress.some((p) => p > 0.1 && p < 0.9), `progress shown: ${seen.progress.slice(0, 20)}`);
    assert.equal(await page.isHidden('#download-progress'), true, 'the bar goes once the file is made');

    const native = `${SHOTS}murex-native.glb`;
    execFileSync(CLI, ['mesh', '--link', link, '--out', native]);
    const expected = readFileSync(native);
    // The same document bit for bit (the page may have grown its triangles in another order
    // than the command line, so the arrays are compared by their layout and bounds).
    assert.equal(glb.bytes.length, expected.length);
    const [a, b] = [glbJson(glb.bytes), glbJson(expected)];
    assert.deepEqual(a.json, b.json);
    // The Murex's parts are textured apart and blended by field (Galbraith et al. §3.4): its
    // colours travel per vertex, as COLOR_0, not as one pattern texture.
    assert.ok(a.json.meshes[0].primitives.some((p) => 'COLOR_0' in p.attributes), 'the blended colours as COLOR_0');
    assert.equal(a.json.images, undefined, 'no pattern texture beside the vertex colours');
    const report = await validator.validateBytes(new Uint8Array(glb.bytes));
    assert.equal(report.issues.numErrors, 0);
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('a mesh asked of an implicit shell still growing is of the whole shell, finished first', async () => {
  const link = 'v=1&preset=implicit-whorl&form.resolution=48&growth.speed=0.2';
  const { page, errors } = await open(browser, `${base}#${link}`);
  try {
    await waitForState(page, ['growing']);
    const stages = page.evaluate(() => new Promise((resolve) => {
      const seen = [];
      const frame = () => {
        const stage = document.body.dataset.download ?? '';
        if (seen.at(-1) !== stage) seen.push(stage);
        if (stage === 'offered' || stage === 'refused') resolve(seen);
        else requestAnimationFrame(frame);
      };
      requestAnimationFrame(frame);
    }));
    const stl = await download(page, 'stl', 'implicit-whorl-while-growing.stl');
    assert.equal(stl.name, 'implicit-whorl.stl');
    const seen = await stages;
    assert.ok(seen.includes('finishing'), `stages: ${seen}`);
    assert.equal(seen.at(-1), 'offered', `stages: ${seen}`);
    assert.equal(await page.evaluate(() => document.body.dataset.growth), 'done', 'the shell was grown whole');
    await waitForState(page, ['grown']);
    const triangles = stl.bytes.readUInt32LE(80);
    const mesh = await page.evaluate(() => document.body.dataset.mesh);
    assert.equal(`${triangles}`, mesh.match(/(\d+) triangles/)[1], `the STL holds the whole shell (${mesh})`);
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('what cannot be exported says why, and nothing downloads', async () => {
  const cases = [
    // Growth stopped: the pattern diverged.
    ['v=1&preset=oliva-porphyria&pattern.model.kappa=0&pattern.model.rho=5', 'stopped', 'glb', null, /stopped growing/],
    // A size no printer makes.
    ['v=1&preset=turbinate&form.spiral.whorls=2&growth.speed=200', 'grown', '3mf', '0', /Size: 0 mm is outside/],
    // A surface with no wall cannot be printed.
    ['v=1&preset=turbinate&form.spiral.whorls=2&form.wall.thickness=0&growth.speed=200', 'grown', '3mf', null, /form\.wall\.thickness/],
    // Whorls that come round onto themselves: the page shows them and says so; no file.
    ['v=1&preset=kawaguchi-ammonite&form.chamber.ratio=1&growth.speed=200', 'grown', 'stl', null, /form\.chamber\.ratio: whorls overlap/],
  ];
  for (const [link, state, what, size, said] of cases) {
    const { page } = await open(browser, `${base}#${link}`);
    try {
      assert.equal((await waitForState(page, [state, 'error'])).state, state, link);
      if (size !== null) await page.fill('#download-size', size);
      let downloaded = false;
      page.on('download', () => { downloaded = true; });
      await page.click(`#download-${what}`);
      await page.waitForFunction(() => document.body.dataset.download === 'refused', null, { timeout: 60_000 });
      assert.match(await page.textContent('#message'), said, link);
      assert.ok(await page.isVisible('#message'));
      await page.waitForTimeout(500);
      assert.equal(downloaded, false, `${link}: a file was offered`);
      assert.equal(await page.isEnabled(`#download-${what}`), true, 'the menu works again');
    } finally {
      await page.close();
    }
  }
});
