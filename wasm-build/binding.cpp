// The wasm boundary: plain extern "C" functions over the C++ core. This file only converts
// (structs of pointers + counts in, Status -> status code + message out); all logic is in
// solver-cpp/src. Results stay owned by the handle until its next call; JS copies them out.
//
// Every struct below mirrors one layout declared in web/solver/wasmStructs.ts (the name is given
// on each); its size is asserted here and every offset is checked by wasmEngine.ts at load
// through hs_struct_layout. Pointers are wasm32 byte offsets (4 bytes).
// Every call returns an HsStatus (wasmStructs.ts SOLVER_STATUS): 0, or the kind of failure, with
// the message in hs_last_error().
#include <emscripten/emscripten.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "curve_set.hpp"
#include "field_solver.hpp"
#include "hair_engine.hpp"
#include "hair_sim.hpp"
#include "parallel.hpp"
#include "strand_motion.hpp"

using namespace hairsketch;

// wasmStructs.ts SOLVER_STATUS.
enum HsStatus : int32_t {
  HS_OK = 0,
  HS_INVALID_INPUT = 1,
  HS_NON_FINITE = 2,
  HS_OVER_MEMORY_CAP = 3,
  HS_NOT_READY = 4,
  HS_INTERNAL = 5,
};

// wasmStructs.ts GRID_INPUT.
struct HsGridInput {
  double originX, originY, originZ, step, omega;
  int32_t nx, ny, nz;
  const char* solver;
};
static_assert(sizeof(HsGridInput) == 56, "wasmStructs.ts GRID_INPUT");

// wasmStructs.ts SCALP_INPUT.
struct HsScalpInput {
  double centerX, centerY, centerZ;
  const float* positions;
  uint32_t vertexCount;
  const uint32_t* indices;
  uint32_t triangleCount;
  const uint8_t* scalp;
};
static_assert(sizeof(HsScalpInput) == 48, "wasmStructs.ts SCALP_INPUT");

// wasmStructs.ts CURVE_SET_HEADER (the CurveSet, see curve_set.hpp CurveSetView).
struct HsCurveSetHeader {
  const double* points;
  uint32_t pointCount;
  const uint32_t* curveStart;
  uint32_t curveCount;
  const uint8_t* kinds;
  const uint8_t* extend;
  const double* params;
  uint32_t paramCount;
  const uint32_t* paramStart;
  const int32_t* extraIndex;
  const double* extraTarget;
  uint32_t extraCount;
};
static_assert(sizeof(HsCurveSetHeader) == 48, "wasmStructs.ts CURVE_SET_HEADER");

// wasmStructs.ts GROWTH_INPUT.
struct HsGrowthInput {
  double thetaStepDeg, phiStepDeg, jitter, seed, stepFraction, minMagnitude, maxLength;
  int32_t maxSegments, maxStrands;
};
static_assert(sizeof(HsGrowthInput) == 64, "wasmStructs.ts GROWTH_INPUT");

// wasmStructs.ts AVOID_INPUT.
struct HsAvoidInput {
  double band, magnitude, minField;
  int32_t wholeHead, insideToo;
};
static_assert(sizeof(HsAvoidInput) == 32, "wasmStructs.ts AVOID_INPUT");

// wasmStructs.ts CONSTRAINT_LIST.
struct HsConstraintList {
  const int32_t* index;
  const double* target;
  uint32_t count;
};
static_assert(sizeof(HsConstraintList) == 12, "wasmStructs.ts CONSTRAINT_LIST");

// wasmStructs.ts ITERATE_PROGRESS.
struct HsIterateProgress {
  double errorEstimate;
  int32_t iterations, converged;
};
static_assert(sizeof(HsIterateProgress) == 16, "wasmStructs.ts ITERATE_PROGRESS");

// wasmStructs.ts STATS_OUTPUT.
struct HsStats {
  double residual, setupMs, solveMs, growMs;
  int32_t iterations, added, removed, changed, constraints;
  char method[32];
};
static_assert(sizeof(HsStats) == 88, "wasmStructs.ts STATS_OUTPUT");

