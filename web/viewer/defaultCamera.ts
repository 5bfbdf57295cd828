// The camera the app starts from (and that presets are sketched from). Kept apart from the
// viewer so the command line and tests can use it without loading three.js.
import type { Vec3 } from '../model/vec3';

export const DEFAULT_CAMERA = { position: [2.6, 0.9, 7.0] as Vec3, target: [0, -0.55, 0] as Vec3 };
