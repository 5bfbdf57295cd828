// Scalar parameters of each curve kind: their index in a curve's parameter block (protocol.ts
// CurveSet.params), in the order of protocol.ts CURVE_PARAMS, which declares their names,
// defaults and ranges. A kind's variable block (dividing normals, ponytail circles) follows its
// scalars. Adding a scalar: a row in CURVE_PARAMS, an index here (before the count), and the
// code that reads it.
#pragma once

#include <cstddef>

namespace hairsketch {

// Stream curves (S4.1): none yet.
enum StreamParam : size_t { kStreamParamCount };

// Dividing curves (S4.5): sigma, h in grid steps; alpha0, alpha1 in radians. Then 3 per point.
enum DividingParam : size_t {
  kDividingSigma,
  kDividingH,
  kDividingAlpha0,
  kDividingAlpha1,
  kDividingParamCount
};

// Ponytails (S4.6): tightness (centripetal magnitude). Then the circle count m and 7 per circle.
enum PonytailParam : size_t { kPonytailTightness, kPonytailParamCount };

}  // namespace hairsketch
