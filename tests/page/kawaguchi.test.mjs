// Kawaguchi's GROWTH in the page: a chamber shell grows chamber by chamber on WebGPU (an
// implicit whorl grows on WebGL2 in implicit.test.mjs, and the gallery's pictures draw
// every preset, on WebGL2 there and on WebGPU in survive.test.mjs), the panel shows the chamber's own fields
// and a slider reshapes it, the panel's form switch turns a swept shell into a chamber stack,
// and a branching form grows in wasm into the same mesh, segment for segment, as natively.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { open, session, waitForState, measureCanvas } from './browser.mjs';
import { nativeMesh } from './native.mjs';

const SHOTS = new URL('./screenshots/kawaguchi/', import.meta.url).pathname;
mkdirSync(SHOTS, { recursive: true });

for (const backend of ['WebGPU']) {
  test(`a chamber shell grows chamber by chamber on ${backend}`, async () => {
    const { browser, base, close } = await session(backend);
    try {
      const { page, errors } = await open(browser, `${base}#v=1&preset=kawaguchi-shell&growth.speed=0.5`);
      const ready = await waitForState(page, ['growing', 'grown', 'error']);
      assert.equal(ready.state, 'growing', `the page reported ${ready.state}`);
      assert.equal(ready.backend, backend);
      await page.waitForFunction(() => Number(document.body.dataset.rows) >= 45);
      await page.keyboard.press('Space');
      await page.waitForFunction(() => document.body.dataset.playing === 'false');
      await page.waitForTimeout(1000);
      const early = await measureCanvas(page, `${SHOTS}shell-${backend}-early.png`);
      await page.keyboard.press('Space');
      await waitForState(page, ['grown']);
      await page.waitForTimeout(1000);
      const late = await measureCanvas(page, `${SHOTS}shell-${backend}-grown.png`);
      assert.ok(early.share > 0.4 * late.share, `half-way the shell covers only ${early.share}, grown ${late.share}`);
      assert.ok(late.shades > 30, `only ${late.shades} shades: not a lit surface`);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  });
}

test("the panel shows the chamber's fields, and a slider reshapes the shell", async () => {
  const { browser, base, close } = await session();
  try {
    const { page, errors } = await open(browser, `${base}#v=1&preset=kawaguchi-horn&growth.speed=200`);
    await waitForState(page, ['grown']);
    const groups = await page.$$eval('details.params summary', (s) => s.map((x) => x.textContent));
    for (const g of ['Mouth polygon', 'Chamber to chamber']) assert.ok(groups.includes(g), `${g} in ${groups}`);
    assert.equal(await page.locator('[data-key="form.spiral.whorls"]').count(), 0, 'no sweep fields');
    const before = await measureCanvas(page, `${SHOTS}horn-before.png`);
    const slider = page.locator('[data-key="form.chamber.shift.y"] input.slider');
    await slider.fill('600');
    await page.waitForFunction(() => location.hash.includes('form.chamber.shift.y='));
    assert.match(await page.evaluate(() => location.hash), /form\.chamber\.shift\.y=2(&|$)/);
    await waitForState(page, ['grown']);
    const after = await measureCanvas(page, `${SHOTS}horn-after.png`);
    assert.notEqual(after.share, before.share, 'a position further off the vertical opens the horn further');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the form switch turns a swept shell into a stack of chambers', async () => {
  const { browser, base, close } = await session();
  try {
    const { page, errors } = await open(browser, `${base}#v=1&preset=turbinate&growth.speed=200`);
    await waitForState(page, ['grown']);
    await page.selectOption('[data-key="form.kind"] select', 'chambers');
    await page.waitForFunction(() => location.hash.includes('form.kind=chambers'));
    await waitForState(page, ['grown']);
    assert.equal(await page.locator('[data-key="form.mouth.apexes"]').count(), 1);
    const shot = await measureCanvas(page, `${SHOTS}turbinate-as-chambers.png`);
    assert.ok(shot.share > 0.03);
    assert.equal(await page.isVisible('#message'), false, await page.textContent('#message'));
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a branching form grows in wasm into the mesh the command line writes', async () => {
  const { browser, base, close } = await session();
  try {
    for (const link of ['v=1&preset=kawaguchi-coral', 'v=1&preset=kawaguchi-tendril&seed=5']) {
      const { page, errors } = await open(browser, `${base}#${link}&growth.speed=200`);
      const grown = await waitForState(page, ['grown']);
      const out = nativeMesh(link).said;
      // Counts only: std's trigonometry may round positions differently in wasm.
      assert.match(out, new RegExp(`: ${grown.mesh}, hash `), `${link}: wasm ${grown.mesh}, native ${out}`);
      assert.deepEqual(errors, []);
      await page.close();
    }
  } finally {
    await close();
  }
});
