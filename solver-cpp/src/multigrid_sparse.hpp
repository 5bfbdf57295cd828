// Small compressed-sparse-row matrix for the coarse multigrid levels: Galerkin products
// (Gustavson), transposes, and in-place value updates at known positions.
#pragma once

#include <cstdint>
#include <vector>

#include "field_system.hpp"

namespace hairsketch {

struct Csr {
  int rows = 0, cols = 0;
  std::vector<int64_t> ptr;  // rows + 1 offsets into col/val
  std::vector<int> col;      // column indices, sorted within each row
  std::vector<double> val;

  int64_t nnz() const { return ptr.empty() ? 0 : ptr.back(); }
  // Position of entry (r, c) in col/val, or -1 when (r, c) is not in the pattern.
  int64_t find(int r, int c) const;
  size_t memoryBytes() const {
    return ptr.size() * sizeof(int64_t) + col.size() * sizeof(int) + val.size() * sizeof(double);
  }
};

Csr transposeCsr(const Csr& a);
// C = A B. Keeps every structural entry (no dropping of numerical zeros), so the pattern of a
// Galerkin product contains every position a later diagonal update can touch.
Csr multiplyCsr(const Csr& a, const Csr& b);
Csr csrFromEigen(const SparseMatrix& m);
SparseMatrix eigenFromCsr(const Csr& a);

}  // namespace hairsketch
