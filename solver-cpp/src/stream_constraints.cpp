#include "stream_constraints.hpp"

#include <cmath>
#include <string>
#include <unordered_map>

#include "dividing_constraints.hpp"
#include "ponytail_constraints.hpp"

namespace hairsketch {

namespace {

// Claims the 8 corners of the cell containing world point m, if m is inside the volume.
void claimCell(const Grid& g, const Eigen::Vector3d& m, const Eigen::Vector3d& target,
               std::vector<Constraint>& out) {
  if (!g.insideVolume(m)) return;
  const Eigen::Vector3d u = (m - g.origin) / g.step;
  const int dims[3] = {g.nx, g.ny, g.nz};
  int c[3];
  for (int a = 0; a < 3; ++a) {
    // A point on the upper face belongs to the last cell.
    c[a] = std::min(int(std::floor(u[a])), dims[a] - 2);
    c[a] = std::max(c[a], 0);
  }
  for (int dk = 0; dk < 2; ++dk)
    for (int dj = 0; dj < 2; ++dj)
      for (int di = 0; di < 2; ++di)
        out.push_back({g.index(c[0] + di, c[1] + dj, c[2] + dk), target});
}

}  // namespace

void appendStreamConstraints(const Grid& g, const double* pts, size_t count, bool extend,
                             std::vector<Constraint>& out, std::vector<ConstraintColour>* colours) {
  Eigen::Vector3d lastTangent = Eigen::Vector3d::Zero();
  double lastLength = 0;
  for (size_t s = 0; s + 1 < count; ++s) {
    const Eigen::Vector3d a(pts[3 * s], pts[3 * s + 1], pts[3 * s + 2]);
    const Eigen::Vector3d b(pts[3 * s + 3], pts[3 * s + 4], pts[3 * s + 5]);
    const double len = (b - a).norm();
    if (!(len > 0)) continue;
    const Eigen::Vector3d t = (b - a) / len;
    claimCell(g, 0.5 * (a + b), t, out);
    if (colours) colours->resize(out.size(), ConstraintColour::Blue);
    lastTangent = t;
    lastLength = len;
  }
  if (!extend || lastLength == 0) return;
  const Eigen::Vector3d end(pts[3 * (count - 1)], pts[3 * (count - 1) + 1],
                            pts[3 * (count - 1) + 2]);
  const int K = kStreamExtensionSegments;
  for (int k = 1; k <= K; ++k) {
    const double m = 1.0 - double(k) / K;
    const Eigen::Vector3d mid = end + (k - 0.5) * lastLength * lastTangent;
    claimCell(g, mid, m * lastTangent, out);
    if (colours) colours->resize(out.size(), ConstraintColour::Red);
  }
}

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
        return Status::Error(StatusCode::InvalidInput,
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
    const size_t begin = cs.curveStart[c], end = cs.curveStart[c + 1];
    const double* pts = cs.points + 3 * begin;
    const size_t n = end - begin;
    const size_t p0 = cs.paramStart ? cs.paramStart[c] : 0;
    const size_t pn = cs.paramStart ? cs.paramStart[c + 1] - p0 : 0;
    const double* prm = cs.params ? cs.params + p0 : nullptr;
    const std::string name = "curves: curve " + std::to_string(c);
    switch (cs.kinds[c]) {
      case uint8_t(CurveKindCode::Stream):
        if (pn != 0)
          return Status::Error(StatusCode::InvalidInput,
                               name + " (stream) must have an empty parameter block, has " +
                                   std::to_string(pn) + " numbers");
        appendStreamConstraints(g, pts, n, cs.extend[c] != 0, raw, rc);
        break;
      case uint8_t(CurveKindCode::Dividing): {
        DividingParams dp;
        Status s = parseDividingParams(prm, pn, n, dp);
        if (!s.ok()) return Status::Error(s.code, name + " (dividing): " + s.message);
        appendDividingConstraints(g, pts, n, dp, raw, rc);
        break;
      }
      case uint8_t(CurveKindCode::Ponytail): {
        PonytailParams pp;
        Status s = parsePonytailParams(prm, pn, pp);
        if (!s.ok()) return Status::Error(s.code, name + " (ponytail): " + s.message);
        appendPonytailConstraints(g, pts, n, cs.extend[c] != 0, pp, raw, rc);
        break;
      }
      default:
        return Status::Error(StatusCode::InvalidInput,
                             name + " has unknown kind " + std::to_string(int(cs.kinds[c])));
    }
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
      return Status::Error(StatusCode::InvalidInput,
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
