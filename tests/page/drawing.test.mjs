// Kawaguchi's ways of looking at a shell, on both backends: his four views (front, side and top
// in orthographic projection, with the perspective view) asked for by the link and toggled by
// the button and the key, and his line drawings (material.drawing=lines), checked by their
// pixels.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { open, session, waitForState } from './browser.mjs';

const SHOTS = new URL('./screenshots/drawing/', import.meta.url).pathname;
mkdirSync(SHOTS, { recursive: true });

// A straight tusk: chambers of ratio 1 with no inclination, a cylinder standing on its axis.
const TUSK = 'v=1&preset=kawaguchi-tusk&form.chamber.ratio=1&form.chamber.inclination.y=0'
  + '&form.chambers=10&form.chamber.width=0.3&growth.rows=11&material.shadow=0&growth.speed=200';

/**
 * Grows `link` to its end and photographs the canvas into `file`; returns the page's state and,
 * measured in the page, for each quarter of the canvas (or the whole), the rows of the shell's
 * silhouette: for every row of pixels, the first and last pixel that differs from the
 * background. Also returns the picture's statistics (see `statistics` below).
 */
async function grow(browser, base, link, file) {
  const { page, errors } = await open(browser, `${base}#${link}`, { width: 900, height: 900 });
  try {
    const state = await waitForState(page, ['grown', 'error']);
    assert.equal(state.state, 'grown', await page.textContent('#message'));
    await page.waitForTimeout(300);
    // The canvas alone: the caption, controls and pane labels over it hidden.
    await page.evaluate(() => {
      for (const e of document.querySelectorAll('#viewer *')) e.style.visibility = 'hidden';
      document.getElementById('shell').style.visibility = 'visible';
    });
    const png = await page.locator('#shell').screenshot({ path: file });
    await page.evaluate(() => {
      for (const e of document.querySelectorAll('#viewer *')) e.style.visibility = '';
    });
    const measured = await page.evaluate(statistics, [...png]);
    assert.deepEqual(errors, []);
    return { page, state, ...measured };
  } catch (error) {
    await page.close();
    throw error;
  }
}

