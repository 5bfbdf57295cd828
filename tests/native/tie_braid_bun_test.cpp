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

// A whole-section bun on the back of the head, its hair 32 cm long, ties from any hand.
struct BackBun {
  Head h = backOfHead();
  BunFrame f;
  Strands s;
};
BackBun backBun(bool volume, bool compact) {
  BackBun b;
  BunParams prm;
  prm.section = true;
  b.f.centre = Eigen::Vector3d(0, 0.8, -0.6);
  b.f.axis = b.f.centre.normalized();
  b.f.radius = 0.3;
  GatheredTail t = bunTail(b.f, prm);
  t.section = true;
  t.anchor = b.f.centre.cast<float>().normalized();
  t.ties = true;
  t.tieVolume = volume;
  t.compactBun = compact;
  b.s = grow(b.h, t, 3.2f);
  return b;
}

TEST(TieBraidBun, ABunIsACoilWithNoHoleOnTopAndItsTipsTuckedUnder) {
  const BackBun b = backBun(false, false);
  const Head& h = b.h;
  const BunFrame& f = b.f;
  const Strands& s = b.s;
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

// The bun of the back of a head, its hair 32 cm long (the test above's scene), compact or not.
struct BunSeen {
  float top = 0;        // its height over the base (world units)
  float covered = 0;    // of the disc within 0.8 of its outline, the share of 1 cm cells under hair
  float roundness = 0;  // the outline's widest sector over its narrowest (24 sectors)
  float tipHeight = 0;  // the highest tip, over the bun's height
  float across = 0;     // its widest outline's diameter
};
BunSeen seeBun(bool compact) {
  const BackBun bb = backBun(true, compact);
  const Head& h = bb.h;
  const BunFrame& f = bb.f;
  const Strands& s = bb.s;
  const Eigen::Vector3f c = f.centre.cast<float>(), n = f.axis.cast<float>();
  const Eigen::Vector3f e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  BunSeen b;
  std::vector<Eigen::Vector3f> bun;  // the points above the combed hair, in the bun's frame
  for (size_t p = 0; p < s.points.size() / 3; ++p) {
    const Eigen::Vector3f d = pointOf(s, p) - c;
    const Eigen::Vector3f x(d.dot(e1), d.dot(e2), d.dot(n));
    if (x.head<2>().norm() < 1.f && x.z() > 0.1f) bun.push_back(x);
  }
  constexpr int kSectors = 24;
  std::vector<float> outline(kSectors, 0.f);
  for (const Eigen::Vector3f& x : bun) {
    b.top = std::max(b.top, x.z());
    const float a = std::atan2(x.y(), x.x()) + 3.14159265f;
    const int k = std::min(kSectors - 1, int(a / (2 * 3.14159265f) * kSectors));
    outline[size_t(k)] = std::max(outline[size_t(k)], x.head<2>().norm());
  }
  const auto [lo, hi] = std::minmax_element(outline.begin(), outline.end());
  b.roundness = *hi / std::max(*lo, 1e-6f);
  b.across = 2 * *hi;
  // seen down the axis: 1 cm cells of the disc within 0.8 of the narrowest outline
  const float R = 0.8f * *lo;
  const int m = int(std::ceil(R / 0.1f));
  int cells = 0, hit = 0;
  for (int i = -m; i <= m; ++i)
    for (int j = -m; j <= m; ++j) {
      const Eigen::Vector2f q(0.1f * float(i), 0.1f * float(j));
      if (q.norm() > R) continue;
      ++cells;
      for (const Eigen::Vector3f& x : bun)
        if ((x.head<2>() - q).cwiseAbs().maxCoeff() < 0.05f && x.z() > 0.3f * b.top) {
          ++hit;
          break;
        }
    }
  b.covered = float(hit) / float(std::max(cells, 1));
  for (size_t st = 0; st < h.roots.size(); ++st) {
    const Eigen::Vector3f d = tipOf(s, st) - c;
    b.tipHeight = std::max(b.tipHeight, d.dot(n) / b.top);
  }
  return b;
}

// Compact bun (the session's compactBun): seen down its axis the bun is hair all over (no hole
// between its stub and its wraps), its outline round (no spiral's loose end), its tips tucked
// low; the rope coiled outwards (compactBun off) fails the first two.
TEST(TieBraidBun, ACompactBunIsARoundKnotWithNoHoleAndNoLooseEnd) {
  const BunSeen on = seeBun(true), off = seeBun(false);
  std::printf(
      "bun, whole head, hair 32 cm: compact %.1f cm across, %.1f cm high, %.0f %% of its disc "
      "under hair, outline "
      "%.2f widest / narrowest, tips up to %.0f %% of its height; rope before %.1f cm, %.0f %%, "
      "%.2f, %.0f %%\n",
      10 * on.across, 10 * on.top, 100 * on.covered, on.roundness, 100 * on.tipHeight, 10 * off.top,
      100 * off.covered, off.roundness, 100 * off.tipHeight);
  EXPECT_GT(on.covered, 0.97f);
  EXPECT_LT(on.roundness, 1.3f);
  EXPECT_LT(on.tipHeight, 0.6f);
  EXPECT_LT(off.covered, 0.97f);
  EXPECT_GT(off.roundness, 1.3f);
}

}  // namespace
}  // namespace tie_braid_bun_test
