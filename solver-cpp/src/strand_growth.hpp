// Hair growth in the vector field (SPEC S5.2): from each root, append segments l * v(p),
// l = stepFraction * d, v trilinearly interpolated from the field and not normalised (paper §6).
// A strand stops when |v(p)| < minMagnitude, when the next point would leave the bounding
// volume, when the next segment would take its length past maxLength, or after maxSegments.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "field_system.hpp"
#include "grid.hpp"
#include "status.hpp"

namespace hairsketch {

struct GrowthParams {
  double stepFraction = 0.5;  // l / d
  double minMagnitude = 0.05;
  double maxLength = 1e30;  // world units
  int maxSegments = 200;
};

// protocol.ts StrandArrays: strand s owns points strandStart[s] .. strandStart[s + 1] - 1,
// the first being its root. Every root gives a strand (possibly just the root point).
// An allocator that leaves new elements uninitialised: growth writes every point it keeps, so
// zero-filling the (large, reused) point buffer on each resize would be wasted work.
template <typename T>
struct UninitAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = UninitAllocator<U>;
  };
  UninitAllocator() = default;
  template <typename U>
  UninitAllocator(const UninitAllocator<U>&) noexcept {}
  template <typename U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

struct Strands {
  std::vector<float, UninitAllocator<float>> points;  // points[3 * point + axis]
  std::vector<uint32_t> strandStart;
};

// The field in float, interleaved (v[3 * p + axis]), for cache-friendly interpolation.
std::vector<float> toFloatField(const Field& T);

// Trilinear interpolation of a float field at world point x (x inside the volume).
Eigen::Vector3f interpolateField(const Grid& grid, const float* field, const Eigen::Vector3f& x);

// Grows one strand per root. OverMemoryCap (and no strands) if the output would exceed
// maxPoints points in total.
Status growStrands(const Grid& grid, const std::vector<float>& field,
                   const std::vector<Eigen::Vector3f>& roots, const GrowthParams& params,
                   Strands& out, size_t maxPoints = size_t(24) << 20);

}  // namespace hairsketch
