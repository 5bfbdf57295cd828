// HairEngine::setCurves: the curves become the field's constraints, the tails laid in growth
// (gathered ponytails, braids, buns: each kind's tail from curve_kinds) and the partings.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "curve_kinds.hpp"
#include "elapsed.hpp"
#include "hair_engine.hpp"
#include "memory_budget.hpp"

namespace hairsketch {

namespace {

// Moves each point of a tail's spine out of the body to its radius plus kTailBodyGap.
constexpr float kTailBodyGap = 0.02f;  // world units: 2 mm
void liftTailOffBody(const HeadDistance& body, GatheredTail& t) {
  for (size_t i = 0; i < t.spine.size(); ++i) {
    const float need = (i < t.radius.size() ? t.radius[i] : 0.f) + kTailBodyGap;
    Eigen::Vector3f& p = t.spine[i];
    for (int it = 0; it < 3; ++it) {
      float dir[3];
      const float d = body.outward(p.data(), dir);
      if (d >= need) break;
      p += (need - d) * Eigen::Vector3f(dir[0], dir[1], dir[2]);
    }
  }
}

// Whether the head surface under curve point q is not scalp: q is carried towards the head (down
// the distance gradient, or towards its centre away from the surface) until the distance grid
// knows its nearest triangle; a point more than kOverReach from the head is in the air (true).
bool offScalp(const HeadDistance& head, const double* q) {
  constexpr float kOverReach = 0.6f, kStep = 0.04f, kKnown = 0.06f;
  float p[3] = {float(q[0]), float(q[1]), float(q[2])};
  for (float walked = 0; walked <= kOverReach; walked += kStep) {
    float dir[3];
    const float d = head.outward(p, dir);
    if (d < kKnown) return !head.scalpNear(p[0], p[1], p[2]);
    for (int e = 0; e < 3; ++e) p[e] -= kStep * dir[e];
  }
  return true;
}

// How far curve point q is from the head (world units): carried towards the head as offScalp
// does until the distance grid's exact band, the walk plus the distance there; kOverReach for a
// point farther away.
float strokeLift(const HeadDistance& head, const double* q) {
  constexpr float kOverReach = 0.6f, kStep = 0.04f;
  float p[3] = {float(q[0]), float(q[1]), float(q[2])};
  for (float walked = 0; walked <= kOverReach; walked += kStep) {
    float dir[3];
    const float d = head.outward(p, dir);
    if (d < 0.8f * head.band()) return std::max(0.f, walked + d);
    for (int e = 0; e < 3; ++e) p[e] -= kStep * dir[e];
  }
  return kOverReach;
}

// Curve c's own Volume (ReachCurve::volume): a stream curve's Volume parameter when it is set
// (above 0), else none (-1).
float ownVolume(const CurveSetView& v, size_t c) {
  if (!v.kinds || CurveKindCode(v.kinds[c]) != CurveKindCode::Stream || !v.params || !v.paramStart)
    return -1.f;
  const uint32_t a = v.paramStart[c], b = v.paramStart[c + 1];
  if (b < a + kStreamParamCount) return -1.f;
  const double vol = v.params[a + kStreamParamVolume];
  return vol > 0 ? float(vol) : -1.f;
}
// Whether curve [a, b) of v leaves the scalp over the face (ReachCurve::fringe): its first point
// off the scalp is in front of the head's centre, within the face's half angle (kFaceHalfAngle)
// and above its bottom (kFaceBottom).
bool leavesOverFace(const CurveSetView& v, size_t a, size_t b, const Eigen::Vector3d& centre) {
  if (!v.offScalp) return false;
  for (size_t k = a; k < b; ++k) {
    if (!v.offScalp[k]) continue;
    const double* p = v.points + 3 * k;
    const double dx = p[0] - centre.x(), dz = p[2] - centre.z();
    return dz > 0 && std::atan2(std::abs(dx), dz) < kFaceHalfAngle &&
           p[1] - centre.y() > kFaceBottom;
  }
  return false;
}
}  // namespace

Status HairEngine::setCurves(const CurveSetView& curves) {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "setCurves before setGrid");
  // At most 16 points of each curve, evenly spaced, for the nearest curve at each root.
  curvePoints_.clear();
  curvePointCurve_.clear();
  for (size_t c = 0; c < curves.curveCount; ++c) {
    const size_t a = curves.curveStart[c], b = curves.curveStart[c + 1];
    if (b <= a) continue;
    const size_t n = b - a, take = std::min<size_t>(n, 16);
    for (size_t k = 0; k < take; ++k) {
      const size_t p = a + (take == 1 ? 0 : k * (n - 1) / (take - 1));
      curvePoints_.emplace_back(float(curves.points[3 * p]), float(curves.points[3 * p + 1]),
                                float(curves.points[3 * p + 2]));
      curvePointCurve_.push_back(int32_t(c));
    }
  }
  ConstraintSet next;
  std::vector<uint8_t> nextColours;
  Status s;
  // the curves' stretches off the scalp (over the face, an ear, the neck, or in the air): where
  // a braid gathers, and where a curve may take hair over the face
  std::vector<uint8_t> overFace(curves.pointCount, 0);
  if (headDistance_.built() && curves.points)
    for (size_t k = 0; k < curves.pointCount; ++k)
      overFace[k] = offScalp(headDistance_, curves.points + 3 * k) ? 1 : 0;
  CurveSetView withHead = curves;
  if (headDistance_.built()) {
    withHead.offScalp = overFace.data();
    withHead.headCentre = &centre_;
  }
  // the tails laid in growth: gathered ponytails (with fall), braids and buns
  std::vector<GatheredTail> nextTails;
  std::vector<int32_t> nextTailCurves;
  if (curves.kinds && curves.curveStart && curves.points && curves.paramStart)
    for (size_t c = 0; c < curves.curveCount; ++c) {
      const CurveKindDef* kind = curveKind(curves.kinds[c]);
      const size_t a = curves.curveStart[c], b = curves.curveStart[c + 1];
      const size_t pa = curves.paramStart[c], pb = curves.paramStart[c + 1];
      if (!kind || !kind->tail || b <= a || b > curves.pointCount || pb < pa ||
          pb > curves.paramCount)
        continue;
      const double* pts = curves.points + 3 * a;
      TailContext context;
      context.fall = fall_;
      if (headDistance_.built())
        context.away = (Eigen::Map<const Eigen::Vector3d>(pts) - centre_).cast<float>();
      GatheredTail tail;
      if (!kind->tail(kindCurve(withHead, c), context, tail)) continue;
      nextTails.push_back(std::move(tail));
      nextTailCurves.push_back(int32_t(c));
    }
  // partings: the dividing curves, which bound the scalp's sections
  std::vector<std::vector<Eigen::Vector3f>> nextPartings;
  if (curves.kinds && curves.curveStart && curves.points)
    for (size_t c = 0; c < curves.curveCount; ++c) {
      const size_t a = curves.curveStart[c], b = curves.curveStart[c + 1];
      const CurveKindDef* kind = curveKind(curves.kinds[c]);
      if (!kind || !kind->parting || b <= a || b > curves.pointCount) continue;
      std::vector<Eigen::Vector3f>& line = nextPartings.emplace_back();
      for (size_t k = a; k < b; ++k)
        line.emplace_back(float(curves.points[3 * k]), float(curves.points[3 * k + 1]),
                          float(curves.points[3 * k + 2]));
    }
  // where each tie meets the head: the head point nearest its first circle's centre; and where
  // its stroke was pressed: the head point nearest the curve's first point
  const auto onHead = [&](Eigen::Vector3f x) {
    if (headDistance_.built())
      for (int it = 0; it < 3; ++it) {
        float dir[3];
        const float d = headDistance_.outward(x.data(), dir);
        x -= d * Eigen::Vector3f(dir[0], dir[1], dir[2]);
      }
    return x;
  };
  for (size_t k = 0; k < nextTails.size(); ++k) {
    GatheredTail& t = nextTails[k];
    t.anchor = onHead(t.shape == TailShape::Bun ? t.bunCentre : t.spine.front());
    const double* first = curves.points + 3 * curves.curveStart[nextTailCurves[k]];
    t.pressed = t.shape == TailShape::Bun
                    ? t.anchor
                    : onHead(Eigen::Vector3f(float(first[0]), float(first[1]), float(first[2])));
  }
  // With the bust, a tail's spine stands off the body by its radius: a braid or round tail
  // drawn over a shoulder lies on it, round, rather than pressed flat into it afterwards.
  if (bust_ && bodyDistance_.built())
    for (GatheredTail& t : nextTails)
      if (t.shape != TailShape::Bun) liftTailOffBody(bodyDistance_, t);
  // Whole-section ties lay all their hair in growth, so the field does not see them (their
  // funnel would pull the loose hair of other sections up into them).
  std::vector<char> drop(curves.curveCount, 0);
  bool dropAny = false;
  for (size_t i = 0; i < nextTails.size(); ++i)
    if (sections_ && nextTails[i].section) dropAny = drop[size_t(nextTailCurves[i])] = 1;
  std::vector<double> keptPoints, keptParams;
  std::vector<uint32_t> keptStart{0}, keptParamStart{0};
  std::vector<uint8_t> keptKinds, keptExtend, keptOff;
  CurveSetView fv = withHead;
  if (dropAny && curves.curveStart && curves.points && curves.kinds) {
    for (size_t c = 0; c < curves.curveCount; ++c) {
      const size_t a = curves.curveStart[c], b = curves.curveStart[c + 1];
      if (drop[c] || b < a || b > curves.pointCount) continue;
      keptPoints.insert(keptPoints.end(), curves.points + 3 * a, curves.points + 3 * b);
      if (withHead.offScalp)
        keptOff.insert(keptOff.end(), overFace.begin() + std::ptrdiff_t(a),
                       overFace.begin() + std::ptrdiff_t(b));
      if (curves.paramStart && curves.params)
        keptParams.insert(keptParams.end(), curves.params + curves.paramStart[c],
                          curves.params + curves.paramStart[c + 1]);
      keptStart.push_back(uint32_t(keptPoints.size() / 3));
      keptParamStart.push_back(uint32_t(keptParams.size()));
      keptKinds.push_back(curves.kinds[c]);
      keptExtend.push_back(curves.extend ? curves.extend[c] : 0);
    }
    fv.points = keptPoints.data();
    fv.pointCount = keptPoints.size() / 3;
    fv.curveStart = keptStart.data();
    fv.curveCount = keptKinds.size();
    fv.kinds = keptKinds.data();
    fv.extend = curves.extend ? keptExtend.data() : nullptr;
    fv.params = curves.params ? keptParams.data() : nullptr;
    fv.paramCount = keptParams.size();
    fv.paramStart = curves.paramStart ? keptParamStart.data() : nullptr;
    fv.offScalp = withHead.offScalp ? keptOff.data() : nullptr;
  }
  if (fall_) {
    // The reach of stream curves, ponytail spines and braids ends their hair, in place of the
    // fading extension; "extend" means the curve's hair grows on.
    std::vector<ReachCurve> rc;
    // with the shape rules, each point's distance off the head
    std::vector<float> lift;
    if (shape_.on && headDistance_.built() && fv.points) {
      lift.resize(fv.pointCount);
      for (size_t k = 0; k < fv.pointCount; ++k)
        lift[k] = strokeLift(headDistance_, fv.points + 3 * k);
    }
    // (ties on) a stroke that grows on into a tie (its end within kIntoTie of a tie's curve: a
    // stroke combed into a bun or a ponytail) says nothing of the length of the hair around it:
    // its hair is the tie's. Counted with its own length, one short stroke into a half-up's bun
    // cut the loose hair below the parting to the chin.
    const auto intoTie = [&](size_t c) {
      if (!ties_ || !(fv.extend && fv.extend[c] != 0)) return false;
      const double* end = fv.points + 3 * (fv.curveStart[c + 1] - 1);
      // every tie of the session (whole-section ties are not in fv: the field does not see them)
      for (size_t t = 0; t < curves.curveCount; ++t) {
        const CurveKindDef* k = curveKind(curves.kinds[t]);
        if (!k || !k->tail) continue;
        for (size_t q = curves.curveStart[t]; q < curves.curveStart[t + 1] && q < curves.pointCount;
             ++q) {
          const double* x = curves.points + 3 * q;
          if (std::hypot(x[0] - end[0], x[1] - end[1], x[2] - end[2]) < kIntoTie) return true;
        }
      }
      return false;
    };
    if (fv.kinds && fv.curveStart && fv.points)
      for (size_t c = 0; c < fv.curveCount; ++c) {
        const CurveKindDef* kind = curveKind(fv.kinds[c]);
        if (!kind || !kind->reach) continue;
        const size_t a = fv.curveStart[c], b = fv.curveStart[c + 1];
        if (b <= a || b > fv.pointCount) continue;
        const bool setsLength = kind->tail == nullptr && !intoTie(c);
        rc.push_back({fv.points + 3 * a, b - a, fv.extend && fv.extend[c] != 0,
                      fv.offScalp ? fv.offScalp + a : nullptr, setsLength,
                      lift.empty() ? nullptr : lift.data() + a, ownVolume(fv, c),
                      shape_.on && leavesOverFace(fv, a, b, centre_)});
      }
    std::vector<uint8_t> noExtension(fv.curveCount, 0);
    CurveSetView view = fv;
    if (fv.extend) view.extend = noExtension.data();
    s = curvesToConstraints(grid_, view, next, &nextColours);
    if (s.ok()) {
      // a curve's footprint is kept while the curve, its flags, the grid and the head stay
      const Grid lattice = reachGrid(grid_);
      std::vector<std::pair<uint64_t, CurveFootprint>> kept;
      std::vector<const CurveFootprint*> parts;
      kept.reserve(rc.size());
      for (const ReachCurve& c : rc) {
        uint64_t key = 1469598103934665603ull;
        auto mix = [&](const void* data, size_t bytes) {
          const auto* b = static_cast<const unsigned char*>(data);
          for (size_t i = 0; i < bytes; ++i) key = (key ^ b[i]) * 1099511628211ull;
        };
        mix(c.points, 3 * c.count * sizeof(double));
        mix(&c.growsOn, sizeof(bool));
        mix(&c.setsLength, sizeof(bool));
        mix(&c.fringe, sizeof(bool));
        mix(&c.volume, sizeof(float));
        if (c.lift) mix(c.lift, c.count * sizeof(float));
        if (c.offScalp) mix(c.offScalp, c.count);
        auto found = std::find_if(footprints_.begin(), footprints_.end(),
                                  [&](const auto& f) { return f.first == key; });
        if (found != footprints_.end()) {
          kept.emplace_back(key, std::move(found->second));
          footprints_.erase(found);
        } else {
          kept.emplace_back(key, CurveFootprint());
          curveFootprint(lattice, c, kept.back().second);
        }
      }
      footprints_ = std::move(kept);
      for (const auto& f : footprints_) parts.push_back(&f.second);
      combineReach(lattice, parts, reach_, shape_.on ? &centre_ : nullptr);
    }
  } else {
    s = curvesToConstraints(grid_, fv, next, &nextColours);
  }
  if (!s.ok()) return s;
  s = solver_->setConstraints(next);
  if (!s.ok()) return s;
  constraints_ = std::move(next);
  colours_ = std::move(nextColours);
  tails_ = std::move(nextTails);
  tailCurves_ = std::move(nextTailCurves);
  partings_ = std::move(nextPartings);
  fieldValid_ = false;
  return Status::Ok();
}

}  // namespace hairsketch
