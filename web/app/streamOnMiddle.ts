// A stream curve drawn in a side view along the head's middle (a mohawk's crest, a centre
// line combed back) is put on it: from the side the middle is the head's outline, and a press
// just inside it lands a few centimetres to the near side (fresh eyes could not draw a centred
// mohawk without Mirror), when it is pressed on the outline; with Mirror on, one drawn within
// 1.5 cm of the middle from any view is too; one that hangs down in front of the face is not.
// Its points that lay on the head are put back on it
// where the middle meets it; those past the scalp keep their place in the plane.
import type { Head } from '../head/head';
import { type MirrorPlane, snapToPlane } from '../model/mirror';
import type { Vec3 } from '../model/vec3';

/** Points within this of the head (world units, 5 mm) lay on it as drawn. */
const ON_HEAD = 0.05;
/** Only a stroke pressed on the head's outline (its surface there within about 33° of facing
 *  across the view, |n · view| below this) is put on the middle: one pressed inside the outline,
 *  a bob's side stroke near the back of the head, is meant where it is (fresh eyes lost a
 *  stroke's mirror twin to the snap). */
const ON_OUTLINE = 0.55;
/** How high above the head's centre the face reaches (world units; the face's column of the
 *  shape rules, solver-cpp/src/hair_fall.hpp kFaceTop). */
const FACE_TOP = 0.5;

/** How far below the stroke's first point a point must lie to hang down (world units, 2 cm). */
const HANGS_BELOW = 0.2;

/** Whether p, off the head, hangs before or beside the face: in front of the head's centre,
 *  below FACE_TOP and more than HANGS_BELOW below where the stroke was pressed (`from`). A stroke
 *  with such a point is a lock drawn down past the face (fresh eyes round 18: a long stroke
 *  pressed near the top of the outline in a side view went down the middle of the face), not a
 *  crest or a centre line, and stays where it is drawn. A crest's spike pressed at the front
 *  hairline and drawn forward or up does not go down: it is put on the middle (fresh eyes: the
 *  mohawk's front spikes stayed off the middle, 5 of 16 and 3 of 18, and its front leaned to one
 *  side). */
function beforeFace(p: Vec3, from: Vec3, head: Head): boolean {
  const c = head.center;
  return (
    p[2] > c[2] &&
    p[1] < Math.min(c[1] + FACE_TOP, from[1] - HANGS_BELOW) &&
    head.signedDistance(p) > ON_HEAD
  );
}

export function streamOnMiddle(
  drawn: Vec3[],
  plane: MirrorPlane,
  view: Vec3,
  head: Head,
  mirrored = false,
): { points: Vec3[]; snapped: boolean } {
  if (drawn.length === 0 || drawn.some((p) => beforeFace(p, drawn[0], head)))
    return { points: drawn, snapped: false };
  const n = head.normalAt(drawn[0]);
  const len = Math.hypot(view[0], view[1], view[2]) || 1;
  const onOutline = Math.abs(n[0] * view[0] + n[1] * view[1] + n[2] * view[2]) / len < ON_OUTLINE;
  let r = onOutline ? snapToPlane(drawn, plane, view, true) : { points: drawn, snapped: false };
  // with Mirror on, a stroke along the middle from any view (its first point and its points on
  // average within SNAP_TO_PLANE, 1.5 cm): its twin would lie beside it, a crest of two strokes
  // a few centimetres apart where one was meant (fresh eyes' first mohawk strokes)
  if (!r.snapped && mirrored) r = snapToPlane(drawn, plane);
  const { points, snapped } = r;
  if (!snapped) return { points, snapped };
  const c = head.center;
  return {
    points: points.map((p, i) => {
      if (Math.abs(head.signedDistance(drawn[i])) > ON_HEAD) return p;
      // the outermost head point on the line from the centre through p
      const d: Vec3 = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
      const len = Math.hypot(d[0], d[1], d[2]);
      if (!(len > 1e-6)) return p;
      const u: Vec3 = [d[0] / len, d[1] / len, d[2] / len];
      const from: Vec3 = [c[0] + 4 * u[0], c[1] + 4 * u[1], c[2] + 4 * u[2]];
      const hit = head.raycast(from, [-u[0], -u[1], -u[2]]);
      return hit ? hit.point : p;
    }),
    snapped,
  };
}
