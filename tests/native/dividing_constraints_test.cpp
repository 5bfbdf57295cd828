// Dividing-curve constraints (method S4.5) on a straight curve over a flat "scalp", against values
// worked out by hand from the header's formulas.
#include "dividing_constraints.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace dividing_constraints_test {

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

// Curve along +z at x = 5 on the plane y = 2 (normal +y): p_i = (5, 2, 2 + i), i = 0..7.
struct FlatCurve {
  std::vector<double> points, params;
  FlatCurve(double sigma, double h, double a0, double a1) {
    params = {sigma, h, a0, a1};
    for (int i = 0; i < 8; ++i) {
      points.insert(points.end(), {5, 2, 2.0 + i});
      params.insert(params.end(), {0, 1, 0});
    }
  }
  DividingParams parse() const {
    DividingParams p;
    EXPECT_TRUE(parseDividingParams(params.data(), params.size(), 8, p).ok());
    return p;
  }
};

}  // namespace

TEST(DividingConstraints, FramesOnAStraightCurveWithTilt) {
  FlatCurve c(1, 0.5, 0.0, 0.7);
  const auto frames = dividingFrames(c.points.data(), 8, c.parse());
  ASSERT_EQ(frames.size(), 8u);
  // i = 0: alpha = 0: y = +y, z = tangent = +z, x = y x z = +x.
  EXPECT_TRUE(frames[0].valid);
  EXPECT_LT((frames[0].y - Eigen::Vector3d(0, 1, 0)).norm(), 1e-15);
  EXPECT_LT((frames[0].z - Eigen::Vector3d(0, 0, 1)).norm(), 1e-15);
  EXPECT_LT((frames[0].x - Eigen::Vector3d(1, 0, 0)).norm(), 1e-15);
  // i = 7: alpha = 0.7. Rotating +z about +y by a gives (sin a, 0, cos a); x = y x z =
  // (cos a, 0, -sin a).
  const double a = 0.7;
  EXPECT_DOUBLE_EQ(frames[7].alpha, a);
  EXPECT_LT((frames[7].z - Eigen::Vector3d(std::sin(a), 0, std::cos(a))).norm(), 1e-15);
  EXPECT_LT((frames[7].x - Eigen::Vector3d(std::cos(a), 0, -std::sin(a))).norm(), 1e-15);
  // i = 3: alpha = 0.7 * 3 / 7 = 0.3.
  EXPECT_NEAR(frames[3].alpha, 0.3, 1e-15);
  // A normal that is not unit is normalised; a tangent with a normal component is flattened.
  std::vector<double> pts = {0, 0, 0, 0, 1, 1}, prm = {1, 0.5, 0, 0, 0, 3, 0, 0, 3, 0};
  DividingParams p;
  ASSERT_TRUE(parseDividingParams(prm.data(), prm.size(), 2, p).ok());
  const auto f2 = dividingFrames(pts.data(), 2, p);
  EXPECT_LT((f2[1].y - Eigen::Vector3d(0, 1, 0)).norm(), 1e-15);
  EXPECT_LT((f2[1].z - Eigen::Vector3d(0, 0, 1)).norm(), 1e-15);
}

TEST(DividingConstraints, GaussianBlueAndRedOnAFlatScalp) {
  const Grid g = unitGrid(12, 8, 12);
  FlatCurve c(1, 0.5, 0, 0);
  std::vector<Constraint> raw;
  std::vector<ConstraintColour> colours;
  appendDividingConstraints(g, c.points.data(), 8, c.parse(), raw, &colours);
  ASSERT_EQ(raw.size(), colours.size());
  // Profile by hand, sigma = 1, h = 0.5: G(s) = 0.5 (exp(-(s+1)^2 / 2) - exp(-1/2)),
  // G'(s) = -0.5 (s + 1) exp(-(s+1)^2 / 2):
  //   G(1) = -0.2356, G(2) = -0.2977, G(3) = -0.3031 (all within 0.5 of v = 0 -> blue at v = 0),
  //   G'(1) = -exp(-2), G'(2) = -1.5 exp(-4.5), G'(3) = -2 exp(-8).
  const double slope[4] = {0, -std::exp(-2.0), -1.5 * std::exp(-4.5), -2 * std::exp(-8.0)};
  // Expected in every slice z = 2..9 (exactly one frame per slice, |w| = 0):
  //   (5 +- s, 2): blue side * (1, G'(s), 0) / |.|, s = 1, 2, 3;
  //   (5 +- 1, 3) and (5 +- 1, 4): red 0.3 * side * (1, 0, 0) (v = 1, 2 > G(1) + 0.5);
  //   nothing at x = 5 (on the parting), nothing at s = 4 (> 3 sigma), nothing at v = 3.
  std::map<std::tuple<int, int, int>, std::pair<Eigen::Vector3d, ConstraintColour>> expected;
  for (int z = 2; z <= 9; ++z)
    for (int side = -1; side <= 1; side += 2) {
      for (int s = 1; s <= 3; ++s)
        expected[{5 + side * s, 2, z}] = {
            Eigen::Vector3d(side, slope[s], 0) / std::sqrt(1 + slope[s] * slope[s]),
            ConstraintColour::Blue};
      for (int v = 3; v <= 4; ++v)
        expected[{5 + side, v, z}] = {Eigen::Vector3d(0.3 * side, 0, 0), ConstraintColour::Red};
    }
  ASSERT_EQ(raw.size(), expected.size());
  for (size_t k = 0; k < raw.size(); ++k) {
    const int p = raw[k].index;
    const std::tuple<int, int, int> ijk{p % 12, (p / 12) % 8, p / 96};
    ASSERT_TRUE(expected.count(ijk)) << "unexpected grid point " << std::get<0>(ijk) << ","
                                     << std::get<1>(ijk) << "," << std::get<2>(ijk);
    EXPECT_LT((raw[k].target - expected[ijk].first).norm(), 1e-14);
    EXPECT_EQ(colours[k], expected[ijk].second);
  }
}

