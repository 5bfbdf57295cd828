// Ties from any hand (gathered_tail.hpp "Ties"; the session's `ties` on): whole-section round
// tails, braids and buns on a unit-sphere head (no field: gatherTails lays every assigned strand
// anew from its root), measured against geometry computed here: a straight spine hanging from
// behind the head, so a point's arc along it is its drop below C1 and its radius its distance from
// the vertical line.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "braid_bun.hpp"
#include "gathered_tail.hpp"
#include "hand_strands.hpp"
#include "ponytail_constraints.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace tie_tails_test {

using namespace hairsketch;

namespace {

constexpr float kTieTestStep = 0.02f;
const Eigen::Vector3f kBand(0.f, 0.3f, -1.1f);  // C1's centre, behind the head

struct Head {
  std::vector<Eigen::Vector3f> roots;
  std::vector<uint32_t> key;
  Strands strands;  // each root with a point 1 mm out: combed strands are laid anew
};

// Roots every 6 degrees over the back and top of the unit sphere (y > 0, z < 0.3).
Head backOfHead() {
  Head h;
  h.strands.strandStart.push_back(0);
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 60; ++j) {
      const float th = 3.14159265f * (float(i) + 0.5f) / 30, ph = 3.14159265f * float(j) / 30;
      const Eigen::Vector3f p(std::sin(th) * std::cos(ph), std::cos(th),
                              std::sin(th) * std::sin(ph));
      if (p.y() <= 0 || p.z() >= 0.3f) continue;
      h.roots.push_back(p);
      h.key.push_back(uint32_t(h.key.size()));
      for (const Eigen::Vector3f& x : {p, Eigen::Vector3f(1.001f * p)})
        h.strands.points.insert(h.strands.points.end(), {x.x(), x.y(), x.z()});
      h.strands.strandStart.push_back(uint32_t(h.strands.points.size() / 3));
    }
  return h;
}

// A straight spine from the band down `length`, as gatheredTail would give a ponytail.
GatheredTail hanging(float length, TailShape shape, bool ties) {
  GatheredTail t;
  for (int i = 0; i <= 20; ++i)
    t.spine.push_back(kBand - Eigen::Vector3f(0, length * float(i) / 20, 0));
  t.radius.assign(t.spine.size(), 0.05f);
  t.axis = -Eigen::Vector3f::UnitY();
  t.out = -Eigen::Vector3f::UnitZ();
  t.shape = shape;
  t.section = true;
  t.anchor = Eigen::Vector3f(0, 0.3f, -0.954f);
  t.ties = ties;
  if (shape == TailShape::Braid) {
    t.braid.section = true;
    t.braidLength = length - float(t.braid.tailLength);
  }
  return t;
}

// Grows `h` into tail t; `every`: only every so many strands are the tie's (the share).
Strands grow(const Head& h, const GatheredTail& t, float maxLength, int every = 1,
             uint64_t seed = 7) {
  SectionGather g;
  g.assigned.assign(h.roots.size(), -1);
  for (size_t s = 0; s < h.roots.size(); s += size_t(every)) g.assigned[s] = 0;
  g.centre = Eigen::Vector3f::Zero();
  Strands out = h.strands;
  gatherTails({t}, h.roots, h.key, seed, kTieTestStep, 255, out, maxLength, &g);
  return out;
}

Eigen::Vector3f pointOf(const Strands& s, size_t p) {
  return Eigen::Vector3f(s.points[3 * p], s.points[3 * p + 1], s.points[3 * p + 2]);
}
float arcOf(const Eigen::Vector3f& x) { return kBand.y() - x.y(); }  // along the spine
float radiusOf(const Eigen::Vector3f& x) { return std::hypot(x.x(), x.z() - kBand.z()); }

// The distances from the axis of the tie's points with arc in [a, b): one per strand, its last
// (hair combed up from below the band passes the window on the scalp first).
std::vector<float> radiiAt(const Strands& s, float a, float b, int every = 1) {
  std::vector<float> r;
  for (size_t st = 0; st + 1 < s.strandStart.size(); st += size_t(every)) {
    float last = -1;
    for (uint32_t p = s.strandStart[st]; p < s.strandStart[st + 1]; ++p) {
      const Eigen::Vector3f x = pointOf(s, p);
      if (arcOf(x) >= a && arcOf(x) < b && radiusOf(x) < 0.6f) last = radiusOf(x);
    }
    if (last >= 0) r.push_back(last);
  }
  return r;
}
float rms(const std::vector<float>& v) {
  double a = 0;
  for (float x : v) a += double(x) * x;
  return v.empty() ? 0.f : float(std::sqrt(a / double(v.size())));
}
float percentile(std::vector<float> v, float q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(q * float(v.size())))];
}
Eigen::Vector3f tipOf(const Strands& s, size_t st) { return pointOf(s, s.strandStart[st + 1] - 1); }

