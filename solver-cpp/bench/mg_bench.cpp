// Multigrid-PCG ("fast") benchmark, SOLVER-NOTES setting: full box grid, ~3000 constraints
// along random curves, then one new stroke of 300 or 1000 points (clustered along a curve),
// warm-started from the previous field.
// Per grid: setup time, per-iteration time, iterations/time to true field error 1e-3 and 1e-6
// (error against a reference from a second solver instance iterated to an error estimate of
// 1e-14; the direct-solve agreement itself is tested in tests/native/multigrid_test.cpp on
// smaller grids), where the error estimate stops, memory. Env: MG_SYM, MG_CSYM, MG_SWEEPS,
// MG_COARSEST, MG_FMG (0: cold solve from zero), MG_FMG_CYCLES, MG_FMG_FINE override
// MultigridOptions; MG_THREADS=N runs the solver on N threads (parallel.hpp).
// Usage: mg_bench [N ...]   (default 29 37 47 63)
//        mg_bench --app BEFORE.txt AFTER.txt   an app's constraint sets ("nx ny nz" then
//          "index tx ty tz" lines): the edit BEFORE -> AFTER as the worker runs it (warm start to
//          1e-6, then the history-free final solve from zero to 1e-6), against a reference.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "mg_pcg_solver.hpp"
#include "parallel.hpp"

using namespace hairsketch;
using Clock = std::chrono::steady_clock;

static double ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// A random smooth curve with unit steps (grid units); the 8 corners of the cell around each
// sample get the curve tangent, until `count` new points are constrained.
static void addStroke(const Grid& g, std::mt19937& rng, int count, std::vector<Constraint>& out,
                      std::set<int>& used) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> nrm(0.0, 0.25);
  Eigen::Vector3d p(1 + u(rng) * (g.nx - 3), 1 + u(rng) * (g.ny - 3), 1 + u(rng) * (g.nz - 3));
  Eigen::Vector3d d(nrm(rng), nrm(rng), nrm(rng));
  d = (d.norm() > 0 ? d.normalized() : Eigen::Vector3d::UnitX());
  int added = 0, guard = 0;
  while (added < count && guard++ < 100000) {
    d += Eigen::Vector3d(nrm(rng), nrm(rng), nrm(rng)) * 0.5;
    d.normalize();
    Eigen::Vector3d q = p + 0.7 * d;
    const double hi[3] = {g.nx - 1.001, g.ny - 1.001, g.nz - 1.001};
    for (int a = 0; a < 3; ++a)
      if (q[a] < 0 || q[a] > hi[a]) {
        d[a] = -d[a];
        q[a] = std::clamp(q[a], 0.0, hi[a]);
      }
    p = q;
    const int i = int(p[0]), j = int(p[1]), k = int(p[2]);
    for (int c = 0; c < 8 && added < count; ++c) {
      const int ii = std::min(i + (c & 1), g.nx - 1), jj = std::min(j + (c >> 1 & 1), g.ny - 1),
                kk = std::min(k + (c >> 2 & 1), g.nz - 1);
      const int idx = g.index(ii, jj, kk);
      if (used.insert(idx).second) {
        out.push_back({idx, d});
        ++added;
      }
    }
  }
}

static double relErr(const Field& a, const Field& ref) { return (a - ref).norm() / ref.norm(); }

static MultigridOptions optionsFromEnv() {
  MultigridOptions mo;
  if (const char* e = std::getenv("MG_SYM")) mo.symmetricSweeps = std::atoi(e) != 0;
  if (const char* e = std::getenv("MG_CSYM")) mo.coarseSymmetricSweeps = std::atoi(e) != 0;
  if (const char* e = std::getenv("MG_SWEEPS")) mo.sweeps = std::atoi(e);
  if (const char* e = std::getenv("MG_COARSEST")) mo.coarsestMaxPoints = std::atoi(e);
  if (const char* e = std::getenv("MG_CSWEEPS")) mo.coarseSweeps = std::atoi(e);
  if (const char* e = std::getenv("MG_CYCLES")) mo.coarseCycles = std::atoi(e);
  if (const char* e = std::getenv("MG_COLOURS")) mo.colours = std::atoi(e);
  if (const char* e = std::getenv("MG_FMG")) mo.fmgStart = std::atoi(e) != 0;
  if (const char* e = std::getenv("MG_FMG_CYCLES")) mo.fmgCycles = std::atoi(e);
  if (const char* e = std::getenv("MG_FMG_FINE")) mo.fmgFineCycles = std::atoi(e);
  return mo;
}

static bool readConstraints(const char* path, Grid& g, ConstraintSet& out) {
  std::ifstream in(path);
  if (!(in >> g.nx >> g.ny >> g.nz)) return false;
  std::vector<Constraint> c;
  int idx;
  double x, y, z;
  while (in >> idx >> x >> y >> z) c.push_back({idx, Eigen::Vector3d(x, y, z)});
  out = normalizeConstraints(c);
  return true;
}

