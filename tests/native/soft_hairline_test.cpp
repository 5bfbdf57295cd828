// A soft hairline (soft_hairline.hpp): the scalp's edges of a mesh, distances to them against a
// hand computation, and the share of roots growing full, short or no hair at the edge and inside.
#include "soft_hairline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace soft_hairline_test {

using namespace hairsketch;

// A 4 x 1 strip of unit squares in the plane z = 0 (two triangles each); the first two squares
// are scalp.
struct Strip {
  std::vector<float> positions;
  std::vector<uint32_t> indices;
  std::vector<uint8_t> scalp;
  Strip() {
    for (int y = 0; y <= 1; ++y)
      for (int x = 0; x <= 4; ++x) positions.insert(positions.end(), {float(x), float(y), 0});
    for (uint32_t x = 0; x < 4; ++x) {
      const uint32_t a = x, b = x + 1, c = x + 6, d = x + 5;
      indices.insert(indices.end(), {a, b, c, a, c, d});
      scalp.insert(scalp.end(), {uint8_t(x < 2), uint8_t(x < 2)});
    }
  }
};

TEST(SoftHairline, TheScalpsEdgesAreTheEdgesItSharesWithTheRestOrWithNothing) {
  const Strip s;
  const std::vector<float> e = scalpEdges(s.positions, s.indices, s.scalp);
  // the scalp (x in [0, 2]) is bounded by: x = 0 (1 edge), y = 0 and y = 1 (2 edges each), and
  // x = 2 against the rest (1 edge): 6 edges; its diagonals and x = 1 are inside it
  ASSERT_EQ(e.size(), 6u * 6u);
  for (size_t k = 0; k < e.size() / 6; ++k) {
    const bool vertical = e[6 * k] == e[6 * k + 3];
    const bool horizontal = e[6 * k + 1] == e[6 * k + 4];
    EXPECT_TRUE(vertical || horizontal) << "edge " << k;
    if (vertical) EXPECT_TRUE(e[6 * k] == 0 || e[6 * k] == 2) << "edge " << k;
  }
}

TEST(SoftHairline, DistancesToTheEdgesAreThePointsOwnCappedAtTheBand) {
  const Strip s;
  const std::vector<float> e = scalpEdges(s.positions, s.indices, s.scalp);
  const std::vector<Eigen::Vector3f> p = {
      {1.0f, 0.5f, 0}, {0.2f, 0.5f, 0}, {1.5f, 0.9f, 0}, {1.0f, 0.5f, 0.3f}};
  const std::vector<float> d = distanceToEdges(p, e, 10.f);
  EXPECT_NEAR(d[0], 0.5f, 1e-6f);                    // halfway between y = 0 and y = 1
  EXPECT_NEAR(d[1], 0.2f, 1e-6f);                    // x = 0
  EXPECT_NEAR(d[2], 0.1f, 1e-6f);                    // y = 1
  EXPECT_NEAR(d[3], std::hypot(0.5f, 0.3f), 1e-6f);  // off the plane
  const std::vector<float> capped = distanceToEdges(p, e, 0.3f);
  EXPECT_FLOAT_EQ(capped[0], 0.3f);
  EXPECT_NEAR(capped[1], 0.2f, 1e-6f);
}

TEST(SoftHairline, AtTheEdgeRootsThinOutAndSomeGrowShortHairInsideEveryRootGrowsFull) {
  const size_t n = 20000;
  std::vector<uint32_t> ids(2 * n);
  for (size_t k = 0; k < ids.size(); ++k) ids[k] = uint32_t(k);
  // the first n roots at the edge, the rest past the band
  std::vector<float> edge(2 * n, 0.f);
  for (size_t k = n; k < 2 * n; ++k) edge[k] = kHairlineWidth * 1.5f;
  std::vector<uint32_t> pick(2 * n);
  for (size_t k = 0; k < pick.size(); ++k) pick[k] = uint32_t(k);
  std::vector<float> cap;
  softHairline(edge, ids, 7, pick, cap);
  ASSERT_EQ(cap.size(), pick.size());
  size_t full = 0, shortHair = 0, inside = 0;
  for (size_t k = 0; k < pick.size(); ++k) {
    if (pick[k] >= n) {
      inside++;
      EXPECT_TRUE(std::isinf(cap[k]));
      continue;
    }
    if (std::isinf(cap[k])) {
      full++;
    } else {
      shortHair++;
      EXPECT_GE(cap[k], kHairlineShortMin);
      EXPECT_LE(cap[k], kHairlineShortMax);
    }
  }
  EXPECT_EQ(inside, n);
  // at the edge: kHairlineFull full, half the rest short (binomial, n = 20000: 3 sigma < 1 %)
  EXPECT_NEAR(double(full) / n, kHairlineFull, 0.012);
  EXPECT_NEAR(double(shortHair) / n, 0.5 * (1 - kHairlineFull), 0.012);
  // the same seed picks the same roots
  std::vector<uint32_t> again(2 * n);
  for (size_t k = 0; k < again.size(); ++k) again[k] = uint32_t(k);
  std::vector<float> cap2;
  softHairline(edge, ids, 7, again, cap2);
  EXPECT_EQ(again, pick);
}

}  // namespace soft_hairline_test
