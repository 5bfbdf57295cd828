#include "curve_set.hpp"

#include <cmath>
#include <string>
#include <unordered_map>

#include "braid_bun.hpp"
#include "dividing_constraints.hpp"
#include "ponytail_constraints.hpp"
#include "stream_constraints.hpp"

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
    const size_t begin = cs.curveStart[c], end = cs.curveStart[c + 1];
    const double* pts = cs.points + 3 * begin;
    const size_t n = end - begin;
    const size_t p0 = cs.paramStart ? cs.paramStart[c] : 0;
    const size_t pn = cs.paramStart ? cs.paramStart[c + 1] - p0 : 0;
    const double* prm = cs.params ? cs.params + p0 : nullptr;
    const std::string name = "curves: curve " + std::to_string(c);
    switch (cs.kinds[c]) {
      case uint8_t(CurveKindCode::Stream):
        if (pn != kStreamParamCount)
          return Status::Error(StatusCode::InvalidInput,
                               name + " (stream) must have " + std::to_string(kStreamParamCount) +
                                   " parameters, has " + std::to_string(pn));
        for (size_t i = 0; i < pn; ++i)
          if (!std::isfinite(prm[i]))
            return Status::Error(StatusCode::NonFinite, name + " (stream): parameter " +
                                                            std::to_string(i) + " is not finite");
        appendStreamConstraints(g, pts, n, cs.extend[c] != 0, raw, rc, pn ? prm : nullptr);
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
      case uint8_t(CurveKindCode::Braid): {
        BraidParams bp;
        Status s = parseBraidParams(prm, pn, bp);
        if (!s.ok()) return Status::Error(s.code, name + " (braid): " + s.message);
        if (n == 0) break;
        const size_t gather = braidGatherIndex(cs.offScalp ? cs.offScalp + begin : nullptr, n);
        appendPonytailConstraints(g, pts, n, cs.extend[c] != 0, braidAsPonytail(pts, n, gather, bp),
                                  raw, rc);
        break;
      }
      case uint8_t(CurveKindCode::Bun): {
        BunParams bp;
        Status s = parseBunParams(prm, pn, bp);
        if (!s.ok()) return Status::Error(s.code, name + " (bun): " + s.message);
        if (n == 0) break;
        std::vector<double> spine;
        const PonytailParams pp = bunAsPonytail(bunFrame(pts, n, bp, cs.headCentre), bp, spine);
        appendPonytailConstraints(g, spine.data(), 2, false, pp, raw, rc);
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
