// Natural fall (hair_fall.hpp): the prior's directions, the curves' reach, growth that ends hair
// where its curve ends, and the engine with the setting off (the paper's method, bit for bit).
#include "hair_fall.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "box_grid.hpp"
#include "hair_engine.hpp"
#include "sphere_mesh.hpp"
#include "strand_growth.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace hair_fall_test {

using namespace hairsketch;

namespace {

using hairsketch_test::boxGrid;

// Hand-computed remaining length of a straight curve from a to b at x: L - s(x) - overshoot.
double straightRemaining(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& x) {
  const Eigen::Vector3d t = (b - a).normalized();
  const double L = (b - a).norm();
  const double u = (x - a).dot(t);
  return L - std::clamp(u, 0.0, L) - std::max(0.0, u - L);
}

// The reach on lattice g itself (buildCurveReach would pick reachGrid's coarser cells).
CurveReach reachOn(const Grid& g, const std::vector<ReachCurve>& curves) {
  std::vector<CurveFootprint> fp(curves.size());
  std::vector<const CurveFootprint*> parts;
  for (size_t c = 0; c < curves.size(); ++c) {
    curveFootprint(g, curves[c], fp[c]);
    parts.push_back(&fp[c]);
  }
  CurveReach r;
  combineReach(g, parts, r);
  return r;
}

}  // namespace

TEST(CurveReach, OneStraightCurveGivesItsRemainingLengthAndOvershoot) {
  const Grid g = boxGrid(21, -1, 1);
  std::vector<double> pts;
  const Eigen::Vector3d a(-0.6, 0.1, 0), b(0.4, 0.1, 0);
  for (int k = 0; k <= 10; ++k) {
    const Eigen::Vector3d p = a + (b - a) * (k / 10.0);
    pts.insert(pts.end(), {p.x(), p.y(), p.z()});
  }
  const CurveReach r = reachOn(g, {{pts.data(), 11, false}});
  ASSERT_EQ(r.remaining.size(), size_t(g.size()));
  int checked = 0;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const Eigen::Vector3d x = g.position(i, j, k);
        const Eigen::Vector3d t = (b - a).normalized();
        const double u = std::clamp((x - a).dot(t), 0.0, (b - a).norm());
        const double d = (x - (a + u * t)).norm();
        const size_t p = size_t(g.index(i, j, k));
        if (d > kReachFar) {
          EXPECT_EQ(r.far[p], 1.f);
          continue;
        }
        EXPECT_NEAR(r.remaining[p], straightRemaining(a, b, x), 1e-5);
        if (d <= kReachNear) EXPECT_NEAR(r.far[p], 0.f, 1e-6);
        ++checked;
      }
  EXPECT_GT(checked, 1000);
}

TEST(CurveReach, TwoCurvesBlendTheirLengthsByDistance) {
  const Grid g = boxGrid(21, -1, 1);
  // two parallel curves along x at z = -0.2 and z = +0.2, ending at x = 0 and x = 0.5
  std::vector<double> c1, c2;
  for (int k = 0; k <= 10; ++k) {
    const double x = -0.8 + 0.08 * k;
    c1.insert(c1.end(), {x, 0, -0.2});
    const double x2 = -0.8 + 0.13 * k;
    c2.insert(c2.end(), {x2, 0, 0.2});
  }
  const CurveReach r = reachOn(g, {{c1.data(), 11, false}, {c2.data(), 11, false}});
  // midway between them at x = -0.4 the two remaining lengths (0.4 and 0.9) weigh equally
  const size_t mid = size_t(g.index(4, 10, 10));  // (-0.6, 0, 0)
  EXPECT_NEAR(r.remaining[mid], 0.5 * ((0.0 + 0.6) + (0.5 + 0.6)), 1e-5);
  // on curve 1 its own length dominates: exp(-0.4^2 / (2 sigma^2)) weighs the other
  const size_t on1 = size_t(g.index(4, 10, 8));  // (-0.6, 0, -0.2)
  const double w = std::exp(-0.16 / (2 * kReachSigma * kReachSigma));
  EXPECT_NEAR(r.remaining[on1], (0.6 + w * 1.1) / (1 + w), 1e-5);
}

