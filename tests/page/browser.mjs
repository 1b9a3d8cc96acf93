// Headless Chromium (Debian's, driven by playwright-core) with the flags that give each
// graphics backend on these machines (see ../shared/TOOLCHAIN.md), and helpers that read the
// page's own signals and its pixels.
import { readdirSync } from 'node:fs';
import { after, before } from 'node:test';
import { PNG } from 'pngjs';
import { chromium } from 'playwright-core';
import { serve } from './serve.mjs';

const COMMON = [
  '--no-sandbox', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--disable-quic',
];

/** Flags per backend: WebGL2 through SwiftShader's GL, WebGPU through SwiftShader's Vulkan. */
/** How many shells the gallery lists: one for each preset in species/. */
export const PRESETS = readdirSync(new URL('../../species/', import.meta.url)).filter((f) => f.endsWith('.json')).length;

export const BACKENDS = {
  WebGL2: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  WebGPU: [
    '--enable-unsafe-webgpu', '--enable-features=Vulkan', '--use-angle=swiftshader',
    '--use-vulkan=swiftshader', '--enable-unsafe-swiftshader',
  ],
};

/** Launches Chromium for `backend` ("WebGL2" or "WebGPU"). */
export function launch(backend) {
  return chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args: [...COMMON, ...BACKENDS[backend]],
  });
}

/** Opens `url` in a new page, collecting console errors and uncaught exceptions. */
export async function open(browser, url, viewport = { width: 900, height: 700 }) {
  const page = await browser.newPage({ viewport });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(url);
  return { page, errors };
}

/** The Chromium trace events of `categories` recorded on `page` while `during()` runs. */
export async function trace(page, categories, during) {
  const cdp = await page.context().newCDPSession(page);
  const events = [];
  cdp.on('Tracing.dataCollected', (e) => events.push(...e.value));
  const complete = new Promise((resolve) => cdp.once('Tracing.tracingComplete', resolve));
  await cdp.send('Tracing.start', {
    traceConfig: { includedCategories: categories, recordMode: 'recordAsMuchAsPossible' },
    transferMode: 'ReportEvents',
  });
  await during();
  await cdp.send('Tracing.end');
  await complete;
  await cdp.detach();
  return events;
}

/**
 * The page's main thread in trace `events`: its `requestAnimationFrame` callbacks (`frames`,
 * those with a thread clock) and all its complete events in time order (`onThread`); the
 * thread is the one that ran the first callback.
 */
export function pageThread(events) {
  const frames = events.filter((e) => e.name === 'FireAnimationFrame' && e.ph === 'X' && e.tdur !== undefined);
  if (frames.length === 0) return { frames, onThread: [] };
  const { pid, tid } = frames[0];
  const onThread = events.filter((e) => e.pid === pid && e.tid === tid && e.ph === 'X').sort((a, b) => a.ts - b.ts);
  return { frames, onThread };
}

/** Waits until <body data-state> is one of `states` (the page's own signal). */
export async function waitForState(page, states, timeout = 120_000) {
  await page.waitForFunction(
    (wanted) => wanted.includes(document.body.dataset.state),
    states,
    { timeout },
  );
  return page.evaluate(() => ({ ...document.body.dataset }));
}

/**
 * Once the shell has started growing, finishes it at once (the Finish key, e) and waits for it
 * grown (or failed); returns the page's signals. The shell is the same as grown row by row
 * (gallery.test.mjs), and a finish costs one meshing where growth at full speed re-meshes the
 * growing edge every frame, which in software rendering takes minutes for an implicit shell.
 */
export async function finishGrowth(page, timeout = 300_000) {
  await waitForState(page, ['growing', 'grown', 'error']);
  await page.keyboard.press('e');
  return waitForState(page, ['grown', 'error'], timeout);
}

/** Measures the canvas as shown, from a screenshot kept in `file` (see `measurePng`). */
export async function measureCanvas(page, file) {
  return measurePng(await page.locator('#shell').screenshot({ path: file }));
}

/**
 * How much of a PNG differs from its top-left pixel (the background): the share of pixels that
 * differ by more than 24 in the sum of their channels, and how many distinct shades (colours
 * quantised to 4 bits a channel) the differing ones have. Read in Node (pngjs).
 */
export function measurePng(png) {
  const { width, height, data } = PNG.sync.read(png);
  const bg = [data[0], data[1], data[2]];
  let differing = 0;
  const shades = new Set();
  for (let i = 0; i < data.length; i += 4) {
    const d = Math.abs(data[i] - bg[0]) + Math.abs(data[i + 1] - bg[1]) + Math.abs(data[i + 2] - bg[2]);
    if (d > 24) {
      differing += 1;
      shades.add(((data[i] >> 4) << 8) | ((data[i + 1] >> 4) << 4) | (data[i + 2] >> 4));
    }
  }
  return { share: differing / (width * height), shades: shades.size, width, height };
}

/**
 * The share of pixels that differ (by more than 24 in the sum of their channels) between two
 * screenshots of the same size. Read in Node (pngjs).
 */
export function differing(pngA, pngB) {
  const [p, q] = [PNG.sync.read(pngA).data, PNG.sync.read(pngB).data];
  let count = 0;
  for (let i = 0; i < p.length; i += 4) {
    if (Math.abs(p[i] - q[i]) + Math.abs(p[i + 1] - q[i + 1]) + Math.abs(p[i + 2] - q[i + 2]) > 24) count += 1;
  }
  return count / (p.length / 4);
}

