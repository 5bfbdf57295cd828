// Result of a solver phase: every phase returns one, and nothing runs on a failed phase.
#pragma once

#include <string>
#include <utility>

namespace hairsketch {

// InvalidInput: malformed input (sizes, ranges, layout). NonFinite: a NaN or infinity in the
// input. OutOfMemory: the work would exceed a memory cap. NotReady: a phase called before the
// one it needs (no grid, no scalp, curves changed since the last solve). NotPositiveDefinite,
// NotConverged: numerical failures.
enum class StatusCode {
  Ok,
  InvalidInput,
  NonFinite,
  OutOfMemory,
  NotReady,
  NotPositiveDefinite,
  NotConverged
};

struct Status {
  StatusCode code = StatusCode::Ok;
  std::string message;

  bool ok() const { return code == StatusCode::Ok; }
  static Status Ok() { return {}; }
  static Status Error(StatusCode c, std::string m) { return {c, std::move(m)}; }
};

}  // namespace hairsketch
