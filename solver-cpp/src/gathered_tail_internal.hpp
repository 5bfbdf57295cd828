// Internal to gathered tails (gathered_tail.hpp): what their translation units share.
// gatherTails (gathered_tail.cpp) captures the strands, seats them and rebuilds the buffers; the
// tails' shapes (round, braid, bun: built from their curves and laid) are in
// gathered_tail_shapes.cpp, whole sections (combed hair, the ties' sizes) in
// gathered_tail_sections.cpp. Not part of the solver's API: only those files include it.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gathered_tail.hpp"

namespace hairsketch::gathered_tail {

inline float smoothstepf(float x) {
  x = std::clamp(x, 0.f, 1.f);
  return x * x * (3 - 2 * x);
}

constexpr float kTwoPi = 6.28318530717958647692f;

struct Capture {
  uint32_t strand;
  uint32_t keep;  // points kept (the root .. the point before the crossing)
  Eigen::Vector3f q;
  float remaining;      // the strand's length after q
  float before;         // its length up to q
  float s0;             // arc length along the spine where q is
  bool combed = false;  // taken by a whole-section tie: laid anew from its root (q = the root)
};

// The spine with a frame at every point, transported without twist.
struct SpineFrames {
  std::vector<Eigen::Vector3f> p, t, e1, e2;
  std::vector<float> s, r;
  Eigen::Vector3f lo, hi;  // the body's box: the spine grown by the capture distance

  explicit SpineFrames(const GatheredTail& tail) : p(tail.spine), r(tail.radius) {
    const size_t n = p.size();
    lo = hi = p[0];
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Vector3f g = Eigen::Vector3f::Constant(kTailCapture * r[i]);
      lo = lo.cwiseMin(p[i] - g);
      hi = hi.cwiseMax(p[i] + g);
    }
    s.assign(n, 0.f);
    for (size_t i = 1; i < n; ++i) s[i] = s[i - 1] + (p[i] - p[i - 1]).norm();
    t.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Vector3f d = p[std::min(i + 1, n - 1)] - p[i > 0 ? i - 1 : 0];
      t[i] = d.norm() > 0 ? d.normalized() : tail.axis;
    }
    e1.resize(n);
    e2.resize(n);
    // C1's own plane at the start: the frame the crossings are measured in
    const Eigen::Vector3f a = tail.axis;
    const Eigen::Vector3f away = tail.out - tail.out.dot(a) * a;
    if (away.norm() > 1e-3f) {  // E2 away from the head, E1 across it
      e2[0] = away.normalized();
      e1[0] = e2[0].cross(a);
    } else {
      const Eigen::Vector3f u =
          std::abs(a.y()) < 0.9f ? Eigen::Vector3f::UnitY() : Eigen::Vector3f::UnitX();
      e1[0] = a.cross(u).normalized();
      e2[0] = a.cross(e1[0]);
    }
    for (size_t i = 1; i < n; ++i) {
      Eigen::Vector3f v = e1[i - 1] - e1[i - 1].dot(t[i]) * t[i];
      if (!(v.norm() > 1e-6f)) v = e2[i - 1] - e2[i - 1].dot(t[i]) * t[i];
      e1[i] = v.normalized();
      e2[i] = t[i].cross(e1[i]);
    }
  }

  // Whether x lies beside the body (past C1, within kTailCapture r(s) of the spine); s its arc
  // length there and d2 its squared distance.
  bool nearBody(const Eigen::Vector3f& x, float& sx, float& d2) const {
    if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any()) return false;
    d2 = 1e30f;
    sx = 0;
    float rad = r[0];
    for (size_t k = 0; k + 1 < p.size(); ++k) {
      const Eigen::Vector3f d = p[k + 1] - p[k];
      const float len2 = d.squaredNorm();
      const float f = len2 > 0 ? std::clamp((x - p[k]).dot(d) / len2, 0.f, 1.f) : 0.f;
      const float e2 = (x - p[k] - f * d).squaredNorm();
      if (e2 < d2) {
        d2 = e2;
        sx = s[k] + f * (s[k + 1] - s[k]);
        rad = r[k] + f * (r[k + 1] - r[k]);
      }
    }
    const float capture = kTailCapture * rad;
    return sx > 0 && d2 <= capture * capture;
  }

  // Point, frame and radius at arc length x (past the end: straight on).
  void at(float x, Eigen::Vector3f& pos, Eigen::Vector3f& f1, Eigen::Vector3f& f2,
          float& rad) const {
    const size_t n = p.size();
    if (x >= s[n - 1]) {
      pos = p[n - 1] + (x - s[n - 1]) * t[n - 1];
      f1 = e1[n - 1];
      f2 = e2[n - 1];
      rad = r[n - 1];
      return;
    }
    const size_t i = size_t(std::upper_bound(s.begin(), s.end(), std::max(x, 0.f)) - s.begin());
    const size_t k = std::min(std::max<size_t>(i, 1), n - 1) - 1;
    const float span = s[k + 1] - s[k];
    const float f = span > 0 ? std::clamp((x - s[k]) / span, 0.f, 1.f) : 0.f;
    pos = p[k] + f * (p[k + 1] - p[k]);
    f1 = (e1[k] + f * (e1[k + 1] - e1[k])).normalized();
    f2 = (e2[k] + f * (e2[k + 1] - e2[k])).normalized();
    rad = r[k] + f * (r[k + 1] - r[k]);
  }
};

