// Stream-curve constraints (method S4.1). The whole curve set is dispatched in curve_set.hpp.
#pragma once

#include <cstddef>
#include <vector>

#include "constraint_colour.hpp"
#include "constraints.hpp"
#include "curve_params.hpp"
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
// entry per appended constraint: Blue for the curve, Red for the extension. params: the curve's
// scalar parameters (curve_params.hpp StreamParam, kStreamParamCount numbers; none shapes the
// constraints: Volume is the shape rules'), or
// nullptr for a stream without a block of its own (a ponytail's spine).
void appendStreamConstraints(const Grid& grid, const double* points, size_t pointCount, bool extend,
                             std::vector<Constraint>& out,
                             std::vector<ConstraintColour>* colours = nullptr,
                             const double* params = nullptr);

}  // namespace hairsketch
