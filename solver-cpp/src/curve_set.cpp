#include "curve_set.hpp"

#include <cmath>
#include <string>
#include <unordered_map>

#include "curve_kinds.hpp"

namespace hairsketch {

Status curvesToConstraints(const Grid& g, const CurveSetView& cs, ConstraintSet& out,
                           std::vector<uint8_t>* colours) {
  out.clear();
  if (colours) colours->clear();
  if (cs.curveCount > 0) {
    if (!cs.curveStart || !cs.kinds || !cs.extend || (cs.pointCount > 0 && !cs.points))
      return Status::Error(StatusCode::InvalidInput, "curves: missing array");
    if (cs.curveStart[0] != 0 || cs.curveStart[cs.curveCount] != cs.pointCount)
      return Status::Error(StatusCode::InvalidInput,
                           "curves: curveStart must start at 0 and end at the point count");
    for (size_t c = 0; c < cs.curveCount; ++c)
      if (cs.curveStart[c + 1] < cs.curveStart[c])
        return Status::Error(StatusCode::InvalidInput, "curves: curveStart is not non-decreasing");
    for (size_t i = 0; i < 3 * cs.pointCount; ++i)
      if (!std::isfinite(cs.points[i]))
        return Status::Error(StatusCode::NonFinite,
                             "curves: point " + std::to_string(i / 3) + " is not finite");
    if (cs.paramStart) {
      if (cs.paramCount > 0 && !cs.params)
        return Status::Error(StatusCode::InvalidInput, "curves: missing params array");
      if (cs.paramStart[0] != 0 || cs.paramStart[cs.curveCount] != cs.paramCount)
        return Status::Error(StatusCode::InvalidInput,
                             "curves: paramStart must start at 0 and end at the params length");
      for (size_t c = 0; c < cs.curveCount; ++c)
        if (cs.paramStart[c + 1] < cs.paramStart[c])
          return Status::Error(StatusCode::InvalidInput,
                               "curves: paramStart is not non-decreasing");
    } else if (cs.paramCount > 0) {
      return Status::Error(StatusCode::InvalidInput, "curves: params without paramStart");
    }
  }
  if (cs.extraCount > 0 && (!cs.extraIndex || !cs.extraTarget))
    return Status::Error(StatusCode::InvalidInput, "curves: missing extra constraint arrays");
  std::vector<Constraint> raw;
  std::vector<ConstraintColour> rawColour;
  std::vector<ConstraintColour>* rc = colours ? &rawColour : nullptr;
  for (size_t c = 0; c < cs.curveCount; ++c) {
    const std::string name = "curves: curve " + std::to_string(c);
    const CurveKindDef* kind = curveKind(cs.kinds[c]);
    if (!kind)
      return Status::Error(StatusCode::InvalidInput,
                           name + " has unknown kind " + std::to_string(int(cs.kinds[c])));
    Status s = kind->constraints(g, kindCurve(cs, c), name + " (" + kind->name + ")", raw, rc);
    if (!s.ok()) return s;
  }
  for (size_t e = 0; e < cs.extraCount; ++e) {
    const int p = cs.extraIndex[e];
    const Eigen::Vector3d t(cs.extraTarget[3 * e], cs.extraTarget[3 * e + 1],
                            cs.extraTarget[3 * e + 2]);
    if (p < 0 || int64_t(p) >= g.size())
      return Status::Error(StatusCode::InvalidInput, "curves: extra constraint " +
                                                         std::to_string(e) + " has grid index " +
                                                         std::to_string(p) + " outside the grid");
    if (!t.allFinite())
      return Status::Error(StatusCode::NonFinite,
                           "curves: extra constraint " + std::to_string(e) + " is not finite");
    raw.push_back({p, t});
    if (rc) rc->push_back(ConstraintColour::Extra);
  }
  std::unordered_map<int, uint8_t> first;
  if (colours)
    for (size_t k = 0; k < raw.size(); ++k) first.emplace(raw[k].index, uint8_t(rawColour[k]));
  out = normalizeConstraints(std::move(raw));
  if (colours) {
    colours->resize(out.size());
    for (size_t k = 0; k < out.size(); ++k) (*colours)[k] = first.at(out[k].index);
  }
  return Status::Ok();
}

}  // namespace hairsketch
