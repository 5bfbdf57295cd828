// The .usda export read by Pixar's own reader (usd-core, PyPI, in build/usd-venv made by
// `bash scripts/setup.sh test`): tests/usd/check_usd.py checks the curves' topology, widths,
// colours, units and axis, and returns the session the file carries, which must be the session
// exported. The checker itself must reject a broken file.
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { runGrow } from '../../web/cli/grow';
import { presetSession } from '../../web/cli/presetSession';
import { readExportedSession } from '../../web/export/readExport';
import { Head } from '../../web/head/head';
import { BOX_MAX, BOX_MIN } from '../../web/model/grid';
import { hangLength } from '../../web/model/session';
import { parseSession } from '../../web/model/sessionFile';

const PYTHON = 'build/usd-venv/bin/python';
const CHECK = 'tests/usd/check_usd.py';
const BOX = [...BOX_MIN, ...BOX_MAX].map(String);

/** The venv's Python; a missing venv fails the test (it is made by the test setup). */
function python(): string {
  if (!existsSync(PYTHON))
    throw new Error(
      `${PYTHON} is missing: Pixar's USD reader (usd-core) lives in a virtual environment made by the test setup. Run \`npm test\`, or \`bash scripts/setup.sh test\` before vitest.`,
    );
  return PYTHON;
}

function check(file: string, box: string[] = BOX) {
  const r = spawnSync(python(), [CHECK, file, '--box', ...box], { encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

describe('USD export read by usd-core', () => {
  // default: stream curves; braid: a braid (its three bundles and loose tail, gathered_tail.hpp)
  it.each(['default', 'braid'] as const)(
    'the %s preset at 2000 strands passes check_usd.py and carries its session',
    async (name) => {
      const dir = mkdtempSync(join(tmpdir(), 'hs-usd-'));
      const session = presetSession(name, Head.builtin());
      const sessionFile = join(dir, `${name}.hairsketch.json`);
      writeFileSync(sessionFile, JSON.stringify(session));
      const file = join(dir, 'hairstyle.usda');
      const lines: string[] = [];
      const rep = await runGrow(
        [sessionFile, '--out', file, '--strands', '2000'],
        { wasmBinary: new Uint8Array(readFileSync('web/generated/hairsolver.wasm')) },
        (l) => lines.push(l),
      );
      expect(rep.strands).toBe(2000);

      // with natural fall the volume grows by the hang length (model/grid.ts gridForSession):
      // a braid's hair reaches past the fixed box (below it and behind the head)
      const hang = hangLength(session);
      const box = [...BOX_MIN, ...BOX_MAX].map((v, i) =>
        i === 4 ? v : i < 3 ? v - hang : v + hang,
      );
      const r = check(file, box.map(String));
      expect(r.stderr).toBe(`check_usd: ok, ${rep.strands} curves, ${rep.points} points\n`);
      expect(r.status).toBe(0);
      const out = r.stdout.trim().split('\n');
      expect(out).toHaveLength(1);
      const embedded = JSON.parse(out[0]);
      // exactly the session exported (the saved file as the app's reader gives it), and the app
      // reads it back unchanged
      const exported = parseSession(JSON.parse(readFileSync(sessionFile, 'utf8')));
      if (!exported.ok) throw new Error(exported.error);
      expect(embedded).toEqual(JSON.parse(JSON.stringify(exported.value)));
      const reread = parseSession(embedded);
      expect(reread.ok && reread.value).toEqual(exported.value);
      // the app's own reader of exports finds the same session in the file
      const mine = readExportedSession(readFileSync(file));
      expect(mine?.ok && mine.session).toEqual(embedded);
    },
  );

  it('check_usd.py rejects a file whose counts do not sum to the points, or outside the box', () => {
    const dir = mkdtempSync(join(tmpdir(), 'hs-usd-bad-'));
    const header =
      '#usda 1.0\n(\n    customLayerData = {\n        string "hairsketch:session" = "{}"\n    }\n    defaultPrim = "hairsketch"\n    metersPerUnit = 0.1\n    upAxis = "Y"\n)\n\n';
    const body = (counts: string, y: number) =>
      `def Xform "hairsketch"\n{\n    def BasisCurves "hair"\n    {\n        uniform token type = "linear"\n        int[] curveVertexCounts = [${counts}]\n        point3f[] points = [(0, 0, 0), (0, ${y}, 0), (0.1, 0, 0), (0.1, 0.1, 0)]\n        float[] widths = [0.001, 0.001, 0.001, 0.001] (\n            interpolation = "vertex"\n        )\n        color3f[] primvars:displayColor = [(1, 0, 0), (1, 0, 0)] (\n            interpolation = "uniform"\n        )\n    }\n}\n`;
    const write = (name: string, text: string) => {
      writeFileSync(join(dir, name), text);
      return join(dir, name);
    };
    const ok = check(write('ok.usda', header + body('2, 2', 0.1)));
    expect(ok.status).toBe(0);
    expect(ok.stdout).toBe('{}\n');
    const sum = check(write('sum.usda', header + body('2, 3', 0.1)));
    expect(sum.status).toBe(1);
    expect(sum.stderr).toMatch(/curveVertexCounts sum to 5 but there are 4 points/);
    const box = check(write('box.usda', header + body('2, 2', 9)));
    expect(box.status).toBe(1);
    expect(box.stderr).toMatch(/points\[1\] .* is outside the box/);
    const units = check(write('units.usda', header.replace('0.1', '1') + body('2, 2', 0.1)));
    expect(units.status).toBe(1);
    expect(units.stderr).toMatch(/metersPerUnit is 1\.0/);
    // usd-core is the one answering: its version is what setup installed
    const v = execFileSync(python(), ['-c', 'from pxr import Usd; print(Usd.GetVersion())'], {
      encoding: 'utf8',
    });
    expect(v).toMatch(/^\(0, \d+, \d+\)/);
  });
});
