// A set of field constraints (method S2.3): grid point index p -> target direction c_p.
// Every constraint carries the weight omega^2; only the set and the targets change while
// editing (S2.4).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "grid.hpp"
#include "status.hpp"

namespace hairsketch {

struct Constraint {
  int index = 0;                                     // grid point p
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  // c_p (not necessarily unit length)
};

// Sorted by index, one entry per grid point.
using ConstraintSet = std::vector<Constraint>;

// Sorts by index and merges duplicates by averaging their targets.
ConstraintSet normalizeConstraints(std::vector<Constraint> raw);

// InvalidInput when an index is out of range or a target is not finite.
Status validateConstraints(const Grid& grid, const ConstraintSet& set);

// Difference between two normalised sets (method S3.2).
struct ConstraintDiff {
  std::vector<int> added;    // in next, not in prev
  std::vector<int> removed;  // in prev, not in next
  std::vector<int> changed;  // in both, target differs
};
ConstraintDiff diffConstraints(const ConstraintSet& prev, const ConstraintSet& next);

}  // namespace hairsketch
