// Curl volume (strand_detail.hpp "Curl volume") against values worked out by hand: on a strand
// hanging straight down, the path moves out from the head by v k L g t^1.3 (k the curl's
// shrinkage, g the lock's factor within 1 +- kCurlSpreadVary), horizontally, within
// kCurlSpreadTurn of straight out and never forward, its back part then scaled by
// kCurlSpreadBack; nothing moves up to the curl's start; hair
// straight in front of the head's centre does not move; loose waves hardly spread; spread 0 leaves
// the curl as before, bit for bit. Coil volume on top of it (strand_detail.hpp "Coil volume").
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "strand_detail.hpp"
#include "strand_lists.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace strand_detail_curl_volume_test {

using namespace hairsketch;
using V3 = Eigen::Vector3d;

namespace {

constexpr double kPi = 3.14159265358979323846;
const V3 kCentre(0.05, 0.3, -0.1);

using strand_lists::makeStrands;
using strand_lists::Strand;
using strand_lists::strandOf;

// A strand hanging straight down from root: n points `step` apart.
Strand hanging(const V3& root, int n, double step) {
  Strand s;
  for (int i = 0; i < n; ++i) s.push_back(root - V3(0, step * i, 0));
  return s;
}

std::vector<uint32_t> iota(size_t n) {
  std::vector<uint32_t> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = uint32_t(i);
  return v;
}

// A curl whose helix is too small to see (radius 1e-5) but as steep as a real one (2 pi q r =
// steep: 1.5 for a 3A curl, 0.207 for a 2A wave): what moves a point is the spread alone, to
// within 2e-5.
DetailParams tinyCurl(double spread, double steep = 1.5) {
  DetailParams d;
  d.curl.radius = 1e-5;
  d.curl.frequency = steep / (2 * kPi * d.curl.radius);
  d.curl.start = 0.2;
  d.curl.spread = spread;
  return d;
}

Strands grow(const std::vector<Strand>& hair, const DetailParams& d) {
  Strands s = makeStrands(hair);
  const size_t n = hair.size();
  EXPECT_TRUE(
      applyDetail({d}, std::vector<uint32_t>(n, 0), iota(n), 11, s, 255, nullptr, false, &kCentre)
          .ok());
  return s;
}

TEST(CurlVolume, SpreadsHairOutFromTheHeadByTheShareOfItsShrinkageGrowingToTheTip) {
  // Roots round the head at its side and back (and one just in front of the ear), 3 units long.
  std::vector<Strand> hair;
  for (int k = 0; k < 40; ++k) {
    const double a = -0.3 * kPi - 1.2 * kPi * k / 39;  // from in front of the side to the back
    hair.push_back(hanging(kCentre + V3(0.8 * std::cos(a), -0.2, -0.8 * std::sin(a)), 121, 0.025));
  }
  const double v = kCurlSpread, L = 3.0;
  const Strands on = grow(hair, tinyCurl(v)), off = grow(hair, tinyCurl(0));
  const double tipWant = v * (1 - 1 / std::sqrt(3.25)) * L;  // shrinkage 0.4453 by hand
  double gMin = 10, gMax = 0;
  for (size_t s = 0; s < hair.size(); ++s) {
    SCOPED_TRACE(testing::Message() << "strand " << s);
    const Strand a = strandOf(on, s), b = strandOf(off, s);
    ASSERT_EQ(a.size(), b.size());
    const size_t m = a.size();
    // the move with its back part as it was before kCurlSpreadBack scaled it
    auto unscaled = [](V3 v) {
      v.z() /= kCurlSpreadBack;
      return v;
    };
    const V3 tipMove = unscaled(a[m - 1] - b[m - 1]);
    const double g = tipMove.norm() / tipWant;
    gMin = std::min(gMin, g);
    gMax = std::max(gMax, g);
    EXPECT_GE(g, 1 - kCurlSpreadVary - 1e-3);
    EXPECT_LE(g, 1 + kCurlSpreadVary + 1e-3);
    EXPECT_NEAR(tipMove.y(), 0, 1e-4);  // horizontally
    // within the turn of straight out (its forward part dropped), and never forward
    V3 out = hair[s][0] - kCentre;
    out.y() = 0;
    out.z() = std::min(out.z(), 0.0);
    const double angle = std::acos(std::clamp(out.normalized().dot(tipMove.normalized()), -1., 1.));
    EXPECT_LE(angle, kCurlSpreadTurn + 1e-3);
    EXPECT_LE(tipMove.z(), 1e-4);
    // along the strand: nothing up to the start, then t^1.3 of the tip's move, the same way
    for (size_t k = 0; k < m; ++k) {
      const double x = double(k) / double(m - 1), t = std::max(0.0, (x - 0.2) / 0.8);
      const V3 move = unscaled(a[k] - b[k]);
      EXPECT_NEAR(move.norm(), tipMove.norm() * std::pow(t, 1.3), 1e-4) << "point " << k;
      if (t > 0.1) EXPECT_GT(move.normalized().dot(tipMove.normalized()), 0.99999);
    }
  }
  // the locks' factors cover their range
  EXPECT_LT(gMin, 0.8);
  EXPECT_GT(gMax, 1.2);
}

TEST(CurlVolume, HairStraightInFrontOfTheHeadDoesNotMoveAndWavesHardlySpread) {
  const Strand front = hanging(kCentre + V3(0, -0.3, 0.9), 81, 0.025);
  const Strands on = grow({front}, tinyCurl(0.45)), off = grow({front}, tinyCurl(0));
  const Strand a = strandOf(on, 0), b = strandOf(off, 0);
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) EXPECT_LT((a[k] - b[k]).norm(), 1e-6) << "point " << k;
  // a 2A wave (radius 3 mm, 1.1 turns a unit: 2 pi q r = 0.2073, shrinkage 1 - 1 / sqrt(1.04297)
  // = 0.0208 by hand): 3 units of hair at the side spread by 0.45 x 0.0208 x 3 x g at the tip
  const Strand side = hanging(kCentre + V3(0.8, -0.2, -0.1), 121, 0.025);
  const Strands wOn = grow({side}, tinyCurl(0.45, 0.2073)),
                wOff = grow({side}, tinyCurl(0, 0.2073));
  const Strand c = strandOf(wOn, 0), e = strandOf(wOff, 0);
  V3 d = c.back() - e.back();
  d.z() /= kCurlSpreadBack;
  const double tip = d.norm(), want = 0.45 * 0.0208 * 3;
  EXPECT_GE(tip, (1 - kCurlSpreadVary) * want - 1e-3);
  EXPECT_LE(tip, (1 + kCurlSpreadVary) * want + 1e-3);
}

