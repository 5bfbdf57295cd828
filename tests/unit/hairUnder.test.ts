// The scalp under the hair takes the hair's root colour (viewer/headMaterial.ts setHeadHairUnder),
// in a band along the scalp's edge: fading in over its last centimetre, down to HAIR_UNDER_INNER of
// it 3.5 cm in and beyond (scalp seen between clumps or along a parting). Checked on
// the built-in head against its own scalp flags and plain Euclidean distances (a path along the
// mesh is never shorter).
import { describe, expect, it } from 'vitest';
import { Head } from '../../web/head/head';
import { rootColor } from '../../web/model/hairLook';
import { absorptionColor, melaninAbsorption } from '../../web/model/melanin';
import {
  createHeadMesh,
  HAIR_UNDER_HOLD,
  HAIR_UNDER_INNER,
  HAIR_UNDER_OUT,
  HAIR_UNDER_SHARE,
  setHeadHairUnder,
} from '../../web/viewer/headMaterial';

const head = Head.builtin();

describe('the scalp under the hair', () => {
  it('fades in from 0 at the scalp edge to 1 a centimetre in, and down to its inner share by 3.5 cm in', () => {
    const mesh = createHeadMesh(head.mesh);
    const share = mesh.geometry.getAttribute('scalpShare').array as Float32Array;
    const { positions: P, indices: I, scalp } = head.mesh;
    const n = P.length / 3;
    const onScalp = new Uint8Array(n);
    const offScalp = new Uint8Array(n);
    for (let t = 0; t < scalp.length; t++)
      for (let k = 0; k < 3; k++) (scalp[t] ? onScalp : offScalp)[I[3 * t + k]] = 1;
    const edge: number[] = [];
    for (let v = 0; v < n; v++) if (onScalp[v] && offScalp[v]) edge.push(v);
    expect(edge.length).toBeGreaterThan(50);
    let inner = 0;
    let band = 0;
    for (let v = 0; v < n; v++) {
      expect(share[v]).toBeGreaterThanOrEqual(0);
      expect(share[v]).toBeLessThanOrEqual(1);
      if (offScalp[v]) expect(share[v]).toBe(0); // at the edge and off the scalp
      if (!onScalp[v] || offScalp[v]) continue;
      let d = Number.POSITIVE_INFINITY;
      for (const e of edge)
        d = Math.min(
          d,
          Math.hypot(P[3 * v] - P[3 * e], P[3 * v + 1] - P[3 * e + 1], P[3 * v + 2] - P[3 * e + 2]),
        );
      // the crown keeps the inner share: past the band along the mesh, which is at least as far
      if (d >= HAIR_UNDER_OUT) {
        expect(share[v]).toBeCloseTo(HAIR_UNDER_INNER, 6);
        inner++;
      }
      // the whole colour only within the band: at least a centimetre from the edge along the
      // mesh, no more than HAIR_UNDER_HOLD (so no more in a straight line either)
      if (share[v] === 1) {
        expect(d).toBeLessThanOrEqual(HAIR_UNDER_HOLD + 1e-6);
        band++;
      }
    }
    expect(inner).toBeGreaterThan(1000);
    expect(band).toBeGreaterThan(200);
  });

  it("takes the hair's root colour while there is hair, and says when it changed", () => {
    const mesh = createHeadMesh(head.mesh);
    const u = (
      mesh.material as unknown as { userData: { hairUnder: { value: { toArray(): number[] } } } }
    ).userData.hairUnder;
    const look = {
      melanin: 0.5,
      redness: 0.3,
      dye: null,
      grey: 0,
      tipMelanin: 0.5,
      tipDye: null,
      tipStart: 1,
      tipLength: 0,
      variation: 0,
      roughness: 0.3,
    };
    const c = rootColor(look, '#000000');
    const want = absorptionColor(melaninAbsorption(0.5, 0.3));
    for (let k = 0; k < 3; k++) expect(c[k]).toBeCloseTo(want[k], 6);
    expect(setHeadHairUnder(mesh, c)).toBe(true);
    expect(setHeadHairUnder(mesh, c)).toBe(false);
    expect(u.value.toArray()).toEqual([...c, HAIR_UNDER_SHARE]);
    expect(setHeadHairUnder(mesh, null)).toBe(true);
    expect(u.value.toArray()).toEqual([0, 0, 0, 0]);
    // all grey: the grey pigment's colour
    const grey = rootColor({ ...look, grey: 100 }, '#000000');
    expect(grey[0]).toBeGreaterThan(c[0]);
  });
});
