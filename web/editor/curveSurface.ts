// A curve's supporting surface (S4.3), built from its points, its own viewpoint and its mode,
// cached per curve object (curves are immutable: an edit makes a new object). Hint strokes are
// lifted onto it; the "Surface" display draws it.
import { defOf } from '../model/kinds';
import type { StyleCurve } from '../model/session';
import { buildSupportingSurface, type SupportingSurface } from '../model/supportingSurface';

/** Half width of a curve's supporting surface, in grid steps. */
export const SURFACE_HALF_WIDTH = 6;

const cache = new WeakMap<StyleCurve, { step: number; surface: SupportingSurface }>();

/** The supporting surface of a curve whose kind has one (a stream curve, a ponytail's spine, a
 *  braid: model/kinds/); null for one that lies on the head (a parting, a bun) or a curve with
 *  fewer than two points. */
export function curveSurface(c: StyleCurve, step: number): SupportingSurface | null {
  const mode = defOf(c).surface(c);
  if (!mode || c.points.length < 2) return null;
  const hit = cache.get(c);
  if (hit && hit.step === step) return hit.surface;
  const surface = buildSupportingSurface(
    c.points,
    c.viewpoint.position,
    mode,
    SURFACE_HALF_WIDTH * step,
  );
  cache.set(c, { step, surface });
  return surface;
}
