// Ties from any hand (gathered_tail.hpp "Ties"; the session's `ties` on): a braid without a
// ledge where the combed hair meets it, and a bun coiled as a rope with no hole on top, on the
// sphere head of tie_scene.hpp, measured against geometry computed here.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "braid_bun.hpp"
#include "gathered_tail.hpp"
#include "tie_scene.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace tie_braid_bun_test {

using namespace hairsketch;
using namespace tie_scene;

namespace {

// The outer surface of the hair over the back of the head round the braid's gather: in each
// centimetre of height from 10 cm above the gather to 5 cm below it, the largest distance off the
// head (|x| - 1) of the points within 3 cm of the braid's plane of symmetry (x = 0) and in front
// of its axis' far side; returns the largest rise from one centimetre to the next (world units).
float braidLedge(const Head& h, bool ties) {
  const Strands s = grow(h, hanging(4.f, TailShape::Braid, ties), 3.2f);
  constexpr int kBins = 15;
  std::vector<float> top(kBins, 0.f);
  for (size_t p = 0; p < s.points.size() / 3; ++p) {
    const Eigen::Vector3f x = pointOf(s, p);
    const int bin = int(std::floor((arcOf(x) + 0.1f) / 0.01f));
    if (bin < 0 || bin >= kBins || std::abs(x.x()) > 0.3f) continue;
    top[size_t(bin)] = std::max(top[size_t(bin)], x.norm() - 1);
  }
  float worst = 0;
  for (int i = 0; i < kBins; ++i) {
    if (i > 0) worst = std::max(worst, std::abs(top[size_t(i)] - top[size_t(i - 1)]));
  }
  return worst;
}

TEST(TieBraidBun, ABraidHasNoLedgeWhereTheHairMeetsIt) {
  const Head h = backOfHead();
  const float on = braidLedge(h, true), off = braidLedge(h, false);
  std::printf(
      "braid ledge (largest rise of the hair's surface off the head per cm near the "
      "gather): ties on %.1f cm, off %.1f cm\n",
      10 * on, 10 * off);
  EXPECT_LT(on, 0.1f);   // under 1 cm per cm: a slope, no step
  EXPECT_GT(off, 0.2f);  // the ledge the plait had: the measure sees it
}

TEST(TieBraidBun, ABunIsACoilWithNoHoleOnTopAndItsTipsTuckedUnder) {
  const Head h = backOfHead();
  BunParams prm;
  prm.section = true;
  BunFrame f;
  f.centre = Eigen::Vector3d(0, 0.8, -0.6);
  f.axis = f.centre.normalized();
  f.radius = 0.3;
  GatheredTail t = bunTail(f, prm);
  t.section = true;
  t.anchor = f.centre.cast<float>().normalized();
  t.ties = true;
  const Strands s = grow(h, t, 3.2f);
  const Eigen::Vector3f c = f.centre.cast<float>(), n = f.axis.cast<float>();
  auto height = [&](const Eigen::Vector3f& x) { return (x - c).dot(n); };
  auto offAxis = [&](const Eigen::Vector3f& x) { return (x - c - height(x) * n).norm(); };
  float top = 0, R = 0;
  for (size_t p = 0; p < s.points.size() / 3; ++p) {
    const Eigen::Vector3f x = pointOf(s, p);
    if (offAxis(x) > 1.f) continue;
    top = std::max(top, height(x));
    if (height(x) > 0.15f) R = std::max(R, offAxis(x));  // above the combed hair: the bun
  }
  std::printf("bun of the back of a head, hair 32 cm: %.1f cm across, %.1f cm high\n", 20 * R,
              10 * top);
  ASSERT_GT(top, 0.1f);
  // no hole: a ray down the axis meets hair at the bun's top (within 10 % of its height), and
  // more than a fifth of the strands pass within 1 cm of the axis in the top fifth (the rope
  // goes over the top's centre)
  float axisTop = 0;
  int onAxis = 0;
  for (size_t st = 0; st < h.roots.size(); ++st) {
    bool passes = false;
    for (uint32_t p = s.strandStart[st]; p < s.strandStart[st + 1]; ++p) {
      const Eigen::Vector3f x = pointOf(s, p);
      if (offAxis(x) >= 0.1f) continue;
      axisTop = std::max(axisTop, height(x));
      passes |= height(x) > 0.8f * top;
    }
    onAxis += passes;
  }
  std::printf(
      "bun: hair on its axis up to %.1f cm of %.1f; %d of %zu strands pass within 1 cm "
      "of its axis in its top fifth\n",
      10 * axisTop, 10 * top, onAxis, h.roots.size());
  EXPECT_GT(axisTop, 0.9f * top);
  EXPECT_GT(onAxis, int(h.roots.size()) / 5);
  // the tips are tucked in: none in the top cap (above 85 % of the bun's height)
  int poking = 0;
  for (size_t st = 0; st < h.roots.size(); ++st)
    if (height(tipOf(s, st)) > 0.85f * top) ++poking;
  EXPECT_EQ(poking, 0);
  // sized from its hair: a rope of the round tail's radius, the whole coil wider than the rope
  EXPECT_GT(R, 2.5f * kBunRopeFill * kTailRadius);
  EXPECT_LT(R, 1.0f);
}

}  // namespace
}  // namespace tie_braid_bun_test
