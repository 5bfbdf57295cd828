// The strict reader refuses every invalid session with a message naming the field, and never
// throws, whatever it is given (Proxies that throw, getters, cycles, BigInt, huge and sparse
// arrays, prototype tricks). Each case below is one class of defect the mutation fuzzing found.
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';
import { BOX_MAX, BOX_MIN } from '../../web/model/grid';
import type { SessionState } from '../../web/model/session';
import { SESSION_LIMITS as L, parseSession } from '../../web/model/sessionFile';

// fig1: c1 is a ponytail (curves[0]), c2..c5 dividing (curves[1..4]), c6.. stream (curves[5..])
const base: SessionState = {
  ...presetSession('fig1', Head.builtin(), '25k', 0),
  avoidScalp: true,
  detail: {
    curl: { radius: 0.05, frequency: 3, start: 0.15, randomOffset: 1 },
    clump: { factor: 0.5, shape: 0.3, tipSpread: 0.02, guideDistance: 0.12 },
    frizz: { distance: 0.006, shape: 0.5 },
    lengthJitter: 0.15,
  },
};
const baseJson = JSON.stringify(base);
const P = 0; // ponytail
const D = 1; // dividing
const S = 5; // stream

// biome-ignore lint/suspicious/noExplicitAny: edits arbitrary JSON to break it
type Json = any;
function errorOf(edit: (j: Json) => void): string {
  const j = JSON.parse(baseJson);
  edit(j);
  const r = parseSession(j);
  return r.ok ? 'accepted' : r.error;
}

const lo = (a: number) => +(BOX_MIN[a] - L.curveMargin).toFixed(4);
const hi = (a: number) => +(BOX_MAX[a] + L.curveMargin).toFixed(4);
const inVolume = (a: number) =>
  `must be within the bounding volume (±${L.curveMargin}): ${'xyz'[a]} from ${lo(a)} to ${hi(a)}`;

describe('the base session is valid', () => {
  it('is accepted', () => {
    expect(errorOf(() => {})).toBe('accepted');
    expect(base.curves.map((c) => c.type).slice(0, 6)).toEqual([
      'ponytail',
      ...Array(4).fill('dividing'),
      'stream',
    ]);
  });
});

