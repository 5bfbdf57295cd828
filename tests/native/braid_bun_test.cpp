// Braids and buns laid in growth (braid_bun.hpp, gathered_tail.hpp), on hand-made strands (no
// field). A braid is measured from its strands alone: each strand's side of the spine's plane
// along the braid (its crossings give the period), each strand's phase (a least-squares fit of
// sin / cos of 2 pi s / P to its offset across the spine) clusters the strands into three bundles
// whose mean paths are the bundle centre lines (kept at least half a bundle apart). A bun's
// strands are measured by where their tips end and how far they wind round the axis. Both: the
// 255-point cap, the strand count, and the seed deciding the layout. Parameter limits too.
#include "braid_bun.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "curve_params.hpp"
#include "gathered_tail.hpp"
#include "gathered_tail_internal.hpp"
#include "hand_strands.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace braid_bun_test {

using namespace hairsketch;

namespace {

using hand_strands::kStep;
constexpr double kPi = 3.14159265358979323846;

using hand_strands::addStrand;
using hand_strands::Hair;
// A sheet of 41 x 3 strands from above, through a thin line at the origin, down to y = -4.5.
Hair sheet() { return hand_strands::sheet(-4.5f); }

// A braid hanging straight down from the origin for 4.5 units; the head is behind it (+z).
const BraidParams kBraid{0.6, 6, 0.5, 0.5};  // P = 1
GatheredTail braid(const BraidParams& prm = kBraid) {
  std::vector<double> spine;
  for (int i = 0; i <= 45; ++i) spine.insert(spine.end(), {0.0, -0.1 * i, 0.0});
  return braidTail(spine.data(), spine.size() / 3, 0, prm, Eigen::Vector3f(0, 0, -1));
}

// Offset across the spine (x) at arc length s = -y, sampled on a grid of s; NaN where absent.
std::vector<double> acrossAt(const Strands& s, size_t st, const std::vector<double>& grid) {
  std::vector<double> out(grid.size(), std::nan(""));
  for (uint32_t p = s.strandStart[st]; p + 1 < s.strandStart[st + 1]; ++p) {
    const float* a = &s.points[3 * p];
    const float* b = a + 3;
    for (size_t g = 0; g < grid.size(); ++g) {
      const double y = -grid[g];
      if ((a[1] - y) * (b[1] - y) > 0 || a[1] == b[1]) continue;
      const double t = (a[1] - y) / (a[1] - b[1]);
      if (std::isnan(out[g])) out[g] = a[0] + t * (b[0] - a[0]);
    }
  }
  return out;
}

}  // namespace

