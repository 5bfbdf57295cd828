#include "hair_engine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "curve_kinds.hpp"
#include "elapsed.hpp"
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
}  // namespace

// Per grid point the engine holds, besides its solver: field_ (24 bytes), fieldF_ (12), the
// binding's float copy for JS (12) and toFloatField's temporary (12).
constexpr double kEngineBytesPerPoint = 60;

Status HairEngine::setGrid(const Grid& grid, double omega, const std::string& solverName) {
  std::unique_ptr<FieldSolver> solver = makeFieldSolver(solverName);
  if (!solver)
    return Status::Error(StatusCode::InvalidInput, "unknown solver '" + solverName + "'");
  Status s = checkGridIndexable(grid);
  if (!s.ok()) return s;
  // The previous grid's solver and buffers are released first (their memory is what the new
  // grid may use); a refused grid leaves the engine without a grid (NotReady until the next).
  solver_.reset();
  hasGrid_ = false;
  field_ = Field();
  std::vector<float>().swap(fieldF_);
  strands_ = Strands{};
  const double n = double(grid.nx) * grid.ny * grid.nz;
  const int64_t cap = availableMemoryBytes();
  s = checkMemory(solverName + " solver", solver->estimateBytes(grid) + kEngineBytesPerPoint * n,
                  cap);
  if (!s.ok()) return s;
  solver->setMemoryCap(cap - int64_t(kEngineBytesPerPoint * n));
  s = solver->setGrid(grid, omega);
  if (!s.ok()) return s;
  solver_ = std::move(solver);
  grid_ = grid;
  hasGrid_ = true;
  constraints_.clear();
  colours_.clear();
  field_ = Field::Zero(grid.size(), 3);
  fieldF_.assign(size_t(grid.size()) * 3, 0.f);
  fieldValid_ = true;  // no constraints: the zero field is the solution
  strands_ = Strands{};
  strands_.strandStart.assign(1, 0);
  priorSet_ = false;
  reach_.clear();
  footprints_.clear();
  return applyPrior();
}

// The solver's prior follows the setting, the grid and the head: set when fall is on and there
// is a head, cleared (only if it was set, so sessions without fall never see the call) otherwise.
Status HairEngine::applyPrior() {
  if (!hasGrid_ || !solver_) return Status::Ok();
  if (fall_ && headDistance_.built()) {
    Status s = solver_->setPrior(fallWeight(grid_.step),
                                 fallDirections(grid_, headDistance_, centre_, finish_));
    priorSet_ = s.ok();
    if (!constraints_.empty()) fieldValid_ = false;
    return s;
  }
  if (!priorSet_) return Status::Ok();
  priorSet_ = false;
  if (!constraints_.empty()) fieldValid_ = false;
  return solver_->setPrior(0.0, Field());
}

Status HairEngine::setFinish(bool on) {
  if (on == finish_) return Status::Ok();
  finish_ = on;
  return fall_ ? applyPrior() : Status::Ok();  // the prior opens the face with finished edges
}

Status HairEngine::setFall(bool on) {
  if (on == fall_) return Status::Ok();
  fall_ = on;
  reach_.clear();
  return applyPrior();
}

Status HairEngine::setScalp(const float* positions, size_t vertexCount, const uint32_t* indices,
                            size_t triangleCount, const uint8_t* scalp,
                            const Eigen::Vector3d& center) {
  rootsValid_ = false;
  roots_.clear();
  rootIds_.clear();
  subset_ = false;
  // The previous head is released first: its memory is what the new one may use.
  scalp_ = ScalpSampler();
  headDistance_ = HeadDistance();
  const HeadMeshView view{positions, vertexCount, indices, triangleCount, scalp};
  Status s = checkMemory(
      "head mesh (" + std::to_string(triangleCount) + " triangles)",
      ScalpSampler::estimateBytes(vertexCount, triangleCount) + HeadDistance::estimateBytes(view),
      availableMemoryBytes());
  if (!s.ok()) return s;
  const auto t0 = Clock::now();
  s = scalp_.build(positions, vertexCount, indices, triangleCount, scalp, center);
  if (!s.ok()) return s;
  const auto t1 = Clock::now();
  s = headDistance_.build(view);
  if (!s.ok()) scalp_ = ScalpSampler();
  samplerMs_ = msBetween(t0, t1);
  distanceMs_ = msSince(t1);
  centre_ = center;
  footprints_.clear();  // the curves' stretches off the scalp depend on the head
  if (!s.ok()) return s;
  return applyPrior();
}

