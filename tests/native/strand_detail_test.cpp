// Hair detail (strand_detail.hpp) against geometry worked out by hand: the helix a curl makes on a
// straight strand, tips on their clump guide, the shape falloff's values, length ranges, the point
// cap, determinism by seed and key, and the parameter checks.
#include "strand_detail.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

#include "strand_lists.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace strand_detail_test {

using namespace hairsketch;
using V3 = Eigen::Vector3d;

namespace {

constexpr double kPi = 3.14159265358979323846;

using strand_lists::Strand;

using strand_lists::makeStrands;
using strand_lists::strandOf;

size_t strandCount(const Strands& s) { return s.strandStart.size() - 1; }

// n points from root along dir (normalised), `step` apart.
Strand straight(const V3& root, const V3& dir, int n, double step) {
  Strand s;
  for (int i = 0; i < n; ++i) s.push_back(root + dir.normalized() * (step * i));
  return s;
}

// A bent strand: a quarter circle of radius 1 in a plane through root.
Strand bent(const V3& root, int n) {
  Strand s;
  for (int i = 0; i < n; ++i) {
    const double a = 0.5 * kPi * i / (n - 1);
    s.push_back(root + V3(1 - std::cos(a), std::sin(a), 0.2 * a));
  }
  return s;
}

double polyLength(const Strand& s) {
  double L = 0;
  for (size_t i = 1; i < s.size(); ++i) L += (s[i] - s[i - 1]).norm();
  return L;
}

bool sameBits(const Strands& a, const Strands& b) {
  return a.strandStart == b.strandStart && a.points.size() == b.points.size() &&
         std::memcmp(a.points.data(), b.points.data(), a.points.size() * sizeof(float)) == 0;
}

std::vector<uint32_t> iota(size_t n, uint32_t from = 0) {
  std::vector<uint32_t> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = from + uint32_t(i);
  return v;
}

Status apply(const DetailParams& d, Strands& s, uint32_t seed = 7, int maxPoints = 255) {
  const size_t n = strandCount(s);
  return applyDetail({d}, std::vector<uint32_t>(n, 0), iota(n), seed, s, maxPoints);
}

// Everything on, at moderate values.
DetailParams allOn() {
  DetailParams d;
  d.curl.radius = 0.05;
  d.curl.frequency = 2;
  d.curl.randomOffset = 1;
  d.clump.factor = 0.5;
  d.clump.tipSpread = 0.01;
  d.clump.guideDistance = 0.1;
  d.frizz.distance = 0.005;
  d.lengthJitter = 0.3;
  return d;
}

// A patch of strands: roots on a jittered grid in the xz plane, growing up with distinct tilts.
std::vector<Strand> patch(int side, double spacing, int points, double step) {
  std::vector<Strand> out;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const int k = i * side + j;
      const V3 root(spacing * i + 0.2 * spacing * std::sin(7.1 * k), 0,
                    spacing * j + 0.2 * spacing * std::cos(5.3 * k));
      const V3 dir(0.2 * std::sin(1.7 * k), 1, 0.2 * std::cos(2.3 * k));
      out.push_back(straight(root, dir, points, step * (1 + 0.1 * std::sin(0.9 * k))));
    }
  return out;
}

}  // namespace

TEST(StrandDetail, ShapeFalloffMatchesHandValues) {
  for (double x : {0.0, 0.3, 1.0}) EXPECT_DOUBLE_EQ(shapeFalloff(x, 0), 1.0);
  for (double x : {0.0, 0.2, 0.7, 1.0}) {
    EXPECT_NEAR(shapeFalloff(x, 0.5), x, 1e-12);
    EXPECT_NEAR(shapeFalloff(x, -0.5), 1 - x, 1e-12);
  }
  // s = 0.25: exponent -log2(0.75) = log2(4/3), so (1/4)^log2(4/3) = (3/4)^2.
  EXPECT_NEAR(shapeFalloff(0.25, 0.25), 9.0 / 16, 1e-12);
  // s = 0.75: 1 - (1/2)^log2(4/3) = 1 - 3/4.
  EXPECT_NEAR(shapeFalloff(0.5, 0.75), 0.25, 1e-12);
  // s = -0.25: x' = 1 - x = 1/2, (1/2)^log2(4/3) = 3/4.
  EXPECT_NEAR(shapeFalloff(0.5, -0.25), 0.75, 1e-12);
  // s = 1: exponent -log2(1) = 0, so 1 - (1 - x)^0 = 0 below the tip.
  EXPECT_NEAR(shapeFalloff(0.3, 1), 0.0, 1e-12);
}

TEST(StrandDetail, CurlOnAStraightStrandIsAHelixOfTheRadiusAndPitch) {
  struct Case {
    double r, q;
  };
  const V3 root(0.3, -0.2, 0.1), dir = V3(1, 2, 0.5).normalized();
  for (const Case c : {Case{0.1, 1}, Case{0.05, 4}, Case{0.2, 0.5}}) {
    SCOPED_TRACE(testing::Message() << "r " << c.r << " q " << c.q);
    Strands s = makeStrands({straight(root, dir, 61, 0.06)});  // 3.6 units
    DetailParams d;
    d.curl.radius = c.r;
    d.curl.frequency = c.q;
    d.curl.start = 0.1;
    ASSERT_TRUE(apply(d, s).ok());
    const Strand out = strandOf(s, 0);
    EXPECT_EQ(out[0], Strand{straight(root, dir, 1, 0)}[0].cast<float>().cast<double>());
    // At least 12 points per turn: 3.6 q turns.
    EXPECT_GE(out.size(), size_t(12 * 3.6 * c.q));
    // An orthonormal basis across the axis.
    const V3 e1 = dir.unitOrthogonal(), e2 = dir.cross(e1);
    std::vector<double> t, ang;
    double radiusSum = 0;
    for (const V3& p : out) {
      const V3 rel = p - root;
      const double along = rel.dot(dir);
      if (along < 0.1 * 3.6 + 1e-3) continue;  // the ramp
      const V3 across = rel - along * dir;
      radiusSum += across.norm();
      EXPECT_NEAR(across.norm(), c.r, 0.05 * c.r);
      double a = std::atan2(across.dot(e2), across.dot(e1));
      if (!ang.empty())  // unwrap
        while (a - ang.back() > kPi) a -= 2 * kPi;
      if (!ang.empty())
        while (a - ang.back() < -kPi) a += 2 * kPi;
      t.push_back(along);
      ang.push_back(a);
    }
    ASSERT_GT(t.size(), 10u);
    EXPECT_NEAR(radiusSum / t.size(), c.r, 0.05 * c.r);
    // Least-squares slope of angle against arc length: 2 pi / pitch.
    double mt = 0, ma = 0;
    for (size_t i = 0; i < t.size(); ++i) mt += t[i] / t.size(), ma += ang[i] / t.size();
    double num = 0, den = 0;
    for (size_t i = 0; i < t.size(); ++i)
      num += (t[i] - mt) * (ang[i] - ma), den += (t[i] - mt) * (t[i] - mt);
    const double pitch = 2 * kPi / std::abs(num / den);
    EXPECT_NEAR(pitch, 1 / c.q, 0.05 / c.q);
    // Inside the ramp the curl is smaller than r.
    const V3 early = out[1] - root;
    EXPECT_LT((early - early.dot(dir) * dir).norm(), 0.5 * c.r);
  }
}

