// The natural-fall prior (FieldSolver::setPrior): every solver minimises
//   E(T) = ||D T||^2 + omega^2 sum_{p in C} ||t_p - c_p||^2 + beta^2 sum_p ||t_p - g_p||^2,
// i.e. solves (D^T D + omega^2 S + beta^2 I) T = omega^2 S C + beta^2 G. Checked against an
// independent dense solve (Eigen LLT of the assembled matrix; Eigen's sparse LDL^T on the grids
// too large for a dense one), after edit sequences, with an empty constraint set, for beta^2 = 0
// (bit-identical to no prior), for refused input, and by the energy's minimum. The multigrid
// hierarchy's base penalty is checked against Galerkin products, and the fast solver's
// history-free solve (forgetWarmStart) with a prior against a fresh solver's, bit for bit.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include "cg_solver.hpp"
#include "exact_solver.hpp"
#include "field_solver.hpp"
#include "mg_pcg_solver.hpp"
#include "multigrid_hierarchy.hpp"
#include "multigrid_transfer.hpp"
#include "random_vector.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace prior_test {

using namespace hairsketch;

namespace {

const char* const kSolvers[] = {"cg", "fast", "exact", "auto"};

Grid box(int nx, int ny, int nz) {
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.nz = nz;
  return g;
}

ConstraintSet randomSet(const Grid& g, unsigned seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(0, int(g.size()) - 1);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<Constraint> raw;
  for (int c = 0; c < count; ++c)
    raw.push_back(
        {pick(rng), hairsketch_test::drawVector([&](int) { return n(rng); }).normalized()});
  return normalizeConstraints(raw);
}

// A random prior field: unit vectors around "down" (as the fall directions are).
Field randomPrior(const Grid& g, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 0.4);
  Field G(g.size(), 3);
  for (int p = 0; p < int(g.size()); ++p)
    G.row(p) =
        hairsketch_test::drawVector([&](int axis) { return (axis == 1 ? -1.0 : 0.0) + n(rng); })
            .normalized()
            .transpose();
  return G;
}

// (D^T D + omega^2 S + beta^2 I) and omega^2 S C + beta^2 G, assembled here from D.
SparseMatrix systemMatrix(const Grid& g, const ConstraintSet& set, double omega, double beta2) {
  const SparseMatrix D = assembleLaplacian(g);
  SparseMatrix M = SparseMatrix(D.transpose()) * D;
  for (int p = 0; p < int(g.size()); ++p) M.coeffRef(p, p) += beta2;
  for (const Constraint& c : set) M.coeffRef(c.index, c.index) += omega * omega;
  return M;
}

Field systemRhs(const Grid& g, const ConstraintSet& set, double omega, double beta2,
                const Field& G) {
  Field B = Field::Zero(g.size(), 3);
  if (G.rows() > 0) B = beta2 * G;
  for (const Constraint& c : set) B.row(c.index) += omega * omega * c.target.transpose();
  return B;
}

// Dense Cholesky (small grids).
Field denseSolve(const Grid& g, const ConstraintSet& set, double omega, double beta2,
                 const Field& G) {
  const Eigen::MatrixXd M(systemMatrix(g, set, omega, beta2));
  Eigen::LLT<Eigen::MatrixXd> llt(M);
  EXPECT_EQ(llt.info(), Eigen::Success);
  return Field(llt.solve(Eigen::MatrixXd(systemRhs(g, set, omega, beta2, G))));
}

// Sparse LDL^T (grids too large for the dense solve).
Field sparseSolve(const Grid& g, const ConstraintSet& set, double omega, double beta2,
                  const Field& G) {
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(systemMatrix(g, set, omega, beta2));
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  return Field(ldlt.solve(Eigen::MatrixXd(systemRhs(g, set, omega, beta2, G))));
}

double relErr(const Field& a, const Field& ref) {
  const double r = ref.norm();
  return r == 0 ? a.norm() : (a - ref).norm() / r;
}

