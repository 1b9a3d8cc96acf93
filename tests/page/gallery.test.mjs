// The gallery, the viewer's controls and panel, and links: every preset has a card with a
// picture of its shell, grown in the page's workers from the preset's own spec (its mesh no
// finer than the picture shows, src/view/picture.rs) and drawn lit on WebGL2 (on WebGPU in
// survive.test.mjs; natively, every preset grows whole in tests/species.rs); a card opens a growing shell and Back returns; a slider changes the link and the
// link reproduces the pattern bit for bit; bad links get messages and a working page;
// the keyboard works; older links open; links copy; meshes download.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readdirSync, readFileSync } from 'node:fs';
import { open, session, waitForState, cardPictures, measurePng } from './browser.mjs';

const ROOT = new URL('../../', import.meta.url).pathname;
const SHOTS = `${ROOT}tests/page/screenshots/`;
mkdirSync(SHOTS, { recursive: true });
const IDS = readdirSync(`${ROOT}species`).filter((f) => f.endsWith('.json')).map((f) => f.slice(0, -5));
const PAPERS = JSON.parse(readFileSync(`${ROOT}species/papers/figures.json`, 'utf8'));
const STORIES = readdirSync(`${ROOT}species/stories`).filter((f) => f.endsWith('.json')).map((f) => f.slice(0, -5));
let browser;
let base;
let close;

before(async () => {
  ({ browser, base, close } = await session());
});
after(() => close());

const dataset = (page) => page.evaluate(() => ({ ...document.body.dataset }));

