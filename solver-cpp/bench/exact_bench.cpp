// Benchmark of the exact solver (paper §4.2) on an N^3 box: analyse, factor, 3-RHS solve, and edits
// that add then remove a curve's 100 / 300 / 1000 clustered points on top of ~3000 existing
// constraints, with the method the cost model chose; peak memory; optionally Eigen's
// SimplicialLDLT refactorisation as the naive baseline. Same source natively and in wasm.
//
//   exact_bench N [--baseline | --baseline-only] [--edits 100,300,1000] [--force-both]
//               [--chunk K] [--panel P] [--rank1|--blocked]   (update kernel settings)
// --force-both: every edit is also timed with the method the cost model did not choose (update
//   forced on a second solver; refactorisation forced on a third), after the memory line.
// --baseline: the naive baseline after everything else (its peak memory includes the rest).
// --baseline-only: only the naive baseline, first in the process, so that its peak memory is its
//   own; the exact solver then runs once (after the baseline's peak is taken) for the comparison.
// Prints one JSON object per line (key "kind") and nothing else on stdout.
#include <Eigen/SparseCholesky>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "exact_solver.hpp"
#include "field_system.hpp"

#ifdef __EMSCRIPTEN__
static double peakMB() { return double(__builtin_wasm_memory_size(0)) * 65536.0 / 1048576.0; }
static const char* kPlatform = "wasm";
#else
#include <sys/resource.h>
static double peakMB() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;
}
static const char* kPlatform = "native";
#endif

using namespace hairsketch;
using Clock = std::chrono::steady_clock;

