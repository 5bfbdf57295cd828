// The solver side of a session as one stateful object (used by the wasm binding):
//   grid + solver by name -> scalp mesh -> curves -> constraints -> solve -> roots -> strands.
// Roots are cached per (theta step, phi step, jitter, seed) and scalp mesh and mask.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "constraints.hpp"
#include "curve_set.hpp"
#include "engine_settings.hpp"
#include "field_solver.hpp"
#include "gathered_tail.hpp"
#include "grid.hpp"
#include "hair_fall.hpp"
#include "head_distance.hpp"
#include "scalp_avoidance.hpp"
#include "scalp_roots.hpp"
#include "scalp_sections.hpp"
#include "status.hpp"
#include "strand_detail.hpp"
#include "strand_growth.hpp"

namespace hairsketch {

// hairArrays.ts DetailArrays: the numbers of one detail group, in this order.
constexpr int kDetailStride = 14;
DetailParams detailFromArray(const double* d);  // d[0 .. kDetailStride)

class HairEngine {
 public:
  // New grid and solver by name (makeFieldSolver: cg, fast, exact, auto). Clears curves and field.
  Status setGrid(const Grid& grid, double omega, const std::string& solverName);
  // The head mesh (hairArrays.ts ScalpMesh): builds the root sampler and the head's distance grid
  // (checked against the memory cap first). A refused head leaves the engine without one.
  Status setScalp(const float* positions, size_t vertexCount, const uint32_t* indices,
                  size_t triangleCount, const uint8_t* scalp, const Eigen::Vector3d& center);
  // A new scalp mask for the same head: scalp[triangle] != 0 on the scalp, triangleCount = the
  // head's. Roots are sampled again over it at the next grow; the head's distance grid, the
  // grid, field and constraints stay. A wrong count (InvalidInput) or no head (NotReady) is
  // refused and the old mask stays in force.
  Status setScalpMask(const uint8_t* scalp, size_t triangleCount);
  // The body under the head (a bust: neck, shoulders, chest, back), a closed triangle mesh
  // apart from the head's (counter-clockwise = outward): builds the body's distance grid
  // (checked against the memory cap first; cell kBodyCell, kBodyBand cells of exact distance).
  // With the bust setting on, hair slides over it (BodyCollider in strand_growth.hpp) and every
  // strand point is kept out of it. 0 triangles clears it. Non-finite positions (NonFinite), an
  // index out of range or missing arrays (InvalidInput) are refused and leave no body. Changes
  // no field: it takes effect at the next grow.
  Status setBody(const float* positions, size_t vertexCount, const uint32_t* indices,
                 size_t triangleCount);
  bool hasBody() const { return bodyDistance_.built(); }
  const HeadDistance& bodyDistance() const { return bodyDistance_; }
  static constexpr double kBodyCell = 0.04;  // world units (4 mm; the head's is 3 mm)
  static constexpr int kBodyBand = 4;        // cells (1.6 cm)
  // Bust on: hair rests on the body (setBody), and the head mesh below kHeadBodyBelowY is body
  // too, not face (with no body set, a loaded head that has its own shoulders is its own body;
  // with one, the head's neck where it meets the body's does not stop hair). Off (the
  // default): growth is what it was before bodies, bit for bit, body or not. Takes effect at the
  // next grow.
  void setBust(bool on) { bust_ = on; }
  bool bust() const { return bust_; }
  // Natural fall (hair_fall.hpp): the prior towards hanging hair joins the field energy (once
  // there is a grid and a head), curves no longer append the fading extension (the curves' reach
  // ends hair instead; "extend" lets a curve's hair grow on), and growth stops hair where its
  // curve ends and lets a curve take hair over the face. Off (the default) is the paper's method
  // exactly. Takes effect for the curves of the next setCurves.
  Status setFall(bool on);
  // The session's settings (engine_settings.hpp: kEngineSettingCount numbers, finite), each
  // handed to what reads it (fall: setFall). A wrong count or a non-finite value is refused and
  // nothing changes.
  Status setSettings(const double* values, size_t count);
  bool fall() const { return fall_; }
  // Sections (scalp_sections.hpp): a tie whose parameters ask for it gathers every strand rooted
  // in its scalp section (gathered_tail.hpp "Whole sections"); off (the default), every tie
  // takes the hair that reaches it, as sessions made before sections did. Takes effect at the
  // next grow.
  void setSections(bool on) { sections_ = on; }
  bool sections() const { return sections_; }
  // Ties from any hand (docs/braids-buns.md "Ties"): partings closing near the edge, a tie's
  // hair as long as its tail needs, tapered tails, a coiled bun. Off: the ties as before.
  void setTies(bool on) { ties_ = on; }
  bool ties() const { return ties_; }
  // A soft hairline (soft_hairline.hpp): over the scalp's last centimetre the roots thin out and
  // some grow short hairs. Off (the default): every root grows, as in sessions made before it.
  // Takes effect at the next grow.
  void setHairline(bool on) { hairline_ = on; }
  bool hairline() const { return hairline_; }
  // Curl volume (strand_detail.hpp "Curl volume"): curly hair spreads out towards its ends by a
  // share of its curl's shrinkage (kCurlSpread); hair a tie lays keeps its shape. Off (the
  // default): curls wind round the hair's path, as in sessions made before it.
  void setCurlVolume(bool on) { curlVolume_ = on; }
  bool curlVolume() const { return curlVolume_; }
  // Coily hair stands out from the head (strand_detail.hpp "Coil volume"; with curl volume).
  void setCoilVolume(bool on) { coilVolume_ = on; }
  bool coilVolume() const { return coilVolume_; }
  // Round plaits (gathered_tail_shapes.cpp plaitStretch): a braid's three sections keep a round
  // section across their own path where they run aslant. Off: as in sessions made before.
  void setRoundPlaits(bool on) { roundPlaits_ = on; }
  bool roundPlaits() const { return roundPlaits_; }
  // Tie volume (gathered_tail.hpp kTieVolume): with ties from any hand, a whole section's round
  // tail and bun hold its hair kTieVolume times as wide. Off: as in sessions made before.
  void setTieVolume(bool on) { tieVolume_ = on; }
  bool tieVolume() const { return tieVolume_; }
  // Compact bun (gathered_tail.hpp knotShape): with ties from any hand, a bun's rope wraps its
  // own base in a round knot, every strand as long as the rope. Off: as in sessions made before.
  void setCompactBun(bool on) { compactBun_ = on; }
  bool compactBun() const { return compactBun_; }
  // Clump all (strand_detail.hpp applyDetail's clumpAll): a strand whose path parts from its
  // nearest clump guide's is clumped to the next nearest whose path stays with it. Off: as in
  // sessions made before (such strands are not clumped).
  void setClumpAll(bool on) { clumpAll_ = on; }
  bool clumpAll() const { return clumpAll_; }
  // Face clear (hair_fall.hpp ShapeRules::faceClear): with the shape rules, hair a stroke governs
  // parts round the face too unless it follows a stroke over the face. Off: as in sessions made
  // before (governed hair went where the strokes' blend took it, across the eyes in the air).
  void setFaceClear(bool on) { faceClear_ = on; }
  bool faceClear() const { return faceClear_; }
  // Locks (strand_detail.hpp applyDetail's locks): detail that bends strands keeps each within
  // the length it grew, and a tie's tail takes its clumps without their tip spread (it drew
  // strands out across the band).
  void setLocks(bool on) { locks_ = on; }
  bool locks() const { return locks_; }
  // Finished edges: every strand not laid into a tie ends up to kEndSpread short of where it
  // grew to (strand_detail.hpp applyDetail's endSpread), seeded per strand; lone roots are not
  // grown (scalp_roots.hpp dropLoneRoots); with fall the prior opens the face (hair_fall.hpp);
  // with sections a strand belongs to the section it is combed into (its point kCombedReach
  // along it: ScalpSections::combedSection), so hair at a parting that sets off across it is
  // gathered with the other side instead of flying loose from the line.
  Status setFinish(bool on);
  bool finish() const { return finish_; }
  // The shape rules (hair_fall.hpp ShapeRules: with fall, a stroke's reach of a few centimetres,
  // hair laid on the head with `volume` of lift at the roots, length from the strokes around).
  // Off (the default): the hair of sessions made before them, bit for bit. The reach takes
  // effect at once (the prior's weight), the rest at the next grow.
  Status setShape(bool on, double volume);
  const ShapeRules& shape() const { return shape_; }
  static constexpr float kCombedReach = 0.15f;  // world units (1.5 cm)
  // Curves -> constraints -> solver (the solver diffs against its previous set).
  Status setCurves(const CurveSetView& curves);
  Status solve();
  // Progressive solve (FieldSolver::iterate): the field becomes the current iterate.
  Status iterate(int maxIterations, double tolerance, IterateProgress& progress);
  // The next iterate() starts from zero (FieldSolver::forgetWarmStart); false for a direct
  // solver (nothing to forget) or before setGrid.
  bool forgetWarmStart() { return hasGrid_ && solver_ && solver_->forgetWarmStart(); }
  // FieldSolver::deferPreconditionerUpdate for the next setCurves (a first look that
  // forgetWarmStart follows).
  void deferPreconditionerUpdate() {
    if (solver_) solver_->deferPreconditionerUpdate();
  }
  // Detail groups (group 0 the session's) and each curve's group (curves of the next setCurves,
  // in order; an empty list = every curve uses group 0). Validated by applyDetail at growth.
  Status setDetail(std::vector<DetailParams> groups, std::vector<int32_t> curveGroup);
  // Samples (or reuses) roots, grows strands in the last solved field, applies the detail of the
  // curve nearest each root and keeps every point outside the head.
  Status grow(const RootParams& roots, const GrowthParams& growth);
  // Scalp avoidance (S4.7) on the last solved field and the scalp mesh: the constraints to store
  // as the CurveSet's extra constraints. Does not change the engine's constraints.
  Status scalpAvoidance(const ScalpAvoidanceParams& params, ConstraintSet& out,
                        ScalpAvoidanceStats* stats = nullptr) const;

