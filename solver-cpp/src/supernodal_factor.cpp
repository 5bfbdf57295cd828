#include "supernodal_factor.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <cmath>
#include <string>

namespace hairsketch {

using Eigen::Index;
using Eigen::MatrixXd;
using BlockMap = Eigen::Map<MatrixXd>;
using ConstBlockMap = Eigen::Map<const MatrixXd>;

void SupernodalFactor::analyse(const SparseMatrix& M, const DissectionTree& tree) {
  sym_ = analyseSupernodal(M, tree);
  release();
}

void SupernodalFactor::release() {
  std::vector<double>().swap(values_);
  valid_ = false;
}

double SupernodalFactor::pivot(int k) const {
  const int s = sym_.colSuper[size_t(k)];
  const int c = k - sym_.superStart[size_t(s)];
  return block(s)[size_t(c) * size_t(sym_.nrows(s)) + size_t(c)];
}

Status SupernodalFactor::factorize(const SparseMatrix& M, const Eigen::VectorXd& penalty) {
  valid_ = false;
  const SupernodalSymbolic& S = sym_;
  const int ns = S.supernodes();
  values_.resize(size_t(S.storedEntries));
  std::vector<MatrixXd> update(
      static_cast<size_t>(ns));             // update matrices (lower triangles) of children
  std::vector<int> local(size_t(S.n), -1);  // position -> row within the current front
  std::vector<int> childRow;

  for (int s = 0; s < ns; ++s) {
    const int w = S.width(s), m = S.nrows(s), b = m - w, start = S.superStart[size_t(s)];
    const int* rows = S.rows(s);
    BlockMap L(block(s), m, w);
    L.setZero();
    MatrixXd& C = update[size_t(s)];
    C.setZero(b, b);
    for (int i = 0; i < m; ++i) local[size_t(rows[i])] = i;

    // Original entries of the own columns (lower triangle), plus the penalty.
    for (int c = 0; c < w; ++c) {
      const int k = start + c, g = S.perm[size_t(k)];
      for (SparseMatrix::InnerIterator it(M, g); it; ++it) {
        const int r = S.iperm[size_t(it.row())];
        if (r >= k) L(local[size_t(r)], c) += it.value();
      }
      L(c, c) += penalty[g];
    }
    // Extend-add the children's update matrices.
    for (int ci = S.childPtr[size_t(s)]; ci < S.childPtr[size_t(s) + 1]; ++ci) {
      const int ch = S.child[size_t(ci)];
      const int cw = S.width(ch), cb = S.nrows(ch) - cw;
      const int* crows = S.rows(ch) + cw;
      childRow.resize(size_t(cb));
      for (int i = 0; i < cb; ++i) childRow[size_t(i)] = local[size_t(crows[i])];
      const MatrixXd& U = update[size_t(ch)];
      for (int jj = 0; jj < cb; ++jj) {
        const int cj = childRow[size_t(jj)];
        const double* u = U.data() + Index(jj) * cb;
        if (cj < w) {
          double* dst = L.data() + Index(cj) * m;
          for (int ii = jj; ii < cb; ++ii) dst[childRow[size_t(ii)]] += u[ii];
        } else {
          double* dst = C.data() + Index(cj - w) * b - w;
          for (int ii = jj; ii < cb; ++ii) dst[childRow[size_t(ii)]] += u[ii];
        }
      }
      MatrixXd().swap(update[size_t(ch)]);
    }

    // Dense kernels: L11 L11^T = F11, L21 = F21 L11^-T, C -= L21 L21^T.
    Eigen::Ref<MatrixXd> L11 = L.topLeftCorner(w, w);
    Eigen::LLT<Eigen::Ref<MatrixXd>> llt(L11);
    if (llt.info() != Eigen::Success || !L11.diagonal().allFinite())
      return Status::Error(StatusCode::NotPositiveDefinite,
                           "factorisation: pivot not positive in supernode " + std::to_string(s));
    if (b > 0) {
      auto L21 = L.bottomRows(b);
      L11.transpose().triangularView<Eigen::Upper>().solveInPlace<Eigen::OnTheRight>(L21);
      C.selfadjointView<Eigen::Lower>().rankUpdate(L21, -1.0);
    }
    // LL^T -> LDL^T, D kept on the diagonal.
    for (int c = 0; c < w; ++c) {
      const double dc = L(c, c);
      L.col(c).tail(m - c - 1) /= dc;
      L(c, c) = dc * dc;
    }
  }
  valid_ = true;
  return Status::Ok();
}

void SupernodalFactor::solveInPlace(Field& B) const {
  const SupernodalSymbolic& S = sym_;
  const int n = S.n, ns = S.supernodes();
  Field y(n, 3);
  for (int k = 0; k < n; ++k) y.row(k) = B.row(S.perm[size_t(k)]);
  Eigen::Matrix<double, Eigen::Dynamic, 3> xj, t;

  // Forward: L z = y.
  for (int s = 0; s < ns; ++s) {
    const int w = S.width(s), m = S.nrows(s), b = m - w, start = S.superStart[size_t(s)];
    ConstBlockMap L(block(s), m, w);
    xj = y.middleRows(start, w);
    L.topLeftCorner(w, w).triangularView<Eigen::UnitLower>().solveInPlace(xj);
    y.middleRows(start, w) = xj;
    if (b > 0) {
      t.noalias() = L.bottomRows(b) * xj;
      const int* rows = S.rows(s) + w;
      for (int i = 0; i < b; ++i) y.row(rows[i]) -= t.row(i);
    }
  }
  // Diagonal.
  for (int s = 0; s < ns; ++s) {
    const int w = S.width(s), m = S.nrows(s), start = S.superStart[size_t(s)];
    const double* L = block(s);
    for (int c = 0; c < w; ++c) y.row(start + c) /= L[size_t(c) * size_t(m) + size_t(c)];
  }
  // Backward: L^T x = z.
  for (int s = ns - 1; s >= 0; --s) {
    const int w = S.width(s), m = S.nrows(s), b = m - w, start = S.superStart[size_t(s)];
    ConstBlockMap L(block(s), m, w);
    xj = y.middleRows(start, w);
    if (b > 0) {
      const int* rows = S.rows(s) + w;
      t.resize(b, 3);
      for (int i = 0; i < b; ++i) t.row(i) = y.row(rows[i]);
      xj.noalias() -= L.bottomRows(b).transpose() * t;
    }
    L.topLeftCorner(w, w).transpose().triangularView<Eigen::UnitUpper>().solveInPlace(xj);
    y.middleRows(start, w) = xj;
  }
  for (int k = 0; k < n; ++k) B.row(S.perm[size_t(k)]) = y.row(k);
}

}  // namespace hairsketch
