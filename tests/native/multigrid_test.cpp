// Multigrid-PCG solver ("fast"): against an independent direct solve (Eigen SimplicialLDLT of the
// assembled D^T D + omega^2 S), Galerkin operators against Eigen sparse products, V-cycle
// symmetry (multicolour sweeps), the stopping criterion's error bound, and input guards. The
// same solve on several threads: tests/native/parallel_test.cpp.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <numeric>
#include <random>
#include <set>

#include "field_solver.hpp"
#include "mg_pcg_solver.hpp"
#include "multigrid_hierarchy.hpp"
#include "multigrid_transfer.hpp"
#include "random_vector.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace multigrid_test {

using namespace hairsketch;

namespace {

Grid box(int nx, int ny, int nz) {
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.nz = nz;
  return g;
}

// Random smooth curve in grid units; the 8 cell corners around each sample get the tangent.
void addStroke(const Grid& g, std::mt19937& rng, int count, std::vector<Constraint>& out,
               std::set<int>& used) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> nrm(0.0, 0.25);
  Eigen::Vector3d p = hairsketch_test::drawVector([&](int axis) {
    return u(rng) * ((axis == 0 ? g.nx : axis == 1 ? g.ny : g.nz) - 1);
  });
  Eigen::Vector3d d = hairsketch_test::drawVector([&](int) { return nrm(rng); }).normalized();
  int added = 0;
  for (int guard = 0; added < count && guard < 20000; ++guard) {
    d = (d + 0.5 * hairsketch_test::drawVector([&](int) { return nrm(rng); })).normalized();
    Eigen::Vector3d q = p + 0.7 * d;
    const double hi[3] = {g.nx - 1.001, g.ny - 1.001, g.nz - 1.001};
    for (int a = 0; a < 3; ++a)
      if (q[a] < 0 || q[a] > hi[a]) {
        d[a] = -d[a];
        q[a] = std::clamp(q[a], 0.0, hi[a]);
      }
    p = q;
    for (int c = 0; c < 8 && added < count; ++c) {
      const int i = std::min(int(p[0]) + (c & 1), g.nx - 1),
                j = std::min(int(p[1]) + (c >> 1 & 1), g.ny - 1),
                k = std::min(int(p[2]) + (c >> 2 & 1), g.nz - 1);
      if (used.insert(g.index(i, j, k)).second) {
        out.push_back({g.index(i, j, k), d});
        ++added;
      }
    }
  }
}

Field directSolve(const Grid& g, const ConstraintSet& set, double omega) {
  SparseMatrix M = assembleBiLaplacian(g);
  const Eigen::VectorXd w = penaltyDiagonal(g, set, omega);
  for (int p = 0; p < M.rows(); ++p) M.coeffRef(p, p) += w[p];
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(M);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  return ldlt.solve(Field(assembleRhs(g, set, omega)));
}

double relErr(const Field& a, const Field& ref) { return (a - ref).norm() / ref.norm(); }

// Fine operator M = D^T D + W assembled independently (Eigen products), for the Galerkin check.
SparseMatrix fineMatrix(const Grid& g, const MultigridHierarchy& h) {
  SparseMatrix M = assembleBiLaplacian(g);
  for (int p = 0; p < M.rows(); ++p) M.coeffRef(p, p) += h.penalty(p);
  return M;
}

double maxAbs(const SparseMatrix& m) {
  double a = 0;
  for (int k = 0; k < m.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(m, k); it; ++it) a = std::max(a, std::abs(it.value()));
  return a;
}

}  // namespace