static int appMode(const char* before, const char* after) {
  Grid g, g1;
  ConstraintSet c0, c1;
  if (!readConstraints(before, g, c0) || !readConstraints(after, g1, c1) || g.nx != g1.nx ||
      g.ny != g1.ny || g.nz != g1.nz) {
    std::fprintf(stderr, "cannot read %s / %s\n", before, after);
    return 2;
  }
  const MultigridOptions mo = optionsFromEnv();
  MgPcgSolver ref(mo);
  ref.setGrid(g, kDefaultOmega);
  ref.setConstraints(c1);
  ref.iterate(1000, 1e-13);
  Field T1, T;
  ref.field(T1);

  MgPcgSolver s(mo);
  auto t0 = Clock::now();
  if (!s.setGrid(g, kDefaultOmega).ok()) return 1;
  const double setupMs = ms(t0, Clock::now());
  s.setConstraints(c0);
  s.iterate(1000, 1e-6);
  t0 = Clock::now();
  s.setConstraints(c1);
  const double editMs = ms(t0, Clock::now());
  t0 = Clock::now();
  MgProgress pw;
  s.iterate(1000, 1e-6, &pw);
  const double warmMs = ms(t0, Clock::now());
  s.field(T);
  const double warmErr = relErr(T, T1);
  t0 = Clock::now();
  s.forgetWarmStart();
  const double forgetMs = ms(t0, Clock::now());
  t0 = Clock::now();
  MgProgress pc;
  s.iterate(1000, 1e-6, &pc);
  const double coldMs = ms(t0, Clock::now());
  s.field(T);
  std::printf(
      "| %dx%dx%d | %lld | %zu -> %zu | %d | %.0f | %.1f | %.1f | %d | %.0f | %.1e | %.0f | %d | "
      "%.0f | %.1e |\n",
      g.nx, g.ny, g.nz, (long long)g.size(), c0.size(), c1.size(), s.hierarchy().levels(), setupMs,
      s.memoryBytes() / 1048576.0, editMs, pw.iterations, warmMs, warmErr, forgetMs, pc.iterations,
      coldMs, relErr(T, T1));
  return 0;
}

int main(int argc, char** argv) {
  if (const char* e = std::getenv("MG_THREADS")) parallel::setThreadCount(std::atoi(e));
  if (argc == 4 && std::string(argv[1]) == "--app") {
    std::printf(
        "| grid | n | constraints | levels | setup ms | MB | edit ms | warm it | warm ms | warm "
        "err "
        "| forget ms | cold it | cold ms | cold err "
        "|\n|---|---|---|---|---|---|---|---|---|---|---|"
        "---|---|---|\n");
    const int r = appMode(argv[2], argv[3]);
    if (parallel::threadCount() > 1)
      std::fprintf(stderr, "loops handed to the threads: %llu\n", parallel::dispatchedLoops());
    return r;
  }
  std::vector<int> sizes;
  for (int a = 1; a < argc; ++a) sizes.push_back(std::atoi(argv[a]));
  if (sizes.empty()) sizes = {29, 37, 47, 63};
  std::printf(
      "| grid | n | levels | setup ms | MB | stroke | edit ms | ms/iter | it->1e-3 | ms->1e-3 | "
      "it->1e-6 | ms->1e-6 | est stop 1e-3 (it, true err) | est stop 1e-6 (it, true err) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int N : sizes) {
    Grid g;
    g.nx = g.ny = g.nz = N;
    for (int stroke : {300, 1000}) {
      std::mt19937 rng(1234 + N);
      std::vector<Constraint> base;
      std::set<int> used;
      while (int(base.size()) < 3000) addStroke(g, rng, 150, base, used);
      std::vector<Constraint> edited = base;
      addStroke(g, rng, stroke, edited, used);
      const ConstraintSet c0 = normalizeConstraints(base), c1 = normalizeConstraints(edited);

      const MultigridOptions mo = optionsFromEnv();
      MgPcgSolver s(mo);
      auto t0 = Clock::now();
      if (!s.setGrid(g, kDefaultOmega).ok()) return 1;
      const double setupMs = ms(t0, Clock::now());
      s.setConstraints(c0);
      s.iterate(400, 1e-13);  // previous field, converged
      Field prev;
      s.field(prev);

      // Reference for the edited constraints: iterate far, then keep the field.
      MgPcgSolver ref(mo);
      ref.setGrid(g, kDefaultOmega);
      ref.setConstraints(c1);
      ref.iterate(400, 1e-14);
      Field T1;
      ref.field(T1);

      // Timed: the edit, then one iteration at a time with the error measured off the clock.
      t0 = Clock::now();
      s.setConstraints(c1);
      const double editMs = ms(t0, Clock::now());
      double iterMs = 0;
      int it3 = -1, it6 = -1, est3 = -1, est6 = -1;
      double ms3 = 0, ms6 = 0, err3 = 0, err6 = 0;
      Field T;
      for (int it = 1; it <= 200 && (it6 < 0 || est6 < 0); ++it) {
        auto a = Clock::now();
        MgProgress pr;
        s.iterate(1, 0, &pr);
        iterMs += ms(a, Clock::now());
        s.field(T);
        const double e = relErr(T, T1);
        if (it3 < 0 && e <= 1e-3) it3 = it, ms3 = editMs + iterMs;
        if (it6 < 0 && e <= 1e-6) it6 = it, ms6 = editMs + iterMs;
        if (est3 < 0 && pr.errorEstimate <= 1e-3 && it >= 2) est3 = it, err3 = e;
        if (est6 < 0 && pr.errorEstimate <= 1e-6 && it >= 2) est6 = it, err6 = e;
      }
      const int iters = s.progress().iterations;
      std::printf(
          "| %d³ | %lld | %d | %.0f | %.1f | %d | %.1f | %.2f | %d | %.0f | %d | %.0f | %d, "
          "%.1e | %d, %.1e |\n",
          N, (long long)g.size(), s.hierarchy().levels(), setupMs, s.memoryBytes() / 1048576.0,
          stroke, editMs, iterMs / iters, it3, ms3, it6, ms6, est3, err3, est6, err6);
      std::fflush(stdout);
      (void)prev;
    }
  }
  return 0;
}
