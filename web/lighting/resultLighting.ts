// The lighting the solver worker adds to each result (protocol.ts HairLightingArrays): the
// precompute of hairLighting.ts towards the fixed key light, timed. ResultLighting keeps one
// HairLightingContext per head and solver grid (the worker's 'init'), so every result reuses
// what depends only on the head; resultLighting computes one result from scratch.
import type { GridSpec, HairLightingArrays, ScalpMesh, StrandArrays } from '../model/hairArrays';
import { computeHairLighting, lightingGridFor } from './hairLighting';
import { HairLightingContext } from './hairLightingContext';
import { KEY_LIGHT_DIRECTION } from './keyLight';

type HeadMesh = Pick<ScalpMesh, 'positions' | 'indices'>;
type V3 = [number, number, number];

/** The lighting grid holds the solver's box grown by this fraction of its size on every side:
 *  a stroke that grows the box a little keeps the head's caches (~0.3 s to build). */
const GRID_MARGIN = 0.2;

export class ResultLighting {
  readonly context: HairLightingContext;

  /** `grid`: the solver's grid, which holds every strand point it grows. `margin`: the lighting
   *  grid also holds that much more of the solver's box on every side (a fraction of its size),
   *  so a box that grows a little later is still held (forGrid). */
  constructor(
    private readonly head: HeadMesh | null,
    grid: GridSpec,
    margin = GRID_MARGIN,
  ) {
    const box = solverBox(grid, margin);
    this.context = new HairLightingContext(head, lightingGridFor(head, box), {
      light: KEY_LIGHT_DIRECTION,
    });
  }

  /** The lighting for hair grown on `grid` (the solver moved to another grid): this one when
   *  its grid still holds that grid's box (the head's caches are kept), else a new one over it
   *  (the head's caches are built again by its first result). */
  forGrid(grid: GridSpec): ResultLighting {
    const g = this.context.grid;
    const box = solverBox(grid, 0);
    const holds = [0, 1, 2].every(
      (a) => box.min[a] >= g.origin[a] && box.max[a] <= g.origin[a] + g.step * (g.dims[a] - 1),
    );
    return holds ? this : new ResultLighting(this.head, grid);
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

/** The solver grid's box, grown by `margin` × its size on every side. */
function solverBox(grid: GridSpec, margin: number): { min: V3; max: V3 } {
  const pad = grid.dims.map((d) => margin * grid.step * (d - 1));
  return {
    min: [0, 1, 2].map((a) => grid.origin[a] - pad[a]) as unknown as V3,
    max: [0, 1, 2].map(
      (a) => grid.origin[a] + grid.step * (grid.dims[a] - 1) + pad[a],
    ) as unknown as V3,
  };
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
