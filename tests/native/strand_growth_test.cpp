// Growth stop rules of method S5.2 in hand-built fields.
#include "strand_growth.hpp"

#include <gtest/gtest.h>

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace strand_growth_test {

using namespace hairsketch;

namespace {

Grid box() {
  Grid g;
  g.nx = 11;
  g.ny = 6;
  g.nz = 6;
  g.origin = {-1, 0, 0};
  g.step = 0.5;  // x in [-1, 4]
  return g;
}

// v(p) = f(position of p) at every grid point.
template <class F>
std::vector<float> makeField(const Grid& g, F f) {
  std::vector<float> v(size_t(g.size()) * 3);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const Eigen::Vector3d x = f(g.position(i, j, k));
        for (int a = 0; a < 3; ++a) v[3 * g.index(i, j, k) + a] = float(x[a]);
      }
  return v;
}

std::vector<float> strandPoints(const Strands& s, int strand, int axis) {
  std::vector<float> out;
  for (uint32_t p = s.strandStart[strand]; p < s.strandStart[strand + 1]; ++p)
    out.push_back(s.points[3 * p + axis]);
  return out;
}

}  // namespace

TEST(StrandGrowth, TrilinearInterpolationIsExactForLinearFields) {
  const Grid g = box();
  auto f = [](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(1 + 0.5 * p.x() - p.y(), 2 * p.z(), p.x() + p.y() + p.z());
  };
  const std::vector<float> v = makeField(g, f);
  for (const Eigen::Vector3f x : {Eigen::Vector3f(0.3f, 1.1f, 2.2f), Eigen::Vector3f(4, 2.5f, 0),
                                  Eigen::Vector3f(-1, 0, 2.49f)}) {
    const Eigen::Vector3f got = interpolateField(g, v.data(), x);
    EXPECT_LT((got - f(x.cast<double>()).cast<float>()).norm(), 1e-5f);
  }
}

TEST(StrandGrowth, StopsWhenLeavingTheBox) {
  const Grid g = box();
  const auto v = makeField(g, [](const Eigen::Vector3d&) { return Eigen::Vector3d(1, 0, 0); });
  Strands s;
  GrowthParams prm;
  prm.maxSegments = 1000;
  ASSERT_TRUE(growStrands(g, v, {Eigen::Vector3f(0, 1, 1)}, prm, s).ok());
  // l = 0.25: x = 0, 0.25, ..., 4.0 (the upper face, still inside); 4.25 would leave.
  const auto xs = strandPoints(s, 0, 0);
  ASSERT_EQ(xs.size(), 17u);
  EXPECT_FLOAT_EQ(xs.back(), 4.0f);
  for (size_t i = 0; i < xs.size(); ++i) EXPECT_NEAR(xs[i], 0.25 * i, 1e-5);
  // A root outside the volume gives just the root.
  ASSERT_TRUE(growStrands(g, v, {Eigen::Vector3f(5, 1, 1)}, prm, s).ok());
  EXPECT_EQ(s.strandStart, (std::vector<uint32_t>{0, 1}));
}

TEST(StrandGrowth, StopsInAWeakField) {
  const Grid g = box();
  // |v| = 1 for x <= 1, then a linear fall to 0 at x = 2 (grid points x = 1.0, 1.5, 2.0): the
  // magnitude drops below 0.05 at x > 1.95. Steps l * |v| shrink as the field weakens.
  const auto v = makeField(g, [](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(std::clamp(2 - p.x(), 0.0, 1.0), 0, 0);
  });
  Strands s;
  GrowthParams prm;
  prm.maxSegments = 100000;
  ASSERT_TRUE(growStrands(g, v, {Eigen::Vector3f(0, 1, 1)}, prm, s).ok());
  const auto xs = strandPoints(s, 0, 0);
  EXPECT_LT(xs.size(), 100000u);
  EXPECT_GT(xs.back(), 1.95f - 1e-3f);              // it got to where the field is weak ...
  EXPECT_LT(xs.back(), 2.0f);                       // ... and stopped there
  EXPECT_GE(2 - xs[xs.size() - 2], 0.05f - 1e-4f);  // the previous point was still strong
  // A field that is weak everywhere grows nothing.
  const auto weak =
      makeField(g, [](const Eigen::Vector3d&) { return Eigen::Vector3d(0, 0.04, 0); });
  ASSERT_TRUE(growStrands(g, weak, {Eigen::Vector3f(0, 1, 1)}, prm, s).ok());
  EXPECT_EQ(s.points.size(), 3u);
  // ... unless the threshold is lowered below its magnitude.
  prm.minMagnitude = 0.03;
  prm.maxSegments = 3;
  ASSERT_TRUE(growStrands(g, weak, {Eigen::Vector3f(0, 1, 1)}, prm, s).ok());
  EXPECT_EQ(s.points.size(), 3u * 4);
}

TEST(StrandGrowth, StopsAtMaxLengthAndMaxSegments) {
  const Grid g = box();
  const auto v = makeField(g, [](const Eigen::Vector3d&) { return Eigen::Vector3d(0, 0, 2); });
  GrowthParams prm;  // l = 0.25, |v| = 2: segments of length 0.5
  prm.maxSegments = 1000;
  prm.maxLength = 1.7;  // 3 segments = 1.5; a 4th would make 2.0
  Strands s;
  ASSERT_TRUE(growStrands(g, v, {Eigen::Vector3f(0, 1, 0)}, prm, s).ok());
  EXPECT_EQ(strandPoints(s, 0, 2), (std::vector<float>{0, 0.5f, 1, 1.5f}));
  prm.maxLength = 100;
  prm.maxSegments = 2;
  ASSERT_TRUE(growStrands(g, v, {Eigen::Vector3f(0, 1, 0), Eigen::Vector3f(1, 1, 0)}, prm, s).ok());
  EXPECT_EQ(s.strandStart, (std::vector<uint32_t>{0, 3, 6}));
  EXPECT_EQ(strandPoints(s, 1, 2), (std::vector<float>{0, 0.5f, 1}));
  EXPECT_EQ(strandPoints(s, 1, 0), (std::vector<float>{1, 1, 1}));
}

TEST(StrandGrowth, RejectsBadParamsAndMissingField) {
  const Grid g = box();
  const auto v = makeField(g, [](const Eigen::Vector3d&) { return Eigen::Vector3d(0, 0, 1); });
  Strands s;
  GrowthParams prm;
  prm.stepFraction = 0;
  EXPECT_FALSE(growStrands(g, v, {Eigen::Vector3f(0, 1, 0)}, prm, s).ok());
  prm = GrowthParams{};
  prm.maxSegments = -1;
  EXPECT_FALSE(growStrands(g, v, {Eigen::Vector3f(0, 1, 0)}, prm, s).ok());
  EXPECT_FALSE(growStrands(g, {}, {Eigen::Vector3f(0, 1, 0)}, GrowthParams{}, s).ok());
  // Output cap.
  prm = GrowthParams{};
  EXPECT_EQ(growStrands(g, v, {Eigen::Vector3f(0, 1, 0)}, prm, s, 3).code,
            StatusCode::OverMemoryCap);
}

}  // namespace strand_growth_test
