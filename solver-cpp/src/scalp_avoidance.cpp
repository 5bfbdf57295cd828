#include "scalp_avoidance.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "triangle_geometry.hpp"

namespace hairsketch {

namespace {
using V3 = Eigen::Vector3d;
}  // namespace

Status scalpAvoidanceConstraints(const Grid& g, const Field& T, const HeadMeshView& m,
                                 const ScalpAvoidanceParams& prm, ConstraintSet& out,
                                 ScalpAvoidanceStats* stats) {
  out.clear();
  if (stats) *stats = ScalpAvoidanceStats{};
  if (!g.valid()) return Status::Error(StatusCode::NotReady, "scalp avoidance: no grid");
  if (T.rows() != g.size())
    return Status::Error(StatusCode::InvalidInput,
                         "scalp avoidance: field has " + std::to_string(T.rows()) +
                             " rows, grid has " + std::to_string(g.size()) + " points");
  if (m.triangleCount == 0 || !m.positions || !m.indices || (!m.scalp && !prm.wholeHead))
    return Status::Error(StatusCode::NotReady, "scalp avoidance: no scalp mesh");
  if (!(prm.band > 0) || !std::isfinite(prm.band) || !std::isfinite(prm.magnitude) ||
      !(prm.minField >= 0) || !std::isfinite(prm.minField))
    return Status::Error(StatusCode::InvalidInput,
                         "scalp avoidance: band must be > 0 and magnitude finite");
  for (size_t i = 0; i < 3 * m.triangleCount; ++i)
    if (m.indices[i] >= m.vertexCount)
      return Status::Error(StatusCode::InvalidInput,
                           "scalp avoidance: triangle index out of range");
  auto vert = [&](uint32_t v) {
    return V3(m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]);
  };
  // Area-weighted vertex normals over the whole head.
  const std::vector<V3> vn =
      areaWeightedVertexNormals(m.positions, m.vertexCount, m.indices, m.triangleCount);
  // Nearest candidate triangle per grid point: splat each triangle into its grown box.
  const double band = prm.band * g.step;
  const size_t n = size_t(g.size());
  std::vector<double> best(n, std::numeric_limits<double>::infinity());
  std::vector<int32_t> bestTri(n, -1);
  std::vector<Eigen::Vector3f> bestBary(n);
  for (size_t t = 0; t < m.triangleCount; ++t) {
    if (!prm.wholeHead && !m.scalp[t]) continue;
    const uint32_t* I = m.indices + 3 * t;
    const V3 a = vert(I[0]), b = vert(I[1]), c = vert(I[2]);
    const V3 lo = (a.cwiseMin(b).cwiseMin(c).array() - band - g.origin.array()) / g.step;
    const V3 hi = (a.cwiseMax(b).cwiseMax(c).array() + band - g.origin.array()) / g.step;
    const int i0 = std::max(0, int(std::ceil(lo.x()))),
              i1 = std::min(g.nx - 1, int(std::floor(hi.x())));
    const int j0 = std::max(0, int(std::ceil(lo.y()))),
              j1 = std::min(g.ny - 1, int(std::floor(hi.y())));
    const int k0 = std::max(0, int(std::ceil(lo.z()))),
              k1 = std::min(g.nz - 1, int(std::floor(hi.z())));
    for (int k = k0; k <= k1; ++k)
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          const V3 p = g.position(i, j, k);
          const V3 w = closestBarycentric(p, a, b, c);
          const double d = (p - (w.x() * a + w.y() * b + w.z() * c)).norm();
          const int idx = g.index(i, j, k);
          if (d < best[idx]) {
            best[idx] = d;
            bestTri[idx] = int32_t(t);
            bestBary[idx] = w.cast<float>();
          }
        }
  }
  for (size_t idx = 0; idx < n; ++idx) {
    if (bestTri[idx] < 0 || best[idx] > band) continue;
    const uint32_t* I = m.indices + 3 * size_t(bestTri[idx]);
    const V3 w = bestBary[idx].cast<double>();
    const V3 a = vert(I[0]), b = vert(I[1]), c = vert(I[2]);
    const V3 q = w.x() * a + w.y() * b + w.z() * c;
    V3 nrm = w.x() * vn[I[0]] + w.y() * vn[I[1]] + w.z() * vn[I[2]];
    if (!(nrm.norm() > 1e-12)) nrm = (b - a).cross(c - a);
    if (!(nrm.norm() > 0)) continue;  // degenerate triangle with no normal around it
    nrm.normalize();
    const int i = int(idx % size_t(g.nx)), j = int((idx / size_t(g.nx)) % size_t(g.ny)),
              k = int(idx / (size_t(g.nx) * size_t(g.ny)));
    if (!prm.insideToo && (g.position(i, j, k) - q).dot(nrm) < 0) continue;  // inside
    if (stats) ++stats->nearPoints;
    V3 v = T.row(Eigen::Index(idx)).transpose();
    if (!v.allFinite()) continue;
    const double field = v.norm();
    if (field < prm.minField) continue;
    const double vn0 = v.dot(nrm);
    if (vn0 < 0) {
      v -= vn0 * nrm;
      if (stats) ++stats->projected;
    }
    const double len = v.norm();
    if (!(len > 1e-6)) {
      if (stats) ++stats->skipped;
      continue;
    }
    out.push_back({int(idx), std::min(prm.magnitude, field) * v / len});
  }
  return Status::Ok();
}

}  // namespace hairsketch
