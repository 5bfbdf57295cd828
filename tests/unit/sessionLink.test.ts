// Share links (web/model/sessionLink.ts): version 3 reopens every preset deep-equal to its
// quantised session (quantize.ts) in a link short enough for a chat; version 1 links still
// open; deflate bombs and over-long links are refused fast; every kind of damage gives a
// sentence, never a throw.
import { createDeflateRaw } from 'node:zlib';
import { describe, expect, it } from 'vitest';
import { presetSession } from '../../web/cli/presetSession';
import { Head } from '../../web/head/head';
import { DIRECTION_SCALE, POSITION_SCALE, quantize } from '../../web/model/gridNumbers';
import { X_PLANE } from '../../web/model/mirror';
import { PRESET_NAMES } from '../../web/model/presets';
import { quantizeCurve, quantizeSession } from '../../web/model/quantize';
import { emptySession, type SessionState } from '../../web/model/session';
import {
  crc32,
  decodeSessionLink,
  encodeSessionLink,
  encodeSessionLinkV1,
  MAX_LINK_CHARS,
  packSession,
  toBase64Url,
  unpackSession,
} from '../../web/model/sessionLink';
import { SESSION_VERSION } from '../../web/model/sessionMigrations';
import type { Vec3 } from '../../web/model/vec3';

const head = Head.builtin();

/** What a link reopens: the quantised session (detail travels as written, in the JSON tail). */
const reopened = (s: SessionState): SessionState => quantizeSession(s);

const DETAIL = {
  curl: { radius: 0.05, frequency: 3.1234567, start: 0.15, randomOffset: 1 },
  clump: { factor: 0.5, shape: -0.3, tipSpread: 0.02, guideDistance: 0.12 },
  frizz: { distance: 0.006, shape: 0.5 },
  lengthJitter: 0.15,
};

async function roundTrip(s: SessionState): Promise<SessionState> {
  const link = await encodeSessionLink(s);
  expect(link).toMatch(/^s=3\.[A-Za-z0-9_-]+$/);
  const r = await decodeSessionLink(`#${link}`);
  if (!r.ok) throw new Error(r.error);
  return r.value;
}

/** A session with every field set away from its default, off the grid. */
function everything(): SessionState {
  const jitter = (p: Vec3, k: number): Vec3 => [
    p[0] + 1.234567e-6 * k,
    p[1] - 7.654321e-7 * k,
    p[2] + Math.PI * 1e-6,
  ];
  const line = (x: number, n: number): Vec3[] =>
    Array.from({ length: n }, (_, i) => jitter([x + 0.01 * i * i, 1 - 0.1 * i, 0.5], i));
  const vp = { position: [0.1234567, -0.2, 6.5] as Vec3, target: [0, 0.3333333, 0] as Vec3 };
  return {
    ...emptySession('100k', {
      thetaStepDeg: 0.7,
      phiStepDeg: 1.3,
      jitter: 0.25,
      seed: 4294967295,
      stepFraction: 0.45,
      minMagnitude: 0.07,
      maxLength: 2.9,
      maxSegments: 333,
      maxStrands: 12345,
    }),
    hairColor: '#A0b1C2',
    curves: [
      { id: 'c1', type: 'stream', points: line(0, 12), extend: true, viewpoint: vp },
      {
        id: 'my-curve_7',
        type: 'stream',
        points: line(0.3, 5),
        extend: false,
        viewpoint: { position: [3, 1, 4], target: [0, -0.1, 0] },
        surfaceMode: 'strip',
      },
      {
        id: 'c3',
        type: 'stream',
        points: line(-0.3, 2),
        extend: true,
        viewpoint: vp,
        surfaceMode: 'ruled',
      },
      {
        id: 'c9',
        type: 'dividing',
        points: line(0.1, 7),
        normals: line(0.1, 7).map((_, i) => [Math.sin(i / 3), Math.cos(i / 3), 1e-7] as Vec3),
        viewpoint: vp,
        sigma: 1.2345678,
        h: 0.3,
        alpha0: -1.0471975,
        alpha1: Math.PI,
      },
      {
        id: 'c10',
        type: 'ponytail',
        points: line(0.5, 9),
        extend: true,
        viewpoint: vp,
        crossSection: line(0.6, 4),
        profiles: [line(0.7, 6), line(0.8, 2)],
        circles: Array.from({ length: 5 }, (_, i) => ({
          centre: jitter([0.5, 1 - 0.2 * i, 0.5], i),
          axis: [0, -0.99999, 0.0044721] as Vec3,
          radius: 0.1 + 0.0123456 * i,
          spineIndex: 2 * i,
        })),
        tightness: 0.6123456,
        section: 1,
      },
    ],
    avoidScalp: true,
    detail: DETAIL,
  };
}

