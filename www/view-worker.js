// The worker that draws the page's main view: loads the same WebAssembly module as the page,
// and hands its messages to the module's drawing worker (web/view_worker.rs), which is given
// the page's canvas as an OffscreenCanvas and runs the viewer and its own pool of workers.
// Messages that come while the module loads wait for it.
import init, { view_worker_start } from './pkg/seashells.js';

const early = [];
self.onmessage = (event) => early.push(event);
await init();
view_worker_start();
for (const event of early.splice(0)) {
  self.onmessage(event);
}
