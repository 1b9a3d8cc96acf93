// A page that survives: a destroyed WebGPU device, a lost WebGL context (given back by the
// browser, or not), a panic, and a drawing worker that fails. After a lost device the page opens
// another (WebGPU again, or WebGL2 when WebGPU cannot be had) and shows the shell again where it
// was, growth resumed, not restarted; the finished shell then has the hashes the native core
// gives the link. After a panic the page says what it was doing and offers a button that reloads
// the link, which grows the same shell again. A drawing worker that hangs before it opens, or
// whose frames the GPU never finishes, gives way to the page's thread. The device is destroyed and the panic
// forced through test-only hooks exported by the wasm module (src/web/debug.rs), the context lost
// with WEBGL_lose_context by another (the drawing worker's canvas is offscreen, so the test
// cannot reach its context), the worker made to fail by test-only switches of
// www/drawing-worker.js. Screenshots after each recovery are kept in tests/page/screenshots/ for
// people to look at.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { finishGrowth, session, open, waitForState, measureCanvas, measurePng, differing, cardPictures, hook } from './browser.mjs';
import { nativeMesh, nativePattern } from './native.mjs';

const SHOTS = new URL('./screenshots/', import.meta.url).pathname;
mkdirSync(SHOTS, { recursive: true });
// A swept shell with a reaction-diffusion pattern (2,100 rows), grown slowly enough to stop it
// on the way.
const LINK = '#v=1&preset=stripes&growth.speed=8';
const PAUSE_AT = 150;

/** The page's hashes of the finished shell. */
async function finished(page) {
  const state = await finishGrowth(page);
  assert.equal(state.state, 'grown', await page.textContent('#message'));
  return { pattern: state.patternHash, mesh: state.meshHash, counts: state.mesh };
}

/**
 * The hashes of the link's whole shell as the native core grows it (the command line; the page
 * grows the same bits, which pattern.test.mjs and implicit.test.mjs check), computed once.
 */
function fresh() {
  const mesh = nativeMesh(LINK.slice(1));
  return { pattern: nativePattern(LINK.slice(1)), mesh: mesh.hash, counts: mesh.counts };
}

/** Opens the link, lets it grow past PAUSE_AT rows and pauses; returns the row it stopped at. */
async function grownAndPaused(page) {
  await waitForState(page, ['growing']);
  await page.waitForFunction((n) => Number(document.body.dataset.rows) >= n, PAUSE_AT, { timeout: 120_000 });
  await page.keyboard.press('Space');
  await page.waitForFunction(() => document.body.dataset.playing === 'false');
  // Rows asked of the worker before the pause still arrive: wait until every answer is in.
  await page.waitForFunction(() => document.body.dataset.settled === 'true', null, { timeout: 60_000 });
  await page.waitForTimeout(300);
  return Number(await page.evaluate(() => document.body.dataset.rows));
}

/**
 * Marks the canvas element (a property, which a copy of the element does not take), to tell
 * afterwards whether a fresh one took its place; and keeps every message the page shows from
 * now on in `window.messages`.
 */
function markCanvas(page) {
  return page.evaluate(() => {
    document.getElementById('shell').original = true;
    window.messages = [];
    const message = document.getElementById('message');
    new MutationObserver(() => window.messages.push(message.textContent))
      .observe(message, { childList: true, characterData: true, subtree: true });
  });
}

/**
 * Waits for the page to say that the device was opened again, checks that growth resumed where
 * it stopped (same row, still paused), that the shell is drawn again, that the canvas still
 * answers a drag, and that the finished shell has the hashes the native core gives the link.
 */
async function checkRecovered(page, { row, backend, sameCanvas, shot }) {
  await page.waitForFunction(() => document.body.dataset.recoveries === '1', null, { timeout: 60_000 });
  const state = await waitForState(page, ['growing']);
  const said = await page.evaluate(() => window.messages);
  assert.ok(said.some((m) => /^The graphics device was lost \(.+\); opening it again/.test(m)), `said: ${said.join(' | ')}`);
  assert.equal(state.backend, backend, 'the backend the device was opened again with');
  assert.equal(Number(state.rows), row, 'growth goes on from the row it had reached, not from the apex');
  assert.match(await page.textContent('#message'), new RegExp(`opened again, with ${backend}: the shell goes on from row ${row}`));
  assert.equal(
    await page.evaluate(() => document.getElementById('shell').original === true),
    sameCanvas,
    sameCanvas ? 'drawn again on the same canvas' : 'drawn on a fresh canvas',
  );
  await page.waitForTimeout(1000);
  const drawn = await measureCanvas(page, `${SHOTS}survive-${shot}.png`);
  assert.ok(drawn.share > 0.03, `after recovery the shell covers only ${drawn.share} of the canvas`);
  assert.ok(drawn.shades > 30, `after recovery only ${drawn.shades} shades: not the lit shell`);
  // The canvas still answers: a drag turns the shell.
  const before = await page.locator('#shell').screenshot();
  const box = await page.locator('#shell').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 160, box.y + box.height / 2, { steps: 8 });
  await page.mouse.up();
  await page.waitForTimeout(800);
  const turned = await page.locator('#shell').screenshot();
  const moved = differing(before, turned);
  assert.ok(moved > 0.01, `a drag after recovery changed only ${moved} of the canvas`);
  const after = await finished(page);
  assert.deepEqual(after, fresh(), 'the finished shell is the link\'s, as the native core grows it');
}

