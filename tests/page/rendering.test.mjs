// The rendering Fowler et al. (1992, §5) asked for: each effect of the material — polished
// reflections, highlights along the growth lines, light through the wall, darkness inside the
// opening, the shadow on the ground — changes the picture of a shell against a plain
// rendering, on WebGL2 and on WebGPU: a link that changes the material alone draws the grown
// shell again without growing it again. Screenshots are kept in screenshots/rendering/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { differing, finishGrowth, open, session, measureCanvas } from './browser.mjs';

const SHOTS = new URL('./screenshots/rendering/', import.meta.url).pathname;
mkdirSync(SHOTS, { recursive: true });
const PLAIN = 'material.gloss=0&material.anisotropy=0&material.translucency=0&material.occlusion=0&material.shadow=0';
// Each effect alone, on a shell that shows it, and the least share of pixels it must change.
const EFFECTS = [
  ['gloss', 'oliva-porphyria', 'material.gloss=1', 0.01],
  ['anisotropy', 'rapa-rapa', 'material.anisotropy=1', 0.01],
  ['translucency', 'turbinate', 'material.translucency=1', 0.01],
  ['occlusion', 'epitonium-scalare', 'material.occlusion=1', 0.005],
  ['shadow', 'conus-marmoreus', 'material.shadow=1', 0.02],
];

/** The grown shell of `fragment` in a fresh page, its picture kept in `file`. */
async function grown(browser, base, fragment, file) {
  const { page, errors } = await open(browser, `${base}#${fragment}`, { width: 560, height: 560 });
  assert.equal((await finishGrowth(page)).state, 'grown', fragment);
  const measure = await measureCanvas(page, file);
  assert.ok(measure.share > 0.03 && measure.shades > 30, `${fragment}: a blank picture`);
  return { page, errors, picture: readFileSync(file) };
}

/**
 * Opens `fragment`, which differs from the page's shell in its material alone, and waits (20 s
 * at most) until the picture kept in `file` differs from `before` in more than `least` of its
 * pixels. The shell is drawn again, not grown again: the page never leaves `grown` and keeps its
 * mesh. Returns the share that differs.
 */
async function restyled(page, fragment, before, least, file) {
  const mesh = await page.evaluate(() => document.body.dataset.meshHash);
  await page.evaluate((f) => {
    window.statesSeen = [];
    new MutationObserver(() => window.statesSeen.push(document.body.dataset.state))
      .observe(document.body, { attributes: true, attributeFilter: ['data-state'] });
    location.hash = f;
  }, fragment);
  let share = 0;
  for (const end = Date.now() + 20_000; share <= least && Date.now() < end;) {
    share = differing(before, await page.locator('#shell').screenshot({ path: file }));
  }
  const after = await page.evaluate(() => ({ ...document.body.dataset, seen: window.statesSeen }));
  assert.ok(after.seen.every((s) => s === 'grown'), `${fragment}: the shell grew again (${after.seen})`);
  assert.equal(after.state, 'grown');
  assert.equal(after.meshHash, mesh, `${fragment}: another mesh`);
  return share;
}

for (const backend of ['WebGL2', 'WebGPU']) {
  test(`every effect of the material changes the picture of the grown shell on ${backend}`, async () => {
    const { browser, base, close } = await session(backend);
    try {
      const effects = backend === 'WebGL2' ? EFFECTS : EFFECTS.filter(([name]) => ['gloss', 'shadow'].includes(name));
      for (const [name, preset, change, least] of effects) {
        const plain = `v=1&preset=${preset}&${PLAIN}`;
        const { page, errors, picture } = await grown(browser, base, plain, `${SHOTS}${backend}-${name}-plain.png`);
        try {
          const share = await restyled(page, `${plain}&${change}`, picture, least, `${SHOTS}${backend}-${name}.png`);
          assert.ok(share > least, `${name} changed only ${share} of the picture of ${preset}`);
          assert.deepEqual(errors, []);
        } finally {
          await page.close();
        }
      }
    } finally {
      await close();
    }
  });
}
