// Breeding: the shell among eight offspring drawn by the pool and the pictures' viewer; choosing
// one makes it the parent of the next eight, Back returns to the generation before, the rate
// breeds the generation again, the lineage is one link that replays it, and keeping the parent
// opens its own shell. Every form breeds; a lineage that cannot be followed says why.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, writeFileSync } from 'node:fs';
import { browsers, composeSheet, hook, shellTiles, waitForState } from './browser.mjs';

const ROOT = new URL('../../', import.meta.url).pathname;
const SHOTS = `${ROOT}tests/page/screenshots/`;
mkdirSync(SHOTS, { recursive: true });
const { sessions, openOn: openAt } = browsers(['WebGL2']);
const openOn = (backend, fragment) => openAt(backend, fragment, { width: 1000, height: 900 });

/**
 * Waits for every tile of generation `n` (any, without `n`), the first offspring's link ending
 * with `ending` if given, and reads the tiles.
 */
async function generation(page, n, ending = '') {
  await page.waitForFunction(([n, ending]) => document.body.dataset.breed === 'whole'
    && (n === null || document.querySelector('#breed-grid .parent')?.title.includes(`generation ${n}:`))
    && (ending === '' || document.querySelector('#breed-grid .tile')?.getAttribute('href')?.endsWith(ending)),
  [n ?? null, ending], { timeout: 180_000 });
  return shellTiles(page, '#breed-grid');
}

/** The grid as the README shows it: written to `file`, and returned as PNG bytes. */
async function shot(page, file) {
  // No pointer or focus on a tile (the one clicked last), and the pictures painted: decoded is
  // not yet painted, two frames later it is.
  await page.mouse.move(0, 0);
  await page.evaluate(() => {
    document.activeElement?.blur();
    return new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
  });
  const clip = await page.evaluate(() => {
    const tiles = [...document.querySelectorAll('#breed-grid .tile')].map((t) => t.getBoundingClientRect());
    const [first, last] = [tiles[0], tiles[tiles.length - 1]];
    return { x: first.left - 4, y: first.top - 4, width: last.right - first.left + 8, height: last.bottom - first.top + 8 };
  });
  return [...await page.screenshot({ path: `${SHOTS}${file}`, clip })];
}

