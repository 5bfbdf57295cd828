// Fuzz target 4b: the reader of exports (readExportedSession) on random and damaged files.
import fc from 'fast-check';
import { readExportedSession } from '../../../web/export/readExport';
import { parseSession } from '../../../web/model/sessionFile';
import { binaryText, concat, type FuzzContext } from '../context';
import { show } from '../mutate';
import { check, checkMessage, type FuzzTarget, guard } from '../outcomes';

// ---- 4b. the reader of exports ------------------------------------------------------------------

export type ExportBytesCase =
  | { kind: 'random'; bytes: Uint8Array; magic: 'usda' | 'glb' | 'none' }
  | {
      kind: 'damaged';
      file: number;
      how: 'truncate' | 'flip' | 'insert';
      at: number;
      bit: number;
      text: string;
    }
  | { kind: 'usdaText'; value: string; key: number; quote: number; close: boolean };

const MAGIC = {
  usda: new TextEncoder().encode('#usda 1.0\n'),
  glb: new Uint8Array([0x67, 0x6c, 0x54, 0x46, 2, 0, 0, 0]),
  none: new Uint8Array(0),
};

function makeExportBytes(ctx: FuzzContext, c: ExportBytesCase): Uint8Array {
  switch (c.kind) {
    case 'random':
      return concat([MAGIC[c.magic], c.bytes]);
    case 'damaged': {
      const file = ctx.exports[c.file % ctx.exports.length];
      const at = c.at % (file.length + 1);
      if (c.how === 'truncate') return file.slice(0, at);
      if (c.how === 'insert')
        return concat([file.subarray(0, at), new TextEncoder().encode(c.text), file.subarray(at)]);
      const out = file.slice();
      if (out.length > 0) out[at % out.length] ^= 1 << (c.bit % 8);
      return out;
    }
    case 'usdaText': {
      const keys = ['"hairsketch:session"', "'hairsketch:session'", '"hairsketch:sessio"', 'def'];
      const quotes = ['"', "'", '"""', "'''"];
      const q = quotes[c.quote % quotes.length];
      const text = `#usda 1.0\n(\n  customLayerData = {\n    string ${keys[c.key % keys.length]} = ${q}${c.value}${c.close ? q : ''}\n  }\n)\n`;
      return new TextEncoder().encode(text);
    }
  }
}

export function exportReadTarget(ctx: FuzzContext): FuzzTarget<ExportBytesCase> {
  const arbitrary: fc.Arbitrary<ExportBytesCase> = fc.oneof(
    fc.record({
      kind: fc.constant('random' as const),
      bytes: fc.uint8Array({ maxLength: 300 }),
      magic: fc.constantFrom('usda', 'glb', 'none'),
    }),
    fc.record({
      kind: fc.constant('damaged' as const),
      file: fc.nat(),
      how: fc.constantFrom('truncate', 'flip', 'insert'),
      at: fc.nat(),
      bit: fc.nat(),
      text: fc.oneof(fc.constantFrom('"', "'", '\\', '\\x', '\\7', '\n', 'def '), fc.string()),
    }),
    fc.record({
      kind: fc.constant('usdaText' as const),
      value: fc.oneof(
        fc.string(),
        binaryText,
        fc.constantFrom('{}', '\\', '\\x', '\\x4', '\\777', '\\"', '{"version":1,"curves":[]}'),
      ),
      key: fc.nat(),
      quote: fc.nat(),
      close: fc.boolean(),
    }),
  );
  return {
    name: 'export reader',
    arbitrary,
    explain: (c) =>
      `${c.kind}: ${show(Buffer.from(makeExportBytes(ctx, c)).toString('latin1'), 400)}`,
    run(c) {
      const bytes = makeExportBytes(ctx, c);
      const r = guard('readExportedSession', () => readExportedSession(bytes));
      if (r === null) return 'rejected';
      check(typeof r === 'object' && typeof r.ok === 'boolean', () => `answered ${show(r)}`);
      if (!r.ok) {
        checkMessage(r.error, 'readExportedSession');
        return 'rejected';
      }
      // whatever it found goes through the strict reader, which must not throw either
      guard('parseSession', () => parseSession(r.session));
      return 'accepted';
    },
  };
}
