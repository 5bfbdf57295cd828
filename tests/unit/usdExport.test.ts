// The .usda export read by Pixar's own reader (usd-core, PyPI, in build/usd-venv made by
// `bash scripts/setup.sh test`): tests/usd/check_usd.py checks the curves' topology, widths,
// colours, units and axis, the groom (GroomAPI, every groom_* primvar's type, interpolation and
// count, ids, root UVs, guides and groups), and returns the session the file carries, which must
// be the session exported. The checker itself must reject a broken file. Blender (bpy from PyPI,
// in build/bpy-venv) imports the file and must give the hair its surface_uv_coordinate.
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
import { hangLength, type SessionState } from '../../web/model/session';
import { parseSession } from '../../web/model/sessionFile';

const PYTHON = 'build/usd-venv/bin/python';
const CHECK = 'tests/usd/check_usd.py';
const BLENDER = 'build/bpy-venv/bin/python';
const CHECK_BLENDER = 'tests/usd/check_blender.py';
const BOX = [...BOX_MIN, ...BOX_MAX].map(String);

/** The venv's Python; a missing venv fails the test (it is made by the test setup). */
function python(): string {
  if (!existsSync(PYTHON))
    throw new Error(
      `${PYTHON} is missing: Pixar's USD reader (usd-core) lives in a virtual environment made by the test setup. Run \`npm test\`, or \`bash scripts/setup.sh test\` before vitest.`,
    );
  return PYTHON;
}

