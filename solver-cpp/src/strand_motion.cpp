// A grown groom in motion: guides picked and resampled, ties bound to their tail, every strand
// bound to a guide (strand_motion.hpp), over HairSim (hair_sim.cpp).
#include "strand_motion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "hair_sim.hpp"
#include "head_distance.hpp"
#include "parallel.hpp"

namespace hairsketch {

namespace {

// Arc length at each point of the polyline p[0 .. count - 1] (acc[0] = 0).
void followerArcLengths(const float* p, int count, std::vector<float>& acc) {
  acc.assign(size_t(std::max(count, 1)), 0.0f);
  for (int i = 1; i < count; ++i) {
    const float* a = p + 3 * (i - 1);
    const float* b = p + 3 * i;
    acc[i] = acc[i - 1] + std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                                    (b[2] - a[2]) * (b[2] - a[2]));
  }
}

// The polyline p[0 .. n - 1]'s point at arc length `at` (acc: its arc lengths), clamped to it.
Eigen::Vector3f pointAtArcLength(const float* p, const std::vector<float>& acc, int n, float at) {
  int j = 0;
  while (j + 2 < n && acc[j + 1] < at) ++j;
  const float seg = acc[j + 1] - acc[j];
  const float w = seg > 0 ? std::clamp((at - acc[j]) / seg, 0.0f, 1.0f) : 0.0f;
  return (1 - w) * Eigen::Map<const Eigen::Vector3f>(p + 3 * j) +
         w * Eigen::Map<const Eigen::Vector3f>(p + 3 * (j + 1));
}

// Guides a strand chooses its own among: those whose roots are nearest its root; and the weight
// of the roots' distance squared against the distance squared of the two paths halfway (a guide
// whose root is far rides its strand's root off its own on every frame: at 1, on long at 8K
// strands, 33 segments of a Head turn frame stretched over 2x near their roots; at 4, 3).
constexpr int kCandidates = 6;
constexpr float kRootWeight = 4;

}  // namespace