TEST(StrandDetail, CurlPhaseVariesByKeyWithinTheRandomOffset) {
  // Parallel straight strands share their frame, so the angle between two strands' curl offsets at
  // the same arc length is their phase difference: below randomOffset of a turn, 0 with offset 0.
  const V3 dir(0, 1, 0);
  std::vector<Strand> in;
  for (int k = 0; k < 20; ++k) in.push_back(straight(V3(0.5 * k, 0, 0), dir, 41, 0.05));
  for (double o : {0.0, 0.25}) {
    SCOPED_TRACE(testing::Message() << "randomOffset " << o);
    Strands s = makeStrands(in);
    DetailParams d;
    d.curl.radius = 0.1;
    d.curl.frequency = 1;
    d.curl.randomOffset = o;
    ASSERT_TRUE(apply(d, s).ok());
    double widest = 0;
    std::vector<V3> offsets;
    for (size_t k = 0; k < in.size(); ++k) {
      const Strand out = strandOf(s, k);
      const V3 rel = out.back() - in[k][0];
      offsets.push_back((rel - rel.dot(dir) * dir).normalized());
    }
    for (const V3& a : offsets)
      for (const V3& b : offsets)
        widest = std::max(widest, std::acos(std::min(1.0, a.dot(b))) / (2 * kPi));
    EXPECT_LE(widest, o + 1e-4);
    if (o > 0) EXPECT_GT(widest, 0.5 * o);  // 20 phases uniform in [0, o) spread out
  }
}

TEST(StrandDetail, ClumpFactorOneShapeZeroPutsEveryTipOnItsNearestGuide) {
  const std::vector<Strand> in = patch(10, 0.03, 30, 0.05);
  Strands s = makeStrands(in);
  DetailParams d;
  d.clump.factor = 1;
  d.clump.shape = 0;
  d.clump.guideDistance = 0.1;
  ASSERT_TRUE(apply(d, s).ok());
  const double g = 0.1;
  // Guides keep their shape; with distinct tilts no other strand ends unchanged.
  std::vector<size_t> guides;
  for (size_t k = 0; k < in.size(); ++k) {
    const Strand out = strandOf(s, k);
    ASSERT_EQ(out.size(), in[k].size());
    EXPECT_LT((out[0] - in[k][0]).norm(), 1e-6) << "root moved, strand " << k;
    if ((out.back() - in[k].back()).norm() < 1e-6) guides.push_back(k);
  }
  ASSERT_GE(guides.size(), 2u);
  ASSERT_LT(guides.size(), in.size() / 2);
  for (size_t a : guides)
    for (size_t b : guides)
      if (a < b) EXPECT_GE((in[a][0] - in[b][0]).norm(), g - 1e-6);
  for (size_t k = 0; k < in.size(); ++k) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t G : guides) best = std::min(best, (in[G][0] - in[k][0]).norm());
    EXPECT_LT(best, g) << "strand " << k << " has no guide within the guide distance";
    const V3 tip = strandOf(s, k).back();
    // the guide's point at the strand's own length (its tip when the strand is as long or
    // longer): the guides are straight, so that point is root + unit direction * length
    bool onNearest = false;
    const double L = (in[k].back() - in[k][0]).norm();
    for (size_t G : guides)
      if ((in[G][0] - in[k][0]).norm() < best + 1e-9) {
        const double LG = (in[G].back() - in[G][0]).norm();
        const V3 at = in[G][0] + (in[G].back() - in[G][0]).normalized() * std::min(L, LG);
        onNearest |= (tip - at).norm() < 1e-5;
      }
    EXPECT_TRUE(onNearest) << "strand " << k;
  }
}

TEST(StrandDetail, ClumpWithLinearShapeMovesHalfwayAtTheTip) {
  // Two parallel strands 0.05 apart: guide(x) - p(x) = the root offset D, so with f = 0.5 and
  // S = x the follower moves by 0.5 x D.
  const V3 D(0.05, 0, 0);
  const std::vector<Strand> in = {straight(V3(0, 0, 0), V3(0, 1, 0), 21, 0.05),
                                  straight(D, V3(0, 1, 0), 21, 0.05)};
  Strands s = makeStrands(in);
  DetailParams d;
  d.clump.factor = 0.5;
  d.clump.shape = 0.5;
  ASSERT_TRUE(apply(d, s).ok());
  const Strand a = strandOf(s, 0), b = strandOf(s, 1);
  const bool aGuide = (a.back() - in[0].back()).norm() < 1e-7;
  const Strand& follower = aGuide ? b : a;
  const Strand& orig = aGuide ? in[1] : in[0];
  const V3 towards = aGuide ? V3(-D) : D;
  EXPECT_LT(((aGuide ? a : b).back() - (aGuide ? in[0] : in[1]).back()).norm(), 1e-7);
  for (int i : {0, 10, 20}) {
    const double x = i / 20.0;
    EXPECT_LT((follower[i] - (orig[i] + 0.5 * x * towards)).norm(), 1e-6) << "point " << i;
  }
}

