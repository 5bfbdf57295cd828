// The bundled command line (build/cli/hairsketch.mjs, what `npx hairsketch` runs). CLI tests call
// its main in-process, so what they check is the bundle, not only the sources it is built from.
import { existsSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';

export const CLI_BUNDLE = fileURLToPath(new URL('../../build/cli/hairsketch.mjs', import.meta.url));

/** The bundled command line's exports (those of web/cli/main.ts). */
export async function bundledCli(): Promise<typeof import('../../web/cli/main')> {
  if (!existsSync(CLI_BUNDLE))
    throw new Error(`${CLI_BUNDLE} is missing: build it with npm run build:cli`);
  return import(/* @vite-ignore */ pathToFileURL(CLI_BUNDLE).href);
}
