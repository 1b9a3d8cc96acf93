// Growth off the page's thread (issue 30): the Murex finished by a pool
// of 1, 2 or 4 workers (`workers=N`, a debug parameter of the page's address; with 4 the
// finish is the GLB export's, asked while the shell grows, and the file is the command
// line's) and on the page's own thread (`workers=0`, the fallback) has the same mesh and
// pattern hashes; workers made to throw (`crash-workers=N`, test-only) or to hang (`hang-workers=N`) are
// replaced, their work redone to the same bits, and the page says so the second time (where
// none answers anything, the pool gives its workers up and the shell grows on the thread that
// draws it: `tests/simulator.rs` proves that decision, with the real pool); and a
// pattern being previewed when its worker throws (`debug_crash_worker_on_fill`, a test-only
// hook of the wasm module) is previewed whole all the same. The workers grow the shell and
// never touch the GPU, so these run on WebGL2 alone (the backend every engine can give); the
// drawing on WebGPU is the other suites' (drawing, growth, implicit, survive). What a value
// changed mid-growth does (the old growth's replies change nothing, the shell ends as the new
// link's; a grown implicit shell is remeshed whole at once) is proven natively, in any
// interleaving, by tests/simulator.rs and work::shell_change's tests.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { open, session, waitForState } from './browser.mjs';
import { CLI, nativeMesh, nativePattern } from './native.mjs';

// A coarse polygonization keeps the software-rendered page quick; it still splits into chunks.
const MUREX = 'v=1&preset=murex-cabritii&form.resolution=48';

/** The JSON chunk of a GLB. */
const glbJson = (bytes) => JSON.parse(bytes.subarray(20, 20 + bytes.readUInt32LE(12)).toString());

/**
 * Opens `query#fragment`, finishes growth at once (End, or with `glb` by asking for the GLB
 * download while the shell grows, which finishes it first), and returns the grown signals
 * (and the GLB's bytes).
 */
async function finished(browser, base, query, fragment, glb = false) {
  const { page, errors } = await open(browser, `${base}?${query}#${fragment}`);
  try {
    await waitForState(page, ['growing', 'grown']);
    let bytes;
    if (glb) {
      await page.waitForFunction(() => Number(document.body.dataset.rows) >= 10, null, { timeout: 120_000 });
      const [event] = await Promise.all([
        page.waitForEvent('download', { timeout: 300_000 }),
        page.click('#download-glb'),
      ]);
      bytes = readFileSync(await event.path());
    } else {
      await page.locator('#shell').click();
      await page.keyboard.press('End');
    }
    const grown = await waitForState(page, ['grown', 'error', 'stopped'], 180_000);
    assert.equal(grown.state, 'grown', `${query}: ${await page.textContent('#message')}`);
    const status = await page.textContent('#workers-status');
    assert.deepEqual(errors, []);
    return { ...grown, status, bytes };
  } finally {
    await page.close();
  }
}

const backend = 'WebGL2';
test(`the Murex finished by 1, 2 or 4 workers or on the page's thread is the same on ${backend}`, async () => {
  const { browser, base, close } = await session(backend);
  try {
    const runs = {};
    for (const workers of [1, 2, 4, 0]) {
      // With 4 workers the GLB is asked for while the shell grows: the export finishes it.
      runs[workers] = await finished(browser, base, `workers=${workers}`, MUREX, workers === 4);
      assert.equal(runs[workers].workers, String(workers));
    }
    // The file is the command line's (its triangles may come in another order: the page grew
    // some before finishing), by its layout: counts, bounds, attributes.
    const out = join(tmpdir(), `murex-${process.pid}.glb`);
    execFileSync(CLI, ['mesh', '--link', MUREX, '--out', out]);
    const cli = readFileSync(out);
    assert.equal(runs[4].bytes.length, cli.length, 'the GLB of the whole shell');
    assert.deepEqual(glbJson(runs[4].bytes), glbJson(cli));
    // Without workers the shell grows on the thread that draws the view: the drawing
    // worker's.
    assert.match(runs[0].status, /drawing worker's own thread/);
    assert.match(runs[2].status, /2 workers/);
    for (const workers of [2, 4, 0]) {
      assert.equal(runs[workers].meshHash, runs[1].meshHash, `mesh with ${workers} workers`);
      assert.equal(runs[workers].patternHash, runs[1].patternHash, `pattern with ${workers} workers`);
      assert.equal(runs[workers].mesh, runs[1].mesh);
    }
    assert.match(runs[1].meshHash, /^[0-9a-f]{16}$/);
  } finally {
    await close();
  }
});

test(`workers that throw or hang are replaced and their work redone on ${backend}`, async () => {
  const { browser, base, close } = await session(backend);
  try {
    const native = nativeMesh(MUREX);
    const reference = { meshHash: native.hash, patternHash: nativePattern(MUREX), mesh: native.counts };
    const crashed = await finished(browser, base, 'workers=1&crash-workers=2', MUREX);
    assert.equal(crashed.workerDeaths, '2');
    assert.match(crashed.status, /second time; it was replaced and its work done again/);
    assert.equal(crashed.meshHash, reference.meshHash);
    assert.equal(crashed.patternHash, reference.patternHash);
    // Both first workers spin without answering: the sessions' worker on building the shell,
    // the other on its first piece of the finish. Each is found out after a fifth of its
    // request's allowance (the switch's), terminated, and its work done by a fresh one.
    const hung = await finished(browser, base, 'workers=2&hang-workers=2', MUREX);
    assert.equal(hung.workerDeaths, '2');
    assert.match(hung.status, /did not answer in time\) for the second time; it was replaced and its work done again/);
    assert.equal(hung.meshHash, reference.meshHash);
    assert.equal(hung.patternHash, reference.patternHash);
    assert.equal(hung.mesh, reference.mesh);
  } finally {
    await close();
  }
});

test(`a pattern previewed while its worker dies is previewed whole by a fresh one on ${backend}`, async () => {
  const { browser, base, close } = await session(backend);
  try {
    const { page, errors } = await open(browser, `${base}?workers=1#v=1&preset=oliva-porphyria&growth.speed=1`);
    await waitForState(page, ['growing']);
    await page.evaluate(async () => {
      const module = await import(new URL('pkg/seashells.js', document.baseURI).href);
      module.debug_crash_worker_on_fill();
      const range = document.querySelector('.field[data-key="pattern.model.d_a"] input[type=range]');
      range.value = String(Math.round(Number(range.max) * 0.04));
      range.dispatchEvent(new Event('input', { bubbles: true }));
    });
    await page.waitForFunction(() => document.body.dataset.preview === 'whole', null, { timeout: 60_000 });
    const state = await page.evaluate(() => ({ ...document.body.dataset }));
    assert.equal(state.workerDeaths, '1', 'the worker threw on its first rows of the preview');
    const drawn = await page.evaluate(() => {
      const c = document.getElementById('planar');
      const { data } = c.getContext('2d').getImageData(0, c.height - 200, c.width, 200);
      let n = 0;
      for (let i = 3; i < data.length; i += 4) n += data[i] === 0 ? 0 : 1;
      return n;
    });
    assert.equal(drawn, 400 * 200, 'every cell of the preview\'s last rows is drawn');
    assert.deepEqual(errors, []);
    await page.close();
  } finally {
    await close();
  }
});