TEST(StrandDetail, LocksDrawShortHairInLessAndKeepItsLength) {
  // The linear shear above lengthens the follower: its tip moves f D sideways, so its length is
  // sqrt(1 + (0.05 f)^2) (hand-computed: the sheared line from the root to (f D, 1)), f = 0.5.
  // With locks, hair 10 cm long (a third of the 30 cm a strand needs to be drawn onto its lock in
  // full) moves a third as far, f = 0.5 / 3, and is cut back to length 1 with its point count,
  // its points along the sheared line.
  const V3 D(0.05, 0, 0);
  const std::vector<Strand> in = {straight(V3(0, 0, 0), V3(0, 1, 0), 21, 0.05),
                                  straight(D, V3(0, 1, 0), 21, 0.05)};
  DetailParams d;
  d.clump.factor = 0.5;
  d.clump.shape = 0.5;
  auto length = [](const Strand& p) {
    double l = 0;
    for (size_t i = 1; i < p.size(); ++i) l += (p[i] - p[i - 1]).norm();
    return l;
  };
  for (bool locks : {false, true}) {
    Strands s = makeStrands(in);
    ASSERT_TRUE(
        applyDetail({d}, {0, 0}, {0, 1}, 7, s, 255, nullptr, false, nullptr, nullptr, false, locks)
            .ok());
    const double f = locks ? 0.5 / 3 : 0.5;
    for (size_t k = 0; k < 2; ++k) {
      const Strand p = strandOf(s, k);
      ASSERT_EQ(p.size(), 21u);
      const bool guide = (p.back() - in[k].back()).norm() < 1e-7;
      if (guide) continue;
      const double want = locks ? 1.0 : std::sqrt(1 + 0.05 * f * 0.05 * f);
      EXPECT_NEAR(length(p), want, 1e-6) << (locks ? "locks" : "no locks");
      // on the sheared line from the root: x = root + f y (towards the guide)
      const double sx = (in[1 - k][0] - in[k][0]).x() * f;
      for (const V3& q : p) EXPECT_NEAR(q.x(), in[k][0].x() + sx * q.y(), 1e-6);
    }
  }
}

TEST(StrandDetail, TipSpreadOffsetsAcrossTheGuideGrowingToTheTip) {
  const std::vector<Strand> in = {straight(V3(0, 0, 0), V3(0, 1, 0), 21, 0.05),
                                  straight(V3(0.05, 0, 0), V3(0.1, 1, 0), 21, 0.05)};
  Strands s = makeStrands(in);
  DetailParams d;
  d.clump.factor = 1;
  d.clump.shape = 0;
  d.clump.tipSpread = 0.02;
  ASSERT_TRUE(apply(d, s).ok());
  const bool aGuide = (strandOf(s, 0).back() - in[0].back()).norm() < 1e-7;
  const Strand guide = aGuide ? in[0] : in[1], f = strandOf(s, aGuide ? 1 : 0);
  const V3 gdir = (guide.back() - guide[0]).normalized();
  for (int i : {10, 20}) {  // the follower's arc fraction i / 20 is the guide's point i
    const V3 off = f[i] - guide[i];
    EXPECT_NEAR(off.norm(), 0.02 * i / 20.0, 1e-6);
    EXPECT_NEAR(off.dot(gdir), 0, 1e-6);
  }
}

TEST(StrandDetail, NothingOnOrFrizzDistanceZeroLeavesStrandsBitIdentical) {
  std::vector<Strand> in = patch(4, 0.03, 25, 0.05);
  in.push_back(bent(V3(1, 0, 0), 40));
  in.push_back({V3(0.5, 0.5, 0.5)});  // one point
  in.push_back({});                   // no points
  const Strands before = makeStrands(in);
  DetailParams off;
  DetailParams zeroFrizz;
  zeroFrizz.frizz.distance = 0;
  zeroFrizz.frizz.shape = -0.3;
  zeroFrizz.curl.frequency = 5;  // radius 0: off
  zeroFrizz.clump.shape = 0;     // factor 0: off
  for (const DetailParams& d : {off, zeroFrizz}) {
    Strands s = before;
    ASSERT_TRUE(apply(d, s).ok());
    EXPECT_TRUE(sameBits(s, before));
  }
  // Off strands stay bit-identical beside strands whose detail is on (curl rebuilds the buffer).
  Strands s = before;
  const size_t n = strandCount(s);
  std::vector<uint32_t> groupOf(n, 0);
  for (size_t k = 0; k < n; k += 2) groupOf[k] = 1;
  ASSERT_TRUE(applyDetail({off, allOn()}, groupOf, iota(n), 3, s).ok());
  size_t changed = 0;
  for (size_t k = 0; k < n; ++k) {
    if (groupOf[k] == 0)
      EXPECT_EQ(strandOf(s, k), strandOf(before, k)) << "strand " << k;
    else
      changed += strandOf(s, k) != strandOf(before, k);
  }
  EXPECT_GE(changed, 8u);
  // A one-point strand with detail on is left as it is.
  Strands one = makeStrands({{V3(1, 2, 3)}});
  const Strands oneBefore = one;
  ASSERT_TRUE(apply(allOn(), one).ok());
  EXPECT_TRUE(sameBits(one, oneBefore));
}

TEST(StrandDetail, FrizzIsACumulativeOffsetWithThePinnedRoot) {
  const Strand in = bent(V3(0, 0, 0), 50);
  Strands s = makeStrands({in});
  DetailParams d;
  d.frizz.distance = 0.01;
  d.frizz.shape = 0;  // S = 1
  ASSERT_TRUE(apply(d, s).ok());
  const Strand out = strandOf(s, 0);
  ASSERT_EQ(out.size(), in.size());
  EXPECT_EQ(out[0], in[0].cast<float>().cast<double>());
  double moved = 0;
  for (size_t i = 1; i < in.size(); ++i) {
    const double off = (out[i] - in[i]).norm();
    EXPECT_LE(off, 0.01 * i + 1e-6);  // i unit-ball steps of size d
    moved = std::max(moved, off);
  }
  EXPECT_GT(moved, 0.01);  // a random walk of 49 steps leaves the first step's ball
  // Shape 0.5 (S = x): the point next to the root barely moves.
  Strands t = makeStrands({in});
  d.frizz.shape = 0.5;
  ASSERT_TRUE(apply(d, t).ok());
  EXPECT_LE((strandOf(t, 0)[1] - in[1]).norm(), 0.01 / 49 + 1e-6);
}

