// The shape rules (hair_fall.hpp ShapeRules): length from the strokes around against a
// hand-computed blend, and growth on a sphere head measured against the sphere's exact distance
// (|p| - r): hair laid on the head at its standoff, hair a lifted stroke governs left to it, hair
// below the widest part hanging, and the rules off giving the same bytes as before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "box_grid.hpp"
#include "hair_fall.hpp"
#include "head_distance.hpp"
#include "sphere_mesh.hpp"
#include "strand_growth.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace shape_rules_test {

using namespace hairsketch;

namespace {

constexpr float kRadius = 1.0f;

using hairsketch_test::boxGrid;

// A sphere head whose scalp is the part above y = scalpAbove.
struct SphereHead {
  hairsketch_test::Mesh mesh = hairsketch_test::uvSphere(0, 0, 0, kRadius, 48, 96);
  HeadDistance distance;
  explicit SphereHead(double scalpAbove = -0.6) {
    hairsketch_test::markScalpAbove(mesh, scalpAbove);
    const HeadMeshView view{mesh.positions.data(), mesh.positions.size() / 3, mesh.indices.data(),
                            mesh.indices.size() / 3, mesh.scalp.data()};
    EXPECT_TRUE(distance.build(view).ok());
  }
};

// The reach of one stroke off the head along +x at the crown's side, from (0.7, 0.7, 0) in ten
// steps of (dx, -0.045, 0), each point's lift its exact distance off the sphere; lift gets them.
CurveReach crownSideStroke(const Grid& g, double dx, std::vector<float>& lift) {
  std::vector<double> pts;
  lift.clear();
  for (int k = 0; k <= 10; ++k) {
    const double x = 0.7 + dx * k, y = 0.7 - 0.045 * k;
    pts.insert(pts.end(), {x, y, 0});
    lift.push_back(float(std::hypot(x, y) - kRadius));
  }
  ReachCurve c;
  c.points = pts.data();
  c.count = 11;
  c.setsLength = true;
  c.lift = lift.data();
  CurveReach reach;
  buildCurveReach(g, {c}, reach);
  return reach;
}

// A constant field: every strand is pushed along v wherever it is.
std::vector<float> constantField(const Grid& g, float x, float y, float z) {
  std::vector<float> f(size_t(g.size()) * 3);
  for (size_t p = 0; p < size_t(g.size()); ++p) {
    f[3 * p] = x;
    f[3 * p + 1] = y;
    f[3 * p + 2] = z;
  }
  return f;
}

// The sphere's exact distance of every point of strand s over its first `within` world units.
std::vector<float> standOff(const Strands& st, size_t s, float within) {
  std::vector<float> d;
  float len = 0;
  for (uint32_t p = st.strandStart[s] + 1; p < st.strandStart[s + 1] && len < within; ++p) {
    const float* q = &st.points[3 * size_t(p)];
    len += std::sqrt((q[0] - q[-3]) * (q[0] - q[-3]) + (q[1] - q[-2]) * (q[1] - q[-2]) +
                     (q[2] - q[-1]) * (q[2] - q[-1]));
    d.push_back(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]) - kRadius);
  }
  return d;
}

float median(std::vector<float> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? NAN : v[v.size() / 2];
}

// Roots on the sphere at polar angle theta (radians from +y), n of them over the front third of
// the circle round the axis (azimuth within 60 degrees of +z).
std::vector<Eigen::Vector3f> ring(float theta, int n) {
  std::vector<Eigen::Vector3f> r;
  for (int k = 0; k < n; ++k) {
    const float phi = 2.0943951f * (float(k) / float(n - 1) - 0.5f);
    r.emplace_back(kRadius * std::sin(theta) * std::sin(phi), kRadius * std::cos(theta),
                   kRadius * std::sin(theta) * std::cos(phi));
  }
  return r;
}

}  // namespace

TEST(LengthAround, ShepardBlendOfTheStrokesLengthsCappedByTheMaximum) {
  const std::vector<StrokeLength> strokes = {{0, 1, 0, 0.7f, false}, {1, 0, 0, 2.0f, false}};
  const float p[3] = {0.3f, 0.8f, 0};
  // by hand: weights 1 / (d^2 + 1e-4)
  const double d1 = 0.3 * 0.3 + 0.2 * 0.2, d2 = 0.7 * 0.7 + 0.8 * 0.8;
  const double w1 = 1 / (d1 + 1e-4), w2 = 1 / (d2 + 1e-4);
  EXPECT_NEAR(lengthAround(strokes, p, 5.f), (w1 * 0.7 + w2 * 2.0) / (w1 + w2), 1e-5);
  // capped by the maximum, each stroke's length too
  EXPECT_NEAR(lengthAround(strokes, p, 1.f), (w1 * 0.7 + w2 * 1.0) / (w1 + w2), 1e-5);
  // a stroke whose hair grows on counts as the maximum
  const std::vector<StrokeLength> on = {{0, 1, 0, 0.7f, true}, {1, 0, 0, 2.0f, false}};
  EXPECT_NEAR(lengthAround(on, p, 3.f), (w1 * 3.0 + w2 * 2.0) / (w1 + w2), 1e-5);
  // at a stroke's root, its own length; with no stroke, the maximum
  const float at[3] = {1, 0, 0};
  EXPECT_NEAR(lengthAround(strokes, at, 5.f), 2.0, 1e-3);
  EXPECT_EQ(lengthAround({}, p, 4.f), 4.f);
  // a stroke that combs (ends on the scalp) counts only when every stroke combs: beside a stroke
  // that ends hair it says nothing of the length; alone (a short slicked back) its own length
  const std::vector<StrokeLength> sweep = {{0, 1, 0, 0.7f, false, true}, {1, 0, 0, 2.0f, false}};
  EXPECT_NEAR(lengthAround(sweep, p, 5.f), 2.0, 1e-6);
  const std::vector<StrokeLength> combs = {{0, 1, 0, 0.7f, false, true},
                                           {1, 0, 0, 2.0f, false, true}};
  EXPECT_NEAR(lengthAround(combs, p, 5.f), (w1 * 0.7 + w2 * 2.0) / (w1 + w2), 1e-5);
}