describe('curve geometry', () => {
  it('refuses a zero-length curve (fewer than 2 points, or one point repeated)', () => {
    expect(errorOf((j) => (j.curves[S].points = [j.curves[S].points[0]]))).toBe(
      `session.curves[${S}].points: needs at least 2 points`,
    );
    expect(errorOf((j) => (j.curves[S].points = []))).toBe(
      `session.curves[${S}].points: needs at least 2 points`,
    );
    expect(
      errorOf((j) => (j.curves[S].points = [j.curves[S].points[0], j.curves[S].points[0]])),
    ).toBe(
      `session.curves[${S}].points[1]: repeats the point before it (consecutive points must differ on the 0.0001 grid)`,
    );
  });

  it('refuses consecutive repeated points anywhere in any polyline', () => {
    expect(errorOf((j) => (j.curves[S].points[5] = [...j.curves[S].points[4]]))).toBe(
      `session.curves[${S}].points[5]: repeats the point before it (consecutive points must differ on the 0.0001 grid)`,
    );
    // closer than the position grid (1e-4) is the same point once quantised
    expect(
      errorOf((j) => {
        const p = j.curves[S].points[4];
        j.curves[S].points[5] = [p[0] + 2e-5, p[1], p[2]];
      }),
    ).toMatch(/^session\.curves\[5\]\.points\[5\]: repeats the point before it/);
    expect(
      errorOf((j) => (j.curves[P].crossSection[3] = [...j.curves[P].crossSection[2]])),
    ).toMatch(/^session\.curves\[0\]\.crossSection\[3\]: repeats the point before it/);
    expect(errorOf((j) => (j.curves[P].profiles[1][1] = [...j.curves[P].profiles[1][0]]))).toMatch(
      /^session\.curves\[0\]\.profiles\[1\]\[1\]: repeats the point before it/,
    );
    // a point may come back later (a loop), just not twice in a row
    expect(
      errorOf((j) => {
        const pts = j.curves[S].points;
        pts.push([...pts[pts.length - 2]]);
      }),
    ).toBe('accepted');
  });

  it('refuses coordinates that are not finite numbers', () => {
    expect(errorOf((j) => (j.curves[S].points[1][2] = 'x'))).toBe(
      `session.curves[${S}].points[1][2]: must be a finite number`,
    );
    expect(errorOf((j) => (j.curves[S].points[1][2] = null))).toBe(
      `session.curves[${S}].points[1][2]: must be a finite number`,
    );
    expect(errorOf((j) => (j.curves[S].points[1] = [0, 1]))).toBe(
      `session.curves[${S}].points[1]: must be [x, y, z]`,
    );
    expect(errorOf((j) => (j.curves[S].points = 'none'))).toBe(
      `session.curves[${S}].points: must be an array of points`,
    );
  });

  it('refuses coordinates over 1e6 or outside the bounding volume plus its margin', () => {
    expect(errorOf((j) => (j.curves[S].points[5][0] = 1e6))).toBe(
      `session.curves[${S}].points[5]: ${inVolume(0)}`,
    );
    expect(errorOf((j) => (j.curves[S].points[5][1] = lo(1) - 0.01))).toBe(
      `session.curves[${S}].points[5]: ${inVolume(1)}`,
    );
    expect(errorOf((j) => (j.curves[S].points[0][2] = -1e300))).toBe(
      `session.curves[${S}].points[0]: ${inVolume(2)}`,
    );
    expect(errorOf((j) => (j.curves[D].points[2][0] = 40))).toBe(
      `session.curves[${D}].points[2]: ${inVolume(0)}`,
    );
    expect(errorOf((j) => (j.curves[P].crossSection[1][1] = 1e6))).toBe(
      `session.curves[${P}].crossSection[1]: ${inVolume(1)}`,
    );
    expect(errorOf((j) => (j.curves[P].profiles[0][2][2] = -1e6))).toBe(
      `session.curves[${P}].profiles[0][2]: ${inVolume(2)}`,
    );
    expect(errorOf((j) => (j.curves[P].circles[0].centre[0] = 1e6))).toBe(
      `session.curves[${P}].circles[0].centre: ${inVolume(0)}`,
    );
    // the edge of the volume itself is inside
    expect(errorOf((j) => (j.curves[S].points.at(-1)[0] = hi(0)))).toBe('accepted');
  });

  it('caps points per polyline and per session, with the cap in the message', () => {
    const line = (n: number) =>
      Array.from({ length: n }, (_, i) => [0, 0, -1 + (i % 2) * 0.01 + i * 1e-4]);
    expect(errorOf((j) => (j.curves[S].points = line(L.maxPoints + 1)))).toBe(
      `session.curves[${S}].points: has ${L.maxPoints + 1} points, more than ${L.maxPoints} (the cap)`,
    );
    expect(errorOf((j) => (j.curves[P].crossSection = line(L.maxPoints + 1)))).toBe(
      `session.curves[${P}].crossSection: has ${L.maxPoints + 1} points, more than ${L.maxPoints} (the cap)`,
    );
    expect(
      errorOf((j) => {
        j.curves = Array.from({ length: 21 }, (_, i) => ({
          ...j.curves[S],
          id: `s${i}`,
          points: line(L.maxPoints),
        }));
      }),
    ).toBe(
      `session.curves[20].points: brings the session over ${L.maxSessionPoints} points in all (the cap)`,
    );
  });

  it('caps curves per session', () => {
    expect(
      errorOf((j) => {
        j.curves = Array.from({ length: L.maxCurves + 1 }, (_, i) => ({
          ...j.curves[S],
          id: `s${i}`,
        }));
      }),
    ).toBe(`session.curves: has ${L.maxCurves + 1} curves, more than ${L.maxCurves} (the cap)`);
  });

  it('refuses duplicate and malformed ids and unknown curve types', () => {
    expect(errorOf((j) => (j.curves[D].id = j.curves[P].id))).toBe(
      `session.curves[${D}].id: "c1" is used by an earlier curve (ids must be unique)`,
    );
    expect(errorOf((j) => (j.curves[D].id = 'a b'))).toMatch(
      /^session\.curves\[1\]\.id: must be a short identifier/,
    );
    expect(errorOf((j) => (j.curves[D].type = 'spiral'))).toBe(
      `session.curves[${D}].type: must be "stream", "dividing", "ponytail", "braid" or "bun"`,
    );
    expect(errorOf((j) => (j.curves[S].surfaceMode = 'wavy'))).toBe(
      `session.curves[${S}].surfaceMode: must be "ruled" or "strip"`,
    );
    expect(errorOf((j) => (j.curves[S].extend = 1))).toBe(
      `session.curves[${S}].extend: must be true or false`,
    );
  });
});

