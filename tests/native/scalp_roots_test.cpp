// Root sampling on spheres (method S5.1), against brute-force ray casting.
#include "scalp_roots.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "sphere_mesh.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace scalp_roots_test {

using namespace hairsketch;
using hairsketch_test::Mesh;

namespace {

// Outermost hit by testing every triangle (independent of the binning).
double bruteOutermost(const Mesh& m, const Eigen::Vector3d& c, const Eigen::Vector3d& dir,
                      int& tri) {
  double best = -1;
  tri = -1;
  for (size_t t = 0; t < m.indices.size() / 3; ++t) {
    Eigen::Vector3d v[3];
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) v[k][a] = m.positions[3 * m.indices[3 * t + k] + a];
    // Plane hit, then inside test by barycentric signs.
    const Eigen::Vector3d n = (v[1] - v[0]).cross(v[2] - v[0]);
    const double den = n.dot(dir);
    if (std::abs(den) < 1e-15) continue;
    const double s = n.dot(v[0] - c) / den;
    if (s <= 0) continue;
    const Eigen::Vector3d x = c + s * dir;
    bool inside = true;
    for (int k = 0; k < 3; ++k) inside &= (v[(k + 1) % 3] - v[k]).cross(x - v[k]).dot(n) >= -1e-12;
    if (inside && s > best) {
      best = s;
      tri = int(t);
    }
  }
  return best;
}

}  // namespace

TEST(ScalpRoots, SphereRootsLieOnTheSphereAndOnlyOnScalp) {
  const Eigen::Vector3d c(0.1, 1.6, -0.05);
  const double r = 0.11;
  Mesh m = hairsketch_test::uvSphere(c.x(), c.y(), c.z(), r, 24, 48);
  hairsketch_test::markScalpAbove(m, c.y());  // upper hemisphere is scalp
  ScalpSampler s;
  ASSERT_TRUE(s.build(m.positions.data(), m.positions.size() / 3, m.indices.data(),
                      m.indices.size() / 3, m.scalp.data(), c)
                  .ok());
  RootParams p;
  p.thetaStepDeg = 3;
  p.phiStepDeg = 3;
  p.jitter = 0.8;
  p.seed = 17;
  std::vector<Eigen::Vector3f> roots;
  ASSERT_TRUE(s.sample(p, roots).ok());
  // Half the rays (theta < 90) hit the scalp; 60 x 120 rays in all.
  EXPECT_NEAR(double(roots.size()), 30 * 120, 3 * 120);
  // Facets: the mesh lies between r cos(pi / 24) and r from the center.
  for (const auto& x : roots) {
    const double d = (x.cast<double>() - c).norm();
    EXPECT_LE(d, r * (1 + 1e-4));
    EXPECT_GE(d, r * std::cos(3.14159265 / 24) * (1 - 1e-4));
    EXPECT_GT(x.y(), c.y() - 1e-6);
  }
  // Same seed, same roots; another seed, other roots.
  std::vector<Eigen::Vector3f> again, other;
  ASSERT_TRUE(s.sample(p, again).ok());
  EXPECT_EQ(roots, again);
  p.seed = 18;
  ASSERT_TRUE(s.sample(p, other).ok());
  EXPECT_NE(roots, other);
  // maxStrands: an even stride over the full list.
  p.seed = 17;
  p.maxStrands = 100;
  std::vector<Eigen::Vector3f> capped;
  ASSERT_TRUE(s.sample(p, capped).ok());
  ASSERT_EQ(capped.size(), 100u);
  for (size_t k = 0; k < 100; ++k) EXPECT_EQ(capped[k], roots[k * roots.size() / 100]);
}