TEST(MultigridTransfer, InterpolationReproducesLinearFunctionsOnAnySize) {
  for (int n : {2, 3, 4, 5, 6, 7, 10, 19, 28, 35, 36}) {
    const Interp1D t = makeInterp1D(n);
    ASSERT_EQ(t.nc, n <= 2 ? n : n / 2 + 1);
    // Coarse node I sits at fine position min(2I, n-1) (identity when not coarsened); a linear
    // function sampled at the nodes must interpolate to the same function everywhere.
    for (int i = 0; i < n; ++i) {
      auto node = [&](int I) { return t.nc == n ? I : std::min(2 * I, n - 1); };
      EXPECT_NEAR(t.w0[i] + t.w1[i], 1.0, 1e-15);
      EXPECT_NEAR(t.w0[i] * node(t.i0[i]) + t.w1[i] * node(t.i1[i]), double(i), 1e-12) << n;
      EXPECT_GE(t.w0[i], 0.0);
      EXPECT_GE(t.w1[i], 0.0);
    }
  }
}

TEST(MultigridHierarchy, GalerkinOperatorsEqualSparseProductsAfterLocalUpdates) {
  for (const Grid g : {box(11, 9, 10), box(14, 7, 12), box(6, 13, 5)}) {
    MultigridOptions o;
    o.coarsestMaxPoints = 20;  // deep hierarchy on a small grid
    MultigridHierarchy h;
    ASSERT_TRUE(h.build(g, o).ok());
    ASSERT_GE(h.levels(), 3);
    std::mt19937 rng(7);
    std::vector<int> on;
    for (int round = 0; round < 4; ++round) {
      for (int a = 0; a < 40; ++a) {  // add 40, drop ~15 of those constrained before
        const int p = int(rng() % g.size());
        ASSERT_TRUE(h.setPenalty(p, 1e4).ok());
        on.push_back(p);
      }
      for (int a = 0; a < 15 && !on.empty(); ++a) {
        const size_t k = rng() % on.size();
        ASSERT_TRUE(h.setPenalty(on[k], 0.0).ok());
        on.erase(on.begin() + k);
      }
      SparseMatrix A = fineMatrix(g, h);
      for (int l = 1; l < h.levels(); ++l) {
        const SparseMatrix P = eigenFromCsr(interpolationMatrix(h.transfer(l - 1)));
        const SparseMatrix ref = SparseMatrix(P.transpose()) * A * P;
        const SparseMatrix got = eigenFromCsr(h.levelMatrix(l));
        ASSERT_EQ(got.rows(), ref.rows());
        EXPECT_LE(maxAbs(got - ref), 1e-12 * maxAbs(ref)) << "level " << l << " round " << round;
        A = ref;
      }
    }
  }
}

TEST(MultigridHierarchy, VcycleIsSymmetricPositiveDefinite) {
  // The plane-multicolour sweeps: the post-smoother is the exact reverse of the pre-smoother for
  // any colour count (3 = the fewest that decouple planes, 5 = the default, 9 = as many as the
  // 9 planes: the lexicographic order) and sweep count.
  struct Case {
    bool sym;
    int colours, sweeps;
  };
  for (const Case cs : {Case{true, 5, 1}, Case{false, 5, 1}, Case{true, 3, 2}, Case{false, 9, 2}}) {
    const bool sym = cs.sym;
    const Grid g = box(13, 10, 9);
    MultigridOptions o;
    o.coarsestMaxPoints = 30;
    o.symmetricSweeps = sym;
    o.colours = cs.colours;
    o.sweeps = cs.sweeps;
    MultigridHierarchy h;
    ASSERT_TRUE(h.build(g, o).ok());
    std::mt19937 rng(3);
    for (int a = 0; a < 60; ++a) ASSERT_TRUE(h.setPenalty(int(rng() % g.size()), 1e4).ok());
    ASSERT_TRUE(h.prepare().ok());
    const Field X = Field::Random(g.size(), 3), Y = Field::Random(g.size(), 3);
    std::vector<double> x(3 * h.paddedRows()), y(x.size()), bx(x.size()), by(x.size());
    h.toPadded(X, x.data());
    h.toPadded(Y, y.data());
    h.vcycle(x.data(), bx.data());
    h.vcycle(y.data(), by.data());
    Field BX, BY;
    h.fromPadded(bx.data(), BX);
    h.fromPadded(by.data(), BY);
    for (int c = 0; c < 3; ++c) {
      const double xby = X.col(c).dot(BY.col(c)), ybx = Y.col(c).dot(BX.col(c));
      EXPECT_NEAR(xby, ybx, 1e-11 * (std::abs(xby) + std::abs(ybx)))
          << sym << " " << cs.colours << " colours, " << cs.sweeps << " sweeps";
      EXPECT_GT(X.col(c).dot(BX.col(c)), 0.0);
    }
    // The matrix-free fine apply equals the assembled operator.
    std::vector<double> mx(x.size());
    h.applyFine(x.data(), mx.data());
    Field MX;
    h.fromPadded(mx.data(), MX);
    const Field ref = fineMatrix(g, h) * X;
    EXPECT_LE((MX - ref).norm(), 1e-12 * ref.norm());
  }
}