describe('viewpoints', () => {
  it('refuses position == target, non-finite and far-away cameras', () => {
    expect(
      errorOf((j) => (j.curves[S].viewpoint.position = [...j.curves[S].viewpoint.target])),
    ).toBe(
      `session.curves[${S}].viewpoint: position and target must differ (on the 0.0001 grid): no view direction`,
    );
    expect(errorOf((j) => (j.curves[D].viewpoint.position[1] = null))).toBe(
      `session.curves[${D}].viewpoint.position[1]: must be a finite number`,
    );
    expect(errorOf((j) => (j.curves[P].viewpoint.target[0] = 1e6))).toBe(
      `session.curves[${P}].viewpoint.target: must be within the bounding volume (±${L.viewMargin}): x from ${+(BOX_MIN[0] - L.viewMargin).toFixed(4)} to ${+(BOX_MAX[0] + L.viewMargin).toFixed(4)}`,
    );
    expect(errorOf((j) => (j.curves[S].viewpoint.position = [0, 0, 100]))).toBe('accepted');
    expect(errorOf((j) => delete j.curves[S].viewpoint)).toBe(
      `session.curves[${S}].viewpoint: must be an object`,
    );
  });
});

describe('dividing curves', () => {
  it('refuses zero and non-unit scalp normals, and a normal count that differs', () => {
    expect(errorOf((j) => (j.curves[D].normals[1] = [0, 0, 0]))).toBe(
      `session.curves[${D}].normals[1]: must be a unit vector (its length is 0, must be 1 ± 0.001)`,
    );
    expect(errorOf((j) => (j.curves[D].normals[0] = [0, 2, 0]))).toBe(
      `session.curves[${D}].normals[0]: must be a unit vector (its length is 2, must be 1 ± 0.001)`,
    );
    expect(errorOf((j) => (j.curves[D].normals[0] = [0, 1.0005, 0]))).toBe('accepted');
    expect(errorOf((j) => j.curves[D].normals.pop())).toBe(
      `session.curves[${D}].normals: must have one normal per point (4), has 3`,
    );
  });

  it('checks every scalar parameter against its range', () => {
    expect(errorOf((j) => (j.curves[D].sigma = 0))).toBe(
      `session.curves[${D}].sigma: must be between 0.05 and 20`,
    );
    expect(errorOf((j) => (j.curves[D].alpha1 = Number.POSITIVE_INFINITY))).toBe(
      `session.curves[${D}].alpha1: must be a finite number`,
    );
  });
});