/** How each test takes the device away, and how the page must come back. */
const LOSSES = [
  {
    name: 'a destroyed WebGPU device is opened again and the shell goes on where it was',
    backend: 'WebGPU',
    lose: (page) => hook(page, 'debug_destroy_device'),
    back: { backend: 'WebGPU', sameCanvas: true, shot: 'webgpu-destroyed' },
  },
  {
    name: 'when WebGPU cannot be had again, the shell goes on with WebGL2 on a fresh canvas',
    backend: 'WebGPU',
    lose: async (page) => {
      // From now on the browser has no WebGPU adapter to give (on the page's thread and in the
      // worker that draws the view).
      await hook(page, 'debug_take_webgpu_away');
      await hook(page, 'debug_destroy_device');
    },
    back: { backend: 'WebGL2', sameCanvas: false, shot: 'webgpu-to-webgl2' },
  },
  {
    name: 'a lost WebGL context that the browser gives back is drawn on again',
    backend: 'WebGL2',
    // The canvases draw off the page's layout (transferControlToOffscreen): the hook loses
    // their contexts with WEBGL_lose_context, here given back 300 ms later.
    lose: (page) => hook(page, 'debug_lose_context', 300),
    back: { backend: 'WebGL2', sameCanvas: true, shot: 'webgl-restored' },
  },
  {
    name: 'a lost WebGL context that never comes back is replaced by a fresh canvas',
    backend: 'WebGL2',
    lose: (page) => hook(page, 'debug_lose_context'),
    back: { backend: 'WebGL2', sameCanvas: false, shot: 'webgl-not-restored' },
  },
];

for (const { name, backend, lose, back } of LOSSES) {
  test(name, async () => {
    const run = await session(backend);
    try {
      const { page } = await open(run.browser, `${run.base}${LINK}`);
      const row = await grownAndPaused(page);
      assert.equal(await page.evaluate(() => document.body.dataset.backend), backend);
      await markCanvas(page);
      await lose(page);
      await checkRecovered(page, { row, ...back });
    } finally {
      await run.close();
    }
  });
}

for (const backend of ['WebGL2', 'WebGPU']) {
  test(`a panic on ${backend} says what was being done and reloading the link grows the shell again`, async () => {
    const run = await session(backend);
    try {
      const { page, errors } = await open(run.browser, `${run.base}${LINK}`);
      await waitForState(page, ['growing']);
      await page.waitForFunction((n) => Number(document.body.dataset.rows) >= n, 100, { timeout: 120_000 });
      await hook(page, 'debug_panic_while_growing');
      const state = await waitForState(page, ['error']);
      assert.equal(state.crashed, 'true');
      assert.ok(await page.isVisible('#crash'));
      const text = await page.textContent('#crash-text');
      assert.match(text, /^Something went wrong while growing stripes, row \d+: .*debug_panic_while_growing/s);
      assert.ok(errors.some((e) => /debug_panic_while_growing/.test(e)), 'the console has the full report');
      // The page does not freeze or go blank: the last picture stays, keys and clicks are
      // ignored without a second panic covering the first's message.
      await page.screenshot({ path: `${SHOTS}survive-panic-page-${backend}.png` });
      const still = await measureCanvas(page, `${SHOTS}survive-panic-${backend}.png`);
      assert.ok(still.share > 0.03, `after the panic the canvas shows only ${still.share} of a shell`);
      await page.keyboard.press('Space');
      await page.click('#finish', { force: true }).catch(() => {});
      assert.equal(await page.textContent('#crash-text'), text, 'the first message stays');
      await Promise.all([page.waitForEvent('load'), page.click('#reload')]);
      await page.waitForFunction(() => document.body.dataset.crashed === undefined && document.body.dataset.state === 'growing');
      assert.equal(await page.isVisible('#crash'), false);
      assert.equal(new URL(page.url()).hash, LINK, 'the reload keeps the link');
      assert.deepEqual(await finished(page), fresh(), 'the reloaded shell is the link\'s, as the native core grows it');
      await measureCanvas(page, `${SHOTS}survive-panic-reloaded-${backend}.png`);
    } finally {
      await run.close();
    }
  });
}

