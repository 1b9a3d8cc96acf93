// Measures how deep the WebAssembly module's own stack goes on the page's thread, phase by
// phase, in each ENGINE (default: all three; Chromium and Firefox are told to draw the view on
// the page's thread too, as WebKit does). The module's stack is the first MiB of its linear
// memory (the stack pointer starts at 1,048,576 and the data follow it; see docs/browsers.md):
// between two of the page's tasks none of it is in use, so the script fills it with a marker,
// lets the page do one thing, and finds the lowest byte written since. A frame that reserves
// more than it writes is counted only as far as it wrote, so the figure is a lower bound.
// Run under xvfb-run after `make build`:
//   xvfb-run -a -s '-screen 0 1600x1200x24' node tests/page/repro/stack-depth.mjs
import { launchEngine } from '../engines.mjs';
import { serve } from '../serve.mjs';

const ENGINES = (process.env.ENGINES ?? 'webkit,chromium,firefox').split(',');
const STACK = 1 << 20;
const root = process.env.WWW ?? new URL('../../../www/', import.meta.url).pathname;
const server = await serve(root);
const base = `http://127.0.0.1:${server.address().port}/`;

/** Fills the stack's unused bytes with the marker (in the page). */
const paint = async (top) => {
  const module = await import(new URL('pkg/seashells.js', document.baseURI).href);
  const wasm = await module.default();
  new Uint8Array(wasm.memory.buffer).fill(0xa5, 16, top);
  return true;
};

/** The bytes of the stack written since [`paint`] (in the page). */
const deepest = async (top) => {
  const module = await import(new URL('pkg/seashells.js', document.baseURI).href);
  const wasm = await module.default();
  const bytes = new Uint8Array(wasm.memory.buffer);
  let low = 16;
  while (low < top && bytes[low] === 0xa5) low += 1;
  return top - low;
};

const kib = (n) => `${(n / 1024).toFixed(1)} KiB`;

for (const engine of ENGINES) {
  const browser = await launchEngine(engine);
  const query = engine === 'webkit' ? '' : '?view=page';
  const page = await browser.newPage({ width: 1000, height: 800 });
  const measure = async (what, act) => {
    await page.evaluate(paint, STACK);
    await act();
    console.log(`${engine}: ${what}: ${kib(await page.evaluate(deepest, STACK))} of ${kib(STACK)}`);
  };
  try {
    await page.goto(`${base}${query}#`);
    await page.waitFor(() => document.body.dataset.pictures === 'done', null, 600_000, 'the gallery drawn');
    await measure('a shell opened from the gallery and grown (the view opened on the page)', async () => {
      await page.evaluate(() => { location.hash = '#v=1&preset=oliva-porphyria&growth.speed=200'; });
      await page.waitForState(['grown'], 600_000);
    });
    await measure('breeding\'s first generation drawn', async () => {
      await page.evaluate(() => { location.hash = '#v=1&preset=turbinate&breed=0.4'; });
      await page.waitFor(() => document.body.dataset.breed === 'whole', null, 600_000, 'every offspring drawn');
    });
    await measure('an offspring chosen and the next generation drawn', async () => {
      await page.click('#breed-grid .tile:nth-child(1)');
      await page.waitFor(() => /Generation 2/.test(document.getElementById('breed-status').textContent)
        && document.body.dataset.breed === 'whole', null, 600_000, 'the next generation drawn');
    });
    await measure('the Murex grown', async () => {
      await page.evaluate(() => { location.hash = '#v=1&preset=murex-cabritii&growth.speed=200'; });
      await page.waitForState(['grown'], 600_000);
    });
    console.log(`${engine}: errors: ${JSON.stringify(await page.errors())}`);
  } catch (e) {
    console.log(`${engine}: ${String(e.message).slice(0, 800)}`);
  }
  await page.close().catch(() => {});
  await browser.close();
}
server.close();
