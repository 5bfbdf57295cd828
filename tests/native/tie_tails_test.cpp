// Ties from any hand (gathered_tail.hpp "Ties"; the session's `ties` on): round tails that taper
// to uneven ends, hair as long as its tie needs, combed hair lying into the band, seeded, on the
// sphere head of tie_scene.hpp (whole-section ties) and a hand-made sheet (hair the field brings),
// measured against geometry computed here.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "braid_bun.hpp"
#include "gathered_tail.hpp"
#include "hand_strands.hpp"
#include "ponytail_constraints.hpp"
#include "tie_scene.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace tie_tails_test {

using namespace hairsketch;
using namespace tie_scene;

namespace {

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

TEST(TieTails, DrawnCirclesWidenTheTailBelowTheBandNotTheBand) {
  // a straight spine, 1 cm a point; the whole head (share 1): tie 1.2 cm, body 2 cm
  const auto sized = [](float drawn) {
    GatheredTail t;
    t.shape = TailShape::Round;
    t.ties = true;
    for (int i = 0; i <= 10; ++i) t.spine.emplace_back(0.f, -0.1f * float(i), 0.f);
    t.radius.assign(t.spine.size(), drawn);
    sizeTie(t, 1.f, 3.f);
    return t.radius;
  };
  const auto ss = [](float x) {
    const float c = std::clamp(x, 0.f, 1.f);
    return c * c * (3 - 2 * c);
  };
  const float tie = kTieRadius, body = kTailRadius;
  // profiles 3 cm round the spine: the band is the tie's (not 3 cm), 3 cm from kTailBlend on
  const std::vector<float> wide = sized(0.3f);
  EXPECT_NEAR(wide[0], std::max(tie, kBandDrawnRadius), 1e-6f);
  for (size_t i = 0; i < wide.size(); ++i) {
    const float f = ss(0.1f * float(i) / kTailBlend);
    const float band = std::max(tie, kBandDrawnRadius);
    const float want = std::max(std::min(0.3f, band + (0.3f - band) * f), tie + (body - tie) * f);
    EXPECT_NEAR(wide[i], want, 1e-6f) << i;
  }
  EXPECT_NEAR(wide.back(), 0.3f, 1e-6f);
  // a one-stroke ponytail (8 mm drawn): as before, the larger of the drawn and the hair's
  const std::vector<float> one = sized(0.08f);
  for (size_t i = 0; i < one.size(); ++i)
    EXPECT_NEAR(one[i], std::max(0.08f, tie + (body - tie) * ss(0.1f * float(i) / kTailBlend)),
                1e-6f)
        << i;
}

// Tie volume (the session's tieVolume): a whole section's tail hangs kTieVolume times as wide,
// its band as before, and its bun's rope is as much thicker; a braid keeps its width.
TEST(TieTails, TieVolumeHoldsAWholeSectionHalfAsWideAgain) {
  const auto sized = [](TailShape shape, bool volume) {
    GatheredTail t;
    t.shape = shape;
    t.ties = true;
    t.tieVolume = volume;
    for (int i = 0; i <= 10; ++i) t.spine.emplace_back(0.f, -0.1f * float(i), 0.f);
    t.radius.assign(t.spine.size(), 0.08f);  // a one-stroke ponytail
    t.braid.width = 0.1;
    sizeTie(t, 1.f, 3.f);
    return t;
  };
  // round: 1.2 cm at the band either way; 2 cm below it before, 3 cm with tie volume
  const GatheredTail off = sized(TailShape::Round, false), on = sized(TailShape::Round, true);
  EXPECT_NEAR(on.radius[0], off.radius[0], 1e-6f);
  EXPECT_NEAR(off.radius.back(), 0.2f, 1e-6f);
  EXPECT_NEAR(on.radius.back(), 0.3f, 1e-6f);
  // braid: three times the body, 6 cm, either way
  EXPECT_NEAR(sized(TailShape::Braid, false).braid.width, 0.6, 1e-6);
  EXPECT_NEAR(sized(TailShape::Braid, true).braid.width, 0.6, 1e-6);
  // bun: its rope is kBunRopeFill times the body, R = rr (kBunRopePitch K + 2) whatever K its
  // length allows
  for (const bool volume : {false, true}) {
    const GatheredTail b = sized(TailShape::Bun, volume);
    const float rr = kBunRopeFill * (volume ? 0.3f : 0.2f);
    EXPECT_NEAR(b.bunRadius, rr * (kBunRopePitch * float(b.bun.turns) + 2), 1e-5f) << volume;
  }
  EXPECT_GT(sized(TailShape::Bun, true).bunRadius, 1.2f * sized(TailShape::Bun, false).bunRadius);
  // and the hair laid: its spread below the band, half as wide again
  const Head h = backOfHead();
  GatheredTail t = hanging(4.f, TailShape::Round, true);
  const float before = rms(radiiAt(grow(h, t, 3.2f), 1.5f, 1.6f));
  t.tieVolume = true;
  const float after = rms(radiiAt(grow(h, t, 3.2f), 1.5f, 1.6f));
  EXPECT_NEAR(after / before, kTieVolume, 0.1f);
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
      EXPECT_GT(highest, lowest + 0.3f);  // uneven ends (3 cm and more apart)
    } else {
      EXPECT_GT(lowest, -1.5f - 0.1f);  // as before: its own length
    }
  }
}