TEST(DividingConstraints, RedIsPointThreeAndFlipsAcrossAnObliqueTiltedParting) {
  Grid g = unitGrid(20, 10, 20);
  g.step = 0.5;
  // Oblique curve on the plane y = 2, tilted from -0.4 to 0.5 rad.
  std::vector<double> pts, prm = {1.3, 0.8, -0.4, 0.5};
  const Eigen::Vector3d dir = Eigen::Vector3d(0.6, 0, 0.8) * g.step;
  for (int i = 0; i < 12; ++i) {
    const Eigen::Vector3d p = Eigen::Vector3d(2.1, 2, 1.3) + i * dir;
    pts.insert(pts.end(), {p.x(), p.y(), p.z()});
    prm.insert(prm.end(), {0, 1, 0});
  }
  DividingParams dp;
  ASSERT_TRUE(parseDividingParams(prm.data(), prm.size(), 12, dp).ok());
  const auto frames = dividingFrames(pts.data(), 12, dp);
  std::vector<Constraint> raw;
  std::vector<ConstraintColour> colours;
  appendDividingConstraints(g, pts.data(), 12, dp, raw, &colours);
  int red[2] = {0, 0}, blue[2] = {0, 0};
  for (size_t k = 0; k < raw.size(); ++k) {
    const int p = raw[k].index;
    const Eigen::Vector3d q = g.position(p % g.nx, (p / g.nx) % g.ny, p / (g.nx * g.ny));
    // The frame whose slab holds q (|w| <= 0.5 step); neighbouring slabs may both hold it.
    bool matched = false;
    for (const DividingFrame& f : frames) {
      const Eigen::Vector3d r = (q - f.origin) / g.step;
      if (std::abs(r.dot(f.z)) > 0.5) continue;
      const double side = r.dot(f.x) > 0 ? 1 : -1;
      if (colours[k] == ConstraintColour::Red) {
        if ((raw[k].target - 0.3 * side * f.x).norm() < 1e-12) matched = true;
      } else {
        const double s = std::abs(r.dot(f.x));
        const double gp = dividingProfileSlope(s, 1.3, 0.8);
        if ((raw[k].target - (side * f.x + gp * f.y).normalized()).norm() < 1e-12) matched = true;
      }
      if (matched) {
        (colours[k] == ConstraintColour::Red ? red : blue)[side > 0]++;
        break;
      }
    }
    EXPECT_TRUE(matched) << "constraint " << k;
    if (colours[k] == ConstraintColour::Red) EXPECT_NEAR(raw[k].target.norm(), 0.3, 1e-12);
    if (colours[k] == ConstraintColour::Blue) EXPECT_NEAR(raw[k].target.norm(), 1.0, 1e-12);
  }
  EXPECT_GT(red[0], 5);
  EXPECT_GT(red[1], 5);
  EXPECT_GT(blue[0], 20);
  EXPECT_GT(blue[1], 20);
}

TEST(DividingConstraints, ParamValidation) {
  DividingParams p;
  std::vector<double> prm = {1, 0.5, 0, 0, 0, 1, 0, 0, 1, 0};
  EXPECT_TRUE(parseDividingParams(prm.data(), prm.size(), 2, p).ok());
  EXPECT_EQ(parseDividingParams(prm.data(), prm.size() - 1, 2, p).code, StatusCode::InvalidInput);
  EXPECT_EQ(parseDividingParams(prm.data(), prm.size(), 3, p).code, StatusCode::InvalidInput);
  prm[0] = 0;  // sigma
  EXPECT_EQ(parseDividingParams(prm.data(), prm.size(), 2, p).code, StatusCode::InvalidInput);
  prm[0] = 1;
  prm[6] = std::nan("");
  const Status s = parseDividingParams(prm.data(), prm.size(), 2, p);
  EXPECT_EQ(s.code, StatusCode::NonFinite);
  EXPECT_NE(s.message.find("not finite"), std::string::npos);
  prm[6] = 0;
  prm[5] = 0;  // zero normal at point 0
  EXPECT_EQ(parseDividingParams(prm.data(), prm.size(), 2, p).code, StatusCode::InvalidInput);
}

}  // namespace dividing_constraints_test
