#include "multigrid_sparse.hpp"

#include <algorithm>

namespace hairsketch {

int64_t Csr::find(int r, int c) const {
  const auto first = col.begin() + ptr[r], last = col.begin() + ptr[r + 1];
  const auto it = std::lower_bound(first, last, c);
  return (it != last && *it == c) ? int64_t(it - col.begin()) : -1;
}

Csr transposeCsr(const Csr& a) {
  Csr t;
  t.rows = a.cols;
  t.cols = a.rows;
  t.ptr.assign(size_t(t.rows) + 1, 0);
  for (int64_t e = 0; e < a.nnz(); ++e) ++t.ptr[a.col[e] + 1];
  for (int r = 0; r < t.rows; ++r) t.ptr[r + 1] += t.ptr[r];
  t.col.resize(a.nnz());
  t.val.resize(a.nnz());
  std::vector<int64_t> next(t.ptr.begin(), t.ptr.end() - 1);
  for (int r = 0; r < a.rows; ++r)  // rows in increasing order -> sorted columns in t
    for (int64_t e = a.ptr[r]; e < a.ptr[r + 1]; ++e) {
      const int64_t d = next[a.col[e]]++;
      t.col[d] = r;
      t.val[d] = a.val[e];
    }
  return t;
}

Csr multiplyCsr(const Csr& a, const Csr& b) {
  // Two passes (count, then fill arrays of the exact size): no push_back slack, so the memory of
  // a product is its nnz (MgPcgSolver::estimateBytes counts on it).
  Csr c;
  c.rows = a.rows;
  c.cols = b.cols;
  c.ptr.assign(size_t(c.rows) + 1, 0);
  std::vector<int> mark(size_t(b.cols), -1);
  for (int r = 0; r < a.rows; ++r) {
    int64_t count = 0;
    for (int64_t e = a.ptr[r]; e < a.ptr[r + 1]; ++e)
      for (int64_t f = b.ptr[a.col[e]]; f < b.ptr[a.col[e] + 1]; ++f)
        if (mark[b.col[f]] != r) {
          mark[b.col[f]] = r;
          ++count;
        }
    c.ptr[r + 1] = c.ptr[r] + count;
  }
  c.col.resize(size_t(c.ptr[size_t(c.rows)]));
  c.val.resize(size_t(c.ptr[size_t(c.rows)]));
  std::fill(mark.begin(), mark.end(), -1);
  std::vector<double> acc(size_t(b.cols), 0.0);
  for (int r = 0; r < a.rows; ++r) {
    int* cols = c.col.data() + c.ptr[r];
    int m = 0;
    for (int64_t e = a.ptr[r]; e < a.ptr[r + 1]; ++e) {
      const int k = a.col[e];
      const double av = a.val[e];
      for (int64_t f = b.ptr[k]; f < b.ptr[k + 1]; ++f) {
        const int j = b.col[f];
        if (mark[j] != r) {
          mark[j] = r;
          acc[j] = 0.0;
          cols[m++] = j;
        }
        acc[j] += av * b.val[f];
      }
    }
    std::sort(cols, cols + m);
    double* vals = c.val.data() + c.ptr[r];
    for (int i = 0; i < m; ++i) vals[i] = acc[cols[i]];
  }
  return c;
}

Csr csrFromEigen(const SparseMatrix& m) {
  const Eigen::SparseMatrix<double, Eigen::RowMajor, int> r(m);
  Csr c;
  c.rows = int(r.rows());
  c.cols = int(r.cols());
  c.ptr.assign(size_t(c.rows) + 1, 0);
  c.col.reserve(r.nonZeros());
  c.val.reserve(r.nonZeros());
  for (int i = 0; i < c.rows; ++i) {
    for (decltype(r)::InnerIterator it(r, i); it; ++it) {
      c.col.push_back(int(it.col()));
      c.val.push_back(it.value());
    }
    c.ptr[i + 1] = int64_t(c.col.size());
  }
  return c;
}

SparseMatrix eigenFromCsr(const Csr& a) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(a.nnz());
  for (int r = 0; r < a.rows; ++r)
    for (int64_t e = a.ptr[r]; e < a.ptr[r + 1]; ++e) t.emplace_back(r, a.col[e], a.val[e]);
  SparseMatrix m(a.rows, a.cols);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

}  // namespace hairsketch
