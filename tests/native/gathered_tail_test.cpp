// Gathered tails (gathered_tail.hpp): hair reaching a ponytail as a flat sheet leaves it as a
// round bunch of the circle's radius. Checked on hand-made strands (no field): the cross-section
// half-way down is measured by its principal widths (a uniform disc of radius R has 2 sigma = R
// along every axis), the kept part of each strand is bit-identical, lengths are kept, strands
// passing far away are untouched, hair hanging beside the tail joins it, the point cap holds and
// the seed decides the layout.
#include "gathered_tail.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "hand_strands.hpp"
#include "ponytail_constraints.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace gathered_tail_test {

using namespace hairsketch;

namespace {

using hand_strands::kStep;
constexpr double kR = 0.15;

// A spine hanging straight down from the origin to y = -3, circles of radius kR at y = 0 and -1.
GatheredTail tail() {
  std::vector<double> spine;
  for (int i = 0; i <= 30; ++i) spine.insert(spine.end(), {0.0, -0.1 * i, 0.0});
  PonytailParams pp;
  pp.gather = 1;
  pp.circles.push_back({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, -1, 0), kR});
  pp.circles.push_back({Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(0, -1, 0), kR});
  return gatheredTail(spine.data(), spine.size() / 3, pp);
}

using hand_strands::addStrand;
using Sheet = hand_strands::Hair;
Sheet sheet() { return hand_strands::sheet(-2.5f); }

float strandLength(const Strands& s, size_t st) {
  float L = 0;
  for (uint32_t p = s.strandStart[st] + 1; p < s.strandStart[st + 1]; ++p)
    L += (Eigen::Map<const Eigen::Vector3f>(&s.points[3 * p]) -
          Eigen::Map<const Eigen::Vector3f>(&s.points[3 * p - 3]))
             .norm();
  return L;
}

// Where each strand crosses the plane y = y0 (x, z), for strands that do.
std::vector<Eigen::Vector2d> crossings(const Strands& s, float y0) {
  std::vector<Eigen::Vector2d> out;
  for (size_t st = 0; st + 1 < s.strandStart.size(); ++st)
    for (uint32_t p = s.strandStart[st]; p + 1 < s.strandStart[st + 1]; ++p) {
      const float* a = &s.points[3 * p];
      const float* b = a + 3;
      if ((a[1] - y0) * (b[1] - y0) > 0 || a[1] == b[1]) continue;
      const float t = (a[1] - y0) / (a[1] - b[1]);
      out.emplace_back(a[0] + t * (b[0] - a[0]), a[2] + t * (b[2] - a[2]));
      break;
    }
  return out;
}

// 2 sigma along the two principal axes.
Eigen::Vector2d principalWidths(const std::vector<Eigen::Vector2d>& xs) {
  Eigen::Vector2d m = Eigen::Vector2d::Zero();
  for (const auto& x : xs) m += x;
  m /= double(xs.size());
  Eigen::Matrix2d C = Eigen::Matrix2d::Zero();
  for (const auto& x : xs) C += (x - m) * (x - m).transpose();
  C /= double(xs.size());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(C);
  return 2 * es.eigenvalues().cwiseMax(0).cwiseSqrt().reverse();  // larger first
}

}  // namespace

TEST(GatheredTail, ASheetLeavesAsARoundBunchOfTheRadius) {
  Sheet s = sheet();
  const Eigen::Vector2d before = principalWidths(crossings(s.strands, -1.f));
  ASSERT_LT(before.y() / before.x(), 0.1) << "the input is a flat sheet";
  const TailStats st = gatherTails({tail()}, s.roots, s.key, 7, kStep, 255, s.strands);
  EXPECT_EQ(st.captured, s.roots.size());
  // each laid strand names the tail that laid it
  ASSERT_EQ(st.tail.size(), st.strands.size());
  for (uint32_t t : st.tail) EXPECT_EQ(t, 0u);
  const std::vector<Eigen::Vector2d> xs = crossings(s.strands, -1.f);
  ASSERT_EQ(xs.size(), s.roots.size());
  const Eigen::Vector2d w = principalWidths(xs);
  EXPECT_GE(w.y() / w.x(), 0.8) << w.transpose();
  EXPECT_NEAR(w.x(), kR, 0.15 * kR);
  EXPECT_NEAR(w.y(), kR, 0.15 * kR);
  for (const auto& x : xs) EXPECT_LE(x.norm(), kR * 1.001);
}

TEST(GatheredTail, KeepsThePathToTheCrossingAndTheLength) {
  Sheet s = sheet();
  const Strands before = s.strands;
  gatherTails({tail()}, s.roots, s.key, 7, kStep, 255, s.strands);
  ASSERT_EQ(s.strands.strandStart.size(), before.strandStart.size());
  for (size_t st = 0; st + 1 < before.strandStart.size(); ++st) {
    // every point above C1's plane (y > 0) is kept bit for bit
    const uint32_t a0 = before.strandStart[st], a1 = s.strands.strandStart[st];
    for (uint32_t p = 0; before.points[3 * (a0 + p) + 1] > 0; ++p)
      for (int e = 0; e < 3; ++e)
        ASSERT_EQ(s.strands.points[3 * (a1 + p) + e], before.points[3 * (a0 + p) + e]);
    EXPECT_NEAR(strandLength(s.strands, st), strandLength(before, st), 0.05f * kStep * 40);
    EXPECT_LE(s.strands.strandStart[st + 1] - a1, 255u);
  }
}

TEST(GatheredTail, FarStrandsAreUntouchedAndHairBesideTheTailJoinsIt) {
  Strands strands;
  std::vector<Eigen::Vector3f> roots;
  // far: crosses C1's plane 1.0 away (> 2.5 r); beside: hangs 0.3 from the spine, below C1
  roots.push_back({1.f, 1.f, 0.f});
  addStrand({roots.back(), {1.f, -2.f, 0.f}}, strands);
  roots.push_back({0.3f, -0.5f, 0.f});
  addStrand({roots.back(), {0.3f, -2.f, 0.f}}, strands);
  const Strands before = strands;
  const TailStats st = gatherTails({tail()}, roots, {0, 1}, 7, kStep, 255, strands);
  EXPECT_EQ(st.captured, 1u);
  for (uint32_t p = 0; p < before.strandStart[1]; ++p)
    for (int e = 0; e < 3; ++e) EXPECT_EQ(strands.points[3 * p + e], before.points[3 * p + e]);
  // the second strand ends inside the bunch
  const float* tip = &strands.points[3 * (strands.strandStart[2] - 1)];
  EXPECT_LE(std::hypot(tip[0], tip[2]), kR * 1.001);
}

TEST(GatheredTail, ThePointCapHoldsAndTheSeedDecides) {
  Sheet a = sheet(), b = sheet(), c = sheet();
  gatherTails({tail()}, a.roots, a.key, 7, kStep, 40, a.strands);
  gatherTails({tail()}, b.roots, b.key, 7, kStep, 40, b.strands);
  gatherTails({tail()}, c.roots, c.key, 8, kStep, 40, c.strands);
  for (size_t st = 0; st + 1 < a.strands.strandStart.size(); ++st)
    EXPECT_LE(a.strands.strandStart[st + 1] - a.strands.strandStart[st], 40u);
  EXPECT_EQ(a.strands.points, b.strands.points);
  EXPECT_NE(a.strands.points, c.strands.points);
}

}  // namespace gathered_tail_test