test('the gallery lists every preset in its group, each with a picture of its shell', async () => {
  const { page, errors } = await open(browser, base, { width: 1280, height: 900 });
  try {
    await waitForState(page, ['gallery']);
    const cards = await page.$$eval('a.card', (as) => as.map((a) => ({
      id: a.dataset.preset, name: a.querySelector('h3').textContent, href: a.getAttribute('href'),
    })));
    assert.deepEqual(cards.map((c) => c.id).sort(), [...IDS].sort());
    for (const c of cards) assert.equal(c.href, `#v=1&preset=${c.id}`);
    const names = cards.map((c) => c.name).join(' | ');
    for (const species of ['Stripes', 'Amoria undulata', 'Volutoconus bednalli', 'Oliva porphyria', 'Conus marmoreus']) {
      assert.match(names, new RegExp(species));
    }
    const groups = await page.$$eval('.group h2', (hs) => hs.map((h) => h.textContent));
    assert.deepEqual(groups, ['Stories', 'Shell shapes', 'Pigmentation patterns', 'Cellular automaton', "Kawaguchi's GROWTH", 'Implicit surfaces']);
    // The stories first, each a card linking to its first step.
    const stories = await page.$$eval('a.story-card', (as) => as.map((a) => [a.dataset.story, a.getAttribute('href')]));
    assert.deepEqual(stories.map(([id]) => id).sort(), [...STORIES].sort());
    for (const [id, href] of stories) assert.equal(href, `#story=${id}`);
    await page.waitForFunction(() => document.body.dataset.pictures === 'done', null, { timeout: 240_000 });
    // Each card shows a PNG read back from the pictures' canvas, by an object URL.
    const pictures = await cardPictures(page);
    assert.ok(pictures.every((p) => p.png !== null), 'every card has its picture');
    assert.equal(new Set(pictures.map((p) => p.png.join(','))).size, pictures.length, 'every picture is a different shell');
    // A lit surface has many shades; a small picture of a pale, plain shell (the Cardium's 26)
    // has fewer than a large view, a flat fill a handful.
    const unlit = pictures.map((p) => ({ preset: p.preset, ...measurePng(Buffer.from(p.png)) }))
      .filter((m) => !(m.share > 0.03 && m.shades > 15)).map((m) => `${m.preset}: ${m.share.toFixed(3)} covered, ${m.shades} shades`);
    assert.deepEqual(unlit, [], 'every picture is a visible, lit shell');
    // The papers' figures beside ours: every figure of species/papers/figures.json, each
    // reproduced one with its shells' pictures (the cards', drawn once), the others saying why.
    const figures = await page.$$eval('#figures-list li.figure', (items) => items.map((li) => ({
      shells: [...li.querySelectorAll('.ours-shell img')].map((img) => img.complete && img.naturalWidth > 0),
      why: li.querySelector('.why-not')?.textContent ?? null,
    })));
    const listed = PAPERS.flatMap((p) => p.figures);
    assert.equal(figures.length, listed.length, 'every figure of the four papers');
    for (const [i, f] of figures.entries()) {
      assert.ok((f.shells.length > 0) !== (f.why !== null), `figure ${i}: shells or why, not both`);
      assert.ok(f.shells.every(Boolean), `figure ${i}: its shells' pictures are drawn`);
    }
    await page.locator('#figures').screenshot({ path: `${SHOTS}figures.png` });
    await page.screenshot({ path: `${SHOTS}gallery.png`, fullPage: true });
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('the page names papers by what they are, never by the files of our copies, and says what each brings', async () => {
  const { page, errors } = await open(browser, base, { width: 1280, height: 900 });
  try {
    await waitForState(page, ['gallery']);
    const text = await page.evaluate(() => document.body.innerText);
    assert.doesNotMatch(text, /seed 00\d|\d{3}_[0-9a-f]{16}/i);
    const papers = await page.$$eval('#about dt', (dts) => dts.map((d) => d.textContent));
    assert.equal(papers.length, 4);
    for (const words of ['Modeling seashells', '1/6-8/5', 'A morphological study of the form of nature', 'Murex cabritii']) {
      assert.ok(papers.some((p) => p.includes(words)), `the About section names ${words}`);
    }
    const sources = await page.$$eval('a.card', (cards) => cards.map((c) => c.textContent));
    for (const s of sources) assert.doesNotMatch(s, /seed 00\d/i);
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('a card opens its shell growing, Back returns to the gallery and Forward to the shell', async () => {
  const { page, errors } = await open(browser, base);
  try {
    await waitForState(page, ['gallery']);
    await page.click('a.card[data-preset="oliva-porphyria"]');
    const opened = await waitForState(page, ['growing', 'grown']);
    assert.equal(opened.view, 'viewer');
    assert.equal(await page.textContent('#title'), 'Oliva porphyria');
    assert.ok(await page.isVisible('#shell'));
    await page.goBack();
    await page.waitForFunction(() => document.body.dataset.view === 'gallery');
    assert.ok(await page.isVisible('#gallery'));
    assert.equal(await page.isVisible('#viewer'), false);
    await page.goForward();
    await page.waitForFunction(() => document.body.dataset.view === 'viewer');
    assert.equal(await page.textContent('#title'), 'Oliva porphyria');
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('moving a slider changes the link, and the link gives the same pattern in a fresh page', async () => {
  const { page, errors } = await open(browser, `${base}#v=1&preset=oliva-porphyria&growth.speed=200`);
  try {
    await waitForState(page, ['grown']);
    const before = (await dataset(page)).patternHash;
    const slider = page.locator('[data-key="pattern.model.d_a"] input.slider');
    await slider.fill('300');
    await page.waitForFunction(() => location.hash.includes('pattern.model.d_a='));
    const link = await page.evaluate(() => location.href);
    assert.match(link, /#v=1&preset=oliva-porphyria&.*pattern\.model\.d_a=0\.15/);
    assert.equal(await page.inputValue('[data-key="pattern.model.d_a"] input.number'), '0.15');
    const grown = await waitForState(page, ['grown']);
    assert.notEqual(grown.patternHash, before, 'a new diffusion gives a new pattern');
    const fresh = await open(browser, link);
    const again = await waitForState(fresh.page, ['grown']);
    assert.equal(again.patternHash, grown.patternHash);
    await fresh.page.close();
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

// Bad links of each kind the page must survive, and words its message must contain: an
// unknown key, a preset name that is markup, a seed far too long, a value shown as asked but
// said, and a chamber form and an implicit one given values they cannot grow with (refused,
// and the shell grown without them). The words of every bad link's message are the native
// suite's (tests/link.rs, the_pages_message_for_each_bad_link_says_what_is_wrong); here they
// must reach the page as text, with a shell growing.
const BAD_LINKS = [
  ['#v=1&preset=turbinate&form.spiral.whorlz=3', 'form.spiral.whorlz: is not a key'],
  ['#v=1&preset=%3Cimg%20src=x%20onerror=alert(1)%3E', 'no preset'],
  [`#v=1&preset=turbinate&seed=${'9'.repeat(20000)}`, 'more than the 16384'],
  ['#v=1&preset=kawaguchi-ammonite&form.chamber.ratio=1', 'Shown as asked, but: form.chamber.ratio: whorls overlap'],
  ['#v=1&preset=kawaguchi-shell&form.mouth.protuberances=0,-1.5', 'fold the mouth polygon over itself'],
  ['#v=1&preset=implicit-whorl&form.spiral.lambda=1.01', 'too thin for the grid of 96 voxels'],
];

test('bad links each get a specific message and still a working page', async () => {
  for (const [fragment, words] of BAD_LINKS) {
    const { page, errors } = await open(browser, `${base}${fragment}`);
    let dialog = false;
    page.on('dialog', async (d) => { dialog = true; await d.dismiss(); });
    try {
      const state = await waitForState(page, ['growing', 'grown']);
      assert.equal(state.view, 'viewer', fragment);
      assert.ok(await page.isVisible('#message'), `${fragment.slice(0, 80)}: no message`);
      assert.ok((await page.textContent('#message')).includes(words), `${fragment.slice(0, 80)}: ${await page.textContent('#message')}`);
      assert.equal(await page.locator('img[src="x"]').count(), 0, 'nothing from the link became HTML');
      assert.equal(dialog, false);
      assert.deepEqual(errors, []);
    } finally {
      await page.close();
    }
  }
});

test('a link of the first format (the preset alone) still opens', async () => {
  const { page } = await open(browser, `${base}#conus-marmoreus`);
  try {
    await waitForState(page, ['growing', 'grown']);
    assert.equal(await page.textContent('#title'), 'Conus marmoreus');
    assert.equal(await page.isVisible('#message'), false);
  } finally {
    await page.close();
  }
});

test('the keyboard plays, pauses, steps and restarts', async () => {
  const { page } = await open(browser, `${base}#v=1&preset=stripes&growth.speed=2`);
  try {
    await waitForState(page, ['growing']);
    await page.locator('#shell').click();
    await page.keyboard.press(' ');
    await page.waitForFunction(() => document.body.dataset.playing === 'false');
    // Rows asked of the worker before the pause still arrive: wait until every answer is in.
    await page.waitForFunction(() => document.body.dataset.settled === 'true');
    const paused = Number((await dataset(page)).rows);
    await page.waitForTimeout(600);
    assert.equal(Number((await dataset(page)).rows), paused, 'paused growth stays put');
    await page.keyboard.press('s');
    await page.waitForFunction((n) => Number(document.body.dataset.rows) === n + 1, paused);
    await page.keyboard.press(' ');
    await page.waitForFunction((n) => Number(document.body.dataset.rows) > n + 5, paused);
    await page.waitForFunction(() => Number(document.body.dataset.rows) > 40);
    await page.keyboard.press('r');
    await page.waitForFunction(() => Number(document.body.dataset.rows) < 20);
    await page.keyboard.press('+');
    await page.waitForFunction(() => location.hash.includes('growth.speed=3'));
  } finally {
    await page.close();
  }
});

test('the finish control and its key grow the shell to its end at once', async () => {
  // Grown at full speed, the shell's mesh is the reference the finished one must equal.
  const reference = await open(browser, `${base}#v=1&preset=stripes&growth.speed=200`);
  const { meshHash } = await waitForState(reference.page, ['grown']);
  await reference.page.close();
  for (const [preset, press] of [['stripes', (page) => page.click('#finish')], ['implicit-whorl', (page) => page.keyboard.press('e')]]) {
    const { page, errors } = await open(browser, `${base}#v=1&preset=${preset}&growth.speed=0.05`);
    try {
      await waitForState(page, ['growing']);
      await page.locator('#shell').click();
      await press(page);
      const grown = await waitForState(page, ['grown'], 60_000);
      const total = Number(await page.getAttribute('#progress', 'max'));
      assert.ok(total > 100 && Number(grown.rows) === total, `${preset}: ${grown.rows} of ${total} rows`);
      if (preset === 'stripes') assert.equal(grown.meshHash, meshHash, 'finished as if grown row by row');
      assert.deepEqual(errors, []);
    } finally {
      await page.close();
    }
  }
});

test('the link copies to the clipboard and the mesh downloads as OBJ and STL', async () => {
  const context = await browser.newContext({ permissions: ['clipboard-read', 'clipboard-write'] });
  const page = await context.newPage();
  try {
    await page.goto(`${base}#v=1&preset=turbinate&form.spiral.whorls=3&growth.speed=200`);
    await waitForState(page, ['grown']);
    await page.click('#copy-link');
    await page.waitForFunction(() => document.getElementById('copy-status').textContent === 'Link copied');
    const copied = await page.evaluate(() => navigator.clipboard.readText());
    assert.equal(copied, await page.evaluate(() => location.href));
    for (const [what, magic] of [['obj', '# seashells'], ['stl', 'seashells']]) {
      const [download] = await Promise.all([page.waitForEvent('download'), page.click(`#download-${what}`)]);
      assert.equal(download.suggestedFilename(), `turbinate.${what}`);
      const file = `${SHOTS}turbinate.${what}`;
      await download.saveAs(file);
      assert.ok(readFileSync(file).subarray(0, 20).toString().startsWith(magic));
    }
    const [picture] = await Promise.all([page.waitForEvent('download'), page.click('#download-picture')]);
    await picture.saveAs(`${SHOTS}turbinate-picture.png`);
    assert.equal(readFileSync(`${SHOTS}turbinate-picture.png`).subarray(1, 4).toString(), 'PNG');
  } finally {
    await context.close();
  }
});

test('on a phone the shell comes first and the panel opens on demand', async () => {
  const context = await browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
  const page = await context.newPage();
  try {
    await page.goto(`${base}#v=1&preset=amoria-undulata&growth.speed=50`);
    await waitForState(page, ['growing', 'grown']);
    assert.equal(await page.isVisible('#panel-fields'), false);
    await page.click('#panel-toggle');
    assert.ok(await page.isVisible('#panel-fields'));
    assert.equal(await page.getAttribute('#panel-toggle', 'aria-expanded'), 'true');
    await page.screenshot({ path: `${SHOTS}phone.png`, fullPage: true });
  } finally {
    await context.close();
  }
});

test('the page allows the wasm and nothing inline', async () => {
  const html = readFileSync(`${ROOT}www/index.html`, 'utf8');
  const csp = /Content-Security-Policy" content="([^"]+)"/.exec(html)[1];
  assert.match(csp, /script-src 'self' 'wasm-unsafe-eval'/);
  assert.doesNotMatch(csp, /'unsafe-inline'|'unsafe-eval'/);
  assert.doesNotMatch(html, /<script>|style=|onclick=/);
});