TEST(CurveReach, GrowsOnCurvesNeverEndHair) {
  const Grid g = boxGrid(11, -1, 1);
  std::vector<double> pts{-0.5, 0, 0, 0, 0, 0};
  const CurveReach r = reachOn(g, {{pts.data(), 2, true}});
  EXPECT_GT(r.remaining[size_t(g.index(8, 5, 5))], 10.f);  // past its end, still long
}

TEST(CurveReach, AFringesLengthHoldsBesideItInFrontOfTheFaceOnly) {
  // the head's centre at the origin, the face towards +z; a bang at x = 0 from y = 0.6 down to
  // 0.2, a long stroke 12 cm across at x = 1.2, both at depth z (0.9: in front of the face; 0:
  // beside the head); points 4 cm beside the bang, past its reach, below its end
  const Grid g = boxGrid(41, -2, 2);
  const Eigen::Vector3d centre(0, 0, 0);
  for (const double z : {0.9, 0.0}) {
    std::vector<double> longPts, bangPts;
    for (int k = 0; k <= 22; ++k) longPts.insert(longPts.end(), {1.2, 0.6 - 0.1 * k, z});
    for (int k = 0; k <= 4; ++k) bangPts.insert(bangPts.end(), {0.0, 0.6 - 0.1 * k, z});
    std::vector<ReachCurve> curves(2);
    curves[0].points = longPts.data();
    curves[0].count = 23;
    curves[0].setsLength = true;
    curves[1].points = bangPts.data();
    curves[1].count = 5;
    curves[1].setsLength = true;
    curves[1].fringe = true;
    CurveReach reach;
    buildCurveReach(g, curves, reach, &centre);
    for (const float y : {0.1f, 0.0f}) {
      const Eigen::Vector3d x(0.4, y, z);
      const double r = reachRemaining(reach, float(x.x()), y, float(z), 3.f);
      // by hand: each stroke's remaining length there (the bang's is past its end: below 0)
      const double bang = straightRemaining({0, 0.6, z}, {0, 0.2, z}, x);
      const double stroke = straightRemaining({1.2, 0.6, z}, {1.2, -1.6, z}, x);
      std::printf(
          "4 cm beside a bang at depth %.1f, y %.1f: remaining %.3f (bang %.3f, long %.3f)\n", z, y,
          r, bang, stroke);
      if (z > 0)  // in front of the face: the bang's (the long stroke weighs e^-(0.8^2-0.4^2)/2s^2)
        EXPECT_NEAR(r, bang, 0.08);
      else  // beside the head: the long stroke's
        EXPECT_NEAR(r, stroke, 0.02);
    }
  }
}

TEST(FallGrowth, AStrandAlongACurveEndsWhereTheCurveEnds) {
  const Grid g = boxGrid(21, -1, 1);
  // a uniform field along +x; a curve from the root to x = 0.3; the strand would run to the box
  std::vector<float> field(size_t(g.size()) * 3, 0.f);
  for (size_t p = 0; p < size_t(g.size()); ++p) field[3 * p] = 1.f;
  std::vector<double> pts;
  for (int k = 0; k <= 8; ++k) pts.insert(pts.end(), {-0.5 + 0.1 * k, 0.0, 0.0});
  CurveReach r;
  buildCurveReach(g, {{pts.data(), 9, false}}, r);
  const std::vector<Eigen::Vector3f> roots{{-0.5f, 0.f, 0.f}, {-0.5f, 0.f, 0.2f}, {0.6f, 0, 0}};
  GrowthParams gp;
  gp.maxLength = 10;
  gp.maxSegments = 400;
  Strands plain, fall;
  ASSERT_TRUE(growStrands(g, field, roots, gp, plain).ok());
  ASSERT_TRUE(growStrands(g, field, roots, gp, fall, size_t(1) << 20, nullptr, &r).ok());
  auto tipX = [](const Strands& s, size_t k) {
    return s.points[3 * size_t(s.strandStart[k + 1] - 1)];
  };
  EXPECT_NEAR(tipX(plain, 0), 1.0, 0.06);  // the paper's rules: out to the box
  // the strand along the curve and one 2 cm beside it end within a growth step of x = 0.3
  const float step = float(0.5 * g.step);
  EXPECT_NEAR(tipX(fall, 0), 0.3, step);
  EXPECT_NEAR(tipX(fall, 1), 0.3, step);
  // rooted past the end: a short stub (kPastEndLength) there
  EXPECT_LE(tipX(fall, 2) - 0.6f, kPastEndLength + 1e-6);
}