TEST(Braid, StrandsCrossTheSpineWithThePeriodInThreeSeparateBundles) {
  Hair h = sheet();
  const GatheredTail t = braid();
  ASSERT_NEAR(t.braidLength, 4.0, 1e-4);
  const TailStats st = gatherTails({t}, h.roots, h.key, 7, kStep, 255, h.strands);
  ASSERT_EQ(st.captured, h.roots.size());
  const double P = 6 / kBraid.crossings;
  // the braid proper: past the blend from the gather, before the taper's last stretch and tie
  std::vector<double> grid;
  for (double s = 0.5; s <= 3.8; s += 0.005) grid.push_back(s);
  const size_t nS = h.roots.size();
  std::vector<double> phase(nS);
  std::vector<std::vector<double>> xs(nS);
  for (size_t k = 0; k < nS; ++k) {
    EXPECT_LE(h.strands.strandStart[k + 1] - h.strands.strandStart[k], 255u);
    xs[k] = acrossAt(h.strands, k, grid);
    // crossings of the spine's plane (x = 0): at least twice per period, spaced P / 2 on average
    std::vector<double> at;
    double sc = 0, cc = 0;
    for (size_t g = 0; g + 1 < grid.size(); ++g) {
      ASSERT_FALSE(std::isnan(xs[k][g])) << "strand " << k << " at s " << grid[g];
      if ((xs[k][g] < 0) != (xs[k][g + 1] < 0)) at.push_back(grid[g]);
      sc += xs[k][g] * std::sin(2 * kPi * grid[g] / P);
      cc += xs[k][g] * std::cos(2 * kPi * grid[g] / P);
    }
    const double span = grid.back() - grid.front();
    ASSERT_GE(at.size(), size_t(2 * std::floor(span / P))) << "strand " << k;
    phase[k] = std::atan2(cc, sc);
  }
  // three bundles by phase: every strand within 30 degrees of one of three phases 120 apart
  const double base = phase[0];
  std::vector<int> bundleOf(nS);
  std::vector<int> count(3, 0);
  for (size_t k = 0; k < nS; ++k) {
    double d = std::remainder(phase[k] - base, 2 * kPi / 3);
    EXPECT_LT(std::abs(d), kPi / 6) << "strand " << k;
    const int b =
        int(std::lround(std::remainder(phase[k] - base - d, 2 * kPi) / (2 * kPi / 3)) + 3) % 3;
    bundleOf[k] = b;
    ++count[size_t(b)];
  }
  for (int c : count) EXPECT_GT(c, int(nS) / 5);
  // centre lines: the mean offset of each bundle, in x (across) and z (depth)
  double closest = 1e9;
  std::vector<std::pair<double, int>> crossing;  // (s, bundle) where a centre line crosses x = 0
  double lastX[3] = {0, 0, 0};
  for (double s = 0.5; s <= 3.8; s += 0.01) {
    Eigen::Vector2d centre[3] = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                 Eigen::Vector2d::Zero()};
    for (size_t k = 0; k < nS; ++k)
      for (uint32_t p = h.strands.strandStart[k]; p + 1 < h.strands.strandStart[k + 1]; ++p) {
        const float* a = &h.strands.points[3 * p];
        const float* b = a + 3;
        if ((a[1] + s) * (b[1] + s) > 0 || a[1] == b[1]) continue;
        const double f = (a[1] + s) / (a[1] - b[1]);
        centre[bundleOf[k]] += Eigen::Vector2d(a[0] + f * (b[0] - a[0]), a[2] + f * (b[2] - a[2]));
        break;
      }
    for (int b = 0; b < 3; ++b) {
      centre[b] /= double(count[size_t(b)]);
      if (s > 0.5 && (lastX[b] < 0) != (centre[b].x() < 0)) crossing.emplace_back(s, b);
      lastX[b] = centre[b].x();
    }
    const double W = kBraid.width * (1 - 0.4 * s / 4.0), halfBundle = W * kBraidBundle;
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j)
        closest = std::min(closest, (centre[i] - centre[j]).norm() / halfBundle);
  }
  EXPECT_GE(closest, 1.0) << "bundle centre lines closer than half a bundle";
  // each centre line crosses every P / 2; the three in turn (never one bundle twice running)
  for (int b = 0; b < 3; ++b) {
    std::vector<double> at;
    for (const auto& c : crossing)
      if (c.second == b) at.push_back(c.first);
    ASSERT_GE(at.size(), 4u);
    EXPECT_NEAR((at.back() - at.front()) / double(at.size() - 1), P / 2, 0.1 * P / 2) << b;
  }
  for (size_t i = 1; i < crossing.size(); ++i)
    EXPECT_NE(crossing[i].second, crossing[i - 1].second) << "at s " << crossing[i].first;
}

TEST(Braid, TheSeedDecidesAndThePointCapHolds) {
  Hair a = sheet(), b = sheet(), c = sheet();
  gatherTails({braid()}, a.roots, a.key, 7, kStep, 120, a.strands);
  gatherTails({braid()}, b.roots, b.key, 7, kStep, 120, b.strands);
  gatherTails({braid()}, c.roots, c.key, 9, kStep, 120, c.strands);
  EXPECT_EQ(a.strands.points, b.strands.points);
  EXPECT_NE(a.strands.points, c.strands.points);
  ASSERT_EQ(a.strands.strandStart.size(), a.roots.size() + 1);
  for (size_t k = 0; k < a.roots.size(); ++k)
    EXPECT_LE(a.strands.strandStart[k + 1] - a.strands.strandStart[k], 120u);
}

