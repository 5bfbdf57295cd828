// The engine end to end: sphere scalp, one stream curve, solve, grow.
#include "hair_engine.hpp"

#include <gtest/gtest.h>

#include "sphere_mesh.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace hair_engine_test {

using namespace hairsketch;

namespace {

struct Scene {
  Grid grid;
  hairsketch_test::Mesh head = hairsketch_test::uvSphere(0, 0, 0, 1.0, 24, 48);
  std::vector<double> points;
  std::vector<uint32_t> start;
  std::vector<uint8_t> kinds{0}, extend{1};
  Scene() {
    grid.nx = 16;
    grid.ny = 16;
    grid.nz = 16;
    grid.origin = {-2, -2, -2};
    grid.step = 4.0 / 15;
    hairsketch_test::markScalpAbove(head, 0.2);
    // A curve from the top of the head, down the back (-z) and beyond.
    for (int i = 0; i <= 12; ++i) {
      const double a = 0.2 + 0.2 * i;
      points.insert(points.end(), {0, 1.05 * std::cos(a), -1.05 * std::sin(a)});
    }
    start = {0, uint32_t(points.size() / 3)};
  }
  CurveSetView curves() const {
    return {points.data(), points.size() / 3, start.data(), 1, kinds.data(), extend.data()};
  }
};

Status setup(HairEngine& e, const Scene& s) {
  Status st = e.setGrid(s.grid, kDefaultOmega, "cg");
  if (!st.ok()) return st;
  st = e.setScalp(s.head.positions.data(), s.head.positions.size() / 3, s.head.indices.data(),
                  s.head.indices.size() / 3, s.head.scalp.data(), Eigen::Vector3d::Zero());
  if (!st.ok()) return st;
  st = e.setCurves(s.curves());
  if (!st.ok()) return st;
  return e.solve();
}

}  // namespace

TEST(HairEngine, CurveToStrandsIsDeterministicPerSeed) {
  Scene s;
  HairEngine e;
  ASSERT_TRUE(setup(e, s).ok());
  EXPECT_GT(e.constraints().size(), 50u);
  EXPECT_EQ(e.stats().method, "cg");
  // Near the curve's middle the field follows the tangent.
  const int mid = 6;
  const Eigen::Vector3d a(&s.points[3 * mid]), b(&s.points[3 * mid + 3]);
  const Eigen::Vector3d t = (b - a).normalized(), m = 0.5 * (a + b);
  const Eigen::Vector3d u = (m - s.grid.origin) / s.grid.step;
  const Eigen::Vector3d v =
      e.field().row(s.grid.index(int(u.x()), int(u.y()), int(u.z()))).transpose();
  EXPECT_GT(v.normalized().dot(t), 0.95);

  RootParams rp;
  rp.thetaStepDeg = 6;
  rp.phiStepDeg = 6;
  rp.seed = 3;
  GrowthParams gp;
  gp.maxLength = 3;
  ASSERT_TRUE(e.grow(rp, gp).ok());
  const Strands first = e.strands();
  ASSERT_GT(first.strandStart.size(), 100u);
  EXPECT_GT(first.points.size() / 3, 3 * (first.strandStart.size() - 1));  // strands grew
  ASSERT_TRUE(e.grow(rp, gp).ok());
  EXPECT_EQ(e.strands().points, first.points);
  // A fresh engine with the same inputs grows the same hair.
  HairEngine e2;
  ASSERT_TRUE(setup(e2, s).ok());
  ASSERT_TRUE(e2.grow(rp, gp).ok());
  EXPECT_EQ(e2.strands().points, first.points);
  EXPECT_EQ(e2.strands().strandStart, first.strandStart);
  // A capped growth (a preview) takes an even stride of the same roots: its strands are exactly
  // the full growth's strands k * total / cap, and growing in full again gives the first hair.
  {
    RootParams capped = rp;
    capped.maxStrands = 37;
    ASSERT_TRUE(e.grow(capped, gp).ok());
    const Strands few = e.strands();
    const size_t total = first.strandStart.size() - 1, m = 37;
    ASSERT_EQ(few.strandStart.size(), m + 1);
    for (size_t k = 0; k < m; ++k) {
      const size_t src = k * total / m;
      const size_t n = few.strandStart[k + 1] - few.strandStart[k];
      ASSERT_EQ(n, first.strandStart[src + 1] - first.strandStart[src]) << k;
      for (size_t q = 0; q < 3 * n; ++q)
        ASSERT_EQ(few.points[3 * few.strandStart[k] + q],
                  first.points[3 * first.strandStart[src] + q]);
    }
    ASSERT_TRUE(e.grow(rp, gp).ok());
    EXPECT_EQ(e.strands().points, first.points);
  }
  rp.seed = 4;
  ASSERT_TRUE(e.grow(rp, gp).ok());
  EXPECT_NE(e.strands().points, first.points);
}

TEST(HairEngine, TheHeadsMemoryCheckCoversWhatTheHeadKeeps) {
  Scene s;
  HairEngine e;
  ASSERT_TRUE(setup(e, s).ok());
  const size_t nv = s.head.positions.size() / 3, nt = s.head.indices.size() / 3;
  const HeadMeshView view{s.head.positions.data(), nv, s.head.indices.data(), nt,
                          s.head.scalp.data()};
  const HairEngine::HeadStats st = e.headStats();
  EXPECT_GT(st.bytes, 12 * nv + 13 * nt);  // at least the mesh copy and its mask
  EXPECT_GE(ScalpSampler::estimateBytes(nv, nt) + HeadDistance::estimateBytes(view),
            double(st.bytes));
  EXPECT_GT(st.distanceCells, 0u);
}

