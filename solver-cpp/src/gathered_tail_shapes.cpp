// The shapes of gathered tails (gathered_tail.hpp): a ponytail's round bunch, a braid and a bun,
// built from their curves, and how each lays a captured strand.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "braid_bun.hpp"
#include "gathered_tail_internal.hpp"
#include "ponytail_constraints.hpp"

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

namespace gathered_tail {

namespace {

// Ties on: how far a braid's bundles have spread at S (of their amplitude), opening over half a
// period from a round gather so the combed hair runs into the plait without a ledge.
float braidOpen(const GatheredTail& T, float S, float period) {
  return T.ties ? kBraidOpenAt + (1 - kBraidOpenAt) * smoothstepf(S / (0.5f * period)) : 1.f;
}

}  // namespace

Eigen::Vector2f plaitStretch(const GatheredTail& T, float A, float B, float t, float period) {
  if (!T.roundPlaits || !(period > 0)) return Eigen::Vector2f(1, 1);
  const float mx = A * (kTwoPi / period) * std::cos(t);
  const float my = B * (2 * kTwoPi / period) * std::cos(2 * t);
  return Eigen::Vector2f(std::min(kPlaitStretchMax, std::sqrt(1 + mx * mx)),
                         std::min(kPlaitStretchMax, std::sqrt(1 + my * my)));
}

Eigen::Vector2f seatOffset(const GatheredTail& T, float S, float rad, float theta, float rho,
                           int bundle) {
  const float ct = std::cos(theta), st = std::sin(theta);
  if (T.shape != TailShape::Braid) return Eigen::Vector2f(rho * ct * rad, rho * st * rad);
  const float Lb = T.braidLength, tau = float(T.braid.tightness);
  const float f = Lb > 0 ? std::clamp(S / Lb, 0.f, 1.f) : 1.f;
  const float W = float(T.braid.width) * (1 - 0.4f * f), rb = W * kBraidBundle;
  float A = W / 2 - rb, B = rb * (1.5f - 0.8f * tau);
  if (T.ties) {
    const float open = braidOpen(T, S, float(6.0 / T.braid.crossings));
    A *= open;
    B *= open;
  }
  const float period = float(6.0 / T.braid.crossings);
  const float t = kTwoPi * (S / period + float(bundle) / 3);
  const Eigen::Vector2f k = plaitStretch(T, A, B, t, period);
  return Eigen::Vector2f(A * std::sin(t) + rb * rho * ct * k.x(),
                         B * std::sin(2 * t) + rb * rho * st * k.y());
}

void layAlongSpine(const GatheredTail& T, const SpineFrames& F, const Capture& cap, float theta,
                   float rho, int bundle, float step, size_t room,
                   std::vector<Eigen::Vector3f>& out, bool seated, float endDraw) {
  const bool braid = T.shape == TailShape::Braid;
  const float period = braid ? float(6.0 / T.braid.crossings) : 0.f;
  // a braid's period gets at least 16 points where the cap allows
  const float ds = braid ? std::min(step, period / 16) : step;
  // the hair ends at the spine's end unless its curve lets it grow on
  float remaining =
      T.growsOn ? cap.remaining : std::max(0.f, std::min(cap.remaining, F.s.back() - cap.s0));
  if (T.ties)  // as long as the tail needs: to the spine's end (the loose tail's ends uneven)
    remaining = T.growsOn ? std::max(cap.remaining, F.s.back() - cap.s0)
                          : std::max(0.f, F.s.back() - cap.s0 -
                                              kBraidEndCut * rho * rho * (0.5f + 0.5f * endDraw) *
                                                  float(T.braid.tailLength));
  const size_t segs = std::min(room, std::max<size_t>(1, size_t(std::ceil(remaining / ds))));
  Eigen::Vector3f pq, g1, g2;
  float rq;
  F.at(cap.s0, pq, g1, g2, rq);
  const float xq = (cap.q - pq).dot(g1), yq = (cap.q - pq).dot(g2);
  const float ct = std::cos(theta), st = std::sin(theta);
  const float Lb = T.braidLength;
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
      const Eigen::Vector2f o = seatOffset(T, S, rad, theta, rho, bundle);
      x = o.x();
      y = o.y();
      if (S > Lb) {  // the tie, then the loose tail
        float loose = kBraidLoose * width(Lb) * rho;
        const float w = smoothstepf((S - Lb) / kBraidTie);
        if (T.ties)  // ties on: the loose tail tapers to its end (uneven: the outer hair is cut)
          loose *= 1 - kTieTaper * smoothstepf((S - Lb) / std::max(F.s.back() - Lb, 1e-3f));
        x += (loose * ct - x) * w;
        y += (loose * st - y) * w;
      }
    }
    const float bl = seated ? 1.f : smoothstepf(s / kTailBlend);
    out.push_back(pos + (xq + (x - xq) * bl) * f1 + (yq + (y - yq) * bl) * f2);
  }
}

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

}  // namespace gathered_tail

}  // namespace hairsketch
