// The benchmark, in one run on this machine: the core code natively (`seashells bench`), the
// same code compiled to wasm on the page www/bench.html (which draws nothing) in headless
// Chromium, and there beside it a plain JavaScript solver of eq 9 on the same sizes. Prints the
// figures, then the ratios wasm / native per pattern model and wasm / JavaScript for eq 9.
// Asserts nothing. Everything it prints is also written to docs/bench-figures.md, headed by
// the date, the commit and the machine, so the figures in the docs are this run's, never typed.
import { execFileSync } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { cpus, totalmem } from 'node:os';
import { session, waitForState } from './browser.mjs';

const root = new URL('../../', import.meta.url).pathname;
const printed = [];
const print = console.log;
console.log = (...args) => {
  printed.push(args.join(' '));
  print(...args);
};
const native = execFileSync(`${root}target/release/seashells`, ['bench'], { encoding: 'utf8' });
console.log(native);

const { browser, base, close } = await session('WebGL2');
let text;
let browserVersion;
try {
  const page = await browser.newPage();
  await page.goto(`${base}bench.html`);
  const { state } = await waitForState(page, ['done', 'error'], 30 * 60_000);
  text = await page.textContent('#report');
  browserVersion = browser.version();
  console.log(`(Chromium ${browserVersion})\n${text}`);
  if (state !== 'done') process.exitCode = 1;
} finally {
  await close();
}

/** The rates of "ID (model)  N M cell updates/s" lines of one section of a report. */
function rates(report) {
  const out = new Map();
  for (const line of report.split('\n')) {
    const m = line.match(/^(\S+ \([^)]*\))\s+([\d.]+) M cell updates\/s/);
    if (m) out.set(m[1], Number(m[2]));
  }
  return out;
}
const [wasmText, jsText = ''] = text.split('\nJavaScript\n');
const [nativeRates, wasmRates, jsRates] = [native, wasmText, jsText].map(rates);
console.log('ratios');
for (const [what, rate] of wasmRates) {
  const parts = [];
  if (nativeRates.has(what)) parts.push(`wasm / native ${(rate / nativeRates.get(what)).toFixed(2)}`);
  if (jsRates.has(what)) parts.push(`wasm / JavaScript ${(rate / jsRates.get(what)).toFixed(2)}`);
  console.log(`${what.padEnd(40)} ${parts.join('   ')}`);
}

// Growth off the page's thread: frame script time, finishing and the gallery, 1 vs W workers.
const { benchWorkers } = await import('./bench-workers.mjs');
await benchWorkers();

/** The commit measured, marked when the work tree differs from it. */
function commit() {
  try {
    const git = (...args) => execFileSync('git', ['-C', root, ...args], { encoding: 'utf8' }).trim();
    return `${git('rev-parse', '--short', 'HEAD')}${git('status', '--porcelain', '--untracked-files=no') ? ' with changes' : ''}`;
  } catch {
    return 'not a git checkout';
  }
}
const machine = `${cpus().length} × ${cpus()[0]?.model ?? 'unknown processor'}, ${(totalmem() / 2 ** 30).toFixed(0)} GiB`;
writeFileSync(`${root}docs/bench-figures.md`, `# The figures of the last \`make bench\`

Written by \`make bench\` (\`tests/page/bench.mjs\`), not by hand: run it again to bring them up to date.
What each figure measures, and what they have shown over time: [benchmarks.md](benchmarks.md).

- When: ${new Date().toISOString().replace(/\.\d+Z$/, 'Z')}
- Commit: ${commit()}
- Machine: ${machine}; Chromium ${browserVersion}

\`\`\`text
${printed.join('\n').trim()}
\`\`\`
`);
print(`wrote ${root}docs/bench-figures.md`);