// The coarsest factor is updated per edit by rank-1 updates/downdates (few changes) or
// refactored (many): either way the V-cycle equals that of a fresh hierarchy given the same
// penalties (which factors from scratch), to rounding.
TEST(MultigridHierarchy, UpdatedCoarsestFactorEqualsAFreshFactorisation) {
  const Grid g = box(15, 12, 11);
  MultigridOptions o;
  o.coarsestMaxPoints = 300;
  MultigridHierarchy h;
  ASSERT_TRUE(h.build(g, o).ok());
  ASSERT_GE(h.levels(), 2);
  std::mt19937 rng(11);
  std::set<int> on;
  const Field X = Field::Random(g.size(), 3);
  std::vector<double> x(3 * h.paddedRows()), z(x.size()), zf(x.size());
  h.toPadded(X, x.data());
  int updated = 0, refactored = 0;
  for (int round = 0; round < 8; ++round) {
    const int add = round == 3 ? 400 : 6, drop = round == 0 ? 0 : 4;
    for (int a = 0; a < drop && !on.empty(); ++a) {
      auto it = on.begin();
      std::advance(it, rng() % on.size());
      ASSERT_TRUE(h.setPenalty(*it, 0.0).ok());
      on.erase(it);
    }
    for (int a = 0; a < add; ++a) {
      const int p = int(rng() % g.size());
      if (on.insert(p).second) ASSERT_TRUE(h.setPenalty(p, 1e4).ok());
    }
    ASSERT_TRUE(h.prepare().ok());
    (h.lastPrepareRefactored() ? refactored : updated) += 1;
    MultigridHierarchy fresh;
    ASSERT_TRUE(fresh.build(g, o).ok());
    for (int p : on) ASSERT_TRUE(fresh.setPenalty(p, 1e4).ok());
    ASSERT_TRUE(fresh.prepare().ok());
    EXPECT_TRUE(fresh.lastPrepareRefactored());
    h.vcycle(x.data(), z.data());
    fresh.vcycle(x.data(), zf.data());
    double d = 0, n = 0;
    for (size_t i = 0; i < z.size(); ++i) {
      d = std::max(d, std::abs(z[i] - zf[i]));
      n = std::max(n, std::abs(zf[i]));
    }
    EXPECT_LE(d, 1e-9 * n) << "round " << round;
  }
  EXPECT_GE(updated, 5);     // small edits: rank-1 updates and downdates
  EXPECT_GE(refactored, 2);  // the first prepare and the 400-point edit: refactorisations
}