TEST(StrandDetail, SameSeedAndKeysGiveTheSameStrandsAnotherSeedOthers) {
  std::vector<Strand> in = patch(6, 0.04, 40, 0.06);
  in.push_back(bent(V3(0, 0, 1), 60));
  const Strands before = makeStrands(in);
  Strands a = before, b = before, c = before;
  ASSERT_TRUE(apply(allOn(), a, 11).ok());
  ASSERT_TRUE(apply(allOn(), b, 11).ok());
  ASSERT_TRUE(apply(allOn(), c, 12).ok());
  EXPECT_TRUE(sameBits(a, b));
  EXPECT_FALSE(sameBits(a, c));
  EXPECT_FALSE(sameBits(a, before));
}

TEST(StrandDetail, AStrandsKeyNotItsIndexDecidesItsDetail) {
  // Without clump (which depends on the neighbours present), a strand grown alone with its key
  // gets exactly the detail it gets among others, and another key gives it other detail: for each
  // random detail on its own and for all of them together.
  DetailParams jitter, curl, frizz, together = allOn();
  jitter.lengthJitter = 0.5;
  curl.curl.radius = 0.05;
  curl.curl.randomOffset = 1;
  frizz.frizz.distance = 0.01;
  together.clump.factor = 0;
  const std::vector<Strand> in = {bent(V3(0, 0, 0), 50), bent(V3(1, 0, 0), 45),
                                  straight(V3(2, 0, 0), V3(0, 1, 0.2), 55, 0.06)};
  for (const DetailParams& d : {jitter, curl, frizz, together}) {
    Strands all = makeStrands(in);
    ASSERT_TRUE(applyDetail({d}, {0, 0, 0}, {10, 20, 30}, 5, all).ok());
    Strands alone = makeStrands({in[2]});
    ASSERT_TRUE(applyDetail({d}, {0}, {30}, 5, alone).ok());
    EXPECT_EQ(strandOf(alone, 0), strandOf(all, 2));
    Strands otherKey = makeStrands({in[2]});
    ASSERT_TRUE(applyDetail({d}, {0}, {31}, 5, otherKey).ok());
    EXPECT_NE(strandOf(otherKey, 0), strandOf(all, 2));
  }
}

TEST(StrandDetail, NoStrandEndsWithMoreThanMaxPoints) {
  const Strand longIn = straight(V3(0, 0, 0), V3(0, 1, 0), 1000, 0.01);
  const std::vector<Strand> in = {longIn, bent(V3(1, 0, 0), 300), bent(V3(2, 0, 0), 60)};
  DetailParams curly;
  curly.curl.radius = 0.05;
  curly.curl.frequency = 10;  // 12 q L = 1200 points wanted on the long strand
  DetailParams frizzy;
  frizzy.frizz.distance = 0.01;
  for (const DetailParams& d : {DetailParams{}, curly, frizzy, allOn()}) {
    Strands s = makeStrands(in);
    ASSERT_TRUE(applyDetail({DetailParams{}, d}, {1, 1, 0}, iota(3), 1, s).ok());
    for (size_t k = 0; k < 3; ++k) EXPECT_LE(strandOf(s, k).size(), 255u) << "strand " << k;
    // The long strand keeps its root (and, without length jitter or detail, its tip).
    const Strand out = strandOf(s, 0);
    EXPECT_EQ(out[0], longIn[0]);
    if (!d.any()) {
      EXPECT_EQ(out.size(), 255u);
      EXPECT_LT((out.back() - longIn.back()).norm(), 1e-6);
      EXPECT_LT((out[127] - V3(0, 9.99 * 127 / 254, 0)).norm(), 1e-5);  // even by arc length
      EXPECT_EQ(strandOf(s, 2), strandOf(makeStrands(in), 2));          // off and short: untouched
    }
  }
  // Another cap.
  Strands s = makeStrands(in);
  ASSERT_TRUE(applyDetail({curly}, {0, 0, 0}, iota(3), 1, s, 50).ok());
  for (size_t k = 0; k < 3; ++k) EXPECT_LE(strandOf(s, k).size(), 50u);
}

TEST(StrandDetail, LengthJitterKeepsLengthsBetweenOneMinusJAndOneTimesTheLength) {
  for (double j : {0.6, 1.0}) {
    SCOPED_TRACE(testing::Message() << "j " << j);
    std::vector<Strand> in;
    for (int k = 0; k < 200; ++k)
      in.push_back(straight(V3(0.01 * k, 0, 0), V3(std::sin(k), 1, std::cos(k)), 41, 0.05));
    const double L = 2.0;
    Strands s = makeStrands(in);
    DetailParams d;
    d.lengthJitter = j;
    ASSERT_TRUE(apply(d, s).ok());
    double lo = L, hi = 0;
    for (size_t k = 0; k < in.size(); ++k) {
      const Strand out = strandOf(s, k);
      const double len = polyLength(out);
      EXPECT_GE(len, (1 - j) * L - 1e-5);
      EXPECT_LE(len, L + 1e-5);
      EXPECT_GT(len, 0);
      lo = std::min(lo, len);
      hi = std::max(hi, len);
      // The cut tip lies on the strand's line.
      const V3 dir = (in[k].back() - in[k][0]).normalized(), rel = out.back() - in[k][0];
      EXPECT_LT((rel - rel.dot(dir) * dir).norm(), 1e-5);
    }
    // 200 uniform draws cover the range.
    EXPECT_LT(lo, (1 - 0.9 * j) * L);
    EXPECT_GT(hi, (1 - 0.1 * j) * L);
  }
}

