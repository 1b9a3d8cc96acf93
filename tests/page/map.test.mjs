// The parameter map: over two parameters of the pattern model, a grid of patterns; over a
// parameter of the form, a morphospace of whole shells drawn by the pool and the pictures'
// viewer. Each tile is a link that opens its shell, the current shell is marked, the arrow keys
// walk the grid, and tiles whose values cannot grow are hatched with the reason.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { browsers, hook, shellTiles, waitForState } from './browser.mjs';

const ROOT = new URL('../../', import.meta.url).pathname;
const SHOTS = `${ROOT}tests/page/screenshots/`;
mkdirSync(SHOTS, { recursive: true });
/** A browser per backend: the map of shells is drawn by either. */
const { openOn } = browsers(['WebGL2', 'WebGPU']);

test('the parameter map fills a grid of patterns, and a chosen tile opens that shell with its two values', async () => {
  const { page, errors } = await openOn('WebGL2', 'v=1&preset=oliva-porphyria');
  try {
    await waitForState(page, ['growing', 'grown']);
    await page.click('#map-open');
    const started = Date.now();
    await page.waitForFunction(() => document.body.dataset.map === 'whole', null, { timeout: 60_000 });
    const seconds = (Date.now() - started) / 1000;
    const tiles = await page.evaluate(() => [...document.querySelectorAll('#map-grid .tile')].map((a) => {
      const c = a.querySelector('canvas');
      return { href: a.getAttribute('href'), title: a.title, failed: a.classList.contains('failed'), width: c.width, picture: c.toDataURL() };
    }));
    await page.screenshot({ path: `${SHOTS}parameter-map.png` });
    assert.equal(tiles.length, 64);
    const painted = tiles.filter((t) => !t.failed && t.width === 100);
    assert.ok(painted.length >= 56, `only ${painted.length} of 64 tiles have a pattern`);
    assert.ok(new Set(painted.map((t) => t.picture)).size >= painted.length - 4, 'the patterns differ from tile to tile');
    console.log(`# the map of oliva-porphyria filled in ${seconds.toFixed(1)} s`);
    const [x, y] = await page.evaluate(() => [document.getElementById('map-x').value, document.getElementById('map-y').value]);
    const chosen = tiles[5 * 8 + 2];
    await page.click(`#map-grid .tile:nth-child(${5 * 8 + 3})`);
    // The address changes at the click, before the page routes it (and the shell shown before
    // may still say `growing`): the map's signal clearing is what says the page took it in.
    await page.waitForFunction((h) => location.hash === h && document.body.dataset.map === '', chosen.href);
    await page.waitForFunction(() => document.body.dataset.state === 'growing');
    assert.ok(await page.isHidden('#map'));
    for (const key of [x, y]) {
      const shown = await page.inputValue(`[id="field-${key}"]`);
      assert.ok(chosen.href.includes(`${key}=${shown}`), `${chosen.href} has ${key}=${shown}`);
    }
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

for (const backend of ['WebGL2', 'WebGPU']) test(`a map over the form's parameters is a morphospace of whole shells, each tile its shell's link (${backend})`, async () => {
  const { page, errors } = await openOn(backend, 'v=1&preset=turbinate', { width: 1100, height: 1000 });
  try {
    await waitForState(page, ['growing', 'grown']);
    await page.click('#map-open');
    const started = Date.now();
    await page.waitForFunction(() => document.body.dataset.map === 'whole', null, { timeout: 180_000 });
    console.log(`# the morphospace of turbinate (64 shells) filled in ${((Date.now() - started) / 1000).toFixed(1)} s on ${backend}`);
    assert.equal(await page.evaluate(() => document.body.dataset.backend), backend);
    const [x, y, groups] = await page.evaluate(() => [
      document.getElementById('map-x').value, document.getElementById('map-y').value,
      [...document.querySelectorAll('#map-x optgroup')].map((g) => g.label),
    ]);
    assert.deepEqual([x, y], ['raup.w', 'raup.t'], "Raup's expansion across, translation down");
    // The gallery's swept shells are marked where their own W and T fall, the turbinate shell
    // within the tile nearest it.
    const marks = await page.$$eval('#map-grid .marker', (ms) => ms.map((m) => ({ name: m.dataset.name, current: m.closest('.tile').classList.contains('current') })));
    assert.ok(marks.length >= 3, `${marks.length} gallery shells marked`);
    assert.ok(marks.some((m) => m.name === 'Turbinate shell' && m.current), JSON.stringify(marks));
    assert.ok(groups.includes('Shape') && groups.includes("Raup's coiling parameters"), `parameters by section: ${groups}`);
    const tiles = await shellTiles(page);
    const clip = await page.evaluate(() => {
      const [first, last] = [...document.querySelectorAll('#map-grid .tile')].filter((_, i, all) => i === 0 || i === all.length - 1).map((t) => t.getBoundingClientRect());
      return { x: first.left - 4, y: first.top - 4, width: last.right - first.left + 8, height: last.bottom - first.top + 8 };
    });
    await page.screenshot({ path: `${SHOTS}shape-map-${backend}.png`, clip });
    assert.equal(tiles.length, 64);
    assert.ok(tiles.every((t) => t.drawn && t.width === 128), 'every tile is a drawn shell');
    assert.ok(new Set(tiles.map((t) => t.digest)).size >= 60, 'the shells differ from tile to tile');
    // Down a column T grows: the shell is drawn out along its axis, from a low cone to a tower
    // (barely, where W is near 1: a whorl then moves the shell along the axis by W − 1 of it).
    const aspect = (t) => t.box[1] / t.box[0];
    for (const column of [4, 7]) {
      const [top, bottom] = [tiles[column], tiles[7 * 8 + column]];
      assert.ok(aspect(bottom) > 2 * aspect(top), `column ${column}: ${top.box} above, ${bottom.box} below`);
    }
    // Where each whorl clears the last (open coiling), the tile says so: fast expansion raised
    // far along the axis, not a slow one.
    const apart = tiles.filter((t) => t.classes.includes('apart'));
    assert.ok(apart.length >= 1 && apart.length < 64, `${apart.length} tiles with their whorls apart`);
    assert.ok(apart.every((t) => /open coiling/.test(t.title)));
    assert.ok(tiles[63].classes.includes('apart') && !tiles[0].classes.includes('apart'));
    const current = tiles.filter((t) => t.classes.includes('current'));
    assert.equal(current.length, 1, 'the shell mapped is marked');
    assert.match(current[0].title, /nearest this shell/);
    // The gallery's swept shells stand where their W and T fall, the shell mapped among them.
    assert.match(current[0].title, /here: [^)]*Turbinate shell/);
    const landmarks = await page.$$eval('#map-grid .tile .landmark', (spans) => spans.map((s) => s.textContent));
    assert.ok(landmarks.length >= 2 && landmarks.some((l) => l.includes('Turbinate shell')), `${landmarks}`);
    // The arrows walk from the marked tile; Enter opens the tile reached.
    const at = tiles.indexOf(current[0]);
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('ArrowDown');
    const reached = tiles[at + 1 + 8] ?? tiles[at];
    assert.equal(await page.evaluate(() => document.activeElement.getAttribute('href')), reached.href);
    await page.keyboard.press('Enter');
    await page.waitForFunction((h) => location.hash === h && document.body.dataset.map === '', reached.href);
    assert.ok(await page.isHidden('#map'));
    await waitForState(page, ['growing', 'grown']);
    // W and T are written into the spiral and the curve: one rate, and z₀ with r₀.
    for (const key of ['form.spiral.lambda_r', 'form.spiral.lambda_z', 'form.curve.lambda_c', 'form.spiral.z0']) {
      const shown = await page.inputValue(`[id="field-${key}"]`);
      assert.ok(reached.href.includes(`${key}=${shown}`), `${reached.href} has ${key}=${shown}`);
    }
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('on a phone the map has 5 × 5 tiles, every one a drawn shell', async () => {
  const { page, errors } = await openOn('WebGL2', 'v=1&preset=turbinate', { width: 390, height: 844 });
  try {
    await waitForState(page, ['growing', 'grown']);
    await page.click('#panel-toggle');
    await page.click('#map-open');
    await page.waitForFunction(() => document.body.dataset.map === 'whole', null, { timeout: 180_000 });
    const tiles = await shellTiles(page);
    assert.equal(tiles.length, 25);
    assert.ok(tiles.every((t) => t.drawn));
    const columns = await page.evaluate(() => new Set([...document.querySelectorAll('#map-grid .tile')].map((t) => t.getBoundingClientRect().left)).size);
    assert.equal(columns, 5);
    const right = await page.evaluate(() => Math.max(...[...document.querySelectorAll('#map, #map *')].map((e) => e.getBoundingClientRect().right)));
    assert.ok(right <= 390, `the map fits the screen's width: its right edge at ${right}`);
    await page.screenshot({ path: `${SHOTS}shape-map-phone.png` });
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('a machine that draws shells slowly gets fewer of them: 5 × 5 at a second a shell', async () => {
  const { page, errors } = await openOn('WebGL2', 'v=1&preset=turbinate');
  try {
    await waitForState(page, ['growing', 'grown']);
    await hook(page, 'debug_pace_of_shells', 1.0);
    await page.click('#map-open');
    await page.waitForFunction(() => document.body.dataset.map === 'whole', null, { timeout: 180_000 });
    const tiles = await shellTiles(page);
    assert.equal(tiles.length, 25);
    assert.ok(tiles.every((t) => t.drawn));
    assert.match(await page.textContent('#map-status'), /5 × 5 tiles: this machine drew the last map's shells at 1\.0 s each/);
    // Its own pace, measured as the map filled, is this machine's: 64 shells again.
    await page.click('#map-draw');
    await page.waitForFunction(() => document.body.dataset.map === 'whole', null, { timeout: 180_000 });
    assert.equal((await shellTiles(page)).length, 64);
    assert.doesNotMatch(await page.textContent('#map-status'), /tiles: this machine/);
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('tiles whose values cannot grow are hatched with the reason, and the others are drawn', async () => {
  const { page, errors } = await openOn('WebGL2', 'v=1&preset=turbinate');
  try {
    await waitForState(page, ['growing', 'grown']);
    await page.click('#map-open');
    await page.waitForFunction(() => document.body.dataset.map !== '');
    await page.selectOption('#map-x', 'form.spiral.lambda_r');
    await page.selectOption('#map-y', 'form.spiral.whorls');
    await page.fill('#map-x-from', '1.003');
    await page.fill('#map-x-to', '1.05');
    await page.fill('#map-y-from', '2');
    await page.fill('#map-y-to', '30');
    await page.click('#map-draw');
    await page.waitForFunction(() => document.body.dataset.map === 'whole', null, { timeout: 180_000 });
    const tiles = await shellTiles(page);
    const failed = tiles.filter((t) => t.classes.includes('failed'));
    assert.ok(failed.length >= 8 && failed.length <= 56, `${failed.length} tiles cannot grow`);
    for (const t of failed) {
      assert.ok(!t.drawn, 'a hatched tile has no picture');
      assert.match(t.title, /form\.spiral\.whorls: .* whorls at λᵣ/);
    }
    assert.ok(tiles.filter((t) => !t.classes.includes('failed')).every((t) => t.drawn));
    // A range beyond the field's is clamped to it, and says so; one wholly beyond is refused.
    await page.fill('#map-x-to', '9');
    await page.click('#map-draw');
    assert.match(await page.textContent('#map-status'), /runs from 0\.8 to 3: 1\.003 to 9 was clamped to 1\.003 to 3/);
    assert.notEqual(await page.evaluate(() => document.body.dataset.map), 'refused');
    await page.fill('#map-x-from', '5');
    await page.click('#map-draw');
    assert.match(await page.textContent('#map-status'), /runs from 0\.8 to 3, and 5 to 9 lies beyond it/);
    assert.equal(await page.evaluate(() => document.body.dataset.map), 'refused');
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});
