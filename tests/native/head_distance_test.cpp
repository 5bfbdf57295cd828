// The head's distance grid against the analytic distance of a sphere, and growth that keeps
// hair outside it.
#include "head_distance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "body_mesh.hpp"
#include "random_vector.hpp"
#include "sphere_mesh.hpp"
#include "strand_growth.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace head_distance_test {

using namespace hairsketch;

namespace {

HeadMeshView view(const hairsketch_test::Mesh& m) {
  return HeadMeshView{m.positions.data(), m.positions.size() / 3, m.indices.data(),
                      m.indices.size() / 3, m.scalp.data()};
}

// A fine UV sphere of radius 1 at the origin: its chords lie within 1 - cos(pi / 96) of the
// sphere, 5e-4.
hairsketch_test::Mesh sphere() {
  hairsketch_test::Mesh m = hairsketch_test::uvSphere(0, 0, 0, 1, 96, 192);
  hairsketch_test::markScalpAbove(m, -2);
  return m;
}

Grid box() {
  Grid g;
  g.nx = g.ny = g.nz = 41;
  g.step = 0.1;
  g.origin = Eigen::Vector3d(-2, -2, -2);
  return g;
}

}  // namespace

TEST(HeadDistance, MatchesTheSpheresDistanceNearTheSurfaceAndItsSignEverywhere) {
  const auto m = sphere();
  HeadDistance hd;
  ASSERT_TRUE(hd.build(view(m), 0.03, 3).ok());
  uint64_t state = 12345;
  for (int t = 0; t < 2000; ++t) {
    auto u = [&] {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      return double(state >> 11) / double(1ull << 53);
    };
    const Eigen::Vector3d p = hairsketch_test::drawVector([&](int) { return 4 * u() - 2; });
    const double exact = p.norm() - 1;
    float g[3];
    const float d = hd.distance(float(p.x()), float(p.y()), float(p.z()), g);
    if (std::fabs(exact) < 0.06) {
      EXPECT_NEAR(d, exact, 2e-3) << p.transpose();
      const Eigen::Vector3d grad(g[0], g[1], g[2]);
      EXPECT_GT(grad.normalized().dot(p.normalized()), 0.98) << p.transpose();
    } else {
      EXPECT_EQ(d > 0, exact > 0) << p.transpose();  // the sign far from the surface
    }
  }
}

// Regular meshes make many cells equally near two triangles once the distance is stored (a
// float): the propagation used to hand such cells between the two without end for these (a UV
// sphere, the body tests' capsule, at 4 mm cells and a 4-cell band). It ends, and the distance
// is right.
TEST(HeadDistance, TiedTrianglesDoNotStallTheBuild) {
  const auto sphereMesh = hairsketch_test::uvSphere(0, 0, 0, 1.0, 24, 48);
  hairsketch_test::Capsule c;
  const auto capsule = hairsketch_test::capsuleMesh(c);
  for (const hairsketch_test::Mesh* m : {&sphereMesh, &capsule}) {
    HeadDistance hd;
    const HeadMeshView v{m->positions.data(), m->positions.size() / 3, m->indices.data(),
                         m->indices.size() / 3, nullptr};
    ASSERT_TRUE(hd.build(v, 0.04, 4).ok());
    for (int t = 0; t <= 40; ++t) {
      // along a line through the surface at the top
      const double y = (m == &capsule ? c.cy + c.r : 1.0) - 0.16 + 0.008 * t;
      const double exact = m == &capsule ? c.distance(0.3, y, 0.01) : std::hypot(0.3, y, 0.01) - 1;
      if (std::abs(exact) < 0.12)                                           // within the band
        EXPECT_NEAR(hd.distance(0.3f, float(y), 0.01f), exact, 6e-3) << y;  // chords
    }
  }
}

TEST(HeadDistance, TwoSeparatePartsAreBothInside) {
  // Two spheres (as a head with separate eyes would be): the flood fill finds both insides.
  auto a = hairsketch_test::uvSphere(-1, 0, 0, 0.5, 24, 48);
  const auto b = hairsketch_test::uvSphere(1, 0, 0, 0.5, 24, 48);
  const uint32_t off = uint32_t(a.positions.size() / 3);
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  for (uint32_t i : b.indices) a.indices.push_back(i + off);
  hairsketch_test::markScalpAbove(a, -2);
  HeadDistance hd;
  ASSERT_TRUE(hd.build(view(a), 0.05, 2).ok());
  EXPECT_LT(hd.distance(-1, 0, 0), -0.05f);
  EXPECT_LT(hd.distance(1, 0, 0), -0.05f);
  EXPECT_GT(hd.distance(0, 0, 0), 0.05f);
  EXPECT_NEAR(hd.distance(1.55f, 0, 0), 0.05f, 0.01f);  // near the surface: its distance
  EXPECT_FLOAT_EQ(hd.distance(1.8f, 0, 0), 0.1f);       // past the band: the band (2 x 0.05)
}

