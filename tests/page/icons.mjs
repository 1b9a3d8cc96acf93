// Writes the page's app icons (www/icon-192.png, www/icon-512.png, named by its manifest) from
// its favicon (www/favicon.svg), drawn by Chromium on the page's paper colour with room around
// it, as platforms that mask icons into circles or rounded squares want: `make icons`.
import { readFileSync } from 'node:fs';
import { launch } from './browser.mjs';

const www = new URL('../../www/', import.meta.url).pathname;
const svg = readFileSync(`${www}favicon.svg`).toString('base64');
const browser = await launch('WebGL2');
try {
  for (const size of [192, 512]) {
    const page = await browser.newPage({ viewport: { width: size, height: size } });
    await page.setContent(`<body style="margin:0;background:#f4f1ea;display:grid;place-items:center;height:100vh">
      <img src="data:image/svg+xml;base64,${svg}" style="width:70%;height:70%"></body>`);
    await page.screenshot({ path: `${www}icon-${size}.png` });
    await page.close();
  }
} finally {
  await browser.close();
}