namespace {

// A head: the unit sphere about the origin; the bun's loop a circle of radius 0.3 on its top.
const BunParams kBun{0, 0.35, 2.5};
GatheredTail bun(BunFrame* frameOut = nullptr) {
  std::vector<double> loop;
  for (int i = 0; i < 24; ++i) {
    const double a = 2 * kPi * i / 24, x = 0.3 * std::cos(a), z = 0.3 * std::sin(a);
    loop.insert(loop.end(), {x, std::sqrt(1 - x * x - z * z), z});
  }
  const Eigen::Vector3d centre(0, 0, 0);
  const BunFrame f = bunFrame(loop.data(), 24, kBun, &centre);
  if (frameOut) *frameOut = f;
  return bunTail(f, kBun);
}

// Strands from roots on the sphere round the bun, along the surface to near the axis, then up.
Hair towardsTheBun(const BunFrame& f) {
  Hair h;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 4; ++j) {
      const float a = float(2 * kPi * i / 60), r = 0.45f + 0.12f * float(j);
      const Eigen::Vector3f root(r * std::cos(a), std::sqrt(1 - r * r), r * std::sin(a));
      const Eigen::Vector3f near(0.1f * std::cos(a), float(f.centre.y()) + 0.02f,
                                 0.1f * std::sin(a));
      h.roots.push_back(root);
      addStrand({root, near, near + Eigen::Vector3f(0, 0.8f + 0.3f * float(j), 0)}, h.strands);
      h.key.push_back(uint32_t(h.key.size()));
    }
  return h;
}

}  // namespace

TEST(Bun, StrandsWindRoundTheAxisAndEndInsideIt) {
  BunFrame f;
  const GatheredTail t = bun(&f);
  EXPECT_NEAR(f.axis.y(), 1.0, 1e-6);
  EXPECT_NEAR(f.radius, 0.3, 0.02);
  Hair h = towardsTheBun(f);
  const TailStats st = gatherTails({t}, h.roots, h.key, 7, kStep, 255, h.strands);
  EXPECT_EQ(st.captured, h.roots.size());
  const Eigen::Vector3f c = f.centre.cast<float>();
  for (size_t k = 0; k < h.roots.size(); ++k) {
    const uint32_t a = h.strands.strandStart[k], b = h.strands.strandStart[k + 1];
    EXPECT_LE(b - a, 255u);
    const Eigen::Vector3f tip(&h.strands.points[3 * (b - 1)]);
    EXPECT_LE((tip - c).norm(), f.radius + kBun.height) << "strand " << k;
    // the angle wound round the axis from where the strand comes within 1.5 R of it
    double wound = 0, last = 0;
    bool in = false;
    for (uint32_t p = a; p < b; ++p) {
      const float* q = &h.strands.points[3 * p];
      const double x = q[0] - c.x(), z = q[2] - c.z();
      if (!in && std::hypot(x, z) > 1.5 * f.radius) continue;
      const double ang = std::atan2(z, x);
      if (in) wound += std::remainder(ang - last, 2 * kPi);
      in = true;
      last = ang;
    }
    EXPECT_GE(std::abs(wound), kPi) << "strand " << k;
  }
}

TEST(Bun, TheSeedDecides) {
  BunFrame f;
  const GatheredTail t = bun(&f);
  Hair a = towardsTheBun(f), b = towardsTheBun(f), c = towardsTheBun(f);
  gatherTails({t}, a.roots, a.key, 7, kStep, 255, a.strands);
  gatherTails({t}, b.roots, b.key, 7, kStep, 255, b.strands);
  gatherTails({t}, c.roots, c.key, 8, kStep, 255, c.strands);
  EXPECT_EQ(a.strands.points, b.strands.points);
  EXPECT_NE(a.strands.points, c.strands.points);
}