TEST(HairEngine, ErrorsAreStatusesNotCrashes) {
  Scene s;
  HairEngine e;
  EXPECT_FALSE(e.setCurves(s.curves()).ok());
  EXPECT_FALSE(e.solve().ok());
  EXPECT_FALSE(e.grow(RootParams{}, GrowthParams{}).ok());
  EXPECT_NE(e.setGrid(s.grid, kDefaultOmega, "nope").message.find("unknown solver"),
            std::string::npos);
  ASSERT_TRUE(e.setGrid(s.grid, kDefaultOmega, "cg").ok());
  EXPECT_FALSE(e.grow(RootParams{}, GrowthParams{}).ok());  // no scalp
  s.kinds[0] = 9;
  EXPECT_EQ(e.setCurves(s.curves()).code, StatusCode::InvalidInput);
  s.kinds[0] = 0;
  ASSERT_TRUE(e.setCurves(s.curves()).ok());
  EXPECT_FALSE(e.grow(RootParams{}, GrowthParams{}).ok());  // curves changed, not solved
}

namespace {

// The left half of the head (x > 0) above the ears: another scalp than the scene's.
std::vector<uint8_t> leftHalf(const hairsketch_test::Mesh& m) {
  std::vector<uint8_t> mask(m.indices.size() / 3, 0);
  for (size_t t = 0; t < mask.size(); ++t) {
    double x = 0, y = 0;
    for (int k = 0; k < 3; ++k) {
      x += m.positions[3 * m.indices[3 * t + k]] / 3;
      y += m.positions[3 * m.indices[3 * t + k] + 1] / 3;
    }
    mask[t] = x > 0 && y > -0.3;
  }
  return mask;
}

}  // namespace

TEST(HairEngine, ANewScalpMaskGrowsWhatAFreshEngineWithThatScalpGrows) {
  Scene s;
  RootParams rp;
  rp.thetaStepDeg = 6;
  rp.phiStepDeg = 6;
  rp.seed = 3;
  GrowthParams gp;
  gp.maxLength = 3;
  HairEngine e;
  ASSERT_TRUE(setup(e, s).ok());
  ASSERT_TRUE(e.grow(rp, gp).ok());  // roots of the scene's scalp cached
  const Strands before = e.strands();
  const Field field = e.field();
  const size_t constraints = e.constraints().size();
  const std::vector<uint8_t> mask = leftHalf(s.head);
  ASSERT_TRUE(e.setScalpMask(mask.data(), mask.size()).ok());
  // The field and constraints stay; the next growth starts from the new scalp.
  EXPECT_EQ(e.field(), field);
  EXPECT_EQ(e.constraints().size(), constraints);
  ASSERT_TRUE(e.grow(rp, gp).ok());
  const Strands after = e.strands();
  // The reference: a fresh engine given a head with that mask.
  Scene fresh;
  fresh.head.scalp = mask;
  HairEngine f;
  ASSERT_TRUE(setup(f, fresh).ok());
  ASSERT_TRUE(f.grow(rp, gp).ok());
  EXPECT_EQ(after.points, f.strands().points);
  EXPECT_EQ(after.strandStart, f.strands().strandStart);
  EXPECT_NE(after.points, before.points);
  for (const Eigen::Vector3f& r : e.roots()) EXPECT_GT(r.x(), -0.1f);  // on the left half
  // Scalp avoidance measures against the new scalp too.
  ScalpAvoidanceParams ap;
  ConstraintSet ae, af;
  ASSERT_TRUE(e.scalpAvoidance(ap, ae).ok());
  ASSERT_TRUE(f.scalpAvoidance(ap, af).ok());
  ASSERT_EQ(ae.size(), af.size());
  for (size_t c = 0; c < ae.size(); ++c) {
    EXPECT_EQ(ae[c].index, af[c].index);
    EXPECT_EQ(ae[c].target, af[c].target);
  }
  // A wrong length (or no mask) is refused and the mask in force stays.
  EXPECT_EQ(e.setScalpMask(s.head.scalp.data(), s.head.scalp.size() - 1).code,
            StatusCode::InvalidInput);
  EXPECT_EQ(e.setScalpMask(nullptr, mask.size()).code, StatusCode::InvalidInput);
  ASSERT_TRUE(e.grow(rp, gp).ok());
  EXPECT_EQ(e.strands().points, f.strands().points);
  // Back to the first mask: the first hair again.
  ASSERT_TRUE(e.setScalpMask(s.head.scalp.data(), s.head.scalp.size()).ok());
  ASSERT_TRUE(e.grow(rp, gp).ok());
  EXPECT_EQ(e.strands().points, before.points);
  // Before any head: not ready.
  HairEngine none;
  ASSERT_TRUE(none.setGrid(s.grid, kDefaultOmega, "cg").ok());
  EXPECT_EQ(none.setScalpMask(mask.data(), mask.size()).code, StatusCode::NotReady);
}

}  // namespace hair_engine_test
