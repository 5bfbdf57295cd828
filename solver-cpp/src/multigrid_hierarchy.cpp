#include "multigrid_hierarchy.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace hairsketch {
namespace {

// x[0 .. n) = 0, in parallel chunks.
void fillParallel(double* x, size_t n) {
  forPlanes(int64_t(n + 4095) / 4096, 4096, [&](int64_t b, int64_t e) {
    std::fill(x + 4096 * b, x + std::min<int64_t>(int64_t(n), 4096 * e), 0.0);
  });
}

}  // namespace

Status MultigridHierarchy::build(const Grid& grid, const MultigridOptions& options) {
  if (!grid.valid()) return Status::Error(StatusCode::InvalidInput, "grid must be at least 2^3");
  if (options.coarsestMaxPoints < 8 || options.sweeps < 1)
    return Status::Error(StatusCode::InvalidInput, "bad multigrid options");
  grid_ = grid;
  opt_ = options;
  levels_.clear();
  transfers_.clear();

  // Fine level: padded box and D's per-point weights.
  Fine& f = fine_;
  f = Fine();
  f.px = grid.nx + 2;
  f.py = grid.ny + 2;
  f.pz = grid.nz + 2;
  f.rows = int64_t(f.px) * f.py * f.pz;
  f.layout = {
      grid.nx, grid.ny, grid.nz, 1 + f.px + int64_t(f.px) * f.py, f.px, int64_t(f.px) * f.py};
  f.inv.assign(f.rows, 0.0);
  f.diagK.assign(f.rows, 0.0);
  f.w.assign(f.rows, 0.0);
  f.invDiag.assign(f.rows, 0.0);
  f.L.assign(3 * f.rows, 0.0);
  f.res.assign(3 * f.rows, 0.0);
  const int64_t sy = f.layout.sy, sz = f.layout.sz;
  for (int k = 0; k < grid.nz; ++k)
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const int cnt =
            (i > 0) + (i + 1 < grid.nx) + (j > 0) + (j + 1 < grid.ny) + (k > 0) + (k + 1 < grid.nz);
        f.inv[f.layout.offset + i + sy * j + sz * k] = 1.0 / cnt;
      }
  for (int k = 0; k < grid.nz; ++k)
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const int64_t p = f.layout.offset + i + sy * j + sz * k;
        const double* v = f.inv.data();
        f.diagK[p] = 1.0 + v[p - 1] * v[p - 1] + v[p + 1] * v[p + 1] + v[p - sy] * v[p - sy] +
                     v[p + sy] * v[p + sy] + v[p - sz] * v[p - sz] + v[p + sz] * v[p + sz];
        f.invDiag[p] = 1.0 / f.diagK[p];
      }

  // Level sizes.
  Level l0;
  l0.nx = grid.nx;
  l0.ny = grid.ny;
  l0.nz = grid.nz;
  levels_.push_back(std::move(l0));
  for (;;) {
    const Level& last = levels_.back();
    const int64_t size = int64_t(last.nx) * last.ny * last.nz;
    if (size <= opt_.coarsestMaxPoints) break;
    Level c;
    c.nx = coarsenedSize(last.nx);
    c.ny = coarsenedSize(last.ny);
    c.nz = coarsenedSize(last.nz);
    if (int64_t(c.nx) * c.ny * c.nz == size) break;  // nothing left to coarsen
    transfers_.push_back(makeTransfer(last.nx, last.ny, last.nz));
    levels_.push_back(std::move(c));
  }

  // Galerkin operators with W = 0: A_1 = (D P_0)^T (D P_0), A_{l+1} = P_l^T A_l P_l.
  const Csr D = csrFromEigen(assembleLaplacian(grid));
  if (levels_.size() == 1) {
    levels_[0].A = multiplyCsr(transposeCsr(D), D);
  } else {
    const Csr G = multiplyCsr(D, interpolationMatrix(transfers_[0]));
    levels_[1].A = multiplyCsr(transposeCsr(G), G);
    for (size_t l = 1; l + 1 < levels_.size(); ++l) {
      const Csr P = interpolationMatrix(transfers_[l]);
      levels_[l + 1].A = multiplyCsr(transposeCsr(P), multiplyCsr(levels_[l].A, P));
    }
  }
  for (size_t l = (levels_.size() == 1 ? 0 : 1); l < levels_.size(); ++l)
    finishLevel(levels_[l], opt_.colours);
  // Smoothing schedules (colour passes) of the fine and the coarse (CSR) levels.
  fineColours_ = std::max(kFineColours, opt_.colours);
  finePre_ = smoothingPlan(fineColours_, opt_.sweeps, opt_.symmetricSweeps, true);
  finePost_ = smoothingPlan(fineColours_, opt_.sweeps, opt_.symmetricSweeps, false);
  const int coarseSweeps = opt_.coarseSweeps > 0 ? opt_.coarseSweeps : opt_.sweeps;
  for (size_t l = 1; l + 1 < levels_.size(); ++l) {
    Level& lv = levels_[l];
    lv.prePlan = smoothingPlan(lv.colours, coarseSweeps, opt_.coarseSymmetricSweeps, true);
    lv.postPlan = smoothingPlan(lv.colours, coarseSweeps, opt_.coarseSymmetricSweeps, false);
  }

  // Composite 1D interpolation tables fine -> level l (identity for l = 0).
  auto compose = [](int n, const std::vector<Interp1D*>& chain) {
    std::vector<Comp1> out(n);
    for (int i = 0; i < n; ++i) {
      Comp1 c;
      c.count = 1;
      c.idx[0] = i;
      c.w[0] = 1.0;
      for (const Interp1D* t : chain) {
        Comp1 d;
        for (int a = 0; a < c.count; ++a) {
          const int s = c.idx[a];
          const int ids[2] = {t->i0[s], t->i1[s]};
          const double ws[2] = {t->w0[s], t->w1[s]};
          for (int b = 0; b < 2; ++b) {
            const double w = c.w[a] * ws[b];
            if (w == 0.0) continue;
            int m = 0;
            while (m < d.count && d.idx[m] != ids[b]) ++m;
            if (m == d.count) {
              // Nested nodes: never more than two coarse nodes per fine index.
              if (d.count == 2) continue;
              d.idx[d.count] = ids[b];
              d.w[d.count++] = 0.0;
            }
            d.w[m] += w;
          }
        }
        c = d;
      }
      out[i] = c;
    }
    return out;
  };
  compX_.assign(levels_.size(), {});
  compY_.assign(levels_.size(), {});
  compZ_.assign(levels_.size(), {});
  for (size_t l = 0; l < levels_.size(); ++l) {
    std::vector<Interp1D*> cx, cy, cz;
    for (size_t m = 0; m < l; ++m) {
      cx.push_back(&transfers_[m].x);
      cy.push_back(&transfers_[m].y);
      cz.push_back(&transfers_[m].z);
    }
    compX_[l] = compose(grid.nx, cx);
    compY_[l] = compose(grid.ny, cy);
    compZ_[l] = compose(grid.nz, cz);
  }
  gramX_.clear();
  gramY_.clear();
  gramZ_.clear();
  basePenalty_ = 0;
  coarsestDirty_ = true;
  factorValid_ = false;
  pending_.clear();
  return Status::Ok();
}

