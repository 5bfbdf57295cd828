// Braids and buns: two sketched curve kinds built on the gathered ponytail (method S4.6 with
// gather = 1, ponytail_constraints.hpp) and laid out in the growth step (gathered_tail.hpp).
// World units (1 = 10 cm).
//
// Braid: the curve's points are a stroke from the scalp along the braid. Parameters
// (curve_params.hpp
//   BraidParam): width W > 0, crossings c > 0 (bundle crossings of the spine's plane per 10 cm,
//   all three bundles counted), tightness tau in [0, 1] (how flat the bundles lie), tail length
//   T >= 0. The field sees a gathered ponytail whose circles sit on every stroke point from the
//   first one off the scalp (the gather; the first point when the whole stroke lies on the
//   scalp) to the braid's end at T before the stroke's end, of radius W(s) / 2, tapering linearly
//   from W at the gather to 0.6 W at the braid's end. In growth (gathered_tail.cpp) the captured
//   hair is split by root angle into three bundles of radius r_b = W(s) / 4.5 whose centres, in the
//   spine's frame (E1 across the head, E2 away from it), are
//     x_b = A sin(t_b), y_b = B sin(2 t_b),  t_b = 2 pi s / P + 2 pi b / 3,  b = 0, 1, 2,
//     A = W(s) / 2 - r_b, B = r_b (1.5 - 0.8 tau), P = 6 / c (each bundle crosses x = 0 twice per
//     period P, so the three make c crossings per unit of length),
//   the classic three-strand plait: each outer bundle passes over the middle in turn. Two centres
//   at the same s are at least sqrt(3) B >= 1.2 r_b apart (equal x happens at equal |sin|; then
//   |y_i - y_j| = sqrt(3) B at the least). Past the braid's end the bundles meet over 1 cm into a
//   loose tail of radius 0.7 W(end).
//
// Bun: the curve's points are a loop drawn on the head where the bun sits. Its centre c is the
//   loop's mean, its axis n the loop's plane normal (least-variance direction) turned away from
//   the head's centre, its size the loop's mean distance from c. Parameters (BunParam): radius
//   R > 0 (0 in the block: the loop's size), height H > 0, turns K > 0. The field sees a gathered
//   ponytail with a short spine from 1.5 R inside the head along n to H above c (so its funnel
//   reaches the scalp about the bun) and two circles of radius 0.6 R, at 0.05 and H along n. In
//   growth each captured strand coils round n: K turns from its seat angle, rising over the dome
//   of radius rho_s = R (0.45 + 0.55 lambda) (lambda the root's distance rank: hair from farther
//   away wraps the outside), narrowed where the strand is too short for K turns, then the last
//   15 % of it turns in and down under the top (the tip tucked under).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ponytail_constraints.hpp"
#include "status.hpp"

namespace hairsketch {

struct BraidParams {
  double width = 0.5;      // W, world units
  double crossings = 6;    // c, per world unit (10 cm)
  double tightness = 0.5;  // tau
  double tailLength = 0.4;
  bool section = false;  // gathers its whole scalp section (gathered_tail.hpp)
};

struct BunParams {
  double radius = 0;  // R; 0 = the loop's size
  double height = 0.35;
  double turns = 2.5;
  bool section = false;  // gathers its whole scalp section (gathered_tail.hpp)
};

// Limits (the strict reader's too): width in (0, 3], crossings in (0, 40], tightness in [0, 1],
// tail length in [0, 20]; radius in [0, 2], height in (0, 2], turns in (0, 10]; section 0 or 1
// (optional, last: a block without it reads as 0).
Status parseBraidParams(const double* params, size_t count, BraidParams& out);
Status parseBunParams(const double* params, size_t count, BunParams& out);

// The gather: the first point flagged off the scalp (offScalp may be null: 0).
size_t braidGatherIndex(const uint8_t* offScalp, size_t pointCount);

// The braid as the field sees it (above). spine: pointCount x 3. braidLength receives the braid's
// length from the gather to its end (where the loose tail starts), world units.
PonytailParams braidAsPonytail(const double* spine, size_t pointCount, size_t gather,
                               const BraidParams& params, double* braidLength = nullptr);

struct BunFrame {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();  // unit, away from the head
  double radius = 0;                                // R in use
};

// headCentre may be null: the axis is then turned towards +y.
BunFrame bunFrame(const double* loop, size_t pointCount, const BunParams& params,
                  const Eigen::Vector3d* headCentre);

// The bun as the field sees it: the spine (2 points, 6 numbers) and the ponytail.
PonytailParams bunAsPonytail(const BunFrame& frame, const BunParams& params,
                             std::vector<double>& spine);

}  // namespace hairsketch