TEST(CurlVolume, SpreadZeroIsTheCurlAsBeforeAndABadSpreadIsRefused) {
  // the same curl with spread 0 and with the field left at its default: bit-identical
  std::vector<Strand> hair{hanging(V3(0.8, 0, -0.3), 61, 0.03),
                           hanging(V3(-0.5, 0.1, -0.7), 61, 0.03)};
  DetailParams d;
  d.curl.radius = 0.1;
  d.curl.frequency = 2.5;
  DetailParams zero = d;
  zero.curl.spread = 0;
  const Strands a = grow(hair, d), b = grow(hair, zero);
  ASSERT_EQ(a.strandStart, b.strandStart);
  EXPECT_EQ(0, std::memcmp(a.points.data(), b.points.data(), a.points.size() * sizeof(float)));
  DetailParams bad = d;
  for (double x : {-0.1, std::nan("")}) {
    bad.curl.spread = x;
    const Status st = validateDetail(bad);
    EXPECT_FALSE(st.ok());
    EXPECT_NE(st.message.find("curl.spread"), std::string::npos) << st.message;
  }
}

// Coil volume (strand_detail.hpp "Coil volume"): a coil (coiliness 1: the tiny curl's frequency is
// far past kCoilFull) moves hair at the side 1 + kCoilGain times as far at the tip, along
// 1 - (1 - t)^2 (out at once, then hanging), horizontally below the head's centre.
TEST(CoilVolume, CoilsStandOutSoonerAndFurtherThanCurls) {
  std::vector<Strand> hair;
  for (int k = 0; k < 12; ++k) {
    const double a = -0.3 * kPi - 1.2 * kPi * k / 11;
    hair.push_back(hanging(kCentre + V3(0.8 * std::cos(a), -0.2, -0.8 * std::sin(a)), 121, 0.025));
  }
  DetailParams coil = tinyCurl(kCurlSpread);
  coil.curl.coil = 1;
  ASSERT_GT(coil.curl.frequency, kCoilFull);
  const Strands on = grow(hair, coil), off = grow(hair, tinyCurl(0)),
                curl = grow(hair, tinyCurl(kCurlSpread));
  for (size_t s = 0; s < hair.size(); ++s) {
    SCOPED_TRACE(testing::Message() << "strand " << s);
    const Strand a = strandOf(on, s), b = strandOf(off, s), c = strandOf(curl, s);
    ASSERT_EQ(a.size(), b.size());
    const size_t m = a.size();
    auto unscaled = [](V3 v) {
      v.z() /= kCurlSpreadBack;
      return v;
    };
    const V3 tipMove = unscaled(a[m - 1] - b[m - 1]), curlTip = unscaled(c[m - 1] - b[m - 1]);
    // the same lock's factor and lean: 1 + kCoilGain times the curl's move, the same way
    EXPECT_NEAR(tipMove.norm(), (1 + kCoilGain) * curlTip.norm(), 1e-4);
    EXPECT_GT(tipMove.normalized().dot(curlTip.normalized()), 0.99999);
    EXPECT_NEAR(tipMove.y(), 0, 1e-4);  // below the centre: horizontally
    for (size_t k = 0; k < m; ++k) {
      const double x = double(k) / double(m - 1), t = std::max(0.0, (x - 0.2) / 0.8);
      const V3 move = unscaled(a[k] - b[k]);
      EXPECT_NEAR(move.norm(), tipMove.norm() * (1 - (1 - t) * (1 - t)), 1e-4) << "point " << k;
    }
  }
}

