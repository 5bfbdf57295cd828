#include "rng.hpp"

#include <gtest/gtest.h>

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace rng_test {

using hairsketch::Pcg32;

TEST(Rng, SameSeedSameSequenceOtherSeedDiffers) {
  Pcg32 a(42), b(42), c(43);
  int differ = 0;
  for (int i = 0; i < 1000; ++i) {
    const uint32_t x = a.nextU32();
    EXPECT_EQ(x, b.nextU32());
    differ += x != c.nextU32();
  }
  EXPECT_GT(differ, 990);
}

TEST(Rng, MatchesPcg32ReferenceOutput) {
  // Reference from the PCG paper's demo (pcg32_srandom(42, 54)): first outputs.
  Pcg32 r(42, 54);
  const uint32_t expected[6] = {0xa15c02b7, 0x7b47f409, 0xba1d3330,
                                0x83d2f293, 0xbfa4784b, 0xcbed606e};
  for (uint32_t e : expected) EXPECT_EQ(r.nextU32(), e);
}

TEST(Rng, UniformIsInUnitIntervalWithPlausibleMean) {
  Pcg32 r(7);
  double sum = 0, lo = 1, hi = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double u = r.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    lo = std::min(lo, u);
    hi = std::max(hi, u);
  }
  EXPECT_NEAR(sum / n, 0.5, 0.005);
  EXPECT_LT(lo, 1e-3);
  EXPECT_GT(hi, 1 - 1e-3);
}

}  // namespace rng_test
