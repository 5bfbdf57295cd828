// The command line's tests run its main() in this process: for each test, what it writes to
// stdout and stderr goes to the test's own handlers instead, and the streams are put back after.
import { afterEach, beforeEach, vi } from 'vitest';

export function captureOutput(onOut: (s: string) => void, onErr: (s: string) => void): void {
  beforeEach(() => {
    vi.spyOn(process.stdout, 'write').mockImplementation((s) => {
      onOut(String(s));
      return true;
    });
    vi.spyOn(process.stderr, 'write').mockImplementation((s) => {
      onErr(String(s));
      return true;
    });
  });
  afterEach(() => vi.restoreAllMocks());
}
