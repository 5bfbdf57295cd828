// HairSim: lengths kept, no point inside the head, the groom holds at rest, same seed same frames.
#include "hair_sim.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "head_distance.hpp"

namespace hairsketch {
namespace {

// A UV sphere of radius r at the origin.
void simSphere(float r, std::vector<float>& v, std::vector<uint32_t>& t) {
  const int nu = 32, nv = 16;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double th = M_PI * j / nv, ph = 2 * M_PI * i / nu;
      v.push_back(float(r * std::sin(th) * std::cos(ph)));
      v.push_back(float(r * std::cos(th)));
      v.push_back(float(r * std::sin(th) * std::sin(ph)));
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const uint32_t a = j * nu + i, b = j * nu + (i + 1) % nu, c = a + nu, d = b + nu;
      t.insert(t.end(), {a, b, c, b, d, c});
    }
}

// Strands rooted on the upper half of a sphere of radius 0.1 m, running straight out of it.
std::vector<float> simGroom(int strands, int n) {
  std::vector<float> p;
  for (int s = 0; s < strands; ++s) {
    const double ph = 2 * M_PI * s / strands, th = 0.3 + 0.9 * (s % 7) / 7.0;
    Eigen::Vector3f q(float(0.1 * std::sin(th) * std::cos(ph)), float(0.1 * std::cos(th)),
                      float(0.1 * std::sin(th) * std::sin(ph)));
    Eigen::Vector3f out = q.normalized();
    for (int i = 0; i < n; ++i) {
      p.insert(p.end(), {q.x(), q.y(), q.z()});
      q += 0.005f * out;
    }
  }
  return p;
}

struct SimHead {
  std::vector<float> v;
  std::vector<uint32_t> t;
  HeadDistance head;
  SimHead() {
    simSphere(0.1f, v, t);
    HeadMeshView mesh;
    mesh.positions = v.data();
    mesh.vertexCount = v.size() / 3;
    mesh.indices = t.data();
    mesh.triangleCount = t.size() / 3;
    EXPECT_TRUE(head.build(mesh, 0.005, 4).ok());
  }
};

float simMaxLengthError(const HairSim& sim) {
  const auto& x = sim.positions();
  const auto& r = sim.rest();
  float worst = 0;
  const int n = sim.pointsPerStrand();
  for (int s = 0; s < sim.strandCount(); ++s)
    for (int i = 0; i + 1 < n; ++i) {
      const size_t a = 3 * (size_t(s) * n + i), b = a + 3;
      const float l = std::hypot(x[b] - x[a], x[b + 1] - x[a + 1], x[b + 2] - x[a + 2]);
      const float l0 = std::hypot(r[b] - r[a], r[b + 1] - r[a + 1], r[b + 2] - r[a + 2]);
      worst = std::max(worst, std::abs(l - l0) / l0);
    }
  return worst;
}

TEST(HairSim, KeepsLengthsAndStaysOutOfTheHeadInEachMotion) {
  SimHead f;
  const int strands = 60, n = 32;
  const std::vector<float> g = simGroom(strands, n);
  for (SimMotion m : {SimMotion::Settle, SimMotion::HeadTurn, SimMotion::Nod, SimMotion::Wind}) {
    HairSim sim;
    sim.init(g.data(), strands, n, &f.head, Eigen::Vector3f(0, -0.1f, 0), m, 7);
    for (int k = 0; k < 48; ++k) {
      sim.step();
      EXPECT_LE(simMaxLengthError(sim), 0.03f) << int(m) << " frame " << k;
      const auto& x = sim.positions();
      const HeadPose& pose = sim.pose();
      float deepest = 1;
      for (size_t i = 0; i < x.size(); i += 3) {
        Eigen::Vector3f local = pose.rotation.transpose() *
                                (Eigen::Vector3f(x[i], x[i + 1], x[i + 2]) - pose.translation);
        deepest = std::min(deepest, f.head.distance(local.x(), local.y(), local.z()));
      }
      EXPECT_GE(deepest, -0.001f) << int(m) << " frame " << k;
    }
  }
}

TEST(HairSim, SettleHoldsTheGroom) {
  SimHead f;
  const int strands = 60, n = 32;
  const std::vector<float> g = simGroom(strands, n);
  HairSim sim;
  sim.init(g.data(), strands, n, &f.head, Eigen::Vector3f(0, -0.1f, 0), SimMotion::Settle, 1);
  for (int k = 0; k < 120; ++k) sim.step();  // 5 s at 24 Hz
  std::vector<float> drift;
  for (size_t i = 0; i < g.size(); i += 3)
    drift.push_back(std::hypot(sim.positions()[i] - g[i], sim.positions()[i + 1] - g[i + 1],
                               sim.positions()[i + 2] - g[i + 2]));
  std::nth_element(drift.begin(), drift.begin() + drift.size() / 2, drift.end());
  EXPECT_LE(drift[drift.size() / 2], 0.001f);
}

TEST(HairSim, SameSeedSameFrames) {
  SimHead f;
  const int strands = 40, n = 16;
  const std::vector<float> g = simGroom(strands, n);
  HairSim a, b, c;
  a.init(g.data(), strands, n, &f.head, Eigen::Vector3f::Zero(), SimMotion::Wind, 5);
  b.init(g.data(), strands, n, &f.head, Eigen::Vector3f::Zero(), SimMotion::Wind, 5);
  c.init(g.data(), strands, n, &f.head, Eigen::Vector3f::Zero(), SimMotion::Wind, 6);
  for (int k = 0; k < 24; ++k) {
    a.step();
    b.step();
    c.step();
    ASSERT_EQ(a.positions(), b.positions()) << k;
  }
  EXPECT_NE(a.positions(), c.positions());
}

TEST(HairSim, HeadTurnMovesTheHair) {
  const int strands = 10, n = 16;
  const std::vector<float> g = simGroom(strands, n);
  HairSim sim;
  sim.init(g.data(), strands, n, nullptr, Eigen::Vector3f::Zero(), SimMotion::HeadTurn, 1);
  for (int k = 0; k < 12; ++k) sim.step();
  EXPECT_NE(sim.positions(), g);
}

TEST(HairSim, FollowersRideTheirGuides) {
  const int strands = 10, n = 16;
  const std::vector<float> g = simGroom(strands, n);
  HairSim sim;
  sim.init(g.data(), strands, n, nullptr, Eigen::Vector3f::Zero(), SimMotion::HeadTurn, 1);
  GuideFollowers followers;
  followers.bind(g.data(), strands, n, sim);  // the guides themselves as followers
  std::vector<float> out(g.size());
  followers.update(sim, out.data());
  EXPECT_EQ(out, g);
  for (int k = 0; k < 6; ++k) sim.step();
  followers.update(sim, out.data());
  for (size_t i = 0; i < out.size(); ++i) EXPECT_NEAR(out[i], sim.positions()[i], 1e-6f);
}

}  // namespace
}  // namespace hairsketch