/** Runs in the page: reads the PNG and measures it. */
async function statistics(bytes) {
  const bitmap = await createImageBitmap(new Blob([new Uint8Array(bytes)], { type: 'image/png' }));
  const c = new OffscreenCanvas(bitmap.width, bitmap.height);
  const g = c.getContext('2d');
  g.drawImage(bitmap, 0, 0);
  const { width, height } = bitmap;
  const { data } = g.getImageData(0, 0, width, height);
  const bg = [data[0], data[1], data[2]];
  const at = (x, y) => 4 * (y * width + x);
  const differs = (i) => Math.abs(data[i] - bg[0]) + Math.abs(data[i + 1] - bg[1]) + Math.abs(data[i + 2] - bg[2]) > 24;
  const dark = (i) => data[i] + data[i + 1] + data[i + 2] < 3 * 90;
  const grey = (i) => data[i] + data[i + 1] + data[i + 2] < 3 * 150;
  // The silhouette of each quarter, row by row: [first, last] differing x, or null.
  const quarters = [[0, 0], [1, 0], [0, 1], [1, 1]].map(([qx, qy]) => {
    const [w, h] = [Math.floor(width / 2), Math.floor(height / 2)];
    const rows = [];
    for (let y = qy * h; y < (qy + 1) * h; y++) {
      let first = null;
      let last = null;
      for (let x = qx * w + 2; x < (qx + 1) * w - 2; x++) {
        if (differs(at(x, y))) {
          first ??= x;
          last = x;
        }
      }
      rows.push(first === null ? null : [first, last]);
    }
    return rows;
  });
  // The whole picture: the box of what differs from the background, the colours that each
  // cover more than 1 % of it (quantised to 5 bits a channel), its dark pixels and how many of
  // them are inside a blob (all eight neighbours dark too), and whether the silhouette is drawn
  // in ink: for each row, the share of ends (first and last differing pixel) with a dark or
  // antialiased dark pixel within 3 px.
  const shades = new Map();
  const box = [width, height, 0, 0];
  let shell = 0;
  let inked = 0;
  let blob = 0;
  let ends = 0;
  let inkedEnds = 0;
  for (let y = 1; y < height - 1; y++) {
    let first = null;
    let last = null;
    for (let x = 1; x < width - 1; x++) {
      const i = at(x, y);
      if (!differs(i)) continue;
      first ??= x;
      last = x;
      shell += 1;
      box[0] = Math.min(box[0], x);
      box[1] = Math.min(box[1], y);
      box[2] = Math.max(box[2], x);
      box[3] = Math.max(box[3], y);
      const shade = ((data[i] >> 3) << 10) | ((data[i + 1] >> 3) << 5) | (data[i + 2] >> 3);
      shades.set(shade, (shades.get(shade) ?? 0) + 1);
      if (dark(i)) {
        inked += 1;
        let all = true;
        for (const [dx, dy] of [[-1, -1], [0, -1], [1, -1], [-1, 0], [1, 0], [-1, 1], [0, 1], [1, 1]]) {
          if (!dark(at(x + dx, y + dy))) all = false;
        }
        if (all) blob += 1;
      }
    }
    if (first === null) continue;
    for (const [end, step] of [[first, 1], [last, -1]]) {
      ends += 1;
      for (let k = 0; k <= 3; k++) {
        if (grey(at(end + step * k, y))) {
          inkedEnds += 1;
          break;
        }
      }
    }
  }
  // A column of the front pane near the middle of the silhouette's middle row, top to bottom
  // where the shell is, the one of 21 that is palest (off the lines drawn along the growth):
  // each pixel's darkness, 0 for the page's background (the paper is as light), 1 for ink.
  const drawn = quarters[0].flatMap((row, y) => (row === null ? [] : [[y, row]]));
  const paper = (bg[0] + bg[1] + bg[2]) / 3;
  let column = [];
  if (drawn.length > 0) {
    const [, [first, last]] = drawn[Math.floor(drawn.length / 2)];
    const middle = Math.round((first + last) / 2);
    const ys = drawn.map(([y]) => y);
    let palest = -1;
    for (let x = middle - 10; x <= middle + 10; x++) {
      const light = ys.map((y) => (data[at(x, y)] + data[at(x, y) + 1] + data[at(x, y) + 2]) / 3);
      const median = [...light].sort((a, b) => a - b)[Math.floor(light.length / 2)];
      if (median > palest) {
        palest = median;
        column = light.map((l) => Math.min(Math.max((paper - l) / (paper - 8), 0), 1));
      }
    }
  }
  return {
    quarters,
    column,
    box,
    shell: shell / (width * height),
    colours: [...shades.values()].filter((n) => n > 0.01 * shell).length,
    ink: inked / Math.max((box[2] - box[0] + 1) * (box[3] - box[1] + 1), 1),
    blobs: blob / Math.max(inked, 1),
    outline: inkedEnds / Math.max(ends, 1),
  };
}

/** The silhouette's width at a fraction `f` of its height, from a quarter's rows. */
function widthAt(rows, f) {
  const filled = rows.map((r, y) => [r, y]).filter(([r]) => r !== null);
  const [, top] = filled[0];
  const [, bottom] = filled[filled.length - 1];
  const [[[first, last]]] = filled.filter(([, y]) => y >= top + f * (bottom - top));
  return last - first + 1;
}