TEST(StrandDetail, AFlaggedStrandHasItsLengthAndNoFlyawayTheOthersTheirGroups) {
  // 200 strands 2 units long, length jitter 0.6 and every strand a flyaway: the even ones kept
  // (kCutAtLine | kLiesOnHead) end bit for bit as grown, the odd ones are cut and moved, as
  // without flags
  std::vector<Strand> in;
  for (int k = 0; k < 200; ++k)
    in.push_back(straight(V3(0.01 * k, 1, 0), V3(std::sin(k), 1, std::cos(k)), 41, 0.05));
  DetailParams d;
  d.lengthJitter = 0.6;
  d.flyaway.share = 1;
  d.flyaway.distance = 0.2;
  d.flyaway.start = 0.3;
  const size_t n = in.size();
  std::vector<uint8_t> flags(n, 0);
  for (size_t k = 0; k < n; k += 2) flags[k] = kCutAtLine | kLiesOnHead;
  const Strands grown = makeStrands(in);
  Strands kept = grown, plain = grown;
  const V3 centre(0, 0, 0);
  ASSERT_TRUE(applyDetail({d}, std::vector<uint32_t>(n, 0), iota(n), 7, kept, 255, nullptr, false,
                          &centre, &flags)
                  .ok());
  ASSERT_TRUE(
      applyDetail({d}, std::vector<uint32_t>(n, 0), iota(n), 7, plain, 255, nullptr, false, &centre)
          .ok());
  int cut = 0;
  for (size_t k = 0; k < n; ++k) {
    if (k % 2 == 0) {
      EXPECT_EQ(strandOf(kept, k), strandOf(grown, k)) << "strand " << k;
    } else {
      EXPECT_EQ(strandOf(kept, k), strandOf(plain, k)) << "strand " << k;
      cut += polyLength(strandOf(kept, k)) < 2.0 - 1e-3;
    }
  }
  EXPECT_GT(cut, 90);
  // flags of the wrong size is refused, strands untouched
  Strands bad = makeStrands(in);
  std::vector<uint8_t> shortFlags(n - 1, 0);
  EXPECT_FALSE(applyDetail({d}, std::vector<uint32_t>(n, 0), iota(n), 7, bad, 255, nullptr, false,
                           &centre, &shortFlags)
                   .ok());
  EXPECT_TRUE(sameBits(bad, makeStrands(in)));
}

TEST(StrandDetail, RejectsBadParametersNamingTheField) {
  struct Case {
    const char* field;
    double DetailParams::*scalar;  // lengthJitter
    double CurlParams::*curl;
    double ClumpParams::*clump;
    double FrizzParams::*frizz;
    std::vector<double> bad;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Case> cases = {
      {"curl.radius", nullptr, &CurlParams::radius, nullptr, nullptr, {-0.1, nan, inf}},
      {"curl.frequency", nullptr, &CurlParams::frequency, nullptr, nullptr, {-1, nan, inf}},
      {"curl.start", nullptr, &CurlParams::start, nullptr, nullptr, {-0.1, 1.5, nan}},
      {"curl.randomOffset", nullptr, &CurlParams::randomOffset, nullptr, nullptr, {-0.1, 2, nan}},
      {"clump.factor", nullptr, nullptr, &ClumpParams::factor, nullptr, {-0.1, 1.1, nan}},
      {"clump.shape", nullptr, nullptr, &ClumpParams::shape, nullptr, {-1.1, 1.1, nan}},
      {"clump.tipSpread", nullptr, nullptr, &ClumpParams::tipSpread, nullptr, {-0.1, nan, inf}},
      {"clump.guideDistance",
       nullptr,
       nullptr,
       &ClumpParams::guideDistance,
       nullptr,
       {-0.1, nan, inf}},
      {"frizz.distance", nullptr, nullptr, nullptr, &FrizzParams::distance, {-0.1, nan, inf}},
      {"frizz.shape", nullptr, nullptr, nullptr, &FrizzParams::shape, {-2, 2, nan}},
      {"lengthJitter", &DetailParams::lengthJitter, nullptr, nullptr, nullptr, {-0.1, 1.1, nan}},
  };
  const Strands before = makeStrands(patch(3, 0.05, 20, 0.05));
  for (const Case& c : cases)
    for (double v : c.bad) {
      DetailParams d = allOn();
      if (c.scalar) d.*c.scalar = v;
      if (c.curl) d.curl.*c.curl = v;
      if (c.clump) d.clump.*c.clump = v;
      if (c.frizz) d.frizz.*c.frizz = v;
      Strands s = before;
      // The bad set is group 1, used by no strand: it is refused all the same.
      const Status st = applyDetail({allOn(), d}, std::vector<uint32_t>(9, 0), iota(9), 1, s);
      EXPECT_EQ(st.code, StatusCode::InvalidInput) << c.field << " = " << v;
      EXPECT_NE(st.message.find(std::string("detail: ") + c.field + " must be"), std::string::npos)
          << st.message;
      EXPECT_TRUE(sameBits(s, before)) << c.field;
    }
  // The limits themselves are accepted.
  DetailParams edge = allOn();
  edge.clump.factor = 1;
  edge.clump.shape = -1;
  edge.frizz.shape = 1;
  edge.curl.start = 0;
  edge.curl.randomOffset = 1;
  edge.lengthJitter = 1;
  Strands s = before;
  EXPECT_TRUE(applyDetail({edge}, std::vector<uint32_t>(9, 0), iota(9), 1, s).ok());

  s = before;
  EXPECT_EQ(applyDetail({allOn()}, std::vector<uint32_t>(8, 0), iota(9), 1, s).code,
            StatusCode::InvalidInput);
  EXPECT_EQ(applyDetail({allOn()}, std::vector<uint32_t>(9, 0), iota(10), 1, s).code,
            StatusCode::InvalidInput);
  EXPECT_EQ(applyDetail({allOn()}, std::vector<uint32_t>(9, 1), iota(9), 1, s).code,
            StatusCode::InvalidInput);  // group out of range
  EXPECT_TRUE(sameBits(s, before));
}

TEST(StrandDetail, HundredThousandStrandsOfSixtyPointsPrintTheirTime) {
  // Roots 1 mm apart on a 317 x 317 patch, strands of 60 points 0.06 apart, gently bent.
  const int side = 317;
  std::vector<Strand> in;
  in.reserve(side * side);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const V3 root(0.01 * i, 0, 0.01 * j);
      Strand st(60);
      for (int k = 0; k < 60; ++k) {
        const double a = 0.01 * k * (1 + 0.001 * ((i * 7 + j * 3) % 17));
        st[k] = root + V3(0.6 * (1 - std::cos(a)), 0.06 * k, 0.1 * std::sin(a));
      }
      in.push_back(std::move(st));
    }
  const Strands base = makeStrands(in);
  const size_t n = in.size();
  DetailParams jitter, clump, curl, frizz;
  jitter.lengthJitter = 0.3;
  clump.clump.factor = 0.8;
  clump.clump.tipSpread = 0.02;
  curl.curl.radius = 0.05;
  curl.curl.frequency = 2;
  frizz.frizz.distance = 0.005;
  struct Run {
    const char* name;
    DetailParams d;
  };
  for (const Run& r : {Run{"length jitter", jitter}, Run{"clump", clump}, Run{"curl", curl},
                       Run{"frizz", frizz}, Run{"all", allOn()}}) {
    Strands s = base;
    const auto t0 = std::chrono::steady_clock::now();
    ASSERT_TRUE(applyDetail({r.d}, std::vector<uint32_t>(n, 0), iota(n), 1, s).ok());
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::printf("[ detail ] %zu strands x 60 points, %s: %.1f ms, %zu points out\n", n, r.name, ms,
                s.points.size() / 3);
    EXPECT_FALSE(sameBits(s, base));
  }
}

