// The page grows a lit shell on either backend, the camera following it so that a third of the
// way into growth it already fills the view, and says so in words when it cannot.
// Screenshots are kept in tests/page/screenshots/ (git-ignored) for people to look at.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { chromium } from 'playwright-core';
import { serve } from './serve.mjs';
import { PRESETS, launch, open, waitForState, measureCanvas, measurePng } from './browser.mjs';

const SHOTS = new URL('./screenshots/', import.meta.url).pathname;
mkdirSync(SHOTS, { recursive: true });
let server;
let base;

before(async () => {
  server = await serve(new URL('../../www/', import.meta.url).pathname);
  base = `http://127.0.0.1:${server.address().port}/`;
});
after(() => server.close());

for (const backend of ['WebGL2', 'WebGPU']) {
  test(`a lit shell grows on ${backend}, framed as it grows`, async () => {
    const browser = await launch(backend);
    try {
      const { page, errors } = await open(browser, `${base}#v=1&preset=turbinate&growth.speed=6`);
      const ready = await waitForState(page, ['growing', 'grown', 'error']);
      assert.equal(ready.state, 'growing', `the page reported ${ready.state}`);
      assert.equal(ready.backend, backend, 'the backend reported matches the flags');
      await page.waitForFunction(() => Number(document.body.dataset.rows) >= 192);
      // Pause there, and let the camera's easing (a third of a second) catch up.
      await page.keyboard.press('Space');
      await page.waitForFunction(() => document.body.dataset.playing === 'false');
      const rows = Number((await page.evaluate(() => document.body.dataset.rows)));
      assert.ok(rows < 576 / 2, `paused at row ${rows}`);
      await page.waitForTimeout(1500);
      const third = await measureCanvas(page, `${SHOTS}growth-${backend}-third.png`);
      // The rest at once (the Finish key): at six rows a frame it took a minute in software.
      await page.keyboard.press('e');
      await waitForState(page, ['grown']);
      await page.waitForTimeout(1500);
      const late = await measureCanvas(page, `${SHOTS}growth-${backend}-grown.png`);
      assert.ok(late.share > 0.04, `the grown shell covers only ${late.share} of the canvas`);
      assert.ok(late.shades > 40, `only ${late.shades} distinct shades: not a lit surface`);
      assert.ok(third.share > 0.5 * late.share, `a third of the way in the shell covers ${third.share}, grown ${late.share}`);
      assert.match(await page.textContent('#backend'), new RegExp(backend));
      assert.deepEqual(errors, []);
    } finally {
      await browser.close();
    }
  });
}

test('a growing shell uploads what it adds, never zeros for the room its buffers keep (WebGL2)', async () => {
  // The Murex's buffers are sized for the grown shell (about 60 MB); a draw that bound all of
  // them had wgpu fill what nothing had written with zeros, one upload of that size in the
  // first frames of growth (53 ms of the page's thread).
  const browser = await launch('WebGL2');
  try {
    const page = await browser.newPage({ viewport: { width: 900, height: 700 } });
    await page.addInitScript(() => {
      window.__uploads = [];
      const upload = WebGL2RenderingContext.prototype.bufferSubData;
      WebGL2RenderingContext.prototype.bufferSubData = function (target, offset, source, from = 0, length) {
        const size = source?.BYTES_PER_ELEMENT ?? 1;
        const count = length ?? (source?.byteLength ?? 0) / size - from;
        window.__uploads.push({ bytes: count * size });
        return upload.apply(this, arguments);
      };
      const allocate = WebGL2RenderingContext.prototype.bufferData;
      window.__room = 0;
      WebGL2RenderingContext.prototype.bufferData = function (target, size) {
        if (typeof size === 'number') window.__room = Math.max(window.__room, size);
        return allocate.apply(this, arguments);
      };
    });
    // The renderer drawn on the page's thread (`view=page`), where this script can watch its
    // WebGL calls: in the drawing worker it is the same code.
    await page.goto(`${base}?workers=1&view=page#v=1&preset=murex-cabritii`);
    await waitForState(page, ['growing']);
    await page.waitForFunction(() => Number(document.body.dataset.rows) >= 12, null, { timeout: 120_000 });
    const { uploads, room } = await page.evaluate(() => ({ uploads: window.__uploads, room: window.__room }));
    assert.ok(room > 20e6, `the largest buffer is ${room} bytes: not sized for the grown Murex`);
    assert.ok(uploads.some((u) => u.bytes > 0), 'nothing was uploaded');
    const largest = Math.max(...uploads.map((u) => u.bytes));
    assert.ok(largest < room / 4, `an upload of ${largest} bytes by row 12, buffers of ${room}`);
  } finally {
    await browser.close();
  }
});

test('without WebGPU or WebGL2 the page says why in a sentence, lists every shell and still grows its pattern and files', async () => {
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu', '--disable-webgl', '--disable-3d-apis', '--disable-features=WebGPU'],
  });
  try {
    // Chromium's flags take WebGL away from canvas elements but not from an OffscreenCanvas,
    // which the drawing worker would draw on: here no canvas can be handed to it either.
    const context = await browser.newContext({ viewport: { width: 1100, height: 760 } });
    await context.addInitScript(() => {
      HTMLCanvasElement.prototype.transferControlToOffscreen = () => {
        throw new Error('no OffscreenCanvas in this test');
      };
    });
    const page = await context.newPage();
    const errors = [];
    page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.goto(base);
    const state = await waitForState(page, ['gallery', 'error']);
    assert.equal(state.state, 'gallery');
    assert.equal(state.backend, 'none');
    assert.ok(await page.isVisible('#no-3d'));
    const notice = await page.textContent('#no-3d p');
    assert.match(notice, /could not draw the shells in 3D.*WebGPU or WebGL2.*Firefox, Chrome, Edge and Safari.*links.*pattern PNG.*mesh files/s);
    assert.equal(await page.isVisible('#no-3d-details'), false, 'the technical cause is folded away');
    await page.click('#no-3d summary');
    assert.match(await page.textContent('#no-3d-details'), /WebGL2/);
    assert.equal(await page.isVisible('#message'), false, 'no error on top of the notice');
    assert.equal(await page.locator('a.card').count(), PRESETS, 'every shell is listed');
    await page.waitForFunction(() => document.body.dataset.pictures === 'none');
    await page.screenshot({ path: `${SHOTS}no-graphics.png` });

    // A shell still grows: its pattern in the planar view, its files.
    await page.click('a.card[data-preset="oliva-porphyria"]');
    await page.waitForFunction(() => Number(document.body.dataset.rows) >= 300, null, { timeout: 120_000 });
    const planar = await measurePng(await page.locator('#planar').screenshot());
    assert.ok(planar.share > 0.05 && planar.shades > 5, `the planar view shows the pattern (${JSON.stringify(planar)})`);
    await page.click('#finish');
    await waitForState(page, ['grown']);
    assert.match((await page.evaluate(() => ({ ...document.body.dataset }))).patternHash, /^[0-9a-f]{16}$/);
    assert.equal(await page.isVisible('#download-picture'), false, 'no picture of a view not drawn');
    for (const [button, name] of [['#download-pattern', 'oliva-porphyria-pattern.png'], ['#download-stl', 'oliva-porphyria.stl']]) {
      const [download] = await Promise.all([page.waitForEvent('download'), page.click(button)]);
      assert.equal(download.suggestedFilename(), name);
    }
    await page.screenshot({ path: `${SHOTS}no-graphics-shell.png` });
    assert.deepEqual(errors, []);
  } finally {
    await browser.close();
  }
});