describe('ponytails', () => {
  it('refuses circles with zero radius or zero axis', () => {
    expect(errorOf((j) => (j.curves[P].circles[1].radius = 0))).toBe(
      `session.curves[${P}].circles[1].radius: must be greater than 0 (at least 0.00005, at most 100)`,
    );
    expect(errorOf((j) => (j.curves[P].circles[1].radius = 1e-5))).toMatch(
      /circles\[1\]\.radius: must be greater than 0/,
    );
    expect(errorOf((j) => (j.curves[P].circles[1].radius = -1))).toBe(
      `session.curves[${P}].circles[1].radius: must be between 0 and 100`,
    );
    expect(errorOf((j) => (j.curves[P].circles[2].axis = [0, 0, 0]))).toBe(
      `session.curves[${P}].circles[2].axis: must be a unit vector (its length is 0, must be 1 ± 0.001)`,
    );
    expect(errorOf((j) => (j.curves[P].circles[2].axis = [0, -0.5, 0]))).toMatch(
      /circles\[2\]\.axis: must be a unit vector \(its length is 0\.5/,
    );
  });

  it('refuses fewer than two cross-section or profile points, and not two profiles', () => {
    expect(errorOf((j) => (j.curves[P].crossSection = [j.curves[P].crossSection[0]]))).toBe(
      `session.curves[${P}].crossSection: needs at least 2 points`,
    );
    expect(errorOf((j) => (j.curves[P].profiles[1] = []))).toBe(
      `session.curves[${P}].profiles[1]: needs at least 2 points`,
    );
    expect(errorOf((j) => j.curves[P].profiles.pop())).toBe(
      `session.curves[${P}].profiles: must hold two profile strokes, has 1`,
    );
  });

  it('refuses no circles, more circles than spine points, and circles out of spine order', () => {
    expect(errorOf((j) => (j.curves[P].circles = []))).toBe(
      `session.curves[${P}].circles: needs at least 1 circle`,
    );
    expect(
      errorOf((j) => {
        j.curves[P].points = j.curves[P].points.slice(0, 3);
        j.curves[P].circles = [0, 1, 2, 2].map((k) => ({
          ...j.curves[P].circles[0],
          spineIndex: k,
        }));
      }),
    ).toBe(`session.curves[${P}].circles: has 4 circles, more than its 3 spine points (the cap)`);
    expect(errorOf((j) => (j.curves[P].circles[1].spineIndex = 2.5))).toBe(
      `session.curves[${P}].circles[1].spineIndex: must be a whole number (between 0 and 18)`,
    );
    expect(errorOf((j) => (j.curves[P].circles[1].spineIndex = 19))).toBe(
      `session.curves[${P}].circles[1].spineIndex: must be between 0 and 18`,
    );
    expect(errorOf((j) => (j.curves[P].circles[1].spineIndex = 0))).toBe(
      `session.curves[${P}].circles[1].spineIndex: must be greater than the previous circle's (C1 first, in spine order)`,
    );
  });
});

describe('growth', () => {
  it('wants whole numbers for the seed, maxSegments and maxStrands', () => {
    expect(errorOf((j) => (j.growth.seed = 1.5))).toBe(
      'session.growth.seed: must be a whole number (between 0 and 4294967295)',
    );
    expect(errorOf((j) => (j.growth.seed = 2 ** 32))).toBe(
      'session.growth.seed: must be between 0 and 4294967295',
    );
    expect(errorOf((j) => (j.growth.seed = -1))).toBe(
      'session.growth.seed: must be between 0 and 4294967295',
    );
    expect(errorOf((j) => (j.growth.maxSegments = 12.25))).toBe(
      `session.growth.maxSegments: must be a whole number (between 1 and ${L.maxSegments})`,
    );
    expect(errorOf((j) => (j.growth.maxStrands = 0.5))).toBe(
      `session.growth.maxStrands: must be a whole number (between 0 and ${L.maxStrands})`,
    );
  });

  it('caps the work: maxSegments, maxStrands and the root samples the steps give', () => {
    expect(errorOf((j) => (j.growth.maxSegments = L.maxSegments + 1))).toBe(
      `session.growth.maxSegments: must be between 1 and ${L.maxSegments}`,
    );
    expect(errorOf((j) => (j.growth.maxStrands = L.maxStrands + 1))).toBe(
      `session.growth.maxStrands: must be between 0 and ${L.maxStrands}`,
    );
    expect(errorOf((j) => (j.growth.maxStrands = L.maxStrands))).toBe('accepted');
    expect(
      errorOf((j) => {
        j.growth.thetaStepDeg = 0.1;
        j.growth.phiStepDeg = 0.1;
      }),
    ).toBe(
      `session.growth: thetaStepDeg 0.1 and phiStepDeg 0.1 sample 6480000 root directions, more than ${L.maxRootSamples} (the cap)`,
    );
    expect(errorOf((j) => (j.growth.thetaStepDeg = 0.01))).toBe(
      'session.growth.thetaStepDeg: must be between 0.1 and 30',
    );
    expect(errorOf((j) => (j.growth.jitter = 5))).toBe(
      'session.growth.jitter: must be between 0 and 1',
    );
  });
});

describe('avoid scalp (a setting since version 2)', () => {
  it('wants true or false; false reads as absent', () => {
    for (const v of [1, 'yes', null, [], {}])
      expect(errorOf((j) => (j.avoidScalp = v))).toBe('session.avoidScalp: must be true or false');
    const off = JSON.parse(baseJson);
    off.avoidScalp = false;
    const r = parseSession(off);
    expect(r.ok).toBe(true);
    expect(r.ok && Object.keys(r.value)).not.toContain('avoidScalp');
  });

  it('refuses the stored constraints of version 1 in a version 2 session, naming them', () => {
    expect(errorOf((j) => (j.avoid = { index: [3], target: [0, 0.3, 0] }))).toBe(
      'session.avoid: is not a field hairsketch knows',
    );
    expect(errorOf((j) => (j.avoid = null))).toBe('session.avoid: is not a field hairsketch knows');
  });

  it('caps the constraint count of a version 1 session while copying it', () => {
    expect(
      errorOf((j) => {
        j.version = 1;
        delete j.avoidScalp;
        j.avoid = { index: new Array(L.maxAvoid + 1).fill(0), target: [] };
      }),
    ).toBe(`session.avoid.index: has ${L.maxAvoid + 1} entries, more than ${L.maxAvoid} (the cap)`);
  });
});

describe('hair detail (session-wide and per curve)', () => {
  it('accepts the base detail and each block alone', () => {
    expect(errorOf((j) => (j.detail = { curl: j.detail.curl }))).toBe('accepted');
    expect(errorOf((j) => (j.detail = { lengthJitter: 1 }))).toBe('accepted');
    expect(errorOf((j) => (j.detail = {}))).toBe('accepted');
    expect(errorOf((j) => delete j.detail)).toBe('accepted');
  });

  it('refuses an unknown key in a block, naming it', () => {
    expect(errorOf((j) => (j.detail.curl.radiuss = 0.1))).toBe(
      'session.detail.curl.radiuss: is not a field hairsketch knows',
    );
  });

  it('refuses a block with a key missing, naming the key', () => {
    expect(errorOf((j) => delete j.detail.clump.tipSpread)).toBe(
      'session.detail.clump.tipSpread: must be a finite number',
    );
  });

  it('refuses numbers out of range, naming the field and the range', () => {
    expect(errorOf((j) => (j.detail.frizz.shape = 2))).toBe(
      'session.detail.frizz.shape: must be between -1 and 1',
    );
    expect(errorOf((j) => (j.detail.clump.guideDistance = 0))).toBe(
      'session.detail.clump.guideDistance: must be between 0.01 and 2',
    );
    expect(errorOf((j) => (j.detail.curl.radius = -0.01))).toBe(
      'session.detail.curl.radius: must be between 0 and 0.5',
    );
    expect(errorOf((j) => (j.detail.lengthJitter = 1.5))).toBe(
      'session.detail.lengthJitter: must be between 0 and 1',
    );
    // the ends of a range are inside it
    expect(errorOf((j) => (j.detail.curl.frequency = 20))).toBe('accepted');
    expect(errorOf((j) => (j.detail.clump.shape = -1))).toBe('accepted');
  });

  it('refuses what is not a number, naming the field', () => {
    expect(errorOf((j) => (j.detail.curl.frequency = '3'))).toBe(
      'session.detail.curl.frequency: must be a finite number',
    );
    expect(errorOf((j) => (j.detail.frizz.distance = null))).toBe(
      'session.detail.frizz.distance: must be a finite number',
    );
    expect(errorOf((j) => (j.detail.lengthJitter = true))).toBe(
      'session.detail.lengthJitter: must be a finite number',
    );
  });

  it('refuses an unknown detail key and blocks that are not objects', () => {
    expect(errorOf((j) => (j.detail.wave = { radius: 1 }))).toBe(
      'session.detail.wave: is not a field hairsketch knows',
    );
    expect(errorOf((j) => (j.detail = 5))).toBe('session.detail: must be an object');
    expect(errorOf((j) => (j.detail.curl = true))).toBe('session.detail.curl: must be an object');
  });

  it("checks a curve's own detail the same way, naming the curve", () => {
    const own = JSON.parse(baseJson).detail;
    expect(errorOf((j) => (j.curves[S].detail = own))).toBe('accepted');
    expect(errorOf((j) => (j.curves[D].detail = { lengthJitter: 0.5 }))).toBe('accepted');
    expect(errorOf((j) => (j.curves[P].detail = {}))).toBe('accepted');
    expect(errorOf((j) => (j.curves[S].detail = { ...own, lengthJitter: 2 }))).toBe(
      `session.curves[${S}].detail.lengthJitter: must be between 0 and 1`,
    );
    expect(errorOf((j) => (j.curves[D].detail = { clump: { factor: 1 } }))).toBe(
      `session.curves[${D}].detail.clump.shape: must be a finite number`,
    );
    expect(errorOf((j) => (j.curves[P].detail = { frizz: { ...own.frizz, size: 1 } }))).toBe(
      `session.curves[${P}].detail.frizz.size: is not a field hairsketch knows`,
    );
  });
});

describe('the session object', () => {
  it('refuses unknown fields, naming them (camera and selected beside the session are fine)', () => {
    expect(errorOf((j) => (j.colour = 'red'))).toBe(
      'session.colour: is not a field hairsketch knows',
    );
    expect(errorOf((j) => (j.curves[S].surfacemode = 'strip'))).toBe(
      `session.curves[${S}].surfacemode: is not a field hairsketch knows`,
    );
    expect(errorOf((j) => (j.growth.speed = 2))).toBe(
      'session.growth.speed: is not a field hairsketch knows',
    );
    expect(errorOf((j) => (j.curves[P].circles[0].colour = 1))).toBe(
      `session.curves[${P}].circles[0].colour: is not a field hairsketch knows`,
    );
    // a key that is not an identifier is quoted, so the path stays unambiguous
    expect(errorOf((j) => (j.curves[S]['a b.c'] = 1))).toBe(
      `session.curves[${S}]["a b.c"]: is not a field hairsketch knows`,
    );
    expect(
      errorOf((j) => {
        j.camera = { position: [0, 0, 5], target: [0, 0, 0] };
        j.selected = 'c2';
      }),
    ).toBe('accepted');
  });

  it('refuses a bad grid, head or hair colour', () => {
    expect(errorOf((j) => (j.grid = '1e9'))).toBe('session.grid: must be 25k, 50k, 100k or 250k');
    expect(errorOf((j) => (j.grid = 'constructor'))).toBe(
      'session.grid: must be 25k, 50k, 100k or 250k',
    );
    expect(errorOf((j) => (j.head = 'mannequin'))).toBe(
      'session.head: must be "builtin" or a head mesh ({"kind": "mesh", "name", "hash", …})',
    );
    expect(errorOf((j) => (j.hairColor = 'red'))).toBe(
      'session.hairColor: must be a colour like #5a3825',
    );
  });

  it('refuses what is not an object', () => {
    for (const v of [null, undefined, 3, 'session', [], true])
      expect(parseSession(v)).toEqual({ ok: false, error: 'session: must be an object' });
  });
});
