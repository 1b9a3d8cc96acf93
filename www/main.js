// Loads the WebAssembly module and starts it; if even that fails, says so on the page. The
// button that a panic's message offers (#reload) is wired here, in JavaScript, because after a
// panic the WebAssembly module can no longer run: it reloads the link as it stands.
import init, { start } from './pkg/seashells.js';

document.getElementById('reload')?.addEventListener('click', () => window.location.reload());

try {
  await init();
  await start();
} catch (error) {
  const message = document.getElementById('message');
  message.textContent = `The shell generator could not start: ${error}`;
  message.hidden = false;
  document.body.dataset.state = 'error';
}
