// The thread pool (parallel.hpp): every index once, chunks in order, nested loops serial,
// ordered sums; growth (strands and keepOutsideHead) and the multigrid solve ("fast": threaded
// sweeps, transfers, mat-vecs and CG vector operations) giving the same bytes with 1, 2 and 3
// threads.
#include "parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <vector>

#include "head_distance.hpp"
#include "mg_pcg_solver.hpp"
#include "random_vector.hpp"
#include "sphere_mesh.hpp"
#include "strand_growth.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace parallel_test {

using namespace hairsketch;

namespace {

// Restores the serial default after a test. Not adaptive meanwhile: every loop of more than one
// task goes to the workers, whatever the load of the machine.
struct Threads {
  explicit Threads(int n) {
    parallel::setThreadCount(n);
    parallel::setAdaptive(false);
  }
  ~Threads() {
    parallel::setThreadCount(1);
    parallel::setAdaptive(true);
  }
};

}  // namespace

TEST(Parallel, EveryIndexOnceInContiguousChunks) {
  Threads t(3);
  EXPECT_EQ(parallel::threadCount(), 3);
  const size_t n = 100003;
  std::vector<int> hits(n, 0);
  std::vector<std::pair<size_t, size_t>> ranges(7);
  parallel::forChunks(n, 7, [&](int c, size_t b, size_t e) {
    ranges[size_t(c)] = {b, e};
    for (size_t i = b; i < e; ++i) ++hits[i];
  });
  for (size_t i = 0; i < n; ++i) ASSERT_EQ(hits[i], 1) << i;
  EXPECT_EQ(ranges.front().first, 0u);
  EXPECT_EQ(ranges.back().second, n);
  for (size_t c = 1; c < ranges.size(); ++c) EXPECT_EQ(ranges[c].first, ranges[c - 1].second);
  // forRange: the same, from an offset
  std::atomic<size_t> sum{0};
  parallel::forRange(10, 5010, 100, [&](size_t b, size_t e) {
    size_t s = 0;
    for (size_t i = b; i < e; ++i) s += i;
    sum += s;
  });
  EXPECT_EQ(sum.load(), (10 + 5009) * 5000 / 2);
}

TEST(Parallel, NestedLoopsRunSeriallyAndManyLoopsInARowFinish) {
  Threads t(2);
  std::atomic<int> inner{0};
  parallel::forChunks(8, 8, [&](int, size_t, size_t) {
    parallel::forChunks(4, 4, [&](int, size_t, size_t) { ++inner; });
  });
  EXPECT_EQ(inner.load(), 32);
  std::atomic<int> count{0};
  for (int k = 0; k < 2000; ++k) parallel::forChunks(2, 2, [&](int, size_t, size_t) { ++count; });
  EXPECT_EQ(count.load(), 4000);
}

TEST(Parallel, EveryTaskOnceInManyShortLoops) {
  // Loops much shorter than a worker's wake-up: the caller claims what the workers have not, and
  // a late worker must never run a task of a newer loop with an older loop's function.
  Threads t(3);
  std::vector<std::atomic<int>> hits(7);
  const unsigned long long before = parallel::dispatchedLoops();
  for (int loop = 1; loop <= 20000; ++loop) {
    const int tasks = 2 + loop % 6;
    parallel::runTasks(tasks, [&](int k) { hits[size_t(k)].fetch_add(1); });
    for (int k = 0; k < tasks; ++k) ASSERT_EQ(hits[size_t(k)].exchange(0), 1) << loop;
    for (int k = tasks; k < 7; ++k) ASSERT_EQ(hits[size_t(k)].load(), 0) << loop;
  }
  EXPECT_EQ(parallel::dispatchedLoops() - before, 20000u);
}

TEST(Parallel, SumBlocksAddsFixedBlocksInOrder) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> v(100003);
  for (double& x : v) x = u(rng) * std::pow(10.0, double(int(rng() % 13)) - 6);
  const size_t block = 1000;
  // the reference: each block summed in index order, the block sums added in block order
  double ref0 = 0, ref1 = 0;
  for (size_t b = 0; b < v.size(); b += block) {
    double s0 = 0, s1 = 0;
    for (size_t i = b; i < std::min(v.size(), b + block); ++i) s0 += v[i], s1 += v[i] * v[i];
    ref0 += s0;
    ref1 += s1;
  }
  for (int threads : {1, 2, 3}) {
    Threads t(threads);
    const auto s = parallel::sumBlocks<2>(v.size(), block, 2, [&](size_t b, size_t e) {
      double s0 = 0, s1 = 0;
      for (size_t i = b; i < e; ++i) s0 += v[i], s1 += v[i] * v[i];
      return std::array<double, 2>{s0, s1};
    });
    EXPECT_EQ(std::memcmp(&s[0], &ref0, sizeof(double)), 0) << threads << " threads";
    EXPECT_EQ(std::memcmp(&s[1], &ref1, sizeof(double)), 0) << threads << " threads";
  }
}