// Random constraint sets and edit sequences on irregular grids: after solve() (tolerance 1e-6)
// the field equals the direct solve to 1e-6; and whenever the error estimate is below a
// tolerance, the true error is below it too.
TEST(MgPcgSolver, MatchesDirectSolveOnEditSequencesAndEstimateBoundsError) {
  struct Case {
    Grid g;
    int coarsest;
  };
  const Case cases[] = {{box(7, 9, 8), 512},     // single level: exact preconditioner
                        {box(12, 10, 14), 512},  // two levels
                        {box(17, 13, 11), 40},   // deep hierarchy
                        {box(20, 16, 14), 512},
                        {box(23, 19, 17), 512}};
  int checked = 0;
  for (const Case& cs : cases) {
    const Grid& g = cs.g;
    MultigridOptions o;
    o.coarsestMaxPoints = cs.coarsest;
    MgPcgSolver s(o);
    ASSERT_TRUE(s.setGrid(g, kDefaultOmega).ok());
    std::mt19937 rng(11 + g.nx);
    std::vector<Constraint> raw;
    std::set<int> used;
    const int per = std::max(10, int(g.size() / 60));
    for (int edit = 0; edit < 5; ++edit) {
      switch (edit) {
        case 0:
        case 1:
        case 3:  // a new stroke
          addStroke(g, rng, per, raw, used);
          break;
        case 2:  // delete a random third of the constraints
          for (size_t k = 0; k < raw.size();)
            if (rng() % 3 == 0) {
              used.erase(raw[k].index);
              raw.erase(raw.begin() + k);
            } else {
              ++k;
            }
          break;
        case 4:  // drag: change every target a little
          for (Constraint& c : raw) c.target += Eigen::Vector3d(0.1, -0.2, 0.05);
          break;
      }
      const ConstraintSet set = normalizeConstraints(raw);
      ASSERT_TRUE(s.setConstraints(set).ok());
      const Field ref = directSolve(g, set, kDefaultOmega);
      const double tols[] = {1e-2, 1e-3, 1e-4, 1e-6};
      bool seen[4] = {false, false, false, false};
      Field T;
      for (int it = 0; it < 200 && !seen[3]; ++it) {
        MgProgress pr;
        ASSERT_TRUE(s.iterate(1, 0, &pr).ok());
        s.field(T);
        const double err = relErr(T, ref);
        for (int t = 0; t < 4; ++t)
          if (!seen[t] && pr.iterations >= 2 && pr.errorEstimate <= tols[t]) {
            seen[t] = true;
            EXPECT_LE(err, tols[t]) << g.nx << "x" << g.ny << "x" << g.nz << " edit " << edit
                                    << " tol " << tols[t] << " it " << pr.iterations;
            ++checked;
          }
      }
      EXPECT_TRUE(seen[3]);
      // The FieldSolver path: continue to the default tolerance (already there), then further.
      ASSERT_TRUE(s.solve(T).ok());
      EXPECT_LE(relErr(T, ref), 1e-6);
      ASSERT_TRUE(s.iterate(100, 1e-10).ok());
      s.field(T);
      EXPECT_LE(relErr(T, ref), 1e-8);
    }
  }
  EXPECT_EQ(checked, 5 * 5 * 4);
}

