// Ponytail constraints (method S4.6): circles, the purple longitudinal directions, the blue spine
// part from C2 on and the green centripetal ring of C1, checked against brute force.
#include "ponytail_constraints.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "hair_engine.hpp"
#include "sphere_mesh.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace ponytail_constraints_test {

using namespace hairsketch;

namespace {

Grid unitGrid(int n) {
  Grid g;
  g.nx = g.ny = g.nz = n;
  g.origin = {0, 0, 0};
  g.step = 1;
  return g;
}

Eigen::Vector3d pos(const Grid& g, int p) {
  return g.position(p % g.nx, (p / g.nx) % g.ny, p / (g.nx * g.ny));
}

// Spine straight down from (10.2, 18, 9.7) to y = 2 (17 points); C1 at y = 15.3, r = 2.2;
// C2 at y = 11.3, r = 1.4; axis -y; tightness 0.6.
struct Tail {
  std::vector<double> spine;
  std::vector<double> params = {0.6, 2,    10.2, 15.3, 9.7, 0,  -1, 0,
                                2.2, 10.2, 11.3, 9.7,  0,   -2, 0,  1.4};  // axis need not be unit
  Tail() {
    for (int i = 0; i <= 16; ++i) spine.insert(spine.end(), {10.2, 18.0 - i, 9.7});
  }
  PonytailParams parse() const {
    PonytailParams p;
    EXPECT_TRUE(parsePonytailParams(params.data(), params.size(), p).ok());
    return p;
  }
};

}  // namespace

TEST(PonytailConstraints, RadiusSlopesAndBlueStart) {
  Tail t;
  const PonytailParams p = t.parse();
  ASSERT_EQ(p.circles.size(), 2u);
  EXPECT_LT((p.circles[1].axis - Eigen::Vector3d(0, -1, 0)).norm(), 1e-15);
  // r' = (1.4 - 2.2) / ((11.3 - 15.3) * -1) = -0.2 at both circles.
  const auto s = ponytailRadiusSlopes(p);
  EXPECT_NEAR(s[0], -0.2, 1e-14);
  EXPECT_NEAR(s[1], -0.2, 1e-14);
  // Spine point nearest C2's centre (y = 11.3) is y = 11, index 7.
  EXPECT_EQ(ponytailBlueStart(t.spine.data(), 17, p), 7u);
}

TEST(PonytailConstraints, GreenRingPurpleTubeAndBlueSpine) {
  const Grid g = unitGrid(21);
  Tail t;
  const PonytailParams p = t.parse();
  std::vector<Constraint> raw;
  std::vector<ConstraintColour> col;
  appendPonytailConstraints(g, t.spine.data(), 17, false, p, raw, &col);
  ASSERT_EQ(raw.size(), col.size());
  const PonytailCircle& c1 = p.circles[0];
  const double tube = std::sqrt(3.0) / 2;
  auto ringCoords = [&](const PonytailCircle& c, const Eigen::Vector3d& q, double& w, double& rho) {
    w = (q - c.centre).dot(c.axis);
    rho = ((q - c.centre) - w * c.axis).norm();
  };
  std::set<int> green, purple;
  int blue = 0;
  for (size_t k = 0; k < raw.size(); ++k) {
    const Eigen::Vector3d q = pos(g, raw[k].index);
    double w, rho;
    if (col[k] == ConstraintColour::Green) {
      ringCoords(c1, q, w, rho);
      EXPECT_LE(std::abs(w), 0.5);
      EXPECT_GE(rho, 1.3 * 2.2);
      EXPECT_LE(rho, 1.9 * 2.2);
      EXPECT_NEAR(raw[k].target.norm(), 0.6, 1e-14);
      EXPECT_LT((raw[k].target.normalized() - (c1.centre - q).normalized()).norm(), 1e-14);
      green.insert(raw[k].index);
    } else if (col[k] == ConstraintColour::Purple) {
      // Within the tube of one of the circles, along its meridian a + r' e.
      bool ok = false;
      for (const PonytailCircle& c : p.circles) {
        ringCoords(c, q, w, rho);
        if (std::hypot(w, rho - c.radius) > tube) continue;
        const Eigen::Vector3d e = ((q - c.centre) - w * c.axis) / rho;
        ok = ok || (raw[k].target - (c.axis - 0.2 * e).normalized()).norm() < 1e-12;
      }
      EXPECT_TRUE(ok) << "purple constraint " << k;
      purple.insert(raw[k].index);
    } else {
      // Blue: only from the segment starting at y = 11 downwards: midpoint y <= 10.5, so the
      // claimed cell has j <= 10 and corners j <= 11.
      EXPECT_LE(q.y(), 11.0);
      EXPECT_LT((raw[k].target - Eigen::Vector3d(0, -1, 0)).norm(), 1e-15);
      ++blue;
    }
  }
  EXPECT_EQ(blue, 8 * 9);  // 9 segments (y = 11 -> 2), 8 corners each, before merging
  // Brute force over the grid: the ring points (not in C1's tube) are exactly the green ones,
  // the tube points of either circle exactly the purple ones.
  std::set<int> ringRef, tubeRef;
  for (int p2 = 0; p2 < int(g.size()); ++p2) {
    const Eigen::Vector3d q = pos(g, p2);
    double w, rho;
    bool inTube = false;
    for (const PonytailCircle& c : p.circles) {
      ringCoords(c, q, w, rho);
      if (std::hypot(w, rho - c.radius) <= tube) inTube = true;
    }
    if (inTube) tubeRef.insert(p2);
    ringCoords(c1, q, w, rho);
    if (std::abs(w) <= 0.5 && rho >= 1.3 * 2.2 && rho <= 1.9 * 2.2 &&
        std::hypot(w, rho - 2.2) > tube)
      ringRef.insert(p2);
  }
  EXPECT_EQ(green, ringRef);
  EXPECT_EQ(purple, tubeRef);
  EXPECT_GT(green.size(), 20u);
}

