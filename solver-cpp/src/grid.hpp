// Uniform 3D grid over the bounding volume (method S1.2).
// Grid point (i, j, k) has index p = i + nx * (j + ny * k); its position is
// origin + step * (i, j, k), in world units.
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace hairsketch {

struct Grid {
  int nx = 0, ny = 0, nz = 0;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // world position of point (0, 0, 0)
  double step = 1.0;                                 // d, world units between neighbours

  int64_t size() const { return int64_t(nx) * ny * nz; }
  int index(int i, int j, int k) const { return i + nx * (j + ny * k); }
  bool contains(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < nx && j < ny && k < nz;
  }
  Eigen::Vector3d position(int i, int j, int k) const {
    return origin + step * Eigen::Vector3d(i, j, k);
  }
  Eigen::Vector3d maxCorner() const { return position(nx - 1, ny - 1, nz - 1); }
  // True when a world point lies inside the closed box spanned by the grid points.
  bool insideVolume(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d hi = maxCorner();
    return (p.array() >= origin.array()).all() && (p.array() <= hi.array()).all();
  }
  bool valid() const { return nx >= 2 && ny >= 2 && nz >= 2 && step > 0; }
};

}  // namespace hairsketch
