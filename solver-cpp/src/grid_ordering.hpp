// Geometric nested dissection of a full box grid, for the 25-point matrix D^T D (method S2).
//
// D couples face neighbours, so D^T D couples every pair of points at L1 distance <= 2 (e.g.
// (i-1, j, k) and (i+1, j, k)). A plane separator must therefore be 2 points thick: a 1-thick
// plane at x = c leaves (c-1, y, z) coupled to (c+1, y, z) and does not separate anything.
// Two variants:
//  - Boxes: the box is cut across its longest side at the middle by a 2-thick slab; the halves
//    are dissected recursively until a box holds at most `leafMax` points.
//  - Planes (default): a region (any point set) is cut by the 2-layer slab {c <= v.p <= c+1}
//    that is smallest among 13 lattice directions v in {-1,0,1}^3 (axes, face and body
//    diagonals) with both sides balanced. Any such slab separates: coupled points differ by at
//    most 2 in v.p. Diagonal slabs are thinner for this stencil (layers 1/sqrt(3) apart along
//    (1,1,1)): the root separator of a cube drops from 2N^2 to about 1.5N^2 points.
//
// The result is a tree of "nodes" (leaf boxes and separator slabs) numbered in postorder; each
// node owns a contiguous range of elimination positions and every subtree owns a contiguous
// range too. The tree is the supernodal elimination tree used by the factorisation.
#pragma once

#include <vector>

#include "grid.hpp"

namespace hairsketch {

struct DissectionOptions {
  enum class Method { Planes, Boxes } method = Method::Planes;
  int leafMax = 32;      // a region with at most this many points is not cut further
  double balance = 0.4;  // Planes: each side keeps at least this share of the other points
  int thickness = 2;     // Boxes: slab thickness in grid steps (2 is the minimum for D^T D)
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