/** Every card's picture, measured as the canvas is (`measurePng`: blank shows no share). */
async function pictures(page) {
  return Promise.all((await cardPictures(page)).map(async ({ preset, src, png }) => {
    const bytes = png ? Buffer.from(png) : null;
    return { preset, src, png: bytes !== null, digest: bytes?.toString('base64'), cover: bytes ? (await measurePng(bytes)).share : 0 };
  }));
}

for (const backend of ['WebGL2', 'WebGPU']) {
  test(`the gallery's pictures and the viewer survive losing every device on ${backend}`, async () => {
    const run = await session(backend);
    try {
      const { page } = await open(run.browser, run.base);
      await waitForState(page, ['gallery']);
      await page.waitForFunction(
        () => [...document.querySelectorAll('a.card img')].filter((i) => i.src.startsWith('blob:')).length >= 4,
        null, { timeout: 120_000 },
      );
      if (backend === 'WebGPU') {
        await hook(page, 'debug_destroy_device');
      } else {
        // Both canvases lose their contexts, which never come back: fresh canvases take over.
        await hook(page, 'debug_lose_context');
      }
      await page.waitForFunction(() => document.body.dataset.recoveries === '1', null, { timeout: 60_000 });
      await page.waitForFunction(() => document.body.dataset.pictures === 'done', null, { timeout: 300_000 });
      assert.equal(await page.evaluate(() => document.body.dataset.state), 'gallery');
      assert.equal(await page.isVisible('#message'), false, 'the gallery shows no message once drawn again');
      const drawn = await pictures(page);
      assert.ok(drawn.every((p) => p.png), 'every card has its picture');
      assert.equal(new Set(drawn.map((p) => p.digest)).size, drawn.length, 'every picture is a different shell');
      const blank = drawn.filter((p) => p.cover < 0.02).map((p) => `${p.preset} ${p.cover}`);
      assert.deepEqual(blank, [], 'no picture is blank');
      await page.screenshot({ path: `${SHOTS}survive-gallery-${backend}.png`, fullPage: true });
      // The viewer's own device was opened again too: a shell grows and is drawn.
      await page.evaluate(() => { window.location.hash = 'v=1&preset=stripes&growth.speed=200'; });
      const state = await waitForState(page, ['grown', 'error']);
      assert.equal(state.state, 'grown');
      const shell = await measureCanvas(page, `${SHOTS}survive-gallery-then-viewer-${backend}.png`);
      assert.ok(shell.share > 0.03, `the shell covers only ${shell.share} of the canvas`);
    } finally {
      await run.close();
    }
  });
}

// A drawing worker that never opens (it spins on its first message: the page's own 20 s
// allowance at start, web/viewer_handle.rs) and one whose frames the GPU never finishes (only a
// GPU shows it): each time the page draws on its own thread instead, on a fresh canvas, and says
// why (test-only switches of www/drawing-worker.js). A drawing worker that falls silent once
// open is found out by `work::drawing_link`, and the view's move to the page's thread while the
// user goes on clicking is `tests/simulator.rs`'s.
for (const [switchName, why] of [
  ['hang-view', /said nothing in 20 s/],
  ['stall-view', /has finished none of the frames handed to it in 10 s/],
]) {
  test(`a drawing worker that fails (${switchName}) gives way to the page's thread, which draws the shell`, async () => {
    const s = await session('WebGL2');
    try {
      const { page, errors } = await open(s.browser, `${s.base}?${switchName}${LINK}`);
      const consoled = [];
      page.on('console', (m) => consoled.push(m.text()));
      await page.waitForFunction(() => document.body.dataset.drawnIn === 'page', null, { timeout: 90_000 });
      const state = await waitForState(page, ['growing', 'grown']);
      assert.equal(state.backend, 'WebGL2');
      if (switchName === 'stall-view') {
        assert.match(await page.textContent('#message'), /could not be drawn in a worker here, so the page draws it on its own thread/);
      } else {
        assert.match(await page.textContent('#workers-status'), /Drawn on the page's thread: this browser cannot draw in a worker/);
      }
      await page.waitForFunction(() => Number(document.body.dataset.rows) >= 100, null, { timeout: 120_000 });
      const shot = await measureCanvas(page, `${SHOTS}survive-${switchName}.png`);
      assert.ok(shot.share > 0.03 && shot.shades > 20, `the page's thread draws the shell (${JSON.stringify(shot)})`);
      assert.ok(consoled.some((line) => why.test(line)), `the console says why: ${consoled.join(' | ')}`);
      assert.deepEqual(errors, []);
    } finally {
      await s.close();
    }
  });
}
