// Pictures to look at, not a test: grows the shell of a link to its end in headless Chromium
// (WebGL2) and photographs the canvas alone from four sides, a quarter turn apart (a drag across
// half the view's height turns the camera by 90°, src/view/camera.rs `orbit`) with the camera
// level (the page's first view looks down a little, `DEFAULT_PITCH`), starting from the side
// the opening faces (the shape's `front`), so that the opening is seen head-on; then puts the
// four into one picture, `four-sides.png`. TURN (degrees added to the camera's yaw, 0 unless
// given) turns the first view further: the camera looks at the shell's centre in perspective,
// so an opening off to one side of it is seen head-on a little to that side of `front` (about
// 20° for the Murex presets at 700 px).
//
//     node tests/page/views.mjs 'v=1&preset=murex-cabritii' DIR [TITLE] [TURN]   (make screenshots)
import { mkdirSync, readFileSync } from 'node:fs';
import { session, open, waitForState } from './browser.mjs';

const [link = 'v=1&preset=murex-cabritii', dir = 'tests/page/screenshots/views', title = link, turn = '0'] =
  process.argv.slice(2);
mkdirSync(dir, { recursive: true });
const names = ['facing the opening', 'a quarter turn', 'from behind', 'three quarters'];
const s = await session('WebGL2');
try {
  const { page, errors } = await open(s.browser, `${s.base}#${link}`, { width: 700, height: 700 });
  // End grows it whole at once (the Finish control), its chunks shared by the workers.
  if ((await waitForState(page, ['growing', 'grown', 'error'], 300_000)).state === 'growing') {
    await page.click('#finish');
  }
  const state = await waitForState(page, ['grown', 'error'], 600_000);
  if (state.state !== 'grown') throw new Error(`the shell did not grow: ${await page.textContent('#message')}`);
  const canvas = page.locator('#shell');
  const box = await canvas.boundingBox();
  const [x, y] = [box.x + box.width / 2, box.y + box.height / 2];
  await page.evaluate(() => {
    for (const e of document.querySelectorAll('body *')) e.style.visibility = 'hidden';
    document.getElementById('shell').style.visibility = 'visible';
  });
  // The view may still change after `grown` (the finished shell's last reply, the camera
  // settling on its framing): wait for two pictures alike before turning it.
  let last;
  for (let i = 0; i < 40; i++) {
    const now = await canvas.screenshot();
    if (last && now.equals(last)) break;
    last = now;
    await page.waitForTimeout(500);
  }
  // Level: a drag up by a fraction f of the view's height lowers the camera by f·π radians;
  // the first view is raised by 0.2 (src/view/camera.rs `DEFAULT_PITCH`).
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x - (Number(turn) / 180) * box.height, y - (0.2 / Math.PI) * box.height, { steps: 4 });
  await page.mouse.up();
  const files = [];
  for (let side = 0; side < 4; side++) {
    await page.waitForTimeout(400);
    const file = `${dir}/side-${side}.png`;
    await canvas.screenshot({ path: file });
    files.push(file);
    console.log(file);
    await page.mouse.move(x, y);
    await page.mouse.down();
    await page.mouse.move(x + box.height / 2, y, { steps: 10 });
    await page.mouse.up();
  }
  if (errors.length) throw new Error(errors.join('\n'));
  const cells = files
    .map((f, i) => `<figure><img src="data:image/png;base64,${readFileSync(f).toString('base64')}">
      <figcaption>${names[i]}</figcaption></figure>`)
    .join('');
  // A blank page of its own: the shell's page forbids inline styles.
  const sheet = await s.browser.newPage({ viewport: { width: 720, height: 600 } });
  await sheet.setContent(`<style>
      body { margin: 0; background: #fff; font: 15px sans-serif; width: 720px; }
      h1 { font-size: 16px; margin: 8px 10px 4px; }
      main { display: grid; grid-template-columns: 1fr 1fr; }
      figure { margin: 0; text-align: center; } img { width: 350px; height: auto; }
      figcaption { margin-bottom: 4px; }
    </style><h1>${title}</h1><main>${cells}</main>`);
  await sheet.bringToFront();
  const file = `${dir}/four-sides.png`;
  // A second page of a busy headless browser is at times not painted yet: try again.
  for (let attempt = 1; ; attempt++) {
    try {
      await sheet.screenshot({ path: file, fullPage: true });
      break;
    } catch (e) {
      if (attempt === 5) throw e;
      await sheet.waitForTimeout(1000);
    }
  }
  console.log(file);
} finally {
  await s.close();
}
