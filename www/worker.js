// A worker of the page's pool: loads the same WebAssembly module as the page and answers the
// page's requests (bytes in a transferred ArrayBuffer) with replies it transfers back. Requests
// that come while the module loads wait for it. An error thrown here reaches the page as the
// worker's `error` event: the page replaces the worker and has its work done again.
//
// Test-only: a worker the page names `seashells-throw` (the page's `crash-workers=N` debug
// switch in its address, used by tests/page/workers.test.mjs) throws on its first request,
// as a worker that fails would; one named `seashells-hang` (`hang-workers=N`) spins forever on
// its first request without answering, as a worker caught in an endless loop would, until the
// page finds it out and terminates it.
import init, { WorkerHost } from './pkg/seashells.js';

const early = [];
self.onmessage = (event) => early.push(event.data);
await init();
const host = new WorkerHost();
let failOnFirst = self.name;
const answer = (data) => {
  if (failOnFirst === 'seashells-throw') {
    failOnFirst = '';
    throw new Error('this worker was made to throw (test-only crash-workers switch)');
  }
  if (failOnFirst === 'seashells-hang') {
    for (;;) {
      // Never answers (test-only hang-workers switch).
    }
  }
  failOnFirst = '';
  for (const reply of host.handle(new Uint8Array(data))) {
    self.postMessage(reply, [reply]);
  }
};
self.onmessage = (event) => answer(event.data);
for (const data of early.splice(0)) {
  answer(data);
}
