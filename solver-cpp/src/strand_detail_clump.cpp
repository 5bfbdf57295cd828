// Clump of hair detail (strand_detail.hpp "Clump"): guides picked by a Poisson-disc pass, found
// through a hash grid of their roots, and the other strands pulled towards them.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <vector>

#include "parallel.hpp"
#include "strand_detail_internal.hpp"

namespace hairsketch::strand_detail {

namespace {

// Open-addressing table from a grid cell to the first guide in it (guides in a cell are linked
// through `next`).
class CellTable {
 public:
  explicit CellTable(size_t n) {
    size_t cap = 16;
    while (cap < 2 * n) cap <<= 1;
    keys_.assign(cap, 0);
    heads_.assign(cap, -1);
    mask_ = cap - 1;
  }
  int32_t head(uint64_t key) const { return heads_[slot(key)]; }
  int32_t& headRef(uint64_t key) {
    const size_t i = slot(key);
    keys_[i] = key;
    return heads_[i];
  }

 private:
  size_t slot(uint64_t key) const {
    uint64_t h = key + 0x9e3779b97f4a7c15ULL;  // splitmix64 finaliser
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
    h ^= h >> 31;
    size_t i = size_t(h) & mask_;
    while (heads_[i] != -1 && keys_[i] != key) i = (i + 1) & mask_;
    return i;
  }
  std::vector<uint64_t> keys_;
  std::vector<int32_t> heads_;
  size_t mask_ = 0;
};

constexpr int64_t kCellHalf = int64_t(1) << 20;  // cell coordinates kept in [-2^20, 2^20)

int64_t cellCoord(double v, double inv) {
  const double c = std::floor(v * inv);
  return int64_t(std::min(double(kCellHalf - 1), std::max(double(-kCellHalf), c)));
}

uint64_t packCell(int64_t x, int64_t y, int64_t z) {
  return (uint64_t(x + kCellHalf) << 42) | (uint64_t(y + kCellHalf) << 21) |
         uint64_t(z + kCellHalf);
}

// Calls f(member) for every guide in the 27 cells around the cell of p.
template <class F>
void forNearGuides(const CellTable& table, const std::vector<int32_t>& next, const V3& p,
                   double inv, F f, int64_t cells = 1) {
  const int64_t cx = cellCoord(p.x(), inv), cy = cellCoord(p.y(), inv), cz = cellCoord(p.z(), inv);
  for (int64_t x = std::max(cx - cells, -kCellHalf); x <= std::min(cx + cells, kCellHalf - 1); ++x)
    for (int64_t y = std::max(cy - cells, -kCellHalf); y <= std::min(cy + cells, kCellHalf - 1);
         ++y)
      for (int64_t z = std::max(cz - cells, -kCellHalf); z <= std::min(cz + cells, kCellHalf - 1);
           ++z)
        for (int32_t k = table.head(packCell(x, y, z)); k >= 0; k = next[size_t(k)])
          if (!f(k)) return;
}

// cos 60°: a guide whose heading is further from a follower's than this does not take it.
constexpr double kSameWay = 0.5;
// How far (world units, 10 cm; at least 4 guide distances) a follower's path may part from its
// guide's and still be clumped to it: round different sides of the head they part by more.
constexpr double kMaxApart = 1.0;
// nextGuide: when no guide in the cells next to a strand's root stays with its path, the guides
// within this many world units (3 cm) of it are tried, nearest first.
constexpr double kNextGuideReach = 0.3;

}  // namespace

void clumpGroup(const ClumpParams& c, const std::vector<uint32_t>& members,
                const std::vector<uint32_t>& key, uint32_t seed, Strands& strands, Work& w,
                std::vector<uint32_t>* phaseKey, bool nextGuide, bool locks, double lockLength) {
  const size_t M = members.size();
  const uint32_t* start = strands.strandStart.data();
  float* P = strands.points.data();
  std::vector<V3> roots(M), heading(M);
  for (size_t m = 0; m < M; ++m) {
    const size_t a = start[members[m]], n = start[members[m] + 1] - a;
    const float* r = P + 3 * a;
    roots[m] = V3(r[0], r[1], r[2]);
    // where the strand sets off to: root to its point a few steps on (unit, or zero)
    const float* q = P + 3 * (a + std::min<size_t>(n - 1, 4));
    const V3 d = V3(q[0], q[1], q[2]) - roots[m];
    heading[m] = d.norm() > 0 ? V3(d / d.norm()) : V3(V3::Zero());
  }
  // Seeded visiting order: by a hash of (seed, key), then key, then position.
  std::vector<std::tuple<uint32_t, uint32_t, uint32_t>> order(M);
  for (size_t m = 0; m < M; ++m) {
    const uint32_t k = key[members[m]];
    order[m] = {strandRng(seed, k, kStreamOrder).nextU32(), k, uint32_t(m)};
  }
  std::sort(order.begin(), order.end());

  const double g = c.guideDistance, g2 = g * g, inv = 1 / g;
  CellTable table(M);
  std::vector<int32_t> next(M, -1);
  std::vector<char> isGuide(M, 0);
  for (const auto& o : order) {
    const uint32_t m = std::get<2>(o);
    bool near = false;
    forNearGuides(table, next, roots[m], inv, [&](int32_t k) {
      near = (roots[size_t(k)] - roots[m]).squaredNorm() < g2;
      return !near;
    });
    if (near) continue;
    isGuide[m] = 1;
    int32_t& head = table.headRef(packCell(
        cellCoord(roots[m].x(), inv), cellCoord(roots[m].y(), inv), cellCoord(roots[m].z(), inv)));
    next[m] = head;
    head = int32_t(m);
  }

  // The guides' un-clumped shapes: arc lengths and (for the tip spread) frames, flat.
  const bool spread = c.tipSpread > 0;
  std::vector<size_t> guideAt(M, 0);
  std::vector<double> gs;
  std::vector<V3> gt, gn;
  for (size_t m = 0; m < M; ++m) {
    if (!isGuide[m]) continue;
    const uint32_t s = members[m];
    load(P + 3 * size_t(start[s]), start[s + 1] - start[s], w.p);
    arcLengths(w.p, w.s);
    guideAt[m] = gs.size();
    gs.insert(gs.end(), w.s.begin(), w.s.end());
    if (spread) {
      frames(w.p, w.t, w.n, w.b);
      gt.insert(gt.end(), w.t.begin(), w.t.end());
      gn.insert(gn.end(), w.n.begin(), w.n.end());
    }
  }

  const Falloff S(c.shape);
  const double maxApart = std::max(kMaxApart, 4 * c.guideDistance);
  // whether the path of strand s (loaded in w.p, its arc lengths in w.s) parts from guide k's by
  // more than maxApart (also when either has no length)
  auto partsFrom = [&](uint32_t s, int32_t k, const Work& w) {
    const uint32_t G = members[size_t(k)];
    const size_t count = start[s + 1] - start[s], gCount = start[G + 1] - start[G];
    const float* gp = P + 3 * size_t(start[G]);
    const double* gArc = gs.data() + guideAt[size_t(k)];
    const double LG = gArc[gCount - 1], L = w.s[count - 1];
    if (!(L > 0) || !(LG > 0)) return true;
    const double along = LG / std::max(L, LG);
    size_t j = 0;
    for (size_t i = 1; i < count; ++i) {
      const double u = locate(gArc, gCount, w.s[i] * along, j);
      const V3 a(gp[3 * j], gp[3 * j + 1], gp[3 * j + 2]);
      const V3 b(gp[3 * j + 3], gp[3 * j + 4], gp[3 * j + 5]);
      if ((lerp(a, b, u) - w.p[i]).norm() > maxApart) return true;
    }
    return false;
  };
  // Each follower reads only guides (which keep their shape) and writes only its own points, so
  // followers are clumped in parallel, each chunk with its own work buffers.
  auto clumpFollower = [&](size_t m, Work& w, std::vector<std::pair<double, int32_t>>& near) {
    int32_t best = -1;
    double bestD2 = std::numeric_limits<double>::infinity();
    near.clear();
    forNearGuides(table, next, roots[m], inv, [&](int32_t k) {
      // a guide that sets off the other way (across a parting) does not take this strand
      if (heading[size_t(k)].dot(heading[m]) < kSameWay) return true;
      const double d2 = (roots[size_t(k)] - roots[m]).squaredNorm();
      if (d2 < bestD2) {
        bestD2 = d2;
        best = k;
      }
      if (nextGuide) near.emplace_back(d2, k);
      return true;
    });
    if (best < 0) return;  // no guide near that sets off the same way: not clumped
    if (nextGuide) {
      // the nearest guide whose path stays with the strand's (nearest first, ties by index)
      const uint32_t s = members[m];
      load(P + 3 * size_t(start[s]), start[s + 1] - start[s], w.p);
      arcLengths(w.p, w.s);
      std::sort(near.begin(), near.end());
      bool found = false;
      for (const auto& [d2, k] : near)
        if (!partsFrom(s, k, w)) {
          best = k;
          found = true;
          break;
        }
      if (!found) {
        near.clear();
        forNearGuides(
            table, next, roots[m], inv,
            [&](int32_t k) {
              const double d2 = (roots[size_t(k)] - roots[m]).squaredNorm();
              if (heading[size_t(k)].dot(heading[m]) >= kSameWay &&
                  d2 < kNextGuideReach * kNextGuideReach)
                near.emplace_back(d2, k);
              return true;
            },
            int64_t(std::ceil(kNextGuideReach * inv)));
        std::sort(near.begin(), near.end());
        for (const auto& [d2, k] : near)
          if (!partsFrom(s, k, w)) {
            best = k;
            break;
          }
      }
    }
    const uint32_t s = members[m], G = members[size_t(best)];
    const size_t count = start[s + 1] - start[s], gCount = start[G + 1] - start[G];
    const float* gp = P + 3 * size_t(start[G]);
    const double* gArc = gs.data() + guideAt[size_t(best)];
    const double LG = gArc[gCount - 1];
    load(P + 3 * size_t(start[s]), count, w.p);
    const double L = arcLengths(w.p, w.s);
    if (!(L > 0) || !(LG > 0)) return;
    // Along the guide by arc length, stretched to its tip only for a strand longer than it: a
    // shorter strand (stubble at a hairline) joins the clump near its root, not at its far tip.
    const double along = LG / std::max(L, LG);
    const double phi = spread ? kTwoPi * strandRng(seed, key[s], kStreamSpread).uniform() : 0;
    const double cPhi = std::cos(phi), sPhi = std::sin(phi);
    // A strand whose path parts from its guide's by more than kMaxApart (the two go round
    // different sides of the head, or either side of a parting further on) is not clumped: a
    // blend of the two paths would cut through the head.
    if (partsFrom(s, best, w)) return;
    const double reach = lockLength > 0 ? std::min(1.0, L / lockLength) : 1.0;
    if (phaseKey) (*phaseKey)[s] = key[G];
    size_t j = 0;
    for (size_t i = 1; i < count; ++i) {
      const double x = w.s[i] / L;
      const double u = locate(gArc, gCount, w.s[i] * along, j);
      const V3 a(gp[3 * j], gp[3 * j + 1], gp[3 * j + 2]);
      const V3 b(gp[3 * j + 3], gp[3 * j + 4], gp[3 * j + 5]);
      const double wgt = c.factor * S(x) * reach;
      w.p[i] = (1 - wgt) * w.p[i] + wgt * lerp(a, b, u);
      if (spread) {
        const size_t o = guideAt[size_t(best)] + j;
        const V3 t = lerp(gt[o], gt[o + 1], u).normalized();
        V3 nrm = lerp(gn[o], gn[o + 1], u);
        nrm = (nrm - nrm.dot(t) * t).normalized();
        w.p[i] += c.tipSpread * x * (cPhi * nrm + sPhi * t.cross(nrm));
      }
    }
    if (locks) keepLength(w.p, w.s, L, w.q);
    store(w.p, P + 3 * size_t(start[s]));
  };
  const int chunks = int(std::min<size_t>(size_t(parallel::threadCount()) * 4, M / 256 + 1));
  parallel::forChunks(M, chunks, [&](int, size_t m0, size_t m1) {
    Work own;
    std::vector<std::pair<double, int32_t>> near;  // nextGuide: the guides that set off its way
    for (size_t m = m0; m < m1; ++m)
      if (!isGuide[m]) clumpFollower(m, own, near);
  });
}

}  // namespace hairsketch::strand_detail
