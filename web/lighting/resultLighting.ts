// The lighting the solver worker adds to each result (protocol.ts HairLightingArrays): the
// precompute of hairLighting.ts towards the fixed key light, timed.
import type { HairLightingArrays, ScalpMesh, StrandArrays } from '../solver/protocol';
import { computeHairLighting } from './hairLighting';
import { KEY_LIGHT_DIRECTION } from './keyLight';

export function resultLighting(
  strands: StrandArrays,
  head: Pick<ScalpMesh, 'positions' | 'indices'> | null,
  now: () => number = () => performance.now(),
  /** The hair's shadow on the head too (the converged hair's; previews keep the last one). */
  headShadow = true,
): HairLightingArrays {
  const t0 = now();
  const r = computeHairLighting(strands, head, { light: KEY_LIGHT_DIRECTION, headShadow });
  return { strand: r.strand, head: r.head, ms: now() - t0 };
}
