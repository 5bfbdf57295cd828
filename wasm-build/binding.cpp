// The wasm boundary: plain extern "C" functions over the C++ core. This file only converts
// (pointers + counts in, pointers + counts out, Status -> 0 / 1 + message); all logic is in
// solver-cpp/src. Results stay owned by the handle until its next call; JS copies them out.
// Errors: a function returns 0 on success, 1 on failure and hs_last_error() says why.
#include <emscripten/emscripten.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "field_solver.hpp"
#include "hair_engine.hpp"

using namespace hairsketch;

namespace {

std::string gLastError;

int report(const Status& s) {
  if (s.ok()) return 0;
  gLastError = s.message.empty() ? "error" : s.message;
  return 1;
}

int fail(const char* msg) {
  gLastError = msg;
  return 1;
}

// Limit in wasm32 (2 GB): the CG solver holds ~8 fields of n x 3 doubles.
constexpr double kMaxGridPoints = 4.0 * 1024 * 1024;

Status makeGrid(int nx, int ny, int nz, double ox, double oy, double oz, double step, Grid& g) {
  if (nx < 2 || ny < 2 || nz < 2)
    return Status::Error(StatusCode::InvalidInput, "grid dims must be >= 2");
  if (double(nx) * ny * nz > kMaxGridPoints)
    return Status::Error(StatusCode::InvalidInput, "grid has too many points for wasm");
  if (!std::isfinite(ox) || !std::isfinite(oy) || !std::isfinite(oz) || !std::isfinite(step) ||
      !(step > 0))
    return Status::Error(StatusCode::InvalidInput, "grid origin/step must be finite, step > 0");
  g.nx = nx;
  g.ny = ny;
  g.nz = nz;
  g.origin = {ox, oy, oz};
  g.step = step;
  return Status::Ok();
}

std::string jsonEscape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    o += c;
  }
  return o;
}

std::string statsJson(const SolveStats& s, double extraValue, const char* extraKey) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "{\"method\":\"%s\",\"iterations\":%d,\"residual\":%.17g,\"added\":%d,"
                "\"removed\":%d,\"changed\":%d,\"setupMs\":%.17g,\"solveMs\":%.17g,\"%s\":%.17g}",
                jsonEscape(s.method).c_str(), s.iterations, s.residual, s.added, s.removed,
                s.changed, s.setupMs, s.solveMs, extraKey, extraValue);
  return buf;
}

struct EngineHandle {
  HairEngine engine;
  std::vector<int32_t> constraintIndex;
  std::vector<float> constraintTarget;
  std::vector<float> field;
  std::vector<int32_t> avoidIndex;  // scalp avoidance result
  std::vector<double> avoidTarget;
  std::string json;
};

struct RawHandle {
  std::unique_ptr<FieldSolver> solver;
  Grid grid;
  bool hasGrid = false;
  size_t constraints = 0;
  Field field;
  std::string json;
};

}  // namespace