namespace {

// Constraints along a random walk of unit steps with momentum (grid units): the 8 corners of the
// cell round each sample get its direction.
void addWalk(const Grid& g, std::mt19937& rng, int count, std::vector<Constraint>& out,
             std::set<int>& used) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> nrm(0.0, 0.3);
  Eigen::Vector3d p = hairsketch_test::drawVector([&](int axis) {
    return u(rng) * ((axis == 0 ? g.nx : axis == 1 ? g.ny : g.nz) - 1);
  });
  Eigen::Vector3d d = hairsketch_test::drawVector([&](int axis) {
                        return axis == 2 ? 1.0 : nrm(rng);
                      }).normalized();
  int added = 0;
  for (int guard = 0; added < count && guard < 20000; ++guard) {
    d = (d + hairsketch_test::drawVector([&](int) { return nrm(rng); })).normalized();
    p += 0.7 * d;
    for (int a = 0; a < 3; ++a) {
      const double hi = (a == 0 ? g.nx : a == 1 ? g.ny : g.nz) - 1.001;
      if (p[a] < 0 || p[a] > hi) d[a] = -d[a], p[a] = std::clamp(p[a], 0.0, hi);
    }
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

}  // namespace

TEST(Parallel, MultigridSolveGivesTheSameBytesWithAnyThreadCount) {
  // 40 x 36 x 44 (63K points, 4 levels): large enough that the sweeps, transfers, mat-vecs and
  // CG sums of the fine and first coarse levels run in parallel chunks. An edit sequence as the
  // app runs it: a solve, an edit warm-started, the history-free final solve from zero.
  Grid g;
  g.nx = 40;
  g.ny = 36;
  g.nz = 44;
  std::mt19937 rng(11);
  std::vector<Constraint> a;
  std::set<int> used;
  for (int c = 0; c < 8; ++c) addWalk(g, rng, 150, a, used);
  std::vector<Constraint> b(a.begin() + 300, a.end());  // a curve and a half removed
  addWalk(g, rng, 400, b, used);                        // a new one
  const ConstraintSet A = normalizeConstraints(a), B = normalizeConstraints(b);
  // 12 iterations per phase (the bits do not need convergence; the estimate's path does run).
  auto solve = [&](int threads, unsigned long long& loops) {
    Threads t(threads);
    const unsigned long long before = parallel::dispatchedLoops();
    std::vector<Field> out(3);
    std::vector<double> estimates;
    MgPcgSolver s;
    MgProgress pr;
    EXPECT_TRUE(s.setGrid(g, kDefaultOmega).ok());
    EXPECT_TRUE(s.setConstraints(A).ok());
    EXPECT_TRUE(s.iterate(12, 0, &pr).ok());
    s.field(out[0]);
    estimates.push_back(pr.errorEstimate);
    EXPECT_TRUE(s.setConstraints(B).ok());
    EXPECT_TRUE(s.iterate(12, 0, &pr).ok());
    s.field(out[1]);
    estimates.push_back(pr.errorEstimate);
    EXPECT_TRUE(s.forgetWarmStart());
    EXPECT_TRUE(s.iterate(12, 0, &pr).ok());
    s.field(out[2]);
    estimates.push_back(pr.errorEstimate);
    loops = parallel::dispatchedLoops() - before;
    return std::make_pair(out, estimates);
  };
  unsigned long long loops1 = 0;
  const auto [one, est1] = solve(1, loops1);
  EXPECT_EQ(loops1, 0u);
  EXPECT_LT(est1[2], 1.0);  // on its way
  for (int threads : {2, 3}) {
    unsigned long long loops = 0;
    const auto [many, est] = solve(threads, loops);
    // every CG iteration hands dozens of loops to the workers
    EXPECT_GT(loops, 20u * 36u) << threads << " threads";
    EXPECT_EQ(est, est1) << threads << " threads";
    for (size_t k = 0; k < one.size(); ++k) {
      ASSERT_EQ(many[k].size(), one[k].size());
      EXPECT_EQ(std::memcmp(many[k].data(), one[k].data(), size_t(one[k].size()) * sizeof(double)),
                0)
          << threads << " threads, phase " << k;
    }
  }
}

TEST(Parallel, AdaptiveLoopsRunSeriallyWhenThreadsDoNotPay) {
  // Tasks of a few nanoseconds: the workers' wake-up costs far more than the work, so after a
  // window of dispatched loops the pool runs the next ones serially, then tries again.
  Threads t(2);
  parallel::setAdaptive(true);
  std::atomic<int> sum{0};
  const unsigned long long before = parallel::dispatchedLoops();
  for (int loop = 0; loop < 3000; ++loop)
    parallel::runTasks(2, [&](int k) { sum.fetch_add(k + 1, std::memory_order_relaxed); });
  EXPECT_EQ(sum.load(), 3 * 3000);  // every task ran once either way
  const unsigned long long dispatched = parallel::dispatchedLoops() - before;
  EXPECT_GE(dispatched, 64u);    // one window at least
  EXPECT_LT(dispatched, 1000u);  // then mostly serial
}

TEST(Parallel, ClampsTheThreadCount) {
  EXPECT_EQ(parallel::setThreadCount(0), 1);
  EXPECT_EQ(parallel::setThreadCount(1000), parallel::kMaxThreads);
  EXPECT_EQ(parallel::setThreadCount(1), 1);
}

TEST(Parallel, GrowthGivesTheSameBytesWithAnyThreadCount) {
  // A swirling field over a box round a unit sphere (the head), strands from its upper half,
  // sliding over it: every step kind (slide, stop at the face, leave the box) occurs.
  Grid g;
  g.nx = g.ny = g.nz = 41;
  g.step = 0.1;
  g.origin = Eigen::Vector3d(-2, -2, -2);
  std::vector<float> field(size_t(g.size()) * 3);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const Eigen::Vector3d p = g.position(i, j, k);
        const size_t q = size_t(g.index(i, j, k));
        field[3 * q] = float(0.3 * std::sin(3 * p.y()) - 0.2 * p.z());
        field[3 * q + 1] = -1;
        field[3 * q + 2] = float(0.2 * p.x() + 0.1 * std::cos(2 * p.x()));
      }
  hairsketch_test::Mesh m = hairsketch_test::uvSphere(0, 0, 0, 1, 48, 96);
  hairsketch_test::markScalpAbove(m, 0.2);
  HeadDistance hd;
  ASSERT_TRUE(hd.build(HeadMeshView{m.positions.data(), m.positions.size() / 3, m.indices.data(),
                                    m.indices.size() / 3, m.scalp.data()},
                       0.03, 3)
                  .ok());
  std::vector<Eigen::Vector3f> roots;
  for (int k = 0; k < 5000; ++k) {
    const double th = 1.2 * std::sqrt((k + 0.5) / 5000.0), ph = 2.399963 * k;
    roots.emplace_back(float(1.01 * std::sin(th) * std::cos(ph)), float(1.01 * std::cos(th)),
                       float(1.01 * std::sin(th) * std::sin(ph)));
  }
  GrowthParams prm;
  prm.maxSegments = 120;
  prm.margin = 0.02;
  auto grow = [&](int threads, size_t maxPoints = size_t(1) << 24) {
    Threads t(threads);
    Strands s;
    Status st = growStrands(g, field, roots, prm, s, maxPoints, &hd);
    const size_t moved = st.ok() ? keepOutsideHead(hd, 0.05f, s) : 0;
    return std::make_tuple(st.ok(), std::move(s), moved);
  };
  const auto [ok1, one, moved1] = grow(1);
  ASSERT_TRUE(ok1);
  ASSERT_EQ(one.strandStart.size(), roots.size() + 1);
  ASSERT_GT(one.points.size(), 3 * roots.size() * 10);  // strands grew
  EXPECT_GT(moved1, 0u);                                // keepOutsideHead had work
  for (int threads : {2, 3}) {
    const auto [ok, s, moved] = grow(threads);
    ASSERT_TRUE(ok);
    EXPECT_EQ(s.strandStart, one.strandStart) << threads << " threads";
    ASSERT_EQ(s.points.size(), one.points.size()) << threads << " threads";
    EXPECT_EQ(std::memcmp(s.points.data(), one.points.data(), one.points.size() * sizeof(float)), 0)
        << threads << " threads";
    EXPECT_EQ(moved, moved1);
  }
  // Past the point cap: the same refusal with threads.
  const size_t cap = one.points.size() / 3 - 1;
  EXPECT_FALSE(std::get<0>(grow(1, cap)));
  EXPECT_FALSE(std::get<0>(grow(3, cap)));
  EXPECT_TRUE(std::get<0>(grow(3, cap + 1)));
}

}  // namespace parallel_test
