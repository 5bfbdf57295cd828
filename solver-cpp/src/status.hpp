// Result of a solver phase: every phase returns one, and nothing runs on a failed phase.
#pragma once

#include <string>
#include <utility>

namespace hairsketch {

enum class StatusCode { Ok, InvalidInput, OutOfMemory, NotPositiveDefinite, NotConverged };

struct Status {
  StatusCode code = StatusCode::Ok;
  std::string message;

  bool ok() const { return code == StatusCode::Ok; }
  static Status Ok() { return {}; }
  static Status Error(StatusCode c, std::string m) { return {c, std::move(m)}; }
};

}  // namespace hairsketch