namespace {

std::string gLastError;

HsStatus kindOf(StatusCode c) {
  switch (c) {
    case StatusCode::Ok:
      return HS_OK;
    case StatusCode::InvalidInput:
      return HS_INVALID_INPUT;
    case StatusCode::NonFinite:
      return HS_NON_FINITE;
    case StatusCode::OverMemoryCap:
      return HS_OVER_MEMORY_CAP;
    case StatusCode::NotReady:
      return HS_NOT_READY;
    default:
      return HS_INTERNAL;
  }
}

int32_t report(const Status& s) {
  if (s.ok()) return HS_OK;
  gLastError = s.message.empty() ? "error" : s.message;
  return kindOf(s.code);
}

int32_t fail(HsStatus kind, const char* msg) {
  gLastError = msg;
  return kind;
}

// The memory cap itself is each solver's estimate against what the module has left
// (memory_budget.hpp); here only the grid's shape.
Status makeGrid(const HsGridInput& in, Grid& g) {
  if (in.nx < 2 || in.ny < 2 || in.nz < 2)
    return Status::Error(StatusCode::InvalidInput, "grid dims must be >= 2");
  if (!std::isfinite(in.originX) || !std::isfinite(in.originY) || !std::isfinite(in.originZ) ||
      !std::isfinite(in.step))
    return Status::Error(StatusCode::NonFinite, "grid origin/step must be finite");
  if (!(in.step > 0)) return Status::Error(StatusCode::InvalidInput, "grid step must be > 0");
  g.nx = in.nx;
  g.ny = in.ny;
  g.nz = in.nz;
  g.origin = {in.originX, in.originY, in.originZ};
  g.step = in.step;
  return Status::Ok();
}

void writeStats(const SolveStats& s, int constraints, double growMs, HsStats* out) {
  out->residual = s.residual;
  out->setupMs = s.setupMs;
  out->solveMs = s.solveMs;
  out->growMs = growMs;
  out->iterations = s.iterations;
  out->added = s.added;
  out->removed = s.removed;
  out->changed = s.changed;
  out->constraints = constraints;
  std::memset(out->method, 0, sizeof out->method);
  std::strncpy(out->method, s.method.c_str(), sizeof out->method - 1);
}

struct EngineHandle {
  HairEngine engine;
  std::vector<int32_t> constraintIndex;
  std::vector<float> constraintTarget;
  std::vector<float> field;
  std::vector<int32_t> avoidIndex;  // scalp avoidance result
  std::vector<double> avoidTarget;
};

struct RawHandle {
  std::unique_ptr<FieldSolver> solver;
  std::string name;
  Grid grid;
  bool hasGrid = false;
  size_t constraints = 0;
  Field field;
};

#define HS_OFFSETS(T, ...) \
  { int32_t(sizeof(T)), __VA_ARGS__ }
#define HS_AT(T, f) int32_t(offsetof(T, f))

}  // namespace

