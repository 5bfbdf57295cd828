// Fuzz target 2: the share-link codec (decodeSessionLink, encodeSessionLink).
import { deflateRawSync } from 'node:zlib';
import fc from 'fast-check';
import {
  decodeSessionLink,
  encodeSessionLink,
  MAX_LINK_BYTES,
} from '../../../web/model/sessionLink';
import { binaryText, type FuzzContext } from '../context';
import { show } from '../mutate';
import { check, checkMessage, type FuzzTarget, guardAsync } from '../outcomes';
import {
  acceptedSession,
  checkReadsBack,
  makeSession,
  PLAIN_MUTATIONS,
  type SessionCase,
  sessionCase,
} from './session';

// ---- 2. the link codec -----------------------------------------------------------------------

export type LinkCase =
  | { kind: 'text'; prefix: string; text: string }
  | { kind: 'bytes'; prefix: string; bytes: Uint8Array; deflate: boolean }
  | { kind: 'json'; prefix: string; value: unknown }
  | { kind: 'session'; prefix: string; session: SessionCase }
  | {
      kind: 'damaged';
      link: number;
      how: 'truncate' | 'flipBit' | 'flipChar' | 'insert' | 'append';
      at: number;
      bit: number;
      text: string;
    }
  | { kind: 'bomb'; prefix: string; bytes: number }
  | { kind: 'encode'; session: SessionCase };

const b64url = (b: Uint8Array) => Buffer.from(b).toString('base64url');

function linkPrefixes(ctx: FuzzContext): string[] {
  const real = new Set(ctx.links.map((l) => /^[^=]*=(\d+\.)?/.exec(l)?.[0] ?? 's='));
  const out = ['#s=', 's=', '', '#', '#s', 's=2.', 's=1.', '#s=9.', 'x=', '#S='];
  for (const p of real) out.push(p, `#${p}`);
  return [...new Set(out)];
}

const bombs = new Map<number, Uint8Array>();
function bomb(size: number): Uint8Array {
  let b = bombs.get(size);
  if (!b) {
    b = deflateRawSync(new Uint8Array(size).fill(0x20));
    bombs.set(size, b);
  }
  return b;
}

function makeLink(ctx: FuzzContext, c: LinkCase): string {
  switch (c.kind) {
    case 'text':
      return c.prefix + c.text;
    case 'bytes':
      return c.prefix + b64url(c.deflate ? deflateRawSync(c.bytes) : c.bytes);
    case 'json':
      return c.prefix + b64url(deflateRawSync(Buffer.from(JSON.stringify(c.value) ?? 'null')));
    case 'session': {
      const { input } = makeSession(ctx, c.session, PLAIN_MUTATIONS);
      return c.prefix + b64url(deflateRawSync(Buffer.from(JSON.stringify(input) ?? 'null')));
    }
    case 'bomb':
      return c.prefix + b64url(bomb(c.bytes));
    case 'damaged': {
      const link = ctx.links[c.link % ctx.links.length];
      const at = link.length === 0 ? 0 : c.at % link.length;
      switch (c.how) {
        case 'truncate':
          return link.slice(0, at);
        case 'flipChar': {
          const alphabet = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_';
          return link.slice(0, at) + alphabet[c.bit % 64] + link.slice(at + 1);
        }
        case 'flipBit': {
          // a bit of the payload (after the prefix), re-encoded
          const m = /^([^=]*=(?:\d+\.)?)(.*)$/.exec(link);
          if (!m) return link;
          const bytes = Buffer.from(m[2], 'base64url');
          if (bytes.length === 0) return link;
          const i = c.at % bytes.length;
          bytes[i] ^= 1 << (c.bit % 8);
          return m[1] + b64url(bytes);
        }
        case 'insert':
          return link.slice(0, at) + c.text + link.slice(at);
        case 'append':
          return link + c.text;
      }
      return link;
    }
    case 'encode':
      return '';
  }
}

export function linkTarget(ctx: FuzzContext): FuzzTarget<LinkCase> {
  const prefix = fc.constantFrom(...linkPrefixes(ctx));
  const arbitrary: fc.Arbitrary<LinkCase> = fc.oneof(
    {
      weight: 20,
      arbitrary: fc.record({
        kind: fc.constant('text' as const),
        prefix,
        text: fc.oneof(
          fc.string({ maxLength: 60 }),
          binaryText,
          fc.stringMatching(/^[A-Za-z0-9_-]{0,80}$/),
        ),
      }),
    },
    {
      weight: 20,
      arbitrary: fc.record({
        kind: fc.constant('bytes' as const),
        prefix,
        bytes: fc.uint8Array({ maxLength: 200 }),
        deflate: fc.boolean(),
      }),
    },
    {
      weight: 10,
      arbitrary: fc.record({ kind: fc.constant('json' as const), prefix, value: fc.jsonValue() }),
    },
    {
      weight: 20,
      arbitrary: fc.record({
        kind: fc.constant('session' as const),
        prefix,
        session: sessionCase(ctx, PLAIN_MUTATIONS),
      }),
    },
    {
      weight: 40,
      arbitrary: fc.record({
        kind: fc.constant('damaged' as const),
        link: fc.nat(),
        how: fc.constantFrom('truncate', 'flipBit', 'flipChar', 'insert', 'append'),
        at: fc.nat(),
        bit: fc.nat(),
        text: fc.oneof(fc.constantFrom('=', '%2B', ' ', '\n', '#s=', '.', '..'), fc.string()),
      }),
    },
    {
      weight: 1,
      arbitrary: fc.record({
        kind: fc.constant('bomb' as const),
        prefix,
        bytes: fc.constantFrom(MAX_LINK_BYTES - 1024, MAX_LINK_BYTES + 1),
      }),
    },
    {
      weight: 30,
      arbitrary: fc.record({
        kind: fc.constant('encode' as const),
        session: sessionCase(ctx, PLAIN_MUTATIONS),
      }),
    },
  );
  return {
    name: 'link codec',
    arbitrary,
    explain(c) {
      if (c.kind === 'encode' || c.kind === 'session')
        return `${c.kind}: ${makeSession(ctx, c.session, PLAIN_MUTATIONS).log.join('; ')}`;
      return `${c.kind}: ${show(makeLink(ctx, c), 400)}`;
    },
    async run(c) {
      if (c.kind === 'encode') {
        const session = acceptedSession(ctx, c.session);
        const l1 = await guardAsync('encodeSessionLink', () => encodeSessionLink(session));
        check(typeof l1 === 'string', () => `encodeSessionLink gave ${show(l1)}`);
        check(/^[A-Za-z0-9_.=-]*$/.test(l1), () => `the link is not URL-safe: ${show(l1)}`);
        const d1 = await guardAsync('decodeSessionLink', () => decodeSessionLink(l1));
        check(d1.ok, () => `the link of an accepted session is refused: ${show(d1)}`);
        checkReadsBack(d1.value, 'decodeSessionLink');
        const l2 = await guardAsync('encodeSessionLink', () => encodeSessionLink(d1.value));
        check(l2 === l1, () => `re-encoding changes the link: ${show(l1)} → ${show(l2)}`);
        return 'accepted';
      }
      const link = makeLink(ctx, c);
      const r = await guardAsync('decodeSessionLink', () => decodeSessionLink(link));
      if (!r.ok) {
        checkMessage(r.error, 'decodeSessionLink');
        return 'rejected';
      }
      checkReadsBack(r.value, 'decodeSessionLink');
      return 'accepted';
    },
  };
}
