// Stream-curve constraints (SPEC S4.1) and the conversion of a whole curve set (protocol.ts
// CurveSet) into one normalised constraint set.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "constraint_colour.hpp"
#include "constraints.hpp"
#include "grid.hpp"
#include "status.hpp"

namespace hairsketch {

// Number of extrapolated segments appended past a stream curve's end when extension is on;
// segment k (1..K) has target magnitude 1 - k / K, so the last one is 0.
constexpr int kStreamExtensionSegments = 4;

// Appends the raw (unmerged) constraints of one stream curve to out.
// points: #P x 3 row-major world coordinates, segments of length ~ grid step.
// Each segment a->b claims the 8 corners of the grid cell containing its midpoint, with target
// the unit tangent (b - a) / |b - a|. Segments whose midpoint lies outside the grid volume, and
// zero-length segments, are skipped. With extend, K segments continue the last tangent with the
// last segment's length, targets m_k * tangent, m_k = 1 - k / K. colours (optional) receives one
// entry per appended constraint: Blue for the curve, Red for the extension.
void appendStreamConstraints(const Grid& grid, const double* points, size_t pointCount, bool extend,
                             std::vector<Constraint>& out,
                             std::vector<ConstraintColour>* colours = nullptr);

// Kind values of CurveSet.kinds (protocol.ts CurveKind).
enum class CurveKindCode : uint8_t { Stream = 0, Dividing = 1, Ponytail = 2 };

// Non-owning view of protocol.ts CurveSet.
struct CurveSetView {
  const double* points = nullptr;  // points[3 * point + axis]
  size_t pointCount = 0;
  const uint32_t* curveStart = nullptr;  // curveCount + 1 entries, [0] = 0, last = pointCount
  size_t curveCount = 0;
  const uint8_t* kinds = nullptr;   // curveCount entries
  const uint8_t* extend = nullptr;  // curveCount entries
  // Kind-specific parameter blocks: curve c owns params[paramStart[c] .. paramStart[c + 1]).
  // paramStart == nullptr means every block is empty (stream curves only).
  const double* params = nullptr;
  size_t paramCount = 0;
  const uint32_t* paramStart = nullptr;  // curveCount + 1 entries, [0] = 0, last = paramCount
  // Explicit constraints (scalp avoidance, S4.7), added to the derived ones before merging.
  const int32_t* extraIndex = nullptr;  // extraCount grid indices
  const double* extraTarget = nullptr;  // extraCount x 3
  size_t extraCount = 0;
};

// All curves (stream, dividing dividing_constraints.hpp, ponytail ponytail_constraints.hpp) and
// the explicit extras -> one normalised set (duplicates averaged). colours (optional) gets one
// entry per merged constraint: the colour of the first raw constraint at that grid point, in
// curve order, extras last (ConstraintColour::Extra). InvalidInput for a malformed
// layout, non-finite points, an unknown kind, a parameter block of the wrong size or with
// non-finite numbers (the message names the curve), or an extra constraint with an index outside
// the grid or a non-finite target.
Status curvesToConstraints(const Grid& grid, const CurveSetView& curves, ConstraintSet& out,
                           std::vector<uint8_t>* colours = nullptr);

}  // namespace hairsketch