Status HairEngine::setBody(const float* positions, size_t vertexCount, const uint32_t* indices,
                           size_t triangleCount) {
  // The previous body is released first: its memory is what the new one may use.
  bodyDistance_ = HeadDistance();
  if (triangleCount == 0) return Status::Ok();
  if (!positions || !indices || vertexCount == 0)
    return Status::Error(StatusCode::InvalidInput, "body: empty mesh");
  if (triangleCount > size_t(1) << 26 || vertexCount > size_t(1) << 28)
    return Status::Error(StatusCode::InvalidInput, "body: too large");
  for (size_t i = 0; i < 3 * vertexCount; ++i)
    if (!std::isfinite(positions[i]))
      return Status::Error(StatusCode::NonFinite, "body: non-finite vertex position");
  for (size_t i = 0; i < 3 * triangleCount; ++i)
    if (indices[i] >= vertexCount)
      return Status::Error(StatusCode::InvalidInput,
                           "body: triangle index " + std::to_string(indices[i]) + " out of range");
  const HeadMeshView view{positions, vertexCount, indices, triangleCount, nullptr};
  Status s =
      checkMemory("body mesh (" + std::to_string(triangleCount) + " triangles)",
                  HeadDistance::estimateBytes(view, kBodyCell, kBodyBand), availableMemoryBytes());
  if (!s.ok()) return s;
  s = bodyDistance_.build(view, kBodyCell, kBodyBand);
  if (!s.ok()) bodyDistance_ = HeadDistance();
  return s;
}

BodyCollider HairEngine::bodyCollider() const {
  BodyCollider c;
  if (!bust_) return c;
  if (bodyDistance_.built()) c.body = &bodyDistance_;
  c.headBelow = true;  // the head's own neck (and a loaded bust's shoulders) below the chin
  return c;
}

// keepOutsideHead for the body (bust on with a body; the head mesh as the body is kept outside
// by the head's own pass).
void HairEngine::keepOutsideBody(float margin, const std::vector<uint32_t>* only) {
  const BodyCollider c = bodyCollider();
  if (c.body) keepOutsideHead(*c.body, margin, strands_, only);
}

Status HairEngine::setScalpMask(const uint8_t* scalp, size_t triangleCount) {
  if (!scalp_.built() || !headDistance_.built())
    return Status::Error(StatusCode::NotReady, "scalp mask before setScalp");
  if (!scalp || triangleCount != scalp_.triangleCount())
    return Status::Error(StatusCode::InvalidInput,
                         "scalp mask: " + std::to_string(triangleCount) + " flags for a head of " +
                             std::to_string(scalp_.triangleCount()) + " triangles");
  Status s = scalp_.setScalpMask(scalp, triangleCount);
  if (s.ok()) s = headDistance_.setScalpMask(scalp, triangleCount);
  if (!s.ok()) return s;
  // Roots are sampled again over the new scalp at the next grow.
  rootsValid_ = false;
  roots_.clear();
  rootIds_.clear();
  subset_ = false;
  return Status::Ok();
}

DetailParams detailFromArray(const double* d) {
  DetailParams p;
  p.curl.radius = d[0];
  p.curl.frequency = d[1];
  p.curl.start = d[2];
  p.curl.randomOffset = d[3];
  p.clump.factor = d[4];
  p.clump.shape = d[5];
  p.clump.tipSpread = d[6];
  p.clump.guideDistance = d[7];
  p.frizz.distance = d[8];
  p.frizz.shape = d[9];
  p.lengthJitter = d[10];
  return p;
}

Status HairEngine::setDetail(std::vector<DetailParams> groups, std::vector<int32_t> curveGroup) {
  for (int32_t g : curveGroup)
    if (g < 0 || size_t(g) >= std::max<size_t>(groups.size(), 1))
      return Status::Error(StatusCode::InvalidInput, "detail: a curve's group is out of range");
  detail_ = std::move(groups);
  curveGroup_ = std::move(curveGroup);
  return Status::Ok();
}