TEST(StrandDetail, ClumpNeverPullsAcrossAPartingNorStretchesStubble) {
  // Two strands 0.05 apart setting off in opposite directions (either side of a parting): each is
  // the other's nearest root, but neither takes the other as its guide.
  {
    const std::vector<Strand> in = {straight(V3(0, 0, 0), V3(1, 0.2, 0), 30, 0.05),
                                    straight(V3(0.05, 0, 0), V3(-1, 0.2, 0), 30, 0.05)};
    Strands s = makeStrands(in);
    DetailParams d;
    d.clump.factor = 1;
    d.clump.shape = 0;
    d.clump.guideDistance = 0.1;
    ASSERT_TRUE(apply(d, s).ok());
    for (size_t k = 0; k < in.size(); ++k)
      EXPECT_LT((strandOf(s, k).back() - in[k].back()).norm(), 1e-6) << k;  // float storage
  }
  // A 2-point stub (0.06 long) beside a 3-long guide going the same way: it joins the guide at
  // its own length (0.06 up the guide), not stretched towards the guide's far tip.
  {
    const std::vector<Strand> in = {straight(V3(0, 0, 0), V3(0, 1, 0), 61, 0.05),
                                    straight(V3(0.03, 0, 0), V3(0, 1, 0), 2, 0.06)};
    Strands s = makeStrands(in);
    DetailParams d;
    d.clump.factor = 1;
    d.clump.shape = 0;
    d.clump.guideDistance = 0.1;
    ASSERT_TRUE(apply(d, s).ok());
    const Strand a = strandOf(s, 0), b = strandOf(s, 1);
    // whichever is the guide keeps its shape; the other moves by at most 4 % of the gap
    const bool stubIsGuide = (b.back() - in[1].back()).norm() < 1e-6;
    if (!stubIsGuide) {
      EXPECT_LT((b.back() - V3(0, 0.06, 0)).norm(), 1e-6);  // hand value: the guide at s = 0.06
    } else {
      EXPECT_LT((a.back() - in[0].back()).norm(), 1e-6);  // a long strand is never pulled
    }                                                     // onto a short guide's tip far away
  }
}

TEST(StrandDetail, ClumpLeavesAStrandWhosePathPartsFromItsGuide) {
  // Two strands from neighbouring roots set off the same way, then one bends off: 1.5 apart at the
  // tips, more than max(1, 4 guide distances): the follower is left as it was, whichever is guide.
  Strand bent = straight(V3(0.03, 0, 0), V3(0, 1, 0), 15, 0.05);
  for (int i = 1; i <= 30; ++i) bent.push_back(bent.back() + V3(0.05, 0, 0));
  const std::vector<Strand> in = {straight(V3(0, 0, 0), V3(0, 1, 0), 30, 0.05), bent};
  Strands s = makeStrands(in);
  DetailParams d;
  d.clump.factor = 1;
  d.clump.shape = 0;
  d.clump.guideDistance = 0.1;
  ASSERT_TRUE(apply(d, s).ok());
  for (size_t k = 0; k < in.size(); ++k)
    for (size_t i = 0; i < in[k].size(); ++i)
      EXPECT_LT((strandOf(s, k)[i] - in[k][i]).norm(), 1e-6) << k << " " << i;
}

