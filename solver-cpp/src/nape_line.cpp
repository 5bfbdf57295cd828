// The lower hairline round the back of the head (nape_line.hpp).
#include "nape_line.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hairsketch {
namespace {

constexpr float kTurnHalf = 3.14159265358979f;

// The bin coordinate of (x, z) about the centre: 0 straight back, kNapeBins / 2 straight ahead.
float napeBinOf(const float centre[3], float x, float z) {
  const float a = std::atan2(x - centre[0], -(z - centre[2]));  // -pi..pi, 0 behind
  return (a + kTurnHalf) / (2 * kTurnHalf) * float(kNapeBins);
}

}  // namespace

std::vector<float> napeLine(const std::vector<float>& edges, const float centre[3]) {
  std::vector<float> line(kNapeBins, std::numeric_limits<float>::infinity());
  const size_t m = edges.size() / 6;
  for (size_t e = 0; e < m; ++e) {
    // a few points along each edge, so a long edge marks every bin it crosses
    for (int k = 0; k <= 4; ++k) {
      const float t = float(k) / 4;
      const float* a = &edges[6 * e];
      const float p[3] = {a[0] + t * (a[3] - a[0]), a[1] + t * (a[4] - a[1]),
                          a[2] + t * (a[5] - a[2])};
      if (p[2] - centre[2] > kNapeFront || p[1] > centre[1] + kNapeTop) continue;
      const int b = std::clamp(int(napeBinOf(centre, p[0], p[2])), 0, kNapeBins - 1);
      line[b] = std::min(line[b], p[1]);
    }
  }
  for (float& v : line)
    if (std::isinf(v)) v = std::numeric_limits<float>::quiet_NaN();
  return line;
}

float napeLineTop(const std::vector<float>& line) {
  float top = -std::numeric_limits<float>::infinity();
  for (float v : line)
    if (v > top) top = v;  // NaN compares false: bins with no edge are skipped
  return top;
}

float napeLineAt(const std::vector<float>& line, const float centre[3], float x, float z) {
  if (line.size() != size_t(kNapeBins) || z - centre[2] > kNapeFront)
    return std::numeric_limits<float>::quiet_NaN();
  const float u = napeBinOf(centre, x, z) - 0.5f;  // bin centres at k + 0.5
  const float f = std::floor(u);
  const int i0 = (int(f) + kNapeBins) % kNapeBins, i1 = (i0 + 1) % kNapeBins;
  const float w = u - f;
  const float a = line[size_t(i0)], b = line[size_t(i1)];
  if (std::isnan(a)) return w > 0.5f ? b : a;  // NaN when the nearer has no edge
  if (std::isnan(b)) return w < 0.5f ? a : b;
  return a + w * (b - a);
}

}  // namespace hairsketch
