// The ties' band colour (session.bandColor): read, kept through files and links, one undoable
// edit; the default band is not written.
import { describe, expect, it } from 'vitest';
import { Editor } from '../../web/editor/editor';
import { DEFAULT_BAND_COLOR } from '../../web/model/hairLook';
import { readBandColor } from '../../web/model/readHairLook';
import { emptySession } from '../../web/model/session';
import { decodeSessionLink, encodeSessionLink } from '../../web/model/sessionLink';
import { parseSession } from '../../web/model/sessionRead';

describe('band colour', () => {
  it('reads #rrggbb in lowercase, absent as absent, and refuses anything else', () => {
    expect(readBandColor('#A0B0C0', 's.bandColor')).toEqual({ bandColor: '#a0b0c0' });
    expect(readBandColor(undefined, 's.bandColor')).toEqual({});
    expect(() => readBandColor('black', 's.bandColor')).toThrow(/bandColor/);
    expect(DEFAULT_BAND_COLOR).toBe('#1c1c1f');
  });

  it('is one undoable edit, the default stored as absent', () => {
    const e = new Editor(emptySession('25k'));
    const before = e.session;
    expect(e.run({ kind: 'setBandColor', color: '#D02060' })).toBe(true);
    expect(e.session.bandColor).toBe('#d02060');
    expect(e.session.curves).toBe(before.curves);
    expect(e.undo()).toBe(true);
    expect(e.session).toBe(before);
    e.run({ kind: 'setBandColor', color: '#d02060' });
    e.run({ kind: 'setBandColor', color: DEFAULT_BAND_COLOR });
    expect('bandColor' in e.session).toBe(false);
    const same = e.session;
    e.run({ kind: 'setBandColor', color: 'red' });
    expect(e.session).toBe(same);
  });

  it('goes through a session file and a share link', async () => {
    const s = { ...emptySession('25k'), bandColor: '#d02060' };
    const read = parseSession(JSON.parse(JSON.stringify(s)));
    expect(read.ok && read.value.bandColor).toBe('#d02060');
    const link = await decodeSessionLink(await encodeSessionLink(s));
    expect(link.ok && link.value.bandColor).toBe('#d02060');
    const plain = await decodeSessionLink(await encodeSessionLink(emptySession('25k')));
    expect(plain.ok && 'bandColor' in plain.value).toBe(false);
  });
});
