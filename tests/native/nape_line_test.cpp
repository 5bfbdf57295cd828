// The lower hairline (nape_line.hpp): per bin of the angle about the vertical axis, the lowest
// height of the scalp's edges behind kNapeFront and below kNapeTop, against heights put there by
// hand; read back between bins and NaN in front of the ears or where no edge passes.
#include "nape_line.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace nape_line_test {

using namespace hairsketch;

constexpr float kPi = 3.14159265358979f;

// A short edge (6 floats) across the angle a (0: straight back, +x to the left) at radius 0.8
// about the origin's vertical axis, at height y.
void edgeAt(std::vector<float>& edges, float a, float y) {
  for (const float d : {-0.01f, 0.01f})
    edges.insert(edges.end(), {0.8f * std::sin(a + d), y, -0.8f * std::cos(a + d)});
}

TEST(NapeLine, TheLowestEdgePerAngleBehindTheEarsReadBackBetweenBins) {
  const float centre[3] = {0, 0, 0};
  const float bin = 2 * kPi / kNapeBins;
  std::vector<float> edges;
  // straight back: two edges in the same bin, the lower counts
  edgeAt(edges, 0.5f * bin, -0.3f);
  edgeAt(edges, 0.5f * bin, -0.5f);
  edgeAt(edges, 1.5f * bin, -0.4f);
  // above kNapeTop, and in front of kNapeFront: not part of it
  edgeAt(edges, 2.5f * bin, kNapeTop + 0.05f);
  edgeAt(edges, kPi - 0.5f * bin, -0.2f);
  const std::vector<float> line = napeLine(edges, centre);
  ASSERT_EQ(line.size(), size_t(kNapeBins));
  const int first = kNapeBins / 2;  // the bin just left of straight back
  EXPECT_FLOAT_EQ(line[first], -0.5f);
  EXPECT_FLOAT_EQ(line[first + 1], -0.4f);
  EXPECT_TRUE(std::isnan(line[first + 2]));
  EXPECT_TRUE(std::isnan(line[kNapeBins - 1]));
  // at the bins' centres their heights, halfway between them the mean
  auto at = [&](float a) {
    return napeLineAt(line, centre, 0.8f * std::sin(a), -0.8f * std::cos(a));
  };
  EXPECT_NEAR(at(0.5f * bin), -0.5f, 1e-5f);
  EXPECT_NEAR(at(1.5f * bin), -0.4f, 1e-5f);
  EXPECT_NEAR(at(1.0f * bin), -0.45f, 1e-5f);
  // next to a bin with no edge: the nearer bin's height, or NaN
  EXPECT_NEAR(at(1.9f * bin), -0.4f, 1e-5f);
  EXPECT_TRUE(std::isnan(at(2.2f * bin)));
  // in front of kNapeFront: NaN whatever the bins hold
  EXPECT_TRUE(std::isnan(napeLineAt(line, centre, 0.f, kNapeFront + 0.01f)));
  EXPECT_TRUE(std::isnan(napeLineAt({}, centre, 0.f, -0.8f)));
  // its highest point, over the bins that have one
  EXPECT_FLOAT_EQ(napeLineTop(line), -0.4f);
  EXPECT_TRUE(std::isinf(napeLineTop(std::vector<float>(kNapeBins, std::nanf("")))));
}

}  // namespace nape_line_test
