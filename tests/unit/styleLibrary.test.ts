// The style library (model/styleLibrary.ts): every style has a session file the strict reader
// accepts, on the built-in head, with the strokes it was drawn with, and a PNG picture of the
// size the script draws; ids are unique and nothing in public/styles is left out of the list.
import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { parseSession } from '../../web/model/sessionFile';
import { STYLE_LIBRARY } from '../../web/model/styleLibrary';

const dir = new URL('../../public/styles/', import.meta.url);

describe('the style library', () => {
  it('lists every file in public/styles once, each with a valid session and its picture', () => {
    const ids = STYLE_LIBRARY.map((s) => s.id);
    expect(new Set(ids).size).toBe(ids.length);
    const files = readdirSync(dir).sort();
    expect(files).toEqual(ids.flatMap((id) => [`${id}.json`, `${id}.png`]).sort());
    for (const s of STYLE_LIBRARY) {
      const r = parseSession(JSON.parse(readFileSync(new URL(`${s.id}.json`, dir), 'utf8')));
      if (!r.ok) throw new Error(`${s.id}: ${r.error}`);
      expect(r.value.head, s.id).toBe('builtin');
      expect(r.value.curves.length, s.id).toBeGreaterThan(0);
      const png = readFileSync(new URL(`${s.id}.png`, dir));
      // PNG signature, then IHDR's width and height (big-endian) at bytes 16 and 20
      expect([...png.subarray(1, 4)].map((c) => String.fromCharCode(c)).join(''), s.id).toBe('PNG');
      expect([png.readUInt32BE(16), png.readUInt32BE(20)], s.id).toEqual([256, 256]);
    }
  });
});
