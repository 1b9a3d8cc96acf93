// The benchmark in the browser: the same core code as `seashells bench`, compiled to wasm and
// timed with performance.now() in headless Chromium, on a viewer whose shell has finished
// growing (so the page draws nothing meanwhile). Prints figures; asserts nothing.
import { serve } from './serve.mjs';
import { launch, open, waitForState } from './browser.mjs';

const server = await serve(new URL('../../www/', import.meta.url).pathname);
const browser = await launch('WebGL2');
try {
  const { page } = await open(browser, `http://127.0.0.1:${server.address().port}/#v=1&preset=turbinate&growth.speed=200`);
  await waitForState(page, ['grown']);
  const report = await page.evaluate(async () => (await import('./pkg/seashells.js')).benchmark());
  console.log(`wasm (Chromium ${browser.version()})\n${report}`);
} finally {
  await browser.close();
  server.close();
}
