// The curve-set dispatcher (curve_set.hpp): merging, layout checks, error codes.
#include "curve_set.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace curve_set_test {

using namespace hairsketch;

namespace {

Grid unitGrid(int nx, int ny, int nz) {
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.nz = nz;
  g.origin = {0, 0, 0};
  g.step = 1;
  return g;
}

}  // namespace

TEST(CurveSet, MergesCurvesAndRejectsBadInput) {
  const Grid g = unitGrid(4, 4, 4);
  // Two opposite single-segment curves through the same cell average to zero.
  std::vector<double> pts = {0.5, 0.5, 0.5, 1.5, 0.5, 0.5, 1.5, 0.5, 0.5, 0.5, 0.5, 0.5};
  std::vector<uint32_t> start = {0, 2, 4};
  std::vector<uint8_t> kinds = {0, 0}, extend = {0, 0};
  CurveSetView v{pts.data(), 4, start.data(), 2, kinds.data(), extend.data()};
  ConstraintSet out;
  ASSERT_TRUE(curvesToConstraints(g, v, out).ok());
  ASSERT_EQ(out.size(), 8u);
  for (const Constraint& c : out) EXPECT_EQ(c.target.norm(), 0.0);
  // The same points as one curve: +x, a zero-length segment (skipped), then +x again through
  // cell (2,0,0) once its last point moves to x = 2.5: corner columns i = 1, 2, 3.
  v.curveCount = 1;
  pts[9] = 2.5;
  std::vector<uint32_t> start1 = {0, 4};
  v.curveStart = start1.data();
  ASSERT_TRUE(curvesToConstraints(g, v, out).ok());
  EXPECT_EQ(out.size(), 8u + 4u);
  // Unknown kind.
  kinds[0] = 7;
  EXPECT_EQ(curvesToConstraints(g, v, out).code, StatusCode::InvalidInput);
  kinds[0] = 0;
  // Layout errors and non-finite points.
  std::vector<uint32_t> bad = {0, 3};
  v.curveStart = bad.data();
  EXPECT_EQ(curvesToConstraints(g, v, out).code, StatusCode::InvalidInput);
  v.curveStart = start1.data();
  pts[4] = std::nan("");
  EXPECT_EQ(curvesToConstraints(g, v, out).code, StatusCode::NonFinite);
  pts[4] = 0.5;
  // A stream curve carries exactly kStreamParamCount parameters.
  std::vector<double> prm = {1.0};
  std::vector<uint32_t> prmStart = {0, uint32_t(kStreamParamCount + 1)};
  v.params = prm.data();
  v.paramCount = prmStart[1];
  v.paramStart = prmStart.data();
  EXPECT_EQ(curvesToConstraints(g, v, out).code, StatusCode::InvalidInput);
  v.params = nullptr;
  v.paramCount = 0;
  v.paramStart = nullptr;
  // No curves: no constraints.
  v.curveCount = 0;
  ASSERT_TRUE(curvesToConstraints(g, v, out).ok());
  EXPECT_TRUE(out.empty());
}

}  // namespace curve_set_test
