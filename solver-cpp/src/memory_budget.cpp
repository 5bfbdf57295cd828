#include "memory_budget.hpp"

#include <cmath>
#include <cstdio>

#if defined(__EMSCRIPTEN__)
#include <malloc.h>
extern "C" unsigned char __heap_base;
#endif

namespace hairsketch {

int64_t memoryInUseBytes() {
#if defined(__EMSCRIPTEN__)
  const struct mallinfo mi = mallinfo();
  return int64_t(reinterpret_cast<uintptr_t>(&__heap_base)) + int64_t(mi.uordblks);
#else
  return 0;
#endif
}

int64_t availableMemoryBytes() { return kMaxMemoryBytes - memoryInUseBytes() - kMemoryMarginBytes; }

std::string overMemoryCapMessage(const std::string& what, double needsBytes, int64_t capBytes) {
  const double mb = 1024.0 * 1024.0;
  const double needs = std::ceil(needsBytes / mb);
  const long long cap = capBytes > 0 ? (long long)(capBytes / int64_t(1 << 20)) : 0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.0f", needs);
  return what + ": over the memory cap (needs ~" + buf + " MB, cap " + std::to_string(cap) + " MB)";
}

Status checkMemory(const std::string& what, double needsBytes, int64_t capBytes) {
  if (!(needsBytes <= double(capBytes)))
    return Status::Error(StatusCode::OverMemoryCap,
                         overMemoryCapMessage(what, needsBytes, capBytes));
  return Status::Ok();
}

Status checkGridIndexable(const Grid& grid) {
  if (!grid.valid())
    return Status::Error(StatusCode::InvalidInput, "grid must be at least 2x2x2 with a step > 0");
  if (double(grid.nx) * double(grid.ny) * double(grid.nz) > double(kMaxIndexablePoints))
    return Status::Error(StatusCode::OverMemoryCap,
                         "over the memory cap: a grid of " + std::to_string(grid.nx) + "x" +
                             std::to_string(grid.ny) + "x" + std::to_string(grid.nz) +
                             " is past the " + std::to_string(kMaxIndexablePoints) +
                             "-point index range");
  return Status::Ok();
}

}  // namespace hairsketch
