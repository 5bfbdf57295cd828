import { startApp } from './app/app';

try {
  startApp();
} catch (e) {
  const status = document.getElementById('status');
  if (status) {
    status.dataset.state = 'error';
    status.textContent = `The app could not start: ${e instanceof Error ? e.message : String(e)}. Reload the page; if it persists, this browser may lack WebGL2 or WebAssembly.`;
  }
  console.error(e);
}