bool bitIdentical(const Field& a, const Field& b) {
  return a.rows() == b.rows() && (a.array() == b.array()).all();
}

// A solver by name with its iterative tolerance tight enough for a 1e-8 comparison.
std::unique_ptr<FieldSolver> tightSolver(const std::string& name) {
  if (name == "cg") {
    CgOptions o;
    o.errorTolerance = 1e-10;
    return std::make_unique<CgSolver>(o);
  }
  if (name == "fast") {
    auto s = std::make_unique<MgPcgSolver>();
    s->setTolerance(1e-11);
    s->setMaxIterations(2000);
    return s;
  }
  return makeFieldSolver(name);
}

Field solved(FieldSolver& s) {
  Field T;
  const Status st = s.solve(T);
  EXPECT_TRUE(st.ok()) << s.name() << ": " << st.message;
  return T;
}

// Converged by small iterate() slices (as the engine runs the fast solver), tolerance 1e-6.
Field converge(FieldSolver& s) {
  Field T;
  IterateProgress p;
  for (int guard = 0; guard < 2000 && !p.converged; ++guard) {
    Status st = s.iterate(4, 1e-6, T, p);
    if (!st.ok() && st.code != StatusCode::NotConverged) ADD_FAILURE() << st.message;
  }
  EXPECT_TRUE(p.converged);
  return T;
}

// Fine operator M = D^T D + W assembled independently, W the hierarchy's penalties.
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

TEST(Prior, EverySolverMatchesADenseSolve) {
  for (const Grid& g : {box(6, 7, 5), box(9, 8, 10)}) {
    const ConstraintSet set = randomSet(g, 3 + g.nx, int(g.size() / 8));
    const Field G = randomPrior(g, 5 + g.nz);
    for (double beta2 : {1e-3, 0.05}) {
      const Field ref = denseSolve(g, set, kDefaultOmega, beta2, G);
      const Field noPrior = denseSolve(g, set, kDefaultOmega, 0, Field());
      ASSERT_GT(relErr(noPrior, ref), 1e-6);  // the prior changes the field
      for (const char* name : kSolvers) {
        SCOPED_TRACE(std::string(name) + " " + std::to_string(g.nx) + "x" + std::to_string(g.ny) +
                     "x" + std::to_string(g.nz) + " beta2 " + std::to_string(beta2));
        auto s = tightSolver(name);
        ASSERT_TRUE(s->setGrid(g, kDefaultOmega).ok());
        ASSERT_TRUE(s->setPrior(beta2, G).ok());
        ASSERT_TRUE(s->setConstraints(set).ok());
        EXPECT_LE(relErr(solved(*s), ref), 1e-8);
      }
    }
  }
}

