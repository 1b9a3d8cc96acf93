// Loads tests/page/repro/lost-context.html (WebGL2 alone, none of the project's code) RUNS
// times in ENGINE (default webkit), each in a fresh window, and counts the loads that ended
// "done", in an error of the page, or with the browser's web process crashed or hung. Run under
// xvfb-run for Firefox and WebKit (see docs/browsers.md):
//   RUNS=60 ENGINE=webkit xvfb-run -a -s '-screen 0 1600x1200x24' node tests/page/repro/lost-context.mjs
import { launchEngine } from '../engines.mjs';
import { serve } from '../serve.mjs';

const RUNS = Number(process.env.RUNS ?? 30);
const ENGINE = process.env.ENGINE ?? 'webkit';
const server = await serve(new URL('./', import.meta.url).pathname);
const url = `http://127.0.0.1:${server.address().port}/lost-context.html`;
const browser = await launchEngine(ENGINE);
const counts = { done: 0, error: 0, crashed: 0 };
for (let run = 1; run <= RUNS; run += 1) {
  const page = await browser.newPage({ width: 1000, height: 1000 });
  try {
    await page.goto(url);
    await page.waitFor(() => document.title !== 'loading', null, 60_000, 'the page to end');
    const title = await page.evaluate(() => document.title);
    counts[title === 'done' ? 'done' : 'error'] += 1;
    if (title !== 'done') console.log(`run ${run}: ${title}`);
  } catch (e) {
    counts.crashed += 1;
    console.log(`run ${run}: ${String(e.message).slice(0, 600)}`);
  }
  await page.close().catch(() => {});
}
console.log(`${ENGINE} ${browser.version}: ${RUNS} loads, ${counts.done} done, ${counts.error} errors of the page, ${counts.crashed} crashed or hung`);
await browser.close();
server.close();
