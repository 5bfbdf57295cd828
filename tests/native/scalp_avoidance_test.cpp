// Scalp penetration avoidance (method S4.7) on a sphere "head", and the curve-set dispatch of the
// new kinds and explicit extra constraints.
#include "scalp_avoidance.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "curve_set.hpp"
#include "hair_engine.hpp"
#include "sphere_mesh.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace scalp_avoidance_test {

using namespace hairsketch;

namespace {

Grid sphereGrid() {
  Grid g;
  g.nx = g.ny = g.nz = 16;
  g.origin = {-2, -2, -2};
  g.step = 4.0 / 15;
  return g;
}

Eigen::Vector3d pos(const Grid& g, int p) {
  return g.position(p % g.nx, (p / g.nx) % g.ny, p / (g.nx * g.ny));
}

HeadMeshView view(const hairsketch_test::Mesh& m) {
  return {m.positions.data(), m.positions.size() / 3, m.indices.data(), m.indices.size() / 3,
          m.scalp.data()};
}

}  // namespace

TEST(ScalpAvoidance, NoInwardDirectionNearASphereScalp) {
  const Grid g = sphereGrid();
  auto head = hairsketch_test::uvSphere(0, 0, 0, 1.0, 24, 48);
  hairsketch_test::markScalpAbove(head, 0.2);
  // A field pointing into the sphere, with a swirl so that projections are not zero.
  Field T(g.size(), 3);
  for (int p = 0; p < int(g.size()); ++p) {
    const Eigen::Vector3d q = pos(g, p);
    const Eigen::Vector3d r =
        q.norm() > 0 ? Eigen::Vector3d(q.normalized()) : Eigen::Vector3d(0, 1, 0);
    T.row(p) =
        (-r + 0.5 * Eigen::Vector3d(0, 1, 0).cross(q) + Eigen::Vector3d(0.1, 0, 0)).transpose();
  }
  ConstraintSet out;
  ScalpAvoidanceStats st;
  ASSERT_TRUE(scalpAvoidanceConstraints(g, T, view(head), {}, out, &st).ok());
  ASSERT_GT(out.size(), 50u);
  EXPECT_EQ(int(out.size()), st.nearPoints - st.skipped);
  EXPECT_GT(st.projected, 50);
  std::vector<bool> got(size_t(g.size()), false);
  for (size_t k = 0; k < out.size(); ++k) {
    if (k > 0) EXPECT_LT(out[k - 1].index, out[k].index);  // sorted, unique
    const Eigen::Vector3d q = pos(g, out[k].index);
    EXPECT_NEAR(out[k].target.norm(), 0.3, 1e-12);
    EXPECT_GT(q.norm(), 0.99);                       // outside the head
    EXPECT_LT(q.norm(), 1.0 + 1.5 * g.step + 1e-9);  // within the band
    // No inward direction: against the true sphere normal (the mesh is faceted, hence 0.02),
    // wherever the nearest scalp point is not on the hairline (scalp: centroid y > 0.2).
    if (q.y() / q.norm() > 0.3)
      EXPECT_GE(out[k].target.normalized().dot(q.normalized()), -0.02) << "at " << q.transpose();
    got[size_t(out[k].index)] = true;
  }
  // Every grid point well inside the band over the scalp (away from the hairline) is returned.
  for (int p = 0; p < int(g.size()); ++p) {
    const Eigen::Vector3d q = pos(g, p);
    const double r = q.norm();
    if (r > 1.01 && r < 1.0 + 1.4 * g.step && q.y() / r > 0.5) EXPECT_TRUE(got[size_t(p)]) << p;
  }
  // Measured against the whole head, every near point is covered and none points inward.
  ScalpAvoidanceParams whole;
  whole.wholeHead = true;
  ASSERT_TRUE(scalpAvoidanceConstraints(g, T, view(head), whole, out, &st).ok());
  int all = 0;
  for (int p = 0; p < int(g.size()); ++p) {
    const double r = pos(g, p).norm();
    all += r > 1.01 && r < 1.0 + 1.4 * g.step;
  }
  EXPECT_GE(int(out.size()), all);
  for (const Constraint& c : out) {
    const Eigen::Vector3d q = pos(g, c.index);
    EXPECT_GE(c.target.normalized().dot(q.normalized()), -0.02) << "at " << q.transpose();
  }
  // insideToo: grid points inside the head within the band are constrained as well, and none
  // of them points inward either.
  ScalpAvoidanceParams inside = whole;
  inside.insideToo = true;
  ASSERT_TRUE(scalpAvoidanceConstraints(g, T, view(head), inside, out, &st).ok());
  int under = 0;
  for (const Constraint& c : out) {
    const Eigen::Vector3d q = pos(g, c.index);
    if (q.norm() < 0.99) ++under;
    EXPECT_GT(q.norm(), 1.0 - 1.5 * g.step - 0.02);
    // against the true sphere normal: the faceted mesh's normal at the nearest point differs a
    // little more from the radial direction of a point inside, hence 0.03
    EXPECT_GE(c.target.normalized().dot(q.normalized()), -0.03) << "at " << q.transpose();
  }
  EXPECT_GT(under, 50);
  // A zero field has no direction to keep: every near point is skipped, nothing returned.
  T.setZero();
  ASSERT_TRUE(scalpAvoidanceConstraints(g, T, view(head), {}, out, &st).ok());
  EXPECT_TRUE(out.empty());
  EXPECT_GT(st.nearPoints, 50);
  EXPECT_EQ(st.skipped, st.nearPoints);
  // Bad input.
  Field wrong(3, 3);
  EXPECT_EQ(scalpAvoidanceConstraints(g, wrong, view(head), {}, out).code,
            StatusCode::InvalidInput);
}

