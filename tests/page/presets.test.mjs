// Every preset in species/ grows to a visible, lit shell in the page (WebGL2, the path every
// machine has), with no console errors and no message. Screenshots are kept for looking.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readdirSync } from 'node:fs';
import { open, session, waitForState, measureCanvas } from './browser.mjs';

const SHOTS = new URL('./screenshots/presets/', import.meta.url).pathname;
mkdirSync(SHOTS, { recursive: true });
const IDS = readdirSync(new URL('../../species/', import.meta.url))
  .filter((f) => f.endsWith('.json'))
  .map((f) => f.slice(0, -5));
let browser;
let base;
let close;

before(async () => {
  ({ browser, base, close } = await session());
});
after(() => close());

for (const id of IDS) {
  test(`preset ${id} grows into a shell`, async () => {
    const { page, errors } = await open(browser, `${base}#v=1&preset=${id}&growth.speed=200`, { width: 480, height: 480 });
    try {
      const state = await waitForState(page, ['grown', 'error']);
      assert.equal(state.state, 'grown');
      const shot = await measureCanvas(page, `${SHOTS}${id}.png`);
      assert.ok(shot.share > 0.03, `${id} covers only ${shot.share} of the canvas`);
      assert.ok(shot.shades > 30, `${id} has only ${shot.shades} shades`);
      assert.equal(await page.isVisible('#message'), false, await page.textContent('#message'));
      assert.deepEqual(errors, []);
    } finally {
      await page.close();
    }
  });
}
