// Flyaways (strand_detail.hpp "Flyaway") against values worked out by hand: the share of strands
// moved for a seed within binomial bounds, nothing moved up to `start`, the tip moved by the
// distance, straight out from the head by D v^2 cos(phi) with the same phi all along, never closer
// to the head's centre, no kink; off (share or distance 0) bit-identical; the parameter checks.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "strand_detail.hpp"
#include "strand_lists.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace strand_detail_flyaway_test {

using namespace hairsketch;
using V3 = Eigen::Vector3d;

namespace {

using strand_lists::Strand;

const V3 kCentre(0.1, 0.2, -0.1);

using strand_lists::makeStrands;
using strand_lists::strandOf;

bool sameBits(const Strands& a, const Strands& b) {
  return a.strandStart == b.strandStart && a.points.size() == b.points.size() &&
         std::memcmp(a.points.data(), b.points.data(), a.points.size() * sizeof(float)) == 0;
}

std::vector<uint32_t> iota(size_t n) {
  std::vector<uint32_t> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = uint32_t(i);
  return v;
}

// n straight strands from roots spread over the upper part of a unit sphere round kCentre (a
// head), each leaving its root along the surface (a tangent, turned by its index) with 80 points
// 0.005 apart (3.95 cm); every 10th strand points straight out instead (no direction across it
// is "out").
std::vector<Strand> hairOnASphere(int n) {
  std::vector<Strand> out;
  for (int k = 0; k < n; ++k) {
    const double z = 0.9 - 1.2 * (k + 0.5) / n, a = 2.39996322972865332 * k;
    const double r = std::sqrt(1 - z * z);
    const V3 up(r * std::cos(a), z, r * std::sin(a));  // y up: the crown at +y
    V3 dir = up;
    if (k % 10 != 0) {
      const V3 t1 = up.cross(std::abs(up.x()) < 0.9 ? V3(1, 0, 0) : V3(0, 0, 1)).normalized();
      const V3 t2 = up.cross(t1);
      dir = std::cos(0.7 * k) * t1 + std::sin(0.7 * k) * t2;
    }
    Strand s;
    for (int i = 0; i < 80; ++i) s.push_back(kCentre + up + 0.005 * i * dir);
    out.push_back(s);
  }
  return out;
}

DetailParams flyaways(double share, double distance, double start) {
  DetailParams d;
  d.flyaway.share = share;
  d.flyaway.distance = distance;
  d.flyaway.start = start;
  return d;
}

Status apply(const std::vector<DetailParams>& groups, Strands& s, uint32_t seed) {
  const size_t n = s.strandStart.size() - 1;
  return applyDetail(groups, std::vector<uint32_t>(n, 0), iota(n), seed, s, 255, nullptr, false,
                     &kCentre);
}

}  // namespace

TEST(StrandDetailFlyaway, MovesAShareOfStrandsAwayFromTheHeadPastStartByTheDistanceAtTheTip) {
  const int n = 2000;
  const double share = 0.1, D = 0.15, a = 0.5;
  const Strands before = makeStrands(hairOnASphere(n));
  for (uint32_t seed : {1u, 7u, 20070807u}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    Strands s = before;
    ASSERT_TRUE(apply({flyaways(share, D, a)}, s, seed).ok());
    ASSERT_EQ(s.strandStart, before.strandStart);  // no point added or dropped
    int moved = 0;
    for (int k = 0; k < n; ++k) {
      const Strand p0 = strandOf(before, k), p = strandOf(s, k);
      bool any = false;
      for (size_t i = 0; i < p.size(); ++i) any |= p[i] != p0[i];
      if (!any) continue;
      ++moved;
      const double L = 0.395;
      double cosPhi = std::numeric_limits<double>::quiet_NaN();
      for (size_t i = 0; i < p.size(); ++i) {
        const double x = 0.005 * double(i) / L;
        const V3 o = p[i] - p0[i];
        // the root and the first `start` of the strand stay bit for bit
        if (x <= a) {
          EXPECT_EQ(o.norm(), 0) << "strand " << k << " point " << i;
          continue;
        }
        // never closer to the head's centre than the unmoved point
        EXPECT_GE((p[i] - kCentre).norm(), (p0[i] - kCentre).norm() - 1e-6);
        // across the (straight) strand only
        const V3 T = (p0.back() - p0.front()).normalized();
        EXPECT_NEAR(o.dot(T), 0, 1e-5);
        // straight out by D v^2 cos(phi), one phi for the strand, |phi| <= 0.5 (R = the unit part
        // of p - c across the strand; none for a strand pointing straight out)
        const V3 d = p0[i] - kCentre;
        const V3 R = d - T * d.dot(T);
        if (R.norm() < 1e-3) continue;
        const double v = (x - a) / (1 - a);
        const double c = o.dot(R.normalized()) / (D * v * v);
        if (v < 0.2) continue;  // float rounding of tiny offsets
        if (std::isnan(cosPhi)) cosPhi = c;
        EXPECT_NEAR(c, cosPhi, 2e-3) << "strand " << k << " point " << i;
        EXPECT_GE(c, std::cos(0.5) - 2e-3);
        EXPECT_LE(c, 1 + 2e-3);
      }
      // the tip moves by the distance
      EXPECT_NEAR((p.back() - p0.back()).norm(), D, 1e-5) << "strand " << k;
      // smooth: no segment (0.5 mm) turns by more than 8 degrees from the one before
      for (size_t i = 2; i < p.size(); ++i) {
        const V3 u = (p[i - 1] - p[i - 2]).normalized(), w = (p[i] - p[i - 1]).normalized();
        EXPECT_GT(u.dot(w), std::cos(8 * 3.14159265358979 / 180)) << "strand " << k;
      }
    }
    // binomial(2000, 0.1): mean 200, sd 13.4; within 4 sd
    EXPECT_GE(moved, 146);
    EXPECT_LE(moved, 254);
  }
}

