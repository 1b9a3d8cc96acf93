// Pictures to look at, not a test: grows each link to its end in headless Chromium (WebGL2),
// photographs the canvas alone, and lays the pictures out on one sheet, a caption under each,
// `columns` to a row. The pictures of the README and docs/ are made with it.
//
//     node tests/page/sheet.mjs OUT.png COLUMNS SIZE 'caption|v=1&preset=…' …
import { writeFileSync } from 'node:fs';
import { composeSheet, session, open, waitForState } from './browser.mjs';

const [out, columns = '3', size = '360', ...cells] = process.argv.slice(2);
if (!out || cells.length === 0) {
  throw new Error("usage: node tests/page/sheet.mjs OUT.png COLUMNS SIZE 'caption|link' …");
}
const side = Number(size);
const s = await session('WebGL2');
try {
  const pictures = [];
  for (const cell of cells) {
    const [caption, link] = cell.includes('|') ? cell.split('|') : ['', cell];
    const { page, errors } = await open(s.browser, `${s.base}#${link}`, { width: side, height: side });
    const state = await waitForState(page, ['grown', 'error'], 600_000);
    if (state.state !== 'grown') throw new Error(`${link} did not grow: ${await page.textContent('#message')}`);
    await page.evaluate(() => {
      for (const e of document.querySelectorAll('#viewer *')) e.style.visibility = 'hidden';
      for (const e of document.querySelectorAll('#shell, #panes, #panes *')) e.style.visibility = 'visible';
      document.querySelector('.viewer').style.gridTemplateColumns = '1fr';
      for (const e of document.querySelectorAll('.panel, .planar')) e.style.display = 'none';
    });
    await page.waitForTimeout(400);
    pictures.push({ caption, png: [...await page.locator('#shell').screenshot()] });
    if (errors.length) throw new Error(errors.join('\n'));
    await page.close();
  }
  const sheet = await composeSheet(s.browser, pictures, Number(columns));
  writeFileSync(out, Buffer.from(sheet));
  console.log(out);
} finally {
  await s.close();
}
