#include "constraints.hpp"

#include <algorithm>
#include <cmath>

namespace hairsketch {

ConstraintSet normalizeConstraints(std::vector<Constraint> raw) {
  std::stable_sort(raw.begin(), raw.end(),
                   [](const Constraint& a, const Constraint& b) { return a.index < b.index; });
  ConstraintSet out;
  out.reserve(raw.size());
  size_t i = 0;
  while (i < raw.size()) {
    size_t j = i;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    while (j < raw.size() && raw[j].index == raw[i].index) sum += raw[j++].target;
    out.push_back({raw[i].index, sum / double(j - i)});
    i = j;
  }
  return out;
}

Status validateConstraints(const Grid& grid, const ConstraintSet& set) {
  const int64_t n = grid.size();
  for (const Constraint& c : set) {
    if (c.index < 0 || c.index >= n)
      return Status::Error(StatusCode::InvalidInput,
                           "constraint index " + std::to_string(c.index) + " is outside the grid");
    if (!c.target.allFinite())
      return Status::Error(StatusCode::NonFinite, "constraint target at index " +
                                                      std::to_string(c.index) + " is not finite");
  }
  return Status::Ok();
}

ConstraintDiff diffConstraints(const ConstraintSet& prev, const ConstraintSet& next) {
  ConstraintDiff d;
  size_t a = 0, b = 0;
  while (a < prev.size() || b < next.size()) {
    if (b == next.size() || (a < prev.size() && prev[a].index < next[b].index)) {
      d.removed.push_back(prev[a++].index);
    } else if (a == prev.size() || next[b].index < prev[a].index) {
      d.added.push_back(next[b++].index);
    } else {
      if (prev[a].target != next[b].target) d.changed.push_back(next[b].index);
      ++a;
      ++b;
    }
  }
  return d;
}

}  // namespace hairsketch