extern "C" {

EMSCRIPTEN_KEEPALIVE const char* hs_last_error() { return gLastError.c_str(); }

// ---- engine -----------------------------------------------------------------------------

EMSCRIPTEN_KEEPALIVE EngineHandle* hs_engine_create() { return new EngineHandle(); }
EMSCRIPTEN_KEEPALIVE void hs_engine_destroy(EngineHandle* h) { delete h; }

EMSCRIPTEN_KEEPALIVE int hs_engine_set_grid(EngineHandle* h, int nx, int ny, int nz, double ox,
                                            double oy, double oz, double step, double omega,
                                            const char* solver) {
  if (!h) return fail("no engine");
  Grid g;
  Status s = makeGrid(nx, ny, nz, ox, oy, oz, step, g);
  if (!s.ok()) return report(s);
  return report(h->engine.setGrid(g, omega, solver ? solver : ""));
}

EMSCRIPTEN_KEEPALIVE int hs_engine_set_scalp(EngineHandle* h, const float* positions,
                                             int vertexCount, const uint32_t* indices,
                                             int triangleCount, const uint8_t* scalp, double cx,
                                             double cy, double cz) {
  if (!h) return fail("no engine");
  if (vertexCount < 0 || triangleCount < 0) return fail("scalp: negative count");
  return report(h->engine.setScalp(positions, size_t(vertexCount), indices, size_t(triangleCount),
                                   scalp, Eigen::Vector3d(cx, cy, cz)));
}

// protocol.ts CurveSet: params / paramStart (curveCount + 1 entries) are the kind-specific
// parameter blocks; extraIndex / extraTarget (extraCount, extraCount x 3) the explicit
// constraints.
EMSCRIPTEN_KEEPALIVE int hs_engine_set_curves(EngineHandle* h, const double* points, int pointCount,
                                              const uint32_t* curveStart, int curveCount,
                                              const uint8_t* kinds, const uint8_t* extend,
                                              const double* params, int paramCount,
                                              const uint32_t* paramStart, const int32_t* extraIndex,
                                              const double* extraTarget, int extraCount) {
  if (!h) return fail("no engine");
  if (pointCount < 0 || curveCount < 0 || paramCount < 0 || extraCount < 0)
    return fail("curves: negative count");
  CurveSetView v{points, size_t(pointCount), curveStart, size_t(curveCount), kinds, extend};
  v.params = params;
  v.paramCount = size_t(paramCount);
  v.paramStart = paramStart;
  v.extraIndex = extraIndex;
  v.extraTarget = extraTarget;
  v.extraCount = size_t(extraCount);
  return report(h->engine.setCurves(v));
}

// Scalp avoidance (S4.7) on the last solved field: fills the handle's avoidance arrays (read
// with hs_engine_avoid_index / hs_engine_avoid_target) and returns 0 / 1 as usual; the count
// is hs_engine_avoid_count. flags: bit 0 = measure against the whole head (else the scalp
// triangles only), bit 1 = also grid points inside the head within the band.
EMSCRIPTEN_KEEPALIVE int hs_engine_scalp_avoidance(EngineHandle* h, double band, double magnitude,
                                                   int flags) {
  if (!h) return fail("no engine");
  ScalpAvoidanceParams p;
  p.band = band;
  p.magnitude = magnitude;
  p.wholeHead = (flags & 1) != 0;
  p.insideToo = (flags & 2) != 0;
  ConstraintSet out;
  h->avoidIndex.clear();
  h->avoidTarget.clear();
  const int rc = report(h->engine.scalpAvoidance(p, out));
  for (const Constraint& c : out) {
    h->avoidIndex.push_back(c.index);
    for (int a = 0; a < 3; ++a) h->avoidTarget.push_back(c.target[a]);
  }
  return rc;
}
EMSCRIPTEN_KEEPALIVE int hs_engine_avoid_count(EngineHandle* h) {
  return int(h->avoidIndex.size());
}
EMSCRIPTEN_KEEPALIVE const int32_t* hs_engine_avoid_index(EngineHandle* h) {
  return h->avoidIndex.data();
}
EMSCRIPTEN_KEEPALIVE const double* hs_engine_avoid_target(EngineHandle* h) {
  return h->avoidTarget.data();
}

EMSCRIPTEN_KEEPALIVE int hs_engine_solve(EngineHandle* h) {
  if (!h) return fail("no engine");
  return report(h->engine.solve());
}

// Progressive solve; the progress is read back with hs_engine_progress (iterations,
// errorEstimate, converged as 0/1) into a 3-double buffer.
EMSCRIPTEN_KEEPALIVE int hs_engine_iterate(EngineHandle* h, int maxIterations, double tolerance,
                                           double* progressOut) {
  if (!h) return fail("no engine");
  IterateProgress p;
  const int rc = report(h->engine.iterate(maxIterations, tolerance, p));
  progressOut[0] = p.iterations;
  progressOut[1] = p.errorEstimate;
  progressOut[2] = p.converged ? 1 : 0;
  return rc;
}

EMSCRIPTEN_KEEPALIVE int hs_engine_grow(EngineHandle* h, double thetaStepDeg, double phiStepDeg,
                                        double jitter, double seed, double stepFraction,
                                        double minMagnitude, double maxLength, int maxSegments,
                                        int maxStrands) {
  if (!h) return fail("no engine");
  if (!(seed >= 0 && seed <= 4294967295.0) || std::floor(seed) != seed)
    return fail("grow: seed must be a uint32");
  RootParams rp;
  rp.thetaStepDeg = thetaStepDeg;
  rp.phiStepDeg = phiStepDeg;
  rp.jitter = jitter;
  rp.seed = uint32_t(seed);
  rp.maxStrands = maxStrands;
  GrowthParams gp;
  gp.stepFraction = stepFraction;
  gp.minMagnitude = minMagnitude;
  gp.maxLength = maxLength;
  gp.maxSegments = maxSegments;
  return report(h->engine.grow(rp, gp));
}

EMSCRIPTEN_KEEPALIVE const float* hs_engine_strand_points(EngineHandle* h) {
  return h->engine.strands().points.data();
}
EMSCRIPTEN_KEEPALIVE int hs_engine_strand_point_count(EngineHandle* h) {
  return int(h->engine.strands().points.size() / 3);
}
EMSCRIPTEN_KEEPALIVE const uint32_t* hs_engine_strand_start(EngineHandle* h) {
  return h->engine.strands().strandStart.data();
}
// Entries of strandStart (strands + 1).
EMSCRIPTEN_KEEPALIVE int hs_engine_strand_start_count(EngineHandle* h) {
  return int(h->engine.strands().strandStart.size());
}
EMSCRIPTEN_KEEPALIVE int hs_engine_root_count(EngineHandle* h) {
  return int(h->engine.roots().size());
}

// Fills the flat constraint arrays; returns the number of constraints.
EMSCRIPTEN_KEEPALIVE int hs_engine_prepare_constraints(EngineHandle* h) {
  const ConstraintSet& cs = h->engine.constraints();
  h->constraintIndex.resize(cs.size());
  h->constraintTarget.resize(cs.size() * 3);
  for (size_t c = 0; c < cs.size(); ++c) {
    h->constraintIndex[c] = cs[c].index;
    for (int a = 0; a < 3; ++a) h->constraintTarget[3 * c + a] = float(cs[c].target[a]);
  }
  return int(cs.size());
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
EMSCRIPTEN_KEEPALIVE int hs_engine_prepare_field(EngineHandle* h) {
  h->field = toFloatField(h->engine.field());
  return int(h->field.size() / 3);
}
EMSCRIPTEN_KEEPALIVE const float* hs_engine_field(EngineHandle* h) { return h->field.data(); }

EMSCRIPTEN_KEEPALIVE const char* hs_engine_stats_json(EngineHandle* h) {
  h->json = statsJson(h->engine.stats(), double(h->engine.constraints().size()), "constraints");
  return h->json.c_str();
}
EMSCRIPTEN_KEEPALIVE double hs_engine_grow_ms(EngineHandle* h) { return h->engine.growMs(); }

// ---- raw solver (explicit grid + constraint list, for research pipelines) ---------------

// Returns 0 (and sets the error) for an unknown name.
EMSCRIPTEN_KEEPALIVE RawHandle* hs_raw_create(const char* name) {
  std::unique_ptr<FieldSolver> s = makeFieldSolver(name ? name : "");
  if (!s) {
    gLastError = std::string("unknown solver '") + (name ? name : "") + "'";
    return nullptr;
  }
  RawHandle* h = new RawHandle();
  h->solver = std::move(s);
  return h;
}
EMSCRIPTEN_KEEPALIVE void hs_raw_destroy(RawHandle* h) { delete h; }

EMSCRIPTEN_KEEPALIVE int hs_raw_set_grid(RawHandle* h, int nx, int ny, int nz, double omega) {
  if (!h) return fail("no solver");
  if (h->hasGrid) return fail("setGrid: a solver takes one grid; create a new one");
  Grid g;
  Status s = makeGrid(nx, ny, nz, 0, 0, 0, 1, g);
  if (!s.ok()) return report(s);
  s = h->solver->setGrid(g, omega);
  if (!s.ok()) return report(s);
  h->grid = g;
  h->hasGrid = true;
  return 0;
}

// index: count grid indices; target: count x 3 doubles. Duplicates are averaged.
EMSCRIPTEN_KEEPALIVE int hs_raw_set_constraints(RawHandle* h, const int32_t* index,
                                                const double* target, int count) {
  if (!h) return fail("no solver");
  if (!h->hasGrid) return fail("setConstraints before setGrid");
  if (count < 0 || (count > 0 && (!index || !target))) return fail("constraints: bad arrays");
  std::vector<Constraint> raw(static_cast<size_t>(count));
  for (int c = 0; c < count; ++c) {
    raw[c].index = index[c];
    raw[c].target = Eigen::Vector3d(target[3 * c], target[3 * c + 1], target[3 * c + 2]);
  }
  // Validate before merging so that a NaN cannot hide in an average.
  Status s = validateConstraints(h->grid, raw);
  if (!s.ok()) return report(s);
  ConstraintSet set = normalizeConstraints(std::move(raw));
  s = h->solver->setConstraints(set);
  if (!s.ok()) return report(s);
  h->constraints = set.size();
  return 0;
}

EMSCRIPTEN_KEEPALIVE int hs_raw_solve(RawHandle* h) {
  if (!h) return fail("no solver");
  return report(h->solver->solve(h->field));
}
// n x 3 doubles, row p = t_p; valid after a successful solve.
EMSCRIPTEN_KEEPALIVE const double* hs_raw_field(RawHandle* h) { return h->field.data(); }
EMSCRIPTEN_KEEPALIVE int hs_raw_field_points(RawHandle* h) { return int(h->field.rows()); }
EMSCRIPTEN_KEEPALIVE const char* hs_raw_stats_json(RawHandle* h) {
  h->json = statsJson(h->solver->stats(), double(h->constraints), "constraints");
  return h->json.c_str();
}

}  // extern "C"