// Tail shapes (gathered_tail_shapes.cpp).

// Round plaits (T.roundPlaits): how much longer than round a braid bundle's section is, across
// the spine, in the frame's two directions, at phase t of a bundle whose centre swings
// A sin t, B sin 2t over `period`: a slice across the spine cuts a round bundle running at slope
// m to it sqrt(1 + m^2) long (at most kPlaitStretchMax). (1, 1) with round plaits off.
Eigen::Vector2f plaitStretch(const GatheredTail& T, float A, float B, float t, float period);

// A seat's offset in the spine's frame at arc length S (as layAlongSpine lays it).
Eigen::Vector2f seatOffset(const GatheredTail& T, float S, float rad, float theta, float rho,
                           int bundle);

// Round and braided tails: the strand follows the spine from its capture at its seat's offset
// (seated: from its seat at once, q being the seat's point). With T.ties a braid's hair reaches
// the spine's end less kBraidEndCut rho^2 (0.5 + 0.5 endDraw) of its loose tail, the loose tail
// tapers by kTieTaper, and its plait opens from a round gather (kBraidOpenAt).
void layAlongSpine(const GatheredTail& T, const SpineFrames& F, const Capture& cap, float theta,
                   float rho, int bundle, float step, size_t room,
                   std::vector<Eigen::Vector3f>& out, bool seated = false, float endDraw = 0);

// A bun: the strand coils round the axis from its seat angle, over the dome, then tucks under.
void layBun(const GatheredTail& T, const SpineFrames& F, const Capture& cap, float theta, float rho,
            float step, size_t room, float maxLength, std::vector<Eigen::Vector3f>& out);

// Ties from any hand (gathered_tail_ties.cpp; T.ties).

// A round tail's strand: as layAlongSpine, to the spine's end less its own cut, tapering.
void layRoundTie(const GatheredTail& T, const SpineFrames& F, const Capture& cap, float theta,
                 float rho, float u1, float u2, float step, size_t room,
                 std::vector<Eigen::Vector3f>& out, bool seated = false);

// A bun's rope (its centreline as a tail's spine, radius rr) and a strand laid along it from its
// seat (theta, rho) in the rope's first cross-section, at most `budget` long (kWholeRope: the
// whole rope, a compact bun's hair whatever its length).
constexpr float kWholeRope = 1e30f;
GatheredTail bunRope(const GatheredTail& T);
void layBunRope(const SpineFrames& rope, const Capture& cap, float theta, float rho, float budget,
                float step, size_t room, bool seated, std::vector<Eigen::Vector3f>& out);

// Whole sections (gathered_tail_sections.cpp).

// A whole-section strand: combed over the scalp to its seat, then laid as its tail lays hair.
void layCombed(const GatheredTail& T, const SpineFrames& F, const SectionGather& g,
               const Capture& cap, float theta, float rho, int bundle, float lambda, float u,
               float step, size_t room, float maxLength, std::vector<Eigen::Vector3f>& out);
// The same with T.ties: the combed hair rises smoothly to its seat; u1, u2 the strand's draws
// (layRoundTie), rope the bun's rope (null unless a bun).
void layCombedTie(const GatheredTail& T, const SpineFrames& F, const SpineFrames* rope,
                  const SectionGather& g, const Capture& cap, float theta, float rho, int bundle,
                  float lambda, float u1, float u2, float step, size_t room,
                  std::vector<Eigen::Vector3f>& out);

}  // namespace hairsketch::gathered_tail