// Constraint edits (add, remove, move targets, empty, refill) and prior changes (a new G, a new
// beta^2, beta^2 = 0) in one session: after each, the field is a fresh dense solve's.
TEST(Prior, EditSequencesMatchAFreshDenseSolve) {
  const Grid g = box(9, 8, 10);
  const Field G1 = randomPrior(g, 21), G2 = randomPrior(g, 22);
  for (const char* name : kSolvers) {
    SCOPED_TRACE(name);
    auto s = tightSolver(name);
    ASSERT_TRUE(s->setGrid(g, kDefaultOmega).ok());
    double beta2 = 1e-3;
    Field G = G1;
    ASSERT_TRUE(s->setPrior(beta2, G).ok());
    std::mt19937 rng(17);
    std::vector<Constraint> raw;
    auto check = [&](const char* step) {
      SCOPED_TRACE(step);
      const ConstraintSet set = normalizeConstraints(raw);
      ASSERT_TRUE(s->setConstraints(set).ok());
      EXPECT_LE(relErr(solved(*s), denseSolve(g, set, kDefaultOmega, beta2, G)), 1e-8);
    };
    for (const Constraint& c : randomSet(g, 1, 60)) raw.push_back(c);
    check("first set");
    for (const Constraint& c : randomSet(g, 2, 40)) raw.push_back(c);
    check("added");
    for (size_t k = 0; k < raw.size();)
      if (rng() % 3 == 0)
        raw.erase(raw.begin() + long(k));
      else
        ++k;
    check("removed a third");
    for (Constraint& c : raw) c.target += Eigen::Vector3d(0.1, -0.2, 0.05);
    check("targets moved");
    beta2 = 0.05;
    G = G2;
    ASSERT_TRUE(s->setPrior(beta2, G).ok());
    check("new prior");
    raw.clear();
    check("emptied");
    for (const Constraint& c : randomSet(g, 3, 80)) raw.push_back(c);
    check("refilled");
    G = G1;
    ASSERT_TRUE(s->setPrior(beta2, G).ok());  // the same beta^2, a new G
    check("new G");
    beta2 = 0;
    ASSERT_TRUE(s->setPrior(0, G).ok());
    check("prior off");
    raw.resize(raw.size() / 2);
    check("halved without a prior");
  }
}

TEST(Prior, ZeroWeightIsBitIdenticalToNoPrior) {
  for (const Grid& g : {box(6, 7, 5), box(14, 12, 10)}) {
    const ConstraintSet set = randomSet(g, 9, int(g.size() / 10));
    const Field G = randomPrior(g, 4);
    for (const char* name : kSolvers) {
      SCOPED_TRACE(std::string(name) + " " + std::to_string(g.nx));
      auto plain = makeFieldSolver(name);
      ASSERT_TRUE(plain->setGrid(g, kDefaultOmega).ok());
      ASSERT_TRUE(plain->setConstraints(set).ok());
      const Field ref = solved(*plain);

      auto zero = makeFieldSolver(name);  // beta^2 = 0 with a G
      ASSERT_TRUE(zero->setGrid(g, kDefaultOmega).ok());
      ASSERT_TRUE(zero->setPrior(0, G).ok());
      ASSERT_TRUE(zero->setConstraints(set).ok());
      EXPECT_TRUE(bitIdentical(solved(*zero), ref));

      auto off = makeFieldSolver(name);  // a prior, switched off again before solving
      ASSERT_TRUE(off->setGrid(g, kDefaultOmega).ok());
      ASSERT_TRUE(off->setPrior(0.05, G).ok());
      ASSERT_TRUE(off->setConstraints(set).ok());
      ASSERT_TRUE(off->setPrior(0, Field()).ok());
      EXPECT_TRUE(bitIdentical(solved(*off), ref));
    }
  }
}

TEST(Prior, EmptyConstraintSetGivesThePriorsField) {
  const Grid g = box(9, 8, 10);
  const Field G = randomPrior(g, 8);
  const double beta2 = 0.05;
  const Field ref = denseSolve(g, {}, kDefaultOmega, beta2, G);
  ASSERT_GT(ref.norm(), 1.0);
  for (const char* name : kSolvers) {
    SCOPED_TRACE(name);
    auto s = tightSolver(name);
    ASSERT_TRUE(s->setGrid(g, kDefaultOmega).ok());
    ASSERT_TRUE(s->setPrior(beta2, G).ok());
    EXPECT_LE(relErr(solved(*s), ref), 1e-8) << "no setConstraints";
    ASSERT_TRUE(s->setConstraints({}).ok());
    EXPECT_LE(relErr(solved(*s), ref), 1e-8) << "empty set";
    ASSERT_TRUE(s->setConstraints(randomSet(g, 2, 50)).ok());
    solved(*s);
    ASSERT_TRUE(s->setConstraints({}).ok());
    EXPECT_LE(relErr(solved(*s), ref), 1e-8) << "emptied";
    // A prior without a direction field pulls towards zero: the field of no constraints is 0.
    ASSERT_TRUE(s->setPrior(beta2, Field()).ok());
    const Field T = solved(*s);
    ASSERT_EQ(T.rows(), g.size());
    EXPECT_EQ(T.norm(), 0.0);
  }
}

