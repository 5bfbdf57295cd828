// Strands from lists of points and back, for the detail tests (double-precision points in,
// the engine's float Strands out).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "strand_growth.hpp"

namespace strand_lists {

using Strand = std::vector<Eigen::Vector3d>;

inline hairsketch::Strands makeStrands(const std::vector<Strand>& list) {
  hairsketch::Strands s;
  s.strandStart.push_back(0);
  for (const Strand& st : list) {
    for (const Eigen::Vector3d& p : st)
      for (int a = 0; a < 3; ++a) s.points.push_back(float(p[a]));
    s.strandStart.push_back(uint32_t(s.points.size() / 3));
  }
  return s;
}

inline Strand strandOf(const hairsketch::Strands& s, size_t k) {
  Strand out;
  for (uint32_t p = s.strandStart[k]; p < s.strandStart[k + 1]; ++p)
    out.emplace_back(s.points[3 * p], s.points[3 * p + 1], s.points[3 * p + 2]);
  return out;
}

}  // namespace strand_lists