namespace {

// Unsigned distance from p to the nearest triangle of m, by testing every triangle.
double bruteDistance(const hairsketch_test::Mesh& m, const Eigen::Vector3d& p) {
  double best = std::numeric_limits<double>::infinity();
  auto v = [&](uint32_t i) {
    return Eigen::Vector3d(m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]);
  };
  for (size_t t = 0; t < m.indices.size() / 3; ++t) {
    const Eigen::Vector3d a = v(m.indices[3 * t]), b = v(m.indices[3 * t + 1]),
                          c = v(m.indices[3 * t + 2]);
    // closest point by projecting onto the plane, else onto the three edges
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    const Eigen::Vector3d q = p - n.dot(p - a) * n;
    bool inside = true;
    const Eigen::Vector3d corners[3] = {a, b, c};
    for (int k = 0; k < 3; ++k)
      inside &= (corners[(k + 1) % 3] - corners[k]).cross(q - corners[k]).dot(n) >= 0;
    double d = inside ? (p - q).norm() : std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e0 = corners[k], e = corners[(k + 1) % 3] - e0;
      const double s = std::clamp((p - e0).dot(e) / e.squaredNorm(), 0.0, 1.0);
      d = std::min(d, (p - (e0 + s * e)).norm());
    }
    best = std::min(best, d);
  }
  return best;
}

}  // namespace

