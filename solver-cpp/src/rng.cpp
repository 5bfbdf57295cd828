#include "rng.hpp"

namespace hairsketch {

namespace {
constexpr uint64_t kMultiplier = 6364136223846793005ULL;
}

Pcg32::Pcg32(uint64_t seed, uint64_t stream) {
  // PCG's documented seeding: state = 0, step, add seed, step.
  inc_ = (stream << 1u) | 1u;
  state_ = 0;
  nextU32();
  state_ += seed;
  nextU32();
}

uint32_t Pcg32::nextU32() {
  const uint64_t old = state_;
  state_ = old * kMultiplier + inc_;
  const uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
  const uint32_t rot = uint32_t(old >> 59u);
  return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

double Pcg32::uniform() {
  const uint64_t hi = nextU32() >> 5;                           // 27 bits
  const uint64_t lo = nextU32() >> 6;                           // 26 bits
  return double((hi << 26) | lo) * (1.0 / 9007199254740992.0);  // / 2^53
}

}  // namespace hairsketch
