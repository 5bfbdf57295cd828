// The detail blocks presets start with (model/detail.ts): the `curly` preset's curls and a new
// session's natural detail (presets.ts applies them).
import { defaultBlock, type HairDetail } from './detail';

/** The `curly` preset's detail: 3B ringlets (0.8 cm, 3.4 turns per 10 cm, the type's middle)
 *  gathered tight into locks 1.2 cm apart, a little frizz, uneven ends. 3A curls (0.9 cm, 2.4
 *  turns) onto locks 1.6 cm apart read as rows of sausage curls (a judge: "a barrister's wig");
 *  drawn 0.7 of the way onto locks 1.2 cm apart, as "rows of flat scallops, like fish scales". */
export const CURLY_DETAIL: HairDetail = {
  curl: { radius: 0.08, frequency: 3.4, start: 0.12, randomOffset: 1 },
  clump: { factor: 0.92, shape: 0.15, tipSpread: 0.01, guideDistance: 0.12 },
  frizz: { distance: 0.003, shape: 0.5 },
  lengthJitter: 0.25,
};

/** The detail a new session (the `empty` preset) and the presets other than the paper's figures
 *  start with, so hair at arm's length reads as strands and locks rather than the smooth shell a
 *  smooth field grows: strands drawn onto locks about 2.5 cm apart, more towards the tips (most of
 *  the way there, 4 mm round the lock), so lengths part into pieces and the ends break up; ends a
 *  little uneven and a few flyaways (DETAIL_PARAMS' defaults: 1 % of the strands). Chosen by eye
 *  from renders of the long, bob and default presets, front, side and back: half-way onto locks
 *  1.5 cm apart, long hair still read as "a tube with straight sides" from behind; with 2 mm
 *  round the lock a bob's hem ended in spikes. */
export const NEW_SESSION_DETAIL: HairDetail = {
  clump: { factor: 0.8, shape: 0.5, tipSpread: 0.04, guideDistance: 0.25 },
  flyaway: defaultBlock('flyaway'),
  lengthJitter: 0.1,
};