TEST(ScalpRoots, BinnedCastMatchesBruteForce) {
  const Eigen::Vector3d c(0, 0, 0);
  // Off-center sphere: rays are not radial to the mesh, triangles cover odd (theta, phi) sets.
  Mesh m = hairsketch_test::uvSphere(0.3, -0.2, 0.1, 1.0, 17, 23);
  hairsketch_test::markScalpAbove(m, 0);
  ScalpSampler s;
  ASSERT_TRUE(s.build(m.positions.data(), m.positions.size() / 3, m.indices.data(),
                      m.indices.size() / 3, m.scalp.data(), c)
                  .ok());
  int mismatches = 0, hits = 0;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 80; ++j) {
      const Eigen::Vector3d dir =
          sphericalDirection((i + 0.37) * 3.14159265 / 40, (j + 0.71) * 2 * 3.14159265 / 80);
      double t;
      int tri, triRef;
      const bool hit = s.castOutermost(dir, t, tri);
      const double tRef = bruteOutermost(m, c, dir, triRef);
      ASSERT_EQ(hit, tRef > 0);
      if (!hit) continue;
      ++hits;
      EXPECT_NEAR(t, tRef, 1e-9);
      mismatches += tri != triRef;  // only on shared edges
    }
  EXPECT_EQ(hits, 40 * 80);  // the center is inside the sphere
  EXPECT_LT(mismatches, 10);
}

TEST(ScalpRoots, OutermostHitDecides) {
  // Inner sphere is scalp, outer is not: no roots. Swap the flags: all roots on the outer one.
  Mesh inner = hairsketch_test::uvSphere(0, 0, 0, 0.5, 12, 24);
  Mesh outer = hairsketch_test::uvSphere(0, 0, 0, 1.0, 12, 24);
  Mesh both = inner;
  const uint32_t off = uint32_t(inner.positions.size() / 3);
  both.positions.insert(both.positions.end(), outer.positions.begin(), outer.positions.end());
  for (uint32_t i : outer.indices) both.indices.push_back(i + off);
  const size_t nInner = inner.indices.size() / 3, nAll = both.indices.size() / 3;
  RootParams p;
  p.thetaStepDeg = 10;
  p.phiStepDeg = 10;
  for (int innerIsScalp = 0; innerIsScalp < 2; ++innerIsScalp) {
    both.scalp.assign(nAll, 0);
    for (size_t t = 0; t < nAll; ++t) both.scalp[t] = (t < nInner) == bool(innerIsScalp);
    ScalpSampler s;
    ASSERT_TRUE(s.build(both.positions.data(), both.positions.size() / 3, both.indices.data(), nAll,
                        both.scalp.data(), Eigen::Vector3d::Zero())
                    .ok());
    std::vector<Eigen::Vector3f> roots;
    ASSERT_TRUE(s.sample(p, roots).ok());
    if (innerIsScalp) {
      EXPECT_TRUE(roots.empty());
    } else {
      EXPECT_EQ(roots.size(), 18u * 36u);
      for (const auto& x : roots) EXPECT_GT(x.norm(), 0.95f);
    }
  }
}

TEST(ScalpRoots, RejectsBadInput) {
  Mesh m = hairsketch_test::uvSphere(0, 0, 0, 1, 4, 8);
  hairsketch_test::markScalpAbove(m, 0);
  ScalpSampler s;
  std::vector<uint32_t> badIdx = m.indices;
  badIdx[4] = 100000;
  EXPECT_FALSE(s.build(m.positions.data(), m.positions.size() / 3, badIdx.data(), badIdx.size() / 3,
                       m.scalp.data(), Eigen::Vector3d::Zero())
                   .ok());
  std::vector<Eigen::Vector3f> roots;
  EXPECT_FALSE(s.sample(RootParams{}, roots).ok());  // nothing built
  ASSERT_TRUE(s.build(m.positions.data(), m.positions.size() / 3, m.indices.data(),
                      m.indices.size() / 3, m.scalp.data(), Eigen::Vector3d::Zero())
                  .ok());
  RootParams p;
  p.thetaStepDeg = 0;
  EXPECT_FALSE(s.sample(p, roots).ok());
  p = RootParams{};
  p.jitter = 2;
  EXPECT_FALSE(s.sample(p, roots).ok());
}

