// Result of a solver phase: every phase returns one, and nothing runs on a failed phase.
#pragma once

#include <string>
#include <utility>

namespace hairsketch {

// InvalidInput: malformed input (sizes, ranges, layout). NonFinite: a NaN or infinity in the
// input. OverMemoryCap: the work would exceed the memory cap (memory_budget.hpp; refused before
// allocating). NotReady: a phase called before the one it needs (no grid, no scalp, curves
// changed since the last solve). NotPositiveDefinite, NotConverged: numerical failures.
// Cancelled: the caller's progress hook asked to stop (a time cap).
enum class StatusCode {
  Ok,
  InvalidInput,
  NonFinite,
  OverMemoryCap,
  NotReady,
  NotPositiveDefinite,
  NotConverged,
  Cancelled
};

struct Status {
  StatusCode code = StatusCode::Ok;
  std::string message;

  bool ok() const { return code == StatusCode::Ok; }
  static Status Ok() { return {}; }
  static Status Error(StatusCode c, std::string m) { return {c, std::move(m)}; }
};

}  // namespace hairsketch