TEST(MgPcgSolver, FreshSolveToleranceAndWarmStart) {
  const Grid g = box(19, 15, 17);
  std::mt19937 rng(5);
  std::vector<Constraint> raw;
  std::set<int> used;
  addStroke(g, rng, 150, raw, used);
  addStroke(g, rng, 150, raw, used);
  const ConstraintSet a = normalizeConstraints(raw);
  std::vector<Constraint> dragged = raw;
  for (Constraint& c : dragged) c.target += Eigen::Vector3d(0.02, 0.0, -0.01);
  const ConstraintSet b = normalizeConstraints(dragged);
  auto solver = makeFieldSolver("fast");
  ASSERT_TRUE(solver);
  EXPECT_EQ(solver->name(), "fast");
  ASSERT_TRUE(solver->setGrid(g, kDefaultOmega).ok());
  ASSERT_TRUE(solver->setConstraints(a).ok());
  Field T;
  ASSERT_TRUE(solver->solve(T).ok());
  EXPECT_LE(relErr(T, directSolve(g, a, kDefaultOmega)), 1e-6);
  ASSERT_TRUE(solver->setConstraints(b).ok());
  ASSERT_TRUE(solver->solve(T).ok());
  const int warm = solver->stats().iterations;
  EXPECT_LE(relErr(T, directSolve(g, b, kDefaultOmega)), 1e-6);
  MgPcgSolver cold;
  ASSERT_TRUE(cold.setGrid(g, kDefaultOmega).ok());
  ASSERT_TRUE(cold.setConstraints(b).ok());
  ASSERT_TRUE(cold.solve(T).ok());
  EXPECT_LT(warm, cold.stats().iterations);  // a small drag converges faster from the old field
  // Unsorted input is normalised.
  std::vector<Constraint> rev(b.rbegin(), b.rend());
  ASSERT_TRUE(cold.setConstraints(rev).ok());
  ASSERT_TRUE(cold.solve(T).ok());
  EXPECT_LE(relErr(T, directSolve(g, b, kDefaultOmega)), 1e-6);
}

TEST(MgPcgSolver, PreviewAfterKIterationsThenRefine) {
  const Grid g = box(16, 18, 15);
  std::mt19937 rng(9);
  std::vector<Constraint> raw;
  std::set<int> used;
  addStroke(g, rng, 300, raw, used);
  const ConstraintSet set = normalizeConstraints(raw);
  const Field ref = directSolve(g, set, kDefaultOmega);
  MgPcgSolver s;
  ASSERT_TRUE(s.setGrid(g, kDefaultOmega).ok());
  ASSERT_TRUE(s.setConstraints(set).ok());
  MgProgress pr;
  ASSERT_TRUE(s.iterate(3, 0, &pr).ok());
  EXPECT_EQ(pr.iterations, 3);
  Field T;
  s.field(T);
  const double e3 = relErr(T, ref);
  EXPECT_LT(e3, 1.0);
  ASSERT_TRUE(s.iterate(5, 0, &pr).ok());
  EXPECT_EQ(pr.iterations, 8);
  s.field(T);
  const double e8 = relErr(T, ref);
  EXPECT_LT(e8, 0.1);  // a usable preview from a cold start
  EXPECT_GE(pr.errorEstimate, e8);
  ASSERT_TRUE(s.iterate(200, 1e-6, &pr).ok());
  EXPECT_TRUE(pr.converged);
  s.field(T);
  EXPECT_LT(relErr(T, ref), std::min(1e-6, e8));
}

TEST(MgPcgSolver, NoConstraintsGiveZeroField) {
  MgPcgSolver s;
  const Grid g = box(9, 8, 10);
  ASSERT_TRUE(s.setGrid(g, kDefaultOmega).ok());
  Field T;
  ASSERT_TRUE(s.solve(T).ok());
  ASSERT_EQ(T.rows(), g.size());
  EXPECT_EQ(T.norm(), 0.0);
  // Constrain, solve, then remove everything: zero again.
  ASSERT_TRUE(
      s.setConstraints({{5, Eigen::Vector3d(1, 0, 0)}, {77, Eigen::Vector3d(0, 1, 0)}}).ok());
  ASSERT_TRUE(s.solve(T).ok());
  EXPECT_GT(T.norm(), 0.0);
  ASSERT_TRUE(s.setConstraints({}).ok());
  ASSERT_TRUE(s.solve(T).ok());
  EXPECT_EQ(T.norm(), 0.0);
}