void MultigridHierarchy::finishLevel(Level& lv, int minColours) {
  lv.base = lv.A.val;
  const int n = lv.A.rows;
  lv.diagPos.assign(n, -1);
  lv.invDiag.assign(n, 0.0);
  const int64_t planeRows = int64_t(lv.nx) * lv.ny;
  int reach = 0;  // the largest plane distance between coupled rows
  for (int i = 0; i < n; ++i) {
    lv.diagPos[i] = lv.A.find(i, i);
    lv.invDiag[i] = 1.0 / lv.A.val[lv.diagPos[i]];
    for (int64_t e = lv.A.ptr[i]; e < lv.A.ptr[i + 1]; ++e)
      reach = std::max(reach, int(std::abs(lv.A.col[e] / planeRows - i / planeRows)));
  }
  lv.colours = std::max(reach + 1, minColours);
  lv.x.assign(3 * size_t(n), 0.0);
  lv.b.assign(3 * size_t(n), 0.0);
  lv.res.assign(3 * size_t(n), 0.0);
}

void MultigridHierarchy::levelDims(int l, int& nx, int& ny, int& nz) const {
  nx = levels_[l].nx;
  ny = levels_[l].ny;
  nz = levels_[l].nz;
}

int64_t MultigridHierarchy::paddedRow(int p) const {
  const int i = p % grid_.nx, j = (p / grid_.nx) % grid_.ny, k = p / (grid_.nx * grid_.ny);
  return fine_.layout.offset + i + fine_.layout.sy * j + fine_.layout.sz * k;
}

void MultigridHierarchy::toPadded(const Field& f, double* x) const {
  std::fill(x, x + 3 * fine_.rows, 0.0);
  int p = 0;
  for (int k = 0; k < grid_.nz; ++k)
    for (int j = 0; j < grid_.ny; ++j) {
      double* row = x + 3 * (fine_.layout.offset + fine_.layout.sy * j + fine_.layout.sz * k);
      for (int i = 0; i < grid_.nx; ++i, ++p)
        for (int c = 0; c < 3; ++c) row[3 * i + c] = f(p, c);
    }
}

void MultigridHierarchy::fromPadded(const double* x, Field& f) const {
  f.resize(grid_.size(), 3);
  int p = 0;
  for (int k = 0; k < grid_.nz; ++k)
    for (int j = 0; j < grid_.ny; ++j) {
      const double* row = x + 3 * (fine_.layout.offset + fine_.layout.sy * j + fine_.layout.sz * k);
      for (int i = 0; i < grid_.nx; ++i, ++p)
        for (int c = 0; c < 3; ++c) f(p, c) = row[3 * i + c];
    }
}

Status MultigridHierarchy::setPenalty(int p, double w) {
  if (p < 0 || p >= grid_.size() || !std::isfinite(w) || w < 0)
    return Status::Error(StatusCode::InvalidInput, "bad penalty update");
  const int64_t r = paddedRow(p);
  const double delta = w - fine_.w[r];
  if (delta == 0.0) return Status::Ok();
  fine_.w[r] = w;
  fine_.invDiag[r] = 1.0 / (fine_.diagK[r] + w);
  Status s = addPenaltyToLevels(p, delta);
  coarsestDirty_ = true;
  return s;
}

