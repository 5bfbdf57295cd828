#include "gathered_tail.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

#include "gathered_tail_internal.hpp"
#include "rng.hpp"

namespace hairsketch {

TailStats gatherTails(const std::vector<GatheredTail>& tails,
                      const std::vector<Eigen::Vector3f>& roots, const std::vector<uint32_t>& key,
                      uint64_t seed, float step, size_t maxPoints, Strands& strands,
                      float maxLength, const SectionGather* sections) {
  using namespace gathered_tail;
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
      if (t.ties) {
        sizeTie(t, share, float(after[k] / held[k]));
        continue;
      }
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
  stats.bandRadius.assign(T.size(), 0.f);
  for (size_t k = 0; k < T.size(); ++k)
    if (T[k].shape == TailShape::Round && !T[k].radius.empty())
      stats.bandRadius[k] = T[k].radius[0];
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
    // ties on: each strand's two draws for its end (tieEndCut), their own stream
    auto endDraws = [&](uint32_t m, float& u1, float& u2) {
      Pcg32 rng(seed ^ (uint64_t(key[cs[m].strand]) * 0x9e3779b97f4a7c15ULL), 0x7a12ULL);
      u1 = float(rng.uniform());
      u2 = float(rng.uniform());
    };
    std::vector<SpineFrames> rope;  // ties on, a bun: its rope
    if (Tk.ties && Tk.shape == TailShape::Bun) rope.emplace_back(bunRope(Tk));
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
      float u1 = 0, u2 = 0;
      if (Tk.ties) endDraws(uint32_t(i), u1, u2);
      if (Tk.ties && cap.combed) {
        layCombedTie(Tk, F, rope.empty() ? nullptr : &rope[0], *sections, cap, theta[i], rho[i],
                     bundle[i], distRank[i], u1, u2, step, room, out);
      } else if (Tk.ties && Tk.shape == TailShape::Bun) {
        const float budget = maxLength > 0 ? maxLength - cap.before : cap.remaining;
        layBunRope(rope[0], cap, theta[i], rho[i],
                   Tk.compactBun ? kWholeRope : std::max(budget, cap.remaining), step, room, false,
                   out);
      } else if (Tk.ties && Tk.shape == TailShape::Round) {
        layRoundTie(Tk, F, cap, theta[i], rho[i], u1, u2, step, room, out);
      } else if (Tk.ties) {
        layAlongSpine(Tk, F, cap, theta[i], rho[i], bundle[i], step, room, out, false, u2);
      } else if (cap.combed) {
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