TEST(ScalpRoots, ANewMaskSamplesLikeAFreshBuildWithIt) {
  Mesh m = hairsketch_test::uvSphere(0.2, 0.1, -0.1, 1.0, 30, 60);
  hairsketch_test::markScalpAbove(m, 0);
  const size_t nt = m.indices.size() / 3;
  std::vector<uint8_t> left(nt);  // another mask: the triangles with a vertex at x > 0.2
  for (size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) left[t] |= m.positions[3 * m.indices[3 * t + k]] > 0.2f;
  ScalpSampler s, fresh;
  ASSERT_TRUE(s.build(m.positions.data(), m.positions.size() / 3, m.indices.data(), nt,
                      m.scalp.data(), Eigen::Vector3d::Zero())
                  .ok());
  ASSERT_TRUE(fresh
                  .build(m.positions.data(), m.positions.size() / 3, m.indices.data(), nt,
                         left.data(), Eigen::Vector3d::Zero())
                  .ok());
  RootParams p;
  p.thetaStepDeg = 4;
  p.phiStepDeg = 4;
  std::vector<Eigen::Vector3f> before, after, ref;
  ASSERT_TRUE(s.sample(p, before).ok());
  ASSERT_TRUE(s.setScalpMask(left.data(), nt).ok());
  ASSERT_TRUE(s.sample(p, after).ok());
  ASSERT_TRUE(fresh.sample(p, ref).ok());
  EXPECT_EQ(after, ref);
  EXPECT_NE(after, before);
  // A wrong count is refused and the mask in force stays.
  EXPECT_EQ(s.setScalpMask(m.scalp.data(), nt - 1).code, StatusCode::InvalidInput);
  EXPECT_EQ(s.setScalpMask(nullptr, nt).code, StatusCode::InvalidInput);
  ASSERT_TRUE(s.sample(p, after).ok());
  EXPECT_EQ(after, ref);
  ScalpSampler empty;
  EXPECT_EQ(empty.setScalpMask(left.data(), nt).code, StatusCode::NotReady);
}

// Timing is printed, not asserted (a loaded machine would fail a bound).
TEST(ScalpRoots, HundredThousandRaysOnThirtyThousandTriangles) {
  Mesh m = hairsketch_test::uvSphere(0, 1.6, 0, 0.1, 122, 124);  // ~30K triangles
  hairsketch_test::markScalpAbove(m, 1.6);
  ScalpSampler s;
  ASSERT_TRUE(s.build(m.positions.data(), m.positions.size() / 3, m.indices.data(),
                      m.indices.size() / 3, m.scalp.data(), Eigen::Vector3d(0, 1.6, 0))
                  .ok());
  RootParams p;
  p.thetaStepDeg = 0.8;  // 225 x 450 = 101K rays
  p.phiStepDeg = 0.8;
  std::vector<Eigen::Vector3f> roots;
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_TRUE(s.sample(p, roots).ok());
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::printf("[ info ] %zu triangles, 101250 rays, %zu roots: %.1f ms\n", s.triangleCount(),
              roots.size(), ms);
  EXPECT_GT(roots.size(), 45000u);
}

