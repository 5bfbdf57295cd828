// The wasm side of a groom in motion (binding.cpp hs_sim_*): strands copied into the module,
// its guides stepped a frame (1/24 s) at a time over the engine's head (and body), read back as
// copies (into a caller's array of the right length when given: no allocation a frame); the
// binding of the strands to the guides is read once.
import type { HairSolverModule } from '../generated/hairsolver.mjs';
import type { GuideBinding } from '../model/guideFollowers';
import type { StrandArrays } from '../model/hairArrays';
import {
  DEFAULT_WIND,
  MOTION_MAX_GUIDES,
  MOTION_PIVOT,
  type MotionFrame,
  motionCode,
} from '../model/motion';
import type { MotionOptions, MotionRun } from './engine';
import { check, withInputs, withScratch } from './wasmMemory';

export function createMotion(
  mod: HairSolverModule,
  engine: number,
  strands: StrandArrays,
  opts: MotionOptions,
): MotionRun {
  const pointCount = strands.points.length / 3;
  const strandCount = strands.strandStart.length - 1;
  const tails =
    strands.tailCurves && strands.tailCurves.length === strandCount ? strands.tailCurves : null;
  const inputs: ArrayBufferView[] = [
    strands.points,
    strands.strandStart,
    new Float32Array(MOTION_PIVOT),
    tails ?? new Int32Array(1),
  ];
  const handle = withInputs(mod, inputs, ([points, start, pivot, tailPtr]) =>
    withScratch(mod, 4, (out) => {
      check(
        mod,
        mod._hs_sim_create(
          engine,
          points,
          pointCount,
          start,
          strandCount,
          tails ? tailPtr : 0,
          pivot,
          motionCode(opts.motion),
          opts.seed >>> 0,
          opts.maxGuides ?? MOTION_MAX_GUIDES,
          opts.body ? 1 : 0,
          (opts.wind ?? DEFAULT_WIND).fromDeg,
          (opts.wind ?? DEFAULT_WIND).speed,
          out,
        ),
      );
      return mod.HEAPU32[out >> 2];
    }),
  );
  let live = true;
  let started = false;
  const guideCount = mod._hs_sim_guide_count(handle);
  const guidePoints = mod._hs_sim_guide_points(handle);
  const floats = 3 * guideCount * guidePoints;
  const rest = mod._hs_sim_guide_rest(handle) >> 2;
  const guideOf = mod._hs_sim_guide_of(handle) >> 2;
  const along = mod._hs_sim_along(handle) >> 2;
  const binding: GuideBinding = {
    guideCount,
    guidePoints,
    guideRest: mod.HEAPF32.slice(rest, rest + floats),
    guideOf: mod.HEAP32.slice(guideOf, guideOf + strandCount),
    along: mod.HEAPF32.slice(along, along + pointCount),
  };
  const read = (into?: Float32Array): MotionFrame => {
    const p = mod._hs_sim_guides(handle) >> 2;
    let guides: Float32Array;
    if (into && into.length === floats) {
      into.set(mod.HEAPF32.subarray(p, p + floats));
      guides = into;
    } else guides = mod.HEAPF32.slice(p, p + floats);
    const pose = withScratch(mod, 48, (ptr) => {
      mod._hs_sim_pose(handle, ptr);
      return mod.HEAPF32.slice(ptr >> 2, (ptr >> 2) + 12);
    });
    return { frame: mod._hs_sim_frame(handle), guides, pose };
  };
  return {
    binding,
    step(into?: Float32Array): MotionFrame {
      this.advance();
      return read(into);
    },
    advance(): void {
      if (!live) throw new Error('motion: stepped after dispose');
      if (started) mod._hs_sim_step(handle);
      started = true;
    },
    dispose(): void {
      if (!live) return;
      live = false;
      mod._hs_sim_destroy(handle);
    },
  };
}
