// Dividing-curve constraints (method S4.5, paper §5 and Fig. 4): a parting line on the scalp.
//
// Frame at unit point p_i (i = 0..n-1) of the curve:
//   y = n_i / |n_i|                      (scalp normal from the parameter block)
//   t = tangent: p_{i+1} - p_{i-1} (one-sided at the ends), with its y component removed,
//       normalised
//   a = alpha0 + (alpha1 - alpha0) * i / (n - 1)   (a = alpha0 when n = 1)
//   z = t rotated about y by a = cos(a) t + sin(a) (y x t)
//   x = y x z
// A point whose tangent is parallel to its normal (or zero) has no frame and claims nothing.
//
// Local coordinates of a grid point g, in grid steps: (u, v, w) = ((g - p) . (x, y, z)) / d.
// Profile (the Gaussian whose inflexion point sits at p, mirrored on both sides of the y axis):
//   G(s) = h * (exp(-(s + sigma)^2 / (2 sigma^2)) - exp(-1/2)),   s = |u| >= 0
//   G(0) = 0 and G''(0) = 0: p is the inflexion point; G falls away from p on both sides.
//   G'(s) = -h (s + sigma) / sigma^2 * exp(-(s + sigma)^2 / (2 sigma^2))
// Side: side = sign(u); grid points with |u| < 1e-9 (on the parting itself) are skipped.
// Grid point g is claimed by frame i when |w| <= 0.5 (its slab along the curve) and either
//   blue: |u| <= max(3 sigma, 1) and |v - G(|u|)| <= 0.5 (within half a step of the profile):
//         target = unit(side * x + G'(|u|) * y)   -- away from the parting and down the profile;
//   red:  otherwise, if |u| <= 1 and G(|u|) + 0.5 < v <= 2 (the column of grid points nearest
//         the parting, above the blue band up to two steps over the scalp):
//         target = 0.3 * side * x               -- away from the parting on each side.
// A grid point claimed by two neighbouring frames (or by a stream curve) is averaged by
// normalizeConstraints, as everywhere.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "constraint_colour.hpp"
#include "constraints.hpp"
#include "curve_params.hpp"
#include "grid.hpp"
#include "status.hpp"

namespace hairsketch {

constexpr double kDividingRedMagnitude = 0.3;
constexpr double kDividingBlueBand = 0.5;   // |v - G(|u|)| <= this, grid steps
constexpr double kDividingRedColumn = 1.0;  // |u| <= this, grid steps
constexpr double kDividingRedTop = 2.0;     // v <= this, grid steps
constexpr double kDividingSlab = 0.5;       // |w| <= this, grid steps

// Parsed dividing parameter block (hairArrays.ts CurveSet.params, kind dividing): the scalars
// (curve_params.hpp DividingParam: sigma, h, alpha0, alpha1), then nx, ny, nz per curve point.
struct DividingParams {
  double sigma = 1.0;               // grid steps, > 0
  double h = 0.5;                   // grid steps
  double alpha0 = 0, alpha1 = 0;    // radians
  const double* normals = nullptr;  // pointCount x 3
};

// Checks the block's size (kDividingParamCount + 3 * pointCount), finiteness (NonFinite),
// sigma > 0 and non-zero normals. The message does not name the curve (the caller prefixes it).
Status parseDividingParams(const double* params, size_t paramCount, size_t pointCount,
                           DividingParams& out);

struct DividingFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d x = Eigen::Vector3d::Zero(), y = Eigen::Vector3d::Zero(),
                  z = Eigen::Vector3d::Zero();
  double alpha = 0;
  bool valid = false;
};

// Frames at every point (see above). points: #P x 3.
std::vector<DividingFrame> dividingFrames(const double* points, size_t pointCount,
                                          const DividingParams& params);

// G(s) and G'(s) of the profile, s = |u| in grid steps.
double dividingProfile(double s, double sigma, double h);
double dividingProfileSlope(double s, double sigma, double h);

// Appends the raw constraints of one dividing curve. colours (optional) receives one entry per
// appended constraint.
void appendDividingConstraints(const Grid& grid, const double* points, size_t pointCount,
                               const DividingParams& params, std::vector<Constraint>& out,
                               std::vector<ConstraintColour>* colours = nullptr);

}  // namespace hairsketch