TEST(HemAround, TheHeightWhereStrokesDrawnDownEndBlendedOverTheScalp) {
  // {x, y, z, length, growsOn, combs, end x, y, z}: two strokes drawn down 4 and 3 units, a spike
  const StrokeLength down1{0, 1, 0, 4.f, false, false, 0, -3.f, 0};
  const StrokeLength down2{1, 0, 0, 3.f, false, false, 1, -3.5f, 0};
  const StrokeLength spike{0, 0, 1, 0.5f, false, false, 0, 0.4f, 1.2f};
  const float p[3] = {0.3f, 0.8f, 0};
  // by hand: weights 1 / (d^2 + 1e-4), the hem is the ends' heights blended
  const double d1 = 0.3 * 0.3 + 0.2 * 0.2, d2 = 0.7 * 0.7 + 0.8 * 0.8;
  const double w1 = 1 / (d1 + 1e-4), w2 = 1 / (d2 + 1e-4);
  EXPECT_NEAR(hemAround({down1, down2}, p), (w1 * -3.0 + w2 * -3.5) / (w1 + w2), 1e-5);
  // at a stroke's root, where it ends
  const float at[3] = {1, 0, 0};
  EXPECT_NEAR(hemAround({down1, down2}, at), -3.5, 1e-3);
  // beside a spike (it ends above where it starts) there is no hem; where the strokes drawn down
  // hold a share between kHemShareFrom and kHemShareTo of the weight, it sinks
  const float bySpike[3] = {0, 0, 0.9f};
  EXPECT_EQ(hemAround({down1, spike}, bySpike), -std::numeric_limits<float>::infinity());
  const float between[3] = {0, 0.55f, 0.45f};
  const double wa = 1 / (2 * 0.45 * 0.45 + 1e-4), wb = 1 / (2 * 0.55 * 0.55 + 1e-4);
  const double share = wa / (wa + wb);  // down1 is the nearer: (0,1,0) vs the spike (0,0,1)
  ASSERT_GT(share, kHemShareFrom);
  ASSERT_LT(share, kHemShareTo);
  const double t = (share - kHemShareFrom) / (kHemShareTo - kHemShareFrom);
  EXPECT_NEAR(hemAround({down1, spike}, between), -3.0 - (1 - t * t * (3 - 2 * t)) * kHemFade,
              1e-4);
  // a stroke that ends a little below its start (a fringe), one whose hair grows on, strokes
  // that comb: no hem
  const StrokeLength fringe{0, 1, 0, 1.2f, false, false, 0, 1 - 0.5f * kHemDrop, 0};
  const StrokeLength grows{0, 1, 0, 4.f, true, false, 0, -3.f, 0};
  const StrokeLength combs{0, 1, 0, 4.f, false, true, 0, -3.f, 0};
  // a stroke drawn down far across the head from the root (a sweep down the front, hair at
  // the back): past kHemFar, no hem; at kHemNear, all of it
  const StrokeLength across{0, 1, 0, 4.f, false, false, 0.3f + kHemFar + 0.01f, -3.f, 0};
  for (const StrokeLength& c : {fringe, grows, combs, across})
    EXPECT_EQ(hemAround({c}, p), -std::numeric_limits<float>::infinity());
  EXPECT_EQ(hemAround({}, p), -std::numeric_limits<float>::infinity());
  const StrokeLength beside{0, 1, 0, 4.f, false, false, 0.3f + kHemNear - 0.01f, -3.f, 0};
  EXPECT_NEAR(hemAround({beside}, p), -3.0, 1e-5);
}

TEST(ShapeGrowth, HairNoStrokeGovernsLiesOnTheHeadAtItsStandoff) {
  const SphereHead head;
  const Grid g = boxGrid(41, -2, 2);
  // a field straight along +z: on the front of the crown it leaves the sphere at once
  const std::vector<float> field = constantField(g, 0, 0, 1);
  const std::vector<Eigen::Vector3f> roots = ring(0.35f, 24);
  GrowthParams gp;
  gp.maxLength = 0.6;
  Strands off, on, lifted;
  ASSERT_TRUE(growStrands(g, field, roots, gp, off, 1 << 20, &head.distance).ok());
  ShapeRules rules;
  rules.on = true;
  ASSERT_TRUE(
      growStrands(g, field, roots, gp, on, 1 << 20, &head.distance, nullptr, BodyCollider(), &rules)
          .ok());
  rules.volume = 0.15f;
  ASSERT_TRUE(growStrands(g, field, roots, gp, lifted, 1 << 20, &head.distance, nullptr,
                          BodyCollider(), &rules)
                  .ok());
  std::vector<float> dOff, dOn, dLift;
  for (size_t s = 0; s < roots.size(); ++s) {
    for (float d : standOff(off, s, 0.3f)) dOff.push_back(d);
    for (float d : standOff(on, s, 0.3f)) dOn.push_back(d);
    // past the rise (volume / kVolumeRise = 0.3), at its standoff
    const std::vector<float> all = standOff(lifted, s, 0.6f);
    dLift.insert(dLift.end(), all.begin() + std::ptrdiff_t(all.size() * 2 / 3), all.end());
  }
  // without the rules the field takes the hair off the head; with them it lies at the margin
  EXPECT_GT(median(dOff), 0.05f);
  EXPECT_LT(median(dOn), float(gp.margin) + 0.01f) << median(dOn);
  EXPECT_GT(median(dOn), float(gp.margin) - 0.01f);
  // with volume, at margin + volume
  EXPECT_NEAR(median(dLift), float(gp.margin) + 0.15f, 0.02f);
}

