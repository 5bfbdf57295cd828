#include "head_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "triangle_geometry.hpp"

namespace hairsketch {

namespace {
using V3 = Eigen::Vector3d;

// The cell lattice of a mesh: bounds grown by (band + 2) cells.
struct Lattice {
  V3 lo, sum;
  int nx = 0, ny = 0, nz = 0;
  size_t cells() const { return size_t(nx) * size_t(ny) * size_t(nz); }
};

Status latticeOf(const HeadMeshView& m, double cell, int bandCells, Lattice& L) {
  if (m.triangleCount == 0 || !m.positions || !m.indices)
    return Status::Error(StatusCode::InvalidInput, "head distance: no mesh");
  if (!(cell > 0) || !std::isfinite(cell) || bandCells < 1)
    return Status::Error(StatusCode::InvalidInput, "head distance: bad cell size or band");
  V3 lo = V3::Constant(std::numeric_limits<double>::infinity()), hi = -lo, sum = V3::Zero();
  for (size_t v = 0; v < m.vertexCount; ++v) {
    const V3 p(m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]);
    if (!p.allFinite())
      return Status::Error(StatusCode::NonFinite, "head distance: vertex is not finite");
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    sum += p;
  }
  const double pad = (bandCells + 2) * cell;
  lo.array() -= pad;
  hi.array() += pad;
  const V3 ext = (hi - lo) / cell;
  if (!(ext.maxCoeff() < 1e6))
    return Status::Error(StatusCode::OverMemoryCap, "head distance: head too large for its grid");
  L.lo = lo;
  L.sum = sum;
  L.nx = int(std::ceil(ext.x())) + 1;
  L.ny = int(std::ceil(ext.y())) + 1;
  L.nz = int(std::ceil(ext.z())) + 1;
  if (double(L.nx) * L.ny * L.nz > 64e6)
    return Status::Error(StatusCode::OverMemoryCap, "head distance: head too large for its grid");
  return Status::Ok();
}

// Per cell: d (4 bytes), tri (4), the propagation's queue flag (1) and tie count (1), the flood
// fill's flag (1) and stack (8, at most); per vertex the double normals (24).
constexpr double kBytesPerCell = 19, kBytesPerVertex = 24;

// Ties the propagation lets a cell take (see offer in build). Heads and bodies that build today
// take at most 35 (UV spheres, capsules, at 3 mm and 4 mm cells); on some regular meshes (a UV
// sphere or a capsule at 4 mm cells, a 1.6 cm band) two triangles at the same stored distance
// handed cells back and forth without end, and build never returned.
constexpr uint8_t kMaxTies = 255;

}  // namespace

double HeadDistance::estimateBytes(const HeadMeshView& m, double cell, int bandCells) {
  Lattice L;
  if (!latticeOf(m, cell, bandCells, L).ok()) return 0;
  return kBytesPerCell * double(L.cells()) + kBytesPerVertex * double(m.vertexCount) +
         double(m.triangleCount);
}

void HeadDistance::clear() {
  d_.clear();
  tri_.clear();
  scalp_.clear();
  triangleCount_ = 0;
}

Status HeadDistance::setScalpMask(const uint8_t* scalp, size_t triangleCount) {
  if (!built()) return Status::Error(StatusCode::NotReady, "scalp mask: no head built");
  if (!scalp || triangleCount != triangleCount_)
    return Status::Error(StatusCode::InvalidInput,
                         "scalp mask: " + std::to_string(triangleCount) + " flags for a head of " +
                             std::to_string(triangleCount_) + " triangles");
  scalp_.assign(scalp, scalp + triangleCount);
  return Status::Ok();
}

