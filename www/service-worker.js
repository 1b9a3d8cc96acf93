// The page's offline copy. On the first visit it keeps every file the page runs on (the page,
// its scripts, the WebAssembly module, the workers' scripts) in a cache named for this build
// (pkg/build.js, written by `make build` from the files' bytes) and for this copy's place (two
// copies of the page on one origin keep their own), and from then on serves those files from
// it, network or none: the page, its module and its workers come from one build. A new build is
// found when the browser checks this script and the build's id beside it (`main.js` asks it to
// bypass the HTTP cache for both); its files are kept in a cache of their own while the page
// goes on with the old one, and it takes over only when the page asks (its "Reload" under "A
// new version of this page is ready"), or once no page of the old one is open. Any other
// request (the README's pictures, a test's routes) goes to the network as it would without
// this worker.
importScripts('pkg/build.js');

const PLACE = `seashells ${self.registration.scope} `;
const CACHE = `${PLACE}${self.BUILD}`;
// The page is kept as the scope's root ('./'), which some hosts redirect index.html to.
const FILES = [
  './',
  'main.js',
  'style.css',
  'favicon.svg',
  'icon-192.png',
  'icon-512.png',
  'manifest.webmanifest',
  'worker.js',
  'drawing-worker.js',
  'pkg/build.js',
  'pkg/seashells.js',
  'pkg/seashells_bg.wasm',
];

/** The name a request has among FILES (the page itself for the scope's root), or null. */
function kept(request) {
  const scope = self.registration.scope;
  const url = new URL(request.url);
  url.search = '';
  url.hash = '';
  if (request.method !== 'GET' || !url.href.startsWith(scope)) return null;
  const path = url.href.slice(scope.length);
  const name = path === '' || path === 'index.html' ? './' : path;
  return FILES.includes(name) ? name : null;
}

self.addEventListener('install', (event) => {
  // Fetched past the browser's HTTP cache, so that the build kept is the build served.
  event.waitUntil(caches.open(CACHE).then((cache) => cache.addAll(FILES.map((f) => new Request(f, { cache: 'reload' })))));
});

self.addEventListener('activate', (event) => {
  event.waitUntil((async () => {
    for (const name of await caches.keys()) {
      if (name.startsWith(PLACE) && name !== CACHE) await caches.delete(name);
    }
    await self.clients.claim();
  })());
});

self.addEventListener('message', (event) => {
  if (event.data === 'take-over') self.skipWaiting();
});

self.addEventListener('fetch', (event) => {
  const name = kept(event.request);
  if (name === null) return;
  event.respondWith((async () => {
    const cache = await caches.open(CACHE);
    const kept = await cache.match(name);
    if (!kept) return fetch(event.request);
    // A response made anew takes the request's address: a worker started with the page's
    // query (`drawing-worker.js?workers=2`) still reads it from its own location.
    return new Response(kept.body, kept);
  })());
});
