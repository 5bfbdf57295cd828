// A whole curve set (hairArrays.ts CurveSet) -> one normalised constraint set: each curve's
// constraints from its kind's entry (curve_kinds.hpp) and the explicit extra constraints. Scalar
// parameter indices: curve_params.hpp.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "constraint_colour.hpp"
#include "constraints.hpp"
#include "curve_params.hpp"
#include "grid.hpp"
#include "status.hpp"

namespace hairsketch {

// Kind values of CurveSet.kinds (curveParams.ts CurveKind); what each does: curve_kinds.hpp.
enum class CurveKindCode : uint8_t { Stream = 0, Dividing = 1, Ponytail = 2, Braid = 3, Bun = 4 };

// Non-owning view of hairArrays.ts CurveSet.
struct CurveSetView {
  const double* points = nullptr;  // points[3 * point + axis]
  size_t pointCount = 0;
  const uint32_t* curveStart = nullptr;  // curveCount + 1 entries, [0] = 0, last = pointCount
  size_t curveCount = 0;
  const uint8_t* kinds = nullptr;   // curveCount entries
  const uint8_t* extend = nullptr;  // curveCount entries
  // Parameter blocks: curve c owns params[paramStart[c] .. paramStart[c + 1]): its kind's
  // scalars (curve_params.hpp), then its variable block. paramStart == nullptr means every
  // block is empty (stream curves only).
  const double* params = nullptr;
  size_t paramCount = 0;
  const uint32_t* paramStart = nullptr;  // curveCount + 1 entries, [0] = 0, last = paramCount
  // Optional, from the head (the engine fills them): offScalp[point] != 0 where a point lies off
  // the scalp (a braid gathers at its first such point), and the head's centre (a bun's axis
  // turns away from it). Without them a braid gathers at its first point and a bun faces +y.
  const uint8_t* offScalp = nullptr;  // pointCount entries
  const Eigen::Vector3d* headCentre = nullptr;
  // Explicit constraints (scalp avoidance, S4.7), added to the derived ones before merging.
  const int32_t* extraIndex = nullptr;  // extraCount grid indices
  const double* extraTarget = nullptr;  // extraCount x 3
  size_t extraCount = 0;
};

// All curves and the explicit extras -> one normalised set (duplicates averaged). colours
// (optional) gets one entry per merged constraint: the colour of the first raw constraint at
// that grid point, in curve order, extras last (ConstraintColour::Extra). InvalidInput for a
// malformed layout, an unknown kind or a parameter block of the wrong size; NonFinite for a
// non-finite point, parameter or extra target (the message names the curve or extra); an extra
// constraint with an index outside the grid is InvalidInput.
Status curvesToConstraints(const Grid& grid, const CurveSetView& curves, ConstraintSet& out,
                           std::vector<uint8_t>* colours = nullptr);

}  // namespace hairsketch
