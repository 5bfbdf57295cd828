// MultigridHierarchy: the V-cycle (the CG preconditioner) and full multigrid (the cold start).
#include <algorithm>

#include "multigrid_hierarchy.hpp"

namespace hairsketch {

namespace {

// x[0 .. n) = 0, in parallel chunks.
void fillParallel(double* x, size_t n) {
  forPlanes(int64_t(n + 4095) / 4096, 4096, [&](int64_t b, int64_t e) {
    std::fill(x + 4096 * b, x + std::min<int64_t>(int64_t(n), 4096 * e), 0.0);
  });
}

}  // namespace

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
