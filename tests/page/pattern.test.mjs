// The pattern the page grows is bit for bit the one the native core computes (the same hash
// from the wasm build), the planar view shows it, and it can be downloaded as a PNG.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync } from 'node:fs';
import { open, session, waitForState } from './browser.mjs';

const ROOT = new URL('../../', import.meta.url).pathname;
const SHOTS = `${ROOT}tests/page/screenshots/`;
mkdirSync(SHOTS, { recursive: true });
let browser;
let base;
let close;

before(async () => {
  ({ browser, base, close } = await session());
});
after(() => close());

/** The hash the native command line reports for a link. */
function nativeHash(fragment) {
  const out = execFileSync(`${ROOT}target/release/seashells`, ['pattern', '--link', fragment, '--out', `${SHOTS}native.png`]);
  return /hash ([0-9a-f]{16})/.exec(out.toString())[1];
}

const LINKS = [
  'v=1&preset=oliva-porphyria',
  'v=1&preset=conus-marmoreus',
  'v=1&preset=amoria-undulata&pattern.model.d_a=0.006&seed=9',
  'v=1&preset=kawaguchi-painted',
];

for (const fragment of LINKS) {
  test(`wasm grows the same pattern as native: ${fragment}`, async () => {
    const { page, errors } = await open(browser, `${base}#${fragment}&growth.speed=200`);
    try {
      const state = await waitForState(page, ['grown', 'stopped', 'error']);
      assert.equal(state.state, 'grown');
      assert.equal(state.patternHash, nativeHash(fragment));
      assert.deepEqual(errors, []);
    } finally {
      await page.close();
    }
  });
}

test('the planar view shows the pattern and downloads as a PNG of cells × rows', async () => {
  const { page } = await open(browser, `${base}#v=1&preset=oliva-porphyria&growth.speed=200`);
  try {
    await waitForState(page, ['grown']);
    assert.ok(await page.isVisible('#planar'));
    const shades = await page.evaluate(() => {
      const c = document.getElementById('planar');
      const { data } = c.getContext('2d').getImageData(0, 0, c.width, c.height);
      const seen = new Set();
      for (let i = 0; i < data.length; i += 4 * 97) seen.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
      return seen.size;
    });
    assert.ok(shades > 10, `the planar view has only ${shades} colours`);
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download-pattern')]);
    assert.equal(download.suggestedFilename(), 'oliva-porphyria-pattern.png');
    const file = `${SHOTS}oliva-pattern-download.png`;
    await download.saveAs(file);
    const png = readFileSync(file);
    assert.equal(png.subarray(1, 4).toString(), 'PNG');
    assert.deepEqual([png.readUInt32BE(16), png.readUInt32BE(20)], [400, 2900]);
  } finally {
    await page.close();
  }
});