// Gathered hair is combed over the head, never down the face: forehead hair gathered into a tie
// low behind the nape (ties on) goes over the crown; the old layout (ties off) took the short way
// down the face and under the chin.
TEST(TieTails, HairGatheredLowIsCombedOverTheCrownNotDownTheFace) {
  Head h;
  h.strands.strandStart.push_back(0);
  for (int j = -5; j <= 5; ++j) {
    const float ph = 0.08f * float(j);
    const Eigen::Vector3f p(0.5f * std::sin(ph), 0.5f, 0.866f * std::cos(ph));
    const Eigen::Vector3f r = p.normalized();
    h.roots.push_back(r);
    h.key.push_back(uint32_t(h.key.size()));
    for (const Eigen::Vector3f& x : {r, Eigen::Vector3f(1.001f * r)})
      h.strands.points.insert(h.strands.points.end(), {x.x(), x.y(), x.z()});
    h.strands.strandStart.push_back(uint32_t(h.strands.points.size() / 3));
  }
  auto low = [](bool ties) {
    GatheredTail t = hanging(1.0f, TailShape::Round, ties);
    const Eigen::Vector3f band(0.f, -0.75f, -0.8f);
    for (Eigen::Vector3f& x : t.spine) x += band - kBand;
    t.anchor = band.normalized();
    return t;
  };
  // the lowest point of the hair in front of the head's centre (z > 0.3): the forehead's own
  // height when it goes over the crown
  auto lowestInFront = [](const Strands& s) {
    float y = 1e9f;
    for (size_t p = 0; p < s.points.size() / 3; ++p) {
      const Eigen::Vector3f x = pointOf(s, p);
      if (x.z() > 0.3f) y = std::min(y, x.y());
    }
    return y;
  };
  const float on = lowestInFront(grow(h, low(true), 4.f)),
              off = lowestInFront(grow(h, low(false), 4.f));
  std::printf(
      "[ties] forehead hair into a tie low at the nape: lowest in front y = %.2f (on), %.2f "
      "(off)\n",
      on, off);
  EXPECT_GT(on, 0.4f);   // no lower than the roots (y 0.5 at the hairline, 1 mm off)
  EXPECT_LT(off, 0.0f);  // before: down the face
}

// A pigtail's hair from the forehead by the parting goes back over the side of the head to its
// band low behind the ear, not across the temple at the eye's height (fresh eyes' pigtails: a
// strap from the parting to the outer corner of the eye). The band behind the +x ear, below the
// centre; roots along the front hairline on the +x side of a centre parting.
TEST(TieTails, AForeheadRootIsCombedBackOverTheSideToABandBehindTheEar) {
  Head h;
  h.strands.strandStart.push_back(0);
  for (int j = 0; j <= 6; ++j) {
    const float ph = 0.03f + 0.07f * float(j);
    const Eigen::Vector3f r =
        Eigen::Vector3f(0.5f * std::sin(ph), 0.5f, 0.866f * std::cos(ph)).normalized();
    h.roots.push_back(r);
    h.key.push_back(uint32_t(h.key.size()));
    for (const Eigen::Vector3f& x : {r, Eigen::Vector3f(1.001f * r)})
      h.strands.points.insert(h.strands.points.end(), {x.x(), x.y(), x.z()});
    h.strands.strandStart.push_back(uint32_t(h.strands.points.size() / 3));
  }
  GatheredTail t = hanging(1.0f, TailShape::Round, true);
  const Eigen::Vector3f band = Eigen::Vector3f(0.8f, -0.35f, -0.45f).normalized() * 1.05f;
  for (Eigen::Vector3f& x : t.spine) x += band - kBand;
  t.anchor = band.normalized();
  const Strands s = grow(h, t, 4.f);
  // in front of the ear (z > 0.2) the hair stays at the roots' height or above: the short way
  // (a great circle from the hairline to the band) passes z 0.4 at y 0.15, beside the eye
  float lowest = 1e9f;
  int inFront = 0;
  for (size_t p = 0; p < s.points.size() / 3; ++p) {
    const Eigen::Vector3f x = pointOf(s, p);
    if (x.z() > 0.2f) lowest = std::min(lowest, x.y()), ++inFront;
  }
  std::printf("[ties] forehead hair into a band behind the ear: lowest in front y = %.2f\n",
              lowest);
  ASSERT_GT(inFront, 0);
  EXPECT_GT(lowest, 0.4f);
  // and it reaches its band: every tip past the band's plane, below the roots
  for (size_t st = 0; st < h.roots.size(); ++st) EXPECT_LT(tipOf(s, st).y(), 0.f);
}

// The growth says how wide a round tail's hair is at its band (its band hugs that): the tie's
// radius for the hair it holds, and every laid strand passes the band's plane within it.
TEST(TieTails, TheBandRadiusIsTheHairsRadiusAtTheTie) {
  const Head h = backOfHead();
  SectionGather g;
  g.assigned.assign(h.roots.size(), 0);
  g.centre = Eigen::Vector3f::Zero();
  Strands out = h.strands;
  const TailStats st = gatherTails({hanging(2.f, TailShape::Round, true)}, h.roots, h.key, 7,
                                   kTieTestStep, 255, out, 4.f, &g);
  ASSERT_EQ(st.bandRadius.size(), 1u);
  EXPECT_NEAR(st.bandRadius[0], kTieRadius, 1e-4f);  // the whole head's hair: share 1
  const std::vector<float> r = radiiAt(out, 0.f, 0.02f);
  ASSERT_FALSE(r.empty());
  EXPECT_LE(percentile(r, 0.99f), st.bandRadius[0] + 0.01f);
  const TailStats braid = gatherTails({hanging(2.f, TailShape::Braid, true)}, h.roots, h.key, 7,
                                      kTieTestStep, 255, out = h.strands, 4.f, &g);
  EXPECT_EQ(braid.bandRadius[0], 0.f);
}

}  // namespace
}  // namespace tie_tails_test
