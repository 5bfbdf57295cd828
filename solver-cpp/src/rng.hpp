// A small seeded random generator (PCG32, O'Neill 2014: 64-bit LCG state, XSH-RR output).
// Only integer arithmetic on fixed-width types, so a seed gives the same sequence natively and
// in wasm. Doubles are built from the bits directly (no std distributions, whose output is
// implementation-defined).
#pragma once

#include <cstdint>

namespace hairsketch {

class Pcg32 {
 public:
  explicit Pcg32(uint64_t seed, uint64_t stream = 0x5851f42d4c957f2dULL);
  // Next 32 uniformly distributed bits.
  uint32_t nextU32();
  // Uniform double in [0, 1) with 53 random bits (two draws).
  double uniform();

 private:
  uint64_t state_ = 0;
  uint64_t inc_ = 1;  // odd: selects the stream
};

}  // namespace hairsketch
