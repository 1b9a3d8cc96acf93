// Pictures to look at, not a test: grows the shell of a link to its end in headless Chromium
// (WebGL2) and photographs the canvas alone from four sides, dragging the camera round between.
//
//     node tests/page/views.mjs 'v=1&preset=murex-cabritii' DIR   (make screenshots)
import { mkdirSync } from 'node:fs';
import { session, open, waitForState } from './browser.mjs';

const [link = 'v=1&preset=murex-cabritii', dir = 'tests/page/screenshots/views'] = process.argv.slice(2);
mkdirSync(dir, { recursive: true });
const s = await session('WebGL2');
try {
  const { page, errors } = await open(s.browser, `${s.base}#${link}&growth.speed=400`, { width: 700, height: 700 });
  const state = await waitForState(page, ['grown', 'error'], 600_000);
  if (state.state !== 'grown') throw new Error(`the shell did not grow: ${await page.textContent('#message')}`);
  const canvas = page.locator('#shell');
  const box = await canvas.boundingBox();
  const [x, y] = [box.x + box.width / 2, box.y + box.height / 2];
  await page.evaluate(() => {
    for (const e of document.querySelectorAll('body *')) e.style.visibility = 'hidden';
    document.getElementById('shell').style.visibility = 'visible';
  });
  for (let side = 0; side < 4; side++) {
    await page.waitForTimeout(400);
    const file = `${dir}/side-${side}.png`;
    await canvas.screenshot({ path: file });
    console.log(file);
    await page.mouse.move(x, y);
    await page.mouse.down();
    await page.mouse.move(x + 90, y, { steps: 10 });
    await page.mouse.up();
  }
  if (errors.length) throw new Error(errors.join('\n'));
} finally {
  await s.close();
}
