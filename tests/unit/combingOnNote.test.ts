// What the status line says of a stroke that ends on the scalp (web/app/tools.ts combingOnNote):
// the hair's length is the stroke's, or Max length when that is shorter.
import { describe, expect, it } from 'vitest';
import { combingOnNote } from '../../web/app/tools';

describe('combingOnNote', () => {
  it("says the stroke's length when Max length allows it", () => {
    expect(combingOnNote(11.2, 32)).toContain('about as long as the stroke, 11 cm');
  });
  it('says Max length when the stroke is longer than it', () => {
    const note = combingOnNote(11.2, 5);
    expect(note).toContain('its hair is 5 cm, Max length');
    expect(note).not.toContain('about as long as the stroke');
  });
  it('says the strokes that end hair set the length when there are any', () => {
    const note = combingOnNote(11.2, 32, true);
    expect(note).toContain('takes its length from the strokes that end hair');
    expect(note).not.toContain('11 cm');
  });
});