TEST(StrandDetailFlyaway, AStrandsKeyAloneDecidesWhetherItFliesAway) {
  const Strands all = makeStrands(hairOnASphere(300));
  Strands s = all;
  ASSERT_TRUE(apply({flyaways(0.2, 0.15, 0.3)}, s, 5).ok());
  int checked = 0;
  for (uint32_t k = 0; k < 300; k += 7) {
    Strands one = makeStrands({strandOf(all, k)});
    ASSERT_TRUE(
        applyDetail({flyaways(0.2, 0.15, 0.3)}, {0}, {k}, 5, one, 255, nullptr, false, &kCentre)
            .ok());
    EXPECT_EQ(strandOf(one, 0), strandOf(s, k)) << "strand " << k;
    ++checked;
  }
  EXPECT_GT(checked, 40);
}

TEST(StrandDetailFlyaway, OffLeavesEveryStrandBitIdentical) {
  const Strands before = makeStrands(hairOnASphere(500));
  DetailParams others;  // clump and length jitter on, with and without a flyaway block that is off
  others.clump.factor = 0.4;
  others.clump.tipSpread = 0.004;
  others.clump.guideDistance = 0.12;
  others.lengthJitter = 0.1;
  Strands ref = before;
  ASSERT_TRUE(apply({others}, ref, 3).ok());
  for (const DetailParams& off : {flyaways(0, 0.15, 0.5), flyaways(0.1, 0, 0.5)}) {
    Strands s = before;
    ASSERT_TRUE(apply({off}, s, 3).ok());
    EXPECT_TRUE(sameBits(s, before));
    DetailParams d = others;
    d.flyaway = off.flyaway;
    s = before;
    ASSERT_TRUE(apply({d}, s, 3).ok());
    EXPECT_TRUE(sameBits(s, ref));
  }
  // and on, it changes some strands, not the others' bits
  DetailParams on = others;
  on.flyaway = flyaways(0.1, 0.15, 0.5).flyaway;
  Strands s = before;
  ASSERT_TRUE(apply({on}, s, 3).ok());
  EXPECT_FALSE(sameBits(s, ref));
  EXPECT_EQ(s.strandStart, ref.strandStart);
}

TEST(StrandDetailFlyaway, RejectsBadParametersNamingTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    const char* field;
    double FlyawayParams::*member;
    std::vector<double> bad;
  };
  const std::vector<Case> cases = {
      {"flyaway.share", &FlyawayParams::share, {-0.1, 1.1, nan}},
      {"flyaway.distance", &FlyawayParams::distance, {-0.1, nan, inf}},
      {"flyaway.start", &FlyawayParams::start, {-0.1, 1.1, nan}},
  };
  const Strands before = makeStrands(hairOnASphere(20));
  for (const Case& c : cases)
    for (double v : c.bad) {
      DetailParams d = flyaways(0.1, 0.15, 0.5);
      d.flyaway.*c.member = v;
      Strands s = before;
      const Status st = apply({flyaways(0.1, 0.15, 0.5), d}, s, 1);
      EXPECT_EQ(st.code, StatusCode::InvalidInput) << c.field << " = " << v;
      EXPECT_NE(st.message.find(std::string("detail: ") + c.field + " must be"), std::string::npos)
          << st.message;
      EXPECT_TRUE(sameBits(s, before));
    }
  Strands s = before;
  EXPECT_TRUE(apply({flyaways(1, 0.5, 1)}, s, 1).ok());  // the limits themselves
  s = before;
  EXPECT_TRUE(apply({flyaways(0, 0, 0)}, s, 1).ok());
}

}  // namespace strand_detail_flyaway_test
