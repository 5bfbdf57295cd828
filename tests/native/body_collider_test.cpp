// The body under the head (issue 37, a bust): HairEngine::setBody and the bust setting. A head
// (a sphere of radius 1 = 10 cm on a neck 9 cm across) over capsule shoulders (4 units = 40 cm
// wide, 2 deep, their top 6 mm under the head; the neck runs into them), long hair (60 cm) with
// natural fall. Every check of "inside the body" uses the capsule's exact distance
// (body_mesh.hpp), not the engine's distance grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

#include "body_mesh.hpp"
#include "curve_kinds.hpp"
#include "hair_engine.hpp"
#include "sphere_mesh.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace body_collider_test {

using namespace hairsketch;
using hairsketch_test::Capsule;
using hairsketch_test::Mesh;

namespace {

constexpr double kMaxLength = 6;    // 60 cm
constexpr double kInside = 0.01;    // 1 mm: no strand point or segment deeper in the body
constexpr int kSegmentSamples = 8;  // points checked along each segment, ends excluded

struct BodyScene {
  Grid grid;
  Mesh head = hairsketch_test::headOnNeck();  // its neck runs down into the shoulders
  Mesh sphere = hairsketch_test::uvSphere(0, 0, 0, 1.0, 24, 48);  // a head without a neck
  Capsule shoulders;
  Mesh body = hairsketch_test::capsuleMesh(shoulders);
  std::vector<double> points, params;
  std::vector<uint32_t> start{0}, paramStart{0};
  std::vector<uint8_t> kinds, extend;
  BodyScene() {
    grid.step = 0.2;
    grid.origin = {-3.2, -6.0, -3.2};
    grid.nx = 33;
    grid.ny = 39;
    grid.nz = 33;
    hairsketch_test::markScalpAbove(head, 0.2);
    hairsketch_test::markScalpAbove(sphere, 0.2);
    // a stream curve from the top of the head down the back, growing on
    std::vector<double> curve;
    for (int i = 0; i <= 12; ++i) {
      const double a = 0.2 + 0.2 * i;
      curve.insert(curve.end(), {0, 1.05 * std::cos(a), -1.05 * std::sin(a)});
    }
    addCurve(curve, CurveKindCode::Stream, {});
  }
  void addCurve(const std::vector<double>& pts, CurveKindCode kind, const std::vector<double>& p) {
    points.insert(points.end(), pts.begin(), pts.end());
    params.insert(params.end(), p.begin(), p.end());
    start.push_back(uint32_t(points.size() / 3));
    paramStart.push_back(uint32_t(params.size()));
    kinds.push_back(uint8_t(kind));
    extend.push_back(1);
  }
  // A ponytail from the back of the head whose tail runs down through the shoulders (a tail laid
  // in growth, not grown: only keepOutsideHead's passes keep it out of the body).
  void addPonytailThroughTheBody() {
    const std::vector<Eigen::Vector3d> corners{
        {0, 0.34, -0.94}, {0, -0.6, -1.15}, {0, -1.5, -0.6}, {0, -4.2, -0.6}};
    std::vector<Eigen::Vector3d> spine{corners[0]};
    for (size_t k = 1; k < corners.size(); ++k) {
      const int n = int(std::ceil((corners[k] - corners[k - 1]).norm() / 0.1));
      for (int i = 1; i <= n; ++i)
        spine.push_back(corners[k - 1] + (corners[k] - corners[k - 1]) * double(i) / n);
    }
    std::vector<double> pts, circles;
    for (const Eigen::Vector3d& q : spine) pts.insert(pts.end(), {q.x(), q.y(), q.z()});
    int m = 0;
    const int n = int(spine.size());
    for (int i = 4; i < n; i += 2) {
      const Eigen::Vector3d t =
          (spine[size_t(std::min(n - 1, i + 1))] - spine[size_t(i - 1)]).normalized();
      const Eigen::Vector3d& c = spine[size_t(i)];
      circles.insert(circles.end(), {c.x(), c.y(), c.z(), t.x(), t.y(), t.z(), 0.15});
      ++m;
    }
    std::vector<double> p{0.6, 1, double(m)};  // tightness, gather, circles
    p.insert(p.end(), circles.begin(), circles.end());
    addCurve(pts, CurveKindCode::Ponytail, p);
  }
  CurveSetView curves() const {
    CurveSetView v;
    v.points = points.data();
    v.pointCount = points.size() / 3;
    v.curveStart = start.data();
    v.curveCount = kinds.size();
    v.kinds = kinds.data();
    v.extend = extend.data();
    v.params = params.data();
    v.paramCount = params.size();
    v.paramStart = paramStart.data();
    return v;
  }
  // Grid, natural fall, the bust setting, head (a head with the shoulders as part of its own
  // mesh when headMesh is given), body (when withBody), curves, solve.
  Status setup(HairEngine& e, bool bust, bool withBody, const Mesh* headMesh = nullptr) const {
    const Mesh& h = headMesh ? *headMesh : head;
    Status st = e.setGrid(grid, kDefaultOmega, "cg");
    double settings[kEngineSettingCount] = {};
    settings[kSettingFall] = 1;
    settings[kSettingBust] = bust ? 1 : 0;
    if (st.ok()) st = e.setSettings(settings, kEngineSettingCount);
    if (st.ok())
      st = e.setScalp(h.positions.data(), h.positions.size() / 3, h.indices.data(),
                      h.indices.size() / 3, h.scalp.data(), Eigen::Vector3d::Zero());
    if (st.ok() && withBody)
      st = e.setBody(body.positions.data(), body.positions.size() / 3, body.indices.data(),
                     body.indices.size() / 3);
    if (st.ok()) st = e.setCurves(curves());
    if (st.ok()) st = e.solve();
    return st;
  }
};

RootParams longRoots() {
  RootParams rp;
  rp.thetaStepDeg = 4;
  rp.phiStepDeg = 4;
  rp.seed = 11;
  return rp;
}

GrowthParams longHair() {
  GrowthParams gp;
  gp.maxLength = kMaxLength;
  gp.stepFraction = 0.2;  // 4 mm steps: a strand ends within 0.7 % of its length budget
  gp.maxSegments = 250;
  return gp;
}

double strandLength(const Strands& s, size_t k) {
  double len = 0;
  for (uint32_t p = s.strandStart[k] + 1; p < s.strandStart[k + 1]; ++p) {
    const float* a = &s.points[3 * size_t(p - 1)];
    const float* b = a + 3;
    len += std::sqrt(double(b[0] - a[0]) * (b[0] - a[0]) + double(b[1] - a[1]) * (b[1] - a[1]) +
                     double(b[2] - a[2]) * (b[2] - a[2]));
  }
  return len;
}

struct Depth {
  size_t pointsInside = 0, segmentsInside = 0;  // deeper than kInside
  double deepest = 0;                           // the deepest point or segment sample
  size_t touching = 0;                          // strands with a point within 5 mm of the body
};

// Every strand point and kSegmentSamples points along each segment, against the exact capsule.
Depth depthIn(const Capsule& c, const Strands& s) {
  Depth d;
  for (size_t k = 0; k + 1 < s.strandStart.size(); ++k) {
    bool touches = false;
    for (uint32_t p = s.strandStart[k]; p < s.strandStart[k + 1]; ++p) {
      const float* q = &s.points[3 * size_t(p)];
      const double dist = c.distance(q[0], q[1], q[2]);
      d.deepest = std::max(d.deepest, -dist);
      touches |= dist < 0.05;
      if (dist < -kInside) ++d.pointsInside;
      if (p + 1 == s.strandStart[k + 1]) continue;
      bool in = false;
      for (int i = 1; i <= kSegmentSamples; ++i) {
        const double t = double(i) / (kSegmentSamples + 1);
        const double ds = c.distance(q[0] + t * (q[3] - q[0]), q[1] + t * (q[4] - q[1]),
                                     q[2] + t * (q[5] - q[2]));
        d.deepest = std::max(d.deepest, -ds);
        in |= ds < -kInside;
      }
      d.segmentsInside += in;
    }
    d.touching += touches;
  }
  return d;
}

// Strands on either side of a plane: those that start beyond +threshold (front) or -threshold
// (back) of it and how many of each end on their own side.
struct Side {
  size_t front = 0, frontOk = 0, back = 0, backOk = 0;
  void add(double from, double to, double threshold) {
    if (from > threshold) {
      ++front;
      frontOk += to > 0;
    } else if (from < -threshold) {
      ++back;
      backOk += to < 0;
    }
  }
  double frontShare() const { return 100.0 * double(frontOk) / double(std::max<size_t>(front, 1)); }
  double backShare() const { return 100.0 * double(backOk) / double(std::max<size_t>(back, 1)); }
};

double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

TEST(BodyCollider, TheTestMeshesAreClosedAndFaceOutward) {
  const BodyScene s;
  EXPECT_GT(hairsketch_test::signedVolume6(s.body), 0);  // counter-clockwise = outward
  // the mesh's volume is the capsule's, less the chords' sag
  const double pi = 3.14159265358979323846, r = s.shoulders.r, a = s.shoulders.a;
  const double exact = pi * r * r * 2 * a + 4.0 / 3 * pi * r * r * r;
  EXPECT_NEAR(hairsketch_test::signedVolume6(s.body) / 6, exact, 0.01 * exact);
  EXPECT_GT(hairsketch_test::signedVolume6(s.head), 0);  // the head on its neck too
}

TEST(BodyCollider, SetBodyRefusesBadMeshesAndZeroTrianglesClearsIt) {
  const BodyScene s;
  HairEngine e;
  const size_t nv = s.body.positions.size() / 3, nt = s.body.indices.size() / 3;
  ASSERT_TRUE(e.setBody(s.body.positions.data(), nv, s.body.indices.data(), nt).ok());
  EXPECT_TRUE(e.hasBody());
  EXPECT_LT(std::abs(e.bodyDistance().distance(0, -1.6f, 0)), 0.01f);  // the capsule's top
  EXPECT_LT(e.bodyDistance().distance(0, -2.6f, 0), -0.1f);            // inside
  std::vector<float> pos = s.body.positions;
  pos[7] = std::nanf("");
  EXPECT_EQ(e.setBody(pos.data(), nv, s.body.indices.data(), nt).code, StatusCode::NonFinite);
  EXPECT_FALSE(e.hasBody());  // a refused body leaves none
  std::vector<uint32_t> idx = s.body.indices;
  idx[5] = uint32_t(nv);
  ASSERT_TRUE(e.setBody(s.body.positions.data(), nv, s.body.indices.data(), nt).ok());
  const Status bad = e.setBody(s.body.positions.data(), nv, idx.data(), nt);
  EXPECT_EQ(bad.code, StatusCode::InvalidInput);
  EXPECT_NE(bad.message.find("out of range"), std::string::npos) << bad.message;
  EXPECT_FALSE(e.hasBody());
  EXPECT_EQ(e.setBody(nullptr, 0, s.body.indices.data(), nt).code, StatusCode::InvalidInput);
  ASSERT_TRUE(e.setBody(s.body.positions.data(), nv, s.body.indices.data(), nt).ok());
  ASSERT_TRUE(e.setBody(nullptr, 0, nullptr, 0).ok());  // 0 triangles: no body
  EXPECT_FALSE(e.hasBody());
}

TEST(BodyCollider, TheBustSettingIsOneEntryOfTheSettings) {
  HairEngine e;
  double v[kEngineSettingCount] = {};
  EXPECT_LT(size_t(kSettingBust), size_t(kEngineSettingCount));
  v[kSettingBust] = 1;
  ASSERT_TRUE(e.setSettings(v, kEngineSettingCount).ok());
  EXPECT_TRUE(e.bust());
  v[kSettingBust] = 0;
  // settings of another count (one number fewer) are refused, nothing changes
  EXPECT_EQ(e.setSettings(v, kEngineSettingCount - 1).code, StatusCode::InvalidInput);
  EXPECT_TRUE(e.bust());
  ASSERT_TRUE(e.setSettings(v, kEngineSettingCount).ok());
  EXPECT_FALSE(e.bust());
}

TEST(BodyCollider, LongHairRestsOnTheShouldersKeepsItsLengthAndItsSide) {
  const BodyScene s;
  HairEngine none, bust;
  ASSERT_TRUE(s.setup(none, false, false).ok());
  ASSERT_TRUE(s.setup(bust, true, true).ok());
  ASSERT_TRUE(none.grow(longRoots(), longHair()).ok());
  ASSERT_TRUE(bust.grow(longRoots(), longHair()).ok());
  const Strands& a = none.strands();
  const Strands& b = bust.strands();
  const size_t n = a.strandStart.size() - 1;
  ASSERT_EQ(b.strandStart.size() - 1, n);
  ASSERT_GT(n, 500u);

  // Without the body the hair runs through the shoulders; with it, nothing is inside.
  const Depth without = depthIn(s.shoulders, a), with = depthIn(s.shoulders, b);
  std::printf(
      "[body] %zu strands; without the body %zu points (%zu segments) > 1 mm inside, deepest "
      "%.3f; with it %zu (%zu), deepest %.4f; %zu strands touch it\n",
      n, without.pointsInside, without.segmentsInside, without.deepest, with.pointsInside,
      with.segmentsInside, with.deepest, with.touching);
  EXPECT_GT(without.pointsInside, 1000u);  // the body is in the hair's way
  EXPECT_EQ(with.pointsInside, 0u);
  EXPECT_EQ(with.segmentsInside, 0u);
  EXPECT_GT(with.touching, n / 10);  // and the hair lies on it

  // Strands that reach the maximum length without the body keep their length with it.
  const double step = longHair().stepFraction * s.grid.step;
  std::vector<double> change;
  size_t full = 0, onBody = 0;
  for (size_t k = 0; k < n; ++k) {
    const double la = strandLength(a, k);
    if (la < kMaxLength - 2 * step) continue;
    ++full;
    change.push_back(std::abs(strandLength(b, k) / la - 1));
  }
  const double worst = change.empty() ? 1 : *std::max_element(change.begin(), change.end());
  std::printf(
      "[body] %zu strands reach 60 cm without the body: length change with it median "
      "%.4f %%, max %.4f %%\n",
      full, 100 * median(change), 100 * worst);
  EXPECT_GT(full, n / 2);
  EXPECT_LE(worst, 0.01);

  // Front and back, of the strands that meet the shoulders: hair that comes down in front of
  // the head (its z where it passes below the head, y = -1, is in front of the shoulders' ridge
  // z = 0) ends in front of the ridge, hair that comes down behind ends behind. By root, the
  // crown's hair is combed back by the stroke down the back (as it should be), so only roots
  // well in front (z > 0.5) or behind (z < -0.5) are counted.
  const double ridge = s.shoulders.cz;
  Side down, rooted;
  for (size_t k = 0; k < n; ++k) {
    const uint32_t r = b.strandStart[k], t = b.strandStart[k + 1] - 1;
    bool touches = false;
    double below = std::numeric_limits<double>::quiet_NaN();
    for (uint32_t p = r; p <= t; ++p) {
      const float* q = &b.points[3 * size_t(p)];
      touches |= s.shoulders.distance(q[0], q[1], q[2]) < 0.05;
      if (std::isnan(below) && q[1] < -1.0f) below = q[2];
    }
    if (!touches) continue;
    ++onBody;
    const double rootZ = b.points[3 * size_t(r) + 2], tipZ = b.points[3 * size_t(t) + 2];
    down.add(below - ridge, tipZ - ridge, 0.1);
    rooted.add(rootZ - ridge, tipZ - ridge, 0.5);
  }
  std::printf(
      "[body] %zu strands meet the shoulders. Coming down in front of the ridge %zu, "
      "%.1f %% end in front; behind %zu, %.1f %% end behind. Rooted in front %zu, %.1f %% "
      "end in front; behind %zu, %.1f %% end behind\n",
      onBody, down.front, down.frontShare(), down.back, down.backShare(), rooted.front,
      rooted.frontShare(), rooted.back, rooted.backShare());
  EXPECT_GT(onBody, n / 2);
  EXPECT_GT(down.front, 100u);
  EXPECT_GT(down.back, 100u);
  EXPECT_GE(down.frontShare(), 99.0);
  EXPECT_GE(down.backShare(), 99.0);
  EXPECT_GT(rooted.front, 50u);
  EXPECT_GT(rooted.back, 50u);
  EXPECT_GE(rooted.frontShare(), 95.0);
  EXPECT_GE(rooted.backShare(), 95.0);
}

TEST(BodyCollider, TheSameSeedGivesTheSameBytesAndBustOffIsNoBodyBitForBit) {
  const BodyScene s;
  HairEngine none, off, on, on2;
  ASSERT_TRUE(s.setup(none, false, false).ok());
  ASSERT_TRUE(s.setup(off, false, true).ok());  // a body, the bust setting off
  ASSERT_TRUE(s.setup(on, true, true).ok());
  ASSERT_TRUE(s.setup(on2, true, true).ok());
  for (HairEngine* e : {&none, &off, &on, &on2}) ASSERT_TRUE(e->grow(longRoots(), longHair()).ok());
  EXPECT_EQ(off.strands().points, none.strands().points);
  EXPECT_EQ(off.strands().strandStart, none.strands().strandStart);
  EXPECT_NE(on.strands().points, none.strands().points);
  EXPECT_EQ(on2.strands().points, on.strands().points);
  EXPECT_EQ(on2.strands().strandStart, on.strands().strandStart);
  const Strands first = on.strands();
  ASSERT_TRUE(on.grow(longRoots(), longHair()).ok());  // again, on the same engine
  EXPECT_EQ(on.strands().points, first.points);
  // bust turned off again: the hair of no body
  double settings[kEngineSettingCount] = {};
  settings[kSettingFall] = 1;
  ASSERT_TRUE(on.setSettings(settings, kEngineSettingCount).ok());
  ASSERT_TRUE(on.grow(longRoots(), longHair()).ok());
  EXPECT_EQ(on.strands().points, none.strands().points);
  // bust on without a body, a head whose mesh ends above kHeadBodyBelowY: nothing changes
  HairEngine sphereOff, sphereOn;
  ASSERT_TRUE(s.setup(sphereOff, false, false, &s.sphere).ok());
  ASSERT_TRUE(s.setup(sphereOn, true, false, &s.sphere).ok());
  ASSERT_TRUE(sphereOff.grow(longRoots(), longHair()).ok());
  ASSERT_TRUE(sphereOn.grow(longRoots(), longHair()).ok());
  EXPECT_EQ(sphereOn.strands().points, sphereOff.strands().points);
  EXPECT_EQ(sphereOn.strands().strandStart, sphereOff.strands().strandStart);
}

TEST(BodyCollider, DetailAndATailThroughTheShouldersAreKeptOutOfTheBody) {
  BodyScene s;
  s.addPonytailThroughTheBody();
  HairEngine none, bust;
  ASSERT_TRUE(s.setup(none, false, false).ok());
  ASSERT_TRUE(s.setup(bust, true, true).ok());
  DetailParams curly;
  curly.curl.radius = 0.25;  // 2.5 cm curls
  curly.curl.frequency = 1.5;
  for (HairEngine* e : {&none, &bust}) {
    ASSERT_TRUE(e->setDetail({curly}, {}).ok());
    ASSERT_TRUE(e->grow(longRoots(), longHair()).ok());
  }
  size_t laid = 0;
  for (int32_t c : bust.strandTailCurves()) laid += c == 1;
  const Depth without = depthIn(s.shoulders, none.strands()),
              with = depthIn(s.shoulders, bust.strands());
  std::printf(
      "[body] curls and a tail of %zu strands: without the body %zu points > 1 mm "
      "inside; with it %zu (%zu segments), deepest %.4f\n",
      laid, without.pointsInside, with.pointsInside, with.segmentsInside, with.deepest);
  EXPECT_GT(laid, 50u);
  EXPECT_GT(without.pointsInside, 1000u);
  EXPECT_EQ(with.pointsInside, 0u);
  EXPECT_EQ(with.segmentsInside, 0u);
}

TEST(BodyCollider, CurlVolumeSpreadsLooseCurlsAndLeavesATiesTailAsItWas) {
  BodyScene s;
  s.addPonytailThroughTheBody();
  HairEngine off, on;
  DetailParams curly;  // a 3A curl
  curly.curl.radius = 0.105;
  curly.curl.frequency = 2.5;
  for (HairEngine* e : {&off, &on}) {
    ASSERT_TRUE(s.setup(*e, false, false).ok());
    e->setCurlVolume(e == &on);
    ASSERT_TRUE(e->setDetail({curly}, {}).ok());
    ASSERT_TRUE(e->grow(longRoots(), longHair()).ok());
  }
  const Strands &a = off.strands(), &b = on.strands();
  const std::vector<int32_t>& tail = on.strandTailCurves();
  ASSERT_EQ(a.strandStart.size(), b.strandStart.size());
  size_t tails = 0, loose = 0, spread = 0;
  double gained = 0;
  for (size_t k = 0; k + 1 < a.strandStart.size(); ++k) {
    const size_t a0 = a.strandStart[k], a1 = a.strandStart[k + 1], b0 = b.strandStart[k];
    ASSERT_EQ(a1 - a0, b.strandStart[k + 1] - b0) << "strand " << k;
    if (tail[k] >= 0) {
      ++tails;
      EXPECT_EQ(0, std::memcmp(&a.points[3 * a0], &b.points[3 * b0], 3 * (a1 - a0) * sizeof(float)))
          << "tail strand " << k;
      continue;
    }
    // the tip's distance from the vertical line through the head's centre (the origin)
    const float *ta = &a.points[3 * (a1 - 1)], *tb = &b.points[3 * (a1 - a0 + b0 - 1)];
    const double ra = std::hypot(ta[0], ta[2]), rb = std::hypot(tb[0], tb[2]);
    ++loose;
    gained += rb - ra;
    spread += rb > ra + 0.02;
  }
  std::printf(
      "[curl volume] %zu tail strands unchanged; %zu loose: tips %.3f further out (mean), "
      "%zu by more than 2 mm\n",
      tails, loose, gained / double(loose), spread);
  EXPECT_GT(tails, 50u);
  EXPECT_GT(loose, 200u);
  EXPECT_GT(gained / double(loose), 0.05);
  EXPECT_GT(spread, loose / 2);
}

TEST(BustHead, ALoadedBustIsItsOwnBodyBelowTheChin) {
  // One head mesh with the shoulders in it (a loaded bust), no body mesh.
  const BodyScene s;
  const Mesh bustMesh = hairsketch_test::joined(s.sphere, s.body);
  HairEngine off, on;
  ASSERT_TRUE(s.setup(off, false, false, &bustMesh).ok());
  ASSERT_TRUE(s.setup(on, true, false, &bustMesh).ok());
  ASSERT_TRUE(off.grow(longRoots(), longHair()).ok());
  ASSERT_TRUE(on.grow(longRoots(), longHair()).ok());
  const Strands& a = off.strands();
  const Strands& b = on.strands();
  const size_t n = a.strandStart.size() - 1;
  // Off, the shoulders are "face" to the face rule: hair that meets them stops there. On, it
  // slides over them to its full length, and stays out of them.
  size_t stoppedOff = 0, stoppedOn = 0, fullOff = 0, fullOn = 0;
  const double step = longHair().stepFraction * s.grid.step;
  for (size_t k = 0; k < n; ++k) {
    const float* ta = &a.points[3 * size_t(a.strandStart[k + 1] - 1)];
    const float* tb = &b.points[3 * size_t(b.strandStart[k + 1] - 1)];
    stoppedOff += s.shoulders.distance(ta[0], ta[1], ta[2]) < 0.05;
    stoppedOn += s.shoulders.distance(tb[0], tb[1], tb[2]) < 0.05;
    fullOff += strandLength(a, k) >= kMaxLength - 2 * step;
    fullOn += strandLength(b, k) >= kMaxLength - 2 * step;
  }
  const Depth with = depthIn(s.shoulders, b);
  std::printf(
      "[bust head] %zu strands: off, %zu end on the shoulders and %zu reach 60 cm; on, "
      "%zu and %zu; on, %zu points > 1 mm inside, deepest %.4f\n",
      n, stoppedOff, fullOff, stoppedOn, fullOn, with.pointsInside, with.deepest);
  EXPECT_GT(stoppedOff, n / 10);
  EXPECT_LT(stoppedOn, stoppedOff / 10);
  EXPECT_GT(fullOn, fullOff + n / 10);
  EXPECT_EQ(with.pointsInside, 0u);
  EXPECT_EQ(with.segmentsInside, 0u);
  EXPECT_GT(with.touching, n / 10);
}

}  // namespace body_collider_test