Status MultigridHierarchy::addPenaltyToLevels(int p, double delta) {
  const int i = p % grid_.nx, j = (p / grid_.nx) % grid_.ny, k = p / (grid_.nx * grid_.ny);
  const size_t first = levels_.size() == 1 ? 0 : 1;
  for (size_t l = first; l < levels_.size(); ++l) {
    Level& lv = levels_[l];
    const Comp1 &cx = compX_[l][i], &cy = compY_[l][j], &cz = compZ_[l][k];
    int idx[8];
    double v[8];
    int m = 0;
    for (int c = 0; c < cz.count; ++c)
      for (int b = 0; b < cy.count; ++b)
        for (int a = 0; a < cx.count; ++a) {
          idx[m] = cx.idx[a] + lv.nx * (cy.idx[b] + lv.ny * cz.idx[c]);
          v[m++] = cx.w[a] * cy.w[b] * cz.w[c];
        }
    for (int a = 0; a < m; ++a) {
      for (int b = 0; b < m; ++b) {
        const int64_t pos = lv.A.find(idx[a], idx[b]);
        if (pos < 0) return Status::Error(StatusCode::InvalidInput, "penalty outside pattern");
        lv.A.val[pos] += delta * v[a] * v[b];
      }
    }
    for (int a = 0; a < m; ++a) lv.invDiag[idx[a]] = 1.0 / lv.A.val[lv.diagPos[idx[a]]];
    if (l + 1 == levels_.size() && factorValid_) {
      CoarseTerm t;
      t.count = m;
      t.delta = delta;
      for (int a = 0; a < m; ++a) t.idx[a] = idx[a], t.v[a] = v[a];
      pending_.push_back(t);
    }
  }
  return Status::Ok();
}

Status MultigridHierarchy::resetPenalties() {
  const size_t first = levels_.size() == 1 ? 0 : 1;
  for (size_t l = first; l < levels_.size(); ++l) {
    Level& lv = levels_[l];
    lv.A.val = lv.base;
    if (basePenalty_ == 0)
      for (int i = 0; i < lv.A.rows; ++i) lv.invDiag[i] = 1.0 / lv.A.val[lv.diagPos[i]];
  }
  if (basePenalty_ != 0) addBaseToLevels();
  factorValid_ = false;  // refactor from the rebuilt operator: no trace of earlier updates
  pending_.clear();
  for (int p = 0; p < grid_.size(); ++p) {
    // setPenalty's delta from the base (without a base penalty: w itself)
    const double delta = fine_.w[paddedRow(p)] - basePenalty_;
    if (delta == 0.0) continue;
    Status s = addPenaltyToLevels(p, delta);
    if (!s.ok()) return s;
  }
  coarsestDirty_ = true;
  return Status::Ok();
}

Status MultigridHierarchy::buildGrams() {
  auto gram = [](const std::vector<Comp1>& comp, int coarse, std::vector<double>& g) {
    g.assign(size_t(kGramWidth) * size_t(coarse), 0.0);
    for (const Comp1& c : comp)
      for (int a = 0; a < c.count; ++a)
        for (int b = 0; b < c.count; ++b) {
          const int d = c.idx[b] - c.idx[a];
          if (d < -kGramReach || d > kGramReach) return false;
          g[size_t(kGramWidth) * size_t(c.idx[a]) + size_t(d + kGramReach)] += c.w[a] * c.w[b];
        }
    return true;
  };
  const size_t L = levels_.size();
  gramX_.assign(L, {});
  gramY_.assign(L, {});
  gramZ_.assign(L, {});
  for (size_t l = 0; l < L; ++l) {
    const Level& lv = levels_[l];
    if (!gram(compX_[l], lv.nx, gramX_[l]) || !gram(compY_[l], lv.ny, gramY_[l]) ||
        !gram(compZ_[l], lv.nz, gramZ_[l])) {
      gramX_.clear();
      gramY_.clear();
      gramZ_.clear();
      return Status::Error(StatusCode::InvalidInput, "interpolation wider than the Gram band");
    }
  }
  return Status::Ok();
}

// (P^T P)(r, c) = Gx(r_x, c_x) Gy(r_y, c_y) Gz(r_z, c_z) for coarse points r, c; every such
// product that is not zero comes from one fine point whose composite row holds both r and c,
// so it lies in the pattern (as setPenalty's v v^T does).
void MultigridHierarchy::addBaseToLevels() {
  const double beta2 = basePenalty_;
  const size_t first = levels_.size() == 1 ? 0 : 1;
  for (size_t l = first; l < levels_.size(); ++l) {
    Level& lv = levels_[l];
    const int nx = lv.nx, ny = lv.ny, plane = lv.nx * lv.ny;
    const double* gx = gramX_[l].data();
    const double* gy = gramY_[l].data();
    const double* gz = gramZ_[l].data();
    const int64_t* ptr = lv.A.ptr.data();
    const int* col = lv.A.col.data();
    double* val = lv.A.val.data();
    double* invDiag = lv.invDiag.data();
    const int64_t* diagPos = lv.diagPos.data();
    forPlanes(lv.A.rows, 2 * lv.A.nnz() / std::max(lv.A.rows, 1), [&](int64_t r0, int64_t r1) {
      for (int64_t r = r0; r < r1; ++r) {
        const int rx = int(r % nx), ry = int((r / nx) % ny), rz = int(r / plane);
        for (int64_t e = ptr[r]; e < ptr[r + 1]; ++e) {
          const int c = col[e];
          const int dx = c % nx - rx, dy = (c / nx) % ny - ry, dz = c / plane - rz;
          if (std::abs(dx) > kGramReach || std::abs(dy) > kGramReach || std::abs(dz) > kGramReach)
            continue;
          const double g = gx[kGramWidth * rx + dx + kGramReach] *
                           gy[kGramWidth * ry + dy + kGramReach] *
                           gz[kGramWidth * rz + dz + kGramReach];
          val[e] += beta2 * g;
        }
        invDiag[r] = 1.0 / val[diagPos[r]];
      }
    });
  }
}