TEST(Prior, RefusesBadInputAndChangesNothing) {
  const Grid g = box(9, 8, 10);
  const ConstraintSet set = randomSet(g, 6, 70);
  const Field G = randomPrior(g, 7);
  Field nanG = G, infG = G;
  nanG(5, 1) = std::numeric_limits<double>::quiet_NaN();
  infG(7, 2) = std::numeric_limits<double>::infinity();
  const Field shortG = G.topRows(g.size() - 1);
  for (const char* name : kSolvers) {
    SCOPED_TRACE(name);
    auto s = tightSolver(name);
    EXPECT_EQ(s->setPrior(0.05, G).code, StatusCode::NotReady);
    ASSERT_TRUE(s->setGrid(g, kDefaultOmega).ok());
    ASSERT_TRUE(s->setPrior(0.05, G).ok());
    ASSERT_TRUE(s->setConstraints(set).ok());
    const Field before = solved(*s);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(s->setPrior(-1e-3, G).code, StatusCode::InvalidInput);
    EXPECT_EQ(s->setPrior(nan, G).code, StatusCode::InvalidInput);
    EXPECT_EQ(s->setPrior(inf, G).code, StatusCode::InvalidInput);
    EXPECT_EQ(s->setPrior(0.05, nanG).code, StatusCode::InvalidInput);
    EXPECT_EQ(s->setPrior(0.05, infG).code, StatusCode::InvalidInput);
    EXPECT_EQ(s->setPrior(0.05, shortG).code, StatusCode::InvalidInput);
    EXPECT_EQ(s->setPrior(0.0, nanG).code, StatusCode::InvalidInput);
    const Field after = solved(*s);
    if (std::string(name) == "cg")  // solves again from its warm start
      EXPECT_LE(relErr(after, before), 1e-9);
    else
      EXPECT_TRUE(bitIdentical(after, before));
    EXPECT_LE(relErr(after, denseSolve(g, set, kDefaultOmega, 0.05, G)), 1e-8);
  }
}

// The solution minimises the stated energy: its directional derivatives vanish (central
// differences, exact for a quadratic up to rounding) and every perturbation raises it. The
// check is not vacuous: the solution for a 2 % smaller beta^2 fails it.
TEST(Prior, SolutionMinimisesTheEnergy) {
  const Grid g = box(9, 8, 10);
  const ConstraintSet set = randomSet(g, 12, 90);
  const Field G = randomPrior(g, 13);
  const double beta2 = 0.05;
  // max |slope| over random directions and the prior's pull G - T, relative to E(T)
  auto worstSlope = [&](const Field& T, bool expectRaised) {
    const double e0 = fieldEnergy(g, set, kDefaultOmega, T, beta2, G);
    std::mt19937 rng(3);
    std::normal_distribution<double> n(0.0, 1.0);
    double worst = 0;
    for (int trial = 0; trial < 7; ++trial) {
      Field dir(g.size(), 3);
      for (int i = 0; i < dir.size(); ++i) dir.data()[i] = n(rng);
      if (trial == 6) dir = G - T;
      dir /= dir.norm();
      const double h = 1e-3;
      const double ep = fieldEnergy(g, set, kDefaultOmega, Field(T + h * dir), beta2, G);
      const double em = fieldEnergy(g, set, kDefaultOmega, Field(T - h * dir), beta2, G);
      if (expectRaised) {
        EXPECT_GT(ep, e0);
        EXPECT_GT(em, e0);
      }
      worst = std::max(worst, std::abs(ep - em) / (2 * h) / e0);
    }
    return worst;
  };
  const Field wrong = denseSolve(g, set, kDefaultOmega, 0.98 * beta2, G);
  EXPECT_GT(worstSlope(wrong, false), 1e-4);
  for (const char* name : kSolvers) {
    SCOPED_TRACE(name);
    auto s = tightSolver(name);
    ASSERT_TRUE(s->setGrid(g, kDefaultOmega).ok());
    ASSERT_TRUE(s->setPrior(beta2, G).ok());
    ASSERT_TRUE(s->setConstraints(set).ok());
    const Field T = solved(*s);
    // the prior term is part of the energy
    EXPECT_GT(fieldEnergy(g, set, kDefaultOmega, T, beta2, G),
              fieldEnergy(g, set, kDefaultOmega, T) + 1e-3);
    EXPECT_LE(worstSlope(T, true), 1e-7);
  }
}

