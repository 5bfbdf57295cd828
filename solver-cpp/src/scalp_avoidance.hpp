// Scalp penetration avoidance (method S4.7, paper §6), run once on request:
//   for every grid point g within band * d of the scalp and outside the head,
//     q   = the nearest point of the scalp triangles to g (brute force over the triangles whose
//           box grown by band * d contains g),
//     n   = the outward normal at q: the vertex normals (area-weighted face normals of all head
//           triangles, counter-clockwise = outward as in three.js) interpolated by q's
//           barycentric coordinates, normalised (the face normal if that is zero),
//     g is outside when (g - q) . n >= 0; points inside the head are left alone unless
//     insideToo is set (then they are treated alike: trilinear growth just outside the surface
//     blends them in, so an inward vector there can pull a strand into the head);
//     v   = the current field at g; if v . n < 0 (pointing inwards) v is replaced by its
//           projection v - (v . n) n onto the tangent plane at q;
//     the constraint is min(magnitude, |v|) * v / |v| (magnitude 0.3: never longer than the
//     field was, so avoidance turns hair and does not grow hair where the curves asked for
//     none); grid points whose field is shorter than minField get none.
//   A near-scalp point whose (projected) field vector is shorter than 1e-6 has no direction to
//   keep: it is skipped (counted in stats.skipped) and the solve interpolates it from its
//   neighbours.
// The constraints are returned sorted by grid index; the app stores them as the CurveSet's
// explicit extra constraints (hairArrays.ts extraIndex / extraTarget), so they are undoable.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "constraints.hpp"
#include "field_system.hpp"
#include "grid.hpp"
#include "status.hpp"

namespace hairsketch {

// Non-owning view of the head mesh (hairArrays.ts ScalpMesh).
struct HeadMeshView {
  const float* positions = nullptr;  // #V x 3
  size_t vertexCount = 0;
  const uint32_t* indices = nullptr;  // #T x 3
  size_t triangleCount = 0;
  const uint8_t* scalp = nullptr;  // #T flags, 1 = scalp
};

struct ScalpAvoidanceParams {
  double band = 1.5;       // grid steps: how near the scalp a grid point must be
  double magnitude = 0.3;  // target length of every returned constraint
  bool wholeHead = false;  // measure against every head triangle, not only the scalp ones
  bool insideToo = false;  // also grid points inside the head within the band
  double minField = 0;     // no constraint where |field| < minField (growth's threshold)
};

struct ScalpAvoidanceStats {
  int nearPoints = 0;  // grid points within the band, outside the head
  int projected = 0;   // of those, pointing inwards and projected
  int skipped = 0;     // of those, no direction left (not returned)
};

// T: the current field, grid.size() x 3.
Status scalpAvoidanceConstraints(const Grid& grid, const Field& T, const HeadMeshView& mesh,
                                 const ScalpAvoidanceParams& params, ConstraintSet& out,
                                 ScalpAvoidanceStats* stats = nullptr);

}  // namespace hairsketch