// A curve's own Volume: the hair rooted near it stands off its volume farther (past the rise),
// the hair 6+ cm away as with the session's (0 here), and without the curve's Volume the hair
// near it lies as the rest does.
TEST(ShapeGrowth, ACurvesOwnVolumeLiftsTheHairAroundItOnly) {
  const SphereHead head;
  const Grid g = boxGrid(41, -2, 2);
  const std::vector<float> field = constantField(g, 0, 0, 1);
  const std::vector<Eigen::Vector3f> roots = ring(0.8f, 25);
  // a stroke lying on the sphere at azimuth -55 degrees, from polar angle 0.3 to 1.1
  std::vector<double> pts;
  for (int k = 0; k <= 16; ++k) {
    const double t = 0.3 + 0.05 * k, a = -0.96;
    pts.insert(pts.end(), {std::sin(t) * std::sin(a), std::cos(t), std::sin(t) * std::cos(a)});
  }
  GrowthParams gp;
  gp.maxLength = 0.6;
  ShapeRules rules;
  rules.on = true;
  auto grow = [&](float volume) {
    ReachCurve rc;
    rc.points = pts.data();
    rc.count = pts.size() / 3;
    rc.growsOn = true;
    rc.volume = volume;
    CurveReach reach;
    buildCurveReach(g, {rc}, reach);
    EXPECT_EQ(reach.ownVolume.empty(), volume < 0);
    Strands st;
    EXPECT_TRUE(growStrands(g, field, roots, gp, st, 1 << 20, &head.distance, &reach,
                            BodyCollider(), &rules)
                    .ok());
    // past the rise, by the root's distance from the stroke's nearest point
    std::vector<float> nearD, farD;
    for (size_t s = 0; s < roots.size(); ++s) {
      double best = 1e9;
      for (size_t k = 0; k < rc.count; ++k)
        best = std::min(best, (roots[s].cast<double>() -
                               Eigen::Vector3d(pts[3 * k], pts[3 * k + 1], pts[3 * k + 2]))
                                  .norm());
      const std::vector<float> all = standOff(st, s, 0.6f);
      std::vector<float>& into = best < 0.15 ? nearD : best > 0.65 ? farD : nearD;
      if (best >= 0.15 && best <= 0.65) continue;
      into.insert(into.end(), all.begin() + std::ptrdiff_t(all.size() * 2 / 3), all.end());
    }
    EXPECT_FALSE(nearD.empty());
    EXPECT_FALSE(farD.empty());
    return std::make_pair(median(nearD), median(farD));
  };
  // (all at the margin plus the layering kLayerSlope adds over the head: compared with each
  // other)
  const auto [nearOwn, farOwn] = grow(0.15f);
  const auto [nearNone, farNone] = grow(-1.f);
  EXPECT_NEAR(nearOwn - nearNone, 0.15f, 0.03f);
  EXPECT_NEAR(farOwn, farNone, 0.003f);
  EXPECT_NEAR(nearNone, farNone, 0.01f);
  EXPECT_NEAR(farNone, float(gp.margin), 0.02f);
}