Status HairEngine::setSettings(const double* values, size_t count) {
  if (count != kEngineSettingCount || (count > 0 && !values))
    return Status::Error(StatusCode::InvalidInput,
                         "settings: " + std::to_string(kEngineSettingCount) + " numbers, not " +
                             std::to_string(count));
  for (size_t k = 0; k < count; ++k)
    if (!std::isfinite(values[k]))
      return Status::Error(StatusCode::NonFinite,
                           "settings: value " + std::to_string(k) + " is not finite");
  setSections(values[kSettingSections] != 0);
  setBust(values[kSettingBust] != 0);
  const Status f = setFinish(values[kSettingFinish] != 0);
  if (!f.ok()) return f;
  return setFall(values[kSettingFall] != 0);
}

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
  // where each tie meets the head: the head point nearest its first circle's centre
  for (GatheredTail& t : nextTails) {
    Eigen::Vector3f x = t.shape == TailShape::Bun ? t.bunCentre : t.spine.front();
    if (headDistance_.built())
      for (int it = 0; it < 3; ++it) {
        float dir[3];
        const float d = headDistance_.outward(x.data(), dir);
        x -= d * Eigen::Vector3f(dir[0], dir[1], dir[2]);
      }
    t.anchor = x;
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
    if (fv.kinds && fv.curveStart && fv.points)
      for (size_t c = 0; c < fv.curveCount; ++c) {
        const CurveKindDef* kind = curveKind(fv.kinds[c]);
        if (!kind || !kind->reach) continue;
        const size_t a = fv.curveStart[c], b = fv.curveStart[c + 1];
        if (b <= a || b > fv.pointCount) continue;
        rc.push_back({fv.points + 3 * a, b - a, fv.extend && fv.extend[c] != 0,
                      fv.offScalp ? fv.offScalp + a : nullptr});
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
      combineReach(lattice, parts, reach_);
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

Status HairEngine::solve() {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "solve before setGrid");
  if (priorSet_ && constraints_.empty()) return zeroField();
  Field T;
  Status s = solver_->solve(T);
  if (!s.ok()) return s;
  field_ = std::move(T);
  fieldF_ = toFloatField(field_);
  fieldValid_ = true;
  return Status::Ok();
}

Status HairEngine::iterate(int maxIterations, double tolerance, IterateProgress& progress) {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "iterate before setGrid");
  if (priorSet_ && constraints_.empty()) {
    progress = IterateProgress();
    progress.converged = true;
    return zeroField();
  }
  Field T;
  Status s = solver_->iterate(maxIterations, tolerance, T, progress);
  if (!s.ok() && s.code != StatusCode::NotConverged) return s;
  field_ = std::move(T);
  fieldF_ = toFloatField(field_);
  fieldValid_ = true;
  return Status::Ok();
}

// No curves: a bald head, with or without the prior (the prior alone would grow hair
// everywhere).
Status HairEngine::zeroField() {
  field_ = Field::Zero(grid_.size(), 3);
  fieldF_.assign(size_t(grid_.size()) * 3, 0.f);
  fieldValid_ = true;
  return Status::Ok();
}

