// The benchmark's figures of one core (`benchmark_one_core`: pattern rates, the Murex
// polygonized whole) on a worker's thread, posted back as text: tests/page/bench-workers.mjs
// compares them with the same figures on the page's thread, in the same run.
import init, { benchmark_one_core as oneCore } from './pkg/seashells.js';

await init();
self.postMessage(oneCore());
