#include "curve_kinds.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "braid_bun.hpp"
#include "curve_params.hpp"
#include "dividing_constraints.hpp"
#include "ponytail_constraints.hpp"
#include "stream_constraints.hpp"

namespace hairsketch {

namespace curve_kinds {

// Constraints of each kind.

Status streamConstraints(const Grid& g, const KindCurve& k, const std::string& who,
                         std::vector<Constraint>& raw, std::vector<ConstraintColour>* rc) {
  const size_t pn = k.paramCount;
  const double* prm = k.params;
  // none (a caller that knows no parameters: every one at its default) or all of them
  if (pn != 0 && pn != kStreamParamCount)
    return Status::Error(StatusCode::InvalidInput, who + " must have " +
                                                       std::to_string(kStreamParamCount) +
                                                       " parameters, has " + std::to_string(pn));
  for (size_t i = 0; i < pn; ++i)
    if (!std::isfinite(prm[i]))
      return Status::Error(StatusCode::NonFinite,
                           who + ": parameter " + std::to_string(i) + " is not finite");
  if (pn && (prm[kStreamParamVolume] < 0 || prm[kStreamParamVolume] > 0.3))
    return Status::Error(StatusCode::InvalidInput, who + ": volume must be within 0..0.3");
  appendStreamConstraints(g, k.points, k.count, k.extend, raw, rc, pn ? prm : nullptr);
  return Status::Ok();
}

Status dividingConstraints(const Grid& g, const KindCurve& k, const std::string& who,
                           std::vector<Constraint>& raw, std::vector<ConstraintColour>* rc) {
  DividingParams dp;
  Status s = parseDividingParams(k.params, k.paramCount, k.count, dp);
  if (!s.ok()) return Status::Error(s.code, who + ": " + s.message);
  appendDividingConstraints(g, k.points, k.count, dp, raw, rc);
  return Status::Ok();
}

Status ponytailConstraints(const Grid& g, const KindCurve& k, const std::string& who,
                           std::vector<Constraint>& raw, std::vector<ConstraintColour>* rc) {
  PonytailParams pp;
  Status s = parsePonytailParams(k.params, k.paramCount, pp);
  if (!s.ok()) return Status::Error(s.code, who + ": " + s.message);
  appendPonytailConstraints(g, k.points, k.count, k.extend, pp, raw, rc);
  return Status::Ok();
}

Status braidConstraints(const Grid& g, const KindCurve& k, const std::string& who,
                        std::vector<Constraint>& raw, std::vector<ConstraintColour>* rc) {
  BraidParams bp;
  Status s = parseBraidParams(k.params, k.paramCount, bp);
  if (!s.ok()) return Status::Error(s.code, who + ": " + s.message);
  if (k.count == 0) return Status::Ok();
  const size_t gather = braidGatherIndex(k.offScalp, k.count);
  appendPonytailConstraints(g, k.points, k.count, k.extend,
                            braidAsPonytail(k.points, k.count, gather, bp), raw, rc);
  return Status::Ok();
}

Status bunConstraints(const Grid& g, const KindCurve& k, const std::string& who,
                      std::vector<Constraint>& raw, std::vector<ConstraintColour>* rc) {
  BunParams bp;
  Status s = parseBunParams(k.params, k.paramCount, bp);
  if (!s.ok()) return Status::Error(s.code, who + ": " + s.message);
  if (k.count == 0) return Status::Ok();
  std::vector<double> spine;
  const PonytailParams pp = bunAsPonytail(bunFrame(k.points, k.count, bp, k.headCentre), bp, spine);
  appendPonytailConstraints(g, spine.data(), 2, false, pp, raw, rc);
  return Status::Ok();
}

// Tails of each kind: a gathered ponytail's (with fall), a braid's, a bun's.

bool ponytailLaysTail(const KindCurve& k, const TailContext& ctx, GatheredTail& out) {
  if (!ctx.fall) return false;
  PonytailParams pp;
  if (!parsePonytailParams(k.params, k.paramCount, pp).ok() || pp.gather != 1) return false;
  out = gatheredTail(k.points, k.count, pp);
  out.growsOn = k.extend;
  out.section = pp.section;
  return true;
}

bool braidLaysTail(const KindCurve& k, const TailContext& ctx, GatheredTail& out) {
  BraidParams bp;
  if (!parseBraidParams(k.params, k.paramCount, bp).ok()) return false;
  const size_t gather = braidGatherIndex(k.offScalp, k.count);
  out = braidTail(k.points, k.count, gather, bp, ctx.away);
  out.growsOn = k.extend;
  out.section = bp.section;
  return true;
}

bool bunLaysTail(const KindCurve& k, const TailContext&, GatheredTail& out) {
  BunParams bp;
  if (!parseBunParams(k.params, k.paramCount, bp).ok()) return false;
  out = bunTail(bunFrame(k.points, k.count, bp, k.headCentre), bp);
  out.section = bp.section;
  return true;
}

// One entry per kind: code, name, constraints, tail, reach, parting.
const CurveKindDef kCurveKinds[] = {
    {CurveKindCode::Stream, "stream", streamConstraints, nullptr, true, false},
    {CurveKindCode::Dividing, "dividing", dividingConstraints, nullptr, false, true},
    {CurveKindCode::Ponytail, "ponytail", ponytailConstraints, ponytailLaysTail, true, false},
    {CurveKindCode::Braid, "braid", braidConstraints, braidLaysTail, true, false},
    {CurveKindCode::Bun, "bun", bunConstraints, bunLaysTail, false, false},
};

}  // namespace curve_kinds

KindCurve kindCurve(const CurveSetView& cs, size_t c) {
  const size_t begin = cs.curveStart[c], end = cs.curveStart[c + 1];
  const size_t p0 = cs.paramStart ? cs.paramStart[c] : 0;
  KindCurve k;
  k.points = cs.points + 3 * begin;
  k.count = end - begin;
  k.extend = cs.extend && cs.extend[c] != 0;
  k.params = cs.params ? cs.params + p0 : nullptr;
  k.paramCount = cs.paramStart ? cs.paramStart[c + 1] - p0 : 0;
  k.offScalp = cs.offScalp ? cs.offScalp + begin : nullptr;
  k.headCentre = cs.headCentre;
  return k;
}

const CurveKindDef* curveKind(uint8_t code) {
  for (const CurveKindDef& k : curve_kinds::kCurveKinds)
    if (uint8_t(k.code) == code) return &k;
  return nullptr;
}

}  // namespace hairsketch
