// Symbolic analysis of M = D^T D + W^T W for a supernodal factorisation (method S3.1).
//
// Supernodes are the nodes of a nested-dissection tree (separator slabs and leaf boxes). The
// rows of supernode s are its own columns J_s (ascending positions) followed by its boundary
// B_s: the positions outside the subtree of s that the subtree couples to in M, ascending.
// Every row of B_s lies in the rows of parent(s), so the columns of L below J_s, the update
// matrices of the multifrontal factorisation and the update vectors of factor_update all pass
// from a child to its parent by an index map. The block of s is stored dense, |R_s| x |J_s|,
// column-major (explicit zeros where the true factor has none).
#pragma once

#include <cstdint>
#include <vector>

#include "field_system.hpp"
#include "grid_ordering.hpp"

namespace hairsketch {

struct SupernodalSymbolic {
  int n = 0;
  std::vector<int> perm, iperm;      // as in DissectionTree
  std::vector<int> superStart;       // s owns positions [superStart[s], superStart[s+1])
  std::vector<int> parent;           // -1 for the root; parent[s] > s
  std::vector<int> childPtr, child;  // children of s: child[childPtr[s] .. childPtr[s+1])
  std::vector<int64_t> rowPtr;       // rows of s: row[rowPtr[s] .. rowPtr[s+1])
  std::vector<int> row;              // positions, ascending; the first width(s) are J_s
  std::vector<int64_t> valuePtr;     // block of s at values[valuePtr[s]], nrows(s) x width(s)
  std::vector<int> colSuper;         // position -> supernode

  int64_t storedEntries = 0;    // sum of nrows * width (the value array)
  int64_t nnzL = 0;             // entries of the lower triangle of L in the supernodal pattern
  double factorFlops = 0;       // flops of a numeric factorisation (LLT + TRSM + SYRK)
  int64_t peakWorkEntries = 0;  // max entries of update matrices alive at once
  int maxWidth = 0, maxRows = 0;

  int supernodes() const { return int(parent.size()); }
  int width(int s) const { return superStart[size_t(s) + 1] - superStart[size_t(s)]; }
  int nrows(int s) const { return int(rowPtr[size_t(s) + 1] - rowPtr[size_t(s)]); }
  const int* rows(int s) const { return row.data() + rowPtr[size_t(s)]; }
  // Bytes of the factor plus the peak working memory of a factorisation.
  int64_t factorBytes() const { return 8 * (storedEntries + peakWorkEntries); }
};

// M: the n x n matrix pattern in grid order, both triangles stored (e.g. assembleBiLaplacian).
// tree: a nested dissection whose separators separate in the graph of M.
SupernodalSymbolic analyseSupernodal(const SparseMatrix& M, const DissectionTree& tree);

}  // namespace hairsketch
