// The stories of species/stories/: each step of the coiling story opens as its link (the shell
// it names, its words, the paper's figure), is drawn, and moves to the next by its link, the
// arrow and page keys and a swipe across its card, without reloading the page; a step beyond
// the end opens the last with a note, an unknown story the gallery with one; a step that asks
// for the parameter map opens it over the numbers it names; an embedded story shows its step
// over the shell. Screenshots go to tests/page/screenshots/story-*.png (the README shows one).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readdirSync, readFileSync } from 'node:fs';
import { browsers, measureCanvas, waitForState } from './browser.mjs';

const ROOT = new URL('../../', import.meta.url).pathname;
const SHOTS = `${ROOT}tests/page/screenshots/`;
mkdirSync(SHOTS, { recursive: true });
const STORIES = readdirSync(`${ROOT}species/stories`).filter((f) => f.endsWith('.json'))
  .map((f) => ({ id: f.slice(0, -5), ...JSON.parse(readFileSync(`${ROOT}species/stories/${f}`, 'utf8')) }));
const { openOn } = browsers(['WebGL2']);
const VIEWPORT = { width: 1400, height: 900 };

/** Waits until step `k` (from 1) of `story` is shown, and returns what the page shows of it. */
async function shownStep(page, story, k, more = '') {
  await page.waitForFunction((want) => document.body.dataset.story === want,
    `story=${story.id}&step=${k}${more}`, { timeout: 60_000 });
  return page.evaluate(() => ({
    count: document.getElementById('story-count').textContent,
    title: document.getElementById('story-step-title').textContent,
    text: document.getElementById('story-text').textContent,
    cites: document.getElementById('story-cites').textContent,
    hidden: document.getElementById('story').hidden,
    hash: location.hash,
  }));
}

/** Waits until the step's shell is drawn (under its map, until the map is filled). */
async function drawn(page, step, file) {
  if (step.map) {
    await page.waitForFunction(() => ['filling', 'whole'].includes(document.body.dataset.map), null, { timeout: 60_000 });
    const axes = await page.evaluate(() => [document.getElementById('map-x').value, document.getElementById('map-y').value]);
    assert.deepEqual(axes, [step.map.across, step.map.down], 'the map spans the numbers the step names');
    return;
  }
  // Grown, or past its first few rows (a chamber, a speck of apex).
  await page.waitForFunction(() => ['grown', 'stopped'].includes(document.body.dataset.state)
    || (document.body.dataset.state === 'growing' && Number(document.body.dataset.rows) >= 10), null, { timeout: 180_000 });
  if (step.growth === 'whole') {
    const still = await waitForState(page, ['grown']);
    assert.equal(still.playing, 'false', 'a step shown whole stands still');
  }
  const { share } = await measureCanvas(page, file);
  assert.ok(share > 0.004, `a shell is drawn (${share} of the canvas)`);
}

// One story is walked here, the coiling story, whose steps are grown, shown whole and under a
// parameter map: what the page shows of each step of every story (which step, its shell, its
// map, whether a step shown whole stands still) is the session's to decide, and
// tests/stories.rs walks them all natively by their Next links; the forms they show are drawn
// by their own page tests.
const WALKED = STORIES.filter((s) => s.id === 'coiling');
assert.equal(WALKED.length, 1, 'the coiling story');

