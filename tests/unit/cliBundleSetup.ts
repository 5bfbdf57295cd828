// vitest global set-up: the CLI tests run the bundled command line (build/cli/), so it is built
// here when missing or older than its sources (npm test has built it already; then this only
// checks file times).
// @ts-expect-error: a plain ES module without declarations
import { buildCliBundle, cliBundleStale } from '../../scripts/cliBundle.mjs';

export default function setup(): void {
  const stale = (cliBundleStale as () => string | null)();
  if (!stale) return;
  console.error(`vitest: the command line bundle is ${stale}; building it (npm run build:cli)`);
  const error = (buildCliBundle as () => string | null)();
  if (error) throw new Error(`cannot build the command line bundle: ${error}`);
}
