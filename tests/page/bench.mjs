// The benchmark in the browser: the same core code as `seashells bench`, compiled to wasm and
// timed with performance.now() in headless Chromium. Prints figures; asserts nothing.
import { serve } from './serve.mjs';
import { launch, open, waitForState } from './browser.mjs';

const server = await serve(new URL('../../www/', import.meta.url).pathname);
const browser = await launch('WebGL2');
try {
  const { page } = await open(browser, `http://127.0.0.1:${server.address().port}/`);
  await waitForState(page, ['growing', 'grown']);
  const report = await page.evaluate(async () => (await import('./pkg/seashells.js')).benchmark());
  console.log(`wasm (Chromium ${browser.version()})\n${report}`);
} finally {
  await browser.close();
  server.close();
}
