// Loads the WebAssembly module and starts it; if even that fails, says so on the page.
import init, { start } from './pkg/seashells.js';

try {
  await init();
  await start();
} catch (error) {
  const message = document.getElementById('message');
  message.textContent = `The shell generator could not start: ${error}`;
  message.hidden = false;
  document.body.dataset.state = 'error';
}