TEST(PonytailConstraints, ParamValidation) {
  PonytailParams p;
  Tail t;
  auto code = [&](std::vector<double> v) {
    return parsePonytailParams(v.data(), v.size(), p).code;
  };
  EXPECT_EQ(code(t.params), StatusCode::Ok);
  std::vector<double> v = t.params;
  v.pop_back();
  EXPECT_EQ(code(v), StatusCode::InvalidInput);  // size != 2 + 7 m
  v = t.params;
  v[1] = 1.5;
  EXPECT_EQ(code(v), StatusCode::InvalidInput);  // non-integer count
  v[1] = 0;
  EXPECT_EQ(code({0.6, 0}), StatusCode::InvalidInput);  // no circles
  v = t.params;
  v[8] = 0;
  EXPECT_EQ(code(v), StatusCode::InvalidInput);  // radius 0
  v = t.params;
  v[5] = v[6] = v[7] = 0;
  EXPECT_EQ(code(v), StatusCode::InvalidInput);  // zero axis
  v = t.params;
  v[0] = INFINITY;
  EXPECT_EQ(code(v), StatusCode::NonFinite);
  EXPECT_EQ(code({0.6}), StatusCode::InvalidInput);
}

TEST(PonytailConstraints, StrandsGatherThroughC1OnASphereHead) {
  // Sphere head r = 1; a ponytail leaving the back of the head, backwards and down.
  Grid g;
  g.nx = g.ny = g.nz = 22;
  g.origin = {-2, -2.4, -2.4};
  g.step = 4.2 / 21;
  auto head = hairsketch_test::uvSphere(0, 0, 0, 1.0, 24, 48);
  hairsketch_test::markScalpAbove(head, -0.1);
  const Eigen::Vector3d s0(0, 0.45, -0.95), dir = Eigen::Vector3d(0, -0.6, -0.8).normalized();
  std::vector<double> spine;
  for (int i = 0; i < 9; ++i) {
    const Eigen::Vector3d p = s0 + i * g.step * dir;
    spine.insert(spine.end(), {p.x(), p.y(), p.z()});
  }
  const Eigen::Vector3d c1 = s0 + 2 * g.step * dir, c2 = s0 + 4 * g.step * dir;
  const double r1 = 0.3;
  std::vector<double> params = {0.6, 2,      c1.x(), c1.y(), c1.z(),  dir.x(), dir.y(), dir.z(),
                                r1,  c2.x(), c2.y(), c2.z(), dir.x(), dir.y(), dir.z(), 0.22};
  std::vector<uint32_t> start = {0, 9}, pstart = {0, uint32_t(params.size())};
  std::vector<uint8_t> kinds = {2}, extend = {1};
  CurveSetView v{spine.data(), 9, start.data(), 1, kinds.data(), extend.data()};
  v.params = params.data();
  v.paramCount = params.size();
  v.paramStart = pstart.data();
  HairEngine e;
  ASSERT_TRUE(e.setGrid(g, kDefaultOmega, "cg").ok());
  ASSERT_TRUE(e.setScalp(head.positions.data(), head.positions.size() / 3, head.indices.data(),
                         head.indices.size() / 3, head.scalp.data(), Eigen::Vector3d::Zero())
                  .ok());
  ASSERT_TRUE(e.setCurves(v).ok());
  ASSERT_TRUE(e.solve().ok());
  RootParams rp;
  rp.thetaStepDeg = 8;
  rp.phiStepDeg = 8;
  rp.seed = 5;
  GrowthParams gp;
  gp.maxLength = 3;
  ASSERT_TRUE(e.grow(rp, gp).ok());
  // Strands rooted within 0.5 of the ponytail's root: how many cross C1's plane inside 1.2 r1?
  const Strands& s = e.strands();
  int near = 0, through = 0;
  for (size_t k = 0; k + 1 < s.strandStart.size(); ++k) {
    const float* P = s.points.data();
    const Eigen::Vector3d root(P[3 * s.strandStart[k]], P[3 * s.strandStart[k] + 1],
                               P[3 * s.strandStart[k] + 2]);
    if ((root - s0).norm() > 0.5) continue;
    ++near;
    for (uint32_t q = s.strandStart[k]; q + 1 < s.strandStart[k + 1]; ++q) {
      const Eigen::Vector3d a(P[3 * q], P[3 * q + 1], P[3 * q + 2]);
      const Eigen::Vector3d b(P[3 * q + 3], P[3 * q + 4], P[3 * q + 5]);
      const double da = (a - c1).dot(dir), db = (b - c1).dot(dir);
      if (da <= 0 && db > 0) {
        const Eigen::Vector3d x = a + (b - a) * (da / (da - db));
        if ((x - c1).norm() <= 1.2 * r1) ++through;
        break;
      }
    }
  }
  ASSERT_GT(near, 5);
  EXPECT_GE(through, near * 3 / 4) << through << " of " << near;
}

}  // namespace ponytail_constraints_test
