// Test helper: an n x n x n grid over the cube [lo, hi]^3.
#pragma once

#include "grid.hpp"

namespace hairsketch_test {

inline hairsketch::Grid boxGrid(int n, double lo, double hi) {
  hairsketch::Grid g;
  g.nx = g.ny = g.nz = n;
  g.origin = {lo, lo, lo};
  g.step = (hi - lo) / (n - 1);
  return g;
}

}  // namespace hairsketch_test