extern "C" {

EMSCRIPTEN_KEEPALIVE const char* hs_last_error() { return gLastError.c_str(); }

// Layout of boundary struct `id` (wasmStructs.ts BOUNDARY_STRUCTS order): writes sizeof, then each
// member's offset in declaration order, into out (at most max entries); returns the number of
// entries, 0 for an unknown id.
EMSCRIPTEN_KEEPALIVE int32_t hs_struct_layout(int32_t id, int32_t* out, int32_t max) {
  const std::vector<std::vector<int32_t>> layouts = {
      HS_OFFSETS(HsGridInput, HS_AT(HsGridInput, originX), HS_AT(HsGridInput, originY),
                 HS_AT(HsGridInput, originZ), HS_AT(HsGridInput, step), HS_AT(HsGridInput, omega),
                 HS_AT(HsGridInput, nx), HS_AT(HsGridInput, ny), HS_AT(HsGridInput, nz),
                 HS_AT(HsGridInput, solver)),
      HS_OFFSETS(HsScalpInput, HS_AT(HsScalpInput, centerX), HS_AT(HsScalpInput, centerY),
                 HS_AT(HsScalpInput, centerZ), HS_AT(HsScalpInput, positions),
                 HS_AT(HsScalpInput, vertexCount), HS_AT(HsScalpInput, indices),
                 HS_AT(HsScalpInput, triangleCount), HS_AT(HsScalpInput, scalp)),
      HS_OFFSETS(HsCurveSetHeader, HS_AT(HsCurveSetHeader, points),
                 HS_AT(HsCurveSetHeader, pointCount), HS_AT(HsCurveSetHeader, curveStart),
                 HS_AT(HsCurveSetHeader, curveCount), HS_AT(HsCurveSetHeader, kinds),
                 HS_AT(HsCurveSetHeader, extend), HS_AT(HsCurveSetHeader, params),
                 HS_AT(HsCurveSetHeader, paramCount), HS_AT(HsCurveSetHeader, paramStart),
                 HS_AT(HsCurveSetHeader, extraIndex), HS_AT(HsCurveSetHeader, extraTarget),
                 HS_AT(HsCurveSetHeader, extraCount)),
      HS_OFFSETS(HsGrowthInput, HS_AT(HsGrowthInput, thetaStepDeg),
                 HS_AT(HsGrowthInput, phiStepDeg), HS_AT(HsGrowthInput, jitter),
                 HS_AT(HsGrowthInput, seed), HS_AT(HsGrowthInput, stepFraction),
                 HS_AT(HsGrowthInput, minMagnitude), HS_AT(HsGrowthInput, maxLength),
                 HS_AT(HsGrowthInput, maxSegments), HS_AT(HsGrowthInput, maxStrands)),
      HS_OFFSETS(HsAvoidInput, HS_AT(HsAvoidInput, band), HS_AT(HsAvoidInput, magnitude),
                 HS_AT(HsAvoidInput, minField), HS_AT(HsAvoidInput, wholeHead),
                 HS_AT(HsAvoidInput, insideToo)),
      HS_OFFSETS(HsConstraintList, HS_AT(HsConstraintList, index), HS_AT(HsConstraintList, target),
                 HS_AT(HsConstraintList, count)),
      HS_OFFSETS(HsIterateProgress, HS_AT(HsIterateProgress, errorEstimate),
                 HS_AT(HsIterateProgress, iterations), HS_AT(HsIterateProgress, converged)),
      HS_OFFSETS(HsStats, HS_AT(HsStats, residual), HS_AT(HsStats, setupMs),
                 HS_AT(HsStats, solveMs), HS_AT(HsStats, growMs), HS_AT(HsStats, iterations),
                 HS_AT(HsStats, added), HS_AT(HsStats, removed), HS_AT(HsStats, changed),
                 HS_AT(HsStats, constraints), HS_AT(HsStats, method)),
  };
  if (id < 0 || size_t(id) >= layouts.size() || !out) return 0;
  const std::vector<int32_t>& l = layouts[size_t(id)];
  const int32_t n = std::min(int32_t(l.size()), max);
  for (int32_t i = 0; i < n; ++i) out[i] = l[size_t(i)];
  return n;
}

// ---- engine -----------------------------------------------------------------------------

// Threads the solver's parallel loops use (the caller included); the threaded module's pthread
// pool must hold n - 1 workers. Returns the count in effect: always 1 in the single-threaded
// module.
EMSCRIPTEN_KEEPALIVE int32_t hs_set_threads(int32_t n) {
  return hairsketch::parallel::setThreadCount(n);
}

EMSCRIPTEN_KEEPALIVE EngineHandle* hs_engine_create() { return new EngineHandle(); }
EMSCRIPTEN_KEEPALIVE void hs_engine_destroy(EngineHandle* h) { delete h; }

EMSCRIPTEN_KEEPALIVE int32_t hs_engine_set_grid(EngineHandle* h, const HsGridInput* in) {
  if (!h || !in) return fail(HS_INVALID_INPUT, "set_grid: no engine or input");
  Grid g;
  Status s = makeGrid(*in, g);
  if (!s.ok()) return report(s);
  return report(h->engine.setGrid(g, in->omega, in->solver ? in->solver : ""));
}

EMSCRIPTEN_KEEPALIVE int32_t hs_engine_set_scalp(EngineHandle* h, const HsScalpInput* in) {
  if (!h || !in) return fail(HS_INVALID_INPUT, "set_scalp: no engine or input");
  return report(h->engine.setScalp(in->positions, in->vertexCount, in->indices, in->triangleCount,
                                   in->scalp,
                                   Eigen::Vector3d(in->centerX, in->centerY, in->centerZ)));
}

// A new scalp mask for the head of the last set_scalp: scalp[triangle] = 1 on the scalp,
// triangleCount = that head's (protocol.ts 'scalpMask'). A wrong count is refused and the old
// mask stays.
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_set_scalp_mask(EngineHandle* h, const uint8_t* scalp,
                                                      int32_t triangleCount) {
  if (!h || triangleCount < 0) return fail(HS_INVALID_INPUT, "set_scalp_mask: no engine or count");
  return report(h->engine.setScalpMask(scalp, size_t(triangleCount)));
}

// The body under the head (a bust: neck, shoulders, chest, back; HairEngine::setBody), a closed
// mesh apart from the head's: positions float[3 * vertexCount], indices uint32[3 * triangleCount]
// (counter-clockwise = outward). 0 triangles clears it. Hair rests on it with the bust setting
// on (engine_settings.hpp kSettingBust). A refused body leaves none.
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_set_body(EngineHandle* h, const float* positions,
                                                int32_t vertexCount, const uint32_t* indices,
                                                int32_t triangleCount) {
  if (!h || vertexCount < 0 || triangleCount < 0)
    return fail(HS_INVALID_INPUT, "set_body: no engine or a negative count");
  return report(h->engine.setBody(positions, size_t(vertexCount), indices, size_t(triangleCount)));
}

// What the last set_scalp took (for benchmarks): out[0] ms building the root sampler, out[1] ms
// building the head's distance grid, out[2] bytes the head keeps, out[3] cells of its distance
// grid, out[4] bytes in use in the module (memory_budget.hpp memoryInUseBytes).
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_head_stats(EngineHandle* h, double* out) {
  if (!h || !out) return fail(HS_INVALID_INPUT, "head_stats: no engine or output");
  const HairEngine::HeadStats s = h->engine.headStats();
  out[0] = s.samplerMs;
  out[1] = s.distanceMs;
  out[2] = double(s.bytes);
  out[3] = double(s.distanceCells);
  out[4] = double(memoryInUseBytes());
  return HS_OK;
}

// The session's settings (solver-cpp/src/engine_settings.hpp): count numbers at values.
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_set_settings(EngineHandle* h, const double* values,
                                                    int32_t count) {
  if (!h) return fail(HS_INVALID_INPUT, "set_settings: no engine");
  if (count < 0) return fail(HS_INVALID_INPUT, "set_settings: negative count");
  return report(h->engine.setSettings(values, size_t(count)));
}

// Natural fall on (1) or off (0) for the curves of the next set_curves (HairEngine::setFall).
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_set_fall(EngineHandle* h, int32_t on) {
  if (!h) return fail(HS_INVALID_INPUT, "set_fall: no engine");
  return report(h->engine.setFall(on != 0));
}

EMSCRIPTEN_KEEPALIVE int32_t hs_engine_set_curves(EngineHandle* h, const HsCurveSetHeader* in) {
  if (!h || !in) return fail(HS_INVALID_INPUT, "set_curves: no engine or input");
  CurveSetView v;
  v.points = in->points;
  v.pointCount = in->pointCount;
  v.curveStart = in->curveStart;
  v.curveCount = in->curveCount;
  v.kinds = in->kinds;
  v.extend = in->extend;
  v.params = in->params;
  v.paramCount = in->paramCount;
  v.paramStart = in->paramStart;
  v.extraIndex = in->extraIndex;
  v.extraTarget = in->extraTarget;
  v.extraCount = in->extraCount;
  return report(h->engine.setCurves(v));
}

// Scalp avoidance (S4.7) on the last solved field: fills the handle's avoidance arrays (read
// with hs_engine_avoid_index / hs_engine_avoid_target, hs_engine_avoid_count entries).
// hairArrays.ts DetailArrays: groupCount groups of kDetailStride doubles, one group per curve.
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_set_detail(EngineHandle* h, const double* groups,
                                                  int32_t groupCount, const int32_t* curveGroup,
                                                  int32_t curveCount) {
  if (!h || groupCount < 0 || curveCount < 0 || (groupCount > 0 && !groups) ||
      (curveCount > 0 && !curveGroup))
    return fail(HS_INVALID_INPUT, "set_detail: no engine or arrays");
  std::vector<DetailParams> g(static_cast<size_t>(groupCount));
  for (int32_t k = 0; k < groupCount; ++k) {
    const double* d = groups + size_t(k) * kDetailStride;
    for (int e = 0; e < kDetailStride; ++e)
      if (!std::isfinite(d[e])) return fail(HS_NON_FINITE, "set_detail: a number is not finite");
    g[k] = detailFromArray(d);
  }
  return report(
      h->engine.setDetail(std::move(g), std::vector<int32_t>(curveGroup, curveGroup + curveCount)));
}
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_scalp_avoidance(EngineHandle* h, const HsAvoidInput* in) {
  if (!h || !in) return fail(HS_INVALID_INPUT, "scalp_avoidance: no engine or input");
  ScalpAvoidanceParams p;
  p.band = in->band;
  p.magnitude = in->magnitude;
  p.wholeHead = in->wholeHead != 0;
  p.insideToo = in->insideToo != 0;
  p.minField = in->minField;
  ConstraintSet out;
  h->avoidIndex.clear();
  h->avoidTarget.clear();
  const int32_t rc = report(h->engine.scalpAvoidance(p, out));
  for (const Constraint& c : out) {
    h->avoidIndex.push_back(c.index);
    for (int a = 0; a < 3; ++a) h->avoidTarget.push_back(c.target[a]);
  }
  return rc;
}
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_avoid_count(EngineHandle* h) {
  return int32_t(h->avoidIndex.size());
}
EMSCRIPTEN_KEEPALIVE const int32_t* hs_engine_avoid_index(EngineHandle* h) {
  return h->avoidIndex.data();
}
EMSCRIPTEN_KEEPALIVE const double* hs_engine_avoid_target(EngineHandle* h) {
  return h->avoidTarget.data();
}

EMSCRIPTEN_KEEPALIVE int32_t hs_engine_solve(EngineHandle* h) {
  if (!h) return fail(HS_INVALID_INPUT, "solve: no engine");
  return report(h->engine.solve());
}

// Progressive solve; the progress is written to out.
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_iterate(EngineHandle* h, int32_t maxIterations,
                                               double tolerance, HsIterateProgress* out) {
  if (!h || !out) return fail(HS_INVALID_INPUT, "iterate: no engine or output");
  IterateProgress p;
  const int32_t rc = report(h->engine.iterate(maxIterations, tolerance, p));
  out->iterations = p.iterations;
  out->errorEstimate = p.errorEstimate;
  out->converged = p.converged ? 1 : 0;
  return rc;
}

// 1 when the next hs_engine_iterate starts from zero (an iterative solver forgot its warm
// start), 0 when there was nothing to forget (a direct solver, or no grid yet).
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_forget_warm_start(EngineHandle* h) {
  return h && h->engine.forgetWarmStart() ? 1 : 0;
}

// The next hs_engine_set_curves may leave the preconditioner's costliest update undone, for a
// first look that hs_engine_forget_warm_start follows (FieldSolver::deferPreconditionerUpdate).
EMSCRIPTEN_KEEPALIVE void hs_engine_defer_preconditioner_update(EngineHandle* h) {
  if (h) h->engine.deferPreconditionerUpdate();
}

EMSCRIPTEN_KEEPALIVE int32_t hs_engine_grow(EngineHandle* h, const HsGrowthInput* in) {
  if (!h || !in) return fail(HS_INVALID_INPUT, "grow: no engine or input");
  if (!std::isfinite(in->seed)) return fail(HS_NON_FINITE, "grow: seed is not finite");
  if (!(in->seed >= 0 && in->seed <= 4294967295.0) || std::floor(in->seed) != in->seed)
    return fail(HS_INVALID_INPUT, "grow: seed must be a uint32");
  RootParams rp;
  rp.thetaStepDeg = in->thetaStepDeg;
  rp.phiStepDeg = in->phiStepDeg;
  rp.jitter = in->jitter;
  rp.seed = uint32_t(in->seed);
  rp.maxStrands = in->maxStrands;
  GrowthParams gp;
  gp.stepFraction = in->stepFraction;
  gp.minMagnitude = in->minMagnitude;
  gp.maxLength = in->maxLength;
  gp.maxSegments = in->maxSegments;
  return report(h->engine.grow(rp, gp));
}

EMSCRIPTEN_KEEPALIVE const float* hs_engine_strand_points(EngineHandle* h) {
  return h->engine.strands().points.data();
}
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_strand_point_count(EngineHandle* h) {
  return int32_t(h->engine.strands().points.size() / 3);
}
EMSCRIPTEN_KEEPALIVE const uint32_t* hs_engine_strand_start(EngineHandle* h) {
  return h->engine.strands().strandStart.data();
}
// Entries of strandStart (strands + 1).
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_strand_start_count(EngineHandle* h) {
  return int32_t(h->engine.strands().strandStart.size());
}
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_root_count(EngineHandle* h) {
  return int32_t(h->engine.roots().size());
}
// Per strand of the last grow (hs_engine_strand_root_id_count entries, the strand count when
// the grow succeeded): its root's sample index, and the curve whose tail laid it (-1: none).
EMSCRIPTEN_KEEPALIVE const uint32_t* hs_engine_strand_root_ids(EngineHandle* h) {
  return h->engine.strandRootIds().data();
}
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_strand_root_id_count(EngineHandle* h) {
  return int32_t(h->engine.strandRootIds().size());
}
EMSCRIPTEN_KEEPALIVE const int32_t* hs_engine_strand_tail_curves(EngineHandle* h) {
  return h->engine.strandTailCurves().data();
}
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_strand_tail_curve_count(EngineHandle* h) {
  return int32_t(h->engine.strandTailCurves().size());
}
// Per tie: its curve, the centre and axis of its tail's first circle, its hair's radius there
// (8 floats each).
EMSCRIPTEN_KEEPALIVE const float* hs_engine_tie_frames(EngineHandle* h) {
  return h->engine.tieFrames().data();
}
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_tie_frame_count(EngineHandle* h) {
  return int32_t(h->engine.tieFrames().size() / 8);
}
// Per strand, with sections on: its root's scalp section (empty otherwise).
EMSCRIPTEN_KEEPALIVE const uint8_t* hs_engine_strand_sections(EngineHandle* h) {
  return h->engine.strandSections().data();
}
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_strand_section_count(EngineHandle* h) {
  return int32_t(h->engine.strandSections().size());
}

// Fills the flat constraint arrays; returns the number of constraints.
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_prepare_constraints(EngineHandle* h) {
  const ConstraintSet& cs = h->engine.constraints();
  h->constraintIndex.resize(cs.size());
  h->constraintTarget.resize(cs.size() * 3);
  for (size_t c = 0; c < cs.size(); ++c) {
    h->constraintIndex[c] = cs[c].index;
    for (int a = 0; a < 3; ++a) h->constraintTarget[3 * c + a] = float(cs[c].target[a]);
  }
  return int32_t(cs.size());
}
EMSCRIPTEN_KEEPALIVE const int32_t* hs_engine_constraint_index(EngineHandle* h) {
  return h->constraintIndex.data();
}
EMSCRIPTEN_KEEPALIVE const float* hs_engine_constraint_target(EngineHandle* h) {
  return h->constraintTarget.data();
}
// ConstraintColour per constraint (0 blue, 1 red, 2 purple, 3 green, 4 extra), same order and
// count as the constraint arrays.
EMSCRIPTEN_KEEPALIVE const uint8_t* hs_engine_constraint_colour(EngineHandle* h) {
  return h->engine.constraintColours().data();
}

// Fills the float field (n x 3, interleaved); returns n (grid points).
EMSCRIPTEN_KEEPALIVE int32_t hs_engine_prepare_field(EngineHandle* h) {
  h->field = toFloatField(h->engine.field());
  return int32_t(h->field.size() / 3);
}
EMSCRIPTEN_KEEPALIVE const float* hs_engine_field(EngineHandle* h) { return h->field.data(); }

EMSCRIPTEN_KEEPALIVE int32_t hs_engine_stats(EngineHandle* h, HsStats* out) {
  if (!h || !out) return fail(HS_INVALID_INPUT, "stats: no engine or output");
  writeStats(h->engine.stats(), int32_t(h->engine.constraints().size()), h->engine.growMs(), out);
  return HS_OK;
}

// ---- raw solver (explicit grid + constraint list, for research pipelines) ---------------

// *out = a new solver by name; HS_INVALID_INPUT for an unknown name.
EMSCRIPTEN_KEEPALIVE int32_t hs_raw_create(const char* name, RawHandle** out) {
  if (!out) return fail(HS_INVALID_INPUT, "raw_create: no output");
  *out = nullptr;
  std::unique_ptr<FieldSolver> s = makeFieldSolver(name ? name : "");
  if (!s) {
    gLastError = std::string("unknown solver '") + (name ? name : "") + "'";
    return HS_INVALID_INPUT;
  }
  RawHandle* h = new RawHandle();
  h->solver = std::move(s);
  h->name = name;
  *out = h;
  return HS_OK;
}
EMSCRIPTEN_KEEPALIVE void hs_raw_destroy(RawHandle* h) { delete h; }

// Uses nx, ny, nz and omega of the input (origin 0, step 1; the solver name was given to
// hs_raw_create).
EMSCRIPTEN_KEEPALIVE int32_t hs_raw_set_grid(RawHandle* h, const HsGridInput* in) {
  if (!h || !in) return fail(HS_INVALID_INPUT, "set_grid: no solver or input");
  if (h->hasGrid)
    return fail(HS_INVALID_INPUT, "setGrid: a solver takes one grid; create a new one");
  HsGridInput unit = *in;
  unit.originX = unit.originY = unit.originZ = 0;
  unit.step = 1;
  Grid g;
  Status s = makeGrid(unit, g);
  if (!s.ok()) return report(s);
  s = h->solver->setGrid(g, in->omega);
  if (!s.ok()) return report(s);
  h->grid = g;
  h->hasGrid = true;
  return HS_OK;
}

// Duplicates are averaged.
EMSCRIPTEN_KEEPALIVE int32_t hs_raw_set_constraints(RawHandle* h, const HsConstraintList* in) {
  if (!h || !in) return fail(HS_INVALID_INPUT, "set_constraints: no solver or input");
  if (!h->hasGrid) return fail(HS_NOT_READY, "setConstraints before setGrid");
  if (in->count > 0 && (!in->index || !in->target))
    return fail(HS_INVALID_INPUT, "constraints: bad arrays");
  std::vector<Constraint> raw(in->count);
  for (uint32_t c = 0; c < in->count; ++c) {
    raw[c].index = in->index[c];
    raw[c].target =
        Eigen::Vector3d(in->target[3 * c], in->target[3 * c + 1], in->target[3 * c + 2]);
  }
  // Validate before merging so that a NaN cannot hide in an average.
  Status s = validateConstraints(h->grid, raw);
  if (!s.ok()) return report(s);
  ConstraintSet set = normalizeConstraints(std::move(raw));
  s = h->solver->setConstraints(set);
  if (!s.ok()) return report(s);
  h->constraints = set.size();
  return HS_OK;
}

// out[0] = the solver's memory estimate for an nx x ny x nz grid (bytes, FieldSolver::
// estimateBytes: no allocation), out[1] = the cap setGrid would check it against now.
EMSCRIPTEN_KEEPALIVE int32_t hs_raw_estimate(RawHandle* h, int32_t nx, int32_t ny, int32_t nz,
                                             double* out) {
  if (!h || !out) return fail(HS_INVALID_INPUT, "estimate: no solver or output");
  if (nx < 2 || ny < 2 || nz < 2) return fail(HS_INVALID_INPUT, "grid dims must be >= 2");
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.nz = nz;
  out[0] = h->solver->estimateBytes(g);
  out[1] = double(h->solver->memoryCap());
  return HS_OK;
}

// Progress of long solves: at most every intervalMs of a solve's iterations the solver calls
// Module.hsOnProgress(iterations, errorEstimate, relResidual) when JS has set it; a falsy
// return stops the solve (status internal, "... stopped after N iterations"). intervalMs <= 0
// removes the hook.
EMSCRIPTEN_KEEPALIVE int32_t hs_raw_set_progress(RawHandle* h, double intervalMs) {
  if (!h) return fail(HS_INVALID_INPUT, "set_progress: no solver");
  if (!(intervalMs > 0)) {
    h->solver->setProgressHook(nullptr);
    return HS_OK;
  }
  double last = emscripten_get_now();
  h->solver->setProgressHook([intervalMs, last](const IterateProgress& p) mutable {
    const double now = emscripten_get_now();
    if (now - last < intervalMs) return true;
    last = now;
    const int keep = EM_ASM_INT(
        {
          const f = Module['hsOnProgress'];
          return f ? (f($0, $1, $2) ? 1 : 0) : 1;
        },
        p.iterations, p.errorEstimate, p.relResidual);
    return keep != 0;
  });
  return HS_OK;
}

EMSCRIPTEN_KEEPALIVE int32_t hs_raw_solve(RawHandle* h) {
  if (!h) return fail(HS_INVALID_INPUT, "solve: no solver");
  if (!h->hasGrid) return fail(HS_NOT_READY, "solve before setGrid");
  return report(h->solver->solve(h->field));
}
// n x 3 doubles, row p = t_p; valid after a successful solve.
EMSCRIPTEN_KEEPALIVE const double* hs_raw_field(RawHandle* h) { return h->field.data(); }
EMSCRIPTEN_KEEPALIVE int32_t hs_raw_field_points(RawHandle* h) { return int32_t(h->field.rows()); }
EMSCRIPTEN_KEEPALIVE int32_t hs_raw_stats(RawHandle* h, HsStats* out) {
  if (!h || !out) return fail(HS_INVALID_INPUT, "stats: no solver or output");
  writeStats(h->solver->stats(), int32_t(h->constraints), 0, out);
  return HS_OK;
}

// ---- motion (strand_motion.hpp StrandMotion) ----------------------------------------------
// A groom's guides in motion over the engine's head (and body when useBody and one is set); the
// engine must outlive it. points: float32[3 * pointCount]; strandStart: uint32[strandCount + 1];
// tails: int32[strandCount] (the tail curve per strand, -1 none) or 0; pivot: float32[3], the
// point the head turns about (world units, 10 cm); motion: 0 settle, 1 head turn, 2 nod,
// 3 wind; windFromDeg: where the wind comes from (degrees about the vertical axis: 0 the front,
// 90 the head's left), windSpeed its mean speed (m/s, 0..30). The arrays are copied. *out
// receives the handle.
struct SimHandle {
  StrandMotion motion;
};

EMSCRIPTEN_KEEPALIVE int32_t hs_sim_create(EngineHandle* h, const float* points, int32_t pointCount,
                                           const uint32_t* strandStart, int32_t strandCount,
                                           const int32_t* tails, const float* pivot, int32_t motion,
                                           double seed, int32_t maxGuides, int32_t useBody,
                                           double windFromDeg, double windSpeed, SimHandle** out) {
  if (!h || !points || !strandStart || !pivot || !out || pointCount < 0 || strandCount < 0)
    return fail(HS_INVALID_INPUT, "sim_create: missing input");
  if (motion < 0 || motion > 3) return fail(HS_INVALID_INPUT, "sim_create: unknown motion");
  if (!(seed >= 0 && seed <= 4294967295.0) || std::floor(seed) != seed)
    return fail(HS_INVALID_INPUT, "sim_create: seed must be a uint32");
  if (!std::isfinite(windFromDeg) || !(windSpeed >= 0 && windSpeed <= 30))
    return fail(HS_INVALID_INPUT, "sim_create: wind direction must be finite, speed 0..30 m/s");
  if (strandStart[0] != 0 || strandStart[strandCount] != uint32_t(pointCount))
    return fail(HS_INVALID_INPUT, "sim_create: strandStart does not cover the points");
  for (int32_t s = 0; s < strandCount; ++s)
    if (strandStart[s + 1] < strandStart[s])
      return fail(HS_INVALID_INPUT, "sim_create: strandStart decreases");
  MotionInput in;
  in.points = points;
  in.strandStart = strandStart;
  in.strandCount = strandCount;
  in.tailCurves = tails;
  in.head = &h->engine.headDistance();
  in.body = useBody ? &h->engine.bodyDistance() : nullptr;
  in.pivot = Eigen::Vector3f(pivot[0], pivot[1], pivot[2]);
  in.motion = SimMotion(motion);
  in.seed = uint32_t(seed);
  in.maxGuides = std::max(1, maxGuides);
  in.settings.windFrom = float(windFromDeg * 3.14159265358979323846 / 180);
  in.settings.windSpeed = float(windSpeed);
  // the simulation's physics are its settings' defaults (hair_sim.hpp SimSettings: world units)
  auto sim = std::make_unique<SimHandle>();
  sim->motion.init(in);
  *out = sim.release();
  return HS_OK;
}
EMSCRIPTEN_KEEPALIVE void hs_sim_destroy(SimHandle* s) { delete s; }
// Advances one frame (1/24 s).
EMSCRIPTEN_KEEPALIVE void hs_sim_step(SimHandle* s) { s->motion.step(); }
// The guides now: float32[3 * (guideCount * guidePoints + point)], strand-major; the same at
// rest (the groom's, resampled); points per guide.
EMSCRIPTEN_KEEPALIVE const float* hs_sim_guides(SimHandle* s) {
  return s->motion.guides().positions().data();
}
EMSCRIPTEN_KEEPALIVE const float* hs_sim_guide_rest(SimHandle* s) {
  return s->motion.guides().rest().data();
}
EMSCRIPTEN_KEEPALIVE int32_t hs_sim_guide_points(SimHandle* s) {
  return s->motion.guides().pointsPerStrand();
}
// Each strand's guide: int32[strandCount] (-1: none); each point's place along it: float32
// [pointCount] (0 .. guidePoints - 1).
EMSCRIPTEN_KEEPALIVE const int32_t* hs_sim_guide_of(SimHandle* s) {
  return s->motion.guideOf().data();
}
EMSCRIPTEN_KEEPALIVE const float* hs_sim_along(SimHandle* s) { return s->motion.along().data(); }
// The head's pose now: out float32[12] = rotation row-major (9), then translation (3).
EMSCRIPTEN_KEEPALIVE void hs_sim_pose(SimHandle* s, float* out) {
  const HeadPose& p = s->motion.pose();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[3 * r + c] = p.rotation(r, c);
  for (int r = 0; r < 3; ++r) out[9 + r] = p.translation[r];
}
EMSCRIPTEN_KEEPALIVE int32_t hs_sim_frame(SimHandle* s) { return s->motion.frame(); }
EMSCRIPTEN_KEEPALIVE int32_t hs_sim_guide_count(SimHandle* s) { return s->motion.guideCount(); }

}  // extern "C"
