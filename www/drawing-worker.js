// The worker that draws the page's main view: loads the same WebAssembly module as the page,
// and hands its messages to the module's drawing worker (web/drawing_worker.rs), which is given
// the page's canvas as an OffscreenCanvas and runs the viewer and its own pool of workers.
// Messages that come while the module loads wait for it.
//
// Test-only (tests/page/survive.test.mjs), from the page's query, which the worker's address
// carries: `hang-view` makes the worker spin forever on the page's first message, before it
// opens a renderer, as a worker caught in an endless loop would; `stall-view` makes every frame
// it hands to the GPU look unfinished forever (a WebGL fence never signalled), as a context that
// opens but never presents would.
import init, { drawing_worker_start } from './pkg/seashells.js';

const query = new URLSearchParams(self.location.search);
if (query.has('stall-view')) {
  const UNSIGNALED = 0x9118;
  WebGL2RenderingContext.prototype.getSyncParameter = () => UNSIGNALED;
}

const early = [];
self.onmessage = (event) => early.push(event);
if (query.has('hang-view')) {
  self.onmessage = () => {
    for (;;) {
      // Never answers (test-only hang-view switch).
    }
  };
} else {
  await init();
  drawing_worker_start();
  for (const event of early.splice(0)) {
    self.onmessage(event);
  }
}