static double ms(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// A stroke's points: a random walk of grid steps with momentum (as a resampled curve makes
// them), unique, not already in `taken`.
static std::vector<int> curvePoints(const Grid& g, int count, std::mt19937& rng,
                                    const std::set<int>& taken) {
  std::vector<int> out;
  std::set<int> mine;
  int p[3] = {int(rng() % unsigned(g.nx)), int(rng() % unsigned(g.ny)),
              int(rng() % unsigned(g.nz))};
  const int lim[3] = {g.nx, g.ny, g.nz};
  int axis = int(rng() % 3), dir = 1;
  int guard = 0;
  while (int(out.size()) < count && guard++ < 100 * count) {
    if (rng() % 4 == 0) {
      axis = int(rng() % 3);
      dir = (rng() % 2) ? 1 : -1;
    }
    int q = p[axis] + dir;
    if (q < 0 || q >= lim[axis]) {
      dir = -dir;
      q = p[axis] + dir;
    }
    p[axis] = q;
    const int idx = g.index(p[0], p[1], p[2]);
    if (!taken.count(idx) && mine.insert(idx).second) out.push_back(idx);
  }
  return out;
}

static ConstraintSet toSet(const std::set<int>& idx) {
  ConstraintSet cs;
  for (int i : idx) cs.push_back({i, Eigen::Vector3d(std::cos(0.1 * i), std::sin(0.1 * i), 0.5)});
  return cs;
}

// Naive baseline: Eigen SimplicialLDLT (AMD, up-looking) refactorisation of the same matrix.
struct Baseline {
  double analyseMs = 0, factorMs = 0, solveMs = 0, peakMB = 0;
  long long nnzL = 0;
  Field X;
};

static Baseline runBaseline(const Grid& g, double omega, const std::set<int>& base) {
  Baseline b;
  const SparseMatrix M = assembleBiLaplacian(g);
  SparseMatrix A = M;
  for (int i : base) A.coeffRef(i, i) += omega * omega;
  Eigen::SimplicialLDLT<SparseMatrix> ldlt;
  auto t0 = Clock::now();
  ldlt.analyzePattern(A);
  b.analyseMs = ms(t0);
  t0 = Clock::now();
  ldlt.factorize(A);
  b.factorMs = ms(t0);
  const Field B = assembleRhs(g, toSet(base), omega);
  t0 = Clock::now();
  Eigen::MatrixXd X = ldlt.solve(Eigen::MatrixXd(B));
  b.solveMs = ms(t0);
  b.X = X;
  b.nnzL = (long long)ldlt.matrixL().nestedExpression().nonZeros();
  b.peakMB = peakMB();
  return b;
}

static void printBaseline(const char* P, int N, const Baseline& b, const Field& T, bool own) {
  const double err = (b.X - T).norm() / T.norm();
  std::printf(
      "{\"kind\":\"baseline\",\"platform\":\"%s\",\"N\":%d,\"analyseMs\":%.1f,\"factorMs\":%.1f,"
      "\"solveMs\":%.1f,\"nnzL\":%lld,\"relDiffToExact\":%.1e,\"peakMB\":%.0f,"
      "\"ownProcess\":%s}\n",
      P, N, b.analyseMs, b.factorMs, b.solveMs, b.nnzL, err, b.peakMB, own ? "true" : "false");
  std::fflush(stdout);
}

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: exact_bench N [--baseline | --baseline-only] [--edits 100,300,1000] "
                 "[--force-both]\n");
    return 2;
  }
  const int N = std::atoi(argv[1]);
  bool baseline = false, baselineOnly = false, forceBoth = false;
  ExactSolverOptions opts;
  std::vector<int> edits = {100, 300, 1000};
  for (int a = 2; a < argc; ++a) {
    if (!std::strcmp(argv[a], "--baseline")) baseline = true;
    if (!std::strcmp(argv[a], "--baseline-only")) baselineOnly = true;
    if (!std::strcmp(argv[a], "--force-both")) forceBoth = true;
    if (!std::strcmp(argv[a], "--chunk") && a + 1 < argc) opts.update.chunk = std::atoi(argv[++a]);
    if (!std::strcmp(argv[a], "--panel") && a + 1 < argc) opts.update.panel = std::atoi(argv[++a]);
    if (!std::strcmp(argv[a], "--rank1")) opts.update.kernel = UpdateKernel::Rank1;
    if (!std::strcmp(argv[a], "--blocked")) opts.update.kernel = UpdateKernel::Blocked;
    if (!std::strcmp(argv[a], "--edits") && a + 1 < argc) {
      edits.clear();
      for (char* s = std::strtok(argv[++a], ","); s; s = std::strtok(nullptr, ","))
        edits.push_back(std::atoi(s));
    }
  }
  Grid g;
  g.nx = g.ny = g.nz = N;
  const double omega = 100;
  std::mt19937 rng(1234);
  const char* P = kPlatform;

  // ~3000 existing constraints from 30 curves of 100 points (the first use of rng, so the same
  // set in every mode).
  std::set<int> base;
  for (int c = 0; c < 30; ++c)
    for (int p : curvePoints(g, 100, rng, base)) base.insert(p);

  if (baselineOnly) {
    const Baseline b = runBaseline(g, omega, base);
    ExactSolver solver(opts);
    Field T;
    if (!solver.setGrid(g, omega).ok() || !solver.setConstraints(toSet(base)).ok() ||
        !solver.solve(T).ok()) {
      std::fprintf(stderr, "exact solve for the baseline comparison failed\n");
      return 1;
    }
    printBaseline(P, N, b, T, true);
    return 0;
  }

  ExactSolver solver(opts);
  auto t0 = Clock::now();
  Status st = solver.setGrid(g, omega);
  const double analyseMs = ms(t0);
  if (!st.ok()) {
    std::fprintf(stderr, "setGrid: %s\n", st.message.c_str());
    return 1;
  }
  const SupernodalSymbolic& S = solver.factor().symbolic();
  std::printf(
      "{\"kind\":\"analyse\",\"platform\":\"%s\",\"N\":%d,\"n\":%d,\"ms\":%.1f,\"supernodes\":%d,"
      "\"nnzL\":%lld,\"stored\":%lld,\"factorGflop\":%.2f,\"rootWidth\":%d,\"maxRows\":%d,"
      "\"factorMB\":%.0f}\n",
      P, N, S.n, analyseMs, S.supernodes(), (long long)S.nnzL, (long long)S.storedEntries,
      S.factorFlops * 1e-9, S.width(S.supernodes() - 1), S.maxRows,
      double(S.factorBytes()) / 1048576.0);
  std::fflush(stdout);

  t0 = Clock::now();
  st = solver.setConstraints(toSet(base));
  const double factorMs = ms(t0);
  if (!st.ok()) {
    std::fprintf(stderr, "factor: %s\n", st.message.c_str());
    return 1;
  }
  Field T;
  t0 = Clock::now();
  solver.solve(T);
  const double solveMs = ms(t0);
  std::printf(
      "{\"kind\":\"factor\",\"platform\":\"%s\",\"N\":%d,\"constraints\":%zu,\"factorMs\":%.1f,"
      "\"gflops\":%.2f,\"solveMs\":%.1f,\"peakMB\":%.0f,\"fieldSum\":%.17g,\"fieldNorm\":%.17g}\n",
      P, N, base.size(), factorMs, S.factorFlops / factorMs * 1e-6, solveMs, peakMB(), T.sum(),
      T.norm());
  std::fflush(stdout);

  // Edits: add a curve (update or refactor), then remove it.
  struct Edit {
    size_t curve;
    std::set<int> from, to;
    std::string method;  // chosen by the cost model
  };
  std::vector<std::vector<int>> curves;
  std::vector<Edit> done;
  for (int k : edits) {
    curves.push_back(curvePoints(g, k, rng, base));
    const std::vector<int>& curve = curves.back();
    std::set<int> with = base;
    with.insert(curve.begin(), curve.end());
    for (int phase = 0; phase < 2; ++phase) {
      const std::set<int>& target = phase == 0 ? with : base;
      const double est = solver.estimateUpdateFlops(curve);
      t0 = Clock::now();
      st = solver.setConstraints(toSet(target));
      const double editMs = ms(t0);
      if (!st.ok()) {
        std::fprintf(stderr, "edit: %s\n", st.message.c_str());
        return 1;
      }
      const std::string method = solver.stats().method;
      done.push_back({curves.size() - 1, phase == 0 ? base : with, target, method});
      t0 = Clock::now();
      solver.solve(T);
      const double sMs = ms(t0);
      std::printf(
          "{\"kind\":\"edit\",\"platform\":\"%s\",\"N\":%d,\"points\":%zu,\"op\":\"%s\","
          "\"method\":\"%s\",\"editMs\":%.1f,\"solveMs\":%.1f,\"refineSolves\":%d,"
          "\"updateGflop\":%.2f,\"peakMB\":%.0f}\n",
          P, N, curve.size(), phase == 0 ? "add" : "remove", method.c_str(), editMs, sMs,
          solver.stats().iterations, est * 1e-9, peakMB());
      std::fflush(stdout);
    }
  }
  std::printf("{\"kind\":\"memory\",\"platform\":\"%s\",\"N\":%d,\"peakMB\":%.0f}\n", P, N,
              peakMB());
  std::fflush(stdout);

  if (forceBoth) {
    // Each edit again with the method the cost model did not choose, to check its choice: an
    // update forced on a second solver, a refactorisation forced on a third (one at a time, after
    // the memory line so that their factors do not count). A forced solver is first brought to
    // the edit's starting set (untimed) when it does not hold it already.
    const ExactSolverOptions::Policy policies[2] = {ExactSolverOptions::Policy::AlwaysUpdate,
                                                    ExactSolverOptions::Policy::AlwaysRefactor};
    const char* names[2] = {"update", "refactor"};
    for (int f = 0; f < 2; ++f) {
      ExactSolverOptions o = opts;
      o.policy = policies[f];
      ExactSolver forced(o);
      forced.setGrid(g, omega);
      std::set<int> holds = base;
      forced.setConstraints(toSet(base));
      for (const Edit& e : done) {
        if (e.method == names[f]) continue;
        if (holds != e.from) forced.setConstraints(toSet(e.from));
        t0 = Clock::now();
        forced.setConstraints(toSet(e.to));
        const double editMs = ms(t0);
        holds = e.to;
        std::printf(
            "{\"kind\":\"forced\",\"platform\":\"%s\",\"N\":%d,\"points\":%zu,\"op\":\"%s\","
            "\"method\":\"%s\",\"editMs\":%.1f}\n",
            P, N, curves[e.curve].size(), e.to.size() > e.from.size() ? "add" : "remove",
            forced.stats().method.c_str(), editMs);
        std::fflush(stdout);
      }
    }
  }

  if (baseline) printBaseline(P, N, runBaseline(g, omega, base), T, false);
  return 0;
}
