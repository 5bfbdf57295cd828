// The scene of the ties' tests (tie_tails_test.cpp, tie_braid_bun_test.cpp): whole-section ties
// on a unit-sphere head (no field: gatherTails lays every assigned strand anew from its root),
// with a straight spine hanging from behind the head, so a point's arc along it is its drop below
// C1 and its radius its distance from the vertical line.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "gathered_tail.hpp"

namespace tie_scene {

using namespace hairsketch;

inline constexpr float kTieTestStep = 0.02f;
inline const Eigen::Vector3f kBand(0.f, 0.3f, -1.1f);  // C1's centre, behind the head

struct Head {
  std::vector<Eigen::Vector3f> roots;
  std::vector<uint32_t> key;
  Strands strands;  // each root with a point 1 mm out: combed strands are laid anew
};

// Roots every 6 degrees over the back and top of the unit sphere (y > 0, z < 0.3).
inline Head backOfHead() {
  Head h;
  h.strands.strandStart.push_back(0);
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 60; ++j) {
      const float th = 3.14159265f * (float(i) + 0.5f) / 30, ph = 3.14159265f * float(j) / 30;
      const Eigen::Vector3f p(std::sin(th) * std::cos(ph), std::cos(th),
                              std::sin(th) * std::sin(ph));
      if (p.y() <= 0 || p.z() >= 0.3f) continue;
      h.roots.push_back(p);
      h.key.push_back(uint32_t(h.key.size()));
      for (const Eigen::Vector3f& x : {p, Eigen::Vector3f(1.001f * p)})
        h.strands.points.insert(h.strands.points.end(), {x.x(), x.y(), x.z()});
      h.strands.strandStart.push_back(uint32_t(h.strands.points.size() / 3));
    }
  return h;
}

// A straight spine from the band down `length`, as gatheredTail would give a ponytail.
inline GatheredTail hanging(float length, TailShape shape, bool ties) {
  GatheredTail t;
  for (int i = 0; i <= 20; ++i)
    t.spine.push_back(kBand - Eigen::Vector3f(0, length * float(i) / 20, 0));
  t.radius.assign(t.spine.size(), 0.05f);
  t.axis = -Eigen::Vector3f::UnitY();
  t.out = -Eigen::Vector3f::UnitZ();
  t.shape = shape;
  t.section = true;
  t.anchor = Eigen::Vector3f(0, 0.3f, -0.954f);
  t.ties = ties;
  if (shape == TailShape::Braid) {
    t.braid.section = true;
    t.braidLength = length - float(t.braid.tailLength);
  }
  return t;
}

// Grows `h` into tail t; `every`: only every so many strands are the tie's (the share).
inline Strands grow(const Head& h, const GatheredTail& t, float maxLength, int every = 1,
                    uint64_t seed = 7) {
  SectionGather g;
  g.assigned.assign(h.roots.size(), -1);
  for (size_t s = 0; s < h.roots.size(); s += size_t(every)) g.assigned[s] = 0;
  g.centre = Eigen::Vector3f::Zero();
  Strands out = h.strands;
  gatherTails({t}, h.roots, h.key, seed, kTieTestStep, 255, out, maxLength, &g);
  return out;
}

inline Eigen::Vector3f pointOf(const Strands& s, size_t p) {
  return Eigen::Vector3f(s.points[3 * p], s.points[3 * p + 1], s.points[3 * p + 2]);
}
inline float arcOf(const Eigen::Vector3f& x) { return kBand.y() - x.y(); }  // along the spine
inline float radiusOf(const Eigen::Vector3f& x) { return std::hypot(x.x(), x.z() - kBand.z()); }

// The distances from the axis of the tie's points with arc in [a, b): one per strand, its last
// (hair combed up from below the band passes the window on the scalp first).
inline std::vector<float> radiiAt(const Strands& s, float a, float b, int every = 1) {
  std::vector<float> r;
  for (size_t st = 0; st + 1 < s.strandStart.size(); st += size_t(every)) {
    float last = -1;
    for (uint32_t p = s.strandStart[st]; p < s.strandStart[st + 1]; ++p) {
      const Eigen::Vector3f x = pointOf(s, p);
      if (arcOf(x) >= a && arcOf(x) < b && radiusOf(x) < 0.6f) last = radiusOf(x);
    }
    if (last >= 0) r.push_back(last);
  }
  return r;
}
inline float rms(const std::vector<float>& v) {
  double a = 0;
  for (float x : v) a += double(x) * x;
  return v.empty() ? 0.f : float(std::sqrt(a / double(v.size())));
}
inline float percentile(std::vector<float> v, float q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(q * float(v.size())))];
}
inline Eigen::Vector3f tipOf(const Strands& s, size_t st) {
  return pointOf(s, s.strandStart[st + 1] - 1);
}

}  // namespace tie_scene