TEST(ShapeGrowth, HairBelowTheWidestPartHangsAndAStrokeKeepsItsOwnHair) {
  const SphereHead head;
  const Grid g = boxGrid(41, -2, 2);
  // a field pointing out and a little down everywhere
  const std::vector<float> field = constantField(g, 0.8f, -0.6f, 0);
  GrowthParams gp;
  gp.maxLength = 2.0;  // 20 cm: long enough to hang (kHugLength)
  ShapeRules rules;
  rules.on = true;
  // roots just under the equator on the +x side: they hang straight down
  const std::vector<Eigen::Vector3f> low = {{0.95f, -0.31f, 0}, {0.94f, -0.3f, 0.15f}};
  Strands hung;
  ASSERT_TRUE(
      growStrands(g, field, low, gp, hung, 1 << 20, &head.distance, nullptr, BodyCollider(), &rules)
          .ok());
  for (size_t s = 0; s < low.size(); ++s) {
    const float* a = &hung.points[3 * size_t(hung.strandStart[s])];
    const float* b = &hung.points[3 * size_t(hung.strandStart[s + 1] - 1)];
    const Eigen::Vector3f d(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    EXPECT_GT(d.norm(), 0.3f);
    EXPECT_LT(-d.y() / d.norm(), 1.0f + 1e-6f);
    EXPECT_GT(-d.y() / d.norm(), 0.9f) << "strand " << s << " leaves along " << d.transpose();
  }
  // a stroke lifted off the head along +x at the crown's side: the hair rooted under it is its
  // own and follows the field out (no farther than the stroke plus kLiftSlack), while hair far
  // from it lies on the head
  std::vector<float> lift;
  const CurveReach reach = crownSideStroke(g, 0.06, lift);
  const std::vector<Eigen::Vector3f> roots = {{0.7f, 0.714f, 0}, {-0.7f, 0.714f, 0}};
  Strands st;
  gp.maxLength = 0.5;
  ASSERT_TRUE(
      growStrands(g, field, roots, gp, st, 1 << 20, &head.distance, &reach, BodyCollider(), &rules)
          .ok());
  const std::vector<float> under = standOff(st, 0, 0.45f), far = standOff(st, 1, 0.45f);
  ASSERT_FALSE(under.empty());
  ASSERT_FALSE(far.empty());
  // the stroke's hair stands off as its stroke does (0.4 at its tip), never past it by more than
  // the slack; the other lies at the margin until it hangs
  EXPECT_GT(under.back(), 0.15f);
  for (size_t k = 0; k < under.size(); ++k) EXPECT_LT(under[k], lift.back() + kLiftSlack + 0.03f);
  EXPECT_LT(median(far), float(gp.margin) + 0.02f);
}

TEST(ShapeGrowth, ShortHairHugsTheNapeLongHairHangsFromIt) {
  const SphereHead head(-0.9);  // the scalp's edge far below: the hair is laid, not tapered
  const Grid g = boxGrid(41, -2, 2);
  // a field pointing back and down everywhere
  const std::vector<float> field = constantField(g, 0, -0.6f, -0.8f);
  ShapeRules rules;
  rules.on = true;
  // roots behind the head just under its widest part (the surface there faces down)
  const std::vector<Eigen::Vector3f> roots = {{0, -0.3f, -0.954f}, {0.15f, -0.35f, -0.925f}};
  GrowthParams gp;
  gp.maxLength = 0.6;  // 6 cm: under every strand's hug threshold (kHugLength, kHugJitter)
  ASSERT_LT(gp.maxLength, kHugLength * (1 - kHugJitter));
  Strands shortHair;
  ASSERT_TRUE(growStrands(g, field, roots, gp, shortHair, 1 << 20, &head.distance, nullptr,
                          BodyCollider(), &rules)
                  .ok());
  for (size_t s = 0; s < roots.size(); ++s) {
    const std::vector<float> d = standOff(shortHair, s, 1.f);
    ASSERT_GT(d.size(), 10u);
    // it lies on at the growth margin (2 mm) plus the layer slope, never more than 1 cm off
    EXPECT_LT(*std::max_element(d.begin(), d.end()), 0.1f) << "strand " << s;
  }
  gp.maxLength = 2.0;  // 20 cm: over every strand's threshold
  ASSERT_GT(gp.maxLength, kHugLength * (1 + kHugJitter));
  Strands longHair;
  ASSERT_TRUE(growStrands(g, field, roots, gp, longHair, 1 << 20, &head.distance, nullptr,
                          BodyCollider(), &rules)
                  .ok());
  for (size_t s = 0; s < roots.size(); ++s) {
    // it hangs from under the widest part: 6 cm along it is well off the sphere
    const std::vector<float> d = standOff(longHair, s, 0.6f);
    ASSERT_FALSE(d.empty());
    EXPECT_GT(d.back(), 0.15f) << "strand " << s;
  }
}

// Short hair keeps its Volume on top and loses it below the skull's widest part (kHugVolumeLow):
// a pixie's crown stands off, its nape lies close, instead of ending off the neck as a shelf.
TEST(ShapeGrowth, ShortHairsVolumeLiftsTheCrownNotTheNape) {
  const SphereHead head;
  const Grid g = boxGrid(41, -2, 2);
  const std::vector<float> field = constantField(g, 0, -0.6f, -0.8f);  // back and down
  ShapeRules rules;
  rules.on = true;
  rules.volume = 0.15f;
  GrowthParams gp;
  gp.maxLength = 0.6;  // 6 cm: short hair
  ASSERT_LT(gp.maxLength, kHugLength * (1 - kHugJitter));
  // roots over the back (azimuth within 60 degrees of -z) at polar angle theta
  const auto back = [](float theta) {
    std::vector<Eigen::Vector3f> r = ring(theta, 12);
    for (Eigen::Vector3f& p : r) p.z() = -p.z();
    return r;
  };
  // the standoff of strand s's points past the rise (kVolumeRise), by the height of their
  // direction from the centre (the sphere's normal): top (y > 0.45) or under the widest part
  const auto past = [](const Strands& st, bool top) {
    std::vector<float> d;
    for (size_t s = 0; s + 1 < st.strandStart.size(); ++s) {
      const std::vector<float> all = standOff(st, s, 1.f);
      for (size_t k = all.size() / 2; k < all.size(); ++k) {
        const float* q = &st.points[3 * size_t(st.strandStart[s] + 1 + k)];
        const float ny = q[1] / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        if (top ? ny > 0.45f : ny < -0.02f) d.push_back(all[k]);
      }
    }
    return d;
  };
  Strands crown, nape;
  ASSERT_TRUE(growStrands(g, field, back(0.5f), gp, crown, 1 << 20, &head.distance, nullptr,
                          BodyCollider(), &rules)
                  .ok());
  ASSERT_TRUE(growStrands(g, field, back(1.45f), gp, nape, 1 << 20, &head.distance, nullptr,
                          BodyCollider(), &rules)
                  .ok());
  const std::vector<float> top = past(crown, true), low = past(nape, false);
  ASSERT_GT(top.size(), 12u);
  ASSERT_GT(low.size(), 12u);
  std::printf("short hair with 1.5 cm Volume: crown %.3f, nape %.3f off\n", median(top),
              median(low));
  // the crown at margin + volume (and a little layering); the nape at the default volume's
  // (kHugVolumeKept) within 5 mm
  EXPECT_NEAR(median(top), float(gp.margin) + 0.15f, 0.03f);
  EXPECT_LT(median(low), float(gp.margin) + kHugVolumeKept + 0.05f);
}

TEST(ShapeGrowth, HairOverAnEarHeadsForAStrokeBehindItNotForOneInFront) {
  // a sphere whose scalp ends at y = 0.3 (an "ear" band below it, still above the widest part)
  const SphereHead sphere(0.3);
  const HeadDistance& head = sphere.distance;
  const Grid g = boxGrid(41, -2.5, 2.5);
  // combed down along the sphere (down less its normal part, a little out), as the prior is
  std::vector<float> field(size_t(g.size()) * 3);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        Eigen::Vector3f n(float(g.origin.x() + g.step * i), float(g.origin.y() + g.step * j),
                          float(g.origin.z() + g.step * k));
        n /= std::max(n.norm(), 1e-3f);
        const Eigen::Vector3f t = (Eigen::Vector3f(0, -1, 0) + n.y() * n + 0.1f * n).normalized();
        std::copy(t.data(), t.data() + 3, &field[3 * size_t(g.index(i, j, k))]);
      }
  // roots across the +x side above the ear band
  std::vector<Eigen::Vector3f> roots;
  for (int k = 0; k < 9; ++k) {
    const float phi = 1.25f + 0.08f * float(k), theta = 0.9f;
    roots.emplace_back(kRadius * std::sin(theta) * std::sin(phi), kRadius * std::cos(theta),
                       kRadius * std::sin(theta) * std::cos(phi));
  }
  GrowthParams gp;
  gp.maxLength = 2.4;
  ShapeRules rules;
  rules.on = true;
  // a stroke straight down beside the +x side at depth z, off the head, to well below it; of the
  // strands reaching 8 cm below the ear band, the median distance from the stroke there
  const auto besideStroke = [&](double z, int& reached) {
    constexpr double kX = 1.1;
    std::vector<double> pts;
    std::vector<float> lift;
    for (int k = 0; k <= 20; ++k) {
      const double y = 0.6 - 0.15 * k;
      pts.insert(pts.end(), {kX, y, z});
      lift.push_back(float(std::sqrt(kX * kX + y * y + z * z) - kRadius));
    }
    ReachCurve c;
    c.points = pts.data();
    c.count = 21;
    c.setsLength = true;
    c.growsOn = true;
    c.lift = lift.data();
    CurveReach reach;
    buildCurveReach(g, {c}, reach);
    Strands st;
    EXPECT_TRUE(
        growStrands(g, field, roots, gp, st, 1 << 20, &head, &reach, BodyCollider(), &rules).ok());
    std::vector<float> d;
    for (size_t s = 0; s < roots.size(); ++s)
      for (uint32_t q = st.strandStart[s]; q < st.strandStart[s + 1]; ++q)
        if (st.points[3 * size_t(q) + 1] < -0.5f) {
          d.push_back(
              float(std::hypot(st.points[3 * size_t(q)] - kX, st.points[3 * size_t(q) + 2] - z)));
          break;
        }
    reached = int(d.size());
    return median(d);
  };
  // the roots span z 0.25 .. -0.4: strokes 3 cm in front of them and 2.5 cm behind
  int nFront = 0, nBehind = 0;
  const float front = besideStroke(0.55, nFront), behind = besideStroke(-0.65, nBehind);
  std::printf(
      "median distance from the stroke 8 cm below the ear: stroke in front %.3f (%d "
      "strands), behind %.3f (%d)\n",
      front, nFront, behind, nBehind);
  EXPECT_GE(nFront, 7);
  EXPECT_GE(nBehind, 7);
  // behind: the hair goes round the ear to it (tucked), beside it, not on its line; in front
  // (hair drawn down over the shoulder): the side's hair hangs where it is, not gathered onto it
  EXPECT_LT(behind, 0.4f);
  EXPECT_GT(behind, 0.5f * kCombBeside);
  EXPECT_GT(front, 0.5f);
}

