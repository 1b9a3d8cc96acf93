// Benchmarks of growth off the page's thread (issue 30), each beside its baseline in the same
// run: the page's own script time per frame while the Murex grows (99th percentile; the page
// on its own thread, `workers=0`, is how the page worked before), the Murex finished at 256³
// with 1 and W workers, and every gallery picture with 1 and W workers. W is the pool this
// machine gets (`navigator.hardwareConcurrency − 1`, at least 1) and 2 besides, so that the
// sharing shows even on a 2-core machine. Prints figures; asserts nothing.
import { open, session, waitForState } from './browser.mjs';

/** Wraps requestAnimationFrame before the page loads, to time each frame's callback. */
function timeFrames() {
  window.__frameMs = [];
  const raf = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (callback) => raf((t) => {
    const start = performance.now();
    try {
      callback(t);
    } finally {
      window.__frameMs.push(performance.now() - start);
    }
  });
}

const percentile = (xs, p) => {
  const sorted = [...xs].sort((a, b) => a - b);
  return sorted[Math.min(sorted.length - 1, Math.floor((p / 100) * sorted.length))];
};

/** Script milliseconds per frame (p50, p99) while the Murex grows for `seconds`. */
async function frameScript(browser, base, workers, seconds = 20) {
  const page = await browser.newPage({ viewport: { width: 900, height: 700 } });
  await page.addInitScript(timeFrames);
  await page.goto(`${base}?workers=${workers}#v=1&preset=murex-cabritii`);
  await waitForState(page, ['growing'], 300_000);
  await page.evaluate(() => { window.__frameMs = []; });
  await page.waitForTimeout(seconds * 1000);
  const ms = await page.evaluate(() => window.__frameMs);
  const rows = await page.evaluate(() => document.body.dataset.rows);
  await page.close();
  return { frames: ms.length, p50: percentile(ms, 50), p99: percentile(ms, 99), rows };
}

/** Seconds from End to the Murex grown whole at 256³ (`data-growth` done). */
async function murexFinish(browser, base, workers) {
  const { page } = await open(browser, `${base}?workers=${workers}#v=1&preset=murex-cabritii&form.resolution=256&growth.speed=0.05`);
  await waitForState(page, ['growing'], 300_000);
  const seconds = await page.evaluate(() => new Promise((resolve) => {
    const start = performance.now();
    const watch = new MutationObserver(() => {
      if (document.body.dataset.growth === 'done') {
        watch.disconnect();
        resolve((performance.now() - start) / 1000);
      }
    });
    watch.observe(document.body, { attributes: true });
    document.getElementById('finish').click();
  }));
  await page.close();
  return seconds;
}

/** Seconds from opening the gallery to every picture drawn. */
async function gallery(browser, base, workers) {
  const page = await browser.newPage({ viewport: { width: 900, height: 700 } });
  const start = Date.now();
  await page.goto(`${base}?workers=${workers}`);
  await page.waitForFunction(() => document.body.dataset.pictures === 'done', null, { timeout: 600_000 });
  const seconds = (Date.now() - start) / 1000;
  await page.close();
  return seconds;
}

export async function benchWorkers() {
  const { browser, base, close } = await session('WebGL2');
  try {
    const page = await browser.newPage();
    await page.goto(base);
    const cores = await page.evaluate(() => navigator.hardwareConcurrency);
    await page.close();
    const pool = Math.min(8, Math.max(1, cores - 1));
    const sizes = [...new Set([1, pool, 2])];
    console.log(`workers (Chromium ${browser.version()}, ${cores} logical processors, pool of ${pool})`);
    for (const workers of [0, 1]) {
      const f = await frameScript(browser, base, workers);
      console.log(`Murex growing, page script per frame, workers=${workers}: p50 ${f.p50.toFixed(2)} ms, p99 ${f.p99.toFixed(2)} ms over ${f.frames} frames (row ${f.rows} after 20 s)`);
    }
    const finish = {};
    for (const workers of sizes) {
      finish[workers] = await murexFinish(browser, base, workers);
      console.log(`Murex finish at 256³, ${workers} worker(s): ${finish[workers].toFixed(2)} s (× ${(finish[1] / finish[workers]).toFixed(2)} of one worker)`);
    }
    const pictures = {};
    for (const workers of [0, ...sizes]) {
      pictures[workers] = await gallery(browser, base, workers);
      const ratio = workers === 0 ? '' : ` (× ${(pictures[0] / pictures[workers]).toFixed(2)} of the page's own thread)`;
      console.log(`all gallery pictures, workers=${workers}: ${pictures[workers].toFixed(2)} s${ratio}`);
    }
  } finally {
    await close();
  }
}

if (import.meta.url === `file://${process.argv[1]}`) {
  await benchWorkers();
}
