import { describe, expect, it } from 'vitest';
import { CURVE_PARAMS } from '../../web/model/curveParams';
import { emptySession, type SessionState } from '../../web/model/session';
import { parseSession } from '../../web/model/sessionFile';
import { decodeSessionLink, encodeSessionLink } from '../../web/model/sessionLink';
import { SESSION_VERSION } from '../../web/model/sessionMigrations';

const vp = {
  position: [0, 0, 6] as [number, number, number],
  target: [0, 0, 0] as [number, number, number],
};

function sample(): SessionState {
  // the settings (avoidScalp, fall, sections, finish, bust, shape, detail) in the order the reader
  // writes them
  const {
    fall: _fall,
    sections: _sections,
    finish: _finish,
    bust: _bust,
    shape: _shape,
    ties: _ties,
    hairline: _hairline,
    curlVolume: _curlVolume,
    nape: _nape,
    coilVolume: _coilVolume,
    roundPlaits: _roundPlaits,
    tieVolume: _tieVolume,
    compactBun: _compactBun,
    clumpAll: _clumpAll,
    faceClear: _faceClear,
    locks: _locks,
    ...s
  } = emptySession('50k');
  return {
    ...s,
    curves: [
      {
        id: 'c1',
        type: 'stream',
        points: [
          [0, 1, 0],
          [0.1, 1.1, 0.05],
          [0.2, 1.15, 0.1],
        ],
        extend: true,
        viewpoint: vp,
        surfaceMode: 'strip',
        volume: 0,
      },
      {
        id: 'c2',
        type: 'dividing',
        points: [
          [0, 1, 0],
          [0, 1, 0.1],
        ],
        normals: [
          [0, 1, 0],
          [0, 1, 0],
        ],
        viewpoint: vp,
        sigma: 1,
        h: 0.5,
        alpha0: 0.1,
        alpha1: -0.2,
      },
    ],
    avoidScalp: true,
    fall: true,
    sections: true,
    detail: {
      curl: { radius: 0.05, frequency: 3, start: 0.15, randomOffset: 1 },
      frizz: { distance: 0.006, shape: 0.5 },
      lengthJitter: 0.15,
    },
  };
}

describe('parseSession', () => {
  it('accepts a session and gives back the same data', () => {
    const s = sample();
    const r = parseSession(JSON.parse(JSON.stringify(s)));
    expect(r.ok).toBe(true);
    if (r.ok) expect(r.value).toEqual(s);
  });

  it('a Save file (session + camera) with avoidScalp, fall and detail reads back as the session', () => {
    const s = sample();
    const text = JSON.stringify({ ...s, camera: vp }, null, 2);
    const r = parseSession(JSON.parse(text));
    expect(r.ok).toBe(true);
    if (!r.ok) return;
    expect(r.value).toEqual(s);
    expect(r.value.avoidScalp).toBe(true);
    expect(r.value.fall).toBe(true);
    expect(r.value.detail?.curl?.frequency).toBe(3);
    expect(r.value.detail).not.toHaveProperty('clump');
    // and the file of what was read is the same file
    expect(JSON.stringify({ ...r.value, camera: vp }, null, 2)).toBe(text);
  });

  it('reads a file saved by an earlier hairsketch (version 1: no surfaceMode, curve parameters, avoid)', () => {
    // the shape "Save" wrote before surface modes, curve parameters and "Avoid scalp" existed,
    // with the camera it writes beside the session
    const old = `{"version":1,"head":"builtin","grid":"25k","curves":[
      {"id":"c1","type":"stream","points":[[0,1,0],[0.1,1.1,0.05]],"extend":true,
       "viewpoint":{"position":[0,0,6],"target":[0,0,0]}},
      {"id":"c2","type":"dividing","points":[[0,1,0],[0,1,0.1]],"normals":[[0,1,0],[0,1,0]],
       "viewpoint":{"position":[0,0,6],"target":[0,0,0]}}],
      "growth":{"thetaStepDeg":1,"phiStepDeg":1,"jitter":0.8,"seed":20070807,"stepFraction":0.5,
       "minMagnitude":0.05,"maxLength":3.2,"maxSegments":120,"maxStrands":0},
      "hairColor":"#5a3825","camera":{"position":[2.6,0.9,7],"target":[0,-0.55,0]}}`;
    const r = parseSession(JSON.parse(old));
    expect(r.ok).toBe(true);
    if (!r.ok) return;
    expect(r.value.curves[0]).not.toHaveProperty('surfaceMode');
    expect(r.value.curves[1]).toMatchObject({ sigma: 1, h: 0.5, alpha0: 0, alpha1: 0 });
    expect(r.value.version).toBe(SESSION_VERSION);
    expect(r.value.head).toBe('builtin');
    expect(r.value).not.toHaveProperty('avoidScalp');
    expect(r.value).not.toHaveProperty('fall'); // made before natural fall: the paper's hair
    expect(r.value).not.toHaveProperty('avoid');
    expect(r.value).not.toHaveProperty('detail');
    expect(r.value).not.toHaveProperty('camera');
  });

  it('names the field of the first problem', () => {
    // biome-ignore lint/suspicious/noExplicitAny: edits arbitrary JSON to break it
    const bad = (edit: (j: any) => void) => {
      const j = JSON.parse(JSON.stringify(sample()));
      edit(j);
      const r = parseSession(j);
      return r.ok ? 'ok' : r.error;
    };
    expect(bad((j) => (j.curves[0].points[1][2] = 'x'))).toBe(
      'session.curves[0].points[1][2]: must be a finite number',
    );
    expect(bad((j) => (j.curves[0].points[1][2] = null))).toMatch(
      /points\[1\]\[2\]: must be a finite/,
    );
    expect(bad((j) => (j.curves[1].type = 'spiral'))).toMatch(/curves\[1\]\.type: must be/);
    expect(bad((j) => (j.curves[1].normals = [[0, 1, 0]]))).toMatch(/normals/);
    expect(bad((j) => (j.curves[1].id = 'c1'))).toMatch(/unique/);
    expect(bad((j) => (j.grid = '1e9'))).toMatch(/session\.grid/);
    expect(bad((j) => (j.growth.jitter = 5))).toMatch(/growth\.jitter: must be between 0 and 1/);
    expect(bad((j) => (j.avoid = { index: [1], target: [0, 0.3, 0] }))).toBe(
      'session.avoid: is not a field hairsketch knows',
    );
    expect(bad((j) => (j.avoidScalp = 'yes'))).toBe('session.avoidScalp: must be true or false');
    expect(bad((j) => (j.detail.curl.radius = 1))).toBe(
      'session.detail.curl.radius: must be between 0 and 0.5',
    );
    expect(bad((j) => (j.version = SESSION_VERSION + 1))).toMatch(
      /^session\.version: .*version 5 was made by a newer hairsketch/,
    );
    expect(bad((j) => (j.fall = 1))).toBe('session.fall: must be true or false');
    expect(parseSession(null)).toEqual({ ok: false, error: 'session: must be an object' });
  });
});