void StrandMotion::init(const MotionInput& in) {
  const HeadDistance* head = in.head && in.head->built() ? in.head : nullptr;
  const HeadDistance* body = in.body && in.body->built() ? in.body : nullptr;
  const int count = std::max(0, in.strandCount);
  const uint32_t* start = in.strandStart;
  const size_t points = count > 0 ? start[count] : 0;
  const float* rest = in.points;
  auto pointsOf = [&](int s) { return int(start[s + 1] - start[s]); };
  auto tailOf = [&](int s) { return in.tailCurves ? in.tailCurves[s] : -1; };
  // Guides: every k-th strand that has a segment; each tail gets at least one.
  int visible = 0;
  for (int s = 0; s < count; ++s) visible += pointsOf(s) >= 2;
  const int k = std::max(1, (visible + std::max(1, in.maxGuides) - 1) / std::max(1, in.maxGuides));
  std::vector<int> guides;
  std::vector<int32_t> guideIndex(size_t(count), -1);
  std::vector<int32_t> tailGuide;  // per tail curve: its guide (index into guides), or -1
  int seen = 0;
  for (int s = 0; s < count; ++s) {
    if (pointsOf(s) < 2) continue;
    const int t = tailOf(s);
    bool take = seen++ % k == 0;
    if (t >= 0) {
      if (size_t(t) >= tailGuide.size()) tailGuide.resize(size_t(t) + 1, -1);
      take = tailGuide[t] < 0;  // one guide per tail: the whole bunch follows it
      if (take) tailGuide[t] = int32_t(guides.size());
    }
    if (take) {
      guideIndex[s] = int32_t(guides.size());
      guides.push_back(s);
    }
  }
  // Resample each guide to G points by arc length.
  const int G = std::max(3, in.guidePoints);
  std::vector<float> gp(guides.size() * G * 3);
  std::vector<float> gLength(guides.size());
  parallel::forRange(0, guides.size(), 64, [&](size_t b, size_t e) {
    std::vector<float> acc;
    for (size_t g = b; g < e; ++g) {
      const int s = guides[g];
      const float* p = rest + 3 * size_t(start[s]);
      const int n = pointsOf(s);
      followerArcLengths(p, n, acc);
      gLength[g] = acc[n - 1];
      int j = 0;
      for (int i = 0; i < G; ++i) {
        const float a = acc[n - 1] * float(i) / float(G - 1);
        while (j + 2 < n && acc[j + 1] < a) ++j;
        const float seg = acc[j + 1] - acc[j];
        const float w = seg > 0 ? std::clamp((a - acc[j]) / seg, 0.0f, 1.0f) : 0.0f;
        for (int c = 0; c < 3; ++c)
          gp[(g * G + i) * 3 + c] = p[3 * j + c] + w * (p[3 * (j + 1) + c] - p[3 * j + c]);
      }
    }
  });
  guides_ = guides;
  sim_.init(gp.data(), int(guides.size()), G, head, in.pivot, in.motion, in.seed, in.settings,
            body);
  // Followers: the guide with the nearest root, by a uniform grid over the guides' roots.
  guideOf_.assign(size_t(count), -1);
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(INFINITY), hi = -lo;
  for (int s : guides) {
    const Eigen::Vector3f r = Eigen::Map<const Eigen::Vector3f>(rest + 3 * start[s]);
    lo = lo.cwiseMin(r);
    hi = hi.cwiseMax(r);
  }
  const int cells = std::max(1, int(std::cbrt(double(guides.size()) / 2.0)));
  const Eigen::Vector3f ext = (hi - lo).cwiseMax(1e-6f);
  const Eigen::Vector3f inv = Eigen::Vector3f::Constant(float(cells)).cwiseQuotient(ext);
  auto cellOf = [&](const float* r, int c) {
    return std::clamp(int(std::floor((r[c] - lo[c]) * inv[c])), 0, cells - 1);
  };
  std::vector<uint32_t> cellStart(size_t(cells) * cells * cells + 1, 0), cellItems(guides.size());
  auto cellIndex = [&](int x, int y, int z) { return size_t(x + cells * (y + cells * z)); };
  for (size_t g = 0; g < guides.size(); ++g) {
    const float* r = rest + 3 * start[guides[g]];
    ++cellStart[cellIndex(cellOf(r, 0), cellOf(r, 1), cellOf(r, 2)) + 1];
  }
  for (size_t c = 1; c < cellStart.size(); ++c) cellStart[c] += cellStart[c - 1];
  {
    std::vector<uint32_t> fill(cellStart.begin(), cellStart.end() - 1);
    for (size_t g = 0; g < guides.size(); ++g) {
      const float* r = rest + 3 * start[guides[g]];
      cellItems[fill[cellIndex(cellOf(r, 0), cellOf(r, 1), cellOf(r, 2))]++] = uint32_t(g);
    }
  }
  const float cellMin = std::min({ext.x(), ext.y(), ext.z()}) / float(cells);
  along_.assign(points, 0.0f);
  parallel::forRange(0, size_t(count), 256, [&](size_t b, size_t e) {
    std::vector<float> acc;
    for (size_t s = b; s < e; ++s) {
      const int n = pointsOf(int(s));
      if (n < 2 || guides.empty()) continue;
      const float* r = rest + 3 * size_t(start[s]);
      int32_t best = guideIndex[s];
      const int t = tailOf(int(s));
      if (best < 0 && t >= 0 && size_t(t) < tailGuide.size()) best = tailGuide[t];
      followerArcLengths(r, n, acc);
      if (best < 0) {
        // the kCandidates guides whose roots are nearest (rings of cells around the root's,
        // until the farthest kept is nearer than the ring), then of those the one whose root
        // and point halfway along the shorter of the two lie nearest the strand's (kRootWeight):
        // hair parted the other way, or falling in front of the shoulder, rides a guide that
        // goes its way
        const int cx = cellOf(r, 0), cy = cellOf(r, 1), cz = cellOf(r, 2);
        std::array<std::pair<float, int32_t>, kCandidates> near;
        int found = 0;
        for (int ring = 0; ring < cells; ++ring) {
          for (int z = std::max(0, cz - ring); z <= std::min(cells - 1, cz + ring); ++z)
            for (int y = std::max(0, cy - ring); y <= std::min(cells - 1, cy + ring); ++y)
              for (int x = std::max(0, cx - ring); x <= std::min(cells - 1, cx + ring); ++x) {
                if (std::max({std::abs(x - cx), std::abs(y - cy), std::abs(z - cz)}) != ring)
                  continue;
                const size_t c = cellIndex(x, y, z);
                for (uint32_t q = cellStart[c]; q < cellStart[c + 1]; ++q) {
                  const int32_t g = int32_t(cellItems[q]);
                  const float* o = rest + 3 * start[guides[g]];
                  const std::pair<float, int32_t> k{(o[0] - r[0]) * (o[0] - r[0]) +
                                                        (o[1] - r[1]) * (o[1] - r[1]) +
                                                        (o[2] - r[2]) * (o[2] - r[2]),
                                                    g};
                  if (found < kCandidates)
                    near[found++] = k;
                  else if (k < near[found - 1])
                    near[found - 1] = k;
                  else
                    continue;
                  std::sort(near.begin(), near.begin() + found);
                }
              }
          // every root outside the searched block is farther than ring * cellMin
          const bool all = found == kCandidates || found == int(guides.size());
          if (all && std::sqrt(near[found - 1].first) <= float(ring) * cellMin) break;
        }
        float bestCost = INFINITY;
        for (int k = 0; k < found; ++k) {
          const int32_t g = near[k].second;
          const float half = 0.5f * std::min(acc[n - 1], gLength[size_t(g)]);
          const Eigen::Vector3f mine = pointAtArcLength(r, acc, n, half);
          const float a = half / std::max(gLength[size_t(g)], 1e-6f) * float(G - 1);
          const int j = std::min(G - 2, int(a));
          const float w = std::min(1.0f, a - float(j));
          const float* q = gp.data() + (size_t(g) * G + j) * 3;
          const Eigen::Vector3f theirs = (1 - w) * Eigen::Map<const Eigen::Vector3f>(q) +
                                         w * Eigen::Map<const Eigen::Vector3f>(q + 3);
          const float cost = kRootWeight * near[k].first + (mine - theirs).squaredNorm();
          if (cost < bestCost) {
            bestCost = cost;
            best = g;
          }
        }
      }
      guideOf_[s] = best;
      // by arc length from the root: a strand shorter than its guide rides the guide's first
      // part, one longer rides all of it and goes on past its tip as the tip does (by fraction,
      // a 1 cm hair on a 60 cm guide would swing 59 cm of offset about the guide's tip)
      const float perPoint = float(G - 1) / std::max(gLength[size_t(best)], 1e-6f);
      for (int i = 0; i < n; ++i) along_[start[s] + i] = std::min(acc[i] * perPoint, float(G - 1));
    }
  });
}

}  // namespace hairsketch
