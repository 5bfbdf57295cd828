// Test helper: a UV sphere as flat arrays (positions #V x 3, indices #T x 3).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

namespace hairsketch_test {

struct Mesh {
  std::vector<float> positions;
  std::vector<uint32_t> indices;
  std::vector<uint8_t> scalp;  // filled by the caller
};

// rings >= 2 latitude bands, segments >= 3 longitude bands, poles on the y axis.
inline Mesh uvSphere(double cx, double cy, double cz, double r, int rings, int segments) {
  const double pi = 3.14159265358979323846;
  Mesh m;
  for (int i = 0; i <= rings; ++i) {
    const double th = pi * i / rings;
    for (int j = 0; j <= segments; ++j) {
      const double ph = 2 * pi * j / segments;
      m.positions.push_back(float(cx + r * std::sin(th) * std::sin(ph)));
      m.positions.push_back(float(cy + r * std::cos(th)));
      m.positions.push_back(float(cz + r * std::sin(th) * std::cos(ph)));
    }
  }
  auto v = [&](int i, int j) { return uint32_t(i * (segments + 1) + j); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      if (i > 0) m.indices.insert(m.indices.end(), {v(i, j), v(i + 1, j), v(i, j + 1)});
      if (i + 1 < rings)
        m.indices.insert(m.indices.end(), {v(i, j + 1), v(i + 1, j), v(i + 1, j + 1)});
    }
  return m;
}

// Marks triangles whose centroid has y > yMin as scalp.
inline void markScalpAbove(Mesh& m, double yMin) {
  m.scalp.assign(m.indices.size() / 3, 0);
  for (size_t t = 0; t < m.scalp.size(); ++t) {
    double y = 0;
    for (int k = 0; k < 3; ++k) y += m.positions[3 * m.indices[3 * t + k] + 1];
    m.scalp[t] = y / 3 > yMin;
  }
}

}  // namespace hairsketch_test
