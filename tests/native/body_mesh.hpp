// Test helper: a bust-like body for the body collider (HairEngine::setBody): a capsule lying
// along x (the shoulders: a cylinder of radius r between x = -a and x = a, closed by half
// spheres), as a closed triangle mesh (counter-clockwise = outward), with its exact signed
// distance for checks that do not go through HeadDistance's grid.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sphere_mesh.hpp"

namespace hairsketch_test {

struct Capsule {
  double cy = -2.6, cz = 0;  // the axis: y = cy, z = cz, x in [-a, a]
  double a = 1.0, r = 1.0;   // shoulders 2 (a + r) wide, 2 r deep; the top at cy + r
  // Signed distance to the exact capsule (negative inside). The mesh's vertices lie on it and its
  // faces are chords, at most r (1 - cos(pi / segments)) inside it: the mesh is within the capsule,
  // so a point's depth in the mesh is never more than its depth here.
  double distance(double x, double y, double z) const {
    const double px = std::clamp(x, -a, a);
    return std::sqrt((x - px) * (x - px) + (y - cy) * (y - cy) + (z - cz) * (z - cz)) - r;
  }
};

// The capsule as a surface of revolution about its axis: capRings latitude bands per half sphere,
// `segments` around, one band for the cylinder; a vertex at each pole.
inline Mesh capsuleMesh(const Capsule& c, int capRings = 16, int segments = 64) {
  const double pi = 3.14159265358979323846;
  std::vector<double> px, rho;  // the profile between the poles, poles excluded
  for (int i = 1; i <= capRings; ++i) {
    const double phi = pi - 0.5 * pi * i / capRings;  // pi .. pi / 2: the left half sphere
    px.push_back(-c.a + c.r * std::cos(phi));
    rho.push_back(c.r * std::sin(phi));
  }
  for (int i = 0; i < capRings; ++i) {
    const double phi = 0.5 * pi - 0.5 * pi * i / capRings;  // pi / 2 .. 0: the right one
    px.push_back(c.a + c.r * std::cos(phi));
    rho.push_back(c.r * std::sin(phi));
  }
  Mesh m;
  auto put = [&](double x, double y, double z) {
    m.positions.insert(m.positions.end(), {float(x), float(y), float(z)});
  };
  put(-c.a - c.r, c.cy, c.cz);  // vertex 0: the left pole
  const int rings = int(px.size());
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double psi = 2 * pi * j / segments;
      put(px[size_t(i)], c.cy + rho[size_t(i)] * std::cos(psi),
          c.cz + rho[size_t(i)] * std::sin(psi));
    }
  const uint32_t right = uint32_t(m.positions.size() / 3);
  put(c.a + c.r, c.cy, c.cz);
  auto v = [&](int i, int j) { return uint32_t(1 + i * segments + (j % segments)); };
  for (int j = 0; j < segments; ++j) m.indices.insert(m.indices.end(), {0, v(0, j + 1), v(0, j)});
  for (int i = 0; i + 1 < rings; ++i)
    for (int j = 0; j < segments; ++j)
      m.indices.insert(m.indices.end(), {v(i, j), v(i, j + 1), v(i + 1, j + 1), v(i, j),
                                         v(i + 1, j + 1), v(i + 1, j)});
  for (int j = 0; j < segments; ++j)
    m.indices.insert(m.indices.end(), {right, v(rings - 1, j), v(rings - 1, j + 1)});
  m.scalp.assign(m.indices.size() / 3, 0);
  return m;
}

// A surface of revolution about the vertical line x = z = 0 through the profile (rho[i], y[i]),
// from a pole at (0, yTop, 0) to one at (0, yBottom, 0) (the poles not in the profile),
// `segments` around; counter-clockwise = outward.
inline Mesh revolvedMesh(double yTop, const std::vector<double>& rho, const std::vector<double>& y,
                         double yBottom, int segments) {
  const double pi = 3.14159265358979323846;
  Mesh m;
  m.positions.insert(m.positions.end(), {0.f, float(yTop), 0.f});
  const int rings = int(rho.size());
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double psi = 2 * pi * j / segments;
      m.positions.insert(m.positions.end(),
                         {float(rho[size_t(i)] * std::sin(psi)), float(y[size_t(i)]),
                          float(rho[size_t(i)] * std::cos(psi))});
    }
  const uint32_t bottom = uint32_t(m.positions.size() / 3);
  m.positions.insert(m.positions.end(), {0.f, float(yBottom), 0.f});
  auto v = [&](int i, int j) { return uint32_t(1 + i * segments + (j % segments)); };
  for (int j = 0; j < segments; ++j) m.indices.insert(m.indices.end(), {0, v(0, j), v(0, j + 1)});
  for (int i = 0; i + 1 < rings; ++i)
    for (int j = 0; j < segments; ++j)
      m.indices.insert(m.indices.end(), {v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j),
                                         v(i + 1, j + 1), v(i, j + 1)});
  for (int j = 0; j < segments; ++j)
    m.indices.insert(m.indices.end(), {bottom, v(rings - 1, j + 1), v(rings - 1, j)});
  m.scalp.assign(m.indices.size() / 3, 0);
  return m;
}

// A head on a neck, as the app's built-in head is: a sphere of radius r about the origin down to
// where it is neckRadius wide, then a neck of that radius down to neckBottom (into the
// shoulders), closed by a flat disc.
inline Mesh headOnNeck(double r = 1.0, double neckRadius = 0.45, double neckBottom = -2.2,
                       int sphereRings = 24, int segments = 48) {
  std::vector<double> rho, y;
  const double thetaMax = 3.14159265358979323846 - std::asin(neckRadius / r);
  for (int i = 1; i <= sphereRings; ++i) {
    const double th = thetaMax * i / sphereRings;
    rho.push_back(r * std::sin(th));
    y.push_back(r * std::cos(th));
  }
  const double neckTop = y.back();
  const int neckRings = int(std::ceil((neckTop - neckBottom) / 0.1));
  for (int i = 1; i <= neckRings; ++i) {
    rho.push_back(neckRadius);
    y.push_back(neckTop + (neckBottom - neckTop) * i / neckRings);
  }
  return revolvedMesh(r, rho, y, neckBottom, segments);
}

// Six times the signed volume (positive: the triangles face outward).
inline double signedVolume6(const Mesh& m) {
  double v = 0;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const float* a = &m.positions[3 * m.indices[t]];
    const float* b = &m.positions[3 * m.indices[t + 1]];
    const float* c = &m.positions[3 * m.indices[t + 2]];
    v += double(a[0]) * (double(b[1]) * c[2] - double(b[2]) * c[1]) -
         double(a[1]) * (double(b[0]) * c[2] - double(b[2]) * c[0]) +
         double(a[2]) * (double(b[0]) * c[1] - double(b[1]) * c[0]);
  }
  return v;
}

// Two meshes as one (b's indices shifted), scalp flags kept.
inline Mesh joined(const Mesh& a, const Mesh& b) {
  Mesh m = a;
  const uint32_t off = uint32_t(a.positions.size() / 3);
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  for (uint32_t i : b.indices) m.indices.push_back(i + off);
  m.scalp.insert(m.scalp.end(), b.scalp.begin(), b.scalp.end());
  return m;
}

}  // namespace hairsketch_test
