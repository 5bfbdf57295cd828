// The lighting the solver worker adds to each result (protocol.ts HairLightingArrays): the
// precompute of hairLighting.ts towards the fixed key light, timed. ResultLighting keeps one
// HairLightingContext per head and solver grid (the worker's 'init'), so every result reuses
// what depends only on the head; resultLighting computes one result from scratch.
import type { GridSpec, HairLightingArrays, ScalpMesh, StrandArrays } from '../solver/protocol';
import { computeHairLighting, lightingGridFor } from './hairLighting';
import { HairLightingContext } from './hairLightingContext';
import { KEY_LIGHT_DIRECTION } from './keyLight';

type HeadMesh = Pick<ScalpMesh, 'positions' | 'indices'>;

export class ResultLighting {
  readonly context: HairLightingContext;

  /** `grid`: the solver's grid, which holds every strand point it grows. */
  constructor(head: HeadMesh | null, grid: GridSpec) {
    const max = grid.origin.map((o, a) => o + grid.step * (grid.dims[a] - 1));
    const box = { min: grid.origin, max: max as [number, number, number] };
    this.context = new HairLightingContext(head, lightingGridFor(head, box), {
      light: KEY_LIGHT_DIRECTION,
    });
  }

  /** The lighting of one result; headShadow: the hair's shadow on the head too (the converged
   *  hair's; previews keep the last one). */
  of(
    strands: StrandArrays,
    now: () => number = () => performance.now(),
    headShadow = true,
  ): HairLightingArrays {
    const t0 = now();
    const r = this.context.compute(strands, headShadow);
    return { strand: r.strand, head: r.head, ms: now() - t0 };
  }
}

export function resultLighting(
  strands: StrandArrays,
  head: HeadMesh | null,
  now: () => number = () => performance.now(),
  /** The hair's shadow on the head too (the converged hair's; previews keep the last one). */
  headShadow = true,
): HairLightingArrays {
  const t0 = now();
  const r = computeHairLighting(strands, head, { light: KEY_LIGHT_DIRECTION, headShadow });
  return { strand: r.strand, head: r.head, ms: now() - t0 };
}