TEST(ShapeGrowth, ShortHairEndsALittlePastTheScalpsEdgeAtTheNapeAndOverAnEar) {
  // a sphere whose scalp ends at y = -0.3
  const SphereHead sphere(-0.3);
  const HeadDistance& head = sphere.distance;
  const Grid g = boxGrid(41, -2, 2);
  ShapeRules rules;
  rules.on = true;
  GrowthParams gp;
  gp.maxLength = 0.8;  // 8 cm: short hair (kHugLength), long enough to go 5 cm past the edge
  ASSERT_LT(gp.maxLength, kHugLength * (1 - kHugJitter));
  // the length of strand s below the edge (from y = -0.3 exactly: up to a triangle's height more
  // than growth's, whose scalp flags are per triangle), and the largest stand-off of its points a
  // triangle's height (0.07) below the edge
  const auto pastEdge = [](const Strands& st, size_t s, float& off) {
    float len = 0;
    off = 0;
    for (uint32_t p = st.strandStart[s] + 1; p < st.strandStart[s + 1]; ++p) {
      const float* q = &st.points[3 * size_t(p)];
      const float r = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
      if (q[1] / r < -0.3f)
        len += std::sqrt((q[0] - q[-3]) * (q[0] - q[-3]) + (q[1] - q[-2]) * (q[1] - q[-2]) +
                         (q[2] - q[-1]) * (q[2] - q[-1]));
      if (q[1] / r < -0.3f - 0.07f) off = std::max(off, r - kRadius);
    }
    return len;
  };
  // twelve roots 1 cm apart at the nape (behind the head), combed down and back, and over an ear
  // (beside the head), combed down and out
  std::vector<Eigen::Vector3f> nape, side;
  for (int k = 0; k < 12; ++k) {
    const float a = 0.1f * float(k - 6), c = std::sqrt(1 - 0.05f * 0.05f);
    nape.emplace_back(c * std::sin(a), -0.05f, -c * std::cos(a));
    side.emplace_back(c * std::cos(a), -0.05f, c * std::sin(a));
  }
  Strands back, ear;
  ASSERT_TRUE(growStrands(g, constantField(g, 0, -1, -0.3f), nape, gp, back, 1 << 20, &head,
                          nullptr, BodyCollider(), &rules)
                  .ok());
  ASSERT_TRUE(growStrands(g, constantField(g, 0.3f, -1, 0), side, gp, ear, 1 << 20, &head, nullptr,
                          BodyCollider(), &rules)
                  .ok());
  ASSERT_EQ(back.strandStart.size(), 13u);
  ASSERT_EQ(ear.strandStart.size(), 13u);
  std::vector<float> b, e;
  float napeOff = 0, off = 0;
  for (size_t s = 0; s < 12; ++s) {
    b.push_back(pastEdge(back, s, off));
    napeOff = std::max(napeOff, off);
    e.push_back(pastEdge(ear, s, off));
  }
  const auto [bMin, bMax] = std::minmax_element(b.begin(), b.end());
  const auto [eMin, eMax] = std::minmax_element(e.begin(), e.end());
  std::printf("past the edge: nape %.3f..%.3f (off the head at most %.3f), ear %.3f..%.3f\n", *bMin,
              *bMax, napeOff, *eMin, *eMax);
  // every strand gets there (the edge is 2.5 cm below the roots, the hair 8 cm long) and ends
  // within its taper (at most 1.5 times kTaperPast*), a step and a triangle
  EXPECT_GT(*bMin, 0.f);
  EXPECT_LT(*bMax, 1.5f * kTaperPastNape + 0.1f);
  EXPECT_GT(*eMin, 0.f);
  EXPECT_LT(*eMax, 1.5f * kTaperPastEar + 0.1f);
  // in uneven tufts, not on one line: the shortest and longest differ by a third of the taper
  EXPECT_GT(*bMax - *bMin, kTaperPastNape / 3);
  // and at the nape closes in to the head: within a millimetre of the growth margin (2 mm; 3.8
  // mm off before it closed in)
  EXPECT_LT(napeOff, float(gp.margin) + 0.01f);
}

