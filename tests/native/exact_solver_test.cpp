#include "exact_solver.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <random>

#include "exact_reference.hpp"

namespace exact_solver_test {
using namespace hairsketch;
namespace {

using testref::box;

Eigen::Vector3d randomTarget(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  return {n(rng), n(rng), n(rng)};
}

// 200 random edits: new curves (clustered points), removals, target changes, occasional
// clear-all; after each edit the field must equal a fresh Eigen solve.
void randomEdits(const Grid& g, ExactSolverOptions::Policy policy, unsigned seed, int steps,
                 std::map<std::string, int>* methods,
                 UpdateKernel kernel = ExactSolverOptions().update.kernel) {
  std::mt19937 rng(seed);
  ExactSolverOptions o;
  o.policy = policy;
  o.update.kernel = kernel;
  ExactSolver solver(o);
  const double omega = 100.0;
  ASSERT_TRUE(solver.setGrid(g, omega).ok());
  std::map<int, Eigen::Vector3d> set;
  testref::ReferenceSolver reference(g, omega);
  double worst = 0;
  for (int step = 0; step < steps; ++step) {
    const int kind = int(rng() % 10);
    if (kind < 4 || set.empty()) {  // a new curve: a random walk of points
      int i = int(rng() % unsigned(g.nx)), j = int(rng() % unsigned(g.ny)),
          k = int(rng() % unsigned(g.nz));
      const int len = 1 + int(rng() % 25);
      for (int s = 0; s < len; ++s) {
        set[g.index(i, j, k)] = randomTarget(rng);
        const int axis = int(rng() % 3), dir = (rng() % 2) ? 1 : -1;
        int* c = axis == 0 ? &i : axis == 1 ? &j : &k;
        const int lim = axis == 0 ? g.nx : axis == 1 ? g.ny : g.nz;
        *c = std::min(lim - 1, std::max(0, *c + dir));
      }
    } else if (kind < 7) {  // remove some
      const int r = 1 + int(rng() % 20);
      for (int t = 0; t < r && !set.empty(); ++t) {
        auto it = set.begin();
        std::advance(it, rng() % set.size());
        set.erase(it);
      }
    } else if (kind < 9) {  // change targets of kept constraints
      for (auto& kv : set)
        if (rng() % 3 == 0) kv.second = randomTarget(rng);
    } else if (rng() % 4 == 0) {
      set.clear();
    } else {  // move: remove some and add others in one edit
      for (int t = 0; t < 5 && !set.empty(); ++t) set.erase(set.begin());
      for (int t = 0; t < 5; ++t) set[int(rng() % unsigned(g.size()))] = randomTarget(rng);
    }
    ConstraintSet cs;
    for (const auto& kv : set) cs.push_back({kv.first, kv.second});
    ASSERT_TRUE(solver.setConstraints(cs).ok()) << "step " << step;
    Field T;
    ASSERT_TRUE(solver.solve(T).ok());
    if (methods) ++(*methods)[solver.stats().method];
    const Field ref = reference.field(cs);
    const double err = testref::relError(T, ref);
    if (getenv("DIAG") && !cs.empty()) {
      ExactSolver fresh;
      ASSERT_TRUE(fresh.setGrid(g, omega).ok());
      ASSERT_TRUE(fresh.setConstraints(cs).ok());
      Field F;
      ASSERT_TRUE(fresh.solve(F).ok());
      printf("step %d %s n=%zu vsEigen %.2e vsFresh %.2e freshVsEigen %.2e\n", step,
             solver.stats().method.c_str(), cs.size(), err, testref::relError(T, F),
             testref::relError(F, ref));
    }
    worst = std::max(worst, err);
    if (!getenv("DIAG"))
      ASSERT_LT(err, 1e-10) << "step " << step << " method " << solver.stats().method;
    if (cs.empty()) {
      ASSERT_EQ(T.norm(), 0.0);
    }
  }
  ::testing::Test::RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(ExactSolver, RandomEditsSmallGridUpdates) {
  std::map<std::string, int> m;
  randomEdits(box(7, 6, 5), ExactSolverOptions::Policy::AlwaysUpdate, 5, 200, &m);
  EXPECT_GT(m["update"], 50);
  EXPECT_GT(m["rhs"], 10);
}

TEST(ExactSolver, RandomEditsMediumGridUpdates) {
  std::map<std::string, int> m;
  randomEdits(box(13, 12, 11), ExactSolverOptions::Policy::AlwaysUpdate, 6, 200, &m);
  EXPECT_GT(m["update"], 50);
}

TEST(ExactSolver, RandomEditsBothKernels) {
  // The wasm build defaults to the rank-1 kernel, the native build to the blocked one.
  for (UpdateKernel k : {UpdateKernel::Rank1, UpdateKernel::Blocked}) {
    std::map<std::string, int> m;
    randomEdits(box(9, 8, 10), ExactSolverOptions::Policy::AlwaysUpdate, 9, 200, &m, k);
    EXPECT_GT(m["update"], 50);
  }
}

TEST(ExactSolver, RandomEditsMediumGridCostModel) {
  std::map<std::string, int> m;
  randomEdits(box(12, 12, 12), ExactSolverOptions::Policy::Auto, 8, 60, &m);
  EXPECT_GT(m["update"], 0);
}

TEST(ExactSolver, NoConstraintsGiveZeroField) {
  auto solver = makeFieldSolver("exact");
  ASSERT_NE(solver, nullptr);
  EXPECT_EQ(solver->name(), "exact");
  const Grid g = box(5, 5, 5);
  ASSERT_TRUE(solver->setGrid(g, 100).ok());
  Field T;
  ASSERT_TRUE(solver->setConstraints({}).ok());
  ASSERT_TRUE(solver->solve(T).ok());
  EXPECT_EQ(T.rows(), g.size());
  EXPECT_EQ(T.norm(), 0.0);
  // Constraints, then none again, then some: still exact.
  ConstraintSet a = {{3, {1, 0, 0}}, {40, {0, 1, 0}}};
  ASSERT_TRUE(solver->setConstraints(a).ok());
  ASSERT_TRUE(solver->solve(T).ok());
  EXPECT_LT(testref::relError(T, testref::referenceField(g, a, 100)), 1e-10);
  ASSERT_TRUE(solver->setConstraints({}).ok());
  ASSERT_TRUE(solver->solve(T).ok());
  EXPECT_EQ(T.norm(), 0.0);
  ConstraintSet b = {{7, {0, 0, 1}}};
  ASSERT_TRUE(solver->setConstraints(b).ok());
  EXPECT_EQ(solver->stats().method, "update");
  ASSERT_TRUE(solver->solve(T).ok());
  EXPECT_LT(testref::relError(T, testref::referenceField(g, b, 100)), 1e-10);
}

TEST(ExactSolver, RejectsBadInput) {
  ExactSolver s;
  EXPECT_FALSE(s.setGrid(box(1, 5, 5), 100).ok());
  EXPECT_FALSE(s.setGrid(box(5, 5, 5), std::numeric_limits<double>::infinity()).ok());
  ExactSolver t;
  ASSERT_TRUE(t.setGrid(box(5, 5, 5), 100).ok());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(t.setConstraints({{3, {nan, 0, 0}}}).code, StatusCode::NonFinite);
  EXPECT_EQ(t.setConstraints({{125, {1, 0, 0}}}).code, StatusCode::InvalidInput);
  EXPECT_EQ(t.setConstraints({{-1, {1, 0, 0}}}).code, StatusCode::InvalidInput);
  EXPECT_EQ(t.setConstraints({{9, {1, 0, 0}}, {3, {1, 0, 0}}}).code, StatusCode::InvalidInput);
  // Nothing reached the factor: a valid set still works.
  ConstraintSet ok = {{3, {1, 0, 0}}};
  ASSERT_TRUE(t.setConstraints(ok).ok());
  Field T;
  ASSERT_TRUE(t.solve(T).ok());
  EXPECT_LT(testref::relError(T, testref::referenceField(box(5, 5, 5), ok, 100)), 1e-10);
}

TEST(ExactSolver, CapRefusesHugeGrid) {
  ExactSolver s;
  s.setMemoryCap(1 << 20);
  const Status st = s.setGrid(box(20, 20, 20), 100);
  EXPECT_EQ(st.code, StatusCode::OverMemoryCap);
  EXPECT_NE(st.message.find("over the memory cap (needs ~"), std::string::npos) << st.message;
  EXPECT_NE(st.message.find(" MB, cap 1 MB)"), std::string::npos) << st.message;
}

TEST(ExactSolver, FailedDowndateIsRecoveredByRefactor) {
  const Grid g = box(10, 9, 8);
  ExactSolverOptions o;
  o.policy = ExactSolverOptions::Policy::AlwaysUpdate;
  ExactSolver s(o);
  ASSERT_TRUE(s.setGrid(g, 100).ok());
  ConstraintSet a = {{5, {1, 0, 0}}, {300, {0, 1, 0}}, {301, {0, 1, 0}}};
  ASSERT_TRUE(s.setConstraints(a).ok());
  ConstraintSet b = {{5, {1, 0, 0}}, {301, {0, 1, 0}}, {600, {0, 0, 1}}};
  s.injectBadDowndateForTest(g.index(4, 4, 4));  // not constrained: the downdate breaks down
  ASSERT_TRUE(s.setConstraints(b).ok());
  EXPECT_EQ(s.stats().method, "recover");
  EXPECT_TRUE(s.factor().valid());
  Field T;
  ASSERT_TRUE(s.solve(T).ok());
  EXPECT_LT(testref::relError(T, testref::referenceField(g, b, 100)), 1e-10);
  // And the recovered factor keeps updating correctly.
  ConstraintSet c = {{5, {1, 0, 0}}, {600, {0, 0, 1}}, {601, {0, 0, 1}}};
  ASSERT_TRUE(s.setConstraints(c).ok());
  EXPECT_EQ(s.stats().method, "update");
  ASSERT_TRUE(s.solve(T).ok());
  EXPECT_LT(testref::relError(T, testref::referenceField(g, c, 100)), 1e-10);
}

TEST(ExactSolver, ResidualAndEnergyMinimum) {
  const Grid g = box(11, 10, 12);
  ExactSolver s;
  ASSERT_TRUE(s.setGrid(g, 100).ok());
  std::mt19937 rng(4);
  ConstraintSet cs;
  for (int p = 0; p < int(g.size()); p += 37) cs.push_back({p, randomTarget(rng)});
  ASSERT_TRUE(s.setConstraints(cs).ok());
  Field T;
  ASSERT_TRUE(s.solve(T).ok());
  // M T = B, with M applied matrix-free (independent of the assembled matrix).
  Field Y;
  applyBiLaplacian(g, T, Y);
  for (const Constraint& c : cs) Y.row(c.index) += 1e4 * T.row(c.index);
  const Field B = assembleRhs(g, cs, 100);
  EXPECT_LT((Y - B).norm() / B.norm(), 1e-12);
  // The solution minimises the energy: perturbations increase it.
  const double e0 = fieldEnergy(g, cs, 100, T);
  for (int t = 0; t < 5; ++t) {
    Field P = T + 1e-3 * Field::Random(g.size(), 3);
    EXPECT_GT(fieldEnergy(g, cs, 100, P), e0);
  }
}

}  // namespace
}  // namespace exact_solver_test

namespace exact_solver_test {
using namespace hairsketch;
namespace {

TEST(ExactSolver, CostModelPrefersUpdateForSmallEditsAndRefactorForHugeOnes) {
  const Grid g = testref::box(16, 16, 16);
  ExactSolver s;
  ASSERT_TRUE(s.setGrid(g, 100).ok());
  ConstraintSet base;
  for (int p = 0; p < int(g.size()); p += 97) base.push_back({p, {1, 0, 0}});
  ASSERT_TRUE(s.setConstraints(base).ok());
  EXPECT_EQ(s.stats().method, "factor");
  // A few new points: update.
  ConstraintSet small = base;
  small.push_back({g.index(3, 3, 3), {0, 1, 0}});
  small.push_back({g.index(3, 3, 4), {0, 1, 0}});
  small = normalizeConstraints(small);
  ASSERT_TRUE(s.setConstraints(small).ok());
  EXPECT_EQ(s.stats().method, "update");
  EXPECT_EQ(s.stats().added, 2);
  // Constrain half the grid at once: the path costs exceed a factorisation.
  ConstraintSet huge;
  for (int p = 0; p < int(g.size()); p += 2) huge.push_back({p, {0, 0, 1}});
  ASSERT_GT(s.estimateUpdateFlops([&] {
    std::vector<int> v;
    for (const Constraint& c : huge) v.push_back(c.index);
    return v;
  }()),
            s.factorFlops());
  ASSERT_TRUE(s.setConstraints(huge).ok());
  EXPECT_EQ(s.stats().method, "refactor");
  Field T;
  ASSERT_TRUE(s.solve(T).ok());
  EXPECT_LT(testref::relError(T, testref::referenceField(g, huge, 100)), 1e-10);
  // Targets only: no factor work.
  for (Constraint& c : huge) c.target = {1, 1, 0};
  ASSERT_TRUE(s.setConstraints(huge).ok());
  EXPECT_EQ(s.stats().method, "rhs");
  EXPECT_EQ(s.stats().changed, int(huge.size()));
}

}  // namespace
}  // namespace exact_solver_test