TEST(TieTails, ARoundTailIsFullAtTheBandAndTapersToUnevenEnds) {
  const Head h = backOfHead();
  const float L = 4.f;  // a 40 cm spine, Max length 32 cm
  const Strands s = grow(h, hanging(L, TailShape::Round, true), 3.2f);
  // at the band: a uniform disc of the tie's radius (1.2 cm for the whole head): RMS r / sqrt 2
  const std::vector<float> band = radiiAt(s, 0.f, 0.02f);
  ASSERT_GT(band.size(), h.roots.size() * 9 / 10);
  EXPECT_NEAR(rms(band), kTieRadius / std::sqrt(2.f), 0.1f * kTieRadius);
  // the silhouette (95th percentile) near the end well inside the one at mid-length
  const float mid = percentile(radiiAt(s, 0.5f * L, 0.5f * L + 0.1f), 0.95f);
  const float end = percentile(radiiAt(s, 0.9f * L, 0.9f * L + 0.1f), 0.95f);
  EXPECT_NEAR(mid, kTailRadius, 0.25f * kTailRadius);
  EXPECT_LT(end, 0.7f * mid);
  // uneven ends: tips spread along the spine by more than 5 cm, the longest at its end
  std::vector<float> tips;
  for (size_t st = 0; st < h.roots.size(); ++st) tips.push_back(arcOf(tipOf(s, st)));
  const auto [lo, hi] = std::minmax_element(tips.begin(), tips.end());
  EXPECT_GT(*hi - *lo, 0.5f);
  EXPECT_NEAR(*hi, L, 0.2f);
  // the outer hair ends earlier: tips of strands seated outside (far at mid-length) end higher
  double outer = 0, inner = 0;
  int no = 0, ni = 0;
  for (size_t st = 0; st < h.roots.size(); ++st)
    for (uint32_t p = s.strandStart[st]; p < s.strandStart[st + 1]; ++p) {
      const Eigen::Vector3f x = pointOf(s, p);
      if (arcOf(x) < 0.5f * L) continue;
      const float r = radiusOf(x) / kTailRadius;
      if (r > 0.8f) outer += tips[st], ++no;
      if (r < 0.4f) inner += tips[st], ++ni;
      break;
    }
  ASSERT_GT(no, 10);
  ASSERT_GT(ni, 10);
  EXPECT_LT(outer / no + 0.3f, inner / ni);
}

TEST(TieTails, ATailsRadiusGrowsWithTheSquareRootOfItsShare) {
  const Head h = backOfHead();
  const GatheredTail t = hanging(4.f, TailShape::Round, true);
  const float whole = rms(radiiAt(grow(h, t, 3.2f), 1.5f, 1.6f));
  const float quarter = rms(radiiAt(grow(h, t, 3.2f, 4), 1.5f, 1.6f, 4));
  EXPECT_NEAR(quarter / whole, 0.5f, 0.06f);
  EXPECT_NEAR(whole * std::sqrt(2.f), kTailRadius, 0.25f * kTailRadius);
}

TEST(TieTails, ATieReachesItsSpinesEndWhateverMaxLength) {
  const Head h = backOfHead();
  const Eigen::Vector3f end = kBand - Eigen::Vector3f(0, 4.f, 0);
  for (TailShape shape : {TailShape::Round, TailShape::Braid}) {
    for (bool ties : {false, true}) {
      const Strands s = grow(h, hanging(4.f, shape, ties), 3.2f);
      float nearest = 1e9f, longest = 0;
      for (size_t st = 0; st < h.roots.size(); ++st) {
        nearest = std::min(nearest, (tipOf(s, st) - end).norm());
        float len = 0;
        for (uint32_t p = s.strandStart[st] + 1; p < s.strandStart[st + 1]; ++p)
          len += (pointOf(s, p) - pointOf(s, p - 1)).norm();
        longest = std::max(longest, len);
      }
      if (ties) {
        EXPECT_LT(nearest, 0.2f) << int(shape);
        EXPECT_GT(longest, 4.f) << int(shape);  // longer than Max length: the tail needs it
      } else {  // as before: the hair spends Max length reaching the tie and ends short
        EXPECT_GT(nearest, 0.5f) << int(shape);
        if (shape == TailShape::Round) EXPECT_LE(longest, 3.2f + 0.05f);
      }
    }
  }
}

