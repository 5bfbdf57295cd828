// HairSim: lengths kept, no point inside the head, the groom holds at rest, same seed same frames,
// each strand the same bits in any pack and with any thread count.
#include "hair_sim.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "head_distance.hpp"
#include "parallel.hpp"
#include "strand_motion.hpp"

namespace hairsketch {
namespace {

// The app's world units (10 cm): lengths below are written in metres times kU, so the head is the
// size of the app's and the simulation runs with its own defaults (gravity and collision margin
// in world units), as users' hair does.
constexpr float kU = 10.f;

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
    const float r = 0.1f * kU;
    Eigen::Vector3f q(float(r * std::sin(th) * std::cos(ph)), float(r * std::cos(th)),
                      float(r * std::sin(th) * std::sin(ph)));
    Eigen::Vector3f out = q.normalized();
    for (int i = 0; i < n; ++i) {
      p.insert(p.end(), {q.x(), q.y(), q.z()});
      q += 0.005f * kU * out;
    }
  }
  return p;
}

struct SimHead {
  std::vector<float> v;
  std::vector<uint32_t> t;
  HeadDistance head;
  SimHead() {
    simSphere(0.1f * kU, v, t);
    HeadMeshView mesh;
    mesh.positions = v.data();
    mesh.vertexCount = v.size() / 3;
    mesh.indices = t.data();
    mesh.triangleCount = t.size() / 3;
    EXPECT_TRUE(head.build(mesh, 0.005 * kU, 4).ok());
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
    sim.init(g.data(), strands, n, &f.head, Eigen::Vector3f(0, -0.1f * kU, 0), m, 7);
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
      EXPECT_GE(deepest, -0.001f * kU) << int(m) << " frame " << k;
    }
  }
}

