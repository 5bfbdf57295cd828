// Trilinear samplers of a vector field on the grid (strand_growth.cpp): Sampler reads the
// interleaved floats as stored, for a point now and then (interpolateField); PaddedSampler keeps
// each grid point as four float lanes, for the growth's every step.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstddef>
#include <vector>

#include "grid.hpp"

namespace hairsketch::field_samplers {

// Grid-relative helper, precomputed once per growth call.
struct Sampler {
  const float* f;
  int nx, ny, nz, sy, sz;
  float ox, oy, oz, invStep;
  float hx, hy, hz;  // upper corner of the volume, world units

  bool inside(float x, float y, float z) const {
    return x >= ox && y >= oy && z >= oz && x <= hx && y <= hy && z <= hz;
  }
  // Precondition: inside(x).
  void at(float x, float y, float z, float out[3]) const {
    const float u = (x - ox) * invStep, v = (y - oy) * invStep, w = (z - oz) * invStep;
    int i = std::min(int(u), nx - 2), j = std::min(int(v), ny - 2), k = std::min(int(w), nz - 2);
    i = std::max(i, 0);
    j = std::max(j, 0);
    k = std::max(k, 0);
    const float a = u - i, b = v - j, c = w - k;
    const float* p = f + 3 * (size_t(i) + size_t(j) * sy + size_t(k) * sz);
    const size_t dx = 3, dy = 3 * size_t(sy), dz = 3 * size_t(sz);
    for (int e = 0; e < 3; ++e) {
      const float c00 = p[e] + a * (p[e + dx] - p[e]);
      const float c10 = p[e + dy] + a * (p[e + dy + dx] - p[e + dy]);
      const float c01 = p[e + dz] + a * (p[e + dz + dx] - p[e + dz]);
      const float c11 = p[e + dz + dy] + a * (p[e + dz + dy + dx] - p[e + dz + dy]);
      const float c0 = c00 + b * (c10 - c00), c1 = c01 + b * (c11 - c01);
      out[e] = c0 + c * (c1 - c0);
    }
  }
};

inline Sampler makeSampler(const Grid& g, const float* field) {
  const Eigen::Vector3d hi = g.maxCorner();
  return Sampler{field,
                 g.nx,
                 g.ny,
                 g.nz,
                 g.nx,
                 g.nx * g.ny,
                 float(g.origin.x()),
                 float(g.origin.y()),
                 float(g.origin.z()),
                 float(1.0 / g.step),
                 float(hi.x()),
                 float(hi.y()),
                 float(hi.z())};
}

// Four float lanes (x, y, z, unused): GCC/Clang vector extensions, which compile to SSE natively
// and to simd128 in wasm. One corner of a cell is one load; a trilinear blend is 7 lane-wise
// lerps instead of 21 scalar ones.
typedef float F4 __attribute__((vector_size(16)));

struct PaddedSampler {
  std::vector<F4> f;  // f[p] = (t_p.x, t_p.y, t_p.z, 0)
  int nx, ny, nz;
  size_t sy, sz;
  float ox, oy, oz, invStep;
  float hx, hy, hz;

  PaddedSampler(const Grid& g, const std::vector<float>& field)
      : f(field.size() / 3),
        nx(g.nx),
        ny(g.ny),
        nz(g.nz),
        sy(size_t(g.nx)),
        sz(size_t(g.nx) * size_t(g.ny)),
        ox(float(g.origin.x())),
        oy(float(g.origin.y())),
        oz(float(g.origin.z())),
        invStep(float(1.0 / g.step)) {
    const Eigen::Vector3d hi = g.maxCorner();
    hx = float(hi.x());
    hy = float(hi.y());
    hz = float(hi.z());
    for (size_t p = 0; p < f.size(); ++p)
      f[p] = F4{field[3 * p], field[3 * p + 1], field[3 * p + 2], 0.0f};
  }
  bool inside(float x, float y, float z) const {
    return x >= ox && y >= oy && z >= oz && x <= hx && y <= hy && z <= hz;
  }
  // Precondition: inside(x).
  F4 at(float x, float y, float z) const {
    const float u = (x - ox) * invStep, v = (y - oy) * invStep, w = (z - oz) * invStep;
    // u >= 0 inside, so truncation is the floor; the upper face belongs to the last cell.
    const int i = std::min(int(u), nx - 2), j = std::min(int(v), ny - 2),
              k = std::min(int(w), nz - 2);
    const float a = u - float(i), b = v - float(j), c = w - float(k);
    const F4* p = f.data() + (size_t(i) + size_t(j) * sy + size_t(k) * sz);
    const F4 c00 = p[0] + a * (p[1] - p[0]);
    const F4 c10 = p[sy] + a * (p[sy + 1] - p[sy]);
    const F4 c01 = p[sz] + a * (p[sz + 1] - p[sz]);
    const F4 c11 = p[sz + sy] + a * (p[sz + sy + 1] - p[sz + sy]);
    const F4 c0 = c00 + b * (c10 - c00), c1 = c01 + b * (c11 - c01);
    return c0 + c * (c1 - c0);
  }
};

}  // namespace hairsketch::field_samplers
