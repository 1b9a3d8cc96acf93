// The worker that draws the page's main view: loads the same WebAssembly module as the page,
// and hands its messages to the module's drawing worker (web/drawing_worker.rs), which is given
// the page's canvas as an OffscreenCanvas and runs the viewer and its own pool of workers.
// Messages that come while the module loads wait for it.
//
// Test-only (tests/page/survive.test.mjs), from the page's query, which the worker's address
// carries: `stall-view` makes every frame the worker hands to the GPU look unfinished forever
// (a WebGL fence never signalled), as a context that opens but never presents would.
import init, { drawing_worker_start } from './pkg/seashells.js';

if (new URLSearchParams(self.location.search).has('stall-view')) {
  const UNSIGNALED = 0x9118;
  WebGL2RenderingContext.prototype.getSyncParameter = () => UNSIGNALED;
}

const early = [];
self.onmessage = (event) => early.push(event);
await init();
drawing_worker_start();
for (const event of early.splice(0)) {
  self.onmessage(event);
}
