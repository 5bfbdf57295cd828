// The ties' bands in the exports: a session with two ponytails (fig8 with natural fall and ties)
// grown at 3,000 strands; its GLB, hair-cards GLB, OBJ and USD hold a band mesh in the band
// colour whose ring the ponytails' strands pass through; without ties, none. The checks read
// the files with their own parsers and count the strands through each ring with their own
// arithmetic (not tieBands.ts's).
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { growSessionHair } from '../../web/export/growSession';
import { writeExport } from '../../web/export/writeExport';
import { Head } from '../../web/head/head';
import { gridForPreset } from '../../web/model/grid';
import type { StrandArrays } from '../../web/model/hairArrays';
import type { SessionState } from '../../web/model/session';
import { loadSolverEngine } from '../../web/solver/wasmEngine';

const head = Head.builtin();
const session: SessionState = {
  ...presetSession('fig8', head, '25k', 0),
  fall: true,
  sections: true,
  ties: true,
  bandColor: '#d02060',
};
let hair: StrandArrays;
beforeAll(async () => {
  const wasmBinary = new Uint8Array(
    readFileSync(fileURLToPath(new URL('../../web/generated/hairsolver.wasm', import.meta.url))),
  );
  const engine = await loadSolverEngine({ wasmBinary });
  try {
    hair = growSessionHair(engine, session, head.scalpMesh(), {
      grid: gridForPreset('25k'),
      solver: 'fast',
      maxStrands: 3000,
    }).strands;
  } finally {
    engine.dispose();
  }
}, 120_000);

function bytesOf(format: 'glb' | 'cards' | 'obj' | 'usda', s: SessionState = session) {
  const chunks = [...writeExport(format, { strands: hair, session: s, head: null, cards: 100 })];
  const out = new Uint8Array(chunks.reduce((n, c) => n + c.length, 0));
  let o = 0;
  for (const c of chunks) {
    out.set(c, o);
    o += c.length;
  }
  return out;
}
const text = (b: Uint8Array) => new TextDecoder().decode(b);

/** The GLB's JSON and its mesh `name`'s positions (float triples) and material, or null. */
function glbMesh(b: Uint8Array, name: string) {
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  const jsonLen = dv.getUint32(12, true);
  const json = JSON.parse(text(b.subarray(20, 20 + jsonLen)));
  const binAt = 20 + jsonLen + 8;
  const mesh = (json.meshes ?? []).find((m: { name: string }) => m.name === name);
  if (!mesh) return null;
  const prim = mesh.primitives[0];
  const acc = json.accessors[prim.attributes.POSITION];
  const view = json.bufferViews[acc.bufferView];
  const positions: number[] = [];
  for (let i = 0; i < 3 * acc.count; i++)
    positions.push(dv.getFloat32(binAt + view.byteOffset + 4 * i, true));
  return { json, prim, positions, material: json.materials?.[prim.material] };
}

/** sRGB → linear, as the glTF and USD colours are (IEC 61966-2-1). */
const linear = (byte: number) => {
  const c = byte / 255;
  return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
};
const BAND_LINEAR = [0xd0, 0x20, 0x60].map(linear);

/** The rings in a band mesh's positions (576 vertices each, as tieBandMesh.ts lays them out):
 *  centre (the vertices' mean), axis (the normal of the ring's middle circle: the cross product
 *  of two of its diameters) and inner radius (the nearest vertex to the axis). */
function rings(positions: number[]) {
  const per = 576;
  const out = [];
  for (let b = 0; b < positions.length / 3 / per; b++) {
    const v = (i: number) => positions.slice(3 * (b * per + i), 3 * (b * per + i) + 3);
    const all = Array.from({ length: per }, (_, i) => v(i));
    const c = [0, 1, 2].map((k) => all.reduce((s, p) => s + p[k], 0) / per);
    // vertices 0, 12·12, 12·24, 12·36: the outer rim at 0°, 90°, 180°, 270° round the tail
    const [a0, a1, a2, a3] = [0, 144, 288, 432].map(v);
    const d1 = a2.map((x, k) => x - a0[k]);
    const d2 = a3.map((x, k) => x - a1[k]);
    const n = [
      d1[1] * d2[2] - d1[2] * d2[1],
      d1[2] * d2[0] - d1[0] * d2[2],
      d1[0] * d2[1] - d1[1] * d2[0],
    ];
    const l = Math.hypot(...n);
    const axis = n.map((x) => x / l);
    const radial = (p: number[]) => {
      const d = p.map((x, k) => x - c[k]);
      const t = d[0] * axis[0] + d[1] * axis[1] + d[2] * axis[2];
      return Math.hypot(...d.map((x, k) => x - t * axis[k]));
    };
    out.push({ centre: c, axis, inner: Math.min(...all.map(radial)) });
  }
  return out;
}

