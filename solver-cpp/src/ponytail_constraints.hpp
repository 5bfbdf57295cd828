// Ponytail constraints (SPEC S4.6, paper §5 and Fig. 5). The curve's points are the spine; the
// parameter block (protocol.ts) is the scalars (curve_params.hpp PonytailParam: tightness), then
// m, then per circle C_k (k = 1..m, C1 nearest the scalp, Cm = "C2" the last): cx, cy, cz, ax,
// ay, az, r.
//
// Per circle k: centre c_k, unit axis a_k (normalised here), radius r_k (world units).
// Radius slope along the axis (the meridian of the surface of revolution through the circles):
//   r'_k = (r_{k+1} - r_{k-1}) / ((c_{k+1} - c_{k-1}) . a_k)   (one-sided at the ends; 0 when
//   m = 1 or the axial distance is zero)
// For a grid point g, with w = (g - c) . a, e = unit((g - c) - w a) and rho = |(g - c) - w a|:
//   (1) purple: distance to the circle sqrt(w^2 + (rho - r)^2) <= tube = (sqrt(3) / 2) d (so every
//       point of the circle has a claimed grid point), target = unit(a + r' e) -- the
//       longitudinal (meridian) direction of the surface of revolution; e is taken as 0 when
//       rho < 1e-9 d;
//   (2) blue: the spine from the point nearest to C_m's centre to its end, as a stream curve
//       (appendStreamConstraints, with the curve's extend flag);
//   (3) green: C1 only: |w| <= d / 2 (on C1's plane, to half a step) and 1.3 r <= rho <= 1.9 r,
//       target = tightness * unit(c_1 - g) (pointing to the centre); grid points also inside
//       C1's purple tube are left to the purple constraint.
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

struct PonytailCircle {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();  // unit, along the spine (scalp -> tip)
  double radius = 0;                                // world units, > 0
};

struct PonytailParams {
  double tightness = kPonytailDefaultTightness;
  std::vector<PonytailCircle> circles;  // C1 first
};

// Checks the block's size (kPonytailParamCount + 1 + 7 m, m >= 1 an integer), finiteness
// (NonFinite), radius > 0, non-zero axes.
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