TEST(ShapeGrowth, ShortHairOfAStrokeThatStaysNearTheHeadLiesOnIt) {
  const SphereHead head;
  const Grid g = boxGrid(41, -2, 2);
  // a field pointing out and a little down everywhere (it would carry the hair off the head)
  const std::vector<float> field = constantField(g, 0.8f, -0.6f, 0);
  ShapeRules rules;
  rules.on = true;
  // a stroke drifting off the head along +x at the crown's side, to 1.3 cm off at its end (as a
  // stroke drawn past the nape in a back view leaves the neck): under kDrawnLift
  std::vector<float> lift;
  const CurveReach reach = crownSideStroke(g, 0.04, lift);
  ASSERT_LT(*std::max_element(lift.begin(), lift.end()), kDrawnLift);
  const std::vector<Eigen::Vector3f> roots = {{0.7f, 0.714f, 0}};
  GrowthParams gp;
  gp.maxLength = 0.5;  // short hair (kHugLength)
  Strands st;
  ASSERT_TRUE(
      growStrands(g, field, roots, gp, st, 1 << 20, &head.distance, &reach, BodyCollider(), &rules)
          .ok());
  const std::vector<float> d = standOff(st, 0, 0.45f);
  ASSERT_GT(d.size(), 5u);
  // laid at the standoff (margin and layer slope), not out along its stroke to 1.3 cm
  std::printf("short hair of a stroke drifting to %.3f off the head: at most %.3f off it\n",
              lift.back(), *std::max_element(d.begin(), d.end()));
  EXPECT_LT(*std::max_element(d.begin(), d.end()), float(gp.margin) + 0.04f);
}

TEST(ShapeGrowth, ShortHairAStrokesHairEndsHasItsEndsSpreadAsALayeredCut) {
  const SphereHead sphere;
  const Grid g = boxGrid(41, -2, 2);
  ShapeRules rules;
  rules.on = true;
  // a stroke down the back on the head, from 60 to 105 degrees from the crown (7.9 cm: short
  // hair), its hair ending at 105 degrees
  constexpr float kFrom = 1.0472f, kTo = 1.8326f;
  std::vector<double> pts;
  std::vector<float> lift;
  for (int k = 0; k <= 12; ++k) {
    const float t = kFrom + (kTo - kFrom) * float(k) / 12;
    pts.insert(pts.end(), {0.0, double(std::cos(t)), -double(std::sin(t))});
    lift.push_back(0.f);
  }
  ReachCurve c;
  c.points = pts.data();
  c.count = lift.size();
  c.setsLength = true;
  c.lift = lift.data();
  CurveReach reach;
  buildCurveReach(g, {c}, reach);
  // twelve roots 1 cm apart across the stroke, 5 degrees below its start, combed down the back
  std::vector<Eigen::Vector3f> roots;
  const float theta = kFrom + 0.0873f;
  for (int k = 0; k < 12; ++k) {
    const float a = 0.1f * (float(k) - 5.5f);
    roots.emplace_back(std::sin(theta) * std::sin(a), std::cos(theta),
                       -std::sin(theta) * std::cos(a));
  }
  GrowthParams gp;
  gp.maxLength = 0.8;
  Strands st;
  ASSERT_TRUE(growStrands(g, constantField(g, 0, -1, -0.3f), roots, gp, st, 1 << 20,
                          &sphere.distance, &reach, BodyCollider(), &rules)
                  .ok());
  ASSERT_EQ(st.strandStart.size(), 13u);
  // each tip's arc from the crown (radians on the unit sphere: world units)
  std::vector<float> tips;
  for (size_t s = 0; s < 12; ++s) {
    const float* q = &st.points[3 * size_t(st.strandStart[s + 1] - 1)];
    tips.push_back(std::acos(q[1] / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2])));
  }
  const auto [lo, hi] = std::minmax_element(tips.begin(), tips.end());
  std::printf("tips from %.3f to %.3f from the crown (the stroke ends at %.3f)\n", *lo, *hi, kTo);
  // none more than kLayeredPast past the stroke's end (and half a step), none more than the
  // layered band before it (and a step), and spread over a quarter of the band: not on one line
  // (1.07 cm; 0.07 mm with the band made 0.1 mm and nothing past)
  EXPECT_LT(*hi, kTo + kLayeredPast + 0.025f);
  EXPECT_GT(*lo, kTo - kLayeredBand - 0.1f);
  EXPECT_GT(*hi - *lo, kLayeredBand / 4);
  // hair rooted 5 mm above the stroke's end is as long as hair rooted past it (kPastEndLength, to
  // a step): no stubs (5 mm long without the rule)
  std::vector<Eigen::Vector3f> low;
  for (const Eigen::Vector3f& r : roots) {
    const float a = std::atan2(r.x(), -r.z()), t = kTo - 0.05f;
    low.emplace_back(std::sin(t) * std::sin(a), std::cos(t), -std::sin(t) * std::cos(a));
  }
  Strands lowSt;
  ASSERT_TRUE(growStrands(g, constantField(g, 0, -1, -0.3f), low, gp, lowSt, 1 << 20,
                          &sphere.distance, &reach, BodyCollider(), &rules)
                  .ok());
  ASSERT_EQ(lowSt.strandStart.size(), 13u);
  for (size_t s = 0; s < 12; ++s) {
    float len = 0;
    for (uint32_t p = lowSt.strandStart[s] + 1; p < lowSt.strandStart[s + 1]; ++p) {
      const float* q = &lowSt.points[3 * size_t(p)];
      len += std::sqrt((q[0] - q[-3]) * (q[0] - q[-3]) + (q[1] - q[-2]) * (q[1] - q[-2]) +
                       (q[2] - q[-1]) * (q[2] - q[-1]));
    }
    EXPECT_GT(len, float(kPastEndLength) - 0.05f) << "strand " << s;
  }
}

