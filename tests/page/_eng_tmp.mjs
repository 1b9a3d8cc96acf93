import { writeFileSync } from 'node:fs';
import { launchEngine } from './engines.mjs';
import { serve } from './serve.mjs';
const [engine, link, out] = process.argv.slice(2);
const server = await serve(new URL('../../www/', import.meta.url).pathname);
const base = `http://127.0.0.1:${server.address().port}/`;
const browser = await launchEngine(engine);
try {
  const page = await browser.newPage({ width: 900, height: 700 });
  await page.goto(`${base}#${link}`);
  const s = await page.waitForState(['growing', 'grown', 'error'], 300_000);
  if (s.state === 'growing') await page.click('#finish');
  await page.waitForState(['grown', 'error'], 600_000);
  await new Promise((r) => setTimeout(r, 2000));
  writeFileSync(out, await page.shot('#shell'));
  console.log(out, JSON.stringify(await page.errors()));
} finally { await browser.close(); server.close(); }
