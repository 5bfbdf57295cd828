// Polyline helpers of hair detail (strand_detail_internal.hpp): a strand loaded as doubles and
// stored back, its arc lengths, even resampling, cutting, and its rotation-minimising frame.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "strand_detail_internal.hpp"

namespace hairsketch::strand_detail {

void load(const float* f, size_t count, std::vector<V3>& p) {
  p.resize(count);
  for (size_t i = 0; i < count; ++i) p[i] = V3(f[3 * i], f[3 * i + 1], f[3 * i + 2]);
}

void store(const std::vector<V3>& p, float* f) {
  for (size_t i = 0; i < p.size(); ++i)
    for (int a = 0; a < 3; ++a) f[3 * i + a] = float(p[i][a]);
}

double arcLengths(const std::vector<V3>& p, std::vector<double>& s) {
  s.resize(p.size());
  s[0] = 0;
  for (size_t i = 1; i < p.size(); ++i) s[i] = s[i - 1] + (p[i] - p[i - 1]).norm();
  return s.back();
}

void resampleEven(const std::vector<V3>& p, const std::vector<double>& s, size_t m,
                  std::vector<V3>& out) {
  out.resize(m);
  const double L = s.back();
  size_t j = 0;
  for (size_t k = 1; k + 1 < m; ++k) {
    const double u = locate(s.data(), s.size(), L * double(k) / double(m - 1), j);
    out[k] = lerp(p[j], p[j + 1], u);
  }
  out[0] = p.front();
  out[m - 1] = p.back();
}

void cutAt(std::vector<V3>& p, std::vector<double>& s, double len) {
  if (!(len < s.back())) return;
  size_t i = 1;
  while (s[i] < len) ++i;
  const double seg = s[i] - s[i - 1];
  const double u = seg > 0 ? (len - s[i - 1]) / seg : 1.0;
  p[i] = lerp(p[i - 1], p[i], u);
  p.resize(i + 1);
  s.resize(i + 1);
  s[i] = len;
}

void keepLength(std::vector<V3>& p, std::vector<double>& s, double len, std::vector<V3>& q) {
  const size_t n = p.size();
  if (n < 2 || !(arcLengths(p, s) > len)) return;
  cutAt(p, s, len);  // leaves at least 2 points
  resampleEven(p, s, n, q);
  std::swap(p, q);
}

void frames(const std::vector<V3>& p, std::vector<V3>& T, std::vector<V3>& N, std::vector<V3>& B) {
  const size_t n = p.size();  // >= 2
  T.resize(n);
  N.resize(n);
  B.resize(n);
  // Unit segment directions (a zero segment repeats the previous direction), in B for now.
  V3 prev(0, 0, 1);
  for (size_t i = 0; i + 1 < n; ++i) {
    const V3 d = p[i + 1] - p[i];
    const double l2 = d.squaredNorm();
    B[i] = l2 > 0 ? V3(d * (1 / std::sqrt(l2))) : prev;
    prev = B[i];
  }
  T[0] = B[0];
  for (size_t i = 1; i + 1 < n; ++i) {
    const V3 t = B[i - 1] + B[i];
    const double l2 = t.squaredNorm();
    T[i] = l2 > 1e-12 ? V3(t * (1 / std::sqrt(l2))) : B[i];
  }
  T[n - 1] = B[n - 2];
  auto normalTo = [](const V3& t) {
    V3 r = V3(0, 1, 0) - t.y() * t;
    if (r.squaredNorm() < 1e-12) r = V3(1, 0, 0) - t.x() * t;
    return V3(r.normalized());
  };
  N[0] = normalTo(T[0]);
  for (size_t i = 0; i + 1 < n; ++i) {
    // Reflect (N, T) in the plane normal to the segment, then in the one taking T onto T_{i+1}.
    const V3& d = B[i];
    const V3 rL = N[i] - 2 * d.dot(N[i]) * d, tL = T[i] - 2 * d.dot(T[i]) * d;
    const V3 v2 = T[i + 1] - tL;
    const double c2 = v2.squaredNorm();
    V3 r = c2 > 1e-30 ? V3(rL - (2 / c2) * v2.dot(rL) * v2) : rL;
    // Reflections keep lengths and angles; only rounding (or a repeated direction) is corrected.
    r -= r.dot(T[i + 1]) * T[i + 1];
    const double l2 = r.squaredNorm();
    N[i + 1] = std::abs(l2 - 1) < 1e-9 ? r
               : l2 > 1e-12            ? V3(r / std::sqrt(l2))
                                       : normalTo(T[i + 1]);
  }
  for (size_t i = 0; i < n; ++i) B[i] = T[i].cross(N[i]);
}

}  // namespace hairsketch::strand_detail