Status MultigridHierarchy::setBasePenalty(double beta2) {
  if (!std::isfinite(beta2) || beta2 < 0)
    return Status::Error(StatusCode::InvalidInput, "base penalty must be finite and >= 0");
  if (beta2 != 0 && gramX_.empty()) {
    Status s = buildGrams();
    if (!s.ok()) return s;
  }
  basePenalty_ = beta2;
  Fine& f = fine_;
  for (int k = 0; k < grid_.nz; ++k)
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = 0; i < grid_.nx; ++i) {
        const int64_t r = f.layout.offset + i + f.layout.sy * j + f.layout.sz * k;
        f.w[r] = beta2;
        f.invDiag[r] = 1.0 / (f.diagK[r] + beta2);
      }
  const size_t first = levels_.size() == 1 ? 0 : 1;
  for (size_t l = first; l < levels_.size(); ++l) {
    Level& lv = levels_[l];
    lv.A.val = lv.base;
    if (beta2 == 0)
      for (int i = 0; i < lv.A.rows; ++i) lv.invDiag[i] = 1.0 / lv.A.val[lv.diagPos[i]];
  }
  if (beta2 != 0) addBaseToLevels();
  factorValid_ = false;
  pending_.clear();
  coarsestDirty_ = true;
  return Status::Ok();
}

Status MultigridHierarchy::prepare() {
  if (!coarsestDirty_) return Status::Ok();
  // Within the band (lower bandwidth w): a rank-1 term costs ~2 w (m - first), m w on average,
  // a refactorisation m w^2 / 2.
  const bool update = factorValid_ && 2 * pending_.size() < size_t(std::max(coarsestBand_, 1));
  lastRefactored_ = !(update && updateCoarsest());
  pending_.clear();
  if (lastRefactored_) {
    Status s = refactorCoarsest();
    if (!s.ok()) return s;
  }
  coarsestDirty_ = false;
  return Status::Ok();
}

// The coarsest operator is banded in its lexicographic order (a Galerkin stencil reaches at
// most 2 points along each axis): its Cholesky factor has no entry outside that band, so every
// loop on the factor stays inside it (lower bandwidth w: m w^2 / 2 flops instead of m^3 / 3;
// 25K's 9 x 10 x 9 level: w = 200 of m = 810). Right-looking, column by column, in a fixed order.
Status MultigridHierarchy::refactorCoarsest() {
  factorValid_ = false;
  const Level& c = levels_.back();
  const int n = c.A.rows;
  coarsestL_.setZero(n, n);
  int band = 0;
  for (int r = 0; r < n; ++r)
    for (int64_t e = c.A.ptr[r]; e < c.A.ptr[r + 1]; ++e)
      if (c.A.col[e] <= r) {
        coarsestL_(r, c.A.col[e]) = c.A.val[e];
        band = std::max(band, r - c.A.col[e]);
      }
  coarsestBand_ = band;
  double* L = coarsestL_.data();
  const int64_t ld = coarsestL_.outerStride();
  for (int j = 0; j < n; ++j) {
    double* __restrict cj = L + ld * j;
    const int end = std::min(n, j + band + 1);
    if (!(cj[j] > 0) || !std::isfinite(cj[j]))
      return Status::Error(StatusCode::NotPositiveDefinite,
                           "coarsest level is not positive definite");
    const double ljj = std::sqrt(cj[j]);
    cj[j] = ljj;
    for (int i = j + 1; i < end; ++i) cj[i] /= ljj;
    for (int k = j + 1; k < end; ++k) {
      double* __restrict ck = L + ld * k;
      const double lkj = cj[k];
      for (int i = k; i < end; ++i) ck[i] -= cj[i] * lkj;
    }
  }
  factorValid_ = true;
  return Status::Ok();
}

// L L^T + delta v v^T for each pending term, updates (delta > 0) before downdates so that every
// intermediate matrix stays positive definite; columns before the term's first entry do not
// change. false (factor invalid) when a pivot is not finite or drops below 1e-10 of its old
// value: the caller refactors from the operator.
bool MultigridHierarchy::updateCoarsest() {
  const int n = int(coarsestL_.rows());
  Eigen::VectorXd u(n);
  for (int pass = 0; pass < 2; ++pass)
    for (const CoarseTerm& t : pending_) {
      if ((pass == 0) != (t.delta > 0)) continue;
      const double sigma = t.delta > 0 ? 1.0 : -1.0;
      const double scale = std::sqrt(std::abs(t.delta));
      int first = n;
      for (int a = 0; a < t.count; ++a) first = std::min(first, t.idx[a]);
      u.segment(first, n - first).setZero();
      for (int a = 0; a < t.count; ++a) u[t.idx[a]] += scale * t.v[a];
      double beta = 1.0;
      for (int j = first; j < n; ++j) {
        const double uj = u[j];
        if (uj == 0.0) continue;  // column j unchanged
        const double ljj = coarsestL_(j, j), dj = ljj * ljj;
        const double su2 = sigma * uj * uj;
        const double x = dj + su2 / beta;
        if (!(x > 1e-10 * dj) || !std::isfinite(x)) {
          factorValid_ = false;
          return false;
        }
        const double nljj = std::sqrt(x);
        const double gamma = dj * beta + su2;
        beta += su2 / dj;
        coarsestL_(j, j) = nljj;
        // u's support stays within [j, j + band] (the term's 8 entries span less than the band)
        const int rs = std::min(n - j - 1, coarsestBand_);
        if (rs == 0) continue;
        auto col = coarsestL_.col(j).segment(j + 1, rs);
        auto ut = u.segment(j + 1, rs);
        ut -= (uj / ljj) * col;
        col = (nljj / ljj) * col + (nljj * sigma * uj / gamma) * ut;
      }
    }
  return true;
}

