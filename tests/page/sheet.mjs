// Pictures to look at, not a test: grows each link to its end in headless Chromium (WebGL2),
// photographs the canvas alone, and lays the pictures out on one sheet, a caption under each,
// `columns` to a row. The pictures of the README and docs/ are made with it.
//
//     node tests/page/sheet.mjs OUT.png COLUMNS SIZE 'caption|v=1&preset=…' …
import { writeFileSync } from 'node:fs';
import { session, open, waitForState } from './browser.mjs';

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
  const page = await s.browser.newPage();
  const sheet = await page.evaluate(async ({ pictures, columns }) => {
    const bitmaps = await Promise.all(pictures.map((p) => createImageBitmap(new Blob([new Uint8Array(p.png)], { type: 'image/png' }))));
    const [w, h] = [Math.max(...bitmaps.map((b) => b.width)), Math.max(...bitmaps.map((b) => b.height))];
    const label = pictures.some((p) => p.caption) ? 28 : 0;
    const rows = Math.ceil(bitmaps.length / columns);
    const c = new OffscreenCanvas(w * Math.min(columns, bitmaps.length), (h + label) * rows);
    const g = c.getContext('2d');
    g.fillStyle = '#f4f1ea';
    g.fillRect(0, 0, c.width, c.height);
    g.fillStyle = '#2b2824';
    g.font = '15px sans-serif';
    g.textAlign = 'center';
    bitmaps.forEach((b, i) => {
      const [x, y] = [(i % columns) * w, Math.floor(i / columns) * (h + label)];
      g.drawImage(b, x, y);
      g.fillText(pictures[i].caption, x + w / 2, y + h + 19);
    });
    const blob = await c.convertToBlob({ type: 'image/png' });
    return [...new Uint8Array(await blob.arrayBuffer())];
  }, { pictures, columns: Number(columns) });
  writeFileSync(out, Buffer.from(sheet));
  console.log(out);
} finally {
  await s.close();
}
