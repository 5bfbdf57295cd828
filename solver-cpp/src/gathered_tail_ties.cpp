// Ties from any hand (gathered_tail.hpp "Ties"): with the session's `ties` on, a round tail
// tapers to uneven ends and a bun is a twisted rope coiled round its base. The ties-off layouts
// (gathered_tail_shapes.cpp) are untouched so saved sessions keep their hair.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "gathered_tail_internal.hpp"

namespace hairsketch {

// full for its first half, then narrowing: a tail thins where its shorter hair has ended
float tieTaper(float f) { return 1 - kTieTaper * gathered_tail::smoothstepf((f - 0.5f) / 0.5f); }

float tieEndCut(float rho, float u1, float u2) {
  // rho^2 is the seat's share of the disc inside it: the outer hair gives up most of its length
  return kTieEndOuter * rho * rho * (0.5f + 0.5f * u1) + kTieEndAll * u2;
}

void bunRopeShape(float R, float K, float& rr, float& H) {
  rr = R / (kBunRopePitch * K + 2);
  H = std::max(H, std::max(0.7f * R, 2.2f * rr));
}

void knotShape(float R, float K, float height, float& rr, float& H) {
  rr = R / (kKnotWrap + kKnotSpread * K + 1);
  // the height asked for spaces the wraps further apart, up to just touching (2 rr)
  H = rr * (2 + kKnotPitch * K);
  H = std::max(H, std::min(height, rr * (2 + 2 * K)));
}

void sizeTie(GatheredTail& t, float share, float after) {
  const float tie = kTieRadius * std::sqrt(share);
  // tie volume widens round tails and buns; a braid's three bundles are as wide as before (three
  // times the body: half as wide again read as a stack of beads)
  const float plain = sectionTailRadius(share);
  const float body = (t.tieVolume ? kTieVolume : 1.f) * plain;
  if (t.shape == TailShape::Bun && t.compactBun) {
    // the rope holds the hair twisted tight; as many wraps as its length allows past the stub:
    // K wraps at a mean radius (kKnotWrap + kKnotSpread K / 2) rr
    const float rr = kKnotRope * plain;
    float K = 1;
    for (int it = 0; it < 6; ++it) {
      const float top = rr * (1 + kKnotPitch * K);
      const float perTurn = gathered_tail::kTwoPi * rr * (kKnotWrap + 0.5f * kKnotSpread * K);
      K = std::clamp(std::max(0.f, after - top) / perTurn, kKnotMinTurns, 6.f);
    }
    t.bun.turns = K;
    t.bunRadius = rr * (kKnotWrap + kKnotSpread * K + 1);
  } else if (t.shape == TailShape::Bun) {
    // the rope holds the hair; as many turns as its length allows once it has climbed the stub
    const float rr = kBunRopeFill * body;
    float K = 1;
    for (int it = 0; it < 4; ++it) {
      float r = 0, H = float(t.bun.height);
      bunRopeShape(rr * (kBunRopePitch * K + 2), K, r, H);
      // the coil's length: K turns at a mean radius R / 2, pi rr (p K^2 + 2 K)
      const float x = std::max(0.f, after - H) / (3.14159265f * rr);
      K = (-2 + std::sqrt(4 + 4 * kBunRopePitch * x)) / (2 * kBunRopePitch);
      K = std::clamp(K, 1.f, 6.f);
    }
    t.bun.turns = K;
    t.bunRadius = rr * (kBunRopePitch * K + 2);
  } else if (t.shape == TailShape::Braid) {
    t.braid.width = std::max(t.braid.width, 3.0 * double(plain));
  } else {
    // full at the band, the body below it (tieTaper narrows the end when laid). The band holds
    // what it gathers however wide the profiles were drawn there: a new user's profiles begin on
    // the head, loosely, and widths of 2-3 cm at the band put half its seats inside the head (the
    // hair rose over the head as a topknot and hung off the spine below); drawn widths past
    // kBandDrawnRadius shape the tail from kTailBlend below the band on. A ponytail of one
    // stroke (drawn 8 mm) is laid as before.
    const float band = std::max(tie, kBandDrawnRadius);
    float arc = 0;
    for (size_t i = 0; i < t.spine.size(); ++i) {
      if (i > 0) arc += (t.spine[i] - t.spine[i - 1]).norm();
      const float f = gathered_tail::smoothstepf(arc / kTailBlend);
      const float drawn = std::min(t.radius[i], band + (t.radius[i] - band) * f);
      t.radius[i] = std::max(drawn, tie + (body - tie) * f);
    }
  }
}

namespace gathered_tail {

void layRoundTie(const GatheredTail& T, const SpineFrames& F, const Capture& cap, float theta,
                 float rho, float u1, float u2, float step, size_t room,
                 std::vector<Eigen::Vector3f>& out, bool seated) {
  const float Ls = F.s.back();
  const float cut = tieEndCut(rho, u1, u2);
  // a tie's hair is as long as its tail needs: to the spine's end (less its own cut), or on
  const float wanted = T.growsOn ? std::max(cap.remaining, Ls - cap.s0) : Ls - cap.s0;
  const float remaining = std::max(0.f, wanted - cut * Ls);
  const size_t segs = std::min(room, std::max<size_t>(1, size_t(std::ceil(remaining / step))));
  Eigen::Vector3f pq, g1, g2;
  float rq;
  F.at(cap.s0, pq, g1, g2, rq);
  const float xq = (cap.q - pq).dot(g1), yq = (cap.q - pq).dot(g2);
  const float ct = std::cos(theta), st = std::sin(theta);
  out.reserve(segs + 1);
  for (size_t j = 0; j <= segs; ++j) {
    const float s = remaining * float(j) / float(segs), S = cap.s0 + s;
    Eigen::Vector3f pos, f1, f2;
    float rad;
    F.at(S, pos, f1, f2, rad);
    const float r = rho * rad * (Ls > 0 ? tieTaper(S / Ls) : 1.f);
    const float bl = seated ? 1.f : smoothstepf(s / kTailBlend);
    out.push_back(pos + (xq + (r * ct - xq) * bl) * f1 + (yq + (r * st - yq) * bl) * f2);
  }
}

GatheredTail bunRope(const GatheredTail& T) {
  // The rope's centreline in the bun's frame (e1, e2 across, n up from the base c): up the axis
  // from the band (the ponytail's stub, hidden inside the coil), over the top's centre (the top
  // is rope, no hole), then K turns outward and down the dome to the base, then a quarter turn
  // in and down under the outer wrap (the end tucked under).
  SpineFrames F0(T);  // only for the bun's frame at its base
  const Eigen::Vector3f n = T.axis, c = T.bunCentre, e1 = F0.e1[0], e2 = F0.e2[0];
  const float R = T.bunRadius, K = std::max(float(T.bun.turns), 0.5f);
  float rr, H = float(T.bun.height);
  if (T.compactBun)
    knotShape(R, K, float(T.bun.height), rr, H);
  else
    bunRopeShape(R, K, rr, H);
  // heights are over the scalp, not the base's tangent plane: the head (radius about
  // kBunHeadRadius) falls away by r^2 / 2 kBunHeadRadius at r from the centre, and the outer
  // wraps follow it down instead of floating over a gap
  auto at = [&](float r, float phi, float z) {
    z -= r * r / (2 * kBunHeadRadius);
    return Eigen::Vector3f(c + z * n + r * (std::cos(phi) * e1 + std::sin(phi) * e2));
  };
  GatheredTail rope;
  rope.axis = n;
  rope.out = e2;
  // the coiled rope spirals out over a dome from the top's centre; the compact knot
  // (knotShape) wraps its own stub from the top down
  const bool knot = T.compactBun;
  const float top = H - rr, r0 = knot ? kKnotWrap * rr : rr;
  const float stub = knot ? top - 0.5f * rr : std::max(0.f, top - 1.5f * rr);
  const float rEnd = knot ? r0 + kKnotSpread * rr * K : R - rr;
  const float tuckIn = knot ? 1.2f : 1.5f, tuckDown = knot ? 0.6f : 0.7f;
  auto wrap = [&](float v) {
    if (knot) return at(r0 + kKnotSpread * rr * K * v, kTwoPi * K * v, top - (top - rr) * v);
    return at(rr + (R - 2 * rr) * v, kTwoPi * K * v, rr + (top - rr) * (1 - v * v));
  };
  for (int i = 0; i <= 4; ++i) rope.spine.push_back(c + (stub * float(i) / 4) * n);
  // the bend over the top: a quadratic from the stub's end through (0, top) to the coil's start
  const Eigen::Vector3f b0 = rope.spine.back(), b1 = c + top * n, b2 = at(r0, 0, top);
  for (int i = 1; i <= 6; ++i) {
    const float t = float(i) / 6;
    rope.spine.push_back((1 - t) * (1 - t) * b0 + 2 * t * (1 - t) * b1 + t * t * b2);
  }
  const int turns = std::max(8, int(std::ceil(24 * K)));
  for (int i = 1; i <= turns; ++i) rope.spine.push_back(wrap(float(i) / float(turns)));
  // a quarter turn in and down under the outer (or lowest) wrap: the end tucked under
  for (int i = 1; i <= 6; ++i) {
    const float w = float(i) / 6;
    rope.spine.push_back(
        at(rEnd - tuckIn * rr * w, kTwoPi * (K + 0.25f * w), rr * (1 - tuckDown * w)));
  }
  rope.radius.assign(rope.spine.size(), rr);
  return rope;
}

void layBunRope(const SpineFrames& rope, const Capture& cap, float theta, float rho, float budget,
                float step, size_t room, bool seated, std::vector<Eigen::Vector3f>& out) {
  // twists of the rope: a turn every kBunRopeTwist rope radii shows the wraps' strands slanting;
  // a strand winding round the rope's centreline is longer than it by the helix's factor
  const float rr = rope.r[0], twist = kTwoPi / (kBunRopeTwist * rr);
  const float helix = std::sqrt(1 + (twist * rho * rr) * (twist * rho * rr));
  const float L = std::clamp(budget / helix, 1e-4f, rope.s.back());
  const size_t segs = std::min(room, std::max<size_t>(1, size_t(std::ceil(L / step))));
  const Eigen::Vector3f from =
      cap.q -
      (rope.p[0] + rho * rr * (std::cos(theta) * rope.e1[0] + std::sin(theta) * rope.e2[0]));
  out.reserve(segs + 1);
  for (size_t j = 0; j <= segs; ++j) {
    const float s = L * float(j) / float(segs);
    Eigen::Vector3f pos, f1, f2;
    float rad;
    rope.at(s, pos, f1, f2, rad);
    // the last 2 rope radii of the strand go into the rope's core: the tip is tucked in
    const float r = rho * rad * (1 - 0.8f * smoothstepf((s - (L - 2 * rr)) / (2 * rr)));
    const float a = theta + twist * s;
    const float bl = seated ? 0.f : 1 - smoothstepf(s / kTailBlend);
    out.push_back(pos + r * (std::cos(a) * f1 + std::sin(a) * f2) + bl * from);
  }
}

}  // namespace gathered_tail

}  // namespace hairsketch
