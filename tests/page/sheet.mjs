// Pictures to look at, not a test: grows each link to its end in headless Chromium (WebGL2),
// photographs the canvas alone, and lays the pictures out on one sheet, a caption under each,
// `columns` to a row. The pictures of the README and docs/ are made with it.
//
//     node tests/page/sheet.mjs OUT.png COLUMNS SIZE 'caption|v=1&preset=…' …
//
// ZOOM (1 unless given) draws each shell in a view ZOOM times as large and keeps its middle
// SIZE pixels: a shell whose long spines keep it small in its frame is seen larger.
import { writeFileSync } from 'node:fs';
import { composeSheet, session, open, waitForState } from './browser.mjs';

const [out, columns = '3', size = '360', ...cells] = process.argv.slice(2);
if (!out || cells.length === 0) {
  throw new Error("usage: node tests/page/sheet.mjs OUT.png COLUMNS SIZE 'caption|link' …");
}
const side = Number(size);
const zoom = Number(process.env.ZOOM ?? 1);
const s = await session('WebGL2');
try {
  const pictures = [];
  for (const cell of cells) {
    const [caption, link] = cell.includes('|') ? cell.split('|') : ['', cell];
    const view = Math.round(side * zoom);
    const { page, errors } = await open(s.browser, `${s.base}#${link}`, { width: view, height: view });
    // End grows it whole at once (the Finish control), as a fine Murex needs.
    if ((await waitForState(page, ['growing', 'grown', 'error'], 300_000)).state === 'growing') {
      await page.click('#finish');
    }
    const state = await waitForState(page, ['grown', 'error'], 600_000);
    if (state.state !== 'grown') throw new Error(`${link} did not grow: ${await page.textContent('#message')}`);
    await page.evaluate(() => {
      for (const e of document.querySelectorAll('#viewer *')) e.style.visibility = 'hidden';
      for (const e of document.querySelectorAll('#shell, #panes, #panes *')) e.style.visibility = 'visible';
      document.querySelector('.viewer').style.gridTemplateColumns = '1fr';
      for (const e of document.querySelectorAll('.panel, .planar')) e.style.display = 'none';
    });
    await page.waitForTimeout(400);
    const canvas = page.locator('#shell');
    let png;
    if (zoom > 1) {
      const box = await canvas.boundingBox();
      const [width, height] = [Math.min(side, box.width), Math.min(side, box.height)];
      const clip = { x: box.x + (box.width - width) / 2, y: box.y + (box.height - height) / 2, width, height };
      png = await page.screenshot({ clip });
    } else {
      png = await canvas.screenshot();
    }
    pictures.push({ caption, png: [...png] });
    if (errors.length) throw new Error(errors.join('\n'));
    await page.close();
  }
  const sheet = await composeSheet(s.browser, pictures, Number(columns));
  writeFileSync(out, Buffer.from(sheet));
  console.log(out);
} finally {
  await s.close();
}