size_t MultigridHierarchy::memoryBytes() const {
  size_t b = (fine_.inv.size() + fine_.diagK.size() + fine_.w.size() + fine_.invDiag.size() +
              fine_.L.size() + fine_.res.size()) *
             sizeof(double);
  for (const Level& l : levels_)
    b += l.A.memoryBytes() + l.diagPos.size() * sizeof(int64_t) +
         (l.base.size() + l.invDiag.size() + l.x.size() + l.b.size() + l.res.size()) *
             sizeof(double);
  for (const Transfer3D& t : transfers_)
    b += (t.x.n + t.y.n + t.z.n) * (2 * sizeof(int) + 2 * sizeof(double));
  for (size_t l = 0; l < compX_.size(); ++l)
    b += (compX_[l].size() + compY_[l].size() + compZ_[l].size()) * sizeof(Comp1);
  for (size_t l = 0; l < gramX_.size(); ++l)
    b += (gramX_[l].size() + gramY_[l].size() + gramZ_[l].size()) * sizeof(double);
  b += size_t(coarsestL_.size() + coarseWork_.size()) * sizeof(double) +
       pending_.capacity() * sizeof(CoarseTerm);
  return b;
}

// ---- fine level, matrix-free -------------------------------------------------------------

void MultigridHierarchy::computeL(const double* x, double* L) const {
  const Fine& f = fine_;
  const int64_t sy = f.layout.sy, sz = f.layout.sz;
  const double* inv = f.inv.data();
  forPlanes(grid_.nz, 3 * int64_t(grid_.nx) * grid_.ny, [&](int64_t k0, int64_t k1) {
    for (int64_t k = k0; k < k1; ++k)
      for (int j = 0; j < grid_.ny; ++j) {
        const int64_t base = f.layout.offset + sy * j + sz * k;
        for (int i = 0; i < grid_.nx; ++i) {
          const int64_t p = base + i;
          const double* xp = x + 3 * p;
          for (int c = 0; c < 3; ++c) {
            const double s = xp[c - 3] + xp[c + 3] + xp[c - 3 * sy] + xp[c + 3 * sy] +
                             xp[c - 3 * sz] + xp[c + 3 * sz];
            L[3 * p + c] = inv[p] * s - xp[c];
          }
        }
      }
  });
}

namespace {

// The 25-point product written once: calls out(r, (D^T L)_r + w_r x_r) for every row
// r = 3 p + axis of every grid point p of the padded layout, with L = D x already computed,
// in parallel over z planes (out must only write row r).
// (D^T L)_p = sum over the 6 neighbours q of inv_q L_q, minus L_p (ghost rows have inv = 0).
template <class Out>
inline void forEachFineProduct(const BoxLayout& lay, const double* inv, const double* w,
                               const double* L, const double* x, Out&& out) {
  const int64_t sy = lay.sy, sz = lay.sz;
  forPlanes(lay.nz, 3 * int64_t(lay.nx) * lay.ny, [&](int64_t k0, int64_t k1) {
    for (int64_t k = k0; k < k1; ++k)
      for (int j = 0; j < lay.ny; ++j) {
        const int64_t base = lay.offset + sy * j + sz * k;
        for (int i = 0; i < lay.nx; ++i) {
          const int64_t p = base + i;
          const double i0 = inv[p - 1], i1 = inv[p + 1], i2 = inv[p - sy], i3 = inv[p + sy],
                       i4 = inv[p - sz], i5 = inv[p + sz];
          const double* Lp = L + 3 * p;
          for (int c = 0; c < 3; ++c) {
            const double dtl = i0 * Lp[c - 3] + i1 * Lp[c + 3] + i2 * Lp[c - 3 * sy] +
                               i3 * Lp[c + 3 * sy] + i4 * Lp[c - 3 * sz] + i5 * Lp[c + 3 * sz] -
                               Lp[c];
            out(3 * p + c, dtl + w[p] * x[3 * p + c]);
          }
        }
      }
  });
}

}  // namespace

// res = b - (D^T L + w x), with L = D x already computed.
void MultigridHierarchy::fineResidual(const double* x, const double* b, double* res) const {
  const Fine& f = fine_;
  forEachFineProduct(f.layout, f.inv.data(), f.w.data(), f.L.data(), x,
                     [&](int64_t r, double v) { res[r] = b[r] - v; });
}

void MultigridHierarchy::applyFine(const double* x, double* y) {
  computeL(x, fine_.L.data());
  const Fine& f = fine_;
  forEachFineProduct(f.layout, f.inv.data(), f.w.data(), f.L.data(), x,
                     [&](int64_t r, double v) { y[r] = v; });
}

