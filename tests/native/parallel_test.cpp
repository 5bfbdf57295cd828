// The thread pool (parallel.hpp): every index once, chunks in order, nested loops serial; and
// growth (strands and keepOutsideHead) giving the same bytes with 1, 2 and 3 threads.
#include "parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <vector>

#include "head_distance.hpp"
#include "sphere_mesh.hpp"
#include "strand_growth.hpp"

using namespace hairsketch;

namespace {

// Restores the serial default after a test.
struct Threads {
  explicit Threads(int n) { parallel::setThreadCount(n); }
  ~Threads() { parallel::setThreadCount(1); }
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
