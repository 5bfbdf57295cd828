// MultigridHierarchy: penalty changes (constraints, a prior's base penalty) carried into every
// coarse Galerkin operator in place.
#include <algorithm>
#include <cmath>

#include "multigrid_hierarchy.hpp"

namespace hairsketch {

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

}  // namespace hairsketch