TEST(FallDirections, UnitHangingFieldCombedAlongTheHead) {
  const Grid g = boxGrid(25, -2, 2);
  hairsketch_test::Mesh m = hairsketch_test::uvSphere(0, 0, 0, 1.0, 24, 48);
  hairsketch_test::markScalpAbove(m, 0.2);
  HeadDistance head;
  const HeadMeshView view{m.positions.data(), m.positions.size() / 3, m.indices.data(),
                          m.indices.size() / 3, m.scalp.data()};
  ASSERT_TRUE(head.build(view).ok());
  const Field G = fallDirections(g, head, Eigen::Vector3d::Zero());
  ASSERT_EQ(G.rows(), g.size());
  for (int p = 0; p < G.rows(); ++p) ASSERT_NEAR(G.row(p).norm(), 1.0, 1e-9);
  // far from the head (a corner below it): straight down
  EXPECT_NEAR(G(g.index(0, 0, 0), 1), -1.0, 1e-9);
  // on the side of the head at its equator (x = 1): down, along the surface
  const Eigen::Vector3d side = G.row(g.index(18, 12, 12)).transpose();  // (1, 0, 0)
  EXPECT_LT(side.y(), -0.9);
  // near the top: combed outward and down over the head, never into it
  for (int i = 0; i < g.nx; ++i)
    for (int k = 0; k < g.nz; ++k) {
      const Eigen::Vector3d x = g.position(i, 18, k);  // y = 1
      const double r = x.norm();
      if (r < 1.0 || r > 1.2) continue;
      const Eigen::Vector3d v = G.row(g.index(i, 18, k)).transpose();
      EXPECT_GT(v.dot(x / r), -0.05) << "at " << x.transpose();
    }
}

// Finished edges open the face: off the head in front of it (below the front hairline's height,
// near straight ahead) g turns to the nearer side, down at most 1 against the side's 1.5 (the
// unit vector (±1.5, -1, 0)/1.80 = ±0.83 sideways); beside the head, behind it and above the
// hairline's height nothing changes; without openFace nothing changes anywhere.
TEST(FallDirections, OpenFaceTurnsHairAsideInFrontOfTheFace) {
  const Grid g = boxGrid(25, -2, 2);
  hairsketch_test::Mesh m = hairsketch_test::uvSphere(0, 0, 0, 1.0, 24, 48);
  hairsketch_test::markScalpAbove(m, 0.2);
  HeadDistance head;
  const HeadMeshView view{m.positions.data(), m.positions.size() / 3, m.indices.data(),
                          m.indices.size() / 3, m.scalp.data()};
  ASSERT_TRUE(head.build(view).ok());
  const Field plain = fallDirections(g, head, Eigen::Vector3d::Zero());
  const Field open = fallDirections(g, head, Eigen::Vector3d::Zero(), true);
  const double aside = 1.5 / std::sqrt(1.5 * 1.5 + 1);
  int checked = 0;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const int p = g.index(i, j, k);
        ASSERT_NEAR(open.row(p).norm(), 1.0, 1e-9);
        const Eigen::Vector3d x = g.position(i, j, k);
        const double r = x.norm();
        const double az = std::atan2(std::abs(x.x()), x.z());
        if (x.z() > 0 && r > 1.3 && az < 0.4 && x.y() < 0.2 && x.y() > -1.2 &&
            std::abs(x.x()) > 0.05) {
          // in front of the face: aside, to the nearer side
          EXPECT_NEAR(open(p, 0), x.x() > 0 ? aside : -aside, 1e-9) << "at " << x.transpose();
          ++checked;
        } else if (x.z() <= 0 || x.y() > kFaceTop || az > kFaceHalfAngle) {
          EXPECT_NEAR((open.row(p) - plain.row(p)).norm(), 0.0, 1e-12) << "at " << x.transpose();
        }
      }
  EXPECT_GT(checked, 10);
}