Status HeadDistance::build(const HeadMeshView& m, double cell, int bandCells) {
  clear();
  Lattice L;
  Status s = latticeOf(m, cell, bandCells, L);
  if (!s.ok()) return s;
  for (size_t i = 0; i < 3 * m.triangleCount; ++i)
    if (m.indices[i] >= m.vertexCount)
      return Status::Error(StatusCode::InvalidInput, "head distance: triangle index out of range");
  auto vert = [&](uint32_t v) {
    return V3(m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]);
  };
  const V3 lo = L.lo;
  const int nx = L.nx, ny = L.ny, nz = L.nz;
  const double band = bandCells * cell;
  // Area-weighted vertex normals (counter-clockwise = outward, as in three.js).
  const std::vector<V3> vn =
      areaWeightedVertexNormals(m.positions, m.vertexCount, m.indices, m.triangleCount);
  const size_t n = L.cells();
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> d(n, inf);  // signed, compared by magnitude
  std::vector<int32_t> tri(n, -1);
  uint8_t* ties = nullptr;  // per cell: the ties it took while propagating (null: not counted)
  auto at = [&](int i, int j, int k) {
    return size_t(i) + size_t(nx) * (size_t(j) + size_t(ny) * k);
  };
  // Distance from cell (i, j, k) to triangle t; when it is within the band and nearer than
  // the cell's current one, the cell takes it (signed) and true is returned.
  auto offer = [&](int i, int j, int k, uint32_t t) {
    const uint32_t* I = m.indices + 3 * size_t(t);
    const V3 a = vert(I[0]), b = vert(I[1]), c = vert(I[2]);
    const V3 p = lo + cell * V3(i, j, k);
    const V3 w = closestBarycentric(p, a, b, c);
    const V3 q = w.x() * a + w.y() * b + w.z() * c;
    const double dist = (p - q).norm();
    const size_t idx = at(i, j, k);
    float& cur = d[idx];
    if (!(dist < std::fabs(cur)) || dist > band) return false;
    // A tie: nearer in double, the same distance once stored (float). A cell takes a bounded
    // number of them while propagating, so that two triangles cannot hand it back and forth
    // without end (kMaxTies).
    if (ties && !(float(dist) < std::fabs(cur))) {
      if (ties[idx] == kMaxTies) return false;
      ++ties[idx];
    }
    V3 nrm = w.x() * vn[I[0]] + w.y() * vn[I[1]] + w.z() * vn[I[2]];
    if (!(nrm.squaredNorm() > 1e-24)) nrm = (b - a).cross(c - a);
    cur = float((p - q).dot(nrm) < 0 ? -dist : dist);
    tri[idx] = int32_t(t);
    return true;
  };
  // Exact within one cell: each triangle splatted into its box grown by one cell. A cell whose
  // distance to the triangle's bounding sphere is already no less than its current distance
  // cannot take it (most of the cells of a small triangle's box: the cheap test first).
  for (size_t t = 0; t < m.triangleCount; ++t) {
    const uint32_t* I = m.indices + 3 * t;
    const V3 a = vert(I[0]), b = vert(I[1]), c = vert(I[2]);
    const V3 mid = (a + b + c) / 3;
    const double r = std::sqrt(
        std::max({(a - mid).squaredNorm(), (b - mid).squaredNorm(), (c - mid).squaredNorm()}));
    const V3 blo = (a.cwiseMin(b).cwiseMin(c).array() - cell - lo.array()) / cell;
    const V3 bhi = (a.cwiseMax(b).cwiseMax(c).array() + cell - lo.array()) / cell;
    const int i0 = std::max(0, int(std::ceil(blo.x()))), i1 = std::min(nx - 1, int(bhi.x()));
    const int j0 = std::max(0, int(std::ceil(blo.y()))), j1 = std::min(ny - 1, int(bhi.y()));
    const int k0 = std::max(0, int(std::ceil(blo.z()))), k1 = std::min(nz - 1, int(bhi.z()));
    for (int k = k0; k <= k1; ++k)
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          const double reach = std::min(double(std::fabs(d[at(i, j, k)])), band) + r;
          if ((lo + cell * V3(i, j, k) - mid).squaredNorm() > reach * reach) continue;
          offer(i, j, k, uint32_t(t));
        }
  }
  // Out to the band: every cell offers its nearest triangle to its 26 neighbours; a neighbour
  // that takes it offers it on in turn (first in, first out, from the cells in index order).
  {
    std::vector<uint8_t> queued(n, 0), tieCount(n, 0);
    ties = tieCount.data();
    std::vector<uint32_t> queue;
    for (size_t idx = 0; idx < n; ++idx)
      if (tri[idx] >= 0) {
        queue.push_back(uint32_t(idx));
        queued[idx] = 1;
      }
    for (size_t head = 0; head < queue.size(); ++head) {
      const size_t idx = queue[head];
      queued[idx] = 0;
      const int i = int(idx % size_t(nx)), j = int((idx / size_t(nx)) % size_t(ny)),
                k = int(idx / (size_t(nx) * size_t(ny)));
      const uint32_t t = uint32_t(tri[idx]);
      for (int dk = -1; dk <= 1; ++dk)
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            const int a = i + di, b = j + dj, c = k + dk;
            if (a < 0 || b < 0 || c < 0 || a >= nx || b >= ny || c >= nz) continue;
            const size_t nb = at(a, b, c);
            if (tri[nb] == int32_t(t) || !offer(a, b, c, t) || queued[nb]) continue;
            queued[nb] = 1;
            queue.push_back(uint32_t(nb));
          }
    }
    ties = nullptr;
  }
  // Far cells: outside when connected to the border through far cells.
  std::vector<uint8_t> outside(n, 0);
  std::vector<size_t> stack;
  auto seed = [&](size_t idx) {
    if (!outside[idx] && std::isinf(d[idx])) {
      outside[idx] = 1;
      stack.push_back(idx);
    }
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        if (i == 0 || j == 0 || k == 0 || i == nx - 1 || j == ny - 1 || k == nz - 1)
          seed(at(i, j, k));
  while (!stack.empty()) {
    const size_t idx = stack.back();
    stack.pop_back();
    const int i = int(idx % size_t(nx)), j = int((idx / size_t(nx)) % size_t(ny)),
              k = int(idx / (size_t(nx) * size_t(ny)));
    if (i > 0) seed(idx - 1);
    if (i < nx - 1) seed(idx + 1);
    if (j > 0) seed(idx - size_t(nx));
    if (j < ny - 1) seed(idx + size_t(nx));
    if (k > 0) seed(idx - size_t(nx) * ny);
    if (k < nz - 1) seed(idx + size_t(nx) * ny);
  }
  for (size_t idx = 0; idx < n; ++idx)
    if (std::isinf(d[idx])) d[idx] = float(outside[idx] ? band : -band);
  d_ = std::move(d);
  tri_ = std::move(tri);
  triangleCount_ = m.triangleCount;
  if (m.scalp) scalp_.assign(m.scalp, m.scalp + m.triangleCount);
  nx_ = nx;
  ny_ = ny;
  nz_ = nz;
  inv_ = float(1.0 / cell);
  ox_ = float(lo.x());
  oy_ = float(lo.y());
  oz_ = float(lo.z());
  far_ = float(band);
  centre_ = (L.sum / double(m.vertexCount)).cast<float>();
  return Status::Ok();
}

