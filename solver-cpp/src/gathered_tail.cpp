#include "gathered_tail.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "head_distance.hpp"
#include "ponytail_constraints.hpp"
#include "rng.hpp"

namespace hairsketch {

GatheredTail gatheredTail(const double* spine, size_t n, const PonytailParams& params) {
  GatheredTail t;
  if (params.circles.empty() || n == 0) return t;
  auto pointAt = [&](size_t i) {
    return Eigen::Vector3f(float(spine[3 * i]), float(spine[3 * i + 1]), float(spine[3 * i + 2]));
  };
  auto nearest = [&](const Eigen::Vector3d& c) {
    size_t best = 0;
    double bestD = 1e300;
    for (size_t i = 0; i < n; ++i) {
      const double d = (pointAt(i).cast<double>() - c).squaredNorm();
      if (d < bestD) {
        bestD = d;
        best = i;
      }
    }
    return best;
  };
  const PonytailCircle& c1 = params.circles.front();
  const size_t start = nearest(c1.centre);
  t.axis = c1.axis.normalized().cast<float>();
  t.spine.push_back(c1.centre.cast<float>());
  for (size_t i = start + 1; i < n; ++i) t.spine.push_back(pointAt(i));
  if (t.spine.size() < 2) t.spine.push_back(t.spine[0] + t.axis);  // C1 at the tip: hang on
  // arc length of each spine point, and of each circle (at its nearest spine point)
  std::vector<float> s(t.spine.size(), 0.f);
  for (size_t i = 1; i < s.size(); ++i) s[i] = s[i - 1] + (t.spine[i] - t.spine[i - 1]).norm();
  std::vector<std::pair<float, float>> at;  // (arc length, radius), by arc length
  for (const PonytailCircle& c : params.circles) {
    const size_t i = nearest(c.centre);
    at.emplace_back(i <= start ? 0.f : s[std::min(i - start, s.size() - 1)], float(c.radius));
  }
  std::stable_sort(at.begin(), at.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  t.radius.resize(s.size());
  for (size_t i = 0; i < s.size(); ++i) {
    float r = at.back().second;
    if (s[i] <= at.front().first) {
      r = at.front().second;
    } else {
      for (size_t k = 0; k + 1 < at.size(); ++k)
        if (s[i] <= at[k + 1].first) {
          const float span = at[k + 1].first - at[k].first;
          const float f = span > 0 ? (s[i] - at[k].first) / span : 1.f;
          r = at[k].second + f * (at[k + 1].second - at[k].second);
          break;
        }
    }
    t.radius[i] = r;
  }
  return t;
}

GatheredTail braidTail(const double* spine, size_t n, size_t gather, const BraidParams& prm,
                       const Eigen::Vector3f& out) {
  double length = 0;
  GatheredTail t = gatheredTail(spine, n, braidAsPonytail(spine, n, gather, prm, &length));
  t.shape = TailShape::Braid;
  t.braid = prm;
  t.braidLength = float(length);
  t.out = out;
  return t;
}

GatheredTail bunTail(const BunFrame& f, const BunParams& prm) {
  std::vector<double> spine;
  const PonytailParams pp = bunAsPonytail(f, prm, spine);
  GatheredTail t;
  t.axis = f.axis.cast<float>();
  for (const PonytailCircle& k : pp.circles) {
    t.spine.push_back(k.centre.cast<float>());
    t.radius.push_back(float(k.radius));
  }
  t.shape = TailShape::Bun;
  t.bun = prm;
  t.bunCentre = f.centre.cast<float>();
  t.bunRadius = float(f.radius);
  return t;
}

namespace {

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

float smoothstepf(float x) {
  x = std::clamp(x, 0.f, 1.f);
  return x * x * (3 - 2 * x);
}

constexpr float kTwoPi = 6.28318530717958647692f;

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
float combPath(const SectionGather& g, const Eigen::Vector3f& root, const Eigen::Vector3f& P,
               float lambda, float step, size_t maxPoints, std::vector<Eigen::Vector3f>& out) {
  const Eigen::Vector3f c = g.centre;
  const float sphere = (root - c).norm();
  const Eigen::Vector3f foot = offHead(g, P, g.margin, sphere);
  const float ra = (root - c).norm(), rb = (foot - c).norm();
  const Eigen::Vector3f a = (root - c).normalized(), b = (foot - c).normalized();
  const float ang = std::acos(std::clamp(a.dot(b), -1.f, 1.f));
  Eigen::Vector3f axis = a.cross(b);
  if (!(axis.norm() > 1e-5f)) axis = a.cross(Eigen::Vector3f::UnitY());
  if (!(axis.norm() > 1e-5f)) axis = a.cross(Eigen::Vector3f::UnitX());
  axis.normalize();
  const float arc = ang * 0.5f * (ra + rb) + (P - foot).norm();
  const float ds = std::max(step, arc / float(std::max<size_t>(maxPoints, 2)));
  const size_t n = std::max<size_t>(1, size_t(std::ceil(ang * 0.5f * (ra + rb) / ds)));
  const float top = kCombLift * lambda;
  Eigen::Vector3f prev = root;
  float length = 0;
  for (size_t i = 1; i <= n; ++i) {
    const float t = float(i) / float(n);
    const Eigen::Vector3f d = Eigen::AngleAxisf(t * ang, axis) * a;
    const Eigen::Vector3f x =
        offHead(g, c + d * (ra + t * (rb - ra)), g.margin + top * smoothstepf(t), sphere);
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

// A seat's offset in the spine's frame at arc length S (as layAlongSpine lays it).
Eigen::Vector2f seatOffset(const GatheredTail& T, float S, float rad, float theta, float rho,
                           int bundle) {
  const float ct = std::cos(theta), st = std::sin(theta);
  if (T.shape != TailShape::Braid) return Eigen::Vector2f(rho * ct * rad, rho * st * rad);
  const float Lb = T.braidLength, tau = float(T.braid.tightness);
  const float f = Lb > 0 ? std::clamp(S / Lb, 0.f, 1.f) : 1.f;
  const float W = float(T.braid.width) * (1 - 0.4f * f), rb = W * kBraidBundle;
  const float A = W / 2 - rb, B = rb * (1.5f - 0.8f * tau);
  const float t = kTwoPi * (S / float(6.0 / T.braid.crossings) + float(bundle) / 3);
  return Eigen::Vector2f(A * std::sin(t) + rb * rho * ct, B * std::sin(2 * t) + rb * rho * st);
}

// Round and braided tails: the strand follows the spine from its capture at its seat's offset
// (seated: from its seat at once, q being the seat's point).
void layAlongSpine(const GatheredTail& T, const SpineFrames& F, const Capture& cap, float theta,
                   float rho, int bundle, float step, size_t room,
                   std::vector<Eigen::Vector3f>& out, bool seated = false) {
  const bool braid = T.shape == TailShape::Braid;
  const float period = braid ? float(6.0 / T.braid.crossings) : 0.f;
  // a braid's period gets at least 16 points where the cap allows
  const float ds = braid ? std::min(step, period / 16) : step;
  // the hair ends at the spine's end unless its curve lets it grow on
  const float remaining =
      T.growsOn ? cap.remaining : std::max(0.f, std::min(cap.remaining, F.s.back() - cap.s0));
  const size_t segs = std::min(room, std::max<size_t>(1, size_t(std::ceil(remaining / ds))));
  Eigen::Vector3f pq, g1, g2;
  float rq;
  F.at(cap.s0, pq, g1, g2, rq);
  const float xq = (cap.q - pq).dot(g1), yq = (cap.q - pq).dot(g2);
  const float ct = std::cos(theta), st = std::sin(theta);
  const float Lb = T.braidLength, tau = float(T.braid.tightness);
  auto width = [&](float S) {
    const float f = Lb > 0 ? std::clamp(S / Lb, 0.f, 1.f) : 1.f;
    return float(T.braid.width) * (1 - 0.4f * f);
  };
  out.reserve(segs + 1);
  for (size_t j = 0; j <= segs; ++j) {
    const float s = remaining * float(j) / float(segs), S = cap.s0 + s;
    Eigen::Vector3f pos, f1, f2;
    float rad;
    F.at(S, pos, f1, f2, rad);
    float x = rho * ct * rad, y = rho * st * rad;
    if (braid) {
      const float W = width(S), rb = W * kBraidBundle, A = W / 2 - rb, B = rb * (1.5f - 0.8f * tau);
      const float t = kTwoPi * (S / period + float(bundle) / 3);
      x = A * std::sin(t) + rb * rho * ct;
      y = B * std::sin(2 * t) + rb * rho * st;
      if (S > Lb) {  // the tie, then the loose tail
        const float loose = kBraidLoose * width(Lb) * rho, w = smoothstepf((S - Lb) / kBraidTie);
        x += (loose * ct - x) * w;
        y += (loose * st - y) * w;
      }
    }
    const float bl = seated ? 1.f : smoothstepf(s / kTailBlend);
    out.push_back(pos + (xq + (x - xq) * bl) * f1 + (yq + (y - yq) * bl) * f2);
  }
}

// A bun: the strand coils round the axis from its seat angle, over the dome, then tucks under.
void layBun(const GatheredTail& T, const SpineFrames& F, const Capture& cap, float theta, float rho,
            float step, size_t room, float maxLength, std::vector<Eigen::Vector3f>& out) {
  const float R = T.bunRadius, H = float(T.bun.height), Kp = float(T.bun.turns);
  const float shell = R * (0.45f + 0.55f * rho);
  // the hair's budget after q (the field walk stops at the bun's top), up to a full coil
  const float budget = maxLength > 0 ? maxLength - cap.before : cap.remaining;
  const float full = 0.8f * kTwoPi * Kp * shell + 0.5f * H;
  const float L0 = std::max(std::min(std::max(budget, cap.remaining), full), 1e-4f);
  // K turns round the dome are about 0.8 (2 pi r K) long: short hair coils tighter, or (a
  // whole-section bun, whose size is its hair's) winds fewer turns
  const float K = T.section ? std::min(Kp, std::max(0.5f, L0 / (0.8f * kTwoPi * shell))) : Kp;
  const float L = T.section ? std::min(L0, 0.8f * kTwoPi * K * shell + 0.5f * H) : L0;
  const float r0 = std::min(shell, L / (0.8f * kTwoPi * K));
  const size_t segs =
      std::min(room, std::max<size_t>({1, size_t(std::ceil(L / step)), size_t(std::ceil(16 * K))}));
  const Eigen::Vector3f n = T.axis, base = T.bunCentre, e1 = F.e1[0], e2 = F.e2[0];
  auto coil = [&](float u) {
    float z, r, phi;
    if (u <= kBunTuckAt) {
      const float v = u / kBunTuckAt;
      z = H * v;
      r = r0 * std::sqrt(1 - 0.8f * v * v);
      phi = theta + kTwoPi * K * v;
    } else {
      const float w = (u - kBunTuckAt) / (1 - kBunTuckAt);
      z = H * (1 - 0.7f * w);
      r = r0 * std::sqrt(0.2f) * (1 - 0.7f * w);
      phi = theta + kTwoPi * K + 0.25f * kTwoPi * w;
    }
    return Eigen::Vector3f(base + z * n + r * (std::cos(phi) * e1 + std::sin(phi) * e2));
  };
  const Eigen::Vector3f from = cap.q - coil(0);
  out.reserve(segs + 1);
  for (size_t j = 0; j <= segs; ++j) {
    const float u = float(j) / float(segs);
    out.push_back(coil(u) + (1 - smoothstepf(u * L / kTailBlend)) * from);
  }
}

// A whole-section strand: combed over the scalp to its seat, then laid as its tail lays hair.
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
    float walked = 0;
    Eigen::Vector3f prev = cap.q;
    for (const Eigen::Vector3f& x : path) {
      const float d = (x - prev).norm();
      if (walked + d > L || out.size() + 1 >= room) {
        if (d > 0 && out.size() + 1 < room) out.push_back(prev + (x - prev) * ((L - walked) / d));
        break;
      }
      walked += d;
      out.push_back(x);
      prev = x;
    }
    if (out.empty()) out.push_back(cap.q);
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

}  // namespace

float sectionTailRadius(float share) { return kTailRadius * std::sqrt(std::max(share, 0.f)); }

float sectionBunRadius(float share, float lengthAfterTie) {
  // The hair's volume: a full head's tail (kTailRadius) times its length, coiled into a dome of
  // radius R and height 0.6 R whose strands lie a little looser: R = 0.63 (A L)^(1/3) in
  // centimetres, 4.5 cm for a whole head of 30 cm of hair past the tie.
  const float areaCm2 = 3.14159265f * 100 * kTailRadius * kTailRadius * std::max(share, 0.f);
  const float cm = 0.63f * std::cbrt(areaCm2 * 10 * std::max(lengthAfterTie, 0.f));
  return cm / 10;
}

TailStats gatherTails(const std::vector<GatheredTail>& tails,
                      const std::vector<Eigen::Vector3f>& roots, const std::vector<uint32_t>& key,
                      uint64_t seed, float step, size_t maxPoints, Strands& strands,
                      float maxLength, const SectionGather* sections) {
  TailStats stats;
  const size_t nS = strands.strandStart.empty() ? 0 : strands.strandStart.size() - 1;
  if (tails.empty() || nS == 0 || !(step > 0)) return stats;
  const float* P = strands.points.data();
  auto point = [&](uint32_t p) { return Eigen::Vector3f(P[3 * p], P[3 * p + 1], P[3 * p + 2]); };
  auto grownLength = [&](size_t st) {
    float len = 0;
    for (uint32_t p = strands.strandStart[st] + 1; p < strands.strandStart[st + 1]; ++p)
      len += (point(p) - point(p - 1)).norm();
    return len;
  };
  // whole-section ties: their strands, and their size from the hair they hold
  const bool bySection = sections && sections->assigned.size() == nS;
  auto sectionTie = [&](size_t st) {
    const int32_t k = bySection ? sections->assigned[st] : -1;
    return k >= 0 && size_t(k) < tails.size() && tails[size_t(k)].section ? k : -1;
  };
  auto hairLength = [&](size_t st) {
    return maxLength > 0 && maxLength < 1e5f ? maxLength : grownLength(st);
  };
  std::vector<GatheredTail> T(tails);
  {
    std::vector<size_t> held(tails.size(), 0);
    std::vector<double> after(tails.size(), 0);
    for (size_t st = 0; st < nS; ++st) {
      const int32_t k = sectionTie(st);
      if (k < 0) continue;
      ++held[size_t(k)];
      const float way = 1.2f * (roots[st] - tails[size_t(k)].anchor).norm();
      after[size_t(k)] += std::max(0.f, hairLength(st) - way);
    }
    for (size_t k = 0; k < T.size(); ++k) {
      if (!T[k].section || held[k] == 0) continue;
      const float share = float(held[k]) / float(nS);
      GatheredTail& t = T[k];
      if (t.shape == TailShape::Bun) {
        t.bunRadius = std::max(t.bunRadius, sectionBunRadius(share, float(after[k] / held[k])));
        t.bun.height = std::max(t.bun.height, 0.6 * t.bunRadius);
      } else if (t.shape == TailShape::Braid) {
        t.braid.width = std::max(t.braid.width, 3.0 * double(sectionTailRadius(share)));
      } else {
        float arc = 0, total = 0;
        for (size_t i = 1; i < t.spine.size(); ++i) total += (t.spine[i] - t.spine[i - 1]).norm();
        const float tie = kTieRadius * std::sqrt(share), body = sectionTailRadius(share);
        for (size_t i = 0; i < t.spine.size(); ++i) {
          if (i > 0) arc += (t.spine[i] - t.spine[i - 1]).norm();
          const float hold = tie + (body - tie) * smoothstepf(arc / kTailBlend);
          const float spread =
              total > 0 ? 1 + 0.3f * smoothstepf((arc - 0.7f * total) / (0.3f * total)) : 1.f;
          t.radius[i] = std::max(t.radius[i], hold) * spread;
        }
      }
    }
  }
  std::vector<SpineFrames> frames;
  for (const GatheredTail& t : T) frames.emplace_back(t);
  // capture: the first crossing of a C1 plane near its axis, or the first point beside a body
  std::vector<std::vector<Capture>> caught(tails.size());
  for (size_t st = 0; st < nS; ++st) {
    const uint32_t a = strands.strandStart[st], b = strands.strandStart[st + 1];
    if (const int32_t k = sectionTie(st); k >= 0) {
      Capture cap{uint32_t(st), 1, roots[st], hairLength(st), 0, 0};
      cap.combed = true;
      caught[size_t(k)].push_back(cap);
      continue;
    }
    int tail = -1;
    uint32_t at = b;  // the first point after q
    Eigen::Vector3f q;
    float s0 = 0;
    uint32_t keep = 0;  // points before q
    for (size_t k = 0; k < tails.size(); ++k) {
      if (tails[k].section) continue;  // takes its section's hair alone
      const SpineFrames& F = frames[k];
      const Eigen::Vector3f c = F.p[0], ax = tails[k].axis;
      const float capture =
          (tails[k].shape == TailShape::Bun ? kBunCapture : kTailCapture) * F.r[0];
      float w0 = (Eigen::Vector3f(P[3 * a], P[3 * a + 1], P[3 * a + 2]) - c).dot(ax);
      for (uint32_t p = a; p + 1 < b && p + 2 <= at; ++p) {
        const Eigen::Vector3f p1(P[3 * p + 3], P[3 * p + 4], P[3 * p + 5]);
        const float w1 = (p1 - c).dot(ax);
        if (w0 < 0 && w1 >= 0) {
          const Eigen::Vector3f p0(P[3 * p], P[3 * p + 1], P[3 * p + 2]);
          const Eigen::Vector3f x = p0 + (w0 / (w0 - w1)) * (p1 - p0);
          const Eigen::Vector3f off = (x - c) - (x - c).dot(ax) * ax;
          if (off.norm() <= capture) {
            tail = int(k);
            at = p + 1;
            keep = p + 1 - a;
            q = x;
            s0 = 0;
            break;
          }
        }
        float sx, d2;
        if (w1 >= 0 && p + 2 < at && F.nearBody(p1, sx, d2)) {
          tail = int(k);
          at = p + 2;
          keep = p + 1 - a;
          q = p1;
          s0 = sx;
          break;
        }
        w0 = w1;
      }
    }
    if (tail < 0) continue;
    float remaining = 0;
    Eigen::Vector3f prev = q;
    for (uint32_t p = at; p < b; ++p) {
      const Eigen::Vector3f x(P[3 * p], P[3 * p + 1], P[3 * p + 2]);
      remaining += (x - prev).norm();
      prev = x;
    }
    float before = 0;
    for (uint32_t p = a + 1; p < a + keep; ++p)
      before += (Eigen::Vector3f(P[3 * p], P[3 * p + 1], P[3 * p + 2]) -
                 Eigen::Vector3f(P[3 * p - 3], P[3 * p - 2], P[3 * p - 1]))
                    .norm();
    if (keep > 0)
      before += (q - Eigen::Vector3f(P[3 * (a + keep - 1)], P[3 * (a + keep - 1) + 1],
                                     P[3 * (a + keep - 1) + 2]))
                    .norm();
    caught[size_t(tail)].push_back({uint32_t(st), keep, q, remaining, before, s0});
  }
  // seats, then the new strands
  std::vector<std::vector<Eigen::Vector3f>> laid(nS);
  std::vector<char> isLaid(nS, 0);
  std::vector<uint32_t> laidBy(nS, 0);
  for (size_t k = 0; k < tails.size(); ++k) {
    const std::vector<Capture>& cs = caught[k];
    const size_t N = cs.size();
    if (N == 0) continue;
    const SpineFrames& F = frames[k];
    const Eigen::Vector3f c = F.p[0];
    std::vector<float> angle(N), dist(N);
    for (size_t i = 0; i < N; ++i) {
      const Eigen::Vector3f v = roots[cs[i].strand] - c;
      angle[i] = std::atan2(v.dot(F.e2[0]), v.dot(F.e1[0]));
      dist[i] = (v - v.dot(tails[k].axis) * tails[k].axis).norm();
    }
    std::vector<uint32_t> byAngle(N), byDist(N);
    std::iota(byAngle.begin(), byAngle.end(), 0u);
    std::iota(byDist.begin(), byDist.end(), 0u);
    std::stable_sort(byAngle.begin(), byAngle.end(),
                     [&](uint32_t x, uint32_t y) { return angle[x] < angle[y]; });
    std::stable_sort(byDist.begin(), byDist.end(),
                     [&](uint32_t x, uint32_t y) { return dist[x] < dist[y]; });
    // start after the widest gap between neighbouring angles (the wrap included)
    size_t first = 0;
    float widest = angle[byAngle[0]] + kTwoPi - angle[byAngle[N - 1]];
    for (size_t i = 1; i < N; ++i) {
      const float gap = angle[byAngle[i]] - angle[byAngle[i - 1]];
      if (gap > widest) {
        widest = gap;
        first = i;
      }
    }
    const float theta0 = angle[byAngle[first]];
    const GatheredTail& Tk = T[k];
    std::vector<float> distRank(N, 0.f);
    for (size_t j = 0; j < N; ++j) distRank[byDist[j]] = (float(j) + 0.5f) / float(N);
    auto jitter = [&](uint32_t m) {
      Pcg32 rng(seed ^ (uint64_t(key[cs[m].strand]) * 0x9e3779b97f4a7c15ULL), 0x7a11ULL);
      return float(rng.uniform());
    };
    // seats: an angle theta and a radius rho in the unit disc (for a braid, in its bundle's)
    std::vector<float> theta(N), rho(N);
    std::vector<uint8_t> bundle(N, 0);
    if (Tk.shape == TailShape::Braid) {
      std::vector<std::vector<uint32_t>> members(3);
      for (size_t i = 0; i < N; ++i) {
        const uint32_t m = byAngle[(first + i) % N];
        bundle[m] = uint8_t(3 * i / N);
        members[bundle[m]].push_back(m);  // in angle order
      }
      for (std::vector<uint32_t>& mb : members) {
        const size_t nb = mb.size();
        for (size_t i = 0; i < nb; ++i)
          theta[mb[i]] = kTwoPi * (float(i) + jitter(mb[i])) / float(nb);
        std::stable_sort(mb.begin(), mb.end(),
                         [&](uint32_t x, uint32_t y) { return dist[x] < dist[y]; });
        for (size_t j = 0; j < nb; ++j) rho[mb[j]] = std::sqrt((float(j) + 0.5f) / float(nb));
      }
    } else {
      for (size_t i = 0; i < N; ++i) {
        const uint32_t m = byAngle[(first + i) % N];
        theta[m] = theta0 + kTwoPi * (float(i) + jitter(m)) / float(N);
      }
      for (size_t j = 0; j < N; ++j) rho[byDist[j]] = std::sqrt((float(j) + 0.5f) / float(N));
    }
    for (size_t i = 0; i < N; ++i) {
      const Capture& cap = cs[i];
      const size_t room = maxPoints > cap.keep + 1 ? maxPoints - cap.keep - 1 : 0;
      if (room == 0) continue;
      std::vector<Eigen::Vector3f>& out = laid[cap.strand];
      if (cap.combed) {
        layCombed(Tk, F, *sections, cap, theta[i], rho[i], bundle[i], distRank[i],
                  jitter(uint32_t(i)), step, room, maxLength, out);
      } else if (Tk.shape == TailShape::Bun) {
        layBun(Tk, F, cap, theta[i], rho[i], step, room, maxLength, out);
      } else {
        layAlongSpine(Tk, F, cap, theta[i], rho[i], bundle[i], step, room, out);
      }
      isLaid[cap.strand] = 1;
      laidBy[cap.strand] = uint32_t(k);
      ++stats.captured;
    }
  }
  if (stats.captured == 0) return stats;
  // rebuild the buffers: kept prefixes and laid tails in strand order
  std::vector<uint32_t> keepOf(nS, 0);
  for (const auto& cs : caught)
    for (const Capture& cap : cs) keepOf[cap.strand] = cap.keep;
  decltype(Strands::points) points;
  size_t total = 0;
  for (size_t st = 0; st < nS; ++st)
    total += isLaid[st] ? keepOf[st] + laid[st].size()
                        : strands.strandStart[st + 1] - strands.strandStart[st];
  points.resize(3 * total);
  std::vector<uint32_t> start(nS + 1, 0);
  size_t w = 0;
  for (size_t st = 0; st < nS; ++st) {
    const uint32_t a = strands.strandStart[st], b = strands.strandStart[st + 1];
    const uint32_t kept = isLaid[st] ? keepOf[st] : b - a;
    std::copy(P + 3 * size_t(a), P + 3 * size_t(a + kept), points.begin() + std::ptrdiff_t(3 * w));
    w += kept;
    if (isLaid[st])
      for (const Eigen::Vector3f& x : laid[st]) {
        points[3 * w] = x.x();
        points[3 * w + 1] = x.y();
        points[3 * w + 2] = x.z();
        ++w;
      }
    start[st + 1] = uint32_t(w);
  }
  strands.points = std::move(points);
  strands.strandStart = std::move(start);
  for (size_t st = 0; st < nS; ++st)
    if (isLaid[st]) {
      stats.strands.push_back(uint32_t(st));
      stats.tail.push_back(laidBy[st]);
    }
  return stats;
}

}  // namespace hairsketch
