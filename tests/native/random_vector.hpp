// Test helper: a random 3-vector whose coordinates are drawn in a fixed order.
//
// The order in which a call's arguments are evaluated is unspecified in C++ (GCC goes right to
// left, clang left to right), so `Vector3d(draw(), draw(), draw())` gives another vector, and
// the test other points, under another compiler. drawVector calls coord(2), coord(1), coord(0),
// in that order: the order GCC used when these tests' points and tolerances were chosen.
#pragma once

#include <Eigen/Dense>

namespace hairsketch_test {

/** The vector (coord(0), coord(1), coord(2)), with coord(2) evaluated first and coord(0) last. */
template <class Coord>
Eigen::Vector3d drawVector(Coord&& coord) {
  const double z = coord(2);
  const double y = coord(1);
  const double x = coord(0);
  return {x, y, z};
}

}  // namespace hairsketch_test