// Clump all (applyDetail's clumpAll): a follower whose nearest guide's path parts from its own is
// clumped to the next nearest guide whose path stays with it. Two bundles side by side, 1 cm a
// root: A hangs straight; B hangs beside it, then bends off sideways (1.5 apart at the tips). Off,
// B's strands whose nearest guide is in A stay as they grew (unclumped: with curls, each curled on
// its own); on, every strand that stays as it grew is a guide (pairwise a guide distance apart),
// and every B strand ends with the bent-off bundle, for every seed tried.
TEST(StrandDetail, ClumpAllTakesTheNextGuideWhosePathStaysWithTheStrand) {
  std::vector<Strand> in;
  for (int k = 0; k < 10; ++k) in.push_back(straight(V3(0.01 * k, 0, 0), V3(0, 1, 0), 45, 0.05));
  for (int k = 10; k < 20; ++k) {
    Strand b = straight(V3(0.01 * k, 0, 0), V3(0, 1, 0), 15, 0.05);
    for (int i = 1; i <= 30; ++i) b.push_back(b.back() + V3(0.05, 0, 0));
    in.push_back(b);
  }
  DetailParams d;
  d.clump.factor = 1;
  d.clump.shape = 0;
  d.clump.guideDistance = 0.06;
  const size_t n = in.size();
  int lonelyOff = 0;
  for (uint32_t seed = 1; seed <= 12; ++seed) {
    for (const bool all : {false, true}) {
      Strands s = makeStrands(in);
      ASSERT_TRUE(applyDetail({d}, std::vector<uint32_t>(n, 0), iota(n), seed, s, 255, nullptr,
                              false, nullptr, nullptr, all)
                      .ok());
      std::vector<size_t> kept;  // the strands that stayed as they grew
      for (size_t k = 0; k < n; ++k) {
        double moved = 0;
        for (size_t i = 0; i < in[k].size(); ++i)
          moved = std::max(moved, (strandOf(s, k)[i] - in[k][i]).norm());
        if (moved < 1e-6) kept.push_back(k);
        // a B strand ends with its bundle (bent off to x > 1), never pulled onto A's path
        if (k >= 10) EXPECT_GT(strandOf(s, k).back().x(), 1.0) << seed << " " << k;
      }
      bool closePair = false;  // two kept strands nearer than a guide distance: one is lone
      for (size_t a = 0; a < kept.size(); ++a)
        for (size_t b = a + 1; b < kept.size(); ++b)
          closePair |= (in[kept[a]][0] - in[kept[b]][0]).norm() < d.clump.guideDistance - 1e-9;
      if (all)
        EXPECT_FALSE(closePair) << "seed " << seed;
      else
        lonelyOff += closePair;
    }
  }
  EXPECT_GT(lonelyOff, 0);  // off, the measure sees the lone strands
}

// Finished edges' end spread: strands that grew to one line end over a band below it. Each kept
// length lies in [L - min(spread, 15 % L), L], the band is used (not all cut alike), a strand
// given no spread keeps every point bit for bit, and the same keys give the same cuts.
TEST(StrandDetail, EndSpreadCutsEndsOverABand) {
  const int n = 200;
  std::vector<Strand> list;
  for (int k = 0; k < n; ++k) list.push_back(straight(V3(0.01 * k, 0, 0), V3(0, -1, 0), 41, 0.05));
  list.push_back(straight(V3(0, 0, 1), V3(0, -1, 0), 3, 0.01));  // 2 cm: the 15 % cap governs
  const double L = 2.0, spread = 0.12;
  std::vector<float> spreadOf(n + 1, float(spread));
  spreadOf[0] = 0;  // strand 0 is kept as it grew
  Strands s = makeStrands(list), again = makeStrands(list);
  ASSERT_TRUE(applyDetail({DetailParams{}}, std::vector<uint32_t>(n + 1, 0), iota(n + 1), 9, s, 255,
                          &spreadOf)
                  .ok());
  ASSERT_TRUE(applyDetail({DetailParams{}}, std::vector<uint32_t>(n + 1, 0), iota(n + 1), 9, again,
                          255, &spreadOf)
                  .ok());
  EXPECT_TRUE(sameBits(s, again));
  EXPECT_EQ(strandOf(s, 0), strandOf(makeStrands(list), 0));
  double lo = L, hi = 0;
  for (int k = 1; k < n; ++k) {
    const double len = polyLength(strandOf(s, size_t(k)));
    EXPECT_LE(len, L + 1e-6);
    EXPECT_GE(len, L - spread - 1e-6);
    lo = std::min(lo, len);
    hi = std::max(hi, len);
  }
  EXPECT_GT(hi - lo, 0.8 * spread);  // 199 uniform draws span most of the band
  EXPECT_GE(polyLength(strandOf(s, size_t(n))), 0.02 * (1 - 0.15) - 1e-6);
  // a wrong-sized spread list is refused, strands untouched
  std::vector<float> shortList(3, 0.1f);
  Strands t = makeStrands(list);
  EXPECT_EQ(applyDetail({DetailParams{}}, std::vector<uint32_t>(n + 1, 0), iota(n + 1), 9, t, 255,
                        &shortList)
                .code,
            StatusCode::InvalidInput);
}

// 1 cm curls, 2 turns per 10 cm from the root, random phase, in clumps of 1.2 cm (factor 0.7).
DetailParams curlyClumps() {
  DetailParams d;
  d.curl.radius = 0.1;
  d.curl.frequency = 2;
  d.curl.start = 0;
  d.curl.randomOffset = 1;
  d.clump.factor = 0.7;
  d.clump.guideDistance = 0.12;
  return d;
}

// Ringlets: two strands 1 mm apart in one clump curl in phase with their guide when asked, so
// they wind round together; each at its own random phase they part by up to twice the radius (1 cm
// here). In phase, the hair that is not the guide winds at its own radius (the ringlet's × (1 ±
// 0.35)) and up to 0.05 of a turn off its phase: it keeps within 0.35 r + 1.35 r · 2π · 0.05 + 1 mm
// (the roots' distance) = 8 mm of the guide's path, 2.9 mm here.
TEST(StrandDetail, RingletsCurlAClumpInPhase) {
  const DetailParams d = curlyClumps();
  const std::vector<Strand> list = {straight(V3(0, 0, 0), V3(0, -1, 0), 41, 0.05),
                                    straight(V3(0.001, 0, 0), V3(0, -1, 0), 41, 0.05)};
  auto apart = [&](bool ringlets) {
    Strands s = makeStrands(list);
    EXPECT_TRUE(applyDetail({d}, {0, 0}, {3, 17}, 5, s, 255, nullptr, ringlets).ok());
    const Strand a = strandOf(s, 0), b = strandOf(s, 1);
    // the farthest a point of a lies from the polyline b
    double most = 0;
    for (const V3& p : a) {
      double best = std::numeric_limits<double>::infinity();
      for (size_t k = 0; k + 1 < b.size(); ++k) {
        const V3 e = b[k + 1] - b[k];
        const double t = std::clamp((p - b[k]).dot(e) / std::max(e.squaredNorm(), 1e-30), 0.0, 1.0);
        best = std::min(best, (b[k] + t * e - p).norm());
      }
      most = std::max(most, best);
    }
    return most;
  };
  EXPECT_LT(apart(true), 0.08);
  EXPECT_GT(apart(false), 0.05);
}

