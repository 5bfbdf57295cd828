#include "supernodal_symbolic.hpp"

#include <algorithm>

namespace hairsketch {

SupernodalSymbolic analyseSupernodal(const SparseMatrix& M, const DissectionTree& tree) {
  SupernodalSymbolic S;
  S.n = int(tree.perm.size());
  S.perm = tree.perm;
  S.iperm = tree.iperm;
  S.superStart = tree.nodeStart;
  S.parent = tree.parent;
  const int ns = tree.nodes();

  // Children lists (CSR).
  S.childPtr.assign(size_t(ns) + 1, 0);
  for (int s = 0; s < ns; ++s)
    if (S.parent[size_t(s)] >= 0) ++S.childPtr[size_t(S.parent[size_t(s)]) + 1];
  for (int s = 0; s < ns; ++s) S.childPtr[size_t(s) + 1] += S.childPtr[size_t(s)];
  S.child.assign(size_t(S.childPtr[size_t(ns)]), 0);
  {
    std::vector<int> fill(S.childPtr.begin(), S.childPtr.end() - 1);
    for (int s = 0; s < ns; ++s)
      if (S.parent[size_t(s)] >= 0) S.child[size_t(fill[size_t(S.parent[size_t(s)])]++)] = s;
  }

  S.colSuper.assign(size_t(S.n), 0);
  for (int s = 0; s < ns; ++s)
    for (int k = S.superStart[size_t(s)]; k < S.superStart[size_t(s) + 1]; ++k)
      S.colSuper[size_t(k)] = s;

  // Rows: own columns, then the boundary, gathered from M's own columns and the children's
  // boundaries (entries at or beyond the end of J_s).
  S.rowPtr.assign(size_t(ns) + 1, 0);
  std::vector<int> mark(size_t(S.n), -1), boundary;
  for (int s = 0; s < ns; ++s) {
    const int b = S.superStart[size_t(s)], e = S.superStart[size_t(s) + 1];
    boundary.clear();
    auto add = [&](int r) {
      if (r >= e && mark[size_t(r)] != s) {
        mark[size_t(r)] = s;
        boundary.push_back(r);
      }
    };
    for (int k = b; k < e; ++k)
      for (SparseMatrix::InnerIterator it(M, S.perm[size_t(k)]); it; ++it)
        add(S.iperm[size_t(it.row())]);
    for (int c = S.childPtr[size_t(s)]; c < S.childPtr[size_t(s) + 1]; ++c) {
      const int ch = S.child[size_t(c)];
      for (int i = S.width(ch); i < S.nrows(ch); ++i) add(S.rows(ch)[i]);
    }
    std::sort(boundary.begin(), boundary.end());
    for (int k = b; k < e; ++k) S.row.push_back(k);
    S.row.insert(S.row.end(), boundary.begin(), boundary.end());
    S.rowPtr[size_t(s) + 1] = int64_t(S.row.size());
  }

  // Sizes, flops and the peak of the multifrontal update-matrix stack (postorder).
  S.valuePtr.assign(size_t(ns) + 1, 0);
  std::vector<int64_t> cb(size_t(ns), 0);
  int64_t alive = 0;
  for (int s = 0; s < ns; ++s) {
    const int64_t w = S.width(s), m = S.nrows(s), bd = m - w;
    S.valuePtr[size_t(s) + 1] = S.valuePtr[size_t(s)] + m * w;
    S.nnzL += w * (w + 1) / 2 + bd * w;
    S.factorFlops += double(w) * w * w / 3.0 + double(w) * w * bd + double(w) * bd * bd;
    S.maxWidth = std::max(S.maxWidth, int(w));
    S.maxRows = std::max(S.maxRows, int(m));
    cb[size_t(s)] = bd * bd;
    // The children's update matrices and this one's are alive while s is assembled.
    S.peakWorkEntries = std::max(S.peakWorkEntries, alive + cb[size_t(s)]);
    for (int c = S.childPtr[size_t(s)]; c < S.childPtr[size_t(s) + 1]; ++c)
      alive -= cb[size_t(S.child[size_t(c)])];
    alive += cb[size_t(s)];
  }
  S.storedEntries = S.valuePtr[size_t(ns)];
  return S;
}

}  // namespace hairsketch
