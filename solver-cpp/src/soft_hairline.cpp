// A soft hairline (soft_hairline.hpp).
#include "soft_hairline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "rng.hpp"

namespace hairsketch {

std::vector<float> scalpEdges(const std::vector<float>& positions,
                              const std::vector<uint32_t>& indices,
                              const std::vector<uint8_t>& scalp) {
  // per undirected edge: how many scalp and other triangles share it
  std::unordered_map<uint64_t, std::pair<int, int>> count;
  const size_t tris = std::min(indices.size() / 3, scalp.size());
  for (size_t t = 0; t < tris; ++t)
    for (int k = 0; k < 3; ++k) {
      uint32_t a = indices[3 * t + k], b = indices[3 * t + (k + 1) % 3];
      if (a > b) std::swap(a, b);
      auto& c = count[(uint64_t(a) << 32) | b];
      (scalp[t] ? c.first : c.second)++;
    }
  std::vector<float> out;
  for (const auto& [key, c] : count) {
    if (c.first == 0 || (c.second == 0 && c.first > 1)) continue;  // not scalp, or inside it
    const uint32_t ends[2] = {uint32_t(key >> 32), uint32_t(key & 0xffffffffu)};
    for (uint32_t v : ends)
      for (int e = 0; e < 3; ++e) out.push_back(positions[3 * size_t(v) + e]);
  }
  return out;
}

std::vector<float> distanceToEdges(const std::vector<Eigen::Vector3f>& points,
                                   const std::vector<float>& edges, float cap) {
  std::vector<float> d(points.size(), cap);
  const size_t m = edges.size() / 6;
  if (m == 0) return d;
  // a hash grid of the edges by the cells (of `cap`) their bounding boxes cover
  const float cell = std::max(cap, 1e-3f);
  auto cellOf = [&](float v) { return int64_t(std::floor(v / cell)); };
  auto key = [](int64_t x, int64_t y, int64_t z) {
    return x * 73856093LL ^ y * 19349663LL ^ z * 83492791LL;
  };
  std::unordered_map<int64_t, std::vector<uint32_t>> grid;
  for (size_t e = 0; e < m; ++e) {
    const float* p = &edges[6 * e];
    int64_t lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = cellOf(std::min(p[k], p[3 + k]));
      hi[k] = cellOf(std::max(p[k], p[3 + k]));
    }
    for (int64_t x = lo[0]; x <= hi[0]; ++x)
      for (int64_t y = lo[1]; y <= hi[1]; ++y)
        for (int64_t z = lo[2]; z <= hi[2]; ++z) grid[key(x, y, z)].push_back(uint32_t(e));
  }
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3f& q = points[i];
    const int64_t c[3] = {cellOf(q.x()), cellOf(q.y()), cellOf(q.z())};
    float best = cap * cap;
    for (int64_t dx = -1; dx <= 1; ++dx)
      for (int64_t dy = -1; dy <= 1; ++dy)
        for (int64_t dz = -1; dz <= 1; ++dz) {
          auto it = grid.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
          if (it == grid.end()) continue;
          for (uint32_t e : it->second) {
            const Eigen::Vector3f a(edges[6 * e], edges[6 * e + 1], edges[6 * e + 2]);
            const Eigen::Vector3f b(edges[6 * e + 3], edges[6 * e + 4], edges[6 * e + 5]);
            const Eigen::Vector3f ab = b - a;
            const float l2 = ab.squaredNorm();
            const float t = l2 > 0 ? std::clamp((q - a).dot(ab) / l2, 0.f, 1.f) : 0.f;
            best = std::min(best, (a + t * ab - q).squaredNorm());
          }
        }
    d[i] = std::sqrt(best);
  }
  return d;
}

void softHairline(const std::vector<float>& edge, const std::vector<uint32_t>& ids, uint32_t seed,
                  std::vector<uint32_t>& pick, std::vector<float>& lengthCap) {
  lengthCap.clear();
  size_t out = 0;
  for (size_t k = 0; k < pick.size(); ++k) {
    const uint32_t r = pick[k];
    const float x = std::clamp(edge[r] / kHairlineWidth, 0.f, 1.f);
    const float full = kHairlineFull + (1 - kHairlineFull) * x * x * (3 - 2 * x);
    float cap = std::numeric_limits<float>::infinity();
    if (full < 1) {
      Pcg32 rng(uint64_t(seed) << 32 | ids[r], 0x6861697231ULL);
      const double u = rng.uniform();
      if (u >= full + 0.5 * (1 - full)) continue;  // no hair here
      if (u >= full)
        cap = kHairlineShortMin + (kHairlineShortMax - kHairlineShortMin) * float(rng.uniform());
    }
    pick[out++] = r;
    lengthCap.push_back(cap);
  }
  pick.resize(out);
}

}  // namespace hairsketch