for (const story of WALKED) test(`the story ${story.id} steps through its ${story.steps.length} steps, each its link, drawn`, async () => {
  const { page, errors } = await openOn('WebGL2', `story=${story.id}`, VIEWPORT);
  try {
    await page.evaluate(() => { window.sameDocument = true; });
    for (const [i, step] of story.steps.entries()) {
      const k = i + 1;
      if (k > 1) await page.click('#story-next');
      const shown = await shownStep(page, story, k);
      assert.equal(shown.hidden, false);
      assert.equal(shown.count, `Step ${k} of ${story.steps.length}`);
      assert.equal(shown.title, step.title);
      assert.equal(shown.text, step.text);
      assert.equal(shown.cites, [step.figure, step.equation].filter(Boolean).join(' · '));
      assert.equal(shown.hash, k === 1 ? `#story=${story.id}` : `#story=${story.id}&step=${k}`, 'the address is the step\'s link');
      await drawn(page, step, `${SHOTS}story-${story.id}-${k}.png`);
      assert.equal(await page.evaluate(() => document.getElementById('message').hidden), true, `step ${k} needs no repair`);
    }
    assert.equal(await page.evaluate(() => window.sameDocument), true, 'no step reloaded the page');
    assert.equal(await page.getAttribute('#story-next', 'aria-disabled'), 'true', 'the last step has no next');
    // A step's link opened afresh shows the same step.
    const middle = Math.ceil(story.steps.length / 2);
    await page.goto(page.url().replace(/#.*$/, `#story=${story.id}&step=${middle}`));
    await page.reload();
    assert.equal((await shownStep(page, story, middle)).title, story.steps[middle - 1].title);
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('the keys and a swipe move between steps; a step beyond the end opens the last, an unknown story the gallery, each with a note', async () => {
  const story = STORIES.find((s) => s.id === 'coiling');
  const n = story.steps.length;
  const { page, errors } = await openOn('WebGL2', `story=coiling&step=${n + 3}`, VIEWPORT);
  try {
    assert.equal((await shownStep(page, story, n)).count, `Step ${n} of ${n}`);
    const note = await page.textContent('#message');
    assert.match(note, /has \d+ steps, not \d+; opened the last/);
    // The last step opens Raup's map, whose tiles the arrows walk: Page Up leaves it.
    await page.keyboard.press('PageUp');
    await shownStep(page, story, n - 1);
    await page.keyboard.press('ArrowRight');
    await shownStep(page, story, n);
    await page.keyboard.press('PageUp');
    await shownStep(page, story, n - 1);
    await page.keyboard.press('ArrowLeft');
    await shownStep(page, story, n - 2);
    await page.keyboard.press('PageDown');
    await shownStep(page, story, n - 1);
    // A quick stroke rightwards across the card: the step before. Dispatched in the page, as
    // one touch's pointer events: driven from outside, a busy page takes each move seconds apart
    // (gestures.rs tests what is quick and what is not).
    await page.evaluate(() => {
      const text = document.getElementById('story-text');
      const { left, top, height } = text.getBoundingClientRect();
      const at = (x) => ({ clientX: left + x, clientY: top + height / 2, pointerId: 7, pointerType: 'touch', bubbles: true });
      text.dispatchEvent(new PointerEvent('pointerdown', at(30)));
      text.dispatchEvent(new PointerEvent('pointerup', at(190)));
    });
    await shownStep(page, story, n - 2);
    await page.click('#story-next');
    await shownStep(page, story, n - 1);
    await page.click('#story-next');
    await shownStep(page, story, n);
    if (story.steps[n - 1].map) {
      await page.waitForFunction(() => document.body.dataset.map === 'whole', null, { timeout: 180_000 });
    }
    await page.screenshot({ path: `${SHOTS}story-step.png` });
    await page.evaluate(() => { location.hash = 'story=nautilus'; });
    await waitForState(page, ['gallery']);
    assert.match(await page.textContent('#message'), /there is no story 'nautilus'/);
    assert.equal(await page.evaluate(() => document.getElementById('story').hidden), true);
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});

test('an embedded story (ui=controls) shows its step over the shell, with the play controls', async () => {
  const { page, errors } = await openOn('WebGL2', 'story=waves&step=2&ui=controls', { width: 800, height: 600 });
  try {
    await shownStep(page, STORIES.find((s) => s.id === 'waves'), 2, '&ui=controls');
    await waitForState(page, ['growing', 'grown']);
    const layout = await page.evaluate(() => {
      const box = (id) => document.getElementById(id).getBoundingClientRect();
      const visible = (sel) => getComputedStyle(document.querySelector(sel)).display !== 'none';
      return { story: box('story'), shell: box('shell'), panel: visible('.panel'), controls: visible('.controls') };
    });
    assert.ok(!layout.panel && layout.controls, 'the embed keeps its controls and hides the panel');
    assert.ok(layout.story.height > 40 && layout.story.bottom < layout.shell.bottom / 2, `the step over the top of the shell: ${JSON.stringify(layout.story)}`);
    await page.click('#story-next');
    await page.waitForFunction(() => document.body.dataset.story === 'story=waves&step=3&ui=controls');
    // That step opens the map in the full page; an embed shows none, and its shell grows.
    const third = await waitForState(page, ['growing', 'grown']);
    assert.equal(third.map, '', 'no map in an embed');
    await page.screenshot({ path: `${SHOTS}story-embed.png` });
    assert.deepEqual(errors, []);
  } finally {
    await page.close();
  }
});