namespace {

// A field that parts at coordinate `axis` = at: along +axis past it, along -axis before it
// (turning over the one lattice cell that holds `at`, as a field between strokes drawn both ways
// from one line does).
std::vector<float> partingField(const Grid& g, int axis, float at) {
  std::vector<float> f(size_t(g.size()) * 3, 0.f);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const Eigen::Vector3d p = g.position(i, j, k);
        const size_t q = size_t(i) + size_t(j) * g.nx + size_t(k) * g.nx * g.ny;
        f[3 * q + axis] = p[axis] > at ? 1.f : -1.f;
      }
  return f;
}

// The unit direction from strand s's root to its first point `arc` or more along it.
Eigen::Vector3f firstDirection(const Strands& st, size_t s, float arc) {
  const float* r = &st.points[3 * size_t(st.strandStart[s])];
  float len = 0;
  for (uint32_t p = st.strandStart[s] + 1; p < st.strandStart[s + 1]; ++p) {
    const float* q = &st.points[3 * size_t(p)];
    len += std::sqrt((q[0] - q[-3]) * (q[0] - q[-3]) + (q[1] - q[-2]) * (q[1] - q[-2]) +
                     (q[2] - q[-1]) * (q[2] - q[-1]));
    if (len >= arc || p + 1 == st.strandStart[s + 1])
      return Eigen::Vector3f(q[0] - r[0], q[1] - r[1], q[2] - r[2]).normalized();
  }
  return Eigen::Vector3f::Zero();
}

Eigen::Vector3f onSphere(float x, float z) {
  return {x, std::sqrt(kRadius * kRadius - x * x - z * z), z};
}

}  // namespace

TEST(ShapeGrowth, HairAtASeamAcrossTheCrownLiesAlongItAPartingFrontToBackStays) {
  const SphereHead sphere;
  const Grid g = boxGrid(41, -2, 2);  // lattice points every 0.1
  ShapeRules rules;
  rules.on = true;
  GrowthParams gp;
  gp.maxLength = 0.5;  // short hair (kHugLength)
  auto grow = [&](const std::vector<float>& field, const std::vector<Eigen::Vector3f>& roots) {
    Strands st;
    EXPECT_TRUE(growStrands(g, field, roots, gp, st, 1 << 20, &sphere.distance, nullptr,
                            BodyCollider(), &rules)
                    .ok());
    EXPECT_EQ(st.strandStart.size(), roots.size() + 1);
    return st;
  };
  // a seam across the crown at z = -0.35: hair forward in front of it, back behind it
  const std::vector<float> across = partingField(g, 2, -0.35f);
  std::vector<Eigen::Vector3f> atSeam;
  for (float x : {-0.25f, -0.15f, 0.15f, 0.25f})
    for (float dz : {-0.02f, 0.f, 0.02f}) atSeam.push_back(onSphere(x, -0.35f + dz));
  const Strands seam = grow(across, atSeam);
  for (size_t s = 0; s < atSeam.size(); ++s) {
    const Eigen::Vector3f d = firstDirection(seam, s, 0.15f);
    std::printf("root x %+.2f z %+.3f: first 1.5 cm along (%+.2f %+.2f %+.2f)\n", atSeam[s].x(),
                atSeam[s].z(), d.x(), d.y(), d.z());
    // along the line (x), towards the mid-plane: the seam is covered (straight along z, 0.0,
    // without the cover)
    EXPECT_GT(-d.x() * std::copysign(1.f, atSeam[s].x()), 0.6f) << "strand " << s;
  }
  // hair rooted 3 cm in front of the seam grows as it does in a field with no seam, to the bit
  std::vector<Eigen::Vector3f> ahead;
  for (float x : {-0.2f, 0.f, 0.2f}) ahead.push_back(onSphere(x, -0.05f));
  const Strands mid = grow(across, ahead), plain = grow(constantField(g, 0, 0, 1), ahead);
  EXPECT_EQ(mid.points, plain.points);
  // a parting front to back (at x = 0.05) stays a parting: the hair at it leaves across it
  const std::vector<float> parted = partingField(g, 0, 0.05f);
  std::vector<Eigen::Vector3f> atParting;
  for (float z : {-0.2f, 0.f, 0.2f})
    for (float dx : {-0.02f, 0.02f}) atParting.push_back(onSphere(0.05f + dx, z));
  const Strands parting = grow(parted, atParting);
  for (size_t s = 0; s < atParting.size(); ++s) {
    const Eigen::Vector3f d = firstDirection(parting, s, 0.15f);
    EXPECT_LT(std::abs(d.z()), 0.2f) << "strand " << s;
    EXPECT_GT(d.x() * std::copysign(1.f, atParting[s].x() - 0.05f), 0.8f) << "strand " << s;
  }
}