TEST(MgPcgSolver, RejectsBadInputAndKeepsState) {
  MgPcgSolver s;
  EXPECT_EQ(s.setGrid(box(1, 5, 5), kDefaultOmega).code, StatusCode::InvalidInput);
  EXPECT_EQ(s.setGrid(box(5, 5, 5), std::nan("")).code, StatusCode::InvalidInput);
  const Grid g = box(10, 9, 8);
  ASSERT_TRUE(s.setGrid(g, kDefaultOmega).ok());
  const ConstraintSet good = {{3, Eigen::Vector3d(0, 0, 1)}, {300, Eigen::Vector3d(1, 0, 0)}};
  ASSERT_TRUE(s.setConstraints(good).ok());
  Field before, after;
  ASSERT_TRUE(s.solve(before).ok());
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(s.setConstraints({{4, Eigen::Vector3d(std::nan(""), 0, 0)}}).code,
            StatusCode::NonFinite);
  EXPECT_EQ(s.setConstraints({{4, Eigen::Vector3d(0, inf, 0)}}).code, StatusCode::NonFinite);
  EXPECT_EQ(s.setConstraints({{int(g.size()), Eigen::Vector3d(0, 0, 1)}}).code,
            StatusCode::InvalidInput);
  EXPECT_EQ(s.setConstraints({{-1, Eigen::Vector3d(0, 0, 1)}}).code, StatusCode::InvalidInput);
  ASSERT_TRUE(s.solve(after).ok());
  EXPECT_LE(relErr(after, directSolve(g, good, kDefaultOmega)), 1e-6);
}

// Full multigrid without V-cycles is the coarsest Galerkin solution interpolated to the fine
// level: x = P_0 ... P_{c-1} A_c^-1 P_{c-1}^T ... P_0^T b, with A_c = P^T M P from Eigen
// products and a dense solve; on two levels that holds for any cycle count (no level between).
TEST(MultigridHierarchy, FullMultigridWithoutCyclesIsTheInterpolatedCoarsestSolution) {
  struct Case {
    Grid g;
    int coarsest, cycles;
  };
  for (const Case& cs :
       {Case{box(12, 10, 14), 512, 2}, Case{box(11, 9, 10), 20, 0}, Case{box(14, 7, 12), 60, 0}}) {
    const Grid& g = cs.g;
    MultigridOptions o;
    o.coarsestMaxPoints = cs.coarsest;
    MultigridHierarchy h;
    ASSERT_TRUE(h.build(g, o).ok());
    std::mt19937 rng(3 + g.nx);
    std::vector<Constraint> raw;
    std::set<int> used;
    addStroke(g, rng, int(g.size() / 30), raw, used);
    const ConstraintSet set = normalizeConstraints(raw);
    for (const Constraint& c : set) ASSERT_TRUE(h.setPenalty(c.index, 1e4).ok());
    ASSERT_TRUE(h.prepare().ok());
    const Field rhs = assembleRhs(g, set, kDefaultOmega);
    std::vector<double> b(3 * size_t(h.paddedRows())), x(b.size(), 1.0);
    h.toPadded(rhs, b.data());
    h.fullMultigrid(b.data(), x.data(), cs.cycles);
    Field got;
    h.fromPadded(x.data(), got);

    SparseMatrix A = fineMatrix(g, h), Pall;
    for (int l = 1; l < h.levels(); ++l) {
      const SparseMatrix P = eigenFromCsr(interpolationMatrix(h.transfer(l - 1)));
      A = SparseMatrix(P.transpose()) * A * P;
      Pall = l == 1 ? P : SparseMatrix(Pall * P);
    }
    const Eigen::MatrixXd Ac(A);
    const Field xc = Ac.llt().solve(Field(Pall.transpose() * rhs));
    const Field ref = Pall * xc;
    EXPECT_LE(relErr(got, ref), 1e-10) << g.nx << "x" << g.ny << "x" << g.nz;
    // x started at 1 everywhere: every row is written, the ghost rows with zeros
    EXPECT_NEAR(std::sqrt(std::inner_product(x.begin(), x.end(), x.begin(), 0.0)), got.norm(),
                1e-12 * got.norm());
  }
}

