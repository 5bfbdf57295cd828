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
    Status s = solver_->setPrior(fallWeight(grid_.step, shape_.on ? kShapeReach : kFallReach),
                                 fallDirections(grid_, headDistance_, centre_, finish_, shape_.on));
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

Status HairEngine::setShape(bool on, double volume) {
  if (!std::isfinite(volume) || volume < 0 || volume > 0.3)
    return Status::Error(StatusCode::InvalidInput, "shape: volume must be within 0..0.3");
  shape_.volume = float(volume);
  if (on == shape_.on) return Status::Ok();
  shape_.on = on;
  return fall_ ? applyPrior() : Status::Ok();  // the prior's reach
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
  napeValid_ = false;
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
  napeValid_ = false;
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
  p.flyaway.share = d[10];
  p.flyaway.distance = d[11];
  p.flyaway.start = d[12];
  p.lengthJitter = d[13];
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
  if (values[kSettingVolume] < 0 || values[kSettingVolume] > 0.3)
    return Status::Error(StatusCode::InvalidInput, "settings: volume must be within 0..0.3");
  setSections(values[kSettingSections] != 0);
  setBust(values[kSettingBust] != 0);
  setTies(values[kSettingTies] != 0);
  setHairline(values[kSettingHairline] != 0);
  setCurlVolume(values[kSettingCurlVolume] != 0);
  setCoilVolume(values[kSettingCoilVolume] != 0);
  setRoundPlaits(values[kSettingRoundPlaits] != 0);
  setTieVolume(values[kSettingTieVolume] != 0);
  setCompactBun(values[kSettingCompactBun] != 0);
  setClumpAll(values[kSettingClumpAll] != 0);
  setFaceClear(values[kSettingFaceClear] != 0);
  setLocks(values[kSettingLocks] != 0);
  const Status sh = setShape(values[kSettingShape] != 0, values[kSettingVolume]);
  if (!sh.ok()) return sh;
  const Status f = setFinish(values[kSettingFinish] != 0);
  if (!f.ok()) return f;
  return setFall(values[kSettingFall] != 0);
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