// The page after one visit works with the network gone (its service worker, www/service-worker.js,
// keeps every file it runs on, named for the build): the gallery draws, a shell grows, is edited
// in the panel and downloads as a file. A newer build served later is kept beside the old one
// and waits: the page says so, still gets the old build's module, and once the reader asks, it
// reloads into the new build, whose module it then gets. Screenshots go to
// tests/page/screenshots/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { cpSync, mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { createHash } from 'node:crypto';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { serve } from './serve.mjs';
import { launch, open, waitForState, measureCanvas } from './browser.mjs';

const WWW = new URL('../../www/', import.meta.url).pathname;
const SHOTS = new URL('./screenshots/', import.meta.url).pathname;
mkdirSync(SHOTS, { recursive: true });
const LINK = 'v=1&preset=stripes&growth.speed=200';

let browser;
before(async () => {
  browser = await launch('WebGL2');
});
after(() => browser.close());

/** Waits until the page is served by its offline copy (`data-offline`). */
function offline(page, state) {
  return page.waitForFunction((s) => document.body.dataset.offline === s, state, { timeout: 60_000 });
}

/** Stops serving: no new connection, and those kept alive cut. */
function stop(server) {
  server.close();
  server.closeAllConnections();
}

/** The SHA-256 of the WebAssembly module as the page fetches it now. */
function servedModule(page) {
  return page.evaluate(async () => {
    const bytes = await (await fetch('pkg/seashells_bg.wasm')).arrayBuffer();
    const digest = await crypto.subtle.digest('SHA-256', bytes);
    return [...new Uint8Array(digest)].map((b) => b.toString(16).padStart(2, '0')).join('');
  });
}

const sha256 = (bytes) => createHash('sha256').update(bytes).digest('hex');

test('after one visit the page works with the network gone: the gallery, a shell grown and edited, a file downloaded', async () => {
  const server = await serve(WWW);
  const base = `http://127.0.0.1:${server.address().port}/`;
  const { page, errors } = await open(browser, `${base}#${LINK}`);
  try {
    await waitForState(page, ['growing', 'grown']);
    await offline(page, 'ready');
    stop(server);
    await page.context().setOffline(true);
    // Offline, with a switch in the query that the drawing worker reads from its own address.
    await page.goto(`${base}?workers=3#${LINK}`);
    const grown = await waitForState(page, ['grown']);
    assert.match(await page.textContent('#workers-status'), /on 3 workers/, 'the drawing worker read the page\'s query');
    const shell = await measureCanvas(page, `${SHOTS}offline-grown.png`);
    assert.ok(shell.share > 0.03, `offline, the shell covers only ${shell.share} of the canvas`);
    // An edit in the panel grows another shell, and its link follows.
    await page.evaluate(() => {
      const slider = document.querySelector('.field[data-key="form.spiral.whorls"] input[type=range]');
      slider.value = String(Math.round(Number(slider.max) * 0.2));
      slider.dispatchEvent(new Event('input', { bubbles: true }));
      slider.dispatchEvent(new Event('change', { bubbles: true }));
    });
    await page.waitForFunction(() => location.hash.includes('form.spiral.whorls='), null, { timeout: 30_000 });
    await page.click('#finish');
    const edited = await waitForState(page, ['grown']);
    assert.ok(edited.meshHash && grown.meshHash, 'both shells have their mesh hash');
    assert.notEqual(edited.meshHash, grown.meshHash, 'fewer whorls, another mesh');
    // A file is written and offered, all on this machine.
    const [download] = await Promise.all([page.waitForEvent('download', { timeout: 120_000 }), page.click('#download-stl')]);
    const stl = readFileSync(await download.path());
    assert.ok(stl.length > 84 + 50 * 1000, `an STL of ${stl.length} bytes`);
    assert.equal(stl.readUInt32LE(80), (stl.length - 84) / 50, 'a binary STL whose count matches its size');
    // The gallery draws its pictures too.
    await page.evaluate(() => { window.location.hash = ''; });
    await waitForState(page, ['gallery']);
    await page.waitForFunction(
      () => [...document.querySelectorAll('a.card img')].filter((i) => i.src.startsWith('blob:')).length >= 4,
      null, { timeout: 120_000 },
    );
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('a newer build waits beside the old one, which the page keeps running on until it asks to reload', async () => {
  // Two builds of the page: this one, and one with another id whose module carries one more
  // custom section (the same code, other bytes).
  const root = mkdtempSync(join(tmpdir(), 'seashells-builds-'));
  const [first, second] = ['first', 'second'].map((name) => {
    const dir = join(root, name);
    cpSync(WWW, dir, { recursive: true });
    return dir;
  });
  const wasm = readFileSync(join(second, 'pkg/seashells_bg.wasm'));
  const name = Buffer.from('seashells-test-build');
  const content = Buffer.concat([Buffer.from([name.length]), name, Buffer.from('second')]);
  writeFileSync(join(second, 'pkg/seashells_bg.wasm'), Buffer.concat([wasm, Buffer.from([0, content.length]), content]));
  writeFileSync(join(second, 'pkg/build.js'), 'self.BUILD = "second-build";\n');
  const [oldModule, newModule] = [first, second].map((dir) => sha256(readFileSync(join(dir, 'pkg/seashells_bg.wasm'))));

  let server = await serve(first);
  const port = server.address().port;
  const { page, errors } = await open(browser, `http://127.0.0.1:${port}/#${LINK}`);
  try {
    await waitForState(page, ['growing', 'grown']);
    await offline(page, 'ready');
    assert.equal(await servedModule(page), oldModule);
    stop(server);
    server = await serve(second, port);
    await page.evaluate(() => navigator.serviceWorker.getRegistration().then((r) => r.update()));
    await offline(page, 'update');
    assert.equal(await page.isVisible('#update'), true, 'the page says a new version is ready');
    await page.screenshot({ path: `${SHOTS}offline-update.png` });
    assert.equal(await servedModule(page), oldModule, 'the page still gets its own build\'s module');
    await Promise.all([page.waitForEvent('load'), page.click('#update-reload')]);
    await offline(page, 'ready');
    assert.equal(await servedModule(page), newModule, 'reloaded, the new build\'s module');
    await waitForState(page, ['growing', 'grown']);
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
    stop(server);
  }
});