float HeadDistance::distance(float x, float y, float z, float gradient[3]) const {
  const float u = (x - ox_) * inv_, v = (y - oy_) * inv_, w = (z - oz_) * inv_;
  if (!(u >= 0 && v >= 0 && w >= 0 && u < float(nx_ - 1) && v < float(ny_ - 1) &&
        w < float(nz_ - 1))) {
    if (gradient) gradient[0] = gradient[1] = gradient[2] = 0;
    return far_;
  }
  const int i = int(u), j = int(v), k = int(w);
  const float a = u - float(i), b = v - float(j), c = w - float(k);
  const size_t sy = size_t(nx_), sz = size_t(nx_) * size_t(ny_);
  const float* p = d_.data() + size_t(i) + sy * size_t(j) + sz * size_t(k);
  const float d000 = p[0], d100 = p[1], d010 = p[sy], d110 = p[sy + 1];
  const float d001 = p[sz], d101 = p[sz + 1], d011 = p[sz + sy], d111 = p[sz + sy + 1];
  const float x00 = d000 + a * (d100 - d000), x10 = d010 + a * (d110 - d010);
  const float x01 = d001 + a * (d101 - d001), x11 = d011 + a * (d111 - d011);
  const float y0 = x00 + b * (x10 - x00), y1 = x01 + b * (x11 - x01);
  if (gradient) {
    const float gx0 = (1 - b) * (d100 - d000) + b * (d110 - d010);
    const float gx1 = (1 - b) * (d101 - d001) + b * (d111 - d011);
    gradient[0] = ((1 - c) * gx0 + c * gx1) * inv_;
    const float gy0 = (1 - a) * (d010 - d000) + a * (d110 - d100);
    const float gy1 = (1 - a) * (d011 - d001) + a * (d111 - d101);
    gradient[1] = ((1 - c) * gy0 + c * gy1) * inv_;
    gradient[2] = (y1 - y0) * inv_;
  }
  return y0 + c * (y1 - y0);
}