TEST(ShapeGrowth, HairNoStrokeGovernsEndsAtTheForeheadsSkinNotLyingAcrossIt) {
  // a sphere whose scalp is the cap above y = 0.4: below it, in front, the forehead's skin (the
  // face's column begins at y = 0.5)
  const SphereHead sphere(0.4);
  const Grid g = boxGrid(41, -2, 2);
  ShapeRules rules;
  rules.on = true;
  rules.volume = 0.05f;  // the Hair panel's default: laid 7 mm off, past the growth margin
  GrowthParams gp;
  gp.maxLength = 0.6;
  // hair combed forward and down over the front of the scalp, rooted just above its edge
  std::vector<Eigen::Vector3f> roots;
  for (float x : {-0.15f, -0.05f, 0.05f, 0.15f}) roots.push_back(onSphere(x, 0.85f));
  Strands st;
  ASSERT_TRUE(growStrands(g, constantField(g, 0, -1, 0.5f), roots, gp, st, 1 << 20,
                          &sphere.distance, nullptr, BodyCollider(), &rules)
                  .ok());
  ASSERT_EQ(st.strandStart.size(), roots.size() + 1);
  // no strand lies on the skin (in front, below y = 0.5, within 1 cm of the sphere) farther than
  // a step below the scalp's edge (3 mm; 11 mm, turned aside across the forehead, without the
  // rule)
  float below = 0;  // how far below the scalp's edge a point lies on the skin (radians)
  for (size_t p = 0; p < st.points.size() / 3; ++p) {
    const float* q = &st.points[3 * p];
    const float r = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    if (q[2] > std::abs(q[0]) && q[1] < 0.5f && r - kRadius < 0.1f)
      below = std::max(below, std::asin(0.4f) - std::asin(q[1] / r));
  }
  std::printf("hair on the forehead's skin: down to %.3f below the scalp's edge\n", below);
  EXPECT_LT(below, 0.05f);
  // and each strand grew down to the scalp's edge (at least one step past its root)
  for (size_t s = 0; s < roots.size(); ++s)
    EXPECT_GE(st.strandStart[s + 1] - st.strandStart[s], 2u);
}

TEST(ShapeGrowth, AFringesLengthIsItsOwnHairsNotTheHairBesideItThatHangsPastItsEnd) {
  // hair hangs straight down (a constant field); a long stroke down at x = 1.2 from y = 0.6 to
  // -1.6; a short stroke (a bang) at x = 0 from y = 0.6 to y = 0.2, 12 cm across from the long one
  const Grid g = boxGrid(41, -2, 2);
  const std::vector<float> field = constantField(g, 0, -1, 0);
  std::vector<double> longPts, bangPts;
  for (int k = 0; k <= 22; ++k) longPts.insert(longPts.end(), {1.2, 0.6 - 0.1 * k, 0});
  for (int k = 0; k <= 4; ++k) bangPts.insert(bangPts.end(), {0.0, 0.6 - 0.1 * k, 0});
  ShapeRules rules;
  rules.on = true;
  GrowthParams gp;
  gp.maxLength = 3;
  gp.maxSegments = 400;
  // roots: on the bang's line; 1 cm beside it (within its reach); 4.5 and 5 cm beside it (past
  // its reach, and farther still from the long stroke)
  const std::vector<Eigen::Vector3f> roots{
      {0.f, 0.6f, 0.f}, {0.1f, 0.6f, 0.f}, {0.45f, 0.6f, 0.f}, {0.5f, 0.6f, 0.f}};
  auto grow = [&](bool withBang, bool fringe) {
    std::vector<ReachCurve> curves(1);
    curves[0].points = longPts.data();
    curves[0].count = 23;
    curves[0].setsLength = true;
    if (withBang) {
      ReachCurve bang;
      bang.points = bangPts.data();
      bang.count = 5;
      bang.setsLength = true;
      bang.fringe = fringe;
      curves.push_back(bang);
    }
    CurveReach reach;
    buildCurveReach(g, curves, reach);
    Strands st;
    EXPECT_TRUE(
        growStrands(g, field, roots, gp, st, 1 << 20, nullptr, &reach, BodyCollider(), &rules)
            .ok());
    std::vector<float> tipY;
    for (size_t s = 0; s + 1 < st.strandStart.size(); ++s)
      tipY.push_back(st.points[3 * size_t(st.strandStart[s + 1] - 1) + 1]);
    return tipY;
  };
  const std::vector<float> alone = grow(false, false), fringe = grow(true, true),
                           unflagged = grow(true, false);
  ASSERT_EQ(fringe.size(), roots.size());
  const float step = float(0.5 * g.step);
  std::printf(
      "tips without the bang %.3f %.3f %.3f %.3f; with it as a fringe %.3f %.3f %.3f %.3f;"
      " as a stroke beside the face %.3f %.3f %.3f %.3f\n",
      alone[0], alone[1], alone[2], alone[3], fringe[0], fringe[1], fringe[2], fringe[3],
      unflagged[0], unflagged[1], unflagged[2], unflagged[3]);
  // the bang's own hair ends where the bang does (y = 0.2), within a step and its slack
  EXPECT_NEAR(fringe[0], 0.2f, 2 * step);
  EXPECT_NEAR(fringe[1], 0.2f, 2 * step);
  // past its reach the hair is as long as without the bang (the independent reference)
  EXPECT_NEAR(fringe[2], alone[2], step);
  EXPECT_NEAR(fringe[3], alone[3], step);
  EXPECT_LT(alone[3], -1.f);  // and that is long hair
  // a stroke that is no fringe sets the length of the hair around it: the same roots are cut
  EXPECT_GT(unflagged[3], alone[3] + 0.8f);
}

}  // namespace shape_rules_test