for (const backend of ['WebGL2', 'WebGPU']) {
  test(`four views: front, side and top are orthographic, each pane shows the shell, on ${backend}`, async () => {
    const { browser, base, close } = await session(backend);
    try {
      const { page, state, quarters } = await grow(browser, base, `${TUSK}&view=four`, `${SHOTS}tusk-four-${backend}.png`);
      assert.equal(state.backend, backend);
      assert.equal(state.layout, 'four');
      const names = await page.$$eval('#panes .pane', (panes) => panes.map((p) => p.textContent));
      assert.deepEqual(names, ['Front', 'Side', 'Top', 'Perspective']);
      assert.equal(await page.isVisible('#panes'), true);
      for (const [i, rows] of quarters.entries()) {
        const drawn = rows.filter((r) => r !== null).length;
        assert.ok(drawn > 0.3 * rows.length, `${names[i]} shows the shell in only ${drawn} of ${rows.length} rows`);
      }
      // A straight cylinder standing upright: the same width near its top and near its bottom
      // in the front and side views; the perspective view, from a little above, draws its
      // nearer top wider (the measurement can tell the two apart).
      for (const [i, name] of [[0, 'Front'], [1, 'Side']]) {
        const [upper, lower] = [widthAt(quarters[i], 0.15), widthAt(quarters[i], 0.85)];
        assert.ok(Math.abs(upper - lower) <= 2, `${name}: ${upper} px wide near the top, ${lower} px near the bottom`);
      }
      const [upper, lower] = [widthAt(quarters[3], 0.15), widthAt(quarters[3], 0.85)];
      assert.ok(upper - lower >= 5, `perspective: ${upper} px near the top, ${lower} px near the bottom`);
      // The key and the button toggle the layout, and the link follows.
      await page.keyboard.press('v');
      await page.waitForFunction(() => document.body.dataset.layout === 'single');
      assert.equal(await page.isVisible('#panes'), false);
      assert.ok(!page.url().includes('view=four'), page.url());
      await page.click('#views');
      await page.waitForFunction(() => document.body.dataset.layout === 'four');
      assert.equal(await page.getAttribute('#views', 'aria-pressed'), 'true');
      await page.waitForFunction(() => window.location.hash.includes('view=four'));
      await page.close();
    } finally {
      await close();
    }
  });

  test(`a line drawing is lines on paper with the shell's outline, on ${backend}`, async () => {
    const { browser, base, close } = await session(backend);
    try {
      const link = 'v=1&preset=kawaguchi-shell&growth.speed=200&material.shadow=0';
      const shaded = await grow(browser, base, link, `${SHOTS}shell-shaded-${backend}.png`);
      await shaded.page.close();
      const lines = await grow(browser, base, `${link}&material.drawing=lines`, `${SHOTS}shell-lines-${backend}.png`);
      await lines.page.close();
      const figures = JSON.stringify({ shaded: { ...shaded, quarters: undefined, page: undefined }, lines: { ...lines, quarters: undefined, page: undefined } });
      // Few colours (paper and ink) where the shaded shell has many.
      assert.ok(lines.colours <= 10 && shaded.colours >= 3 * lines.colours, figures);
      // Many dark pixels, in thin lines rather than filled areas.
      assert.ok(lines.ink > 0.05 && lines.ink < 0.4 && shaded.ink < 0.02, figures);
      assert.ok(lines.blobs < 0.25, figures);
      // The same shell: the drawing spans what the shaded shell covers (its paper may match the
      // page's), and its outline is drawn in ink all round.
      for (const k of [0, 1, 2, 3]) {
        assert.ok(Math.abs(lines.box[k] - shaded.box[k]) <= 4, figures);
      }
      assert.ok(lines.outline > 0.9, figures);
      assert.ok(shaded.outline < 0.6, figures);
    } finally {
      await close();
    }
  });
}

test('a line drawing draws every chamber base, spaced apart or crowded together', async () => {
  const { browser, base, close } = await session('WebGL2');
  try {
    // An upright cylinder of chambers three units tall, seen from the front in orthographic
    // projection: its chamber bases are level lines across it. Spaced a dozen pixels apart,
    // each is a line of its own; crowded two pixels apart, they are no longer told apart, and
    // the cylinder takes the share of ink they cover, as on a vector display (they once faded
    // away, and a crowded tusk was drawn as its outline alone).
    const cylinder = (n) => TUSK.replace('form.chambers=10', `form.chambers=${n}`)
      .replace('form.chamber.width=0.3', `form.chamber.width=${3 / n}`)
      .replace('growth.rows=11', `growth.rows=${n + 1}`) + '&view=four&material.drawing=lines';
    // A line whose middle falls between two rows of pixels greys both, each less than half.
    const runs = (column) => column.filter((d, i) => d > 0.15 && !(column[i - 1] > 0.15)).length;
    const spaced = await grow(browser, base, cylinder(24), `${SHOTS}bases-spaced.png`);
    await spaced.page.close();
    const inner = (column) => column.slice(Math.floor(column.length * 0.1), Math.ceil(column.length * 0.9));
    assert.ok(runs(spaced.column) >= 24, `${runs(spaced.column)} lines across 24 chambers: ${spaced.column.map((d, i) => (d > 0.05 ? `${i}:${d.toFixed(2)}` : "")).filter(Boolean)}`);
    const crowded = await grow(browser, base, cylinder(160), `${SHOTS}bases-crowded.png`);
    await crowded.page.close();
    const mid = inner(crowded.column);
    const mean = mid.reduce((a, b) => a + b, 0) / mid.length;
    assert.ok(mean > 0.3, `160 chambers ${crowded.column.length} px tall: mean darkness ${mean.toFixed(2)} inside`);
  } finally {
    await close();
  }
});

test('a link asking for an unknown view says so and shows one view', async () => {
  const { browser, base, close } = await session('WebGL2');
  try {
    const { page, errors } = await open(browser, `${base}#v=1&preset=kawaguchi-tusk&view=nine`);
    const state = await waitForState(page, ['growing', 'grown', 'error']);
    assert.equal(state.layout, 'single');
    assert.match(await page.textContent('#message'), /view: 'nine' is not one of single, four/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