// Gauss-Seidel on M x = b in plane-multicolour order: a point's update reads x and L = D x
// within two planes of its own, so planes k and k + C are independent for C >= 3
// (kFineColours); colour c holds the planes k = c mod C (C = fineColours_), swept one colour after
// the other, the planes of a colour in parallel, each plane in lexicographic order (forward) or
// its reverse (backward). The order is fixed, so every thread count gives the same bits, and a
// backward sweep is the exact reverse of a forward one (the V-cycle stays symmetric).
// fineSweepPlane keeps fine_.L = D x exact: the update delta at p changes L_p by -delta and L_q
// by inv_q * delta for the 6 neighbours q (in planes k - 1 .. k + 1: not touched by any other
// plane of the colour).
// Along a line, L at the previous and the current point stay in registers (carried from one
// point to the next), so the only serial dependency is delta_{p-1} -> delta_p through a few
// flops instead of a store and reload; everything read from the other lines is off that path.
void MultigridHierarchy::fineSweepPlane(int k, bool forward, double* x, const double* b) {
  Fine& f = fine_;
  const int64_t sy = f.layout.sy, sz = f.layout.sz;
  const double* inv = f.inv.data();
  const double* w = f.w.data();
  const double* invDiag = f.invDiag.data();
  double* L = f.L.data();
  const int nx = grid_.nx, ny = grid_.ny;
  const int64_t step = forward ? 1 : -1;  // along x
  for (int jj = 0; jj < ny; ++jj) {
    const int j = forward ? jj : ny - 1 - jj;
    const int64_t first = f.layout.offset + sy * j + sz * k + (forward ? 0 : nx - 1);
    // prev = the point before `first` in sweep order (a ghost), cur = first.
    double Lprev[3], Lcur[3];
    for (int c = 0; c < 3; ++c) {
      Lprev[c] = L[3 * (first - step) + c];
      Lcur[c] = L[3 * first + c];
    }
    for (int ii = 0; ii < nx; ++ii) {
      const int64_t p = first + step * ii;
      const int64_t pb = p - step, pn = p + step;  // previous / next in sweep order
      const double ib = inv[pb], in = inv[pn], i2 = inv[p - sy], i3 = inv[p + sy], i4 = inv[p - sz],
                   i5 = inv[p + sz];
      double* xp = x + 3 * p;
      const double* bp = b + 3 * p;
      double* Ln = L + 3 * pn;
      const double wp = w[p], dp = invDiag[p];
      for (int c = 0; c < 3; ++c) {
        const double Lnext = Ln[c];
        // Off the serial path: everything but the previous and current point's L.
        const double rest =
            bp[c] - wp * xp[c] -
            ((in * Lnext + i2 * L[3 * (p - sy) + c]) +
             (i3 * L[3 * (p + sy) + c] + i4 * L[3 * (p - sz) + c]) + i5 * L[3 * (p + sz) + c]);
        const double d = (rest + Lcur[c] - ib * Lprev[c]) * dp;
        xp[c] += d;
        L[3 * pb + c] = Lprev[c] + ib * d;  // the previous point's L is final now
        Lprev[c] = Lcur[c] - d;
        Lcur[c] = Lnext + in * d;
        L[3 * (p - sy) + c] += i2 * d;
        L[3 * (p + sy) + c] += i3 * d;
        L[3 * (p - sz) + c] += i4 * d;
        L[3 * (p + sz) + c] += i5 * d;
      }
    }
    const int64_t last = first + step * (nx - 1);
    for (int c = 0; c < 3; ++c) {
      L[3 * last + c] = Lprev[c];
      L[3 * (last + step) + c] = Lcur[c];  // ghost: inv there is 0, stays 0
    }
  }
}

void MultigridHierarchy::fineColourPass(int colour, bool forward, double* x, const double* b) {
  const int nz = grid_.nz;
  const int C = fineColours_;
  const int64_t planes = colour < nz ? (nz - colour + C - 1) / C : 0;
  forPlanes(planes, 6 * int64_t(grid_.nx) * grid_.ny, [&](int64_t t0, int64_t t1) {
    for (int64_t t = t0; t < t1; ++t) fineSweepPlane(colour + int(t) * C, forward, x, b);
  });
}

// ---- smoothing schedule --------------------------------------------------------------------

// Appends a sweep's colour passes: forward = colours ascending, each plane forward; backward =
// the exact reverse.
void MultigridHierarchy::appendSweep(std::vector<ColourPass>& plan, int colours, bool forward) {
  for (int a = 0; a < colours; ++a) plan.push_back({forward ? a : colours - 1 - a, forward});
}

std::vector<MultigridHierarchy::ColourPass> MultigridHierarchy::smoothingPlan(int colours,
                                                                              int sweeps,
                                                                              bool symmetric,
                                                                              bool pre) {
  // pre: forward (then backward when symmetric); post: its adjoint, (forward then) backward.
  std::vector<ColourPass> plan;
  for (int s = 0; s < sweeps; ++s) {
    if (pre || symmetric) appendSweep(plan, colours, true);
    if (!pre || symmetric) appendSweep(plan, colours, false);
  }
  return plan;
}

// ---- coarse levels, CSR --------------------------------------------------------------------

