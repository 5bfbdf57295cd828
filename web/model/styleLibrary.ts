// The style library: everyday styles to start from, each a session drawn with the app's own tools
// (strokes, partings, ties and the panels' settings, with the mouse, by a new user: the fresh-eyes
// trials) and kept as a session file, public/styles/<id>.json, beside its picture,
// public/styles/<id>.png (`npm run pictures:styles` draws every picture from its file with
// `hairsketch render`). The app's "Styles" dialog lists them in this order.

export interface LibraryStyle {
  /** The session file's and the picture's name: public/styles/<id>.json, .png. */
  readonly id: string;
  /** What the dialog's button says. */
  readonly name: string;
  /** The view its picture is drawn from: the one that shows the style (a ponytail from the side,
   *  pigtails and a braid from behind). */
  readonly view: 'front' | 'side' | 'back';
}

export const STYLE_LIBRARY: readonly LibraryStyle[] = [
  { id: 'bob-fringe', name: 'Chin bob with a fringe', view: 'front' },
  { id: 'long-bob', name: 'Long bob', view: 'front' },
  { id: 'long-side-part', name: 'Long, side part', view: 'front' },
  { id: 'curtain-bangs', name: 'Long, curtain bangs', view: 'front' },
  { id: 'tucked', name: 'Tucked behind the ears', view: 'side' },
  { id: 'pixie', name: 'Pixie', view: 'side' },
  { id: 'short-crop', name: 'Short crop', view: 'side' },
  { id: 'slicked-back', name: 'Slicked back', view: 'side' },
  { id: 'long-curls', name: 'Long curls', view: 'front' },
  { id: 'coily', name: 'Coily', view: 'front' },
  { id: 'high-ponytail', name: 'High ponytail', view: 'side' },
  { id: 'low-ponytail', name: 'Low ponytail', view: 'back' },
  { id: 'side-ponytail', name: 'Side ponytail', view: 'front' },
  { id: 'pigtails', name: 'Pigtails', view: 'back' },
  { id: 'half-up', name: 'Half-up, half-down', view: 'side' },
  { id: 'top-bun', name: 'Top bun', view: 'side' },
  { id: 'low-bun', name: 'Low bun', view: 'back' },
  { id: 'braid', name: 'Braid', view: 'back' },
  { id: 'two-braids', name: 'Two braids', view: 'back' },
  { id: 'mohawk', name: 'Mohawk', view: 'side' },
];

/** Where a style's session file and picture are served from (relative to the app's page). */
export const styleFileUrl = (s: LibraryStyle): string => `styles/${s.id}.json`;
export const stylePictureUrl = (s: LibraryStyle): string => `styles/${s.id}.png`;
