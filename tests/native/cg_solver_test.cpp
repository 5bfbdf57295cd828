// CG against an independent dense solve of the normal equations (method S2.3).
#include "cg_solver.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "field_system.hpp"
#include "rng.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace cg_solver_test {

using namespace hairsketch;

namespace {

Grid makeGrid(int nx, int ny, int nz) {
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.nz = nz;
  g.origin = {-1, 0.5, 2};
  g.step = 0.25;
  return g;
}

ConstraintSet randomConstraints(const Grid& g, int count, uint64_t seed) {
  Pcg32 r(seed);
  std::vector<Constraint> raw;
  for (int c = 0; c < count; ++c) {
    const int p = int(r.nextU32() % uint32_t(g.size()));
    raw.push_back({p, {2 * r.uniform() - 1, 2 * r.uniform() - 1, 2 * r.uniform() - 1}});
  }
  return normalizeConstraints(raw);
}

// Dense (D^T D + w^2 S) T = w^2 S C, D built from its definition (S2.2), LLT.
Field denseSolve(const Grid& g, const ConstraintSet& set, double omega) {
  const int n = int(g.size());
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        std::vector<int> nb;
        const int d[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (const auto& o : d)
          if (g.contains(i + o[0], j + o[1], k + o[2]))
            nb.push_back(g.index(i + o[0], j + o[1], k + o[2]));
        const int p = g.index(i, j, k);
        D(p, p) = -1;
        for (int q : nb) D(p, q) += 1.0 / nb.size();
      }
  Eigen::MatrixXd M = D.transpose() * D;
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, 3);
  for (const Constraint& c : set) {
    M(c.index, c.index) += omega * omega;
    B.row(c.index) = omega * omega * c.target.transpose();
  }
  return Field(M.llt().solve(B));
}

}  // namespace

TEST(CgSolver, OperatorMatchesBiLaplacianPlusPenalty) {
  const Grid g = makeGrid(5, 6, 7);
  const ConstraintSet set = randomConstraints(g, 20, 3);
  CgSolver s;
  ASSERT_TRUE(s.setGrid(g, 100).ok());
  ASSERT_TRUE(s.setConstraints(set).ok());
  const Field X = Field::Random(g.size(), 3);
  Field Y, Yref;
  s.applyOperator(X, Y);
  applyBiLaplacian(g, X, Yref);
  Yref += (penaltyDiagonal(g, set, 100).asDiagonal() * X);
  EXPECT_LT((Y - Yref).cwiseAbs().maxCoeff(), 1e-9 * Yref.cwiseAbs().maxCoeff());
}

TEST(CgSolver, MatchesDenseSolveAndMinimisesEnergy) {
  for (auto dims : {std::array<int, 3>{5, 6, 7}, std::array<int, 3>{2, 3, 4}}) {
    const Grid g = makeGrid(dims[0], dims[1], dims[2]);
    const ConstraintSet set = randomConstraints(g, 12, 11);
    const Field ref = denseSolve(g, set, kDefaultOmega);
    CgOptions tight;
    tight.errorTolerance = 1e-9;
    CgSolver s(tight);
    ASSERT_TRUE(s.setGrid(g, kDefaultOmega).ok());
    ASSERT_TRUE(s.setConstraints(set).ok());
    Field T;
    const Status st = s.solve(T);
    ASSERT_TRUE(st.ok()) << st.message;
    EXPECT_EQ(s.stats().method, "cg");
    EXPECT_GT(s.stats().iterations, 0);
    double worst = 0;  // per-component relative error, as the stopping bound measures it
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, (T.col(c) - ref.col(c)).norm() / ref.col(c).norm());
    EXPECT_LT(worst, 1e-8);
    // The stopping bound really bounds the error.
    EXPECT_GE(s.errorEstimate(), worst);
    EXPECT_LE(s.errorEstimate(), tight.errorTolerance * (1 + 1e-6));
    // E is minimal: every perturbation raises it.
    const double e0 = fieldEnergy(g, set, kDefaultOmega, T);
    Pcg32 r(5);
    for (int trial = 0; trial < 20; ++trial) {
      Field P = T;
      const int p = int(r.nextU32() % uint32_t(g.size()));
      P(p, trial % 3) += (trial < 10 ? 1e-3 : -1e-2);
      EXPECT_GT(fieldEnergy(g, set, kDefaultOmega, P), e0);
    }
  }
}

