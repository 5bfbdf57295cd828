import { startEmbed } from './embed/embedApp';

startEmbed().catch((e: unknown) => {
  const status = document.getElementById('status');
  if (status) {
    status.dataset.state = 'error';
    status.textContent = `The viewer could not start: ${e instanceof Error ? e.message : String(e)}. This browser may lack WebGL2 or WebAssembly.`;
  }
  console.error(e);
});