TEST(CoilVolume, HairOnTheTopStandsUpAndLooseCurlsAreAsBefore) {
  // a strand rising from the top of the head: its coil volume lifts it, never pushes it down
  Strand up;
  for (int i = 0; i < 81; ++i) up.push_back(kCentre + V3(0.2, 0.7 + 0.025 * i, -0.1));
  DetailParams coil = tinyCurl(kCurlSpread);
  coil.curl.coil = 1;
  const Strands on = grow({up}, coil), off = grow({up}, tinyCurl(0));
  const Strand a = strandOf(on, 0), b = strandOf(off, 0);
  for (size_t k = 0; k < a.size(); ++k) EXPECT_GE(a[k].y() - b[k].y(), -1e-6) << "point " << k;
  EXPECT_GT(a.back().y() - b.back().y(), 0.1);
  // 3C (4.8 turns a unit, under kCoilFrom): coil on is the curl volume alone, bit for bit
  std::vector<Strand> hair{hanging(V3(0.8, 0, -0.3), 61, 0.03),
                           hanging(V3(-0.5, 0.1, -0.7), 61, 0.03)};
  DetailParams d;
  d.curl.radius = 0.058;
  d.curl.frequency = 4.8;
  d.curl.spread = kCurlSpread;
  DetailParams c = d;
  c.curl.coil = 1;
  const Strands x = grow(hair, d), y = grow(hair, c);
  ASSERT_EQ(x.strandStart, y.strandStart);
  EXPECT_EQ(0, std::memcmp(x.points.data(), y.points.data(), x.points.size() * sizeof(float)));
}

}  // namespace

}  // namespace strand_detail_curl_volume_test
