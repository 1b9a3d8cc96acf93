// Opens the page (www/, or the folder WWW names) at LINK RUNS times in ENGINE (default webkit),
// each in a fresh window of one browser, and counts the loads that started growing within 60 s
// and those that did not, printing what each of those showed (its state and its errors: a
// WebAssembly trap at start was seen so, see docs/browsers.md). Run under xvfb-run:
//   RUNS=100 xvfb-run -a -s '-screen 0 1600x1200x24' node tests/page/repro/start.mjs
import { launchEngine } from '../engines.mjs';
import { serve } from '../serve.mjs';

const RUNS = Number(process.env.RUNS ?? 30);
const ENGINE = process.env.ENGINE ?? 'webkit';
const LINK = process.env.LINK ?? 'v=1&preset=oliva-porphyria&growth.speed=200';
const root = process.env.WWW ?? new URL('../../../www/', import.meta.url).pathname;
const server = await serve(root);
const url = `http://127.0.0.1:${server.address().port}/#${LINK}`;
const browser = await launchEngine(ENGINE);
const counts = { started: 0, stalled: 0, crashed: 0 };
for (let run = 1; run <= RUNS; run += 1) {
  const page = await browser.newPage({ width: 900, height: 700 });
  try {
    await page.goto(url);
    await page.waitForState(['growing', 'grown'], 60_000);
    counts.started += 1;
  } catch (e) {
    const crashed = /crash or hang/.test(e.message);
    counts[crashed ? 'crashed' : 'stalled'] += 1;
    console.log(`run ${run}: ${String(e.message).slice(0, 800)}`);
  }
  await page.close().catch(() => {});
}
console.log(`${ENGINE} ${browser.version} ${root}: ${RUNS} loads, ${counts.started} started, ${counts.stalled} stalled, ${counts.crashed} crashed or hung`);
await browser.close();
server.close();
