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

namespace {

// Forward step on one supernode: u (m x 3, column-major, ld m) holds the gathered right-hand
// sides; L (m x w, unit lower below the diagonal). For c < w: u[r] -= L[r, c] u[c], r > c.
// Four columns at a time so each pass over the rows reads 4 columns of L and 3 of u.
void forwardBlock(const double* L, int m, int w, double* u) {
  double* u0 = u;
  double* u1 = u + m;
  double* u2 = u + 2 * size_t(m);
  int c = 0;
  for (; c + 4 <= w; c += 4) {
    const double* l0 = L + size_t(c) * m;
    const double* l1 = l0 + m;
    const double* l2 = l1 + m;
    const double* l3 = l2 + m;
    // The 4 x 4 triangle.
    for (int q = 1; q < 4; ++q)
      for (int p = 0; p < q; ++p) {
        const double l = (L + size_t(c + p) * m)[c + q];
        u0[c + q] -= l * u0[c + p];
        u1[c + q] -= l * u1[c + p];
        u2[c + q] -= l * u2[c + p];
      }
    const double a0 = u0[c], a1 = u0[c + 1], a2 = u0[c + 2], a3 = u0[c + 3];
    const double b0 = u1[c], b1 = u1[c + 1], b2 = u1[c + 2], b3 = u1[c + 3];
    const double d0 = u2[c], d1 = u2[c + 1], d2 = u2[c + 2], d3 = u2[c + 3];
    for (int r = c + 4; r < m; ++r) {
      const double x0 = l0[r], x1 = l1[r], x2 = l2[r], x3 = l3[r];
      u0[r] -= x0 * a0 + x1 * a1 + x2 * a2 + x3 * a3;
      u1[r] -= x0 * b0 + x1 * b1 + x2 * b2 + x3 * b3;
      u2[r] -= x0 * d0 + x1 * d1 + x2 * d2 + x3 * d3;
    }
  }
  for (; c < w; ++c) {
    const double* l = L + size_t(c) * m;
    const double a = u0[c], b = u1[c], d = u2[c];
    for (int r = c + 1; r < m; ++r) {
      u0[r] -= l[r] * a;
      u1[r] -= l[r] * b;
      u2[r] -= l[r] * d;
    }
  }
}

// Backward step: for c = w-1 .. 0: u[c] -= sum_{r > c} L[r, c] u[r]. Four columns at a time.
void backwardBlock(const double* L, int m, int w, double* u) {
  double* u0 = u;
  double* u1 = u + m;
  double* u2 = u + 2 * size_t(m);
  int c = w;
  for (; c - 4 >= 0; c -= 4) {
    const int c0 = c - 4;
    const double* l0 = L + size_t(c0) * m;
    const double* l1 = l0 + m;
    const double* l2 = l1 + m;
    const double* l3 = l2 + m;
    double s[4][3] = {};
    for (int r = c; r < m; ++r) {
      const double x = u0[r], y = u1[r], z = u2[r];
      s[0][0] += l0[r] * x, s[0][1] += l0[r] * y, s[0][2] += l0[r] * z;
      s[1][0] += l1[r] * x, s[1][1] += l1[r] * y, s[1][2] += l1[r] * z;
      s[2][0] += l2[r] * x, s[2][1] += l2[r] * y, s[2][2] += l2[r] * z;
      s[3][0] += l3[r] * x, s[3][1] += l3[r] * y, s[3][2] += l3[r] * z;
    }
    for (int q = 3; q >= 0; --q) {
      const int cq = c0 + q;
      const double* l = L + size_t(cq) * m;
      double a = u0[cq] - s[q][0], b = u1[cq] - s[q][1], d = u2[cq] - s[q][2];
      for (int r = cq + 1; r < c; ++r) {
        a -= l[r] * u0[r];
        b -= l[r] * u1[r];
        d -= l[r] * u2[r];
      }
      u0[cq] = a, u1[cq] = b, u2[cq] = d;
    }
  }
  for (--c; c >= 0; --c) {
    const double* l = L + size_t(c) * m;
    double a = u0[c], b = u1[c], d = u2[c];
    for (int r = c + 1; r < m; ++r) {
      a -= l[r] * u0[r];
      b -= l[r] * u1[r];
      d -= l[r] * u2[r];
    }
    u0[c] = a, u1[c] = b, u2[c] = d;
  }
}

}  // namespace

void SupernodalFactor::solveInPlace(Field& B) const {
  const SupernodalSymbolic& S = sym_;
  const int n = S.n, ns = S.supernodes();
  // y: permuted right-hand sides, one contiguous array per component.
  std::vector<double> y(3 * size_t(n)), u(3 * size_t(S.maxRows));
  double* y0 = y.data();
  double* y1 = y0 + n;
  double* y2 = y1 + n;
  for (int k = 0; k < n; ++k) {
    const int g = S.perm[size_t(k)];
    y0[k] = B(g, 0), y1[k] = B(g, 1), y2[k] = B(g, 2);
  }
  auto gather = [&](int s, int m) {
    const int* rows = S.rows(s);
    for (int i = 0; i < m; ++i) {
      const int r = rows[i];
      u[size_t(i)] = y0[r], u[size_t(m + i)] = y1[r], u[2 * size_t(m) + size_t(i)] = y2[r];
    }
  };
  auto scatter = [&](int s, int m) {
    const int* rows = S.rows(s);
    for (int i = 0; i < m; ++i) {
      const int r = rows[i];
      y0[r] = u[size_t(i)], y1[r] = u[size_t(m + i)], y2[r] = u[2 * size_t(m) + size_t(i)];
    }
  };
  // Forward (L z = y), diagonal, backward (L^T x = z).
  for (int s = 0; s < ns; ++s) {
    const int m = S.nrows(s);
    gather(s, m);
    forwardBlock(block(s), m, S.width(s), u.data());
    scatter(s, m);
  }
  for (int s = 0; s < ns; ++s) {
    const int w = S.width(s), m = S.nrows(s), start = S.superStart[size_t(s)];
    const double* L = block(s);
    for (int c = 0; c < w; ++c) {
      const double d = L[size_t(c) * size_t(m) + size_t(c)];
      y0[start + c] /= d, y1[start + c] /= d, y2[start + c] /= d;
    }
  }
  for (int s = ns - 1; s >= 0; --s) {
    const int m = S.nrows(s), w = S.width(s);
    gather(s, m);
    backwardBlock(block(s), m, w, u.data());
    // Only the own rows changed.
    const int start = S.superStart[size_t(s)];
    for (int i = 0; i < w; ++i)
      y0[start + i] = u[size_t(i)], y1[start + i] = u[size_t(m + i)],
                 y2[start + i] = u[2 * size_t(m) + size_t(i)];
  }
  for (int k = 0; k < n; ++k) {
    const int g = S.perm[size_t(k)];
    B(g, 0) = y0[k], B(g, 1) = y1[k], B(g, 2) = y2[k];
  }
}

}  // namespace hairsketch