TEST(ScalpRoots, SampleIdsNameEachRootsThetaRowAndPhiColumnWhateverTheMaskOrCap) {
  const Eigen::Vector3d c(0, 0, 0);
  Mesh m = hairsketch_test::uvSphere(c.x(), c.y(), c.z(), 1.0, 24, 48);
  hairsketch_test::markScalpAbove(m, c.y());
  ScalpSampler s;
  ASSERT_TRUE(s.build(m.positions.data(), m.positions.size() / 3, m.indices.data(),
                      m.indices.size() / 3, m.scalp.data(), c)
                  .ok());
  RootParams p;
  p.thetaStepDeg = 4;
  p.phiStepDeg = 5;
  p.jitter = 0.8;
  p.seed = 3;
  std::vector<Eigen::Vector3f> roots;
  std::vector<uint32_t> ids;
  ASSERT_TRUE(s.sample(p, roots, &ids).ok());
  ASSERT_EQ(ids.size(), roots.size());
  const int nP = 72;
  const double kDeg = 180.0 / 3.14159265358979323846;
  for (size_t k = 0; k < roots.size(); ++k) {
    const Eigen::Vector3d d = roots[k].cast<double>().normalized();
    const double theta = std::acos(d.y()) * kDeg;
    const double phi = std::fmod(std::atan2(d.x(), d.z()) * kDeg + 360.0, 360.0);
    EXPECT_EQ(int(theta / p.thetaStepDeg), int(ids[k] / nP)) << k;
    EXPECT_EQ(int(phi / p.phiStepDeg), int(ids[k] % nP)) << k;
    if (k > 0) EXPECT_LT(ids[k - 1], ids[k]);
  }
  // a cap takes the same stride of roots and of ids
  RootParams capped = p;
  capped.maxStrands = 100;
  std::vector<Eigen::Vector3f> some;
  std::vector<uint32_t> someIds;
  ASSERT_TRUE(s.sample(capped, some, &someIds).ok());
  ASSERT_EQ(someIds.size(), 100u);
  for (size_t k = 0; k < 100; ++k) {
    EXPECT_EQ(someIds[k], ids[k * roots.size() / 100]);
    EXPECT_EQ(some[k], roots[k * roots.size() / 100]);
  }
  // less scalp: the roots left keep their ids (and positions)
  std::vector<uint8_t> mask = m.scalp;
  for (size_t t = 0; t < mask.size(); t += 2) mask[t] = 0;
  ASSERT_TRUE(s.setScalpMask(mask.data(), mask.size()).ok());
  std::vector<Eigen::Vector3f> fewer;
  std::vector<uint32_t> fewerIds;
  ASSERT_TRUE(s.sample(p, fewer, &fewerIds).ok());
  ASSERT_LT(fewer.size(), roots.size());
  size_t shifted = 0;
  for (size_t k = 0; k < fewer.size(); ++k) {
    const auto at = std::find(ids.begin(), ids.end(), fewerIds[k]);
    ASSERT_NE(at, ids.end());
    EXPECT_EQ(fewer[k], roots[size_t(at - ids.begin())]);
    shifted += size_t(at - ids.begin()) != k;
  }
  EXPECT_GT(shifted, 0u);
}

// Lone roots (finished edges), counted by hand: on a square lattice of spacing h, with a reach
// of 2.5 h, every root has at least 2 others within reach,
// corners included. Out of its reach (4-5 h away): a root alone has none and goes; each of a pair
// h apart has one and goes; each of a line of three h apart has two and stays. Order is kept.
TEST(ScalpRoots, DropLoneRootsKeepsTheLatticeAndDropsStrays) {
  std::vector<Eigen::Vector3f> all;
  const float h = 0.01f;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) all.emplace_back(h * float(i), h * float(j), 0.f);
  const uint32_t lattice = uint32_t(all.size());
  all.emplace_back(-4 * h, 5 * h, 0.f);  // alone
  all.emplace_back(23 * h, 5 * h, 0.f);  // a pair, each with one neighbour
  all.emplace_back(23 * h, 6 * h, 0.f);
  for (int k = 0; k < 3; ++k) all.emplace_back(5 * h, (24 + k) * h, 0.f);  // a line of three
  std::vector<uint32_t> pick(all.size());
  for (uint32_t k = 0; k < pick.size(); ++k) pick[k] = k;
  dropLoneRoots(all, pick, kLoneReach * h);
  std::vector<uint32_t> expected(lattice);
  for (uint32_t k = 0; k < lattice; ++k) expected[k] = k;
  for (uint32_t k = 0; k < 3; ++k) expected.push_back(lattice + 3 + k);
  EXPECT_EQ(pick, expected);
}

}  // namespace scalp_roots_test
