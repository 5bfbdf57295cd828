// The tools of the ties drawn as one stroke (curveParams.ts PLAIN_TIE_KINDS): one row each says
// how its stroke is drawn, its button, key and hint, and how the status line names a new one.
// tools.ts builds a tool from each row and actions.ts a toolbar button; a new plain tie kind's
// row is required here by the compiler.
import type { PlainTieKind } from '../model/curveParams';
import type { Vec3 } from '../model/vec3';

export interface TieToolSpec {
  /** How its stroke is drawn: `spine` as a stream curve is (from the scalp, the depth rule past
   *  it; previewed as the tie it makes), `loop` a closed loop on the head. */
  readonly draw: 'spine' | 'loop';
  readonly label: string;
  readonly key: string;
  /** The button's tooltip. */
  readonly title: string;
  /** The hint line while the tool is chosen. */
  readonly hint: string;
  /** The status line's name of a new one from its stroke's points (`{id}`: its id). */
  what(points: readonly Vec3[]): string;
}

export const TIE_TOOLS: { readonly [K in PlainTieKind]: TieToolSpec } = {
  braid: {
    draw: 'spine',
    label: 'Braid',
    key: 'k',
    title:
      'One stroke from the scalp along where the braid should hang, scalp to tip; the hair near it is gathered into a three-strand braid',
    hint: 'Drag from the scalp along where the braid should hang, scalp to tip · right-drag orbits · ? lists shortcuts',
    what: (p) => `braid {id} (${p.length - 1} segments)`,
  },
  bun: {
    draw: 'loop',
    label: 'Bun',
    key: 'u',
    title:
      'Draw a loop on the head where the bun sits; the hair near it is gathered and coiled into it',
    hint: 'Draw a loop on the head where the bun sits · right-drag orbits · ? lists shortcuts',
    // its length round (world units are 10 cm), not its resampled points: fresh eyes read "a loop
    // of 10 points" for a loop of 80 pointer moves as their loop cut short
    what: (p) => `bun {id} (a loop ${Math.round(10 * loopLength(p))} cm round)`,
  },
};

/** The plain tie kinds in table order. */
export const TIE_TOOL_KINDS = Object.keys(TIE_TOOLS) as PlainTieKind[];

/** A closed loop's length: its segments and the one back to its start. */
function loopLength(p: readonly Vec3[]): number {
  let l = 0;
  for (let i = 0; i < p.length; i++) {
    const a = p[i];
    const b = p[(i + 1) % p.length];
    l += Math.hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  }
  return l;
}
