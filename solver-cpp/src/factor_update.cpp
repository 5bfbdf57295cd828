#include "factor_update.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>

namespace hairsketch {
namespace {

constexpr int kStrip = 16;  // rows per strip in the sweep below a panel

struct Rotation {
  int t;
  double p, beta;
};

// Flops of one vector entering a block of m rows and w columns at local column e.
double blockFlops(double m, double w, double e) {
  const double cols = w - e;
  return 4.0 * (cols * (m - 1.0) - (w - 1.0 + e) * cols / 2.0);
}

// Method C1 on one supernode block. L: m x w column-major, D on the diagonal, unit lower
// triangle below; W: m x k column-major; alpha: k. Returns the failing local column or -1.
int modifyBlock(double* L, int m, int w, double* W, int k, double* alpha, double tol, int nb,
                std::vector<std::vector<Rotation>>& rot, double& flops) {
  if (int(rot.size()) < nb) rot.resize(size_t(nb));
  for (int j0 = 0; j0 < w; j0 += nb) {
    const int j1 = std::min(j0 + nb, w);
    // Panel rows [j0, j1): pivots and scalars, one column at a time.
    for (int j = j0; j < j1; ++j) {
      double* Lj = L + size_t(j) * size_t(m);
      std::vector<Rotation>& rj = rot[size_t(j - j0)];
      rj.clear();
      for (int t = 0; t < k; ++t) {
        double* Wt = W + size_t(t) * size_t(m);
        const double p = Wt[j];
        if (p == 0.0) continue;
        const double d = Lj[j], a = alpha[t];
        const double dbar = d + a * p * p;
        if (!std::isfinite(dbar) || !(dbar > tol * d)) return j;
        const double beta = a * p / dbar;
        alpha[t] = a * d / dbar;
        Lj[j] = dbar;
        rj.push_back({t, p, beta});
        for (int r = j + 1; r < j1; ++r) {
          Wt[r] -= p * Lj[r];
          Lj[r] += beta * Wt[r];
        }
      }
      flops += 4.0 * double(rj.size()) * double(m - j - 1);
    }
    // Rows [j1, m): all rotations of the panel, a strip of rows at a time.
    int i0 = j1;
    for (; i0 + kStrip <= m; i0 += kStrip) {
      for (int j = j0; j < j1; ++j) {
        const std::vector<Rotation>& rj = rot[size_t(j - j0)];
        if (rj.empty()) continue;
        double* Lj = L + size_t(j) * size_t(m) + i0;
        double l[kStrip];
        for (int r = 0; r < kStrip; ++r) l[r] = Lj[r];
        for (const Rotation& q : rj) {
          double* Wt = W + size_t(q.t) * size_t(m) + i0;
          const double p = q.p, beta = q.beta;
          for (int r = 0; r < kStrip; ++r) {
            const double wr = Wt[r] - p * l[r];
            Wt[r] = wr;
            l[r] += beta * wr;
          }
        }
        for (int r = 0; r < kStrip; ++r) Lj[r] = l[r];
      }
    }
    if (i0 < m) {
      const int len = m - i0;
      for (int j = j0; j < j1; ++j) {
        double* Lj = L + size_t(j) * size_t(m) + i0;
        for (const Rotation& q : rot[size_t(j - j0)]) {
          double* Wt = W + size_t(q.t) * size_t(m) + i0;
          for (int r = 0; r < len; ++r) {
            Wt[r] -= q.p * Lj[r];
            Lj[r] += q.beta * Wt[r];
          }
        }
      }
    }
  }
  return -1;
}

// Blocked multiple-rank modification of one supernode block: L <- L + W Lambda W^T restricted to
// the block's columns, with W (m x k) and a symmetric Lambda (k x k, not necessarily diagonal).
// This is method C1 with its rotations grouped: a panel of p columns is eliminated at once,
//   Y_p = L_pp^-1 W_p                           (the C1 multipliers "p" of the panel, p x k)
//   u_j = Lambda_j y_j, d'_j = d_j + y_j^T u_j, g_j = u_j / d'_j, Lambda_{j+1} = Lambda_j - u_j
//   g_j^T column j of L gains (W - sum_{i<=j in panel} l_i y_i^T) g_j     (rows below the panel) W
//   <- W - L_p Y_p                             (rows below the panel)
// so the work on the rows below each panel is two GEMMs with inner dimension k (BLAS-3) instead
// of k rank-1 sweeps. On return W's rows below the block hold the vectors for the parent and
// Lambda their (full) weight matrix. Returns the failing local column or -1.
int modifyBlockBlocked(double* Lx, int m, int w, Eigen::MatrixXd& W, Eigen::MatrixXd& Lambda,
                       double tol, int nb, double& flops) {
  using Eigen::MatrixXd;
  const int k = int(W.cols());
  Eigen::Map<MatrixXd> L(Lx, m, w);
  MatrixXd Y, P, U, G, YG, T1;
  Eigen::VectorXd dOld;
  for (int j0 = 0; j0 < w; j0 += nb) {
    const int p = std::min(nb, w - j0), j1 = j0 + p, below = m - j1;
    auto Lp = L.block(j0, j0, m - j0, p);  // panel columns, rows from j0
    dOld = Lp.topRows(p).diagonal();
    Lp.topRows(p).diagonal().setOnes();  // unit lower for the products below
    // Multipliers of the panel.
    Y = W.middleRows(j0, p);
    Lp.topRows(p).triangularView<Eigen::UnitLower>().solveInPlace(Y);
    // Pivots and g_j: u_j = Lambda y_j - sum_{i<j} u_i (g_i^T y_j).
    P.noalias() = Y * Lambda;  // row j = u_j^T before the in-panel corrections
    U.resize(k, p);
    G.resize(k, p);
    for (int j = 0; j < p; ++j) {
      Eigen::VectorXd u = P.row(j).transpose();
      if (j > 0) u.noalias() -= U.leftCols(j) * (G.leftCols(j).transpose() * Y.row(j).transpose());
      const double d = dOld[j];
      const double dbar = d + Y.row(j).dot(u);
      if (!std::isfinite(dbar) || !(dbar > tol * d)) {
        Lp.topRows(p).diagonal() = dOld;
        return j0 + j;
      }
      U.col(j) = u;
      G.col(j) = u / dbar;
      dOld[j] = dbar;
    }
    Lambda.noalias() -= U * G.transpose();
    Lambda = 0.5 * (Lambda + Lambda.transpose()).eval();
    // Rows inside the panel (strictly lower part only): column j gains
    // (W_r - sum_{i<=j} l_ri y_i^T) g_j for panel rows r > j.
    YG.noalias() = Y * G;             // (i, j) = y_i^T g_j
    for (int j = p - 1; j >= 0; --j)  // descending: columns i <= j still hold old values
      for (int r = j + 1; r < p; ++r) {
        double v = W.row(j0 + r).dot(G.col(j));
        for (int i = 0; i <= j; ++i) v -= Lp(r, i) * YG(i, j);
        Lp(r, j) += v;
      }
    if (below > 0) {
      auto Lb = L.block(j1, j0, below, p);
      auto Wb = W.bottomRows(below);
      const MatrixXd UT = YG.triangularView<Eigen::Upper>();
      T1.noalias() = Wb * G;
      T1.noalias() -= Lb * UT;
      Wb.noalias() -= Lb * Y;
      Lb += T1;
    }
    Lp.topRows(p).diagonal() = dOld;
    flops += 4.0 * double(below) * p * k + 4.0 * double(p) * k * k;
  }
  return -1;
}

// Supernodes on the union of the paths from the given positions to the root.
std::vector<char> markPaths(const SupernodalSymbolic& S, const std::vector<int>& positions) {
  std::vector<char> active(size_t(S.supernodes()), 0);
  for (int pos : positions)
    for (int s = S.colSuper[size_t(pos)]; s >= 0 && !active[size_t(s)]; s = S.parent[size_t(s)])
      active[size_t(s)] = 1;
  return active;
}

}  // namespace

double estimateModifyFlops(const SupernodalSymbolic& S, const std::vector<int>& positions) {
  const int ns = S.supernodes();
  std::vector<int> inherited(size_t(ns), 0);  // vectors arriving from children
  std::vector<double> ownFlops(size_t(ns), 0.0);
  std::vector<int> own(size_t(ns), 0);
  for (int pos : positions) {
    const int s = S.colSuper[size_t(pos)];
    ++own[size_t(s)];
    ownFlops[size_t(s)] += blockFlops(S.nrows(s), S.width(s), pos - S.superStart[size_t(s)]);
  }
  double total = 0;
  for (int s = 0; s < ns; ++s) {
    const int k = inherited[size_t(s)];
    total += ownFlops[size_t(s)] + k * blockFlops(S.nrows(s), S.width(s), 0);
    if (S.parent[size_t(s)] >= 0 && S.nrows(s) > S.width(s))
      inherited[size_t(S.parent[size_t(s)])] += k + own[size_t(s)];
  }
  return total;
}

namespace {

// Rank-1 sweeps (method C1 column by column, all vectors of a supernode at once).
Status modifyRank1(SupernodalFactor& F, const std::vector<DiagonalTerm>& terms,
                   const UpdateOptions& options, UpdateStats* stats) {
  const SupernodalSymbolic& S = F.symbolic();
  const int ns = S.supernodes();

  std::vector<int> positions(terms.size());
  for (size_t t = 0; t < terms.size(); ++t) positions[t] = terms[t].position;
  const std::vector<char> active = markPaths(S, positions);

  // Own terms of each supernode (term ids ascending).
  std::vector<std::vector<int>> ownTerms(static_cast<size_t>(ns));
  for (size_t t = 0; t < terms.size(); ++t)
    ownTerms[size_t(S.colSuper[size_t(terms[t].position)])].push_back(int(t));

  // Vectors leaving a supernode for its parent: term ids, rows below the own block, alphas.
  struct Pending {
    std::vector<int> ids;
    Eigen::MatrixXd W;
    std::vector<double> alpha;
  };
  std::vector<Pending> pending(static_cast<size_t>(ns));
  std::vector<int> local(size_t(S.n), -1), column(terms.size(), -1);
  std::vector<std::vector<Rotation>> rot;
  UpdateStats st;

  for (int s = 0; s < ns; ++s) {
    if (!active[size_t(s)]) continue;
    const int w = S.width(s), m = S.nrows(s), start = S.superStart[size_t(s)];
    const int* rows = S.rows(s);
    // Vector order = term order (updates before downdates when the caller sorted them so).
    std::vector<int> ids = ownTerms[size_t(s)];
    for (int ci = S.childPtr[size_t(s)]; ci < S.childPtr[size_t(s) + 1]; ++ci) {
      const Pending& P = pending[size_t(S.child[size_t(ci)])];
      ids.insert(ids.end(), P.ids.begin(), P.ids.end());
    }
    std::sort(ids.begin(), ids.end());
    const int k = int(ids.size());
    for (int c = 0; c < k; ++c) column[size_t(ids[size_t(c)])] = c;
    for (int i = 0; i < m; ++i) local[size_t(rows[i])] = i;

    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(m, k);
    std::vector<double> alpha(static_cast<size_t>(k));
    for (int t : ownTerms[size_t(s)]) {
      const int c = column[size_t(t)];
      W(terms[size_t(t)].position - start, c) += 1.0;
      alpha[size_t(c)] = terms[size_t(t)].alpha;
    }
    for (int ci = S.childPtr[size_t(s)]; ci < S.childPtr[size_t(s) + 1]; ++ci) {
      const int ch = S.child[size_t(ci)];
      Pending& P = pending[size_t(ch)];
      if (P.ids.empty()) continue;
      const int cw = S.width(ch), cb = S.nrows(ch) - cw;
      const int* crows = S.rows(ch) + cw;
      for (size_t v = 0; v < P.ids.size(); ++v) {
        const int c = column[size_t(P.ids[v])];
        alpha[size_t(c)] = P.alpha[v];
        for (int i = 0; i < cb; ++i) W(local[size_t(crows[i])], c) = P.W(i, Eigen::Index(v));
      }
      P = Pending();
    }

    const int bad = modifyBlock(F.block(s), m, w, W.data(), k, alpha.data(), options.pivotTolerance,
                                std::max(1, options.panel), rot, st.flops);
    ++st.supernodes;
    st.maxRank = std::max(st.maxRank, k);
    if (bad >= 0) {
      F.invalidate();
      if (stats) *stats = st;
      return Status::Error(
          StatusCode::NotPositiveDefinite,
          "downdate lost positive definiteness at position " + std::to_string(start + bad));
    }
    if (S.parent[size_t(s)] >= 0 && m > w) {
      Pending& out = pending[size_t(s)];
      out.ids = std::move(ids);
      out.W = W.bottomRows(m - w);
      out.alpha = std::move(alpha);
    }
  }
  if (stats) *stats = st;
  return Status::Ok();
}

}  // namespace

namespace {

// Blocked: vectors travel in chunks of at most options.chunk, each with its weight matrix.
Status modifyBlocked(SupernodalFactor& F, const std::vector<DiagonalTerm>& terms,
                     const UpdateOptions& options, UpdateStats* stats) {
  const SupernodalSymbolic& S = F.symbolic();
  const int ns = S.supernodes();
  const int cmax = std::max(1, options.chunk);
  std::vector<int> positions(terms.size());
  for (size_t t = 0; t < terms.size(); ++t) positions[t] = terms[t].position;
  const std::vector<char> active = markPaths(S, positions);
  std::vector<std::vector<int>> ownTerms(static_cast<size_t>(ns));
  for (size_t t = 0; t < terms.size(); ++t)
    ownTerms[size_t(S.colSuper[size_t(terms[t].position)])].push_back(int(t));

  struct Chunk {
    std::vector<int> ids;       // term ids (ascending within a chunk)
    std::vector<int> rows;      // positions of W's rows
    Eigen::MatrixXd W, Lambda;  // rows x k, k x k
  };
  std::vector<std::vector<Chunk>> pending(static_cast<size_t>(ns));
  std::vector<int> local(size_t(S.n), -1);
  UpdateStats st;

  for (int s = 0; s < ns; ++s) {
    if (!active[size_t(s)]) continue;
    const int w = S.width(s), m = S.nrows(s), start = S.superStart[size_t(s)];
    const int* rows = S.rows(s);
    for (int i = 0; i < m; ++i) local[size_t(rows[i])] = i;

    // Incoming chunks: own terms (diagonal weights) and the children's residuals.
    std::vector<Chunk> in;
    const std::vector<int>& own = ownTerms[size_t(s)];
    for (size_t a = 0; a < own.size(); a += size_t(cmax)) {
      Chunk c;
      const size_t e = std::min(own.size(), a + size_t(cmax));
      c.ids.assign(own.begin() + long(a), own.begin() + long(e));
      const int k = int(c.ids.size());
      c.W = Eigen::MatrixXd::Zero(1, k);  // marker: built below from positions
      c.Lambda = Eigen::MatrixXd::Zero(k, k);
      for (int v = 0; v < k; ++v) c.Lambda(v, v) = terms[size_t(c.ids[size_t(v)])].alpha;
      in.push_back(std::move(c));
    }
    for (int ci = S.childPtr[size_t(s)]; ci < S.childPtr[size_t(s) + 1]; ++ci)
      for (Chunk& c : pending[size_t(S.child[size_t(ci)])]) in.push_back(std::move(c));
    std::sort(in.begin(), in.end(),
              [](const Chunk& a, const Chunk& b) { return a.ids.front() < b.ids.front(); });

    // Group consecutive chunks up to cmax vectors; each group is one blocked pass.
    size_t a = 0;
    while (a < in.size()) {
      size_t e = a + 1;
      int k = int(in[a].ids.size());
      while (e < in.size() && k + int(in[e].ids.size()) <= cmax) k += int(in[e++].ids.size());
      Eigen::MatrixXd W = Eigen::MatrixXd::Zero(m, k), Lambda = Eigen::MatrixXd::Zero(k, k);
      std::vector<int> ids;
      int col = 0;
      for (size_t c = a; c < e; ++c) {
        Chunk& ch = in[c];
        const int kc = int(ch.ids.size());
        if (ch.rows.empty()) {  // own terms: unit vectors
          for (int v = 0; v < kc; ++v)
            W(terms[size_t(ch.ids[size_t(v)])].position - start, col + v) = 1.0;
        } else {
          for (size_t i = 0; i < ch.rows.size(); ++i)
            W.row(local[size_t(ch.rows[i])]).segment(col, kc) = ch.W.row(Eigen::Index(i));
        }
        Lambda.block(col, col, kc, kc) = ch.Lambda;
        ids.insert(ids.end(), ch.ids.begin(), ch.ids.end());
        col += kc;
        ch = Chunk();
      }
      const int bad = modifyBlockBlocked(F.block(s), m, w, W, Lambda, options.pivotTolerance,
                                         std::max(1, options.panel), st.flops);
      st.maxRank = std::max(st.maxRank, k);
      if (bad >= 0) {
        F.invalidate();
        if (stats) *stats = st;
        return Status::Error(
            StatusCode::NotPositiveDefinite,
            "downdate lost positive definiteness at position " + std::to_string(start + bad));
      }
      if (S.parent[size_t(s)] >= 0 && m > w) {
        Chunk out;
        out.ids = std::move(ids);
        out.rows.assign(rows + w, rows + m);
        out.W = W.bottomRows(m - w);
        out.Lambda = std::move(Lambda);
        pending[size_t(s)].push_back(std::move(out));
      }
      a = e;
    }
    ++st.supernodes;
  }
  if (stats) *stats = st;
  return Status::Ok();
}

}  // namespace

Status modifyDiagonal(SupernodalFactor& F, const std::vector<DiagonalTerm>& terms,
                      const UpdateOptions& options, UpdateStats* stats) {
  if (!F.valid()) return Status::Error(StatusCode::InvalidInput, "modify: factor is not valid");
  const SupernodalSymbolic& S = F.symbolic();
  for (const DiagonalTerm& t : terms)
    if (t.position < 0 || t.position >= S.n || !std::isfinite(t.alpha))
      return Status::Error(StatusCode::InvalidInput, "modify: bad diagonal term");
  if (stats) *stats = UpdateStats();
  if (terms.empty()) return Status::Ok();
  return options.kernel == UpdateKernel::Blocked ? modifyBlocked(F, terms, options, stats)
                                                 : modifyRank1(F, terms, options, stats);
}

}  // namespace hairsketch