describe('quantize.ts', () => {
  it('is idempotent and keeps the identity of what is already on the grid', () => {
    const q = quantizeSession(everything());
    expect(quantizeSession(q)).toBe(q);
    for (const c of q.curves) expect(quantizeCurve(c)).toBe(c);
    expect(q.curves[0].points[3][2]).toBe(quantize(0.5 + Math.PI * 1e-6, POSITION_SCALE));
    expect(q.hairColor).toBe('#a0b1c2');
    // an edit of one curve leaves the others as they were (same objects)
    const s = { ...q, curves: [...q.curves.slice(0, 4), { ...q.curves[4], tightness: 0.1234567 }] };
    const r = quantizeSession(s as SessionState);
    expect(r.curves.slice(0, 4).every((c, i) => c === q.curves[i])).toBe(true);
    expect((r.curves[4] as { tightness: number }).tightness).toBe(0.1235);
  });

  it('never gives -0 and clamps absurd numbers', () => {
    expect(Object.is(quantize(-1e-9, POSITION_SCALE), 0)).toBe(true);
    expect(quantize(1e300, DIRECTION_SCALE)).toBe(1e6);
  });
});

describe('version 2 links', () => {
  it.each(PRESET_NAMES)('reopen preset %s deep-equal to its quantised session', async (name) => {
    const s = presetSession(name, head);
    expect(quantizeSession(s)).toBe(s); // presets are built on the grid
    expect(await roundTrip(s)).toEqual(reopened(s));
  });

  it('reopen every field of a session, numbers on the grid of quantize.ts', async () => {
    const s = everything();
    const back = await roundTrip(s);
    expect(back).toEqual(reopened(s));
    // the same link from the session and from its quantised self; reopening changes nothing
    expect(await encodeSessionLink(s)).toBe(await encodeSessionLink(reopened(s)));
    expect(await roundTrip(back)).toEqual(back);
    expect(back.avoidScalp).toBe(true);
    expect(back.detail).toEqual(DETAIL);
    // avoid scalp off (absent or false) and no detail reopen as absent
    const { avoidScalp: _a, detail: _d, ...plain } = s;
    const off = await roundTrip({ ...plain, avoidScalp: false });
    expect(Object.keys(off)).not.toContain('avoidScalp');
    expect(Object.keys(off)).not.toContain('detail');
    expect(off).toEqual(reopened(plain));
  });

  it('write the avoid slot empty: avoidScalp, fall and detail travel in the JSON tail', () => {
    const s = everything();
    const data = unpackSession(packSession(s));
    expect(data.version).toBe(SESSION_VERSION);
    expect(data).not.toHaveProperty('avoid');
    expect(data.avoidScalp).toBe(true);
    expect(data.fall).toBe(true);
    expect(data.detail).toEqual(DETAIL);
    // without them the tail is empty: the body ends with the avoid slot 0, tail length 0, CRC
    const {
      avoidScalp: _a,
      detail: _d,
      fall: _f,
      sections: _s,
      finish: _e,
      bust: _b,
      hairLook: _l,
      locks: _k,
      ...plain
    } = presetSession('default', head);
    const body = packSession(plain);
    expect(Array.from(body.subarray(body.length - 6, body.length - 4))).toEqual([0, 0]);
  });

  it("carry a curve's own detail (in the JSON tail)", async () => {
    const s = everything();
    const curves = s.curves.map((c, i) =>
      i === 1 ? { ...c, detail: { frizz: DETAIL.frizz } } : i === 3 ? { ...c, detail: {} } : c,
    );
    const withOwn = { ...s, curves };
    const data = unpackSession(packSession(withOwn)) as { curves: Record<string, unknown>[] };
    expect(data.curves[1].detail).toEqual({ frizz: DETAIL.frizz });
    expect(data.curves[3].detail).toEqual({});
    expect(data.curves[0]).not.toHaveProperty('detail');
    expect(await roundTrip(withOwn)).toEqual(reopened(withOwn));
  });

  it('carry fields the layout has no place for in the JSON tail', () => {
    const s = { ...everything(), futureField: { a: 1 } } as SessionState;
    (s.curves[0] as unknown as Record<string, unknown>).note = 'kept';
    const data = unpackSession(packSession(s)) as Record<string, unknown>;
    expect(data.futureField).toEqual({ a: 1 });
    expect((data.curves as Record<string, unknown>[])[0].note).toBe('kept');
    // a tail cannot set an object's prototype
    expect(Object.getPrototypeOf(data)).toBe(Object.prototype);
  });

  it('of the default preset fit in 2,000 characters (a chat message)', async () => {
    const s = presetSession('default', head);
    const v2 = await encodeSessionLink(s);
    const v1 = await encodeSessionLinkV1(s);
    console.log(
      `default preset link: version 3 ${v2.length + 1} characters (#${v2.slice(0, 12)}…), version 1 ${v1.length + 1}`,
    );
    for (const name of PRESET_NAMES)
      console.log(`  ${name}: ${(await encodeSessionLink(presetSession(name, head))).length + 1}`);
    expect(v2.length + 1).toBeLessThanOrEqual(2000); // with the '#'
    expect(v2).toMatch(/^s=3\.[A-Za-z0-9_-]+$/); // URL-safe, no line breaks
  });
});

