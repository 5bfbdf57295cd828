#include "grid_ordering.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>

namespace hairsketch {
namespace {

struct Box {
  std::array<int, 3> lo, hi;  // half-open [lo, hi) per axis
  long long volume() const {
    return (long long)(hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  }
};

class Dissector {
 public:
  Dissector(const Grid& g, const DissectionOptions& o) : g_(g), o_(o) {
    t_.perm.reserve(size_t(g.size()));
    t_.nodeStart.push_back(0);
  }

  int run(const Box& b) {
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (b.hi[a] - b.lo[a] > b.hi[axis] - b.lo[axis]) axis = a;
    const int len = b.hi[axis] - b.lo[axis];
    const int th = o_.thickness;
    if (b.volume() <= o_.leafMax || len < th + 2) return emit(b, -1, -1);
    // Middle slab [mid, mid + th); both sides keep at least one layer.
    const int mid = b.lo[axis] + (len - th) / 2;
    Box left = b, right = b, sep = b;
    left.hi[axis] = mid;
    sep.lo[axis] = mid;
    sep.hi[axis] = mid + th;
    right.lo[axis] = mid + th;
    const int c1 = run(left);
    const int c2 = run(right);
    return emit(sep, c1, c2);
  }

  DissectionTree take() {
    const int n = int(t_.perm.size());
    t_.iperm.assign(size_t(n), -1);
    for (int k = 0; k < n; ++k) t_.iperm[size_t(t_.perm[size_t(k)])] = k;
    return std::move(t_);
  }

 private:
  // Appends a node owning every point of b (lexicographic z, y, x), parent of c1 and c2.
  int emit(const Box& b, int c1, int c2) {
    for (int k = b.lo[2]; k < b.hi[2]; ++k)
      for (int j = b.lo[1]; j < b.hi[1]; ++j)
        for (int i = b.lo[0]; i < b.hi[0]; ++i) t_.perm.push_back(g_.index(i, j, k));
    const int id = int(t_.parent.size());
    t_.parent.push_back(-1);
    t_.nodeStart.push_back(int(t_.perm.size()));
    if (c1 >= 0) t_.parent[size_t(c1)] = id;
    if (c2 >= 0) t_.parent[size_t(c2)] = id;
    return id;
  }

  const Grid& g_;
  DissectionOptions o_;
  DissectionTree t_;
};

// Point-set dissection by the thinnest balanced 2-layer lattice slab.
class PlaneDissector {
 public:
  PlaneDissector(const Grid& g, const DissectionOptions& o) : g_(g), o_(o) {
    t_.perm.reserve(size_t(g.size()));
    t_.nodeStart.push_back(0);
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int c = -1; c <= 1; ++c) {
          // One of v, -v: the first non-zero component positive.
          const int first = a != 0 ? a : b != 0 ? b : c;
          if (first > 0) dirs_.push_back({a, b, c});
        }
  }

  int run(std::vector<int> pts) {
    const int total = int(pts.size());
    if (total <= o_.leafMax) return emit(pts, -1, -1);
    int bestSep = total + 1, bestImb = total + 1, bestDir = -1, bestC = 0;
    std::vector<int> hist;
    for (size_t d = 0; d < dirs_.size(); ++d) {
      int lo = 1 << 30, hi = -(1 << 30);
      for (int p : pts) {
        const int v = dot(d, p);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
      hist.assign(size_t(hi - lo + 1), 0);
      for (int p : pts) ++hist[size_t(dot(d, p) - lo)];
      int left = 0;  // points with value < c
      for (int c = lo + 1; c + 2 <= hi; ++c) {
        left += hist[size_t(c - 1 - lo)];
        const int sep = hist[size_t(c - lo)] + hist[size_t(c + 1 - lo)];
        const int right = total - left - sep;
        if (std::min(left, right) < o_.balance * (left + right)) continue;
        const int imb = std::abs(left - right);
        if (sep < bestSep || (sep == bestSep && imb < bestImb)) {
          bestSep = sep;
          bestImb = imb;
          bestDir = int(d);
          bestC = c;
        }
      }
    }
    if (bestDir < 0) return emit(pts, -1, -1);
    std::vector<int> left, right, sep;
    for (int p : pts) {
      const int v = dot(size_t(bestDir), p);
      (v < bestC ? left : v > bestC + 1 ? right : sep).push_back(p);
    }
    std::vector<int>().swap(pts);
    const int c1 = run(std::move(left));
    const int c2 = run(std::move(right));
    return emit(sep, c1, c2);
  }

  DissectionTree take() {
    const int n = int(t_.perm.size());
    t_.iperm.assign(size_t(n), -1);
    for (int k = 0; k < n; ++k) t_.iperm[size_t(t_.perm[size_t(k)])] = k;
    return std::move(t_);
  }

 private:
  int dot(size_t d, int p) const {
    const int i = p % g_.nx, j = (p / g_.nx) % g_.ny, k = p / (g_.nx * g_.ny);
    return dirs_[d][0] * i + dirs_[d][1] * j + dirs_[d][2] * k;
  }
  int emit(const std::vector<int>& pts, int c1, int c2) {
    t_.perm.insert(t_.perm.end(), pts.begin(), pts.end());
    const int id = int(t_.parent.size());
    t_.parent.push_back(-1);
    t_.nodeStart.push_back(int(t_.perm.size()));
    if (c1 >= 0) t_.parent[size_t(c1)] = id;
    if (c2 >= 0) t_.parent[size_t(c2)] = id;
    return id;
  }

  const Grid& g_;
  DissectionOptions o_;
  DissectionTree t_;
  std::vector<std::array<int, 3>> dirs_;
};

}  // namespace

DissectionTree boxNestedDissection(const Grid& grid, const DissectionOptions& options) {
  if (options.method == DissectionOptions::Method::Planes) {
    PlaneDissector d(grid, options);
    std::vector<int> all(size_t(grid.size()));
    for (size_t p = 0; p < all.size(); ++p) all[p] = int(p);
    d.run(std::move(all));
    return d.take();
  }
  Dissector d(grid, options);
  d.run(Box{{0, 0, 0}, {grid.nx, grid.ny, grid.nz}});
  return d.take();
}

}  // namespace hairsketch
