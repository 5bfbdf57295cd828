// Hair roots sampled on the scalp over spherical coordinates (method S5.1).
// Direction of (theta, phi) from the mesh center: (sin t sin p, cos t, sin t cos p)
// (y up, +z the face's front, +x the head's left). Each ray takes the outermost hit on the head
// mesh; when that triangle is scalp, the hit (pushed out along the normal) is a root.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "status.hpp"

namespace hairsketch {

struct RootParams {
  double thetaStepDeg = 2.0;  // sampling step of theta in [0, 180)
  double phiStepDeg = 2.0;    // sampling step of phi in [0, 360)
  double jitter = 0.5;        // random offset, fraction of a step (0..1)
  uint32_t seed = 1;
  int maxStrands = 0;  // 0 = no cap; else an even stride over the sampled roots
};

class ScalpSampler {
 public:
  // positions: #V x 3, indices: #T x 3, scalp: #T flags. Copies the mesh and bins the
  // triangles by the spherical cap around their vertex directions.
  Status build(const float* positions, size_t vertexCount, const uint32_t* indices,
               size_t triangleCount, const uint8_t* scalp, const Eigen::Vector3d& center);
  // Replaces the scalp flags (count = the built mesh's triangle count); the binning stays. A
  // wrong count or nothing built is refused and the old flags stay.
  Status setScalpMask(const uint8_t* scalp, size_t triangleCount);
  // Bytes build keeps and its temporaries, for a memory check before building.
  static double estimateBytes(size_t vertexCount, size_t triangleCount);
  // Roots in deterministic order (theta rows, then phi), at most maxStrands of them. sampleIds
  // (optional) gets each root's sample index i * nPhi + j (theta row i, phi column j): it names
  // the root whatever the scalp mask, the cap or the other roots.
  Status sample(const RootParams& params, std::vector<Eigen::Vector3f>& roots,
                std::vector<uint32_t>* sampleIds = nullptr) const;
  // Outermost hit along the ray center + t * dir (t > 0). Returns false when nothing is hit.
  bool castOutermost(const Eigen::Vector3d& dir, double& t, int& triangle) const;
  bool built() const { return !scalp_.empty(); }
  size_t triangleCount() const { return scalp_.size(); }
  // The mesh as built (scalp avoidance reads it): positions #V x 3, indices #T x 3, flags #T.
  const std::vector<float>& positions() const { return positions_; }
  const std::vector<uint32_t>& indices() const { return indices_; }
  const std::vector<uint8_t>& scalpMask() const { return scalp_; }
  // Bytes kept (the mesh copy and the bins).
  size_t bytes() const {
    return positions_.capacity() * sizeof(float) + indices_.capacity() * sizeof(uint32_t) +
           scalp_.capacity() + (binStart_.capacity() + binTris_.capacity()) * sizeof(uint32_t);
  }

 private:
  // Corner k of triangle t relative to the center, in double.
  Eigen::Vector3d corner(size_t t, int k) const;
  // Unit normal of triangle t pointing away from the center (zero when degenerate).
  Eigen::Vector3d normal(size_t t) const;
  int binOf(double theta, double phi) const;
  std::vector<float> positions_;
  std::vector<uint32_t> indices_;
  std::vector<uint8_t> scalp_;
  Eigen::Vector3d center_ = Eigen::Vector3d::Zero();
  double radius_ = 0;  // largest vertex distance from the center
  int nTheta_ = 0, nPhi_ = 0;
  std::vector<uint32_t> binStart_;  // CSR: bin b owns binTris_[binStart_[b] .. binStart_[b+1])
  std::vector<uint32_t> binTris_;
};

// Finished edges' rule against lone strands: of the roots all[pick[k]], keeps those with at least
// kLoneNeighbours others within `reach` (world units), again until none goes, so a root whose
// neighbours are gone (a scrap an erase left) goes too. pick keeps its order. The reach is fixed
// by the caller (kLoneReach root spacings of the sampling), so a root's fate depends only on the
// roots near it.
constexpr int kLoneNeighbours = 2;
constexpr float kLoneReach = 2.5f;
void dropLoneRoots(const std::vector<Eigen::Vector3f>& all, std::vector<uint32_t>& pick,
                   float reach);

// Direction of spherical coordinates (radians), as in S5.1.
Eigen::Vector3d sphericalDirection(double theta, double phi);

}  // namespace hairsketch