// A ringlet has a thickness: twenty strands with roots within 1 mm of each other (one clump, one
// ringlet) wind round at radii (the farthest each comes from the axis through the first root)
// that spread over more than 0.2 of the ringlet's radius, within its radius × (1 ± 0.35) and the
// roots' 1 mm; without ringlets each winds at the curl's radius (1 cm) about its own root.
TEST(StrandDetail, RingletsHaveAThicknessStrandByStrand) {
  const DetailParams d = curlyClumps();
  std::vector<Strand> list;
  for (int k = 0; k < 20; ++k) {
    const double a = 2.399963 * k, rho = 0.001 * std::sqrt((k + 0.5) / 20);  // a 1 mm disc
    list.push_back(straight(V3(rho * std::cos(a), 0, rho * std::sin(a)), V3(0, -1, 0), 41, 0.05));
  }
  std::vector<uint32_t> keys;
  for (uint32_t k = 0; k < 20; ++k) keys.push_back(7 + 13 * k);
  auto radii = [&](bool ringlets) {
    Strands s = makeStrands(list);
    EXPECT_TRUE(
        applyDetail({d}, std::vector<uint32_t>(20, 0), keys, 5, s, 255, nullptr, ringlets).ok());
    std::vector<double> r;
    for (size_t k = 0; k < 20; ++k) {
      double most = 0;
      for (const V3& p : strandOf(s, k)) most = std::max(most, std::hypot(p.x(), p.z()));
      r.push_back(most);
    }
    std::sort(r.begin(), r.end());
    return r;
  };
  const std::vector<double> plain = radii(false), ringlet = radii(true);
  EXPECT_LT(plain.back() - plain.front(), 0.0025);
  const double median = ringlet[10];
  EXPECT_GT(ringlet.back() - ringlet.front(), 0.2 * median);
  EXPECT_LT(ringlet.back(), 1.35 / 0.65 * ringlet.front() + 0.002);
}

// Eight straight strands 2 long hanging down, 0.5 apart along x, each its own clump, with `d`'s
// detail applied (as ringlets or not).
Strands eightClumps(const DetailParams& d, bool ringlets) {
  std::vector<Strand> list;
  for (int k = 0; k < 8; ++k) list.push_back(straight(V3(0.5 * k, 0, 0), V3(0, -1, 0), 41, 0.05));
  Strands s = makeStrands(list);
  EXPECT_TRUE(applyDetail({d}, std::vector<uint32_t>(8, 0), {3, 17, 29, 41, 53, 67, 79, 97}, 5, s,
                          255, nullptr, ringlets)
                  .ok());
  return s;
}

// Ringlets vary in size and winding, clump by clump: eight strands 0.5 apart (each its own
// clump) curl at exactly the radius asked without ringlets (each point's distance from the
// straight axis is r) and all wind the same way; with ringlets each clump's radius lies within
// r (1 ± 0.4), the radii differ by more than r / 4, and some wind each way (the sign of the turn of
// the point's offset from the axis, seen along the strand), so neighbouring ringlets do not line up
// in rows.
TEST(StrandDetail, RingletsVaryInSizeClumpByClump) {
  const DetailParams d = curlyClumps();
  auto radii = [&](bool ringlets) {
    const Strands s = eightClumps(d, ringlets);
    std::vector<double> r;
    int clockwise = 0;
    for (int k = 0; k < 8; ++k) {
      const Strand a = strandOf(s, size_t(k));
      double most = 0, turn = 0;
      for (size_t i = 0; i < a.size(); ++i) {
        const V3& p = a[i];
        most = std::max(most, std::hypot(p.x() - 0.5 * k, p.z()));
        if (i + 1 < a.size())
          turn += (p.x() - 0.5 * k) * a[i + 1].z() - p.z() * (a[i + 1].x() - 0.5 * k);
      }
      r.push_back(most);
      clockwise += turn > 0;
    }
    r.push_back(clockwise);
    return r;
  };
  std::vector<double> plain = radii(false);
  EXPECT_TRUE(plain.back() == 0 || plain.back() == 8) << plain.back() << " of 8 wind one way";
  plain.pop_back();
  for (double r : plain) EXPECT_NEAR(r, 0.1, 1e-3);
  std::vector<double> v = radii(true);
  EXPECT_GT(v.back(), 0);
  EXPECT_LT(v.back(), 8);
  v.pop_back();
  for (double r : v) {
    EXPECT_GE(r, 0.06 - 1e-3);
    EXPECT_LE(r, 0.14 + 1e-3);
  }
  EXPECT_GT(*std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end()), 0.025);
}

// Each ringlet's curl ramps in over its own share of the hair (the curl's start × (1 ± 0.5)),
// so the curls of neighbouring ringlets do not begin at one height: eight straight strands 2 long
// (each its own clump), curl start 0.3, ramped in by smoothstep(s / (start · L)), reach half their
// radius at s = start · L / 2 = 0.3 without ringlets, one height for all; with ringlets within
// 0.15 … 0.45, and spread over more than 0.08.
TEST(StrandDetail, RingletsStartTheirCurlAtTheirOwnHeight) {
  DetailParams d = curlyClumps();
  d.curl.start = 0.3;
  auto halfway = [&](bool ringlets) {
    const Strands s = eightClumps(d, ringlets);
    std::vector<double> at;
    for (int k = 0; k < 8; ++k) {
      const Strand a = strandOf(s, size_t(k));
      double most = 0;
      for (const V3& p : a) most = std::max(most, std::hypot(p.x() - 0.5 * k, p.z()));
      double depth = 0;
      for (const V3& p : a)
        if (std::hypot(p.x() - 0.5 * k, p.z()) >= 0.5 * most) {
          depth = -p.y();  // the straight strand's arc length there, near enough
          break;
        }
      at.push_back(depth);
    }
    return at;
  };
  auto spread = [](const std::vector<double>& v) {
    return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
  };
  const std::vector<double> plain = halfway(false), own = halfway(true);
  EXPECT_LT(spread(plain), 0.05);
  for (double y : own) {
    EXPECT_GE(y, 0.1);
    EXPECT_LE(y, 0.5);
  }
  EXPECT_GT(spread(own), 0.08);
}

}  // namespace strand_detail_test