// The cold start (full multigrid with the default settings, then CG): after forgetWarmStart on
// every edit of an edit sequence, and on regular, irregular and deep hierarchies, the error
// estimate bounds the true error (against a direct solve) whenever it first drops below
// 1e-2 .. 1e-6, and the converged field agrees with the direct solve. (Not every setting passes
// every case: with these cases, a zero start on 17x13x11 and the interpolation-only start on
// 26x11x21 stopped at 1.0e-3 and 1.4e-3 true error for an estimate of 1e-3, fmgCycles 2 +
// fmgFineCycles 1 on 12x10x14 at 1.04e-4 for 1e-4: the estimate's rate is a 3-step mean.)
TEST(MgPcgSolver, ColdStartsMatchDirectSolveAndEstimateBoundsError) {
  struct Case {
    Grid g;
    int coarsest;
  };
  const Case cases[] = {{box(7, 9, 8), 512},  // single level
                        {box(12, 10, 14), 512}, {box(17, 13, 11), 40}, {box(20, 16, 14), 512},
                        {box(23, 19, 17), 120}, {box(26, 11, 21), 512}};
  struct Fmg {
    bool on;
    int cycles, fine;
  };
  const MultigridOptions defaults;
  const Fmg fmgs[] = {{defaults.fmgStart, defaults.fmgCycles, defaults.fmgFineCycles}};
  int checked = 0, expected = 0;
  for (const Case& cs : cases)
    for (const Fmg& fm : fmgs) {
      const Grid& g = cs.g;
      MultigridOptions o;
      o.coarsestMaxPoints = cs.coarsest;
      o.fmgStart = fm.on;
      o.fmgCycles = fm.cycles;
      o.fmgFineCycles = fm.fine;
      MgPcgSolver s(o);
      ASSERT_TRUE(s.setGrid(g, kDefaultOmega).ok());
      std::mt19937 rng(29 + g.nx + 3 * fm.cycles);
      std::vector<Constraint> raw;
      std::set<int> used;
      const int per = std::max(10, int(g.size() / 50));
      for (int edit = 0; edit < 4; ++edit) {
        if (edit == 2) {  // delete a random half
          for (size_t k = 0; k < raw.size();)
            if (rng() % 2 == 0) {
              used.erase(raw[k].index);
              raw.erase(raw.begin() + k);
            } else {
              ++k;
            }
        } else {
          addStroke(g, rng, per, raw, used);
        }
        const ConstraintSet set = normalizeConstraints(raw);
        ASSERT_TRUE(s.setConstraints(set).ok());
        ASSERT_TRUE(s.iterate(2, 0).ok());  // the app's first look, then the cold solve
        ASSERT_TRUE(s.forgetWarmStart());
        const Field ref = directSolve(g, set, kDefaultOmega);
        const double tols[] = {1e-2, 1e-3, 1e-4, 1e-6};
        bool seen[4] = {false, false, false, false};
        Field T;
        for (int it = 0; it < 200 && !seen[3]; ++it) {
          MgProgress pr;
          ASSERT_TRUE(s.iterate(1, 0, &pr).ok());
          s.field(T);
          const double err = relErr(T, ref);
          for (int t = 0; t < 4; ++t)
            if (!seen[t] && pr.iterations >= 2 && pr.errorEstimate <= tols[t]) {
              seen[t] = true;
              EXPECT_LE(err, tols[t]) << g.nx << "x" << g.ny << "x" << g.nz << " edit " << edit
                                      << " tol " << tols[t] << " it " << pr.iterations << " fmg "
                                      << fm.on << "/" << fm.cycles << "/" << fm.fine;
              ++checked;
            }
        }
        expected += 4;
        EXPECT_TRUE(seen[3]);
        ASSERT_TRUE(s.forgetWarmStart());
        ASSERT_TRUE(s.solve(T).ok());
        EXPECT_LE(relErr(T, ref), 1e-6);
      }
    }
  EXPECT_EQ(checked, expected);
}

}  // namespace multigrid_test