function check(file: string, box: string[] = BOX, dump?: string) {
  const r = spawnSync(python(), [CHECK, file, '--box', ...box, ...(dump ? ['--dump', dump] : [])], {
    encoding: 'utf8',
  });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

/** The box a session's hair stays in: with natural fall the volume grows by the hang length
 *  (model/grid.ts gridForSession), a braid's hair reaches past the fixed box. */
function boxOf(session: SessionState): string[] {
  const hang = hangLength(session);
  return [...BOX_MIN, ...BOX_MAX].map((v, i) => String(i === 4 ? v : i < 3 ? v - hang : v + hang));
}

/** Grows `session` into a .usda with `hairsketch grow` (the browser's pipeline). */
async function growUsda(session: SessionState, strands: number | null, dir: string, name: string) {
  const sessionFile = join(dir, `${name}.hairsketch.json`);
  writeFileSync(sessionFile, JSON.stringify(session));
  const file = join(dir, `${name}.usda`);
  const rep = await runGrow(
    [sessionFile, '--out', file, ...(strands ? ['--strands', String(strands)] : [])],
    { wasmBinary: new Uint8Array(readFileSync('web/generated/hairsolver.wasm')) },
    () => {},
  );
  return { file, sessionFile, rep };
}

interface Dump {
  roots: [number, number, number][];
  ids: number[];
  group_ids: number[];
  group_names: Record<string, string>;
  guide_ids: number[];
}

const SUMMARY =
  /^check_usd: ok, (\d+) curves, (\d+) points, (\d+) guides, (\d+) groups \((.*)\)\n$/;

describe('USD export read by usd-core', () => {
  // default: stream curves; braid: a braid (its three bundles and loose tail, gathered_tail.hpp)
  it.each(['default', 'braid'] as const)(
    'the %s preset at 2000 strands passes check_usd.py and carries its session',
    async (name) => {
      const dir = mkdtempSync(join(tmpdir(), 'hs-usd-'));
      const session = presetSession(name, Head.builtin());
      const { file, sessionFile, rep } = await growUsda(session, 2000, dir, name);
      expect(rep.strands).toBe(2000);

      const r = check(file, boxOf(session));
      const m = SUMMARY.exec(r.stderr);
      expect(m, r.stderr).not.toBeNull();
      expect(r.status).toBe(0);
      const [, curves, points, guides, groups, names] = m as RegExpExecArray;
      expect([Number(curves), Number(points)]).toEqual([rep.strands, rep.points]);
      console.log(`${name}: ${rep.strands} strands, ${guides} guides, ${groups} groups (${names})`);
      // a braid's strands are a group of their own beside the rest
      if (name === 'braid') expect(names).toMatch(/\bbraid1\b/);
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

  it('a preset with a parting (fig7) gives a group on each side of it', async () => {
    const dir = mkdtempSync(join(tmpdir(), 'hs-usd-parting-'));
    const session = presetSession('fig7', Head.builtin());
    expect(session.curves.filter((c) => c.type === 'dividing')).toHaveLength(1);
    const { file, rep } = await growUsda(session, 2000, dir, 'fig7');
    const dumpFile = join(dir, 'fig7.json');
    const r = check(file, boxOf(session), dumpFile);
    expect(r.status, r.stderr).toBe(0);
    const d = JSON.parse(readFileSync(dumpFile, 'utf8')) as Dump;
    const names = Object.values(d.group_names);
    expect(names.filter((n) => n.startsWith('parting1_')).length).toBe(2);
    // the two sides lie on either side of the parting: each side's roots are nearer its own
    // side's mean root than the other's, nearly always
    const sideMean = (g: string) => {
      const m = [0, 0, 0];
      let k = 0;
      d.group_ids.forEach((id, s) => {
        if (String(id) !== g) return;
        for (let c = 0; c < 3; c++) m[c] += d.roots[s][c];
        k++;
      });
      return { mean: m.map((v) => v / k), count: k };
    };
    const groups = Object.keys(d.group_names);
    const stats = groups.map(sideMean);
    for (const st of stats) expect(st.count).toBeGreaterThan(50);
    let own = 0;
    d.group_ids.forEach((id, s) => {
      const dist = stats.map((st) => Math.hypot(...st.mean.map((v, c) => d.roots[s][c] - v)));
      if (dist.indexOf(Math.min(...dist)) === groups.indexOf(String(id))) own++;
    });
    expect(own / rep.strands).toBeGreaterThan(0.9);
    console.log(
      `fig7: ${rep.strands} strands, ${d.guide_ids.length} guides, groups ${groups
        .map((g, i) => `${d.group_names[g]} ${stats[i].count}`)
        .join(', ')}`,
    );
  });

  it('a strand keeps its groom_id when the scalp changes elsewhere, and the id names its root sample', async () => {
    const dir = mkdtempSync(join(tmpdir(), 'hs-usd-ids-'));
    const head = Head.builtin();
    const base = presetSession('default', head);
    // every root grown (no cap, coarse sampling): the roots themselves do not move
    const growth = { ...base.growth, thetaStepDeg: 4, phiStepDeg: 4, maxStrands: 0 };
    const a: SessionState = { ...base, growth };
    const back = head.scalpPoint(120, 180)?.point;
    if (!back) throw new Error('no scalp point at the back of the head');
    const b: SessionState = { ...a, scalpPaint: [{ erase: true, radius: 0.35, points: [back] }] };
    const dumps: Dump[] = [];
    for (const [name, session] of [
      ['a', a],
      ['b', b],
    ] as const) {
      const { file } = await growUsda(session, null, dir, name);
      const dumpFile = join(dir, `${name}.json`);
      const r = check(file, boxOf(session), dumpFile);
      expect(r.status, r.stderr).toBe(0);
      dumps.push(JSON.parse(readFileSync(dumpFile, 'utf8')) as Dump);
    }
    const [da, db] = dumps;
    expect(db.ids.length).toBeLessThan(da.ids.length);
    const key = (p: number[]) => p.join(',');
    const inA = new Map(da.roots.map((p, s) => [key(p), s]));
    let common = 0;
    let moved = 0;
    db.roots.forEach((p, s) => {
      const sa = inA.get(key(p));
      if (sa === undefined) return;
      common++;
      if (sa !== s) moved++;
      expect(db.ids[s]).toBe(da.ids[sa]);
    });
    expect(common).toBe(db.ids.length);
    // the erased patch shifts the strands after it: an id by position would change
    expect(moved).toBeGreaterThan(0);
    // the id is the root's sample index i * nPhi + j: the root's direction from the head's centre
    // lies in theta row i and phi column j (jitter 0.8 keeps it 0.1 step clear of their edges)
    const nPhi = Math.ceil(360 / growth.phiStepDeg);
    da.roots.forEach((p, s) => {
      const theta = (Math.acos(p[1] / Math.hypot(...p)) * 180) / Math.PI;
      const phi = ((Math.atan2(p[0], p[2]) * 180) / Math.PI + 360) % 360;
      expect(Math.floor(theta / growth.thetaStepDeg)).toBe(Math.floor(da.ids[s] / nPhi));
      expect(Math.floor(phi / growth.phiStepDeg)).toBe(da.ids[s] % nPhi);
    });
    console.log(`ids: ${da.ids.length} strands, ${db.ids.length} after the erase, ${moved} moved`);
  });

  it('Blender imports the groom: the hair has surface_uv_coordinate per curve, melanin per point, redness and tint per curve', async () => {
    const dir = mkdtempSync(join(tmpdir(), 'hs-usd-blender-'));
    const session = presetSession('default', Head.builtin());
    const { file, rep } = await growUsda(session, 500, dir, 'blender');
    if (!existsSync(BLENDER))
      throw new Error(
        `${BLENDER} is missing: Blender's Python module (bpy) lives in a virtual environment made by the test setup. Run \`bash scripts/setup.sh test\`.`,
      );
    const r = spawnSync(BLENDER, [CHECK_BLENDER, file], { encoding: 'utf8' });
    expect(r.status, r.stderr).toBe(0);
    const out = JSON.parse(r.stdout.trim().split('\n').at(-1) as string) as {
      blender: string;
      objects: Record<
        string,
        {
          curves: number;
          points: number;
          attributes: Record<string, [string, string, number]>;
          first_uv: number[];
        }
      >;
    };
    const hair = out.objects.hair;
    expect(hair, JSON.stringify(Object.keys(out.objects))).toBeDefined();
    expect(hair.curves).toBe(rep.strands);
    expect(hair.points).toBe(rep.points);
    expect(hair.attributes.surface_uv_coordinate).toEqual(['CURVE', 'FLOAT2', rep.strands]);
    // the file's first root UV, as written
    const text = readFileSync(file, 'utf8');
    const m = /float2\[\] primvars:surface_uv_coordinate = \[\(([^,]+), ([^)]+)\)/.exec(text);
    expect(m).not.toBeNull();
    const [u, v] = [Number(m?.[1]), Number(m?.[2])];
    expect(hair.first_uv[0]).toBeCloseTo(u, 5);
    expect(hair.first_uv[1]).toBeCloseTo(v, 5);
    expect(out.objects.guides).toBeDefined();
    // the colour model's pigment, for an Attribute node into the Principled Hair BSDF
    expect(hair.attributes.melanin).toEqual(['POINT', 'FLOAT', rep.points]);
    expect(hair.attributes.redness).toEqual(['CURVE', 'FLOAT', rep.strands]);
    expect(hair.attributes.tint?.[0]).toBe('CURVE');
    console.log(
      `Blender ${out.blender}: hair ${hair.curves} curves, guides ${out.objects.guides.curves}; attributes ${Object.keys(hair.attributes).join(', ')}`,
    );
  });

  it('check_usd.py rejects a file whose counts, box, units or groom are wrong', () => {
    const dir = mkdtempSync(join(tmpdir(), 'hs-usd-bad-'));
    const header =
      '#usda 1.0\n(\n    customLayerData = {\n        string "hairsketch:session" = "{}"\n    }\n    defaultPrim = "hairsketch"\n    metersPerUnit = 0.1\n    upAxis = "Y"\n)\n\n';
    const pv = (decl: string, values: string, interpolation = 'uniform') =>
      `        ${decl} = [${values}] (\n            interpolation = "${interpolation}"\n        )\n`;
    // two strands (ids 5 and 7) and one guide, a copy of strand 5
    const groom = (o: {
      counts?: string;
      y?: number;
      api?: boolean;
      ids?: string;
      uv?: string;
      colorInterp?: string;
      closest?: string;
    }) => {
      const y = o.y ?? 0.1;
      const uv = o.uv ?? '(0.5, 0.5), (0.6, 0.5)';
      const hair =
        `    def BasisCurves "hair"\n    {\n        uniform token type = "linear"\n        int[] curveVertexCounts = [${o.counts ?? '2, 2'}]\n        point3f[] points = [(0, 0, 0), (0, ${y}, 0), (0.1, 0, 0), (0.1, 0.1, 0)]\n` +
        pv('float[] widths', '0.001, 0.001, 0.001, 0.001', 'vertex') +
        pv('color3f[] primvars:displayColor', '(1, 0, 0), (1, 0, 0)') +
        pv('int[] primvars:groom_guide', '0, 0') +
        pv('int[] primvars:groom_id', o.ids ?? '5, 7') +
        pv('int[] primvars:groom_group_id', '0, 0') +
        pv('string[] primvars:groom_group_name', '"hair", "hair"') +
        pv('float2[] primvars:groom_root_uv', uv) +
        pv('float2[] primvars:surface_uv_coordinate', uv) +
        pv(
          'float3[] primvars:groom_color',
          '(1, 0, 0), (1, 0, 0), (1, 0, 0), (1, 0, 0)',
          o.colorInterp ?? 'vertex',
        ) +
        pv('float3[] primvars:groom_closest_guides', o.closest ?? '(5, 5, 5), (5, 5, 5)') +
        pv('float3[] primvars:groom_guide_weights', '(1, 0, 0), (1, 0, 0)') +
        '    }\n';
      const guides =
        `    def BasisCurves "guides"\n    {\n        uniform token type = "linear"\n        int[] curveVertexCounts = [2]\n        point3f[] points = [(0, 0, 0), (0, ${y}, 0)]\n` +
        pv('float[] widths', '0.001, 0.001', 'vertex') +
        pv('color3f[] primvars:displayColor', '(1, 0, 0)') +
        pv('int[] primvars:groom_guide', '1') +
        pv('int[] primvars:groom_id', '5') +
        pv('int[] primvars:groom_group_id', '0') +
        pv('string[] primvars:groom_group_name', '"hair"') +
        pv('float2[] primvars:groom_root_uv', '(0.5, 0.5)') +
        pv('float2[] primvars:surface_uv_coordinate', '(0.5, 0.5)') +
        pv('float3[] primvars:groom_color', '(1, 0, 0), (1, 0, 0)', 'vertex') +
        '    }\n';
      const api = o.api === false ? '' : ' (\n    prepend apiSchemas = ["GroomAPI"]\n)';
      return `def Xform "hairsketch"\n{\ndef Xform "groom"${api}\n{\n${hair}${guides}}\n}\n`;
    };
    const write = (name: string, text: string) => {
      writeFileSync(join(dir, name), text);
      return join(dir, name);
    };
    const ok = check(write('ok.usda', header + groom({})));
    expect(ok.stderr).toBe('check_usd: ok, 2 curves, 4 points, 1 guides, 1 groups (hair)\n');
    expect(ok.status).toBe(0);
    expect(ok.stdout).toBe('{}\n');
    const bad: [string, string, RegExp][] = [
      ['sum', groom({ counts: '2, 3' }), /curveVertexCounts sum to 5 but there are 4 points/],
      ['box', groom({ y: 9 }), /points\[1\] .* is outside the box/],
      ['units', groom({}), /metersPerUnit is 1\.0/],
      ['api', groom({ api: false }), /API schemas \[\], not GroomAPI/],
      ['ids', groom({ ids: '5, 5' }), /groom_id has 1 repeats/],
      ['uv', groom({ uv: '(1.5, 0.5), (0.6, 0.5)' }), /groom_root_uv is outside \[0, 1\]/],
      [
        'interp',
        groom({ colorInterp: 'uniform' }),
        /groom_color interpolation is "uniform", not "vertex"/,
      ],
      [
        'closest',
        groom({ closest: '(7, 7, 7), (5, 5, 5)' }),
        /closest guide 7\.0 is not a guide's id/,
      ],
    ];
    for (const [name, text, message] of bad) {
      const h = name === 'units' ? header.replace('0.1', '1') : header;
      const r = check(write(`${name}.usda`, h + text));
      expect(r.stderr, name).toMatch(message);
      expect(r.status, name).toBe(1);
    }
    // usd-core is the one answering: its version is what setup installed
    const v = execFileSync(python(), ['-c', 'from pxr import Usd; print(Usd.GetVersion())'], {
      encoding: 'utf8',
    });
    expect(v).toMatch(/^\(0, \d+, \d+\)/);
  });
});
