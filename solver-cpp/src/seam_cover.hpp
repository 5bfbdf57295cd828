// The seam cover (hair_fall.hpp kSeam*), for strand_growth.cpp's growStrands: where the field
// sends the hair apart across a line that runs across the head, the hair rooted at the line
// first lies along it, as a crown's whorl does, instead of leaving a bare line.
#pragma once

#include <algorithm>
#include <cmath>

#include "hair_fall.hpp"
#include "head_distance.hpp"

namespace hairsketch {

// The seam cover at a root (x, y, z) on the head: its weight (0: none) and the direction the hair
// first lies along (t: unit, along the head), towards the head's mid-plane through `centre`.
// sample(q, out) reads the field at q into out (3 floats), false outside its volume.
template <class Sample>
float seamCover(const HeadDistance& head, const Sample& sample, const float centre[3], float x,
                float y, float z, float t[3]) {
  float n[3];
  head.distance(x, y, z, n);
  const float nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(nl > 1e-6f)) return 0.f;
  for (float& c : n) c /= nl;
  // a basis of the head's tangent plane
  float e[2][3];
  const float a[3] = {std::abs(n[0]) < 0.9f ? 1.f : 0.f, std::abs(n[0]) < 0.9f ? 0.f : 1.f, 0.f};
  const float an = a[0] * n[0] + a[1] * n[1];
  for (int k = 0; k < 3; ++k) e[0][k] = a[k] - an * n[k];
  const float el = std::sqrt(e[0][0] * e[0][0] + e[0][1] * e[0][1] + e[0][2] * e[0][2]);
  for (float& c : e[0]) c /= el;
  e[1][0] = n[1] * e[0][2] - n[2] * e[0][1];
  e[1][1] = n[2] * e[0][0] - n[0] * e[0][2];
  e[1][2] = n[0] * e[0][1] - n[1] * e[0][0];
  // the field's direction along the head at +-kSeamProbe along each axis: u[2j + (0: +, 1: -)]
  float u[4][2];
  for (int p = 0; p < 4; ++p) {
    const float* ax = e[p / 2];
    const float sg = p % 2 == 0 ? kSeamProbe : -kSeamProbe;
    const float q[3] = {x + sg * ax[0], y + sg * ax[1], z + sg * ax[2]};
    float v[3];
    if (!sample(q, v)) return 0.f;
    const float c0 = v[0] * e[0][0] + v[1] * e[0][1] + v[2] * e[0][2];
    const float c1 = v[0] * e[1][0] + v[1] * e[1][1] + v[2] * e[1][2];
    const float m = std::sqrt(c0 * c0 + c1 * c1);
    if (!(m > 1e-6f)) return 0.f;
    u[p][0] = c0 / m;
    u[p][1] = c1 / m;
  }
  // the symmetric part of the direction's derivative (over the probe's length): its largest
  // eigenvalue is how sharply the hair parts, its eigenvector the parting's normal
  const float m00 = 0.5f * (u[0][0] - u[1][0]), m11 = 0.5f * (u[2][1] - u[3][1]);
  const float m01 = 0.25f * ((u[2][0] - u[3][0]) + (u[0][1] - u[1][1]));
  const float half = 0.5f * (m00 - m11);
  const float lambda = 0.5f * (m00 + m11) + std::sqrt(half * half + m01 * m01);
  if (!(lambda > kSeamLow)) return 0.f;
  float v0 = m01, v1 = lambda - m00;  // the eigenvector, from whichever row is better conditioned
  if (std::abs(lambda - m11) > std::abs(v1)) {
    v0 = lambda - m11;
    v1 = m01;
  }
  const float vl = std::sqrt(v0 * v0 + v1 * v1);
  if (!(vl > 1e-6f)) return 0.f;
  // the line's direction: across the normal
  for (int k = 0; k < 3; ++k) t[k] = (-v1 * e[0][k] + v0 * e[1][k]) / vl;
  auto smooth = [](float f) {
    f = std::clamp(f, 0.f, 1.f);
    return f * f * (3 - 2 * f);
  };
  const float across = 1.f - std::abs(t[2]);
  const float w = smooth((lambda - kSeamLow) / (kSeamHigh - kSeamLow)) *
                  smooth((across - kSeamAcrossLow) / (kSeamAcrossHigh - kSeamAcrossLow));
  // towards the mid-plane, up on the sides (mirror-symmetric): the two sides' hair meets over
  // the middle of the line
  const float in = x >= centre[0] ? -1.f : 1.f;
  if (in * t[0] + t[1] < 0)
    for (int k = 0; k < 3; ++k) t[k] = -t[k];
  return w;
}

}  // namespace hairsketch