describe('curve parameters (protocol.ts CURVE_PARAMS)', () => {
  // biome-ignore lint/suspicious/noExplicitAny: edits arbitrary JSON
  const parse = (edit: (j: any) => void) => {
    const j = JSON.parse(JSON.stringify(sample()));
    edit(j);
    return parseSession(j);
  };

  it('checks every scalar against its range and names it', () => {
    for (const spec of CURVE_PARAMS.dividing) {
      const at = `session.curves[1].${spec.name}`;
      for (const bad of [spec.min - 1, spec.max + 1])
        expect(parse((j) => (j.curves[1][spec.name] = bad))).toEqual({
          ok: false,
          error: `${at}: must be between ${spec.min} and ${spec.max}`,
        });
      expect(parse((j) => (j.curves[1][spec.name] = 'x'))).toEqual({
        ok: false,
        error: `${at}: must be a finite number`,
      });
      const r = parse((j) => (j.curves[1][spec.name] = spec.max));
      expect(r.ok && (r.value.curves[1] as unknown as Record<string, number>)[spec.name]).toBe(
        spec.max,
      );
    }
  });

  it('gives a curve saved without a parameter its default (older sessions)', () => {
    const r = parse((j) => {
      delete j.curves[1].h;
    });
    expect(r.ok).toBe(true);
    if (r.ok) expect((r.value.curves[1] as { h: number }).h).toBe(0.5);
    // the ranges and defaults of the parameters saved sessions already carry
    expect(CURVE_PARAMS.dividing.map((p) => [p.name, p.default, p.min, p.max])).toEqual([
      ['sigma', 1, 0.05, 20],
      ['h', 0.5, 0, 20],
      ['alpha0', 0, -Math.PI, Math.PI],
      ['alpha1', 0, -Math.PI, Math.PI],
    ]);
    expect(CURVE_PARAMS.ponytail.map((p) => [p.name, p.default, p.min, p.max])).toEqual([
      ['tightness', 0.6, 0, 10],
      ['section', 1, 0, 1],
    ]);
  });
});

describe('session links', () => {
  it('round-trip a session (numbers to 1e-5)', async () => {
    const s = sample();
    const link = await encodeSessionLink(s);
    expect(link).toMatch(/^s=3\.[A-Za-z0-9_-]+$/);
    const r = await decodeSessionLink(`#${link}`);
    expect(r.ok).toBe(true);
    if (r.ok) {
      expect(r.value.curves.length).toBe(2);
      expect(r.value.curves[0].points[1][1]).toBeCloseTo(1.1, 5);
      expect(r.value.avoidScalp).toBe(true);
      expect(r.value.detail).toEqual(s.detail);
    }
  });

  it('say what is wrong with a damaged link', async () => {
    expect(await decodeSessionLink('#x=1')).toEqual({
      ok: false,
      error: 'the link holds no session (#s=…)',
    });
    expect((await decodeSessionLink('#s=%%%')) as { error: string }).toMatchObject({
      error: expect.stringMatching(/base64url/),
    });
    expect((await decodeSessionLink('#s=AAAA')) as { error: string }).toMatchObject({
      error: expect.stringMatching(/damaged/),
    });
    const link = await encodeSessionLink(sample());
    expect((await decodeSessionLink(`#${link.slice(0, link.length - 8)}`)).ok).toBe(false);
  });
});
