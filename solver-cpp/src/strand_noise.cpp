#include "strand_noise.hpp"

#include <cmath>
#include <cstdint>

#include "rng.hpp"

namespace hairsketch {

float rootNoise(float x, float y, float z) {
  const float p[3] = {x / kRootNoiseCell, y / kRootNoiseCell, z / kRootNoiseCell};
  int64_t c[3];
  float f[3];
  for (int k = 0; k < 3; ++k) {
    const float fl = std::floor(p[k]);
    c[k] = int64_t(fl);
    f[k] = p[k] - fl;
  }
  float sum = 0;
  for (int corner = 0; corner < 8; ++corner) {
    float w = 1;
    uint64_t key = 0;
    for (int k = 0; k < 3; ++k) {
      const int bit = (corner >> k) & 1;
      w *= bit ? f[k] : 1 - f[k];
      key = key << 20 | (uint64_t(c[k] + bit) & 0xfffff);
    }
    sum += w * float(Pcg32(key, 0x68756773ULL).uniform());
  }
  return sum;
}

}  // namespace hairsketch