TEST(ScalpAvoidance, EngineResolveWithExtrasPointsNoWhereInward) {
  Grid g = sphereGrid();
  auto head = hairsketch_test::uvSphere(0, 0, 0, 1.0, 24, 48);
  hairsketch_test::markScalpAbove(head, 0.2);
  // A stream curve diving straight through the top of the head, to make inward directions.
  std::vector<double> pts;
  for (int i = 0; i <= 12; ++i) pts.insert(pts.end(), {0.35, 1.9 - 0.27 * i, 0.1});
  std::vector<uint32_t> start = {0, 13};
  std::vector<uint8_t> kinds = {0}, extend = {0};
  CurveSetView v{pts.data(), 13, start.data(), 1, kinds.data(), extend.data()};
  HairEngine e;
  ASSERT_TRUE(e.setGrid(g, kDefaultOmega, "cg").ok());
  ConstraintSet extra;
  EXPECT_EQ(e.scalpAvoidance({}, extra).code, StatusCode::NotReady);  // no scalp yet
  ASSERT_TRUE(e.setScalp(head.positions.data(), head.positions.size() / 3, head.indices.data(),
                         head.indices.size() / 3, head.scalp.data(), Eigen::Vector3d::Zero())
                  .ok());
  ASSERT_TRUE(e.setCurves(v).ok());
  EXPECT_EQ(e.scalpAvoidance({}, extra).code, StatusCode::NotReady);  // not solved
  ASSERT_TRUE(e.solve().ok());
  ASSERT_TRUE(e.scalpAvoidance({}, extra).ok());
  ASSERT_GT(extra.size(), 50u);
  std::vector<int32_t> index;
  std::vector<double> target;
  for (const Constraint& c : extra) {
    index.push_back(c.index);
    target.insert(target.end(), {c.target.x(), c.target.y(), c.target.z()});
  }
  v.extraIndex = index.data();
  v.extraTarget = target.data();
  v.extraCount = index.size();
  ASSERT_TRUE(e.setCurves(v).ok());
  ASSERT_TRUE(e.solve().ok());
  // At each avoidance point not shared with the curve, the solved field is not inward.
  int checked = 0;
  for (const Constraint& c : extra) {
    const Eigen::Vector3d q = pos(g, c.index);
    const Eigen::Vector3d f = e.field().row(c.index).transpose();
    if ((q - Eigen::Vector3d(0.35, q.y(), 0.1)).norm() < 2 * g.step) continue;  // near curve
    ++checked;
    EXPECT_GE(f.normalized().dot(q.normalized()), -0.05) << "at " << q.transpose();
  }
  EXPECT_GT(checked, 30);
}