Status HairEngine::grow(const RootParams& rp, const GrowthParams& gp) {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "grow before setGrid");
  if (!fieldValid_) return Status::Error(StatusCode::NotReady, "grow: curves changed, solve first");
  if (rp.maxStrands < 0) return Status::Error(StatusCode::InvalidInput, "maxStrands < 0");
  const auto t0 = Clock::now();
  // The full root set is cached (sampling casts a ray per root); a cap takes an even stride of
  // it, so previews (capped) and full growth share one sampling.
  const bool same = rootsValid_ && rootKey_.thetaStepDeg == rp.thetaStepDeg &&
                    rootKey_.phiStepDeg == rp.phiStepDeg && rootKey_.jitter == rp.jitter &&
                    rootKey_.seed == rp.seed;
  if (!same) {
    rootsValid_ = false;
    RootParams all = rp;
    all.maxStrands = 0;
    Status s = scalp_.sample(all, roots_, &rootIds_);
    if (!s.ok()) return s;
    rootKey_ = all;
    rootsValid_ = true;
  }
  // the roots grown: all, less lone ones (finished edges: judged on the full set, so a cap
  // keeps its count), then an even stride of those under a cap
  const size_t total = roots_.size();
  if (!same || keptFinish_ != finish_ || kept_.empty() != (total == 0)) {
    kept_.resize(total);
    for (size_t k = 0; k < total; ++k) kept_[k] = uint32_t(k);
    if (finish_ && total > 0) {
      // the sampling's spacing: a θ step at the roots' mean distance from the centre
      double r = 0;
      for (const Eigen::Vector3f& p : roots_) r += (p.cast<double>() - centre_).norm();
      const double spacing = r / double(total) * rootKey_.thetaStepDeg * 3.14159265358979 / 180;
      dropLoneRoots(roots_, kept_, float(kLoneReach * spacing));
    }
    keptFinish_ = finish_;
  }
  const std::vector<uint32_t>& kept = kept_;
  const bool capped = rp.maxStrands > 0 && kept.size() > size_t(rp.maxStrands);
  const size_t m = capped ? size_t(rp.maxStrands) : kept.size();
  subsetIndex_.resize(m);
  for (size_t k = 0; k < m; ++k) subsetIndex_[k] = kept[k * kept.size() / m];
  subset_ = m != total;
  if (subset_) {
    subsetRoots_.resize(subsetIndex_.size());
    subsetRootIds_.resize(subsetIndex_.size());
    for (size_t k = 0; k < subsetIndex_.size(); ++k) {
      subsetRoots_[k] = roots_[subsetIndex_[k]];
      subsetRootIds_[k] = rootIds_[subsetIndex_[k]];
    }
  }
  // The strand buffers for every root at maxSegments must fit: the point buffer (12 bytes a
  // point) is grown by doubling up to that bound, so it and its previous copy may both be live.
  const double worstPoints =
      double(roots().size()) * (double(std::max(gp.maxSegments, 0)) + 1) + 3 * 4096;
  const double needs = 2 * 12 * worstPoints + 4 * double(roots().size() + 1);
  const int64_t cap = availableMemoryBytes() + int64_t(strands_.points.capacity() * sizeof(float));
  Status fits = checkMemory("growth (" + std::to_string(roots().size()) + " strands of up to " +
                                std::to_string(gp.maxSegments) + " segments)",
                            needs, cap);
  if (!fits.ok()) {
    strands_ = Strands{};
    strands_.strandStart.assign(1, 0);
    return fits;
  }
  const HeadDistance* head = headDistance_.built() ? &headDistance_ : nullptr;
  const CurveReach* reach = fall_ && !reach_.empty() ? &reach_ : nullptr;
  Status s = growStrands(grid_, fieldF_, roots(), gp, strands_, size_t(24) << 20, head, reach,
                         head ? bodyCollider() : BodyCollider());
  const std::vector<Eigen::Vector3f>& R = roots();
  const size_t n = R.size();
  // a strand's seed key: its index in the full root set (previews take a stride of it)
  std::vector<uint32_t> key(n);
  for (size_t k = 0; k < n; ++k) key[k] = subset_ ? subsetIndex_[k] : uint32_t(k);
  strandTailCurve_.assign(n, -1);
  strandSection_.clear();
  ScalpSections sections;
  if (sections_) {
    sections.build(roots_, centre_.cast<float>(), partings_);
    strandSection_.resize(n);
    for (size_t st = 0; st < n; ++st) {
      // with finished edges, hair at a parting belongs to the side it is combed to
      const int at =
          finish_ && s.ok()
              ? sections.combedSection(
                    strands_.points.data() + 3 * size_t(strands_.strandStart[st]),
                    strands_.strandStart[st + 1] - strands_.strandStart[st], kCombedReach)
              : sections.section(R[st]);
      strandSection_[st] = uint8_t(std::min(at, 255));
    }
  }
  if (s.ok() && !tails_.empty()) {
    // laid strands keep to the 255 points engines take (detail's cap too)
    // whole-section ties (with sections on): each strand goes to the nearest such tie in its
    // root's section; without sections every tie takes the hair that reaches it
    std::vector<GatheredTail> tails = tails_;
    SectionGather sg;
    bool bySection = false;
    for (GatheredTail& t : tails) {
      t.section = t.section && sections_;
      bySection |= t.section;
    }
    if (bySection) {
      std::vector<int> tieSection(tails.size(), -1);
      for (size_t k = 0; k < tails.size(); ++k)
        if (tails[k].section) tieSection[k] = sections.section(tails[k].anchor);
      sg.assigned.assign(n, -1);
      for (size_t st = 0; st < n; ++st) {
        const int here = strandSection_[st];
        float best = std::numeric_limits<float>::infinity();
        for (size_t k = 0; k < tails.size(); ++k) {
          if (tieSection[k] != here) continue;
          const float d = (R[st] - tails[k].anchor).squaredNorm();
          if (d < best) {
            best = d;
            sg.assigned[st] = int32_t(k);
          }
        }
      }
      sg.head = head;
      sg.centre = centre_.cast<float>();
      sg.margin = float(gp.margin);
    }
    const TailStats ts =
        gatherTails(tails, R, key, rp.seed, float(gp.stepFraction * grid_.step),
                    std::min<size_t>(size_t(std::max(gp.maxSegments, 1)) + 1, 255), strands_,
                    float(std::min(gp.maxLength, 1e6)), bySection ? &sg : nullptr);
    for (size_t i = 0; i < ts.strands.size(); ++i)
      strandTailCurve_[ts.strands[i]] = tailCurves_[ts.tail[i]];
    // growth kept the rest outside already
    if (head && ts.captured > 0) {
      keepOutsideHead(*head, float(gp.margin), strands_, &ts.strands);
      keepOutsideBody(float(gp.margin), &ts.strands);
    }
  }
  bool anyDetail = false;
  for (const DetailParams& d : detail_) anyDetail |= d.any();
  std::vector<float> endSpread;
  if (finish_) {
    endSpread.assign(n, kEndSpread);
    for (size_t st = 0; st < n; ++st)
      if (strandTailCurve_[st] >= 0) endSpread[st] = 0;
  }
  if (s.ok() && (anyDetail || finish_)) {
    std::vector<uint32_t> groupOf(n, 0);
    bool perCurve = false;
    for (int32_t g : curveGroup_) perCurve |= g != 0;
    if (anyDetail && perCurve && !curvePoints_.empty())
      for (size_t k = 0; k < n; ++k) {
        float best = std::numeric_limits<float>::infinity();
        int32_t curve = -1;
        for (size_t q = 0; q < curvePoints_.size(); ++q) {
          const float d2 = (curvePoints_[q] - R[k]).squaredNorm();
          if (d2 < best) {
            best = d2;
            curve = curvePointCurve_[q];
          }
        }
        if (curve >= 0 && size_t(curve) < curveGroup_.size())
          groupOf[k] = uint32_t(curveGroup_[curve]);
      }
    s = applyDetail(detail_.empty() ? std::vector<DetailParams>{DetailParams{}} : detail_, groupOf,
                    key, rp.seed, strands_, 255, finish_ ? &endSpread : nullptr, finish_);
    // cutting ends back moves no point: only detail needs keeping outside again
    if (head && anyDetail) {
      keepOutsideHead(*head, float(gp.margin), strands_);
      keepOutsideBody(float(gp.margin), nullptr);
    }
  }
  growMs_ = msSince(t0);
  return s;
}

Status HairEngine::scalpAvoidance(const ScalpAvoidanceParams& params, ConstraintSet& out,
                                  ScalpAvoidanceStats* stats) const {
  out.clear();
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "scalp avoidance before setGrid");
  if (!fieldValid_)
    return Status::Error(StatusCode::NotReady, "scalp avoidance: curves changed, solve first");
  if (!scalp_.built())
    return Status::Error(StatusCode::NotReady, "scalp avoidance before setScalp");
  HeadMeshView m{scalp_.positions().data(), scalp_.positions().size() / 3, scalp_.indices().data(),
                 scalp_.triangleCount(), scalp_.scalpMask().data()};
  return scalpAvoidanceConstraints(grid_, field_, m, params, out, stats);
}

SolveStats HairEngine::stats() const {
  if (!solver_) return SolveStats{};
  return solver_->stats();
}

}  // namespace hairsketch
