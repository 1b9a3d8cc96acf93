// The pattern the page grows is bit for bit the one the native core computes (the same hash
// from the wasm build, on a fixed and on a growing edge), the planar view shows it (a growing
// edge's as a fan), and it can be downloaded as a PNG.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { open, session, waitForState } from './browser.mjs';
import { nativePattern } from './native.mjs';

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

const LINKS = [
  'v=1&preset=oliva-porphyria-growing-edge',
  'v=1&preset=conus-marmoreus',
  'v=1&preset=amoria-undulata&pattern.model.d_a=0.006&seed=9',
  'v=1&preset=kawaguchi-painted',
  'v=1&preset=stripes-growing-edge',
];

for (const fragment of LINKS) {
  test(`wasm grows the same pattern as native: ${fragment}`, async () => {
    const { page, errors } = await open(browser, `${base}#${fragment}&growth.speed=200`);
    try {
      const state = await waitForState(page, ['grown', 'stopped', 'error']);
      assert.equal(state.state, 'grown');
      assert.equal(state.patternHash, nativePattern(fragment));
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

test('dragging a pattern slider redraws the whole pattern in the planar view while the shell waits', async () => {
  const { page, errors } = await open(browser, `${base}#v=1&preset=oliva-porphyria&growth.speed=1`);
  /** Pixels of the planar view's last 200 rows that are drawn, and their distinct colours. */
  const bottom = () => page.evaluate(() => {
    const c = document.getElementById('planar');
    const { data } = c.getContext('2d').getImageData(0, c.height - 200, c.width, 200);
    const seen = new Set();
    let drawn = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (data[i + 3] === 0) continue;
      drawn += 1;
      seen.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
    }
    return { drawn, colours: seen.size };
  });
  /** Moves the slider of `key` to a fraction of its range, as a drag passes it. */
  const drag = (key, fraction, event) => page.evaluate(([key, fraction, event]) => {
    const range = document.querySelector(`.field[data-key="${key}"] input[type=range]`);
    range.value = String(Math.round(Number(range.max) * fraction));
    range.dispatchEvent(new Event(event, { bubbles: true }));
    return document.getElementById(`field-${key}`).value;
  }, [key, fraction, event]);
  try {
    await waitForState(page, ['growing']);
    assert.equal((await bottom()).drawn, 0, 'the end of the pattern is not grown yet');
    // The planar view's last rows once every cell of them is drawn and, if `unlike` is given,
    // they are not those pixels: a preview said whole and drawn to the end.
    const whole = (unlike) => page.waitForFunction((unlike) => {
      const c = document.getElementById('planar');
      const { data } = c.getContext('2d').getImageData(0, c.height - 200, c.width, 200);
      if (document.body.dataset.preview !== 'whole' || !data.every((v, i) => i % 4 !== 3 || v !== 0)) return null;
      let hash = 0;
      for (let i = 0; i < data.length; i += 1) hash = (hash * 31 + data[i]) >>> 0;
      return hash !== unlike ? hash : null;
    }, unlike, { timeout: 60_000, polling: 100 }).then((h) => h.jsonValue());
    await drag('pattern.model.d_a', 0.04, 'input');
    const first = await whole(null);
    // The second drag's preview starts over; the view is whole again only with its own rows.
    await drag('pattern.model.d_a', 0.05, 'input');
    await whole(first);
    const filled = await bottom();
    const state = await page.evaluate(() => ({ ...document.body.dataset }));
    assert.equal(state.state, 'growing', 'the whole pattern came before the shell grew');
    assert.ok(Number(state.rows) < 1000, `the shell waited at row ${state.rows}`);
    assert.equal(filled.drawn, 400 * 200, 'every cell of the last rows is drawn');
    assert.ok(filled.colours > 5, `the last rows have only ${filled.colours} colours`);
    const value = await drag('pattern.model.d_a', 0.05, 'change');
    await page.waitForFunction(() => document.body.dataset.preview === '' && Number(document.body.dataset.rows) < 50);
    await page.waitForFunction((v) => location.hash.includes(`pattern.model.d_a=${v}`), value);
    assert.equal((await bottom()).drawn, 0, 'let go, the shell grows its pattern again from the start');
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test("a growing edge's planar view widens as a fan, and downloads as one", async () => {
  const { page } = await open(browser, `${base}#v=1&preset=stripes-growing-edge&growth.speed=200`);
  try {
    await waitForState(page, ['grown']);
    // The drawn (opaque) cells of a row, near the apex and at the lip.
    const widths = await page.evaluate(() => {
      const c = document.getElementById('planar');
      const row = (y) => {
        const { data } = c.getContext('2d').getImageData(0, y, c.width, 1);
        let drawn = 0;
        for (let i = 3; i < data.length; i += 4) drawn += data[i] === 255 ? 1 : 0;
        return drawn;
      };
      return [row(0), row(Math.floor(c.height / 2)), row(c.height - 1), c.width];
    });
    const [apex, middle, lip, width] = widths;
    assert.equal(lip, width, `the last row is the whole edge: ${widths}`);
    assert.ok(apex * 10 < lip && apex < middle && middle < lip, `rows widen: ${widths}`);
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download-pattern')]);
    const file = `${SHOTS}stripes-growing-edge-pattern.png`;
    await download.saveAs(file);
    const png = readFileSync(file);
    assert.deepEqual([png.readUInt32BE(16), png.readUInt32BE(20)], [180, 2100]);
  } finally {
    await page.close();
  }
});
