// Ponytail constraints (method S4.6, paper §5 and Fig. 5). The curve's points are the spine; the
// parameter block (hairArrays.ts) is the scalars (curve_params.hpp PonytailParam), then m, then per
// circle C_k (k = 1..m, C1 nearest the scalp, Cm = "C2" the last): cx, cy, cz, ax, ay, az, r.
// Two layouts, told apart by their size (they differ mod 7):
//   2 + 7 m numbers: tightness, m, circles            (the original layout; gather = 0)
//   3 + 7 m numbers: tightness, gather, m, circles    (gather = 0 or 1)
// gather selects the constraint version; 0 reproduces the original constraints exactly (old
// sessions and share links keep their hair), 1 gathers the tail into a round bunch.
//
// Per circle k: centre c_k, unit axis a_k (normalised here), radius r_k (world units).
// Radius slope along the axis (the meridian of the surface of revolution through the circles):
//   r'_k = (r_{k+1} - r_{k-1}) / ((c_{k+1} - c_{k-1}) . a_k)   (one-sided at the ends; 0 when
//   m = 1 or the axial distance is zero)
// For a grid point g, with w = (g - c) . a, e = unit((g - c) - w a) and rho = |(g - c) - w a|:
//
// gather = 0 (the paper, literally):
//   (1) purple: distance to the circle sqrt(w^2 + (rho - r)^2) <= tube = (sqrt(3) / 2) d (so every
//       point of the circle has a claimed grid point), target = unit(a + r' e) -- the
//       longitudinal (meridian) direction of the surface of revolution; e is taken as 0 when
//       rho < 1e-9 d;
//   (2) blue: the spine from the point nearest to C_m's centre to its end, as a stream curve
//       (appendStreamConstraints, with the curve's extend flag);
//   (3) green: C1 only: |w| <= d / 2 (on C1's plane, to half a step) and 1.3 r <= rho <= 1.9 r,
//       target = tightness * unit(c_1 - g) (pointing to the centre); grid points also inside
//       C1's purple tube are left to the purple constraint.
//
// gather = 1 (the tail as a solid of revolution, fed by a funnel): the constraints of 0 reach a
// thin shell of grid points only, so hair entering the tail off-centre stays there (a sheet or a
// crescent) and hair beside C1's small ring is never drawn in. Instead:
//   (1) purple, the body: between consecutive circles C_k, C_k+1 (the frustum; t = the
//       projection of g onto c_k -> c_k+1, 0 <= t <= 1, centre, axis and radius interpolated
//       linearly at t), every grid point with rho <= R + shell, shell = max(tube, R / 2):
//       inside (rho <= R), target = unit(a + s (rho / R) e) with s = (r_k+1 - r_k) / axial
//       length -- the scaled meridian, so a strand keeps its relative place rho / R and the
//       bunch keeps its round shape and fills the surface; in the shell, target = unit(a +
//       (s - kPonytailHold (rho - R) / shell) e), an inward pull back into the surface. A grid
//       point in two frusta (a bent spine) gets both; merging averages them.
//   (2) blue: as for 0.
//   (3) green, the funnel: the paper's centripetal ring made solid and extended from C1's plane
//       back to the scalp: every grid point with -L <= w <= 0 (L = the axial distance from C1
//       back to the spine point farthest behind it, plus a step) and rho <= F(w) = max(1.9 r, r + 2
//       d) + kPonytailFunnelSlope (-w), target = tightness * unit(q - g), q = c_1 + r sqrt(rho /
//       F(w)) e (along a_1 when g is within d / 4 of q) -- a point of C1's disc at the same
//       angle; the square root spreads the hair, which enters mostly near the axis, over the
//       whole disc (with rho / F it filled about its inner half). Hair flowing into the funnel
//       is drawn into C1 from every side, so the hair of the scalp around the tail's base fills
//       the disc instead of passing C1 as a flat sheet.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "constraint_colour.hpp"
#include "constraints.hpp"
#include "curve_params.hpp"
#include "grid.hpp"
#include "status.hpp"

namespace hairsketch {

constexpr double kPonytailRingInner = 1.3;  // x r of C1
constexpr double kPonytailRingOuter = 1.9;  // x r of C1
constexpr double kPonytailDefaultTightness = 0.6;
// gather = 1: the inward pull of the body's shell and the funnel's widening per unit of
// distance back from C1 toward the scalp.
constexpr double kPonytailHold = 0.5;
constexpr double kPonytailFunnelSlope = 1.5;

struct PonytailCircle {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();  // unit, along the spine (scalp -> tip)
  double radius = 0;                                // world units, > 0
};

struct PonytailParams {
  double tightness = kPonytailDefaultTightness;
  int gather = 0;                       // constraint version (0 or 1), see above
  bool section = false;                 // the tie gathers its whole scalp section (growth only)
  std::vector<PonytailCircle> circles;  // C1 first
};

// Checks the block's size (2 + 7 m, 3 + 7 m or 4 + 7 m, m >= 1 an integer), finiteness
// (NonFinite), gather and section 0 or 1, radius > 0, non-zero axes.
// The message does not name the curve (the caller prefixes it).
Status parsePonytailParams(const double* params, size_t paramCount, PonytailParams& out);

// Radius slope r'_k (dimensionless) of each circle, as above.
std::vector<double> ponytailRadiusSlopes(const PonytailParams& params);

// Index of the spine point nearest to the last circle's centre (where the blue part starts).
size_t ponytailBlueStart(const double* spine, size_t pointCount, const PonytailParams& params);

// Appends the raw constraints of one ponytail. spine: #P x 3. colours (optional) receives one
// entry per appended constraint.
void appendPonytailConstraints(const Grid& grid, const double* spine, size_t pointCount,
                               bool extend, const PonytailParams& params,
                               std::vector<Constraint>& out,
                               std::vector<ConstraintColour>* colours = nullptr);

}  // namespace hairsketch
