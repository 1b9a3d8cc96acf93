// The rendering Fowler et al. (1992, §5) asked for: each effect of the material — polished
// reflections, highlights along the growth lines, light through the wall, darkness inside the
// opening, the shadow on the ground — changes the picture of a shell against a plain
// rendering, on WebGL2 and on WebGPU. Screenshots are kept in screenshots/rendering/.
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

async function shot(browser, base, fragment, file) {
  const { page, errors } = await open(browser, `${base}#${fragment}`, { width: 560, height: 560 });
  try {
    assert.equal((await finishGrowth(page)).state, 'grown', fragment);
    const measure = await measureCanvas(page, file);
    assert.ok(measure.share > 0.03 && measure.shades > 30, `${fragment}: a blank picture`);
    assert.deepEqual(errors, []);
    return readFileSync(file);
  } finally {
    await page.close();
  }
}

for (const backend of ['WebGL2', 'WebGPU']) {
  test(`every effect of the material changes the picture on ${backend}`, async () => {
    const { browser, base, close } = await session(backend);
    try {
      const effects = backend === 'WebGL2' ? EFFECTS : EFFECTS.filter(([name]) => ['gloss', 'shadow'].includes(name));
      for (const [name, preset, change, least] of effects) {
        const plain = await shot(browser, base, `v=1&preset=${preset}&${PLAIN}`, `${SHOTS}${backend}-${name}-plain.png`);
        const shown = await shot(browser, base, `v=1&preset=${preset}&${PLAIN}&${change}`, `${SHOTS}${backend}-${name}.png`);
        const share = differing(plain, shown);
        assert.ok(share > least, `${name} changed only ${share} of the picture of ${preset}`);
      }
    } finally {
      await close();
    }
  });
}