namespace {

// Row r of A (CSR) times x (rows of 3): two accumulator sets halve the add-latency chain.
inline void rowDot3(const int64_t* ptr, const int* col, const double* val, const double* x, int r,
                    double& o0, double& o1, double& o2) {
  double a0 = 0, a1 = 0, a2 = 0, b0 = 0, b1 = 0, b2 = 0;
  int64_t e = ptr[r];
  const int64_t end = ptr[r + 1];
  for (; e + 1 < end; e += 2) {
    const double va = val[e], vb = val[e + 1];
    const double* xa = x + 3 * int64_t(col[e]);
    const double* xb = x + 3 * int64_t(col[e + 1]);
    a0 += va * xa[0];
    a1 += va * xa[1];
    a2 += va * xa[2];
    b0 += vb * xb[0];
    b1 += vb * xb[1];
    b2 += vb * xb[2];
  }
  if (e < end) {
    const double va = val[e];
    const double* xa = x + 3 * int64_t(col[e]);
    a0 += va * xa[0];
    a1 += va * xa[1];
    a2 += va * xa[2];
  }
  o0 = a0 + b0;
  o1 = a1 + b1;
  o2 = a2 + b2;
}

}  // namespace

// One colour of a Gauss-Seidel sweep on level l: the planes k = colour mod lv.colours, each in
// row order (forward) or its reverse; rows of one colour's planes never couple (lv.colours is
// one more than the largest plane distance in the operator's pattern), so they run in parallel.
void MultigridHierarchy::coarseColourPass(int l, int colour, bool forward) {
  Level& lv = levels_[l];
  const int64_t planeRows = int64_t(lv.nx) * lv.ny;
  const int C = lv.colours;
  const int64_t planes = colour < lv.nz ? (lv.nz - colour + C - 1) / C : 0;
  const int64_t* ptr = lv.A.ptr.data();
  const int* col = lv.A.col.data();
  const double* val = lv.A.val.data();
  double* x = lv.x.data();
  const double* b = lv.b.data();
  const double* invDiag = lv.invDiag.data();
  const int64_t perPlane = 3 * lv.A.nnz() / std::max(lv.nz, 1);
  forPlanes(planes, perPlane, [&](int64_t t0, int64_t t1) {
    for (int64_t t = t0; t < t1; ++t) {
      const int64_t first = (colour + t * C) * planeRows;
      for (int64_t rr = 0; rr < planeRows; ++rr) {
        const int r = int(forward ? first + rr : first + planeRows - 1 - rr);
        double s0, s1, s2;
        rowDot3(ptr, col, val, x, r, s0, s1, s2);
        const double d = invDiag[r];
        x[3 * r] += (b[3 * r] - s0) * d;
        x[3 * r + 1] += (b[3 * r + 1] - s1) * d;
        x[3 * r + 2] += (b[3 * r + 2] - s2) * d;
      }
    }
  });
}

void MultigridHierarchy::coarseResidual(int l) {
  Level& lv = levels_[l];
  const int n = lv.A.rows;
  const int64_t* ptr = lv.A.ptr.data();
  const int* col = lv.A.col.data();
  const double* val = lv.A.val.data();
  const double* x = lv.x.data();
  const double* b = lv.b.data();
  double* res = lv.res.data();
  forPlanes(n, 3 * lv.A.nnz() / std::max(n, 1), [&](int64_t r0, int64_t r1) {
    for (int64_t r = r0; r < r1; ++r) {
      double s0, s1, s2;
      rowDot3(ptr, col, val, x, int(r), s0, s1, s2);
      res[3 * r] = b[3 * r] - s0;
      res[3 * r + 1] = b[3 * r + 1] - s1;
      res[3 * r + 2] = b[3 * r + 2] - s2;
    }
  });
}

// x = (L L^T)^-1 b for the 3 columns of b by column-oriented substitution on the column-major
// factor, the columns of b apart (coarseWork_: 3 contiguous vectors, so the inner loops
// vectorise): each pass reads every column of L once, contiguously, for all 3 right-hand sides.
// (Eigen's blocked triangular solve repacked L into GEMM panels on every call: 18 % of the fast
// solver's time at 37^3 natively, for a 1000-point coarsest level.)
void MultigridHierarchy::solveCoarsest() {
  Level& c = levels_.back();
  const int n = c.A.rows;
  const double* L = coarsestL_.data();
  const int64_t ld = coarsestL_.outerStride();
  const int band = coarsestBand_;
  coarseWork_.resize(3 * size_t(n));
  double* __restrict y0 = coarseWork_.data();
  double* __restrict y1 = y0 + n;
  double* __restrict y2 = y1 + n;
  for (int i = 0; i < n; ++i) {
    y0[i] = c.b[3 * i];
    y1[i] = c.b[3 * i + 1];
    y2[i] = c.b[3 * i + 2];
  }
  for (int j = 0; j < n; ++j) {  // L y = b
    const double* __restrict col = L + ld * j;
    const double a = y0[j] / col[j], b = y1[j] / col[j], d = y2[j] / col[j];
    y0[j] = a;
    y1[j] = b;
    y2[j] = d;
    const int end = std::min(n, j + band + 1);
    for (int i = j + 1; i < end; ++i) {
      const double l = col[i];
      y0[i] -= l * a;
      y1[i] -= l * b;
      y2[i] -= l * d;
    }
  }
  for (int j = n - 1; j >= 0; --j) {  // L^T x = y: dot products, 4 partial sums each
    const double* __restrict col = L + ld * j;
    double s[3][4] = {};
    int i = j + 1;
    const int end = std::min(n, j + band + 1);
    for (; i + 3 < end; i += 4)
      for (int u = 0; u < 4; ++u) {
        const double l = col[i + u];
        s[0][u] += l * y0[i + u];
        s[1][u] += l * y1[i + u];
        s[2][u] += l * y2[i + u];
      }
    for (; i < end; ++i) {
      s[0][0] += col[i] * y0[i];
      s[1][0] += col[i] * y1[i];
      s[2][0] += col[i] * y2[i];
    }
    y0[j] = (y0[j] - ((s[0][0] + s[0][1]) + (s[0][2] + s[0][3]))) / col[j];
    y1[j] = (y1[j] - ((s[1][0] + s[1][1]) + (s[1][2] + s[1][3]))) / col[j];
    y2[j] = (y2[j] - ((s[2][0] + s[2][1]) + (s[2][2] + s[2][3]))) / col[j];
  }
  for (int i = 0; i < n; ++i) {
    c.x[3 * i] = y0[i];
    c.x[3 * i + 1] = y1[i];
    c.x[3 * i + 2] = y2[i];
  }
}