// Fast solver on multilevel hierarchies (two levels at the default coarsest size, three, and a
// deep one), edits included, against a sparse direct solve.
TEST(Prior, FastSolverOnMultilevelHierarchies) {
  struct Case {
    Grid g;
    int coarsest;
  };
  for (const Case& cs :
       {Case{box(14, 12, 10), 1000}, Case{box(20, 16, 14), 512}, Case{box(17, 13, 11), 40}}) {
    const Grid& g = cs.g;
    SCOPED_TRACE(std::to_string(g.nx) + "x" + std::to_string(g.ny) + "x" + std::to_string(g.nz));
    MultigridOptions o;
    o.coarsestMaxPoints = cs.coarsest;
    MgPcgSolver s(o);
    s.setTolerance(1e-11);
    s.setMaxIterations(2000);
    ASSERT_TRUE(s.setGrid(g, kDefaultOmega).ok());
    ASSERT_GE(s.hierarchy().levels(), 2);
    const Field G = randomPrior(g, 31);
    for (double beta2 : {1e-3, 0.05}) {
      ASSERT_TRUE(s.setPrior(beta2, G).ok());
      ConstraintSet set = randomSet(g, 41, int(g.size() / 30));
      ASSERT_TRUE(s.setConstraints(set).ok());
      EXPECT_LE(relErr(solved(s), sparseSolve(g, set, kDefaultOmega, beta2, G)), 1e-8);
      set = randomSet(g, 42, int(g.size() / 25));  // a big edit: adds and removes
      ASSERT_TRUE(s.setConstraints(set).ok());
      EXPECT_LE(relErr(solved(s), sparseSolve(g, set, kDefaultOmega, beta2, G)), 1e-8);
      ASSERT_TRUE(s.setConstraints({}).ok());
      EXPECT_LE(relErr(solved(s), sparseSolve(g, {}, kDefaultOmega, beta2, G)), 1e-8);
    }
  }
}

// The base penalty's coarse operators are the Galerkin products P^T (D^T D + W) P with W
// = beta^2 I + the point penalties, after local updates, resets and a change of beta^2.
TEST(Prior, HierarchyBasePenaltyGivesGalerkinOperators) {
  for (const Grid g : {box(11, 9, 10), box(14, 7, 12), box(6, 13, 5)}) {
    MultigridOptions o;
    o.coarsestMaxPoints = 20;
    MultigridHierarchy h;
    ASSERT_TRUE(h.build(g, o).ok());
    ASSERT_GE(h.levels(), 3);
    std::mt19937 rng(7);
    for (double beta2 : {0.05, 1e-3}) {
      ASSERT_TRUE(h.setBasePenalty(beta2).ok());
      EXPECT_EQ(h.penalty(0), beta2);
      for (int round = 0; round < 3; ++round) {
        for (int a = 0; a < 30; ++a) ASSERT_TRUE(h.setPenalty(int(rng() % g.size()), 1e4).ok());
        for (int a = 0; a < 10; ++a) ASSERT_TRUE(h.setPenalty(int(rng() % g.size()), beta2).ok());
        if (round == 2) ASSERT_TRUE(h.resetPenalties().ok());
        ASSERT_TRUE(h.prepare().ok());
        SparseMatrix A = fineMatrix(g, h);
        for (int l = 1; l < h.levels(); ++l) {
          const SparseMatrix P = eigenFromCsr(interpolationMatrix(h.transfer(l - 1)));
          const SparseMatrix ref = SparseMatrix(P.transpose()) * A * P;
          const SparseMatrix got = eigenFromCsr(h.levelMatrix(l));
          ASSERT_EQ(got.rows(), ref.rows());
          EXPECT_LE(maxAbs(got - ref), 1e-12 * maxAbs(ref))
              << "level " << l << " round " << round << " beta2 " << beta2;
          A = ref;
        }
      }
    }
  }
}