TEST(CgSolver, NoConstraintsGiveZeroField) {
  const Grid g = makeGrid(4, 4, 4);
  CgSolver s;
  ASSERT_TRUE(s.setGrid(g, kDefaultOmega).ok());
  Field T = Field::Ones(3, 3);
  ASSERT_TRUE(s.solve(T).ok());
  EXPECT_EQ(T.rows(), g.size());
  EXPECT_EQ(T.cwiseAbs().maxCoeff(), 0.0);
  // After clearing a previous set, the field is zero again (no stale warm start).
  ASSERT_TRUE(s.setConstraints(randomConstraints(g, 5, 1)).ok());
  ASSERT_TRUE(s.solve(T).ok());
  EXPECT_GT(T.cwiseAbs().maxCoeff(), 0.1);
  ASSERT_TRUE(s.setConstraints({}).ok());
  ASSERT_TRUE(s.solve(T).ok());
  EXPECT_EQ(T.cwiseAbs().maxCoeff(), 0.0);
}

TEST(CgSolver, RejectsBadInput) {
  const Grid g = makeGrid(4, 4, 4);
  CgSolver s;
  Field T;
  EXPECT_FALSE(s.solve(T).ok());
  EXPECT_FALSE(s.setGrid(makeGrid(1, 4, 4), 100).ok());
  EXPECT_FALSE(s.setGrid(g, std::numeric_limits<double>::quiet_NaN()).ok());
  ASSERT_TRUE(s.setGrid(g, 100).ok());
  ConstraintSet bad = {{3, {1, std::numeric_limits<double>::infinity(), 0}}};
  EXPECT_EQ(s.setConstraints(bad).code, StatusCode::NonFinite);
  EXPECT_EQ(s.setConstraints({{64, {1, 0, 0}}}).code, StatusCode::InvalidInput);
  EXPECT_EQ(s.setConstraints({{5, {1, 0, 0}}, {2, {1, 0, 0}}}).code, StatusCode::InvalidInput);
}

TEST(CgSolver, WarmStartAfterSmallEditConvergesFasterToSameAnswer) {
  const Grid g = makeGrid(10, 12, 10);
  ConstraintSet set = randomConstraints(g, 60, 9);
  CgOptions coldOptions;
  coldOptions.warmStart = false;
  CgSolver warm, cold(coldOptions);
  for (CgSolver* s : {&warm, &cold}) {
    ASSERT_TRUE(s->setGrid(g, kDefaultOmega).ok());
    ASSERT_TRUE(s->setConstraints(set).ok());
    Field T;
    ASSERT_TRUE(s->solve(T).ok());
  }
  set[3].target *= 0.9;  // drag: one target changes
  Field Tw, Tc;
  ASSERT_TRUE(warm.setConstraints(set).ok());
  ASSERT_TRUE(cold.setConstraints(set).ok());
  EXPECT_EQ(warm.stats().changed, 1);
  ASSERT_TRUE(warm.solve(Tw).ok());
  ASSERT_TRUE(cold.solve(Tc).ok());
  EXPECT_LT(warm.stats().iterations, cold.stats().iterations);
  EXPECT_LT((Tw - Tc).norm() / Tc.norm(), 1e-5);
}

TEST(CgSolver, FactoryMakesCg) {
  auto s = makeFieldSolver("cg");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->name(), "cg");
  EXPECT_FALSE(makeFieldSolver("nope"));
}

}  // namespace cg_solver_test