TEST(HairSim, SettleHoldsTheGroom) {
  SimHead f;
  const int strands = 60, n = 32;
  const std::vector<float> g = simGroom(strands, n);
  HairSim sim;
  sim.init(g.data(), strands, n, &f.head, Eigen::Vector3f(0, -0.1f * kU, 0), SimMotion::Settle, 1);
  for (int k = 0; k < 120; ++k) sim.step();  // 5 s at 24 Hz
  std::vector<float> drift;
  for (size_t i = 0; i < g.size(); i += 3)
    drift.push_back(std::hypot(sim.positions()[i] - g[i], sim.positions()[i + 1] - g[i + 1],
                               sim.positions()[i + 2] - g[i + 2]));
  std::nth_element(drift.begin(), drift.begin() + drift.size() / 2, drift.end());
  EXPECT_LE(drift[drift.size() / 2], 0.001f * kU);
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

// Strands are stepped eight at a time (a lane each) and split among threads: a strand moves the
// same, bit for bit, with any thread count, in a partial last pack, and stepped alone.
TEST(HairSim, StrandsMoveAloneWhateverTheirPackOrThread) {
  SimHead f;
  const int strands = 203, n = 16;  // 25 full packs and one of 3
  const std::vector<float> g = simGroom(strands, n);
  auto run = [&](const float* points, int count, int threads) {
    parallel::setThreadCount(threads);
    parallel::setAdaptive(false);  // every loop of more than one chunk goes to the workers
    HairSim sim;
    sim.init(points, count, n, &f.head, Eigen::Vector3f(0, -0.1f * kU, 0), SimMotion::HeadTurn, 3);
    const unsigned long long loops = parallel::dispatchedLoops();
    for (int k = 0; k < 24; ++k) sim.step();
    if (threads > 1) EXPECT_EQ(parallel::dispatchedLoops() - loops, 24u);
    parallel::setThreadCount(1);
    parallel::setAdaptive(true);
    return sim.positions();
  };
  const std::vector<float> one = run(g.data(), strands, 1), three = run(g.data(), strands, 3);
  EXPECT_EQ(one, three);
  EXPECT_NE(one, g);
  for (int s : {0, 9, 117, 202}) {
    const std::vector<float> alone = run(g.data() + size_t(s) * n * 3, 1, 1);
    EXPECT_TRUE(std::equal(alone.begin(), alone.end(), one.begin() + size_t(s) * n * 3)) << s;
  }
}

TEST(HairSim, HeadTurnMovesTheHair) {
  const int strands = 10, n = 16;
  const std::vector<float> g = simGroom(strands, n);
  HairSim sim;
  sim.init(g.data(), strands, n, nullptr, Eigen::Vector3f::Zero(), SimMotion::HeadTurn, 1);
  for (int k = 0; k < 12; ++k) sim.step();
  EXPECT_NE(sim.positions(), g);
}

// The groom as the engine lays it: strands of varying point counts (strandStart).
struct VarGroom {
  std::vector<float> points;
  std::vector<uint32_t> start{0};
  std::vector<int32_t> tails;
};

VarGroom simVarGroom(int strands) {
  VarGroom v;
  const std::vector<float> g = simGroom(strands, 24);
  for (int s = 0; s < strands; ++s) {
    const int n = 10 + s % 15;
    v.points.insert(v.points.end(), g.begin() + size_t(s) * 24 * 3,
                    g.begin() + (size_t(s) * 24 + n) * 3);
    v.start.push_back(v.start.back() + n);
    v.tails.push_back(s % 7 == 3 ? 0 : -1);
  }
  return v;
}

MotionInput simMotionInput(const VarGroom& v, const HeadDistance* head, const HeadDistance* body,
                           SimMotion m) {
  MotionInput in;
  in.points = v.points.data();
  in.strandStart = v.start.data();
  in.strandCount = int(v.start.size()) - 1;
  in.tailCurves = v.tails.data();
  in.head = head;
  in.body = body;
  in.pivot = Eigen::Vector3f(0, -0.1f * kU, 0);
  in.motion = m;
  in.seed = 3;
  in.maxGuides = 40;
  return in;
}

// Guides stay outside the head in every motion; a tie's strands all ride one guide (the tail
// moves as one bunch); every point's place along its guide is its arc length from the root, in
// guide points (the guide's length over G - 1 each), at most the guide's tip.
TEST(HairSimMotion, GuidesStayOutsideTiesShareAGuideAndPointsLieAlongIt) {
  SimHead f;
  const VarGroom v = simVarGroom(300);
  for (SimMotion m : {SimMotion::Settle, SimMotion::HeadTurn, SimMotion::Nod, SimMotion::Wind}) {
    StrandMotion motion;
    motion.init(simMotionInput(v, &f.head, nullptr, m));
    EXPECT_LE(motion.guideCount(), 61);
    const int G = motion.guides().pointsPerStrand();
    // frame 0: the guides are their resampled groom
    EXPECT_EQ(motion.guides().positions(), motion.guides().rest());
    for (int k = 0; k < 24; ++k) motion.step();
    const auto& x = motion.guides().positions();
    const HeadPose& pose = motion.pose();
    int inside = 0;
    for (size_t i = 0; i < x.size(); i += 3) {
      Eigen::Vector3f local = pose.rotation.transpose() *
                              (Eigen::Vector3f(x[i], x[i + 1], x[i + 2]) - pose.translation);
      inside += f.head.distance(local.x(), local.y(), local.z()) < -0.001f * kU;
    }
    EXPECT_EQ(inside, 0) << int(m);
    int tieGuide = -2;
    for (size_t s = 0; s + 1 < v.start.size(); ++s) {
      const int32_t g = motion.guideOf()[s];
      ASSERT_GE(g, 0) << s;
      if (v.tails[s] == 0) {
        if (tieGuide == -2) tieGuide = g;
        EXPECT_EQ(g, tieGuide) << s;
      }
      const uint32_t a = v.start[s], b = v.start[s + 1];
      double total = 0;
      std::vector<double> acc{0};
      for (uint32_t p = a + 1; p < b; ++p) {
        const float* q = v.points.data() + 3 * p;
        total += std::hypot(q[0] - q[-3], q[1] - q[-2], q[2] - q[-1]);
        acc.push_back(total);
      }
      // the guide's length: its own strand's (guides are resampled from their strands)
      const int guideStrand = motion.guideStrands()[size_t(motion.guideOf()[s])];
      double guideLength = 0;
      for (uint32_t p = v.start[guideStrand] + 1; p < v.start[guideStrand + 1]; ++p) {
        const float* q = v.points.data() + 3 * p;
        guideLength += std::hypot(q[0] - q[-3], q[1] - q[-2], q[2] - q[-1]);
      }
      for (uint32_t p = a; p < b; ++p)
        EXPECT_NEAR(motion.along()[p], std::min(acc[p - a] / guideLength * (G - 1), G - 1.0), 1e-3)
            << s;
    }
  }
}

TEST(HairSimMotion, SettleHoldsTheGuidesFor5Seconds) {
  SimHead f;
  const VarGroom v = simVarGroom(200);
  StrandMotion motion;
  motion.init(simMotionInput(v, &f.head, nullptr, SimMotion::Settle));
  for (int k = 0; k < 120; ++k) motion.step();
  std::vector<float> drift;
  const auto& x = motion.guides().positions();
  const auto& r = motion.guides().rest();
  for (size_t i = 0; i < x.size(); i += 3)
    drift.push_back(std::hypot(x[i] - r[i], x[i + 1] - r[i + 1], x[i + 2] - r[i + 2]));
  std::nth_element(drift.begin(), drift.begin() + drift.size() / 2, drift.end());
  std::printf("guide drift after 5 s of Settle: median %.4f mm, %d guides\n",
              drift[drift.size() / 2] * 1000 / kU, motion.guideCount());
  EXPECT_LE(drift[drift.size() / 2], 0.001f * kU);
}

// A strand's point at arc length `at` along its points p[0 .. n - 1] (brute force).
Eigen::Vector3f atArcLength(const float* p, int n, float at) {
  float walked = 0;
  for (int i = 1; i < n; ++i) {
    const Eigen::Vector3f a = Eigen::Map<const Eigen::Vector3f>(p + 3 * (i - 1));
    const Eigen::Vector3f b = Eigen::Map<const Eigen::Vector3f>(p + 3 * i);
    const float l = (b - a).norm();
    if (walked + l >= at || i == n - 1)
      return a + (b - a) * (l > 0 ? std::clamp((at - walked) / l, 0.f, 1.f) : 0.f);
    walked += l;
  }
  return Eigen::Map<const Eigen::Vector3f>(p);
}

float arcLength(const float* p, int n) {
  float l = 0;
  for (int i = 1; i < n; ++i)
    l += (Eigen::Map<const Eigen::Vector3f>(p + 3 * i) -
          Eigen::Map<const Eigen::Vector3f>(p + 3 * (i - 1)))
             .norm();
  return l;
}

// Each strand rides, of the 6 guides whose roots are nearest its root, the one whose root and
// point halfway along the shorter of the two lie nearest its own (4 x root distance squared plus
// the distance squared of the two points there): the grid's choice against all guides sorted by
// brute force.
TEST(HairSimMotion, GuideChoiceByGridMatchesBruteForce) {
  const VarGroom v = simVarGroom(2000);
  MotionInput in = simMotionInput(v, nullptr, nullptr, SimMotion::HeadTurn);
  std::vector<int32_t> noTails(v.tails.size(), -1);
  in.tailCurves = noTails.data();
  in.maxGuides = 150;
  StrandMotion m;
  m.init(in);
  const auto& guides = m.guideStrands();
  auto pointsOf = [&](size_t s) { return v.points.data() + 3 * v.start[s]; };
  auto countOf = [&](size_t s) { return int(v.start[s + 1] - v.start[s]); };
  int notNearest = 0, ties = 0;
  for (size_t s = 0; s + 1 < v.start.size(); ++s) {
    const Eigen::Vector3f root = Eigen::Map<const Eigen::Vector3f>(pointsOf(s));
    std::vector<std::pair<float, int>> byRoot;
    for (size_t g = 0; g < guides.size(); ++g)
      byRoot.push_back(
          {(Eigen::Map<const Eigen::Vector3f>(pointsOf(size_t(guides[g]))) - root).squaredNorm(),
           int(g)});
    std::sort(byRoot.begin(), byRoot.end());
    const float mine = arcLength(pointsOf(s), countOf(s));
    float bestCost = INFINITY, chosenCost = INFINITY;
    int best = -1;
    const int G = m.guides().pointsPerStrand();
    for (int k = 0; k < 6 && k < int(byRoot.size()); ++k) {
      const int gi = byRoot[size_t(k)].second;
      const float length =
          arcLength(pointsOf(size_t(guides[size_t(gi)])), countOf(size_t(guides[size_t(gi)])));
      const float half = 0.5f * std::min(mine, length);
      // the guide as simulated (resampled to G points, evenly by the strand's arc length), there
      const float a = half / length * float(G - 1);
      const int j = std::min(G - 2, int(a));
      const float* q = m.guides().rest().data() + (size_t(gi) * G + size_t(j)) * 3;
      const Eigen::Vector3f theirs =
          Eigen::Map<const Eigen::Vector3f>(q) +
          std::min(1.f, a - float(j)) *
              (Eigen::Map<const Eigen::Vector3f>(q + 3) - Eigen::Map<const Eigen::Vector3f>(q));
      const float cost = 4 * byRoot[size_t(k)].first +
                         (atArcLength(pointsOf(s), countOf(s), half) - theirs).squaredNorm();
      if (gi == m.guideOf()[s]) chosenCost = cost;
      if (cost < bestCost) {
        bestCost = cost;
        best = byRoot[size_t(k)].second;
      }
    }
    ASSERT_GE(m.guideOf()[s], 0);
    // the same guide, or one as good to float rounding (the groom is symmetric: near ties)
    EXPECT_LE(chosenCost, bestCost * (1 + 1e-4f) + 1e-9f) << s;
    ties += m.guideOf()[s] != best;
    notNearest += best != byRoot[0].second;
  }
  std::printf("%d of %zu strands ride a guide other than the nearest root's; %d near ties\n",
              notNearest, v.start.size() - 1, ties);
}

// Hair parted: a strand whose root is nearer the guide going the other way rides the guide that
// goes its way.
TEST(HairSimMotion, AStrandRidesTheGuideGoingItsWay) {
  VarGroom v;
  auto strand = [&](float z, float dir) {
    for (int i = 0; i <= 10; ++i) {
      v.points.insert(v.points.end(), {dir * 0.1f * float(i), -0.02f * float(i), z});
    }
    v.start.push_back(v.start.back() + 11);
    v.tails.push_back(-1);
  };
  strand(0.f, 1.f);    // a guide, going +x
  strand(0.1f, -1.f);  // 0.1 from the first guide's root, 0.2 from the second's; going -x
  strand(0.3f, -1.f);  // a guide, going -x
  MotionInput in = simMotionInput(v, nullptr, nullptr, SimMotion::Settle);
  in.maxGuides = 2;
  StrandMotion m;
  m.init(in);
  ASSERT_EQ(m.guideStrands(), (std::vector<int>{0, 2}));
  EXPECT_EQ(m.guideOf()[1], 1);  // the second guide: strand 2
}

}  // namespace
}  // namespace hairsketch
