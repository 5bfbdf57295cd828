// The embed's pieces that are plain logic: its query options, the editor address its link
// opens, the <iframe> snippet "Copy embed code" writes, and the still views' framing.
import { describe, expect, it } from 'vitest';
import { embedCode } from '../../web/app/sessionIO';
import { editorUrlFor, parseEmbedOptions } from '../../web/embed/embedOptions';
import { DEFAULT_CAMERA } from '../../web/viewer/defaultCamera';
import { framedAppView, highestPoint, lowestPoint, namedView } from '../../web/viewer/namedViews';

describe('the embed', () => {
  it('reads its options, ignoring unknown values', () => {
    expect(parseEmbedOptions('?still&view=side&quality=high')).toEqual({
      view: 'side',
      quality: 'high',
      still: true,
    });
    expect(parseEmbedOptions('?view=top&quality=ultra')).toEqual({
      view: null,
      quality: 'auto',
      still: false,
    });
  });

  it('links to the editor with the same session, and is framed by the snippet', () => {
    expect(editorUrlFor('https://x.org/app/embed.html?still#s=3.abc')).toBe(
      'https://x.org/app/#s=3.abc',
    );
    expect(embedCode('https://x.org/app/?preset=bob#s=3.a"b&c')).toBe(
      '<iframe src="https://x.org/app/embed.html#s=3.a%22b&amp;c" width="640" height="480" style="border:0" title="Hairstyle (hairsketch)" loading="lazy" allowfullscreen></iframe>',
    );
  });

  it("frames the front view as the app's starting view, and long hair from farther away", () => {
    const front = namedView('front', -1);
    for (let a = 0; a < 3; a++) {
      expect(front.position[a]).toBeCloseTo(DEFAULT_CAMERA.position[a], 9);
      expect(front.target[a]).toBeCloseTo(DEFAULT_CAMERA.target[a], 9);
    }
    const dist = (v: { position: number[]; target: number[] }) =>
      Math.hypot(...v.position.map((p, a) => p - v.target[a]));
    // hair down to y = -6: the picture's height grows from 3.6 to 7.2 units, so twice as far
    const long = namedView('front', -6);
    expect(dist(long) / dist(front)).toBeCloseTo(2, 6);
    expect(long.target[1]).toBeCloseTo(DEFAULT_CAMERA.target[1] - 1.8, 6);
    for (const v of ['side', 'back'] as const)
      expect(dist(namedView(v, -1))).toBeGreaterThan(0.5 * dist(front));
  });

  it("the app's view keys frame long hair as the still views do; short hair at the head's framing", () => {
    const home = DEFAULT_CAMERA;
    const dist = (v: { position: number[]; target: number[] }) =>
      Math.hypot(...v.position.map((p, a) => p - v.target[a]));
    for (const name of ['front', 'left', 'back'] as const) {
      // hair above the default floor (-2.4): the head's framing, the distance of the starting view
      const short = framedAppView(name, home, -1);
      expect(dist(short)).toBeCloseTo(dist(home), 9);
      expect(short.target).toEqual(home.target);
      // hair down to y = -6: framed to the step below it, -3.3 - 2 × 1.5 = -6.3: 7.5 units tall
      // against 3.6 (2.083 times as far), aimed (6.3 - 2.4) / 2 = 1.95 lower
      const long = framedAppView(name, home, -6);
      expect(dist(long) / dist(home)).toBeCloseTo(7.5 / 3.6, 6);
      expect(long.target[1]).toBeCloseTo(home.target[1] - 1.95, 6);
      // a stroke that lengthens the hair within a step keeps the view where it was; one past it
      // steps out
      expect(framedAppView(name, home, -5.0)).toEqual(long);
      expect(dist(framedAppView(name, home, -6.4))).toBeGreaterThan(dist(long));
      // down to the shoulders, the shoulders' framing (the bust's floor, -3.3)
      expect(framedAppView(name, home, -2.5)).toEqual(framedAppView(name, home, -3.3));
    }
    // the lowest point of strands and a floor
    expect(lowestPoint([0, -1, 0, 0, -3.5, 1], -2)).toBe(-3.5);
    expect(lowestPoint([], -2)).toBe(-2);
  });

  it('big hair above the head is framed whole: taller picture, aimed higher', () => {
    const dist = (v: { position: number[]; target: number[] }) =>
      Math.hypot(...v.position.map((p, a) => p - v.target[a]));
    const front = namedView('front', -1);
    // hair within the head's top (1.2): as before
    expect(namedView('front', -1, 1.1)).toEqual(front);
    // an afro up to y = 3: the picture spans -2.4 .. 3 (5.4 units against 3.6), so 1.5 times as
    // far, its middle 0.9 higher (from -0.6 to 0.3)
    const afro = namedView('front', -1, 3);
    expect(dist(afro) / dist(front)).toBeCloseTo(1.5, 6);
    expect(afro.target[1]).toBeCloseTo(front.target[1] + 0.9, 6);
    const key = framedAppView('left', DEFAULT_CAMERA, -1, 3);
    expect(dist(key) / dist(DEFAULT_CAMERA)).toBeCloseTo(1.5, 6);
    expect(key.target[1]).toBeCloseTo(DEFAULT_CAMERA.target[1] + 0.9, 6);
    expect(highestPoint([0, -1, 0, 0, 2.5, 1])).toBe(2.5);
    expect(highestPoint([0, 0.3, 0])).toBe(1.2);
  });
});