  const ConstraintSet& constraints() const { return constraints_; }
  // ConstraintColour of each constraint (same order), for display.
  const std::vector<uint8_t>& constraintColours() const { return colours_; }
  const Field& field() const { return field_; }
  const Strands& strands() const { return strands_; }
  // Per strand of the last growth: its root's sample index (ScalpSampler::sample), which names
  // the strand across edits that keep the growth settings and the head.
  const std::vector<uint32_t>& strandRootIds() const { return subset_ ? subsetRootIds_ : rootIds_; }
  // Per strand of the last growth: the curve whose gathered tail (ponytail, braid, bun) laid it,
  // or -1.
  const std::vector<int32_t>& strandTailCurves() const { return strandTailCurve_; }
  // Per strand of the last growth with sections on: the scalp section its root is in
  // (scalp_sections.hpp; at most 255), for showing the sections; empty with sections off.
  const std::vector<uint8_t>& strandSections() const { return strandSection_; }
  // Per tie of the last growth that laid hair (ponytail, braid, bun), 8 numbers: its curve's
  // index, the centre and unit axis of its tail's first circle, where the growth gathers its
  // hair (a braid's first stroke point off the scalp), and the hair's radius there as laid (0:
  // not one circle, a braid or a bun): where its band goes (web/model/tieBands.ts).
  const std::vector<float>& tieFrames() const { return tieFrames_; }
  // The roots of the last growth (the cached set, or its capped stride).
  const std::vector<Eigen::Vector3f>& roots() const { return subset_ ? subsetRoots_ : roots_; }
  SolveStats stats() const;
  double growMs() const { return growMs_; }
  // The head's distance grid (built by setScalp): growth keeps hair outside it.
  const HeadDistance& headDistance() const { return headDistance_; }
  // What the last setScalp took: milliseconds to build the root sampler and the distance grid,
  // and the bytes the head keeps (sampler + distance grid).
  struct HeadStats {
    double samplerMs = 0, distanceMs = 0;
    size_t bytes = 0, distanceCells = 0;
  };
  HeadStats headStats() const {
    return {samplerMs_, distanceMs_, scalp_.bytes() + headDistance_.bytes(), headDistance_.cells()};
  }
  const Grid& grid() const { return grid_; }

