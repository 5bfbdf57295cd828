// Hand-made strands for the tests of growth steps that work on grown hair (gathered_tail.hpp):
// polylines sampled at a fixed step, and a flat sheet of them converging on a tail.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "strand_growth.hpp"

namespace hand_strands {

constexpr float kStep = 0.05f;

// Appends a strand through the corners, sampled every kStep (or less) along each leg.
inline void addStrand(const std::vector<Eigen::Vector3f>& corners, hairsketch::Strands& out) {
  if (out.strandStart.empty()) out.strandStart.push_back(0);
  for (size_t k = 0; k + 1 < corners.size(); ++k) {
    const Eigen::Vector3f a = corners[k], b = corners[k + 1];
    const int n = std::max(1, int(std::ceil((b - a).norm() / kStep)));
    for (int i = (k == 0 ? 0 : 1); i <= n; ++i) {
      const Eigen::Vector3f p = a + (float(i) / float(n)) * (b - a);
      out.points.insert(out.points.end(), {p.x(), p.y(), p.z()});
    }
  }
  out.strandStart.push_back(uint32_t(out.points.size() / 3));
}

struct Hair {
  hairsketch::Strands strands;
  std::vector<Eigen::Vector3f> roots;
  std::vector<uint32_t> key;  // each strand's seed key: its index
};

// A sheet: roots on a 41 x 3 patch above the origin (y = 1), each strand running to a point of a
// thin line on the plane y = 0 (x in [-0.1, 0.1], z under 0.01), then straight down to y = bottom.
inline Hair sheet(float bottom) {
  Hair h;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j < 3; ++j) {
      const float x = -1.f + 0.05f * float(i), z = 0.3f + 0.1f * float(j);
      const Eigen::Vector3f root(x, 1.f, z), at(0.1f * x, 0.f, 0.02f * z);
      h.roots.push_back(root);
      addStrand({root, at + Eigen::Vector3f(0, 0.05f, 0), Eigen::Vector3f(at.x(), bottom, at.z())},
                h.strands);
      h.key.push_back(uint32_t(h.key.size()));
    }
  return h;
}

}  // namespace hand_strands