namespace {

struct FallScene {
  Grid grid = boxGrid(16, -2, 2);
  hairsketch_test::Mesh head = hairsketch_test::uvSphere(0, 0, 0, 1.0, 24, 48);
  std::vector<double> points;
  std::vector<uint32_t> start;
  std::vector<uint8_t> kinds{0}, extend{1};
  FallScene() {
    hairsketch_test::markScalpAbove(head, 0.2);
    for (int i = 0; i <= 12; ++i) {
      const double a = 0.2 + 0.2 * i;
      points.insert(points.end(), {0, 1.05 * std::cos(a), -1.05 * std::sin(a)});
    }
    start = {0, uint32_t(points.size() / 3)};
  }
  CurveSetView curves(size_t count = 1) const {
    return {points.data(), count ? points.size() / 3 : 0, start.data(), count, kinds.data(),
            extend.data()};
  }
  Status setup(HairEngine& e, bool fall, const std::string& solver = "cg") const {
    Status st = e.setGrid(grid, kDefaultOmega, solver);
    if (st.ok() && fall) st = e.setFall(true);
    if (st.ok())
      st = e.setScalp(head.positions.data(), head.positions.size() / 3, head.indices.data(),
                      head.indices.size() / 3, head.scalp.data(), Eigen::Vector3d::Zero());
    if (st.ok()) st = e.setCurves(curves());
    if (st.ok()) st = e.solve();
    return st;
  }
};

RootParams someRoots() {
  RootParams rp;
  rp.thetaStepDeg = 6;
  rp.phiStepDeg = 6;
  rp.seed = 3;
  return rp;
}

}  // namespace

TEST(FallEngine, OffIsThePapersMethod) {
  const FallScene s;
  HairEngine plain, on, toggled;
  ASSERT_TRUE(s.setup(plain, false, "exact").ok());
  ASSERT_TRUE(s.setup(on, true, "exact").ok());
  ASSERT_TRUE(s.setup(toggled, true, "exact").ok());
  // the prior changes the field
  EXPECT_GT((on.field() - plain.field()).norm(), 1e-3 * plain.field().norm());
  // turned off again: the prior is cleared and the curves give the paper's field (to rounding:
  // the factor was refactored)
  ASSERT_TRUE(toggled.setFall(false).ok());
  ASSERT_TRUE(toggled.setCurves(s.curves()).ok());
  ASSERT_TRUE(toggled.solve().ok());
  EXPECT_LT((toggled.field() - plain.field()).norm(), 1e-9 * plain.field().norm());
  // an engine told "off" before anything grows the same bytes as one never told
  HairEngine told;
  ASSERT_TRUE(told.setFall(false).ok());
  ASSERT_TRUE(s.setup(told, false, "exact").ok());
  GrowthParams gp;
  gp.maxLength = 3;
  ASSERT_TRUE(plain.grow(someRoots(), gp).ok());
  ASSERT_TRUE(told.grow(someRoots(), gp).ok());
  EXPECT_EQ(plain.strands().points, told.strands().points);
}

TEST(FallEngine, NoCurvesIsBaldAndFarHairHangs) {
  FallScene s;
  HairEngine e;
  ASSERT_TRUE(s.setup(e, true).ok());
  ASSERT_TRUE(e.setCurves(s.curves(0)).ok());
  ASSERT_TRUE(e.solve().ok());
  GrowthParams gp;
  gp.maxLength = 3;
  ASSERT_TRUE(e.grow(someRoots(), gp).ok());
  EXPECT_EQ(e.strands().points.size(), 3 * (e.strands().strandStart.size() - 1));  // roots only
  // one curve down the back: the hair on the far side (front, +z) hangs down
  ASSERT_TRUE(e.setCurves(s.curves()).ok());
  ASSERT_TRUE(e.solve().ok());
  ASSERT_TRUE(e.grow(someRoots(), gp).ok());
  const Strands& st = e.strands();
  int front = 0, hanging = 0;
  for (size_t k = 0; k + 1 < st.strandStart.size(); ++k) {
    const uint32_t a = st.strandStart[k], b = st.strandStart[k + 1];
    if (b < a + 4) continue;
    const float* r = &st.points[3 * size_t(a)];
    if (!(r[2] > 0.5f && r[1] > 0.3f && r[1] < 0.7f)) continue;  // front, above the equator
    ++front;
    const float* q = &st.points[3 * size_t(b - 1)];
    const Eigen::Vector3f d(q[0] - r[0], q[1] - r[1], q[2] - r[2]);
    if (d.normalized().y() < -0.7f) ++hanging;
  }
  ASSERT_GT(front, 5);
  EXPECT_GE(hanging, front * 8 / 10) << hanging << " of " << front;
}

}  // namespace hair_fall_test
