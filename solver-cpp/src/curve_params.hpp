// Scalar parameters of each curve kind: their index in a curve's parameter block (protocol.ts
// CurveSet.params), in the order of curveParams.ts CURVE_PARAMS, which declares their names,
// defaults and ranges. A kind's variable block (dividing normals, ponytail circles) follows its
// scalars. Adding a scalar: a row in CURVE_PARAMS, an index here (before the count), and the
// code that reads it.
#pragma once

#include <cstddef>

namespace hairsketch {

// Stream curves (S4.1): the curve's own Volume (world units; 0: none, the session's Volume
// applies; with the shape rules the hair around it stands off the head by this much).
enum StreamParam : size_t { kStreamParamVolume, kStreamParamCount };

// Dividing curves (S4.5): sigma, h in grid steps; alpha0, alpha1 in radians. Then 3 per point.
enum DividingParam : size_t {
  kDividingSigma,
  kDividingH,
  kDividingAlpha0,
  kDividingAlpha1,
  kDividingParamCount
};

// Ponytails (S4.6): tightness (centripetal magnitude), gather (the constraint version: 0 the
// paper's thin tubes and ring, 1 the gathered tail; ponytail_constraints.hpp), section (1: the
// tie gathers its whole scalp section, scalp_sections.hpp; 0: the hair that reaches it). Then
// the circle count m and 7 per circle. gather and section are optional: a block without them
// (tightness, m, 7 m) reads as gather = 0, one with gather alone (tightness, gather, m, 7 m) as
// section = 0; the three layouts differ in size mod 7.
enum PonytailParam : size_t {
  kPonytailTightness,
  kPonytailGather,
  kPonytailSection,
  kPonytailParamCount
};

// Braids (braid_bun.hpp): width, crossings per unit length, tightness, tail length, section
// (as a ponytail's; optional: a block without it reads as 0). No block.
enum BraidParam : size_t {
  kBraidWidth,
  kBraidCrossings,
  kBraidTightness,
  kBraidTailLength,
  kBraidSection,
  kBraidParamCount
};

// Buns (braid_bun.hpp): radius (0: the drawn loop's size), height, turns, section (as a
// braid's). No block.
enum BunParam : size_t { kBunRadius, kBunHeight, kBunTurns, kBunSection, kBunParamCount };

}  // namespace hairsketch
