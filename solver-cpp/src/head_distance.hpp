// The head's signed distance on a fine grid of its own, for keeping hair outside the head
// (growth and detail never leave a strand point inside it).
//
// Built once per head mesh:
//   cells of size h over the mesh's bounds grown by (band + 2) cells;
//   every cell within one cell (h) of a triangle gets its exact distance to the nearest triangle
//     (each triangle splatted into its box grown by h);
//   the other cells within band * h of the surface get the distance to the nearest of their
//     26 neighbours' nearest triangles, propagated outward until nothing changes (closest-point
//     propagation, as in Bridson's makelevelset3: exact on smooth surfaces, within 2e-3 of the
//     brute-force distance beside a crease in the tests; splatting every triangle into the whole
//     band took about ten times as long for a million small triangles);
//   each distance is signed by the outward normal at the closest point (area-weighted vertex
//     normals interpolated by its barycentric weights);
//   every other cell is ±band * h: outside when a 6-connected path of such cells reaches the
//     grid's border (flood fill), inside otherwise, so the sign far from the surface needs no
//     normals and tolerates meshes with several parts.
// Each cell within the band keeps its nearest triangle, so scalpNear reads the current scalp
// mask (setScalpMask replaces it without a rebuild).
// Queries interpolate trilinearly (accurate to about h² / (8 R) on a surface of radius R) and are
// +band * h outside the grid.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "scalp_avoidance.hpp"
#include "status.hpp"

namespace hairsketch {

class HeadDistance {
 public:
  // mesh.scalp may be null (no scalp flags: scalpNear is false until setScalpMask).
  Status build(const HeadMeshView& mesh, double cell = 0.03, int bandCells = 3);
  bool built() const { return !d_.empty(); }
  // Bytes kept (distances, nearest triangles, scalp flags) and the cells of the grid.
  size_t bytes() const {
    return d_.capacity() * sizeof(float) + tri_.capacity() * sizeof(int32_t) + scalp_.capacity();
  }
  size_t cells() const { return d_.size(); }
  void clear();
  // Replaces the scalp flags (scalp[triangle] != 0 on the scalp; count = the built mesh's
  // triangle count). A wrong count or no built head is refused and the old flags stay.
  Status setScalpMask(const uint8_t* scalp, size_t triangleCount);
  // Bytes the distance grid of this mesh would hold (the arrays build allocates, temporaries
  // included), for a memory check before building; 0 for an empty mesh.
  static double estimateBytes(const HeadMeshView& mesh, double cell = 0.03, int bandCells = 3);
  // Signed distance (negative inside) and its gradient (not normalised; zero when flat).
  float distance(float x, float y, float z, float gradient[3] = nullptr) const;
  // A lower bound of the distance at p, cheap far from the mesh: distance(p) inside the grid;
  // outside it, p's distance to the grid's box plus the (band + 2) cells the grid reaches past
  // the mesh's bounds (distance reads only band * h there).
  float distanceAtLeast(float x, float y, float z) const;
  // Whether the head surface nearest p is scalp (the nearest cell's nearest triangle); false
  // away from the surface or when the mesh has no scalp flags.
  bool scalpNear(float x, float y, float z) const;
  // The unit direction out of the head at p: the distance gradient where it is exact, else the
  // direction from the mesh centre. Returns the distance at p.
  float outward(const float p[3], float dir[3]) const;
  // Moves p out to `margin` outside the surface along the distance gradient (the direction
  // from the mesh centre where the gradient vanishes). Returns the distance before the move.
  // Each move aims `overshoot` past the margin: with none, the last moves shrink with what is
  // left (a gradient a little short of 1), down to where a coordinate's rounding stalls them,
  // and the walk can take all of its 64 steps.
  float pushOut(float p[3], float margin, float overshoot = 0) const;
  // The mean of the mesh's vertices (where outward and pushOut turn to away from the surface).
  const Eigen::Vector3f& centre() const { return centre_; }
  // How far from the surface the distance is exact (band cells); past it distance reads this.
  float band() const { return far_; }

 private:
  float ox_ = 0, oy_ = 0, oz_ = 0, inv_ = 1, far_ = 0;
  int nx_ = 0, ny_ = 0, nz_ = 0;
  Eigen::Vector3f centre_ = Eigen::Vector3f::Zero();
  std::vector<float> d_;
  std::vector<int32_t> tri_;    // per cell: its nearest triangle within the band, else -1
  std::vector<uint8_t> scalp_;  // per triangle: 1 on the scalp (empty: no flags)
  size_t triangleCount_ = 0;
};

}  // namespace hairsketch
