// The benchmark page: the wasm benchmark, then the JavaScript reference solver of eq 9 timed
// the same way (median of five timings of at least 0.25 s each), on a page that draws nothing.
import init, { benchmark, preset_pattern as presetPattern } from './pkg/seashells.js';
import { eq9 } from './eq9-reference.js';

const LEAST_MS = 250;
const REPEATS = 5;
const REFERENCE = 'oliva-porphyria';

/** Median milliseconds of one call of `work`, and the spread of the timings over it. */
function timed(work) {
  const run = (calls) => {
    const start = performance.now();
    for (let i = 0; i < calls; i++) work();
    return performance.now() - start;
  };
  let calls = 1;
  for (;;) {
    const spent = run(calls);
    if (spent >= LEAST_MS / 4) {
      calls = Math.max(1, Math.ceil((calls * LEAST_MS) / spent));
      break;
    }
    calls *= 4;
  }
  const times = Array.from({ length: REPEATS }, () => run(calls) / calls).sort((x, y) => x - y);
  const median = times[REPEATS >> 1];
  return { median, spread: (times[REPEATS - 1] - times[0]) / median };
}

const report = document.getElementById('report');
try {
  await init();
  const wasm = benchmark();
  const spec = JSON.parse(presetPattern(REFERENCE));
  const k = Math.max(spec.refinement, 1);
  const [cells, steps] = [spec.cells * k, spec.iterations * k * k];
  const solver = eq9(spec.model, cells, 1 / (k * k));
  const { median, spread } = timed(() => solver.advance(steps));
  if (!solver.activator().every(Number.isFinite)) throw new Error('the JavaScript eq 9 diverged');
  const rate = (cells * steps) / median / 1e3;
  const line = `${REFERENCE} (eq 9)  ${rate.toFixed(3)} M cell updates/s  (spread ${(spread * 100).toFixed(1)} %)`;
  report.textContent = `wasm\n${wasm}\nJavaScript\n${line}\n`;
  document.body.dataset.state = 'done';
} catch (error) {
  report.textContent = `The benchmark failed: ${error}`;
  document.body.dataset.state = 'error';
}
