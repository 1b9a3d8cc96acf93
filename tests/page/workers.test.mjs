// Growth off the page's thread (issue 30): on WebGL2 and WebGPU, the Murex finished by a pool
// of 1, 2 or 4 workers (`workers=N`, a debug parameter of the page's address) and on the
// page's own thread (`workers=0`, the fallback) has the same mesh and pattern hashes; a value
// changed mid-growth cancels what was in flight, so the shell ends as a fresh load of the new
// link; and workers made to throw (`crash-workers=N`, test-only) are replaced, their work
// redone to the same bits, and the page says so the second time.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { open, session, waitForState } from './browser.mjs';

// A coarse polygonization keeps the software-rendered page quick; it still splits into chunks.
const MUREX = 'v=1&preset=murex-cabritii&form.resolution=48';

/** Opens `query#fragment`, finishes growth at once (End), and returns the grown signals. */
async function finished(browser, base, query, fragment) {
  const { page, errors } = await open(browser, `${base}?${query}#${fragment}`);
  try {
    await waitForState(page, ['growing', 'grown']);
    await page.locator('#shell').click();
    await page.keyboard.press('End');
    const grown = await waitForState(page, ['grown', 'error', 'stopped'], 180_000);
    assert.equal(grown.state, 'grown', `${query}: ${await page.textContent('#message')}`);
    const status = await page.textContent('#workers-status');
    assert.deepEqual(errors, []);
    return { ...grown, status };
  } finally {
    await page.close();
  }
}

for (const backend of ['WebGL2', 'WebGPU']) {
  test(`the Murex finished by 1, 2 or 4 workers or on the page's thread is the same on ${backend}`, async () => {
    const { browser, base, close } = await session(backend);
    try {
      const runs = {};
      for (const workers of [1, 2, 4, 0]) {
        runs[workers] = await finished(browser, base, `workers=${workers}`, MUREX);
        assert.equal(runs[workers].workers, String(workers));
      }
      assert.match(runs[0].status, /page's own thread/);
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

  test(`a value changed while the Murex grows cancels the old growth on ${backend}`, async () => {
    const { browser, base, close } = await session(backend);
    try {
      const { page, errors } = await open(browser, `${base}?workers=2#${MUREX}&growth.speed=2`);
      await waitForState(page, ['growing']);
      await page.waitForFunction(() => Number(document.body.dataset.rows) >= 40, null, { timeout: 120_000 });
      const number = page.locator('[data-key="form.resolution"] input.number');
      await number.fill('40');
      await number.press('Enter');
      await page.waitForFunction(() => location.hash.includes('form.resolution=40'));
      await page.locator('#shell').click();
      await page.keyboard.press('End');
      const edited = await waitForState(page, ['grown', 'error'], 180_000);
      assert.equal(edited.state, 'grown');
      const link = await page.evaluate(() => location.hash.slice(1));
      assert.deepEqual(errors, []);
      await page.close();
      const fresh = await finished(browser, base, 'workers=2', link);
      assert.equal(edited.meshHash, fresh.meshHash, 'the edited shell is the new link\'s');
      assert.equal(edited.patternHash, fresh.patternHash);
    } finally {
      await close();
    }
  });

  test(`workers that throw are replaced and their work redone on ${backend}`, async () => {
    const { browser, base, close } = await session(backend);
    try {
      const reference = await finished(browser, base, 'workers=1', MUREX);
      const crashed = await finished(browser, base, 'workers=1&crash-workers=2', MUREX);
      assert.equal(crashed.workerDeaths, '2');
      assert.match(crashed.status, /second time; it was replaced and its work done again/);
      assert.equal(crashed.meshHash, reference.meshHash);
      assert.equal(crashed.patternHash, reference.patternHash);
    } finally {
      await close();
    }
  });
}