TEST(CurveSetDispatch, KindsParamBlocksAndExtras) {
  Grid g = sphereGrid();
  // Curve 0 stream (2 points), curve 1 dividing (3 points), curve 2 ponytail (4 points).
  std::vector<double> pts = {0,     1.2, 0,    0, 1.2, -0.27,                 // stream
                             -0.27, 1.0, 0,    0, 1.0, 0,     0.27, 1.0,  0,  // dividing
                             0,     0.5, -1.1, 0, 0.2, -1.2,  0,    -0.1, -1.3, 0, -0.4, -1.3};
  std::vector<uint32_t> start = {0, 2, 5, 9};
  std::vector<uint8_t> kinds = {0, 1, 2}, extend = {1, 0, 1};
  std::vector<double> params = {1,   0.5, 0, 0.2, 0,    1, 0,  0, 1,
                                0,   0,   1, 0,                          // dividing: 4 + 9
                                0.6, 1,   0, 0.2, -1.2, 0, -1, 0, 0.3};  // ponytail: 2 + 7
  std::vector<uint32_t> pstart = {0, 0, 13, 22};
  std::vector<int32_t> xi = {5, 5};
  std::vector<double> xt = {0, 0.3, 0, 0, 0.1, 0};
  CurveSetView v{pts.data(), 9, start.data(), 3, kinds.data(), extend.data()};
  v.params = params.data();
  v.paramCount = params.size();
  v.paramStart = pstart.data();
  v.extraIndex = xi.data();
  v.extraTarget = xt.data();
  v.extraCount = 2;
  ConstraintSet out;
  ASSERT_TRUE(curvesToConstraints(g, v, out).ok());
  EXPECT_GT(out.size(), 50u);
  bool found = false;
  for (const Constraint& c : out)
    if (c.index == 5) {
      found = true;
      EXPECT_LT((c.target - Eigen::Vector3d(0, 0.2, 0)).norm(), 1e-15);  // averaged extras
    }
  EXPECT_TRUE(found);
  // Colours: one per merged constraint; every kind is present; the extras' point keeps the
  // colour of the first raw constraint there.
  std::vector<uint8_t> colours;
  ConstraintSet again;
  ASSERT_TRUE(curvesToConstraints(g, v, again, &colours).ok());
  ASSERT_EQ(colours.size(), again.size());
  int seen[5] = {0, 0, 0, 0, 0};
  for (uint8_t c : colours) {
    ASSERT_LT(c, 5);
    ++seen[c];
  }
  for (int c = 0; c < 5; ++c) EXPECT_GT(seen[c], 0) << "colour " << c;
  for (size_t k = 0; k < again.size(); ++k)
    if (colours[k] == uint8_t(ConstraintColour::Green))
      EXPECT_NEAR(again[k].target.norm(), 0.6, 1e-12);
  auto expectError = [&](const char* needle, StatusCode code = StatusCode::InvalidInput) {
    const Status s = curvesToConstraints(g, v, out);
    EXPECT_EQ(s.code, code) << needle;
    EXPECT_NE(s.message.find(needle), std::string::npos) << s.message;
  };
  // Wrong block sizes name the curve.
  pstart = {0, 0, 12, 22};
  expectError("curve 1 (dividing)");
  pstart = {0, 1, 13, 22};
  expectError("curve 0 (stream)");
  pstart = {0, 0, 13, 22};
  params[21] = std::nan("");
  expectError("curve 2 (ponytail)", StatusCode::NonFinite);
  params[21] = 0.3;
  params[4] = INFINITY;
  expectError("curve 1 (dividing)", StatusCode::NonFinite);
  params[4] = 0;
  pstart = {0, 0, 13, 21};
  expectError("paramStart");
  pstart = {0, 0, 13, 22};
  // Extras out of range or not finite.
  xi[1] = int32_t(g.size());
  expectError("extra constraint 1");
  xi[1] = 5;
  xt[0] = std::nan("");
  expectError("extra constraint 0", StatusCode::NonFinite);
  xt[0] = 0;
  // No parameter blocks at all: the dividing curve has nothing to read.
  v.paramStart = nullptr;
  v.params = nullptr;
  v.paramCount = 0;
  expectError("curve 1 (dividing)");
  ASSERT_TRUE(curvesToConstraints(g, v, out).code == StatusCode::InvalidInput);
}

}  // namespace scalp_avoidance_test
