// The baseline's worker (see index.html): answers each request after 24 ms of work, as the
// seashells page's growth worker does, with a reply of 1 kB.
onmessage = () => {
  const start = performance.now();
  while (performance.now() - start < 24) { /* work */ }
  const reply = new Uint8Array(1024).buffer;
  postMessage(reply, [reply]);
};