// Segments of the combed hair (strands rooted 15 cm over the band, up to their seat) that leave the
// scalp steeper than 50 degrees: hair standing off the head where it is gathered.
int standingOff(const Head& h, const Strands& s) {
  int steep = 0;
  for (size_t st = 0; st < h.roots.size(); ++st) {
    if (h.roots[st].y() < kBand.y() + 0.15f) continue;  // nearer, hair goes straight in
    Eigen::Vector3f prev = pointOf(s, s.strandStart[st]);
    for (uint32_t p = s.strandStart[st] + 1; p < s.strandStart[st + 1]; ++p) {
      const Eigen::Vector3f x = pointOf(s, p), d = x - prev;
      if (std::abs(arcOf(x)) < 1e-4f) break;  // the seat, on C1's plane
      if (d.norm() > 1e-4f &&
          d.normalized().dot(x.normalized()) > std::sin(50.f * 3.14159265f / 180))
        ++steep;
      prev = x;
    }
  }
  return steep;
}

TEST(TieTails, TheCombedHairLiesSmoothlyIntoTheBand) {
  const Head h = backOfHead();
  for (TailShape shape : {TailShape::Round, TailShape::Braid}) {
    EXPECT_LT(standingOff(h, grow(h, hanging(4.f, shape, true), 3.2f)), int(h.roots.size()) / 100)
        << int(shape);
    // before: the hair turned straight up from the scalp to its seat
    EXPECT_GT(standingOff(h, grow(h, hanging(4.f, shape, false), 3.2f)), 50) << int(shape);
  }
}

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

TEST(TieTails, ABraidHasNoLedgeWhereTheHairMeetsIt) {
  const Head h = backOfHead();
  const float on = braidLedge(h, true), off = braidLedge(h, false);
  std::printf(
      "braid ledge (largest rise of the hair's surface off the head per cm near the "
      "gather): ties on %.1f cm, off %.1f cm\n",
      10 * on, 10 * off);
  EXPECT_LT(on, 0.1f);   // under 1 cm per cm: a slope, no step
  EXPECT_GT(off, 0.2f);  // the ledge the plait had: the measure sees it
}

TEST(TieTails, ABunIsACoilWithNoHoleOnTopAndItsTipsTuckedUnder) {
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

TEST(TieTails, TheSeedDecidesAndTiesOffLaysAsBefore) {
  const Head h = backOfHead();
  for (TailShape shape : {TailShape::Round, TailShape::Braid}) {
    const GatheredTail on = hanging(4.f, shape, true);
    const Strands a = grow(h, on, 3.2f), b = grow(h, on, 3.2f), c = grow(h, on, 3.2f, 1, 8);
    EXPECT_EQ(a.points, b.points);
    EXPECT_EQ(a.strandStart, b.strandStart);
    if (shape == TailShape::Round) EXPECT_NE(a.points, c.points);  // the ends are seeded
    // off: what the same tail without the flag's branches lays (the field `ties` is the only
    // difference), and different from on
    const Strands off = grow(h, hanging(4.f, shape, false), 3.2f);
    EXPECT_NE(off.points, a.points);
  }
}

TEST(TieTails, HairTheFieldBringsReachesTheSpinesEndAndKeepsItsPathAbove) {
  // a sheet of hair running to y = -1.5 (about 25 cm of it past C1) into a ponytail whose spine
  // hangs from the origin to y = -3 (30 cm); not a whole-section tie
  std::vector<double> spine;
  for (int i = 0; i <= 30; ++i) spine.insert(spine.end(), {0.0, -0.1 * i, 0.0});
  PonytailParams pp;
  pp.gather = 1;
  pp.circles.push_back({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, -1, 0), 0.15});
  pp.circles.push_back({Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(0, -1, 0), 0.15});
  for (bool ties : {false, true}) {
    GatheredTail t = gatheredTail(spine.data(), spine.size() / 3, pp);
    t.ties = ties;
    hand_strands::Hair h = hand_strands::sheet(-1.5f);
    const Strands before = h.strands;
    gatherTails({t}, h.roots, h.key, 7, hand_strands::kStep, 255, h.strands);
    float lowest = 0, highest = -10;
    for (size_t st = 0; st + 1 < h.strands.strandStart.size(); ++st) {
      const float* tip = &h.strands.points[3 * (h.strands.strandStart[st + 1] - 1)];
      lowest = std::min(lowest, tip[1]);
      highest = std::max(highest, tip[1]);
      // above C1's plane the path is the field's, bit for bit
      const uint32_t a0 = before.strandStart[st], a1 = h.strands.strandStart[st];
      for (uint32_t p = 0; before.points[3 * (a0 + p) + 1] > 0; ++p)
        ASSERT_EQ(h.strands.points[3 * (a1 + p) + 1], before.points[3 * (a0 + p) + 1]);
    }
    if (ties) {
      EXPECT_LT(lowest, -3.f + 0.2f);     // to the spine's end, past the hair's own length
      EXPECT_GT(highest, lowest + 0.5f);  // uneven ends
    } else {
      EXPECT_GT(lowest, -1.5f - 0.1f);  // as before: its own length
    }
  }
}

}  // namespace
}  // namespace tie_tails_test