 private:
  Grid grid_;
  bool hasGrid_ = false;
  std::unique_ptr<FieldSolver> solver_;
  ScalpSampler scalp_;  // also keeps the head mesh and its mask (scalp avoidance reads them)
  HeadDistance headDistance_;
  HeadDistance bodyDistance_;  // the body's (setBody), no scalp flags
  bool bust_ = false;
  double samplerMs_ = 0, distanceMs_ = 0;
  ConstraintSet constraints_;
  std::vector<uint8_t> colours_;
  Field field_;
  bool fieldValid_ = false;
  std::vector<float> fieldF_;
  bool rootsValid_ = false;
  RootParams rootKey_;
  std::vector<Eigen::Vector3f> roots_;  // all roots of rootKey_
  // the roots grown when not all of roots_: an even stride under a cap, less lone roots with
  // finished edges (scalp_roots.hpp dropLoneRoots); subsetIndex_ their indices in roots_
  std::vector<Eigen::Vector3f> subsetRoots_;
  std::vector<uint32_t> subsetIndex_;
  std::vector<uint32_t> kept_;  // roots_ less lone ones (all without finished edges), cached
  bool keptFinish_ = false, keptHairline_ = false;
  // with a soft hairline: per root of roots_, the longest its hair may grow (infinity: full)
  std::vector<float> rootCap_;
  // the lower hairline (nape_line.hpp) of the current scalp and centre, while napeValid_
  std::vector<float> napeLine_;
  bool napeValid_ = false;
  std::vector<float> growCap_;                     // the same for the roots grown (roots())
  std::vector<uint32_t> rootIds_, subsetRootIds_;  // sample indices of roots_, subsetRoots_
  std::vector<int32_t> strandTailCurve_;
  std::vector<uint8_t> strandSection_;
  std::vector<float> tieFrames_;
  bool subset_ = false;
  Strands strands_;
  double growMs_ = 0;
  std::vector<DetailParams> detail_;
  std::vector<int32_t> curveGroup_;
  // Curve points subsampled for the nearest-curve lookup, with their curve's index.
  std::vector<Eigen::Vector3f> curvePoints_;
  std::vector<int32_t> curvePointCurve_;
  // Natural fall: the setting, whether the solver holds a prior, the head's centre (the prior's
  // vertical axis) and the reach of the last setCurves' curves.
  bool fall_ = false;
  bool priorSet_ = false;
  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();
  CurveReach reach_;
  std::vector<std::pair<uint64_t, CurveFootprint>> footprints_;  // by a hash of each curve
  std::vector<GatheredTail> tails_;  // the gathered ponytails of the last setCurves (with fall)
  std::vector<int32_t> tailCurves_;  // the curve of each of tails_
  bool sections_ = false;
  bool ties_ = false;
  bool hairline_ = false;
  bool curlVolume_ = false;
  bool coilVolume_ = false;
  bool roundPlaits_ = false;
  bool tieVolume_ = false;
  bool compactBun_ = false;
  bool clumpAll_ = false;
  bool faceClear_ = false;
  bool locks_ = false;
  bool finish_ = false;
  ShapeRules shape_;
  std::vector<std::vector<Eigen::Vector3f>> partings_;  // the dividing curves of the last setCurves
  Status applyPrior();
  // What hair rests on in growth (bust on), and keepOutsideHead's passes for the body.
  BodyCollider bodyCollider() const;
  void keepOutsideBody(float margin, const std::vector<uint32_t>* only);
  Status zeroField();
};

}  // namespace hairsketch