// With a prior, forgetWarmStart still makes the converged field a function of the constraints
// and the prior alone: bit-identical to a fresh solver's, whatever came before (edits, an empty
// set solved with the prior, an earlier prior, the prior set after the constraints).
TEST(Prior, ForgettingTheWarmStartIsHistoryFree) {
  const Grid g = box(14, 12, 10);
  const ConstraintSet before = randomSet(g, 1, 120);
  const ConstraintSet after = randomSet(g, 2, 150);
  const Field G = randomPrior(g, 3), Gold = randomPrior(g, 4);
  const double beta2 = 2e-3;
  for (const char* name : {"fast", "cg"}) {
    SCOPED_TRACE(name);
    auto fresh = makeFieldSolver(name);
    ASSERT_TRUE(fresh->setGrid(g, kDefaultOmega).ok());
    ASSERT_TRUE(fresh->setPrior(beta2, G).ok());
    ASSERT_TRUE(fresh->setConstraints(after).ok());
    const Field cold = converge(*fresh);
    EXPECT_LE(relErr(cold, sparseSolve(g, after, kDefaultOmega, beta2, G)), 1e-5);

    auto edited = makeFieldSolver(name);  // edits, then forget
    ASSERT_TRUE(edited->setGrid(g, kDefaultOmega).ok());
    ASSERT_TRUE(edited->setPrior(beta2, G).ok());
    ASSERT_TRUE(edited->setConstraints(before).ok());
    converge(*edited);
    ASSERT_TRUE(edited->setConstraints(after).ok());
    EXPECT_TRUE(edited->forgetWarmStart());
    EXPECT_TRUE(bitIdentical(converge(*edited), cold)) << "after edits";

    auto fromEmpty = makeFieldSolver(name);  // the prior's field first, then constraints
    ASSERT_TRUE(fromEmpty->setGrid(g, kDefaultOmega).ok());
    ASSERT_TRUE(fromEmpty->setPrior(beta2, G).ok());
    ASSERT_TRUE(fromEmpty->setConstraints({}).ok());
    converge(*fromEmpty);
    ASSERT_TRUE(fromEmpty->setConstraints(after).ok());
    EXPECT_TRUE(fromEmpty->forgetWarmStart());
    EXPECT_TRUE(bitIdentical(converge(*fromEmpty), cold)) << "after the empty set";

    auto priorLater = makeFieldSolver(name);  // an older prior, constraints, then the prior
    ASSERT_TRUE(priorLater->setGrid(g, kDefaultOmega).ok());
    ASSERT_TRUE(priorLater->setPrior(0.05, Gold).ok());
    ASSERT_TRUE(priorLater->setConstraints(before).ok());
    converge(*priorLater);
    ASSERT_TRUE(priorLater->setConstraints(after).ok());
    converge(*priorLater);
    ASSERT_TRUE(priorLater->setPrior(beta2, G).ok());
    EXPECT_TRUE(priorLater->forgetWarmStart());
    EXPECT_TRUE(bitIdentical(converge(*priorLater), cold)) << "prior set last";
  }
}

}  // namespace prior_test
