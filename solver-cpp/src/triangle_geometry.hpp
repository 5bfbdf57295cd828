// Closest points on triangles, shared by scalp avoidance and the head's distance grid.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hairsketch {

// Closest point of triangle (a, b, c) to p, as barycentric weights (wa, wb, wc) (Voronoi regions
// of the vertices, edges and face, tested in turn; Ericson, Real-Time Collision Detection 5.1.5).
inline Eigen::Vector3d closestBarycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    return {1 - t, t, 0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    return {1 - t, 0, t};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - t, t};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1 - v - w, v, w};
}

// Unit area-weighted vertex normals of a triangle mesh (counter-clockwise = outward, as in
// three.js); zero for a vertex no triangle with area touches. positions #V x 3, indices #T x 3
// (checked by the caller).
inline std::vector<Eigen::Vector3d> areaWeightedVertexNormals(const float* positions,
                                                              size_t vertexCount,
                                                              const uint32_t* indices,
                                                              size_t triangleCount) {
  auto vert = [&](uint32_t v) {
    return Eigen::Vector3d(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
  };
  std::vector<Eigen::Vector3d> vn(vertexCount, Eigen::Vector3d::Zero());
  for (size_t t = 0; t < triangleCount; ++t) {
    const uint32_t* I = indices + 3 * t;
    const Eigen::Vector3d fn = (vert(I[1]) - vert(I[0])).cross(vert(I[2]) - vert(I[0]));
    for (int k = 0; k < 3; ++k) vn[I[k]] += fn;
  }
  for (Eigen::Vector3d& n : vn) {
    const double l = n.norm();
    if (l > 0) n /= l;
  }
  return vn;
}

}  // namespace hairsketch
