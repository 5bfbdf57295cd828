// Scalp avoidance's options as the app, the export and `hairsketch grow` all apply them.
import type { GrowthParams } from '../model/growthParams';

/** Scalp avoidance as the app applies it (S4.7): grid points within 1.5 grid steps of the scalp
 *  (inside it too: growth interpolates them just outside), turned along the surface where they
 *  point inwards; the target keeps the field's length up to 0.3 (never longer: avoidance turns
 *  hair, it does not make hair where the curves asked for none), and grid points where the
 *  field is weaker than the growth threshold get none. Only the scalp is measured against,
 *  so no hair is pulled down over the face. */
export function avoidanceOptions(growth: GrowthParams) {
  return {
    band: 1.5,
    magnitude: 0.3,
    wholeHead: false,
    insideToo: true,
    minField: growth.minMagnitude,
  };
}