float HeadDistance::distanceAtLeast(float x, float y, float z) const {
  const float u = (x - ox_) * inv_, v = (y - oy_) * inv_, w = (z - oz_) * inv_;
  if (u >= 0 && v >= 0 && w >= 0 && u < float(nx_ - 1) && v < float(ny_ - 1) && w < float(nz_ - 1))
    return distance(x, y, z);
  // cells outside the box along each axis (0 within its range)
  const float du = std::max({-u, u - float(nx_ - 1), 0.f});
  const float dv = std::max({-v, v - float(ny_ - 1), 0.f});
  const float dw = std::max({-w, w - float(nz_ - 1), 0.f});
  return far_ + (2 + std::sqrt(du * du + dv * dv + dw * dw)) / inv_;
}

bool HeadDistance::scalpNear(float x, float y, float z) const {
  const float u = (x - ox_) * inv_, v = (y - oy_) * inv_, w = (z - oz_) * inv_;
  if (!(u >= 0 && v >= 0 && w >= 0 && u < float(nx_ - 1) && v < float(ny_ - 1) &&
        w < float(nz_ - 1)))
    return false;
  const size_t i = size_t(u + 0.5f), j = size_t(v + 0.5f), k = size_t(w + 0.5f);
  const int32_t t = tri_[i + size_t(nx_) * (j + size_t(ny_) * k)];
  return t >= 0 && size_t(t) < scalp_.size() && scalp_[size_t(t)] != 0;
}

float HeadDistance::outward(const float p[3], float dir[3]) const {
  const float d = distance(p[0], p[1], p[2], dir);
  float len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  if (!(len > 0.5f)) {
    dir[0] = p[0] - centre_.x();
    dir[1] = p[1] - centre_.y();
    dir[2] = p[2] - centre_.z();
    len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  }
  for (int e = 0; e < 3; ++e) dir[e] = len > 0 ? dir[e] / len : 0.f;
  return d;
}

float HeadDistance::pushOut(float p[3], float margin, float overshoot) const {
  float g[3];
  const float d0 = distance(p[0], p[1], p[2], g);
  float d = d0;
  // Steps along the gradient, which has unit length where the distance is exact (within the
  // band); deeper inside it is flat (the band's value) and the direction from the mesh centre is
  // used instead. Each step moves at most the band width, so a point deep inside walks out in
  // several steps rather than being thrown by a near-zero gradient.
  for (int it = 0; it < 64 && d < margin; ++it) {
    float len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if (!(len > 0.5f)) {
      g[0] = p[0] - centre_.x();
      g[1] = p[1] - centre_.y();
      g[2] = p[2] - centre_.z();
      len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
      if (!(len > 0)) return d0;
    }
    const float move = std::min(margin + overshoot - d, far_);
    for (int e = 0; e < 3; ++e) p[e] += move * g[e] / len;
    d = distance(p[0], p[1], p[2], g);
  }
  return d0;
}

}  // namespace hairsketch