TEST(HeadDistance, MatchesBruteForceBetweenTwoNearlyTouchingParts) {
  // Two spheres 0.08 apart (a crease, as between an ear and the head): the distance within the
  // band is the nearest triangle's wherever the distance is smooth (away from the bisector).
  const double cell = 0.03;
  auto a = hairsketch_test::uvSphere(-0.54, 0, 0, 0.5, 24, 48);
  const auto b = hairsketch_test::uvSphere(0.54, 0.05, 0, 0.5, 24, 48);
  const uint32_t off = uint32_t(a.positions.size() / 3);
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  for (uint32_t i : b.indices) a.indices.push_back(i + off);
  hairsketch_test::markScalpAbove(a, -2);
  HeadDistance hd;
  ASSERT_TRUE(hd.build(view(a), cell, 3).ok());
  uint64_t state = 777;
  auto u = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) / double(1ull << 53);
  };
  int compared = 0;
  for (int t = 0; t < 3000; ++t) {
    const Eigen::Vector3d p = hairsketch_test::drawVector(
        [&](int axis) { return axis == 0 ? 2.4 * u() - 1.2 : 1.2 * u() - 0.6; });
    const double da = (p - Eigen::Vector3d(-0.54, 0, 0)).norm() - 0.5;
    const double db = (p - Eigen::Vector3d(0.54, 0.05, 0)).norm() - 0.5;
    // skip where the nearest sphere changes within two cells (the distance has a kink there)
    if (std::fabs(da - db) < 2 * cell) continue;
    const double exact = bruteDistance(a, p);
    if (exact > 0.06) continue;  // a cell past the band (clamped to it) is in the stencil
    const double sign = std::min(da, db) < 0 ? -1 : 1;
    EXPECT_NEAR(hd.distance(float(p.x()), float(p.y()), float(p.z())), sign * exact, 2e-3)
        << p.transpose();
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

TEST(HeadDistance, ScalpNearReadsTheMaskInForce) {
  const auto m = sphere();  // all scalp
  std::vector<uint8_t> top(m.scalp.size());
  for (size_t t = 0; t < top.size(); ++t) {
    double y = 0;
    for (int k = 0; k < 3; ++k) y += m.positions[3 * m.indices[3 * t + k] + 1];
    top[t] = y / 3 > 0.3;
  }
  HeadDistance hd, fresh;
  ASSERT_TRUE(hd.build(view(m), 0.03, 3).ok());
  hairsketch_test::Mesh withTop = m;
  withTop.scalp = top;
  ASSERT_TRUE(fresh.build(view(withTop), 0.03, 3).ok());
  ASSERT_TRUE(hd.setScalpMask(top.data(), top.size()).ok());
  // a wrong count is refused and leaves the mask in force
  EXPECT_EQ(hd.setScalpMask(m.scalp.data(), m.scalp.size() + 1).code, StatusCode::InvalidInput);
  int scalp = 0, other = 0;
  for (int i = 0; i < 400; ++i) {
    const double th = 3.14159265 * (i + 0.5) / 400, ph = 0.7 * i;
    const float r = 1.01f;
    const float x = float(r * std::sin(th) * std::sin(ph)), y = float(r * std::cos(th)),
                z = float(r * std::sin(th) * std::cos(ph));
    EXPECT_EQ(hd.scalpNear(x, y, z), fresh.scalpNear(x, y, z)) << i;
    // away from the mask's edge, the mask itself
    if (std::fabs(y - 0.3f) > 0.05f) EXPECT_EQ(hd.scalpNear(x, y, z), y > 0.3f) << i;
    (hd.scalpNear(x, y, z) ? scalp : other)++;
  }
  EXPECT_GT(scalp, 50);
  EXPECT_GT(other, 50);
  EXPECT_FALSE(hd.scalpNear(1.5f, 0, 0));  // away from the surface
  HeadDistance none;
  EXPECT_EQ(none.setScalpMask(top.data(), top.size()).code, StatusCode::NotReady);
}

TEST(HeadDistance, GrowthIntoTheHeadSlidesAlongItAndStaysOutside) {
  // A field pointing down and slightly inwards everywhere: strands from the top of the sphere
  // would cut through it. With the distance grid they slide over the surface, never deeper
  // than the margin allows, and stop where the field points straight in.
  const Grid g = box();
  std::vector<float> field(size_t(g.size()) * 3);
  for (int64_t p = 0; p < g.size(); ++p) {
    field[3 * p] = 0.2f;
    field[3 * p + 1] = -1;
    field[3 * p + 2] = 0;
  }
  const auto m = sphere();
  HeadDistance hd;
  ASSERT_TRUE(hd.build(view(m), 0.03, 3).ok());
  std::vector<Eigen::Vector3f> roots;
  for (int k = 0; k < 40; ++k) {
    const double th = 0.6 * k / 40.0, ph = 0.37 * k;
    roots.emplace_back(float(std::sin(th) * std::cos(ph)), float(std::cos(th)),
                       float(std::sin(th) * std::sin(ph)));
  }
  GrowthParams prm;
  prm.maxSegments = 400;
  prm.margin = 0.02;
  Strands with, without;
  ASSERT_TRUE(growStrands(g, field, roots, prm, with, size_t(1) << 24, &hd).ok());
  ASSERT_TRUE(growStrands(g, field, roots, prm, without).ok());
  int deepWithout = 0;
  double lowestEnd = 1;
  for (size_t s = 0; s < roots.size(); ++s) {
    for (uint32_t p = with.strandStart[s] + 1; p < with.strandStart[s + 1]; ++p) {
      const Eigen::Vector3d q(with.points[3 * p], with.points[3 * p + 1], with.points[3 * p + 2]);
      EXPECT_GT(q.norm() - 1, 0.02 - 2e-3) << "strand " << s << " point " << p;
      // the midpoint of each segment too
      const Eigen::Vector3d q0(with.points[3 * p - 3], with.points[3 * p - 2],
                               with.points[3 * p - 1]);
      EXPECT_GT((q + q0).norm() / 2 - 1, -1e-3);
    }
    const uint32_t tip = with.strandStart[s + 1] - 1;
    lowestEnd = std::min(lowestEnd, double(with.points[3 * tip + 1]));
    for (uint32_t p = without.strandStart[s] + 1; p < without.strandStart[s + 1]; ++p) {
      const Eigen::Vector3d q(without.points[3 * p], without.points[3 * p + 1],
                              without.points[3 * p + 2]);
      deepWithout += q.norm() < 0.9;
    }
  }
  EXPECT_GT(deepWithout, 100);  // the test's field does push hair into the head
  EXPECT_LT(lowestEnd, -1.5);   // hair slid round the sphere and fell below it
  // keepOutsideHead moves points that something else put inside back out.
  Strands moved = without;
  EXPECT_GT(keepOutsideHead(hd, 0.02f, moved), size_t(deepWithout));
  for (size_t p = 0; p < moved.points.size() / 3; ++p) {
    const Eigen::Vector3d q(moved.points[3 * p], moved.points[3 * p + 1], moved.points[3 * p + 2]);
    bool root = false;
    for (uint32_t r : moved.strandStart) root |= r == p;
    if (!root) EXPECT_GT(q.norm() - 1, 0.02 - 2e-3);
  }
}

TEST(HeadDistance, AFieldPointingStraightInStopsTheStrand) {
  const Grid g = box();
  std::vector<float> field(size_t(g.size()) * 3, 0.f);
  for (int64_t p = 0; p < g.size(); ++p) field[3 * p + 1] = -1;
  const auto m = sphere();
  HeadDistance hd;
  ASSERT_TRUE(hd.build(view(m), 0.03, 3).ok());
  Strands s;
  GrowthParams prm;
  ASSERT_TRUE(growStrands(g, field, {Eigen::Vector3f(0, 1, 0)}, prm, s, 1 << 20, &hd).ok());
  EXPECT_LE(s.points.size() / 3, 2u);  // at most a root and the first point at the margin
}

TEST(HeadDistance, PushOutBringsADeepPointJustOutsideNearWhereItWas) {
  const auto m = sphere();
  HeadDistance hd;
  ASSERT_TRUE(hd.build(view(m), 0.03, 3).ok());
  // 0.3, 0.6 and 0.9 deep (the grid's band is 0.09: the distance is flat there)
  for (float depth : {0.3f, 0.6f, 0.9f}) {
    const Eigen::Vector3f dir = Eigen::Vector3f(0.3f, 0.8f, -0.5f).normalized();
    float p[3] = {dir.x() * (1 - depth), dir.y() * (1 - depth), dir.z() * (1 - depth)};
    hd.pushOut(p, 0.02f);
    const Eigen::Vector3f q(p[0], p[1], p[2]);
    EXPECT_NEAR(q.norm(), 1.02f, 3e-3f) << depth;         // at the margin, hand value 1 + 0.02
    EXPECT_GT(q.normalized().dot(dir), 0.999f) << depth;  // straight out from the centre
  }
}

}  // namespace head_distance_test
