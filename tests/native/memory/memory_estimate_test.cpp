// Each solver's memory estimate against the measured peak of setGrid (+ setPrior) +
// setConstraints + solve:
// its own executable (memory_estimate_tests), as it replaces malloc to count every byte.
// estimate >= measured, and not absurdly larger (<= 3x). Prints the figures.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "counting_malloc.hpp"
#include "field_solver.hpp"

using namespace hairsketch;

namespace {

struct Case {
  const char* solver;
  int nx, ny, nz;
  bool prior = false;  // setPrior(beta^2, G) after setGrid (G is the caller's, not counted)
};

void measure(const Case& c) {
  Grid g;
  g.nx = c.nx;
  g.ny = c.ny;
  g.nz = c.nz;
  Field G;
  if (c.prior) G = Field::Constant(g.size(), 3, -0.5);
  const int64_t base = counting::live.load();
  counting::resetPeak();
  double estimate = 0;
  {
    auto s = makeFieldSolver(c.solver);
    s->setMemoryCap(int64_t(1) << 40);
    // Plain CG holds all it will hold from its first iteration: a few are enough for its peak
    // (it took 20 s to converge on 2 x 2 x 100000). The multigrid solver's peak comes later.
    if (std::string(c.solver) == "cg")
      s->setProgressHook([n = 0](const IterateProgress&) mutable { return ++n < 4; });
    const double before = s->estimateBytes(g);
    ASSERT_TRUE(s->setGrid(g, 100).ok());
    estimate = s->estimateBytes(g);  // exact: from the symbolic count now
    if (c.prior) ASSERT_TRUE(s->setPrior(2e-3, G).ok());
    ConstraintSet cs;
    for (int k = 1; k < g.nz - 1; k += 3) cs.push_back({g.index(g.nx / 2, g.ny / 2, k), {0, 0, 1}});
    for (int i = 0; i < g.nx; i += 2) cs.push_back({g.index(i, 0, 0), {1, 0, 0}});
    ASSERT_TRUE(s->setConstraints(normalizeConstraints(cs)).ok());
    Field T;
    s->solve(T);
    const double peak = double(counting::peak.load() - base);
    std::printf(
        "[memory] %-5s%s %4dx%4dx%6d  estimate %8.1f MB (from dims %8.1f MB)  measured %8.1f MB  "
        "ratio %.2f\n",
        c.solver, c.prior ? "+prior" : "", c.nx, c.ny, c.nz, estimate / 1e6, before / 1e6,
        peak / 1e6, estimate / peak);
    EXPECT_GE(estimate, peak) << c.solver << " " << c.nx << "x" << c.ny << "x" << c.nz;
    EXPECT_LE(estimate, 3 * peak + double(2 << 20))
        << c.solver << " " << c.nx << "x" << c.ny << "x" << c.nz;
    EXPECT_GE(before, 0.5 * peak);  // the figure before the analysis is of the right size
  }
}

}  // namespace

TEST(MemoryEstimate, ExactAgainstMeasuredPeak) {
  for (const Case& c :
       {Case{"exact", 10, 10, 10}, Case{"exact", 20, 20, 20}, Case{"exact", 29, 29, 29},
        Case{"exact", 12, 30, 40}, Case{"exact", 2, 2, 2000}, Case{"exact", 4, 4, 3000},
        Case{"exact", 20, 20, 20, true}, Case{"exact", 2, 2, 2000, true}})
    measure(c);
}

TEST(MemoryEstimate, FastAgainstMeasuredPeak) {
  for (const Case& c :
       {Case{"fast", 10, 10, 10}, Case{"fast", 40, 40, 40}, Case{"fast", 64, 64, 64},
        Case{"fast", 100, 50, 20}, Case{"fast", 2, 2, 100000}, Case{"fast", 2, 40, 40},
        Case{"fast", 40, 40, 40, true}})
    measure(c);
}

TEST(MemoryEstimate, CgAndAutoAgainstMeasuredPeak) {
  for (const Case& c : {Case{"cg", 20, 20, 20}, Case{"cg", 40, 40, 40}, Case{"cg", 2, 2, 100000},
                        Case{"auto", 20, 20, 20}, Case{"auto", 40, 40, 40},
                        Case{"cg", 40, 40, 40, true}, Case{"auto", 40, 40, 40, true}})
    measure(c);
}