// Round plaits: where a bundle runs aslant, a slice across the spine cuts its round section
// sqrt(1 + m^2) long (m its centre's slope against the spine's arc length). Hand values for the
// test braid at S = 1 (P = 1, bundle 0: phase 2 pi, its centre crossing the spine at its
// steepest): width 0.6 (1 - 0.4 S / 4) = 0.54, bundle radius rb = 0.54 / 4.5 = 0.12, swing
// A = 0.27 - 0.12 = 0.15 across and B = 0.12 (1.5 - 0.8 x 0.5) = 0.132 in depth, slopes
// A 2 pi = 0.94248 and B 4 pi = 1.65876.
TEST(Braid, RoundPlaitsKeepEachBundleRoundAcrossItsOwnPath) {
  GatheredTail off = braid();
  GatheredTail on = braid();
  on.roundPlaits = true;
  const double rb = 0.12, kx = std::sqrt(1 + 0.94248 * 0.94248),
               ky = std::sqrt(1 + 1.65876 * 1.65876);
  const float rad = 0.1f;
  for (const float rho : {0.5f, 1.f}) {
    // across the spine (theta 0) and in depth (theta pi / 2); the centre is at ~0 here
    const Eigen::Vector2f x0 = gathered_tail::seatOffset(off, 1.f, rad, 0.f, rho, 0);
    const Eigen::Vector2f x1 = gathered_tail::seatOffset(on, 1.f, rad, 0.f, rho, 0);
    EXPECT_NEAR(x0.x(), rb * rho, 1e-5);
    EXPECT_NEAR(x1.x(), rb * rho * kx, 1e-5);
    const float half = 0.5f * float(kPi);
    const Eigen::Vector2f y0 = gathered_tail::seatOffset(off, 1.f, rad, half, rho, 0);
    const Eigen::Vector2f y1 = gathered_tail::seatOffset(on, 1.f, rad, half, rho, 0);
    EXPECT_NEAR(y0.y(), rb * rho, 1e-5);
    EXPECT_NEAR(y1.y(), rb * rho * ky, 1e-5);
  }
  // where the bundle turns (phase 2 pi + pi / 2: its centre at the braid's edge, not moving
  // across) a slice is round across; in depth it runs at B 4 pi |cos(pi)| there, as steep
  const Eigen::Vector2f edge = gathered_tail::seatOffset(on, 1.25f, rad, 0.f, 1.f, 0);
  const double W = 0.6 * (1 - 0.4 * 1.25 / 4), A = W / 2 - W / 4.5;
  EXPECT_NEAR(edge.x(), A + W / 4.5, 1e-5);
  // the same seed lays the same strands each time; round plaits lay the same strands wider
  Hair a = sheet(), b = sheet(), c = sheet();
  gatherTails({off}, a.roots, a.key, 7, kStep, 255, a.strands);
  GatheredTail off2 = braid();
  gatherTails({off2}, b.roots, b.key, 7, kStep, 255, b.strands);
  gatherTails({on}, c.roots, c.key, 7, kStep, 255, c.strands);
  EXPECT_EQ(a.strands.points, b.strands.points);
  EXPECT_EQ(a.strands.strandStart, c.strands.strandStart);
  EXPECT_NE(a.strands.points, c.strands.points);
}

TEST(BraidBun, ParameterLimits) {
  BraidParams bp;
  const double good[kBraidParamCount] = {0.5, 6, 0.5, 0.4};
  EXPECT_TRUE(parseBraidParams(good, kBraidParamCount, bp).ok());
  EXPECT_EQ(bp.crossings, 6);
  EXPECT_FALSE(parseBraidParams(good, 3, bp).ok());
  for (size_t i = 0; i < kBraidParamCount; ++i)
    for (double bad : {-1.0, 100.0, std::nan("")}) {
      double p[kBraidParamCount] = {0.5, 6, 0.5, 0.4};
      p[i] = bad;
      EXPECT_FALSE(parseBraidParams(p, kBraidParamCount, bp).ok()) << i << " " << bad;
    }
  BunParams un;
  const double bun[kBunParamCount] = {0, 0.35, 2.5};
  EXPECT_TRUE(parseBunParams(bun, kBunParamCount, un).ok());
  for (size_t i = 0; i < kBunParamCount; ++i)
    for (double bad : {-1.0, 100.0, std::nan("")}) {
      double p[kBunParamCount] = {0, 0.35, 2.5};
      p[i] = bad;
      EXPECT_FALSE(parseBunParams(p, kBunParamCount, un).ok()) << i << " " << bad;
    }
}

}  // namespace braid_bun_test