describe('version 1 links', () => {
  it('still open (numbers to 1e-5)', async () => {
    for (const name of ['default', 'fig1'] as const) {
      const s = presetSession(name, head);
      const link = await encodeSessionLinkV1(s);
      expect(link).toMatch(/^s=[A-Za-z0-9_-]+$/);
      const r = await decodeSessionLink(`#${link}`);
      if (!r.ok) throw new Error(r.error);
      expect(r.value.curves.length).toBe(s.curves.length);
      let worst = 0;
      r.value.curves.forEach((c, i) => {
        c.points.forEach((p, j) => {
          p.forEach((x, a) => {
            worst = Math.max(worst, Math.abs(x - s.curves[i].points[j][a]));
          });
        });
      });
      expect(worst).toBeLessThan(6e-6);
      expect({ ...r.value, curves: [] }).toEqual({ ...reopened(s), curves: [] });
    }
  });

  it('with scalp-avoidance constraints open with avoidScalp on (migrated from version 1)', async () => {
    const s = presetSession('fig6', head);
    const v1 = { ...s, version: 1, avoid: { index: [3, 7], target: [0, 0.3, 0, 0.3, 0, 0] } };
    const r = await decodeSessionLink(
      `#${await encodeSessionLinkV1(v1 as unknown as SessionState)}`,
    );
    if (!r.ok) throw new Error(r.error);
    expect(r.value.version).toBe(SESSION_VERSION);
    expect(r.value.avoidScalp).toBe(true);
    expect(r.value).not.toHaveProperty('avoid');
    expect({ ...r.value, curves: [] }).toEqual({ ...reopened(s), avoidScalp: true, curves: [] });
    // null constraints: avoid scalp off
    const none = { ...s, version: 1, avoid: null } as unknown as SessionState;
    const n = await decodeSessionLink(`#${await encodeSessionLinkV1(none)}`);
    expect(n.ok && Object.keys(n.value)).not.toContain('avoidScalp');
  });
});