// One backend: the tiles are drawn as the map's are, which both backends draw (map.test.mjs);
// what this adds is breeding's own clicks, links and lineage.
for (const backend of ['WebGL2']) test(`breeding: the chosen offspring becomes the parent of eight more, Back returns, and the lineage is one link (${backend})`, async () => {
  const { page, errors } = await openOn(backend, 'v=1&preset=turbinate');
  try {
    await waitForState(page, ['growing', 'grown']);
    await page.click('#breed-open');
    const first = await generation(page, 1);
    assert.match(await page.evaluate(() => location.hash), /&breed=0\.4$/);
    assert.equal(first.length, 9);
    assert.ok(first.every((t) => t.drawn && t.width === 128), 'the parent and its offspring are drawn shells');
    assert.ok(first[4].classes.includes('parent') && /generation 1/.test(first[4].title));
    assert.equal(new Set(first.map((t) => t.digest)).size, 9, 'nine different shells');
    const offspring = first.filter((_, i) => i !== 4);
    assert.ok(offspring.every((t) => /^Offspring \d: .+ → /.test(t.title)), offspring.map((t) => t.title).join('\n'));
    const shots = [{ caption: 'Generation 1', png: await shot(page, `breed-1-${backend}.png`) }];

    // The third offspring is chosen: it stands in the middle, its picture the same.
    await page.click('#breed-grid .tile:nth-child(3)');
    const second = await generation(page, 2);
    assert.match(await page.evaluate(() => location.hash), /&breed=0\.4\/3,0\.4$/);
    assert.equal(second[4].digest, first[2].digest, 'offspring 3 is the parent now');
    assert.match(second[4].title, /generation 2/);
    assert.match(await page.textContent('#breed-status'), /Generation 2/);
    shots.push({ caption: 'Generation 2: the third chosen', png: await shot(page, `breed-2-${backend}.png`) });
    await page.click('#breed-grid .tile:nth-child(8)');
    const third = await generation(page, 3);
    assert.equal(third[4].digest, second[7].digest);
    assert.ok(new Set(third.map((t) => t.digest)).size >= 8, 'the third generation is drawn, each shell its own');
    shots.push({ caption: 'Generation 3: then the seventh', png: await shot(page, `breed-3-${backend}.png`) });
    writeFileSync(`${SHOTS}breed-generations-${backend}.png`, await composeSheet(sessions[backend].browser, shots, 3));
    const lineage = await page.evaluate(() => location.hash);
    assert.match(lineage, /&breed=0\.4\/3,0\.4\/7,0\.4$/);

    // Back: the generation before, drawn as it was.
    await page.click('#breed-back');
    const again = await generation(page, 2);
    assert.deepEqual(again.map((t) => t.href), second.map((t) => t.href));
    assert.deepEqual(again.map((t) => t.digest), second.map((t) => t.digest));

    // The arrow keys walk from the parent, Enter chooses; the browser's Back returns.
    await page.keyboard.press('ArrowLeft');
    assert.equal(await page.evaluate(() => document.activeElement.getAttribute('href')), second[3].href);
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => /&breed=0\.4\/3,0\.4\/4,0\.4$/.test(location.hash));
    assert.equal((await generation(page, 3))[4].digest, second[3].digest);
    await page.goBack();
    await page.waitForFunction(() => /&breed=0\.4\/3,0\.4$/.test(location.hash));
    assert.deepEqual((await generation(page, 2)).map((t) => t.href), second.map((t) => t.href));

    // The lineage's link, opened afresh, replays the same generation.
    const { page: other, errors: otherErrors } = await openOn(backend, lineage.slice(1));
    try {
      const replayed = await generation(other, 3);
      assert.deepEqual(replayed.map((t) => t.href), third.map((t) => t.href));
      assert.deepEqual(otherErrors, []);
    } finally {
      await other.close();
    }

    // A higher rate breeds the generation again, further from the parent.
    await page.$eval('#breed-rate', (input) => {
      input.value = '1';
      input.dispatchEvent(new Event('change', { bubbles: true }));
    });
    const wilder = await generation(page, 2, ',1/1,1');
    assert.match(await page.evaluate(() => location.hash), /&breed=0\.4\/3,1$/);
    assert.equal(wilder[4].href, second[4].href, 'the same parent');
    assert.ok(wilder.filter((t, i) => i !== 4 && t.href !== second[i].href).length >= 7);

    // Keeping the parent opens its own shell, its values in the panel.
    const parent = wilder[4].href;
    await page.keyboard.press('Escape');
    await page.waitForFunction((h) => location.hash === h && document.body.dataset.breed === '', parent);
    assert.ok(await page.isHidden('#breed'));
    await waitForState(page, ['growing', 'grown']);
    const changed = [...parent.matchAll(/&([a-z_.0-9]+)=([^&]+)/g)].filter(([, k]) => k.startsWith('form.'));
    assert.ok(changed.length >= 1, parent);
    for (const [, key, value] of changed) {
      if (await page.$(`[id="field-${key}"]`)) {
        assert.equal(await page.inputValue(`[id="field-${key}"]`), decodeURIComponent(value), key);
      }
    }
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('every form breeds: chambers, branching and the Murex stand among drawn offspring', async () => {
  for (const preset of ['kawaguchi-ammonite', 'kawaguchi-coral', 'murex-cabritii']) {
    const { page, errors } = await openOn('WebGL2', `v=1&preset=${preset}&breed=0.4`);
    try {
      const tiles = await generation(page);
      assert.equal(tiles.length, 9, preset);
      const drawn = tiles.filter((t) => t.drawn);
      assert.ok(drawn.length >= 6, `${preset}: ${drawn.length} of 9 drawn`);
      for (const t of tiles.filter((t) => !t.drawn)) {
        assert.ok(t.classes.includes('failed') && /: ./.test(t.title), `${preset}: an offspring not drawn says why`);
      }
      assert.ok(new Set(drawn.map((t) => t.digest)).size >= drawn.length - 1, `${preset}: the offspring differ`);
      await shot(page, `breed-${preset}.png`);
      assert.deepEqual(errors, []);
    } finally {
      await page.close();
    }
  }
});

test('a lineage that cannot be followed is read as far as it goes, and says why', async () => {
  const { page, errors } = await openOn('WebGL2', 'v=1&preset=turbinate&breed=0.4/2,0.4/12,3');
  try {
    const tiles = await generation(page);
    assert.equal(tiles.length, 9);
    assert.match(await page.textContent('#breed-status'), /Generation 2/);
    const message = await page.textContent('#message');
    assert.match(message, /'12' is not an offspring/);
    assert.equal(await page.evaluate(() => document.getElementById('breed-back').disabled), false);
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('a machine that draws shells slowly breeds fewer offspring at once, and says so', async () => {
  const { page, errors } = await openOn('WebGL2', 'v=1&preset=turbinate');
  try {
    await waitForState(page, ['growing', 'grown']);
    await hook(page, 'debug_pace_of_shells', 5.0);
    await page.click('#breed-open');
    const tiles = await generation(page, 1);
    assert.equal(tiles.length, 9);
    // The parent and its first three offspring in 20 s at 5 s a shell; the others say why.
    const drawn = tiles.map((t) => t.drawn);
    assert.deepEqual(drawn, [true, true, true, false, true, false, false, false, false], JSON.stringify(tiles.map((t) => t.title)));
    const undrawn = await page.$$eval('#breed-grid .tile.failed', (as) => as.map((a) => [a.title, a.getAttribute('href')]));
    assert.equal(undrawn.length, 5);
    assert.ok(undrawn.every(([title, href]) => /not drawn: this machine drew the last generation's shells at 5\.0 s each/.test(title) && href === null), JSON.stringify(undrawn));
    assert.match(await page.textContent('#breed-status'), /3 of 8 offspring drawn: this machine drew the last generation's shells at 5\.0 s each/);
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});
