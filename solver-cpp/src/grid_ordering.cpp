#include "grid_ordering.hpp"

#include <array>

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

}  // namespace

DissectionTree boxNestedDissection(const Grid& grid, const DissectionOptions& options) {
  Dissector d(grid, options);
  d.run(Box{{0, 0, 0}, {grid.nx, grid.ny, grid.nz}});
  return d.take();
}

}  // namespace hairsketch
