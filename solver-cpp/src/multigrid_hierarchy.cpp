// MultigridHierarchy: building the levels (transfers, Galerkin operators, smoothing plans),
// the padded fine layout and the memory count. The other members live in
// multigrid_penalties.cpp, multigrid_coarsest.cpp, multigrid_smoothing.cpp and
// multigrid_cycles.cpp.
#include "multigrid_hierarchy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace hairsketch {

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

}  // namespace hairsketch