/** Serves www/ and launches Chromium for `backend`: what a test file shares across its tests. */
export async function session(backend = 'WebGL2') {
  const server = await serve(new URL('../../www/', import.meta.url).pathname);
  const browser = await launch(backend);
  return {
    base: `http://127.0.0.1:${server.address().port}/`,
    browser,
    close: async () => {
      await browser.close();
      server.close();
    },
  };
}

/**
 * The gallery cards' pictures as shown: for each card, its preset, the image's address and the
 * image's pixels as PNG bytes (drawn from the decoded image, since the page's policy lets no
 * script fetch the object URLs it shows).
 */
export function cardPictures(page) {
  return page.$$eval('a.card', (cards) => Promise.all(cards.map(async (card) => {
    const img = card.querySelector('img');
    const src = img.src;
    if (!src.startsWith('blob:')) return { preset: card.dataset.preset, src, png: null };
    await img.decode();
    const c = new OffscreenCanvas(img.naturalWidth, img.naturalHeight);
    c.getContext('2d').drawImage(img, 0, 0);
    const blob = await c.convertToBlob({ type: 'image/png' });
    return { preset: card.dataset.preset, src, png: [...new Uint8Array(await blob.arrayBuffer())] };
  })));
}

/**
 * The shells of a grid of tiles as drawn (the parameter map's, or breeding's, by the grid's
 * selector): each tile's link, title and classes, and for a drawn picture the
 * box of its pixels that differ from its corner (the shell, not the background), and a digest
 * of its pixels.
 */
export async function shellTiles(page, grid = '#map-grid') {
  // A picture is drawn in one frame and shown in its tile once the browser has read it.
  await page.waitForFunction((g) => [...document.querySelectorAll(`${g} .tile`)]
    .every((a) => a.classList.contains('failed') || a.querySelector('img')?.src.startsWith('blob:')), grid);
  return page.$$eval(`${grid} .tile`, (tiles) => Promise.all(tiles.map(async (a) => {
    const img = a.querySelector('img');
    const tile = { href: a.getAttribute('href'), title: a.title, classes: [...a.classList], drawn: false };
    if (!img || !img.src.startsWith('blob:')) return tile;
    await img.decode();
    const { naturalWidth: w, naturalHeight: h } = img;
    const c = new OffscreenCanvas(w, h);
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    const { data } = g.getImageData(0, 0, w, h);
    let [x0, y0, x1, y1, digest] = [w, h, -1, -1, 0];
    for (let y = 0; y < h; y += 1) {
      for (let x = 0; x < w; x += 1) {
        const i = (y * w + x) * 4;
        digest = (digest * 31 + data[i] + data[i + 1] * 7 + data[i + 2] * 13) >>> 0;
        if (Math.abs(data[i] - data[0]) + Math.abs(data[i + 1] - data[1]) + Math.abs(data[i + 2] - data[2]) > 40) {
          [x0, y0, x1, y1] = [Math.min(x0, x), Math.min(y0, y), Math.max(x1, x), Math.max(y1, y)];
        }
      }
    }
    return { ...tile, drawn: true, width: w, box: [x1 - x0 + 1, y1 - y0 + 1], digest };
  })));
}

/**
 * Pictures laid out on one sheet, `columns` to a row, each with its caption under it: PNG bytes.
 * `pictures` are `{ caption, png }`, the PNG as an array of bytes.
 */
export async function composeSheet(browser, pictures, columns) {
  const page = await browser.newPage();
  try {
    const sheet = await page.evaluate(async ({ pictures, columns }) => {
      const bitmaps = await Promise.all(pictures.map((p) => createImageBitmap(new Blob([new Uint8Array(p.png)], { type: 'image/png' }))));
      const [w, h] = [Math.max(...bitmaps.map((b) => b.width)), Math.max(...bitmaps.map((b) => b.height))];
      const label = pictures.some((p) => p.caption) ? 28 : 0;
      const rows = Math.ceil(bitmaps.length / columns);
      const c = new OffscreenCanvas(w * Math.min(columns, bitmaps.length), (h + label) * rows);
      const g = c.getContext('2d');
      g.fillStyle = '#f4f1ea';
      g.fillRect(0, 0, c.width, c.height);
      g.fillStyle = '#2b2824';
      g.font = '15px sans-serif';
      g.textAlign = 'center';
      bitmaps.forEach((b, i) => {
        const [x, y] = [(i % columns) * w, Math.floor(i / columns) * (h + label)];
        g.drawImage(b, x, y);
        g.fillText(pictures[i].caption, x + w / 2, y + h + 19);
      });
      const blob = await c.convertToBlob({ type: 'image/png' });
      return [...new Uint8Array(await blob.arrayBuffer())];
    }, { pictures, columns });
    return Buffer.from(sheet);
  } finally {
    await page.close();
  }
}

/** Calls one of the wasm module's test-only hooks (src/web/debug.rs) in the page. */
export function hook(page, name, ...args) {
  return page.evaluate(async ([name, args]) => {
    const module = await import(new URL('pkg/seashells.js', document.baseURI).href);
    module[name](...args);
  }, [name, args]);
}

/**
 * A browser for each backend, opened before a file's tests and closed after them: `sessions`
 * by backend, and `openOn(backend, fragment, viewport)`, which opens the page at `#fragment`.
 */
export function browsers(backends) {
  const sessions = {};
  before(async () => {
    for (const backend of backends) sessions[backend] = await session(backend);
  });
  after(async () => {
    for (const s of Object.values(sessions)) await s.close();
  });
  const openOn = (backend, fragment, viewport) => {
    const { browser, base } = sessions[backend];
    return open(browser, `${base}#${fragment}`, viewport);
  };
  return { sessions, openOn };
}
