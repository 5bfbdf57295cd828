// The memory cap every solver, the engine and growth check BEFORE allocating (so that nothing a
// user makes is lost to an out-of-memory abort).
//
// The wasm module may grow to kMaxMemoryBytes (-sMAXIMUM_MEMORY=2GB in wasm-build/build.sh);
// past it an allocation aborts the module. The cap for new work is
//   availableMemoryBytes() = kMaxMemoryBytes - memoryInUseBytes() - kMemoryMarginBytes,
// memoryInUseBytes() being, in wasm, the static data and stack below the heap (__heap_base) plus
// the bytes malloc has handed out and not taken back (mallinfo().uordblks: the head mesh, an
// engine's solver and buffers, strands). Natively it is 0: the same 2 GB budget applies to an
// empty module, so native tests refuse what the browser refuses.
// kMemoryMarginBytes (128 MB) covers what the estimates do not count: dlmalloc's fragmentation
// and per-chunk overhead (free chunks below the heap top cannot always take a large block),
// JS inputs copied into wasm memory during a call (curve sets, head mesh: a few MB), the
// rounding of the estimates, and small containers (constraint sets, root lists).
#pragma once

#include <cstdint>
#include <string>

#include "grid.hpp"
#include "status.hpp"

namespace hairsketch {

constexpr int64_t kMaxMemoryBytes = int64_t(2) << 30;
constexpr int64_t kMemoryMarginBytes = int64_t(128) << 20;
// Grids are indexed by int (3 * points too, in the field loops): past this a grid is refused
// before any index arithmetic (a 2 x 2 x 10^9 box would overflow int32 indices).
constexpr int64_t kMaxIndexablePoints = (int64_t(1) << 31) / 3 - 1;

int64_t memoryInUseBytes();
// The cap for new allocations now (may be negative when the module is already full).
int64_t availableMemoryBytes();

// Bytes as a double of a product of counts (no int64 overflow on absurd dims).
inline double bytesOf(double count, double bytesEach) { return count * bytesEach; }

// "over the memory cap (needs ~X MB, cap Y MB)", prefixed by what (e.g. "exact solver").
std::string overMemoryCapMessage(const std::string& what, double needsBytes, int64_t capBytes);

// OverMemoryCap when needsBytes > capBytes, else Ok.
Status checkMemory(const std::string& what, double needsBytes, int64_t capBytes);

// InvalidInput / OverMemoryCap unless the grid is valid and indexable by int (see above).
Status checkGridIndexable(const Grid& grid);

}  // namespace hairsketch
