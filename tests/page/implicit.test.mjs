// Implicit surfaces in the page (Galbraith, Prusinkiewicz & Wyvill): a BlobTree whorl grows on
// screen, section by section, on WebGL2 (the renderer takes a form's growth alike on either
// backend: a lit shell grows on both in growth.test.mjs, a chamber shell on WebGPU in
// kawaguchi.test.mjs, and the gallery's pictures draw every preset,
// on WebGL2 there and on WebGPU in survive.test.mjs), wasm meshes the
// same triangles, bit for bit, as the command line, and a link with bad implicit numbers gets a
// message, and the preset's values or the cap.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { finishGrowth, open, session, waitForState, measureCanvas } from './browser.mjs';
import { nativeMesh } from './native.mjs';

const SHOTS = new URL('./screenshots/implicit/', import.meta.url).pathname;
mkdirSync(SHOTS, { recursive: true });

for (const backend of ['WebGL2']) {
  test(`an implicit whorl grows section by section on ${backend}`, async () => {
    const { browser, base, close } = await session(backend);
    try {
      const { page, errors } = await open(browser, `${base}#v=1&preset=implicit-whorl&growth.speed=3&form.resolution=64`);
      const ready = await waitForState(page, ['growing', 'grown', 'error']);
      assert.equal(ready.state, 'growing', `the page reported ${ready.state}`);
      assert.equal(ready.backend, backend);
      await page.waitForFunction(() => Number(document.body.dataset.rows) >= 250, null, { timeout: 120_000 });
      await page.keyboard.press('Space');
      await page.waitForFunction(() => document.body.dataset.playing === 'false');
      await page.waitForTimeout(1000);
      const early = await measureCanvas(page, `${SHOTS}whorl-${backend}-half.png`);
      // The rest at once (the Finish key): section by section it took a minute in software.
      await page.keyboard.press('e');
      await waitForState(page, ['grown']);
      await page.waitForTimeout(1000);
      const late = await measureCanvas(page, `${SHOTS}whorl-${backend}-grown.png`);
      assert.ok(early.share > 0.02, `part-way the whorl covers only ${early.share}`);
      assert.ok(late.shades > 30, `only ${late.shades} shades: not a lit surface`);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  });
}

test('an implicit shell grows in wasm into the very mesh the command line writes', async () => {
  const { browser, base, close } = await session();
  try {
    for (const link of [
      'v=1&preset=implicit-whorl',
      'v=1&preset=implicit-canal-whorl&form.resolution=64',
      // Bumps and canal spines drawn from the seed, spines placed by the pattern.
      'v=1&preset=murex-cabritii&form.resolution=48',
      'v=1&preset=murex-rd-spines&form.resolution=48',
    ]) {
      const { page, errors } = await open(browser, `${base}#${link}`);
      const grown = await finishGrowth(page);
      const said = `${await page.textContent('#message')} ${await page.textContent('#crash-text')}`;
      assert.equal(grown.state, 'grown', `${link}: ${said}`);
      const out = nativeMesh(link).said;
      assert.match(out, new RegExp(`: ${grown.mesh}, hash ${grown.meshHash}, \\d+ bytes$`, 'm'),
        `${link}: wasm ${grown.mesh} ${grown.meshHash}, native ${out}`);
      assert.deepEqual(errors, []);
      await page.close();
    }
  } finally {
    await close();
  }
});

test('bad implicit numbers in a link get a message naming the key, and the shell grows all the same', async () => {
  const { browser, base, close } = await session();
  try {
    const canal = 'preset=implicit-canal-whorl&form.whorls=5';
    const murex = 'preset=murex-cabritii&form.resolution=40';
    for (const [link, key] of [
      [`${canal}&form.generator.pairs=0,3`, 'form.generator.pairs'],
      [`${canal}&form.generator.points=0,0,0,-1`, 'form.generator.points'],
      [`${canal}&form.resolution=5000`, 'form.resolution'],
      [`${murex}&form.varices.bend=500`, 'form.varices.bend'],
      [`${murex}&form.canal_spines.spines=7,1`, 'form.canal_spines.spines'],
      // Once grew to nothing without a word.
      [`${murex}&form.generator.points=0,0,0,1e300`, 'form.generator.points'],
      [`${murex}&form.spiral.r0=1e-300`, 'form.spiral.r0'],
      ['preset=murex-rd-spines&form.resolution=40&pattern.model.kind=none', 'form.varices.placement'],
    ]) {
      const { page, errors } = await open(browser, `${base}#v=1&${link}&growth.speed=200`);
      // The resolution is capped at 384, which grows slowly in software rendering: growing
      // (never an error, never a frozen tab) is what counts here.
      const state = await waitForState(page, ['growing', 'grown', 'error']);
      assert.notEqual(state.state, 'error', link);
      await page.waitForFunction(() => Number(document.body.dataset.rows) > 5);
      assert.ok(await page.isVisible('#message'), `${link}: no message`);
      assert.match(await page.textContent('#message'), new RegExp(key.replaceAll('.', '\\.')));
      assert.deepEqual(errors, []);
      await page.close();
    }
  } finally {
    await close();
  }
});

test('the implicit panel has one section per concept and its own ranges (R₀ > 0)', async () => {
  const { browser, base, close } = await session();
  try {
    const { page, errors } = await open(browser, `${base}#v=1&preset=implicit-whorl&form.resolution=48`);
    await waitForState(page, ['growing', 'grown']);
    const sections = await page.$$eval('details.params summary', (s) => s.map((x) => x.textContent));
    assert.equal(new Set(sections).size, sections.length, `a section comes twice: ${sections}`);
    for (const s of ['Helico-spiral', 'Whorls and sections', 'Generating surface', 'Opening', 'Polygonization']) {
      assert.ok(sections.includes(s), `${s} in ${sections}`);
    }
    const r0 = page.locator('[data-key="form.spiral.r0"] input[type=number]');
    assert.ok(Number(await r0.getAttribute('min')) > 0, 'R₀ starts above 0');
    assert.equal(await page.locator('[data-key="form.curve.points"]').count(), 0, 'no sweep fields');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