/** The share of the strands laid by tie `curve` that cross the ring's plane inside its hole. */
function throughRing(ring: ReturnType<typeof rings>[number], curve: number): number {
  const { points: P, strandStart, tailCurves } = hair;
  let own = 0;
  let through = 0;
  for (let s = 0; s + 1 < strandStart.length; s++) {
    if (tailCurves?.[s] !== curve) continue;
    own++;
    for (let q = strandStart[s]; q + 1 < strandStart[s + 1]; q++) {
      const side = (i: number) =>
        [0, 1, 2].reduce((sum, k) => sum + (P[3 * i + k] - ring.centre[k]) * ring.axis[k], 0);
      const da = side(q);
      const db = side(q + 1);
      if (da === db || (da > 0 && db > 0) || (da < 0 && db < 0)) continue;
      const f = da / (da - db);
      const x = [0, 1, 2].map((k) => P[3 * q + k] + (P[3 * q + 3 + k] - P[3 * q + k]) * f);
      if (Math.hypot(...x.map((v, k) => v - ring.centre[k])) < ring.inner) {
        through++;
        break;
      }
    }
  }
  return own > 0 ? through / own : 0;
}

describe('the band in exports', () => {
  it('GLB: a mesh "band" in the band colour round each ponytail, valid glTF', async () => {
    const b = bytesOf('glb');
    const validator = createRequire(import.meta.url)('gltf-validator') as {
      validateBytes(d: Uint8Array): Promise<{ issues: { numErrors: number } }>;
    };
    expect((await validator.validateBytes(b)).issues.numErrors).toBe(0);
    const band = glbMesh(b, 'band');
    expect(band).not.toBeNull();
    if (!band) return;
    expect(band.prim.mode).toBe(4);
    expect(band.material.name).toBe('band');
    band.material.pbrMetallicRoughness.baseColorFactor
      .slice(0, 3)
      .forEach((c: number, k: number) => {
        expect(c).toBeCloseTo(BAND_LINEAR[k], 5);
      });
    const found = rings(band.positions);
    expect(found).toHaveLength(2);
    // each ring sits within 6 cm of its ponytail's first circle, and holds nearly all its hair
    for (const [i, r] of found.entries()) {
      const c1 = session.curves[i].type === 'ponytail' ? session.curves[i].circles[0] : null;
      expect(c1).not.toBeNull();
      if (!c1) continue;
      expect(Math.hypot(...r.centre.map((x, k) => x - c1.centre[k]))).toBeLessThan(0.6);
      const share = throughRing(r, i);
      console.log(
        `band ${i}: inner radius ${r.inner.toFixed(3)}, ${(100 * share).toFixed(1)} % of its strands through it`,
      );
      expect(share).toBeGreaterThan(0.9);
      // hugs the tail: not much wider than a ponytail (≤ 4 cm inside)
      expect(r.inner).toBeLessThan(0.4);
    }
  });

  it('hair cards: the same band mesh beside the cards', () => {
    const cards = glbMesh(bytesOf('cards'), 'band');
    const glb = glbMesh(bytesOf('glb'), 'band');
    expect(cards?.material.name).toBe('band');
    expect(cards?.positions).toEqual(glb?.positions);
  });

  it('OBJ: an object "band" with the same vertices and faces that index them', () => {
    const obj = text(bytesOf('obj'));
    const at = obj.indexOf('\no band\n');
    expect(at).toBeGreaterThan(0);
    expect(obj).toContain('# band colour #d02060');
    const before = obj.slice(0, at).match(/^v /gm)?.length ?? 0;
    const lines = obj.slice(at).split('\n');
    const v = lines.filter((l) => l.startsWith('v ')).map((l) => l.slice(2).split(' ').map(Number));
    const f = lines.filter((l) => l.startsWith('f '));
    const glb = glbMesh(bytesOf('glb'), 'band');
    expect(v.length).toBe(2 * 576);
    expect(f.length).toBe(2 * 2 * 576);
    v.flat().forEach((x, i) => {
      expect(Math.abs(x - (glb?.positions[i] ?? Number.NaN))).toBeLessThan(1e-4);
    });
    for (const l of f)
      for (const c of l.slice(2).split(' ')) {
        const k = Number(c.split('/')[0]);
        expect(k).toBeGreaterThan(before);
        expect(k).toBeLessThanOrEqual(before + v.length);
      }
  });

  it('USD: a Mesh "band" inside the root Xform, its colour as displayColor', () => {
    const usd = text(bytesOf('usda'));
    const at = usd.indexOf('def Mesh "band"');
    expect(at).toBeGreaterThan(usd.indexOf('def Xform "hairsketch"'));
    const block = usd.slice(at, usd.indexOf('\n    }\n', at));
    const points = block.match(/point3f\[\] points = \[([^\]]*)\]/)?.[1] ?? '';
    expect(points.split('(').length - 1).toBe(2 * 576);
    const colour =
      block
        .match(/displayColor = \[\(([^)]*)\)\]/)?.[1]
        .split(',')
        .map(Number) ?? [];
    colour.forEach((c, k) => {
      expect(c).toBeCloseTo(BAND_LINEAR[k], 4);
    });
    const indices =
      block
        .match(/faceVertexIndices = \[([^\]]*)\]/)?.[1]
        .split(',')
        .map(Number) ?? [];
    expect(indices.length).toBe(3 * 2 * 2 * 576);
    expect(Math.max(...indices)).toBe(2 * 576 - 1);
  });

  it('none without ties (sessions made before them look and export as before)', () => {
    const off = { ...session, ties: false };
    expect(glbMesh(bytesOf('glb', off), 'band')).toBeNull();
    expect(text(bytesOf('obj', off))).not.toContain('o band');
    expect(text(bytesOf('usda', off))).not.toContain('def Mesh "band"');
    expect(glbMesh(bytesOf('glb', off), 'hair')).not.toBeNull();
  });
});