void MultigridHierarchy::cycle(int l, bool zeroStart) {
  Level& lv = levels_[l];
  if (l + 1 == levels()) {
    solveCoarsest();
    return;
  }
  if (zeroStart) fillParallel(lv.x.data(), lv.x.size());
  for (const ColourPass& c : lv.prePlan) coarseColourPass(l, c.colour, c.forward);
  const Transfer3D& t = transfers_[l];
  // More than one correction only when the next level is not the exact coarsest.
  const int corrections = l + 2 == levels() ? 1 : std::max(1, opt_.coarseCycles);
  for (int g = 0; g < corrections; ++g) {
    coarseResidual(l);
    restrictTranspose(t, lv.res.data(), BoxLayout::dense(lv.nx, lv.ny, lv.nz),
                      levels_[l + 1].b.data(), work_);
    cycle(l + 1);
    prolongAdd(t, levels_[l + 1].x.data(), lv.x.data(), BoxLayout::dense(lv.nx, lv.ny, lv.nz),
               work_);
  }
  for (const ColourPass& c : lv.postPlan) coarseColourPass(l, c.colour, c.forward);
}

void MultigridHierarchy::vcycle(const double* r, double* z) {
  Fine& f = fine_;
  if (levels_.size() == 1) {  // the whole problem is small: exact solve
    std::fill(z, z + 3 * f.rows, 0.0);
    Level& c = levels_[0];
    Field tmp(grid_.size(), 3);
    fromPadded(r, tmp);
    std::copy(tmp.data(), tmp.data() + 3 * grid_.size(), c.b.begin());
    solveCoarsest();
    Eigen::Map<const Field> xs(c.x.data(), grid_.size(), 3);
    toPadded(Field(xs), z);
    return;
  }
  fillParallel(z, 3 * size_t(f.rows));
  fillParallel(f.L.data(), f.L.size());  // L = D z = 0
  for (const ColourPass& c : finePre_) fineColourPass(c.colour, c.forward, z, r);
  fineResidual(z, r, f.res.data());
  restrictTranspose(transfers_[0], f.res.data(), f.layout, levels_[1].b.data(), work_);
  cycle(1);
  prolongAdd(transfers_[0], levels_[1].x.data(), z, f.layout, work_);
  computeL(z, f.L.data());
  for (const ColourPass& c : finePost_) fineColourPass(c.colour, c.forward, z, r);
}

// Full multigrid (Briggs, Henson, McCormick, "A Multigrid Tutorial", ch. 3: nested iteration,
// FMG): the Galerkin levels are the problem's own coarse approximations (A_{l+1} = P^T A_l P,
// b_{l+1} = P^T b_l), so each level's solution, interpolated, is a good start for the next finer
// one, and a V-cycle there removes what the coarser level could not represent. Working storage:
// levels_[l].b holds b_l until level l is done (cycles on level l overwrite only coarser b's),
// levels_[l].x the level's solution.
void MultigridHierarchy::fullMultigrid(const double* b, double* x, int cycles) {
  Fine& f = fine_;
  if (levels_.size() == 1) {  // the whole problem is small: exact solve
    vcycle(b, x);
    return;
  }
  restrictTranspose(transfers_[0], b, f.layout, levels_[1].b.data(), work_);
  for (size_t l = 1; l + 1 < levels_.size(); ++l) {
    const Level& lv = levels_[l];
    restrictTranspose(transfers_[l], lv.b.data(), BoxLayout::dense(lv.nx, lv.ny, lv.nz),
                      levels_[l + 1].b.data(), work_);
  }
  solveCoarsest();
  for (int l = levels() - 2; l >= 1; --l) {
    Level& lv = levels_[l];
    fillParallel(lv.x.data(), lv.x.size());
    prolongAdd(transfers_[l], levels_[l + 1].x.data(), lv.x.data(),
               BoxLayout::dense(lv.nx, lv.ny, lv.nz), work_);
    for (int c = 0; c < cycles; ++c) cycle(l, false);
  }
  fillParallel(x, 3 * size_t(f.rows));
  prolongAdd(transfers_[0], levels_[1].x.data(), x, f.layout, work_);
}

}  // namespace hairsketch