describe('version 2 links made before session version 2 (constraints in the avoid slot)', () => {
  /** A varint and a zigzag varint, as the layout comment states them (written here by hand). */
  const varint = (n: number): number[] => {
    const out: number[] = [];
    for (;;) {
      if (n < 128) return [...out, n];
      out.push((n % 128) | 128);
      n = Math.floor(n / 128);
    }
  };
  const zigzag = (n: number) => varint(n >= 0 ? 2 * n : -2 * n - 1);

  it('open as version 1 sessions with avoidScalp on', async () => {
    // the bust and the colour model would go in the JSON tail
    // (and the streams' own Volume, a parameter version 2 cannot hold)
    const { bust: _b, hairLook: _l, ...p } = presetSession('fig7', head);
    const s = {
      ...p,
      curves: p.curves.map((c) => {
        if (c.type !== 'stream') return c;
        const { volume: _v, ...rest } = c;
        return rest as typeof c;
      }),
    };
    const body = packSession(s, 2);
    // no tail: the body ends with the avoid slot (0), the tail length (0) and the CRC
    const before = body.subarray(0, body.length - 6);
    expect(Array.from(body.subarray(body.length - 6, body.length - 4))).toEqual([0, 0]);
    // two constraints: grid points 3 and 7, targets (0, 0.3, 0) and (0.3, 0, -0.15)
    const avoid = [
      ...varint(2 + 1),
      ...zigzag(3),
      ...zigzag(7 - 3),
      ...zigzag(0),
      ...zigzag(3000),
      ...zigzag(0),
      ...zigzag(3000 - 0),
      ...zigzag(0 - 3000),
      ...zigzag(-1500 - 0),
    ];
    const old = new Uint8Array([...before, ...avoid, 0]);
    const data = unpackSession(withCrc(old), 2);
    expect(data.version).toBe(1);
    expect(data.avoid).toEqual({ index: [3, 7], target: [0, 0.3, 0, 0.3, 0, -0.15] });
    const r = await decodeSessionLink(await linkOf(withCrc(old)));
    if (!r.ok) throw new Error(r.error);
    expect(r.value).toEqual({ ...reopened(s), avoidScalp: true });
    // the same body with an empty slot is the session itself
    const same = await decodeSessionLink(await linkOf(body));
    expect(same.ok && same.value).toEqual(reopened(s));
  });
});

/** deflate-raw of `size` zero bytes, made in pieces (never `size` bytes in memory). */
async function zeroBomb(size: number): Promise<Uint8Array> {
  const z = createDeflateRaw({ level: 9 });
  const out: Buffer[] = [];
  z.on('data', (b: Buffer) => out.push(b));
  const done = new Promise((res) => z.on('end', res));
  const chunk = Buffer.alloc(1 << 20);
  for (let left = size; left > 0; left -= chunk.length) {
    const piece = left >= chunk.length ? chunk : chunk.subarray(0, left);
    if (!z.write(piece)) await new Promise((res) => z.once('drain', res));
  }
  z.end();
  await done;
  return new Uint8Array(Buffer.concat(out));
}

function v2Fragment(deflated: Uint8Array): string {
  // the length prefix of encodeSessionLink: a varint of the deflated size
  const head: number[] = [];
  for (let v = deflated.length; ; v = Math.floor(v / 128)) {
    if (v < 128) {
      head.push(v);
      break;
    }
    head.push((v % 128) | 128);
  }
  return `#s=2.${toBase64Url(new Uint8Array([...head, ...deflated]))}`;
}

/** A body with its CRC-32 appended. */
function withCrc(b: Uint8Array): Uint8Array {
  const out = new Uint8Array(b.length + 4);
  out.set(b);
  new DataView(out.buffer).setUint32(b.length, crc32(b), true);
  return out;
}

/** The version 2 fragment of a body (deflated here, not by the codec). */
async function linkOf(b: Uint8Array): Promise<string> {
  const cs = new Response(
    new Blob([b as BlobPart]).stream().pipeThrough(new CompressionStream('deflate-raw')),
  );
  return v2Fragment(new Uint8Array(await cs.arrayBuffer()));
}

describe('caps', () => {
  it('refuse deflate bombs while inflating, fast', async () => {
    // (tests/e2e/links.spec.ts opens a 1 GiB bomb in the app)
    for (const [label, size] of [['100 MB', 100e6]] as const) {
      const bomb = await zeroBomb(size);
      for (const fragment of [`#s=${toBase64Url(bomb)}`, v2Fragment(bomb)]) {
        expect(fragment.length).toBeLessThan(MAX_LINK_CHARS); // the length cap lets it through
        const t0 = performance.now();
        const r = await decodeSessionLink(fragment);
        const ms = performance.now() - t0;
        console.log(
          `${label} of zeros (${fragment.length.toLocaleString('en-US')} characters, ${fragment.slice(0, 5)}…): refused in ${ms.toFixed(0)} ms`,
        );
        expect(r).toEqual({ ok: false, error: 'the session link is too large' });
      }
    }
  }, 60_000);

  it('refuse an over-long link before decoding it', async () => {
    const r = await decodeSessionLink(`#s=2.${'A'.repeat(MAX_LINK_CHARS)}`);
    expect(r.ok).toBe(false);
    if (!r.ok) expect(r.error).toMatch(/too long \(2,000,005 characters; at most 2,000,000\)/);
  });
});

