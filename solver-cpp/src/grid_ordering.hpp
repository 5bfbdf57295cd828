// Geometric nested dissection of a full box grid, for the 25-point matrix D^T D (SPEC S2).
//
// D couples face neighbours, so D^T D couples every pair of points at L1 distance <= 2 (e.g.
// (i-1, j, k) and (i+1, j, k)). A plane separator must therefore be 2 points thick: a 1-thick
// plane at x = c leaves (c-1, y, z) coupled to (c+1, y, z) and does not separate anything.
// The box is cut across its longest side at the middle by a 2-thick slab; the two halves are
// dissected recursively until a box holds at most `leafMax` points (or is too thin to cut).
//
// The result is a tree of "nodes" (leaf boxes and separator slabs) numbered in postorder; each
// node owns a contiguous range of elimination positions and every subtree owns a contiguous
// range too. The tree is the supernodal elimination tree used by the factorisation.
#pragma once

#include <vector>

#include "grid.hpp"

namespace hairsketch {

struct DissectionOptions {
  int leafMax = 64;   // a box with at most this many points is not cut further
  int thickness = 2;  // separator thickness in grid steps (2 is the minimum for D^T D)
};

struct DissectionTree {
  std::vector<int> perm;   // perm[k] = grid point eliminated at position k (size n)
  std::vector<int> iperm;  // iperm[p] = position of grid point p (size n)
  std::vector<int>
      nodeStart;            // node s owns positions [nodeStart[s], nodeStart[s+1]); size #nodes+1
  std::vector<int> parent;  // parent node, -1 for the root; parent[s] > s (postorder)
  int nodes() const { return int(parent.size()); }
};

// Requires grid.valid().
DissectionTree boxNestedDissection(const Grid& grid, const DissectionOptions& options = {});

}  // namespace hairsketch
