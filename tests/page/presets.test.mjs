// Every preset in species/ grows to a visible, lit shell in the page (WebGL2, the path every
// machine has), with no console errors and no message. Screenshots are kept for looking.
import { test, before, after } from 'node:test';
import { mkdirSync, readdirSync } from 'node:fs';
import { growPreset, session } from './browser.mjs';

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
    await growPreset(browser, base, id, `${SHOTS}${id}.png`);
  });
}