describe('damaged links say what is wrong', () => {
  const bad = async (fragment: string, error: RegExp) => {
    const r = await decodeSessionLink(fragment);
    expect(r.ok, fragment.slice(0, 40)).toBe(false);
    if (!r.ok) expect(r.error).toMatch(error);
  };

  it('no session, bad base64url, wrong version', async () => {
    await bad('#x=1', /holds no session/);
    await bad('#s=2.%%%', /damaged \(not base64url\)/);
    await bad('#s=2.ab cd', /damaged \(not base64url\)/);
    await bad('#s=2.abcd\nefgh', /damaged \(not base64url\)/);
    await bad('#s=2.abcde', /cut short/);
    await bad('#s=2.', /damaged \(not base64url\)/);
    await bad('#s=4.AAAA', /version 4; this app opens versions 1, 2 and 3/);
    await bad('#s=0.AAAA', /version 0/);
  });

  it('truncated, extended, flipped', async () => {
    const original = presetSession('fig1', head);
    const link = `#${await encodeSessionLink(original)}`;
    for (const cut of [1, 2, 4, 8, 100, link.length - 8]) await bad(link.slice(0, -cut), /damaged/);
    await bad(link.slice(0, -4), /cut short \(\d+ of \d+ bytes\)/);
    await bad(`${link}AAAA`, /3 bytes too many at the end/);
    await bad(`${link}x`, /cut short\?|too many at the end/);
    // one character changed anywhere: never a throw, never a wrong session (a change in the
    // deflate stream's unused last bits inflates to the same bytes: the same session is right)
    const alphabet = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_';
    let damaged = 0;
    for (let i = 8; i < link.length; i += 7) {
      const c = alphabet[(alphabet.indexOf(link[i]) + 1 + (i % 63)) % 64];
      const r = await decodeSessionLink(`${link.slice(0, i)}${c}${link.slice(i + 1)}`);
      if (r.ok) expect(r.value, `changed at ${i} of ${link.length}`).toEqual(original);
      else {
        expect(r.error).toMatch(/damaged/);
        damaged++;
      }
    }
    expect(damaged).toBeGreaterThan(100);
  });

  it('a body that inflates but does not fit the layout', async () => {
    const body = packSession(presetSession('fig8', head), 2);
    const link = linkOf;
    const payload = body.subarray(0, body.length - 4);
    // after the JSON tail: the optional parts (a mask), then nothing
    await bad(await link(withCrc(new Uint8Array([...payload, 8]))), /parts this app does not know/);
    await bad(await link(withCrc(new Uint8Array([...payload, 0]))), /parts this app does not know/);
    await bad(await link(withCrc(new Uint8Array([...payload, 7]))), /ends too early/);
    const withPlane = packSession({ ...presetSession('fig8', head), symmetry: X_PLANE }, 2);
    await bad(
      await link(withCrc(new Uint8Array([...withPlane.subarray(0, withPlane.length - 4), 1]))),
      /data past its end/,
    );
    await bad(
      await link(withCrc(payload.subarray(0, payload.length - 5))),
      /ends too early|larger than the data/,
    );
    await bad(await link(withCrc(new Uint8Array([9, ...payload.subarray(1)]))), /unknown grid/);
    await bad(await link(payload), /checksum does not match/);
    await bad(await link(new Uint8Array(0)), /ends too early|does not inflate/);
    // a well-formed body whose session the strict reader refuses
    const s = presetSession('default', head);
    const twin = { ...s, curves: [s.curves[0], s.curves[0]] };
    await bad(`#${await encodeSessionLink(twin)}`, /invalid: session\.curves.*unique/);
  });
});
