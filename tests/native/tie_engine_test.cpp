// Ties from any hand through the engine (HairEngine::ties, set from kSettingTies): a whole-section
// braid drawn 40 cm down from the back of a sphere head (radius 1, scalp above y = -0.25) with
// Max length 32 cm. On, its plait reaches the stroke's end; off, the hair spends its length
// reaching the braid, as before, and an engine that grew with ties on grows the old hair again.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <vector>

#include "curve_params.hpp"
#include "engine_settings.hpp"
#include "hair_engine.hpp"
#include "sphere_mesh.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace tie_engine_test {

using namespace hairsketch;
using Eigen::Vector3d;

namespace {

struct BraidScene {
  hairsketch_test::Mesh head = hairsketch_test::uvSphere(0, 0, 0, 1.0, 48, 96);
  std::vector<double> points, params{0.3, 6, 0.5, 0.4, 1};  // width, crossings, tightness,
                                                            // tail length, whole section
  std::vector<uint32_t> start{0, 0}, paramStart{0, 5};
  std::vector<uint8_t> kinds{uint8_t(CurveKindCode::Braid)}, extend{0};
  Vector3d end;

  BraidScene() {
    hairsketch_test::markScalpAbove(head, -0.25);
    // on the scalp at the back, 1 cm out, then straight down 4 units (40 cm)
    const Vector3d dir = Vector3d(0, 0.2, -1).normalized();
    Vector3d p = dir * 1.02;
    points.insert(points.end(), {p.x(), p.y(), p.z()});
    p = dir * 1.12;
    for (int i = 0; i <= 40; ++i) {
      points.insert(points.end(), {p.x(), p.y(), p.z()});
      end = p;
      p += 0.1 * -Vector3d::UnitY();
    }
    start[1] = uint32_t(points.size() / 3);
  }
  CurveSetView view() const {
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
  void run(HairEngine& e, bool ties) const {
    Grid g;
    g.origin = Vector3d(-1.75, -4.75, -1.75);
    g.step = 0.25;
    g.nx = 15;
    g.ny = 26;
    g.nz = 15;
    ASSERT_TRUE(e.setGrid(g, kDefaultOmega, "exact").ok());
    ASSERT_TRUE(e.setScalp(head.positions.data(), head.positions.size() / 3, head.indices.data(),
                           head.indices.size() / 3, head.scalp.data(), Vector3d::Zero())
                    .ok());
    double settings[kEngineSettingCount] = {};
    settings[kSettingFall] = 1;
    settings[kSettingSections] = 1;
    settings[kSettingTies] = ties ? 1 : 0;
    ASSERT_TRUE(e.setSettings(settings, kEngineSettingCount).ok());
    ASSERT_TRUE(e.setCurves(view()).ok());
    ASSERT_TRUE(e.solve().ok());
    RootParams rp;
    rp.thetaStepDeg = 4;
    rp.phiStepDeg = 4;
    rp.seed = 7;
    GrowthParams gp;
    gp.maxLength = 3.2;
    gp.maxSegments = 250;
    ASSERT_TRUE(e.grow(rp, gp).ok());
  }
};

// The braid's strands' tips' distances from the stroke's end: the nearest and the median.
struct Tips {
  double nearest = 1e9, median = 1e9;
  size_t laid = 0;
};
Tips tips(const HairEngine& e, const Vector3d& end) {
  const Strands& s = e.strands();
  std::vector<double> d;
  for (size_t k = 0; k + 1 < s.strandStart.size(); ++k) {
    if (e.strandTailCurves()[k] != 0) continue;
    const float* t = &s.points[3 * (s.strandStart[k + 1] - 1)];
    d.push_back((Vector3d(t[0], t[1], t[2]) - end).norm());
  }
  Tips out;
  out.laid = d.size();
  if (d.empty()) return out;
  std::sort(d.begin(), d.end());
  out.nearest = d.front();
  out.median = d[d.size() / 2];
  return out;
}

TEST(TieEngine, ABraidReachesItsStrokesEndOnlyWithTies) {
  const BraidScene sc;
  HairEngine on, off;
  sc.run(on, true);
  sc.run(off, false);
  const Tips a = tips(on, sc.end), b = tips(off, sc.end);
  std::printf(
      "[ties] braid 40 cm, Max length 32 cm: tips from the stroke's end, nearest %.1f / "
      "median %.1f cm (on), %.1f / %.1f cm (off); %zu strands laid\n",
      10 * a.nearest, 10 * a.median, 10 * b.nearest, 10 * b.median, a.laid);
  ASSERT_GT(a.laid, 100u);
  EXPECT_EQ(a.laid, b.laid);  // the same hair is taken; only how it is laid differs
  EXPECT_LT(a.nearest, 0.2);  // the plait reaches the stroke's end
  EXPECT_LT(a.median, 0.3);   // all of it: ends within its loose tail's cut
  EXPECT_GT(b.median, 1.0);   // before: the hair spent its length reaching the braid
  // the flag holds no state: the engine that grew with ties on grows the off hair again
  sc.run(on, false);
  EXPECT_EQ(on.strands().points, off.strands().points);
  EXPECT_EQ(on.strands().strandStart, off.strands().strandStart);
}

// The engine says where each tie gathers its hair (its band's place): a point of the braid's
// stroke (where it leaves the scalp), with the axis along the stroke there.
TEST(TieEngine, TieFramesNameTheGather) {
  const BraidScene sc;
  HairEngine e;
  sc.run(e, true);
  const std::vector<float>& f = e.tieFrames();
  ASSERT_EQ(f.size(), 8u);
  EXPECT_EQ(f[7], 0.f);  // a braid's hair is three bundles there, not one circle
  EXPECT_EQ(f[0], 0.f);
  const Vector3d c(f[1], f[2], f[3]);
  size_t k = 0;
  double best = 1e9;
  for (size_t i = 0; i < sc.points.size() / 3; ++i) {
    const double d =
        (Vector3d(sc.points[3 * i], sc.points[3 * i + 1], sc.points[3 * i + 2]) - c).norm();
    if (d < best) {
      best = d;
      k = i;
    }
  }
  EXPECT_LT(best, 1e-5);
  ASSERT_LT(k + 1, sc.points.size() / 3);
  const Vector3d along =
      (Vector3d(sc.points[3 * k + 3], sc.points[3 * k + 4], sc.points[3 * k + 5]) - c).normalized();
  const Vector3d axis(f[4], f[5], f[6]);
  EXPECT_NEAR(axis.norm(), 1.0, 1e-5);
  EXPECT_GT(axis.dot(along), 0.9);
}

}  // namespace
}  // namespace tie_engine_test
