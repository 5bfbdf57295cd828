// Whole sections of gathered tails (gathered_tail.hpp "Whole sections"): a tie's size from the
// hair it holds, and a strand combed from its root over the scalp to its seat, then laid.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "gathered_tail_internal.hpp"
#include "head_distance.hpp"

namespace hairsketch {

namespace gathered_tail {

namespace {

// The long way round (combPath) must pass this far above the centre at its middle (the unit
// direction's height).
constexpr float kLongWayAbove = 0.2f;

// A point put `lift` off the head (outside it) along the head's distance gradient, or on the
// sphere about the centre through `onSphere` when there is no head.
Eigen::Vector3f offHead(const SectionGather& g, Eigen::Vector3f x, float lift, float sphere) {
  if (!g.head) return g.centre + (x - g.centre).normalized() * (sphere + lift);
  for (int it = 0; it < 3; ++it) {
    float dir[3];
    const float d = g.head->outward(x.data(), dir);
    x += (lift - d) * Eigen::Vector3f(dir[0], dir[1], dir[2]);
  }
  return x;
}

// A whole-section strand's way from its root over the scalp to the foot of its seat point P,
// then up to P (gathered_tail.hpp); out gets the points after the root, up to P. Returns the
// path's length.
// smooth (ties on): instead of turning up from the foot to P, the hair rises to P over its last
// max(3 cm, kCombRise |P - foot|) on the scalp, so gathered hair lies smoothly into the band.
float combPath(const SectionGather& g, const Eigen::Vector3f& root, const Eigen::Vector3f& P,
               float lambda, float step, size_t maxPoints, std::vector<Eigen::Vector3f>& out,
               bool smooth = false) {
  const Eigen::Vector3f c = g.centre;
  const float sphere = (root - c).norm();
  const Eigen::Vector3f foot = offHead(g, P, g.margin, sphere);
  const float ra = (root - c).norm(), rb = (foot - c).norm();
  const Eigen::Vector3f a = (root - c).normalized(), b = (foot - c).normalized();
  // (ties on) hair is combed back over the head, never down across the face: a root in front of
  // a lower seat (a forehead root and a pigtail's band behind the ear, or a low ponytail's at the
  // nape) is combed back towards a point at its own height above the seat (the waypoint w: the
  // seat's bearing, the root's height) and round down to it; the short way from a forehead root
  // near the parting to a band behind the ear ran across the temple at the eye's height as a strap
  Eigen::Vector3f w = b;
  const Eigen::Vector2f bh(b.x(), b.z());
  const float high = std::max(a.y(), b.y());
  const bool viaAbove =
      smooth && b.y() < a.y() - 0.1f && a.z() - b.z() > 0.3f && bh.norm() > 0.2f && high < 0.95f;
  if (viaAbove) {
    const Eigen::Vector2f h = bh.normalized() * std::sqrt(1 - high * high);
    w = Eigen::Vector3f(h.x(), high, h.y());
  }
  float ang = std::acos(std::clamp(a.dot(b), -1.f, 1.f));
  Eigen::Vector3f axis = a.cross(b);
  if (!(axis.norm() > 1e-5f)) axis = a.cross(Eigen::Vector3f::UnitY());
  if (!(axis.norm() > 1e-5f)) axis = a.cross(Eigen::Vector3f::UnitX());
  axis.normalize();
  // (ties on) when the short way from root to foot passes in front of the centre below the root
  // (a temple root and a seat low on the nape: the short way runs down the cheek), it goes the
  // long way, over the crown: only when the long way does pass over the top (its middle, -mid,
  // above the centre by kLongWayAbove); a crown root beside a bun on top of the head went the
  // long way round under the chin, a veil of hair over the face and throat
  const Eigen::Vector3f mid = (a + b).normalized();
  if (!viaAbove && smooth && (a + b).norm() > 1e-3f && mid.z() > 0 && mid.y() < a.y() &&
      -mid.y() > kLongWayAbove) {
    ang = 2 * 3.14159265f - ang;
    axis = -axis;
  }
  // via w: a quadratic Bezier on the sphere (slerps of slerps, de Casteljau), which turns down
  // towards the seat gradually rather than at a corner above it, tabulated by its angle so that
  // a share t of the route is a share t of its length
  constexpr int kRouteSamples = 64;
  // fixed arrays: this runs for every gathered strand, and heap vectors cost more than the slerps
  std::array<Eigen::Vector3f, kRouteSamples + 1> route;
  std::array<float, kRouteSamples + 1> turned{};
  if (viaAbove) {
    const auto slerp = [](const Eigen::Vector3f& p, const Eigen::Vector3f& q, float t) {
      const float om = std::acos(std::clamp(p.dot(q), -1.f, 1.f));
      if (!(om > 1e-4f)) return Eigen::Vector3f(p);
      return Eigen::Vector3f((std::sin((1 - t) * om) * p + std::sin(t * om) * q) / std::sin(om));
    };
    for (int k = 0; k <= kRouteSamples; ++k) {
      const float t = float(k) / kRouteSamples;
      route[k] = slerp(slerp(a, w, t), slerp(w, b, t), t).normalized();
      turned[k] =
          k == 0 ? 0.f
                 : turned[k - 1] + std::acos(std::clamp(route[k].dot(route[k - 1]), -1.f, 1.f));
    }
    ang = turned.back();
  }
  // the direction at share t of the route's angle
  const auto along = [&](float t) -> Eigen::Vector3f {
    if (!viaAbove) return Eigen::AngleAxisf(t * ang, axis) * a;
    const float at = t * ang;
    const size_t k = std::min<size_t>(kRouteSamples - 1,
                                      size_t(std::upper_bound(turned.begin(), turned.end(), at) -
                                             turned.begin() - (at > 0 ? 1 : 0)));
    const float span = turned[k + 1] - turned[k];
    const float f = span > 0 ? std::clamp((at - turned[k]) / span, 0.f, 1.f) : 0.f;
    return ((1 - f) * route[k] + f * route[k + 1]).normalized();
  };
  const float arc = ang * 0.5f * (ra + rb) + (P - foot).norm();
  const float ds = std::max(step, arc / float(std::max<size_t>(maxPoints, 2)));
  const size_t n = std::max<size_t>(1, size_t(std::ceil(ang * 0.5f * (ra + rb) / ds)));
  const float top = kCombLift * lambda;
  const Eigen::Vector3f rise = P - foot;
  const float overHead = ang * 0.5f * (ra + rb);
  const float span =
      overHead > 0 ? std::min(1.f, std::max(kTailBlend, kCombRise * rise.norm()) / overHead) : 1.f;
  Eigen::Vector3f prev = root;
  float length = 0;
  for (size_t i = 1; i <= n; ++i) {
    const float t = float(i) / float(n);
    const Eigen::Vector3f d = along(t);
    Eigen::Vector3f x =
        offHead(g, c + d * (ra + t * (rb - ra)), g.margin + top * smoothstepf(t), sphere);
    if (smooth) x += smoothstepf((t - (1 - span)) / span) * rise;
    length += (x - prev).norm();
    out.push_back(x);
    prev = x;
  }
  const size_t up = size_t(std::ceil((P - prev).norm() / ds));
  const Eigen::Vector3f from = prev;
  for (size_t i = 1; i <= up; ++i) {
    const Eigen::Vector3f x = from + (P - from) * (float(i) / float(up));
    length += (x - prev).norm();
    out.push_back(x);
    prev = x;
  }
  return length;
}

// A strand too short to reach its tie (or with too few points left): its combed path from q
// while its length L and the point budget last, appended to out; with cutAtLength the last
// point is cut where L runs out (else the path stops at the point before). At least q.
void combedTowards(const std::vector<Eigen::Vector3f>& path, const Eigen::Vector3f& q, float L,
                   size_t room, bool cutAtLength, std::vector<Eigen::Vector3f>& out) {
  float walked = 0;
  Eigen::Vector3f prev = q;
  for (const Eigen::Vector3f& x : path) {
    const float d = (x - prev).norm();
    if (walked + d > L || out.size() + 1 >= room) {
      if (cutAtLength && d > 0 && out.size() + 1 < room)
        out.push_back(prev + (x - prev) * ((L - walked) / d));
      break;
    }
    walked += d;
    out.push_back(x);
    prev = x;
  }
  if (out.empty()) out.push_back(q);
}

}  // namespace

void layCombedTie(const GatheredTail& T, const SpineFrames& F, const SpineFrames* rope,
                  const SectionGather& g, const Capture& cap, float theta, float rho, int bundle,
                  float lambda, float u1, float u2, float step, size_t room,
                  std::vector<Eigen::Vector3f>& out) {
  const bool bun = T.shape == TailShape::Bun && rope;
  Eigen::Vector3f seat;
  if (bun) {
    seat = rope->p[0] +
           rho * rope->r[0] * (std::cos(theta) * rope->e1[0] + std::sin(theta) * rope->e2[0]);
  } else {
    const Eigen::Vector2f o = seatOffset(T, 0, F.r[0], theta, rho, bundle);
    seat = F.p[0] + o.x() * F.e1[0] + o.y() * F.e2[0];
  }
  std::vector<Eigen::Vector3f> path;
  const float way = combPath(g, cap.q, seat, lambda, step, room / 2, path, true);
  // the hair's length by Max length: a bun coils what it has; a compact bun's hair is as long as
  // its rope (a knot shows no hair ending short: shorter hair ends hidden in it)
  const float L = cap.remaining;
  const bool whole = bun && T.compactBun;
  if ((bun && way >= L && !whole) || path.size() + 1 >= room) {  // combed towards the tie
    out.clear();
    combedTowards(path, cap.q, L, room, false, out);
    return;
  }
  out = path;
  Capture tail = cap;
  tail.q = seat;
  tail.before = way;
  tail.s0 = 0;
  // round and braid: as long as the tail needs (layRoundTie, layAlongSpine with ties)
  tail.remaining = std::max(0.f, L - way);
  std::vector<Eigen::Vector3f> laid;
  const size_t left = room - path.size();
  if (bun)
    layBunRope(*rope, tail, theta, rho, whole ? kWholeRope : L - way, step, left, true, laid);
  else if (T.shape == TailShape::Round)
    layRoundTie(T, F, tail, theta, rho, u1, u2, step, left, laid, true);
  else
    layAlongSpine(T, F, tail, theta, rho, bundle, step, left, laid, true, u2);
  out.insert(out.end(), laid.begin() + (laid.empty() ? 0 : 1), laid.end());
}

void layCombed(const GatheredTail& T, const SpineFrames& F, const SectionGather& g,
               const Capture& cap, float theta, float rho, int bundle, float lambda, float u,
               float step, size_t room, float maxLength, std::vector<Eigen::Vector3f>& out) {
  // the seat's point on C1's plane (a bun: on its base circle)
  Eigen::Vector3f seat;
  if (T.shape == TailShape::Bun) {
    const float shell = T.bunRadius * (0.45f + 0.55f * rho);
    seat = T.bunCentre + shell * (std::cos(theta) * F.e1[0] + std::sin(theta) * F.e2[0]);
  } else {
    const Eigen::Vector2f o = seatOffset(T, 0, F.r[0], theta, rho, bundle);
    seat = F.p[0] + o.x() * F.e1[0] + o.y() * F.e2[0];
  }
  std::vector<Eigen::Vector3f> path;
  const float way = combPath(g, cap.q, seat, lambda, step, room / 2, path);
  const float L = cap.remaining;              // the hair's whole length
  if (way >= L || path.size() + 1 >= room) {  // too short to reach the tie: combed towards it
    combedTowards(path, cap.q, L, room, true, out);
    return;
  }
  out = path;
  Capture tail = cap;
  tail.q = seat;
  tail.before = way;
  tail.s0 = 0;
  // a tail ends at its spine's end, less a seeded 0-8 % (ends not cut straight), unless it grows on
  tail.remaining = L - way;
  if (!T.growsOn) tail.remaining = std::min(tail.remaining, F.s.back() * (1 - 0.08f * u));
  std::vector<Eigen::Vector3f> laid;
  const size_t left = room - path.size();
  if (T.shape == TailShape::Bun)
    layBun(T, F, tail, theta, rho, step, left, maxLength, laid);
  else
    layAlongSpine(T, F, tail, theta, rho, bundle, step, left, laid, true);
  out.insert(out.end(), laid.begin() + (laid.empty() ? 0 : 1), laid.end());
}

}  // namespace gathered_tail

float sectionTailRadius(float share) { return kTailRadius * std::sqrt(std::max(share, 0.f)); }

float sectionBunRadius(float share, float lengthAfterTie) {
  // The hair's volume: a full head's tail (kTailRadius) times its length, coiled into a dome of
  // radius R and height 0.6 R whose strands lie a little looser: R = 0.63 (A L)^(1/3) in
  // centimetres, 4.5 cm for a whole head of 30 cm of hair past the tie.
  const float areaCm2 = 3.14159265f * 100 * kTailRadius * kTailRadius * std::max(share, 0.f);
  const float cm = 0.63f * std::cbrt(areaCm2 * 10 * std::max(lengthAfterTie, 0.f));
  return cm / 10;
}

}  // namespace hairsketch
