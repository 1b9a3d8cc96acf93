// Loads the WebAssembly module and starts it; if even that fails, says so on the page. The
// button that a panic's message offers (#reload) is wired here, in JavaScript, because after a
// panic the WebAssembly module can no longer run: it reloads the link as it stands.
import init, { start } from './pkg/seashells.js';

document.getElementById('reload')?.addEventListener('click', () => window.location.reload());

/**
 * Registers the page's offline copy (service-worker.js) and says how it stands on <body
 * data-offline>: "ready" once the copy is kept and serves this page (after that the page works
 * with the network gone), "update" when a newer build is kept and waiting, which the notice
 * #update offers to load.
 * Where the browser keeps no offline copy (no service workers, a page not served over HTTPS or
 * from this machine) the page works as before, online, and says why on the console.
 */
function keepOffline() {
  if (!('serviceWorker' in navigator)) {
    console.info('This browser keeps no offline copy of the page (no service workers here).');
    return;
  }
  const body = document.body;
  const ready = () => { if (navigator.serviceWorker.controller && body.dataset.offline !== 'update') body.dataset.offline = 'ready'; };
  // A worker waits as an update only beside an active one: a first visit's worker passes through
  // "installed" too, and Firefox may tell the page so after that worker already controls it.
  const waiting = (registration) => {
    if (!registration.waiting || !registration.active || !navigator.serviceWorker.controller) return;
    body.dataset.offline = 'update';
    const notice = document.getElementById('update');
    notice.hidden = false;
    document.getElementById('update-reload').onclick = () => registration.waiting?.postMessage('take-over');
  };
  // Another build took over a page that ran one already (asked for here or in another tab):
  // this page reloads into it, rather than run on with the old build's module beside the new
  // build's workers. A first visit's page, uncontrolled until its copy is kept, is taken over
  // by the build it was served.
  const ranOne = navigator.serviceWorker.controller !== null;
  let reloading = false;
  navigator.serviceWorker.addEventListener('controllerchange', () => {
    if ((ranOne || body.dataset.offline === 'update') && !reloading) {
      reloading = true;
      window.location.reload();
      return;
    }
    ready();
  });
  // The browser checks the worker and the build's id beside it past its HTTP cache, so that a
  // new build is found on the next visit whatever the host's caching.
  navigator.serviceWorker.register('service-worker.js', { updateViaCache: 'none' }).then((registration) => {
    ready();
    waiting(registration);
    registration.addEventListener('updatefound', () => {
      const installing = registration.installing;
      const update = registration.active !== null;
      installing?.addEventListener('statechange', () => {
        if (installing.state === 'installed' && update) waiting(registration);
        if (installing.state === 'activated') ready();
      });
    });
  }).catch((error) => console.info(`No offline copy of the page is kept: ${error}`));
}

try {
  await init();
  await start();
} catch (error) {
  const message = document.getElementById('message');
  message.textContent = `The shell generator could not start: ${error}`;
  message.hidden = false;
  document.body.dataset.state = 'error';
}
// Once the page runs (its module fetched), so that a first visit does not fetch it twice at once.
keepOffline();
