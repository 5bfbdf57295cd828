// Wall time of a phase in milliseconds, for the timings solvers and the engine report.
#pragma once
#include <chrono>

namespace hairsketch {

using Clock = std::chrono::steady_clock;

/** Milliseconds from t0 to now (steady clock). */
inline double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

/** Milliseconds from t0 to t1. */
inline double msBetween(Clock::time_point t0, Clock::time_point t1) {
  return std::chrono::duration<double, std::milli>(t1 - t0).count();
}

}  // namespace hairsketch
