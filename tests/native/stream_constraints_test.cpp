// Stream-curve constraints (method S4.1) for hand-computed curves.
#include "stream_constraints.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace stream_constraints_test {

using namespace hairsketch;

namespace {

Grid unitGrid(int nx, int ny, int nz) {
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.nz = nz;
  g.origin = {0, 0, 0};
  g.step = 1;
  return g;
}

std::map<int, Eigen::Vector3d> asMap(const ConstraintSet& s) {
  std::map<int, Eigen::Vector3d> m;
  for (const Constraint& c : s) m[c.index] = c.target;
  return m;
}

ConstraintSet single(const Grid& g, const std::vector<double>& pts, bool extend) {
  std::vector<Constraint> raw;
  appendStreamConstraints(g, pts.data(), pts.size() / 3, extend, raw);
  return normalizeConstraints(raw);
}

}  // namespace

TEST(StreamConstraints, LShapedCurveClaimsCellCornersAndAveragesOverlap) {
  const Grid g = unitGrid(4, 4, 4);
  // Segment 1: (0.5,0.5,0.5)->(1.5,0.5,0.5), midpoint (1,0.5,0.5) -> cell (1,0,0), target +x.
  // Segment 2: (1.5,0.5,0.5)->(1.5,1.5,0.5), midpoint (1.5,1,0.5) -> cell (1,1,0), target +y.
  // Shared corners i in {1,2}, j = 1, k in {0,1}: (0.5, 0.5, 0).
  const auto m = asMap(single(g, {0.5, 0.5, 0.5, 1.5, 0.5, 0.5, 1.5, 1.5, 0.5}, false));
  std::map<int, Eigen::Vector3d> expected;
  for (int k = 0; k < 2; ++k)
    for (int i = 1; i <= 2; ++i) {
      expected[g.index(i, 0, k)] = {1, 0, 0};
      expected[g.index(i, 1, k)] = {0.5, 0.5, 0};
      expected[g.index(i, 2, k)] = {0, 1, 0};
    }
  ASSERT_EQ(m.size(), expected.size());
  for (const auto& [p, t] : expected) {
    ASSERT_TRUE(m.count(p)) << "missing grid point " << p;
    EXPECT_LT((m.at(p) - t).norm(), 1e-15) << "at grid point " << p;
  }
}

TEST(StreamConstraints, ExtensionFadesTargetsToZero) {
  const Grid g = unitGrid(8, 4, 4);
  // One segment along +x ending at x = 1.5; extension midpoints at x = 2, 3, 4, 5 with
  // magnitudes 3/4, 1/2, 1/4, 0. Corner column i is shared by cells i-1 and i.
  const auto m = asMap(single(g, {0.5, 0.5, 0.5, 1.5, 0.5, 0.5}, true));
  const double expectedX[8] = {
      0, 1, (1 + 0.75) / 2, (0.75 + 0.5) / 2, (0.5 + 0.25) / 2, (0.25 + 0) / 2, 0, 0};
  EXPECT_EQ(m.size(), size_t(6 * 4));  // columns i = 1..6, 4 corners each
  for (int i = 1; i <= 6; ++i)
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j) {
        const int p = g.index(i, j, k);
        ASSERT_TRUE(m.count(p)) << "i=" << i;
        EXPECT_NEAR(m.at(p).x(), expectedX[i], 1e-15) << "i=" << i;
        EXPECT_EQ(m.at(p).y(), 0.0);
      }
  // The last extension segment's own cell has target exactly 0 at its far corners.
  EXPECT_EQ(m.at(g.index(6, 0, 0)).norm(), 0.0);
}

TEST(StreamConstraints, OutsideAndZeroLengthSegmentsAreSkippedUpperFaceIsLastCell) {
  const Grid g = unitGrid(4, 4, 4);
  // Midpoint (-0.5, 1.5, 1.5) is outside; the second segment has zero length.
  EXPECT_TRUE(single(g, {-1, 1.5, 1.5, 0, 1.5, 1.5, 0, 1.5, 1.5}, false).empty());
  // Midpoint (3, 1.5, 1.5) lies on the upper x face: it belongs to cell (2, 1, 1).
  const auto m = asMap(single(g, {2.5, 1.5, 1.5, 3.5, 1.5, 1.5}, false));
  ASSERT_EQ(m.size(), 8u);
  for (int k = 1; k <= 2; ++k)
    for (int j = 1; j <= 2; ++j)
      for (int i = 2; i <= 3; ++i) EXPECT_EQ(m.count(g.index(i, j, k)), 1u);
}

}  // namespace stream_constraints_test
